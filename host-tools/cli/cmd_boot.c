/* cmd_boot.c: `links1 boot`: boot the board, show every unit computer
 * reporting in, shut it down cleanly; optionally count guest instructions. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "host-tools/launcher/launcher.h"
#include "host-tools/insn/insn_report.h"
#include "host-tools/cli/links1_cmds.h"
#include "host-tools/opts/tmp_dir.h"

enum { BOOT_OPT_COUNT_INSNS = CLI_OWN_CODES };

static const struct cli_optdef boot_optdefs[] = {
    {"count-insns", NULL, BOOT_OPT_COUNT_INSNS,
     "count guest instructions per core (the TCG plugin insn-count.so\n"
     "next to this program) and print them"},
    CLI_OPTDEF_END,
};

static void cmd_boot_usage(FILE *out)
{
    fprintf(out, "usage: links1 boot [options]\n"
                 "Boots the board, prints its log and every unit computer reporting in,\n"
                 "then shuts it down.  Exits non-zero naming the cores that did not report.\n");
    cli_optdefs_help(out, board_optdefs);
    cli_optdefs_help(out, boot_optdefs);
}

int cmd_boot(int argc, char **argv)
{
    struct board_opts o;
    int count_insns = 0;
    board_opts_init(&o);
    static const struct cli_optdef *const lists[] = {board_optdefs, boot_optdefs, NULL};
    struct option longs[32];
    struct cli c;
    if (cli_optdefs_table(lists, longs, 32) != 0)
        return 2;
    cli_init(&c, "links1 boot", argc, argv, "h", longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        int r = code == CLI_BAD ? -1 : board_opt(&o, &c, code);
        if (r < 0)
            return 2;
        if (r)
            continue;
        if (code == BOOT_OPT_COUNT_INSNS) {
            count_insns = 1;
        } else if (code == 'h') {
            cmd_boot_usage(stdout);
            return 0;
        } else {
            cli_usage_error("links1 boot", "unexpected argument '%s'", c.arg);
            return 2;
        }
    }
    /* The plugin's counts in a private directory of the run's (an an521
     * NC board's beside them, .bK), each file made new by the plugin. */
    char dir[PATH_MAX] = "", insn_path[PATH_MAX + 16];
    if (count_insns) {
        if (tmp_dir_make("insns", dir, sizeof dir) != 0) {
            perror("links1: a private directory for the instruction counts");
            return 1;
        }
        snprintf(insn_path, sizeof insn_path, "%s/counts", dir);
        o.insn_count_out = insn_path;
    }
    struct board b;
    int rc = 1;
    if (board_start(&b, &o) == 0 && board_wait_reported(&b, o.timeout_s * 1000) == 0) {
        if (o.quiet) /* else board_wait_reported said "board up" */
            printf("links1: all %d unit computers reported in: DM, RC and %d NCs\n", o.ncores,
                   o.ncores - 2);
        rc = 0;
    }
    int stop = board_stop(&b);
    if (board_report_link_errors(&b))
        rc = 1;
    if (stop < 0)
        rc = 1;
    if (count_insns) {
        if (insn_report_print(insn_path, o.ncores) < 0)
            rc = 1;
        tmp_dir_remove(dir);
    }
    return rc;
}
