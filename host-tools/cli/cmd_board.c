/* cmd_board.c: `links1 board start|stop|list|status`: boards that keep running
 * between commands, so `links1 render --board NAME` re-renders without
 * booting (host-tools/launcher/board_named.c). */
#include <stdio.h>
#include <string.h>

#include "host-tools/launcher/launcher.h"
#include "host-tools/cli/links1_cmds.h"

enum { BOARD_CMD_OPT_NAME = CLI_OWN_CODES };

static const struct cli_optdef board_cmd_optdefs[] = {
    {"name", "NAME", BOARD_CMD_OPT_NAME, "the board's name (default '" BOARD_DEFAULT_NAME "')"},
    CLI_OPTDEF_END,
};

static void cmd_board_usage(FILE *out)
{
    fprintf(out, "usage: links1 board start [options]\n"
                 "       links1 board stop [NAME]\n"
                 "       links1 board list\n"
                 "       links1 board status [NAME]\n"
                 "start boots a board that keeps running after this command; `links1 render\n"
                 "--board NAME ...` then renders on it, and stop shuts it down.  list shows\n"
                 "the boards running, status one of them; each reports and removes the state\n"
                 "of a board whose QEMU is gone.  With --machine an521 the board is a set of\n"
                 "QEMUs; list and status show each NC board, and stop ends them all.\n"
                 "start options:\n");
    cli_optdefs_help(out, board_cmd_optdefs);
    cli_optdefs_help(out, board_optdefs);
}

static int cmd_board_start(int argc, char **argv)
{
    struct board_opts o;
    const char *name = BOARD_DEFAULT_NAME;
    board_opts_init(&o);
    static const struct cli_optdef *const lists[] = {board_cmd_optdefs, board_optdefs, NULL};
    struct option longs[32];
    struct cli c;
    if (cli_optdefs_table(lists, longs, 32) != 0)
        return 2;
    cli_init(&c, "links1 board start", argc, argv, "h", longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        int r = code == CLI_BAD ? -1 : board_opt(&o, &c, code);
        if (r < 0)
            return 2;
        if (r)
            continue;
        if (code == BOARD_CMD_OPT_NAME) {
            name = c.arg;
        } else if (code == 'h') {
            cmd_board_usage(stdout);
            return 0;
        } else {
            cli_usage_error("links1 board start", "unexpected argument '%s'", c.arg);
            return 2;
        }
    }
    /* float and fixed boot the firmware that escalates, as links1 render's
     * own boards do: each render on it escalates by default (or not, with
     * --no-escalate); --firmware's is booted as it is */
    o.escalate = !o.firmware && (strcmp(o.arith, "float") == 0 || strcmp(o.arith, "fixed") == 0);
    struct board b;
    if (board_start_named(&b, &o, name, o.timeout_s * 1000) < 0)
        return 1;
    if (o.machine == MACHINE_AN521)
        printf("links1: board %s runs on (%d an521 boards, board 0's QEMU pid %d): `links1 "
               "render --board %s ...`, `links1 board stop %s`\n", name,
               o.ncores / AN521_CORES_PER_BOARD, (int)b.qemu_pid, name, name);
    else
        printf("links1: board %s runs on (QEMU pid %d): `links1 render --board %s ...`, "
               "`links1 board stop %s`\n", name, (int)b.qemu_pid, name, name);
    int rc = board_report_link_errors(&b) ? 1 : 0;
    if (b.nfaults)
        rc = 1;
    board_stop(&b); /* this session only: the board runs on */
    return rc;
}

int cmd_board(int argc, char **argv)
{
    if (argc < 2) {
        cli_usage_error("links1 board", "start, stop, list or status?");
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        cmd_board_usage(stdout);
        return 0;
    }
    if (strcmp(argv[1], "start") == 0)
        return cmd_board_start(argc - 1, argv + 1);
    if (strcmp(argv[1], "stop") == 0 && argc <= 3)
        return board_stop_named(argc == 3 ? argv[2] : BOARD_DEFAULT_NAME) == 0 ? 0 : 1;
    if (strcmp(argv[1], "status") == 0 && argc <= 3)
        return board_status_named(argc == 3 ? argv[2] : BOARD_DEFAULT_NAME) == 0 ? 0 : 1;
    if (strcmp(argv[1], "list") == 0 && argc == 2)
        return board_list_named() < 0 ? 1 : 0;
    cli_usage_error("links1 board", "unknown subcommand or extra arguments: '%s'", argv[1]);
    return 2;
}
