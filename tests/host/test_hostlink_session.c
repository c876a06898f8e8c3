/* Host tests of a whole board session (host-tools/link/board.c): start, report-in,
 * commands, shutdown, against a fake board.  The fake is this same program:
 * the tests point $QEMU at /proc/self/exe and name a behaviour in
 * $FAKE_BOARD, and main() plays the board on the UART socket QEMU would
 * have been given.  No emulator needed, all under ASan and UBSan. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host-tools/launcher/launcher.h"
#include "proto/wire.h"
#include "tests/check.h"
#include "tests/host/fake_qemu.h"

/* ------------------------------------------------------------ the fake */

/* Plays the board: behaviour "all" reports every core in and powers off on
 * CMD_SHUTDOWN; "missing" leaves out cores 3 and ncores-1; "deaf" never
 * powers off; "crash" dies after two report-ins. */
static int fake_board(const char *mode, int argc, char **argv)
{
    int ncores = 0;
    fake_fd = -1;
    for (int i = 1; i + 1 < argc; i++) {
        if (strcmp(argv[i], "-smp") == 0)
            ncores = atoi(argv[i + 1]);
        if (strcmp(argv[i], "-chardev") == 0)
            sscanf(argv[i + 1], "socket,id=link,fd=%d", &fake_fd);
    }
    if (ncores < 3 || fake_fd < 0)
        return 9;
    if (fake_send(LINK_LOG, "core 0 DM: fake board up", 24) < 0)
        _exit(5);
    for (int k = 0; k < ncores; k++) {
        if (strcmp(mode, "crash") == 0 && k == 2)
            return 3;
        if (strcmp(mode, "missing") == 0 && (k == 3 || k == ncores - 1))
            continue;
        if (fake_hello(k, ncores) < 0)
            _exit(5);
    }
    struct link_decoder d;
    link_decoder_init(&d);
    uint8_t byte;
    while (read(fake_fd, &byte, 1) == 1) {
        struct link_frame f;
        if (!link_decoder_push(&d, byte, &f) || f.type != LINK_CMD)
            continue;
        uint16_t cmd = wire_get_u16(f.payload);
        uint8_t r[8];
        wire_put_u16(r, cmd);
        wire_put_u16(r + 2, 0);
        wire_put_u16(r + 4, (uint16_t)ncores);
        wire_put_u16(r + 6, (uint16_t)ncores);
        if (cmd == CMD_SHUTDOWN && strcmp(mode, "deaf") == 0)
            continue;
        if (fake_send(LINK_RESULT, r, cmd == CMD_STATUS ? 8 : 4) < 0)
            _exit(5);
        if (cmd == CMD_SHUTDOWN)
            return 0;
    }
    /* Like QEMU, a board that lost its host link keeps running. */
    if (strcmp(mode, "deaf") == 0)
        for (;;)
            pause();
    return 0;
}

/* ------------------------------------------------------------ the tests */

static int session_start(struct board *b, const char *mode, int ncores)
{
    struct board_opts o;
    board_opts_init(&o);
    o.ncores = ncores;
    o.quiet = 1;
    o.firmware = "/proc/self/exe"; /* any ELF will do for the fake */
    setenv("QEMU", "/proc/self/exe", 1);
    setenv("FAKE_BOARD", mode, 1);
    return board_start(b, &o);
}

static void session_all_report_in_and_power_off(void)
{
    struct board b;
    CHECK_EQ_INT(session_start(&b, "all", 12), 0);
    CHECK_EQ_INT(board_wait_reported(&b, 5000), 0);
    CHECK_EQ_INT(b.reported_count, 12);
    struct board_frame r;
    int status = -1;
    const uint8_t *f;
    size_t n = 0;
    CHECK_EQ_INT(board_send_cmd(&b, CMD_STATUS, NULL, 0), 0);
    CHECK_EQ_INT(board_wait_result(&b, CMD_STATUS, 5000, &r, &status, &f, &n), 0);
    CHECK_EQ_INT(status, 0);
    CHECK_EQ_INT(n, 4);
    CHECK_EQ_INT(board_stop(&b), 0); /* exited by itself, status 0 */
    CHECK_EQ_INT(b.qemu_pid, 0);
    CHECK_EQ_INT(board_link_errors(&b), 0);
}

static void session_missing_cores_time_out(void)
{
    struct board b;
    CHECK_EQ_INT(session_start(&b, "missing", 10), 0);
    /* The fake board's eight report-ins come first, however slowly the
     * host starts it; then the wait for all ten times out. */
    long long end = board_now_ms() + 30000;
    while (b.reported_count < 8 && board_now_ms() < end && board_pump(&b, 100) == 0) {
    }
    CHECK_EQ_INT(b.reported_count, 8);
    long long t0 = board_now_ms();
    CHECK_EQ_INT(board_wait_reported(&b, 300), -1);
    CHECK(board_now_ms() - t0 >= 300);
    CHECK_EQ_INT(b.reported_count, 8);
    CHECK_EQ_INT(b.reported[3], 0);
    CHECK_EQ_INT(b.reported[9], 0);
    CHECK_EQ_INT(board_stop(&b), 0);
}

static void session_deaf_board_is_terminated(void)
{
    struct board b;
    CHECK_EQ_INT(session_start(&b, "deaf", 3), 0);
    CHECK_EQ_INT(board_wait_reported(&b, 5000), 0);
    /* No power-off: after the wait, SIGTERM ends it (a signalled stop). */
    CHECK_EQ_INT(board_stop(&b), 1);
    CHECK_EQ_INT(b.qemu_pid, 0);
    CHECK(WIFSIGNALED(b.qemu_status) && WTERMSIG(b.qemu_status) == SIGTERM);
}

static void session_board_that_dies_is_noticed(void)
{
    struct board b;
    CHECK_EQ_INT(session_start(&b, "crash", 6), 0);
    CHECK_EQ_INT(board_wait_reported(&b, 5000), -1);
    CHECK_EQ_INT(b.reported_count, 2);
    CHECK_EQ_INT(b.fd, -1);
    CHECK(WIFEXITED(b.qemu_status) && WEXITSTATUS(b.qemu_status) == 3);
    CHECK_EQ_INT(board_stop(&b), 0);
}

int main(int argc, char **argv)
{
    const char *mode = getenv("FAKE_BOARD");
    if (mode)
        return fake_board(mode, argc, argv);
    RUN(session_all_report_in_and_power_off);
    RUN(session_missing_cores_time_out);
    RUN(session_deaf_board_is_terminated);
    RUN(session_board_that_dies_is_noticed);
    return check_exit();
}
