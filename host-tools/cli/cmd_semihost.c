/* cmd_semihost.c: `links1 semihost ELF`: runs a bare-metal program that
 * talks through semihosting (e.g. tests/bench/check_arm_bits.sh's renders,
 * tests/bench/bench_apu.sh's Table 1) on the board's CPU, its output on
 * stdout, through the one launcher. */
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "host-tools/launcher/launcher.h"
#include "host-tools/cli/links1_cmds.h"
#include "host-tools/opts/cli_opt.h"
#include "host-tools/opts/out_file.h"
#include "host-tools/opts/tmp_dir.h"

static void cmd_semihost_usage(FILE *out)
{
    fprintf(out, "usage: links1 semihost ELF [--cores N] [--trace-marks FILE]\n"
                 "Runs ELF on the plain virt board (cortex-a15, %d MiB) with semihosting on;\n"
                 "its console output goes to stdout.  The program must end the run itself\n"
                 "(semihosting SYS_EXIT).  Exits with QEMU's status.\n"
                 "  --cores N        cores of the board (1..8, default 1); the program starts\n"
                 "                   the others (PSCI CPU_ON)\n"
                 "  --trace-marks F  each core's trace marks (proto/insn_mark.h) with its\n"
                 "                   instruction count, one 'core kind count' line each\n",
            BOARD_DEFAULT_RAM_MB);
}

enum { SEMIHOST_OPT_CORES = CLI_OWN_CODES, SEMIHOST_OPT_TRACE };

static const struct option semihost_options[] = {
    {"cores", required_argument, NULL, SEMIHOST_OPT_CORES},
    {"trace-marks", required_argument, NULL, SEMIHOST_OPT_TRACE},
    {"help", no_argument, NULL, 'h'},
    {NULL, 0, NULL, 0},
};

int cmd_semihost(int argc, char **argv)
{
    const char *elf = NULL, *trace = NULL;
    long cores = 1;
    struct cli c;
    cli_init(&c, "links1 semihost", argc, argv, "h", semihost_options);
    for (int code; (code = cli_next(&c)) != -1;) {
        switch (code) {
        case 'h':
            cmd_semihost_usage(stdout);
            return 0;
        case SEMIHOST_OPT_CORES:
            if (cli_long(&c, 10, 1, 8, &cores) < 0)
                return 2;
            break;
        case SEMIHOST_OPT_TRACE:
            trace = c.arg;
            break;
        case CLI_OPERAND:
            if (elf) {
                fprintf(stderr, "links1 semihost: %s: one program at a time\n", c.arg);
                return 2;
            }
            elf = c.arg;
            break;
        default:
            return 2;
        }
    }
    if (!elf) {
        cli_usage_error("links1 semihost", "name an ELF");
        return 2;
    }
    /* The plugin's marks go to a private directory of the run's first
     * (it makes its file new), then whole to F (out_file). */
    char dir[PATH_MAX] = "", marks[PATH_MAX + 16], err[2 * PATH_MAX];
    if (trace && tmp_dir_make("insns", dir, sizeof dir) != 0) {
        perror("links1 semihost: a private directory for the trace marks");
        return 1;
    }
    snprintf(marks, sizeof marks, "%s/marks", dir);
    int r = board_run_semihost_smp(elf, BOARD_DEFAULT_RAM_MB, (int)cores, trace ? marks : NULL);
    if (trace && r >= 0 && out_file_copy(marks, trace, err, sizeof err) != 0) {
        fprintf(stderr, "links1 semihost: --trace-marks: %s\n", err);
        r = r ? r : 1;
    }
    if (dir[0])
        tmp_dir_remove(dir);
    return r < 0 ? 1 : r;
}
