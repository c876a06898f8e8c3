/* cmd_semihost.c: `links1 semihost ELF`: runs a bare-metal program that
 * talks through semihosting (e.g. tests/bench/check_arm_bits.sh's renders)
 * on the board's CPU, its output on stdout, through the one launcher. */
#include <stdio.h>
#include <string.h>

#include "host-tools/launcher/launcher.h"
#include "host-tools/cli/links1_cmds.h"

static void cmd_semihost_usage(FILE *out)
{
    fprintf(out, "usage: links1 semihost ELF\n"
                 "Runs ELF on one cortex-a15 core of the plain virt board (%d MiB) with\n"
                 "semihosting on; its console output goes to stdout.  The program must end\n"
                 "the run itself (semihosting SYS_EXIT).  Exits with QEMU's status.\n",
            BOARD_DEFAULT_RAM_MB);
}

int cmd_semihost(int argc, char **argv)
{
    if (argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        cmd_semihost_usage(stdout);
        return 0;
    }
    if (argc != 2 || argv[1][0] == '-') {
        cmd_semihost_usage(stderr);
        return 2;
    }
    int r = board_run_semihost(argv[1], BOARD_DEFAULT_RAM_MB);
    return r < 0 ? 1 : r;
}
