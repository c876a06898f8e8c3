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

enum semihost_opt_code { SEMIHOST_OPT_CORES = CLI_OWN_CODES, SEMIHOST_OPT_TRACE };

static const struct cli_optdef semihost_optdefs[] = {
    {"cores", "N", SEMIHOST_OPT_CORES,
     "cores of the board (1..8, default 1); the program starts the\n"
     "others (PSCI CPU_ON)"},
    {"trace-marks", "FILE", SEMIHOST_OPT_TRACE,
     "each core's trace marks (proto/insn_mark.h) with its instruction\n"
     "count, one 'core kind count' line each"},
    CLI_OPTDEF_END,
};

static void cmd_semihost_usage(FILE *out)
{
    fprintf(out, "usage: links1 semihost ELF [options]\n"
                 "Runs ELF on the plain virt board (cortex-a15, %d MiB) with semihosting on;\n"
                 "its console output goes to stdout.  The program must end the run itself\n"
                 "(semihosting SYS_EXIT).  Exits with QEMU's status.\n",
            BOARD_DEFAULT_RAM_MB);
    cli_optdefs_help(out, semihost_optdefs);
}

int cmd_semihost(int argc, char **argv)
{
    const char *elf = NULL, *trace = NULL;
    long cores = 1;
    static const struct cli_optdef *const lists[] = {semihost_optdefs, NULL};
    struct option longs[8];
    struct cli c;
    if (cli_optdefs_table(lists, longs, 8) != 0)
        return 2;
    cli_init(&c, "links1 semihost", argc, argv, "h", longs);
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
                cli_usage_error("links1 semihost", "one program at a time, not also '%s'",
                                c.arg);
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
