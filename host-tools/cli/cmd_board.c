/* cmd_board.c: `links1 board start|stop|list|status`: boards that keep running
 * between commands, so `links1 render --board NAME` re-renders without
 * booting (host-tools/launcher/board_named.c). */
#include <stdio.h>
#include <string.h>

#include "host-tools/launcher/launcher.h"
#include "host-tools/cli/links1_cmds.h"

static void cmd_board_usage(FILE *out)
{
    fprintf(out, "usage: links1 board start [--ncs N] [--name NAME] [board options]\n"
                 "       links1 board stop [NAME]\n"
                 "       links1 board list\n"
                 "       links1 board status [NAME]\n"
                 "start boots a board that keeps running after this command (NAME default\n"
                 "'%s'); `links1 render --board NAME ...` then renders on it, and stop\n"
                 "shuts it down.  list shows the boards running, status one of them;\n"
                 "start, stop, list and status report and remove the state of a board\n"
                 "whose QEMU is gone.  With --machine an521 the board is a set of QEMUs\n"
                 "(board 0: DM and RC; two NCs on each other board) joined by one shared\n"
                 "file; list and status show each NC board, and stop ends them all.\n"
                 "start options:\n"
                 "  --ncs N          node computers (1..254, default %d; an521: even, 2..64)\n"
                 "  --name NAME      the board's name\n%s",
            BOARD_DEFAULT_NAME, BOARD_DEFAULT_CORES - 2, board_opts_usage);
}

enum { BOARD_CMD_OPT_NCS = CLI_OWN_CODES, BOARD_CMD_OPT_NAME };

static const struct option board_cmd_options[] = {
    BOARD_LONG_OPTIONS,
    {"ncs", required_argument, NULL, BOARD_CMD_OPT_NCS},
    {"name", required_argument, NULL, BOARD_CMD_OPT_NAME},
    {"help", no_argument, NULL, 'h'},
    {NULL, 0, NULL, 0},
};

static int cmd_board_start(int argc, char **argv)
{
    struct board_opts o;
    const char *name = BOARD_DEFAULT_NAME;
    board_opts_init(&o);
    struct cli c;
    cli_init(&c, "links1 board start", argc, argv, "h", board_cmd_options);
    for (int code; (code = cli_next(&c)) != -1;) {
        int r = board_opt(&o, &c, code);
        if (r < 0)
            return 2;
        if (r)
            continue;
        long n;
        if (code == BOARD_CMD_OPT_NCS) {
            if (cli_long(&c, 10, 1, UNITS_MAX_CORES - 2, &n) < 0)
                return 2;
            o.ncores = (int)n + 2;
        } else if (code == BOARD_CMD_OPT_NAME) {
            name = c.arg;
        } else if (code == 'h') {
            cmd_board_usage(stdout);
            return 0;
        } else {
            if (code == CLI_OPERAND)
                fprintf(stderr, "links1 board start: unexpected argument '%s'\n", c.arg);
            cmd_board_usage(stderr);
            return 2;
        }
    }
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
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        cmd_board_usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (strcmp(argv[1], "start") == 0)
        return cmd_board_start(argc - 1, argv + 1);
    if (strcmp(argv[1], "stop") == 0 && argc <= 3)
        return board_stop_named(argc == 3 ? argv[2] : BOARD_DEFAULT_NAME) == 0 ? 0 : 1;
    if (strcmp(argv[1], "status") == 0 && argc <= 3)
        return board_status_named(argc == 3 ? argv[2] : BOARD_DEFAULT_NAME) == 0 ? 0 : 1;
    if (strcmp(argv[1], "list") == 0 && argc == 2)
        return board_list_named() < 0 ? 1 : 0;
    fprintf(stderr, "links1 board: unknown subcommand or extra arguments: '%s'\n", argv[1]);
    cmd_board_usage(stderr);
    return 2;
}
