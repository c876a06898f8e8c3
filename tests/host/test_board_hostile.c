/* Host tests of a board that sends what it should not, played on the other
 * end of a socketpair (fake_board.h): its text (LOG lines, fault texts,
 * refusals, reports of dropped frames) printed with every control
 * character escaped, never raw; a serial frame pull that brings more than
 * the frame's own bytes stopped at once with an error; a board whose end of
 * the link is gone makes a write fail with an error, never SIGPIPE. */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host-tools/gigs/render_session.h"
#include "proto/wire.h"
#include "tests/check.h"
#include "tests/host/capture.h"
#include "tests/host/fake_board.h"

static uint16_t peer_seq; /* the fake board's frame counter */

static void peer_send_flags(int fd, uint8_t type, uint8_t flags, const void *p, size_t len)
{
    uint8_t frame[LINK_MAX_FRAME];
    size_t n = link_frame_encode(frame, sizeof frame, type, flags, peer_seq++, p, len);
    CHECK(write(fd, frame, n) == (ssize_t)n);
}

static void peer_send(int fd, uint8_t type, const void *p, size_t len)
{
    peer_send_flags(fd, type, 0, p, len);
}

/* No byte below ' ' but '\n', none above '~'. */
static int printable(const char *s, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (((unsigned char)s[i] < ' ' && s[i] != '\n') || (unsigned char)s[i] > '~')
            return 0;
    return 1;
}

static void session(struct board *b, int *peer, int quiet)
{
    CHECK(fake_session(b, peer) == 0);
    b->opts.quiet = quiet;
    peer_seq = 0;
}

static void hostile_log_text_is_escaped(void)
{
    struct board b;
    int peer;
    session(&b, &peer, 0);
    static const char text[] = "title\x1b]0;pwned\x07 clear\x1b[2J\nnext \x9b line\\";
    peer_send(peer, LINK_LOG, text, sizeof text - 1);
    struct capture c;
    char out[4096];
    capture_begin(&c, STDOUT_FILENO);
    board_pump(&b, 500);
    size_t n = capture_end(&c, out, sizeof out);
    CHECK(printable(out, n));
    CHECK(strstr(out, "board: title\\x1b]0;pwned\\x07 clear\\x1b[2J\n") != NULL);
    CHECK(strstr(out, "board: next \\x9b line\\\\\n") != NULL);
    if (!printable(out, n) || !strstr(out, "\\x1b"))
        printf("    printed: %s\n", out);
    board_session_close(&b);
    close(peer);
}

static void hostile_fault_text_is_escaped(void)
{
    struct board b;
    int peer;
    session(&b, &peer, 1);
    uint8_t p[LINK_FAULT_FIXED_SIZE + 32];
    struct link_fault ft = {5, ROLE_NC, FAULT_PANIC, 0x1000, 0x2000, 0};
    link_fault_put(p, &ft);
    static const char text[] = "oops\x1b[31m red\r";
    memcpy(p + LINK_FAULT_FIXED_SIZE, text, sizeof text - 1);
    peer_send(peer, LINK_FAULT, p, LINK_FAULT_FIXED_SIZE + sizeof text - 1);
    struct capture c;
    char out[4096];
    capture_begin(&c, STDOUT_FILENO);
    board_pump(&b, 500);
    size_t n = capture_end(&c, out, sizeof out);
    CHECK_EQ_INT(b.nfaults, 1);
    CHECK(printable(out, n));
    CHECK(strstr(out, "oops\\x1b[31m red\\x0d") != NULL);
    CHECK(printable(b.fault_text[0], strlen(b.fault_text[0])));
    CHECK(strstr(b.fault_text[0], "oops\\x1b[31m") != NULL);
    board_session_close(&b);
    close(peer);
}

static void hostile_refusal_text_is_escaped(void)
{
    struct board b;
    int peer;
    session(&b, &peer, 1);
    uint8_t p[LINK_RESULT_FIXED_SIZE + 32];
    static const char text[] = "no\x1b[8m hidden";
    wire_put_u16(p, CMD_STATUS);
    wire_put_u16(p + 2, (uint16_t)LINK_ERR_CHECK);
    memcpy(p + LINK_RESULT_FIXED_SIZE, text, sizeof text - 1);
    peer_send(peer, LINK_RESULT, p, LINK_RESULT_FIXED_SIZE + sizeof text - 1);
    /* and a report of a frame of ours it dropped, with text */
    wire_put_u16(p, 0);
    peer_send(peer, LINK_RESULT, p, LINK_RESULT_FIXED_SIZE + sizeof text - 1);
    struct board_frame f;
    const uint8_t *fields;
    size_t nf;
    char why[LINK_MAX_PAYLOAD * 4 + 96], err[4096];
    struct capture c;
    capture_begin(&c, STDERR_FILENO);
    int rc = board_wait_ok(&b, CMD_STATUS, 1000, 0, &f, &fields, &nf, why, sizeof why);
    size_t n = capture_end(&c, err, sizeof err);
    CHECK_EQ_INT(rc, -1);
    CHECK(printable(why, strlen(why)));
    CHECK(strstr(why, "no\\x1b[8m hidden") != NULL);
    CHECK(printable(err, n));
    CHECK(strstr(err, "no\\x1b[8m hidden") != NULL);
    CHECK(printable(b.host_drop_text, strlen(b.host_drop_text)));
    board_session_close(&b);
    close(peer);
}

/* The ACK frames the host sent, counted from what waits on the peer. */
static int peer_count_acks(int fd)
{
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    struct link_decoder d;
    link_decoder_init(&d);
    uint8_t buf[4096];
    int acks = 0;
    ssize_t n;
    while ((n = read(fd, buf, sizeof buf)) > 0) {
        for (ssize_t i = 0; i < n; i++) {
            struct link_frame f;
            if (link_decoder_push(&d, buf[i], &f) && f.type == LINK_ACK)
                acks++;
        }
    }
    return acks;
}

/* A 2x2 frame is 12 bytes on the serial path; the board sends 8 KiB and no
 * end: the pull stops at the first byte beyond the frame. */
static void hostile_serial_pull_is_bounded(void)
{
    struct board b;
    int peer;
    session(&b, &peer, 1);
    b.opts.link = LINK_PATH_SERIAL;
    uint8_t chunk[LINK_DATA_CHUNK];
    memset(chunk, 0x55, sizeof chunk);
    for (int i = 0; i < 8; i++)
        peer_send(peer, LINK_DATA, chunk, sizeof chunk);
    struct image img = {0, 0, NULL};
    long long ms = 0, t0 = board_now_ms();
    struct capture c;
    char err[4096];
    capture_begin(&c, STDERR_FILENO);
    int rc = render_session_pull(&b, 2, 2, &img, &ms);
    capture_end(&c, err, sizeof err);
    long long took = board_now_ms() - t0;
    CHECK_EQ_INT(rc, -1);
    CHECK(img.rgb == NULL);
    CHECK(took < 5000);
    CHECK(peer_count_acks(peer) == 0);
    CHECK(strstr(err, "more than the frame's 12 bytes") != NULL);
    if (!strstr(err, "more than the frame's 12 bytes"))
        printf("    stderr: %s\n", err);
    image_free(&img);
    board_session_close(&b);
    close(peer);
}

/* In a child, so that the signal, if it comes, ends the child and not the
 * test: a command to a board whose end is closed fails with an error. */
static void hostile_dead_peer_is_no_sigpipe(void)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        signal(SIGPIPE, SIG_DFL); /* as a new program starts */
        struct board b;
        int peer;
        if (fake_session(&b, &peer) != 0)
            _exit(3);
        close(peer);
        int rc = board_send_cmd(&b, CMD_STATUS, NULL, 0);
        board_session_close(&b);
        _exit(rc == -1 ? 0 : 4);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    CHECK(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    if (WIFSIGNALED(st))
        printf("    the session was killed by signal %d\n", WTERMSIG(st));
}

int main(void)
{
    RUN(hostile_log_text_is_escaped);
    RUN(hostile_fault_text_is_escaped);
    RUN(hostile_refusal_text_is_escaped);
    RUN(hostile_serial_pull_is_bounded);
    RUN(hostile_dead_peer_is_no_sigpipe);
    return check_exit();
}
