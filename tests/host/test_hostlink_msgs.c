/* Host tests of the host-link message encodings: HELLO and FAULT payloads
 * (proto/hostlink.c) and the host tool's CMD and RESULT frames
 * (host-tools/link/board.c), each pinned to a literal byte string so that host
 * and firmware cannot drift apart unnoticed; and the host's side of the
 * retransmission (proto/link_arq.h): a damaged or missing frame asked for
 * with LINK_NAK, a silent board polled, our frames resent on the board's NAK. */
#include <fcntl.h>
#include <poll.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "host-tools/link/board.h"
#include "host-tools/link/board_arq.h"
#include "proto/hostlink.h"
#include "proto/wire.h"
#include "tests/check.h"
#include "tests/host/fake_board.h"

static void msg_hello_layout_and_round_trip(void)
{
    struct link_hello h = {.core = 0x0105, .role = ROLE_NC, .variant = 1,
                           .mpidr = 0x80000105u, .ncores = 0x010a, .reserved = 0};
    static const uint8_t want[LINK_HELLO_SIZE] = {0x05, 0x01, 0x02, 0x01, 0x05, 0x01,
                                                  0x00, 0x80, 0x0a, 0x01, 0x00, 0x00};
    uint8_t p[LINK_HELLO_SIZE + 1];
    p[LINK_HELLO_SIZE] = 0xee;
    link_hello_put(p, &h);
    CHECK(memcmp(p, want, sizeof want) == 0);
    CHECK_EQ_INT(p[LINK_HELLO_SIZE], 0xee); /* nothing written past the payload */
    struct link_hello g;
    link_hello_get(want, &g);
    CHECK_EQ_INT(g.core, h.core);
    CHECK_EQ_INT(g.role, h.role);
    CHECK_EQ_INT(g.variant, h.variant);
    CHECK_EQ_INT(g.mpidr, h.mpidr);
    CHECK_EQ_INT(g.ncores, h.ncores);
}

static void msg_fault_layout_and_round_trip(void)
{
    struct link_fault f = {.core = 7, .role = ROLE_NC, .kind = FAULT_UNDEF,
                           .addr = 0x40012344u, .pc = 0x40012348u, .status = 0x0000000du};
    static const uint8_t want[LINK_FAULT_FIXED_SIZE] = {
        0x07, 0x00, 0x02, 0x01, 0x44, 0x23, 0x01, 0x40,
        0x48, 0x23, 0x01, 0x40, 0x0d, 0x00, 0x00, 0x00};
    uint8_t p[LINK_FAULT_FIXED_SIZE];
    link_fault_put(p, &f);
    CHECK(memcmp(p, want, sizeof want) == 0);
    struct link_fault g;
    link_fault_get(want, &g);
    CHECK_EQ_INT(g.core, 7);
    CHECK_EQ_INT(g.role, ROLE_NC);
    CHECK_EQ_INT(g.kind, FAULT_UNDEF);
    CHECK_EQ_INT(g.addr, 0x40012344u);
    CHECK_EQ_INT(g.pc, 0x40012348u);
    CHECK_EQ_INT(g.status, 13);
}

/* LINK_BULK: offset, length, crc, each a little-endian u32. */
static void msg_bulk_layout_and_round_trip(void)
{
    struct link_bulk k = {.offset = 0x03812340u, .length = 0x00300000u, .sum = 0xcbf43926u};
    static const uint8_t want[LINK_BULK_SIZE] = {
        0x40, 0x23, 0x81, 0x03, 0x00, 0x00, 0x30, 0x00, 0x26, 0x39, 0xf4, 0xcb};
    uint8_t p[LINK_BULK_SIZE + 1];
    p[LINK_BULK_SIZE] = 0xee;
    link_bulk_put(p, &k);
    CHECK(memcmp(p, want, sizeof want) == 0);
    CHECK_EQ_INT(p[LINK_BULK_SIZE], 0xee);
    struct link_bulk g;
    link_bulk_get(want, &g);
    CHECK_EQ_INT(g.offset, k.offset);
    CHECK_EQ_INT(g.length, k.length);
    CHECK_EQ_INT(g.sum, k.sum);
}

static void msg_cmd_frame_bytes_are_pinned(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    uint8_t args[4] = {64, 0, 0, 0};
    CHECK_EQ_INT(board_send_cmd(&b, CMD_LINE_STRESS, args, sizeof args), 0);
    /* 'L' '1', type 4 (CMD), flags 0, seq 0, length 6, cmd 4, u32 64, crc32. */
    static const uint8_t want[] = {'L', '1', 4, 0, 0, 0, 6, 0, 4, 0, 64, 0, 0, 0,
                                   0xbc, 0xee, 0x39, 0xbe};
    uint8_t got[64];
    ssize_t n = read(peer, got, sizeof got);
    CHECK_EQ_INT(n, sizeof want);
    CHECK(n == sizeof want && memcmp(got, want, sizeof want) == 0);
    CHECK_EQ_INT(b.tx_seq, 1);
    close(peer);
    board_session_close(&b);
}

static void msg_result_frame_is_parsed(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    uint8_t frame[64], payload[16] = {2, 0, 0xfd, 0xff}; /* cmd 2, status -3 */
    memcpy(payload + 4, "no line", 7);
    size_t n = link_frame_encode(frame, sizeof frame, LINK_RESULT, 0, 0, payload, 11);
    CHECK(write(peer, frame, n) == (ssize_t)n);
    struct board_frame r;
    int status = 0;
    const uint8_t *fields = NULL;
    size_t nf = 0;
    CHECK_EQ_INT(board_wait_result(&b, CMD_LINE_PING, 2000, &r, &status, &fields, &nf), 0);
    CHECK_EQ_INT(status, -3);
    CHECK_EQ_INT(nf, 7);
    CHECK(fields && memcmp(fields, "no line", 7) == 0);
    /* A result for another command than the one awaited is an error. */
    n = link_frame_encode(frame, sizeof frame, LINK_RESULT, 0, 1, payload, 4);
    CHECK(write(peer, frame, n) == (ssize_t)n);
    CHECK_EQ_INT(board_wait_result(&b, CMD_STATUS, 2000, &r, &status, &fields, &nf), -1);
    close(peer);
    board_session_close(&b);
}

/* A RESULT for cmd 0 is the board reporting a frame from the host it
 * dropped: counted as a link error, never taken as a command's answer. */
static void msg_dropped_frame_report_is_counted(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    uint8_t frame[64], p[16] = {0, 0, 0xfd, 0xff}; /* cmd 0, LINK_ERR_BAD_FRAME */
    memcpy(p + 4, "seq gap", 7);
    size_t n = link_frame_encode(frame, sizeof frame, LINK_RESULT, 0, 0, p, 11);
    CHECK(write(peer, frame, n) == (ssize_t)n);
    uint8_t answer[8] = {2, 0, 0, 0, 9, 0, 0, 0}; /* cmd 2 ok, u32 9 */
    n = link_frame_encode(frame, sizeof frame, LINK_RESULT, 0, 1, answer, sizeof answer);
    CHECK(write(peer, frame, n) == (ssize_t)n);
    struct board_frame r;
    int status = -1;
    const uint8_t *fields = NULL;
    size_t nf = 0;
    CHECK_EQ_INT(board_wait_result(&b, CMD_LINE_PING, 2000, &r, &status, &fields, &nf), 0);
    CHECK_EQ_INT(status, 0);
    CHECK_EQ_INT(nf, 4);
    CHECK_EQ_INT(b.host_frames_dropped, 1);
    CHECK_EQ_INT(board_link_errors(&b), 1);
    close(peer);
    board_session_close(&b);
}

/* Reads the frames the host sent to the fake board within ms; returns how
 * many were put in out (at most max). */
static int peer_frames(int peer, int ms, struct board_frame *out, int max)
{
    static struct link_decoder d;
    static int d_ready;
    if (!d_ready) {
        link_decoder_init(&d);
        d_ready = 1;
    }
    int got = 0;
    struct pollfd p = {.fd = peer, .events = POLLIN};
    while (got < max && poll(&p, 1, ms) > 0) {
        uint8_t buf[4096];
        ssize_t n = read(peer, buf, sizeof buf);
        if (n <= 0)
            break;
        for (ssize_t i = 0; i < n && got < max; i++) {
            struct link_frame f;
            if (!link_decoder_push(&d, buf[i], &f))
                continue;
            out[got].type = f.type;
            out[got].flags = f.flags;
            out[got].seq = f.seq;
            out[got].length = f.length;
            memcpy(out[got].payload, f.payload, f.length);
            got++;
        }
        ms = 50;
    }
    return got;
}

/* A damaged frame from the board: the host asks for it again (LINK_NAK
 * naming the seq it expects) and takes the frame sent again, exactly once. */
static void msg_damaged_frame_is_asked_for_again(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    b.arq->rx.known = 1; /* a board booted by us: its frames from seq 0 */
    uint8_t frame[64], answer[8] = {2, 0, 0, 0, 9, 0, 0, 0}; /* cmd 2 ok, u32 9 */
    size_t n = link_frame_encode(frame, sizeof frame, LINK_RESULT, 0, 0, answer, sizeof answer);
    frame[9] ^= 0x10;
    CHECK(write(peer, frame, n) == (ssize_t)n);
    board_pump(&b, 100);
    struct board_frame got[4];
    int k = peer_frames(peer, 200, got, 4);
    CHECK(k >= 1);
    CHECK_EQ_INT(got[0].type, LINK_NAK);
    CHECK_EQ_INT(wire_get_u16(got[0].payload), 0);
    CHECK_EQ_INT(board_queued(&b), 0);
    frame[9] ^= 0x10; /* sent again, whole */
    CHECK(write(peer, frame, n) == (ssize_t)n);
    CHECK(write(peer, frame, n) == (ssize_t)n); /* and once more: a repeat */
    struct board_frame r;
    int status = -1;
    const uint8_t *fields = NULL;
    size_t nf = 0;
    CHECK_EQ_INT(board_wait_result(&b, CMD_LINE_PING, 2000, &r, &status, &fields, &nf), 0);
    CHECK_EQ_INT(status, 0);
    board_pump(&b, 100);
    CHECK_EQ_INT(board_queued(&b), 0); /* the repeat was dropped */
    CHECK_EQ_INT(b.frames_dropped_dup, 1);
    CHECK_EQ_INT(board_arq_failed(&b), 0);
    close(peer);
    board_session_close(&b);
}

/* A frame after a gap is held back (not handled out of order) and the lost
 * one asked for; a silent board is then polled (LINK_FLAG_POLL). */
static void msg_gap_is_asked_for_and_silence_polled(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    b.arq->rx.known = 1; /* a board booted by us: its frames from seq 0 */
    uint8_t frame[64], answer[8] = {2, 0, 0, 0, 9, 0, 0, 0};
    size_t n = link_frame_encode(frame, sizeof frame, LINK_RESULT, 0, 1, answer, sizeof answer);
    CHECK(write(peer, frame, n) == (ssize_t)n); /* seq 1: seq 0 was lost */
    board_pump(&b, 100);
    CHECK_EQ_INT(board_queued(&b), 0);
    struct board_frame got[4];
    CHECK(peer_frames(peer, 200, got, 4) >= 1);
    CHECK_EQ_INT(got[0].type, LINK_NAK);
    CHECK_EQ_INT(got[0].flags & LINK_FLAG_POLL, 0);
    CHECK_EQ_INT(wire_get_u16(got[0].payload), 0);
    long long t0 = board_now_ms();
    while (board_now_ms() - t0 < LINK_ARQ_POLL_MS + 200)
        board_pump(&b, 50);
    int k = peer_frames(peer, 100, got, 4);
    CHECK(k >= 1);
    CHECK_EQ_INT(got[0].type, LINK_NAK);
    CHECK(got[0].flags & LINK_FLAG_POLL);
    CHECK_EQ_INT(wire_get_u16(got[0].payload), 0);
    close(peer);
    board_session_close(&b);
}

/* A NAK from the board: the host sends its kept frames again, the same
 * bytes; a NAK for a frame it does not hold ends the link with an error. */
static void msg_board_nak_gets_our_frames_again(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    CHECK_EQ_INT(board_send_cmd(&b, CMD_STATUS, NULL, 0), 0);
    CHECK_EQ_INT(board_send_cmd(&b, CMD_LINE_PING, NULL, 0), 0);
    struct board_frame first[4], again[4];
    CHECK_EQ_INT(peer_frames(peer, 200, first, 4), 2);
    uint8_t nak[16];
    size_t n = link_arq_nak_encode(nak, sizeof nak, 0, 0);
    CHECK(write(peer, nak, n) == (ssize_t)n);
    board_pump(&b, 100);
    CHECK_EQ_INT(peer_frames(peer, 200, again, 4), 2);
    for (int i = 0; i < 2; i++) {
        CHECK_EQ_INT(again[i].seq, first[i].seq);
        CHECK_EQ_INT(again[i].length, first[i].length);
        CHECK(memcmp(again[i].payload, first[i].payload, first[i].length) == 0);
    }
    CHECK_EQ_INT(b.frames_resent, 2);
    n = link_arq_nak_encode(nak, sizeof nak, 0, 7); /* never sent */
    CHECK(write(peer, nak, n) == (ssize_t)n);
    board_pump(&b, 100);
    CHECK_EQ_INT(board_arq_failed(&b), 1);
    CHECK_EQ_INT(board_pump(&b, 10), -1);
    CHECK_EQ_INT(peer_frames(peer, 200, again, 4), 1);
    CHECK_EQ_INT(again[0].type, LINK_NAK);
    CHECK(again[0].flags & LINK_FLAG_GONE);
    close(peer);
    board_session_close(&b);
}

/* A frame of ours the board keeps asking for: the host gives up after
 * LINK_ARQ_MAX_ASKS resends, with an error, rather than resending forever. */
static void msg_host_gives_up_on_a_frame_that_never_arrives(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    CHECK_EQ_INT(board_send_cmd(&b, CMD_STATUS, NULL, 0), 0);
    uint8_t nak[16];
    size_t n = link_arq_nak_encode(nak, sizeof nak, 0, 0);
    for (int i = 0; i < LINK_ARQ_MAX_ASKS; i++)
        CHECK(write(peer, nak, n) == (ssize_t)n);
    for (int i = 0; i < 10; i++)
        board_pump(&b, 20);
    CHECK_EQ_INT(board_arq_failed(&b), 0);
    CHECK_EQ_INT(b.frames_resent, LINK_ARQ_MAX_ASKS);
    CHECK(write(peer, nak, n) == (ssize_t)n);
    board_pump(&b, 100);
    CHECK_EQ_INT(board_arq_failed(&b), 1);
    close(peer);
    board_session_close(&b);
    /* What the session saw outlives it: the command's summary and exit
     * status are decided after the board is stopped. */
    CHECK_EQ_INT(board_arq_failed(&b), 1);
    CHECK_EQ_INT(b.frames_resent, LINK_ARQ_MAX_ASKS);
    CHECK(board_report_link_errors(&b) > 0 || b.frames_resent > 0);
    CHECK_EQ_INT(board_send_cmd(&b, CMD_STATUS, NULL, 0), -1); /* closed: refused */
}

/* A frame whose length field was spoilt keeps the decoder waiting with no
 * damage shown: on a link seen damaged, after LINK_ARQ_STALL_MS without a
 * byte the host gives the partial frame up and polls (after zero bytes that
 * would complete the board's own such frame); on a link never seen damaged
 * it waits LINK_ARQ_STALL_CLEAN_MS, so a slow emulator is not polled. */
static void msg_stalled_partial_frame_leads_to_a_poll(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    b.arq->rx.known = 1;
    uint8_t frame[64], answer[8] = {2, 0, 0, 0, 9, 0, 0, 0};
    size_t n = link_frame_encode(frame, sizeof frame, LINK_RESULT, 0, 0, answer, sizeof answer);
    wire_put_u16(frame + 6, 2000); /* the length field spoilt */
    CHECK(write(peer, frame, n) == (ssize_t)n);
    long long t0 = board_now_ms();
    while (board_now_ms() - t0 < LINK_ARQ_STALL_MS + 300)
        board_pump(&b, 50);
    struct board_frame got[4];
    CHECK_EQ_INT(peer_frames(peer, 50, got, 4), 0); /* clean link: nothing yet */
    CHECK(LINK_ARQ_STALL_CLEAN_MS > LINK_ARQ_STALL_MS + 300);
    b.arq->damage_seen = 1; /* now as on a link seen damaged */
    t0 = board_now_ms();
    while (board_now_ms() - t0 < 300)
        board_pump(&b, 50);
    CHECK(peer_frames(peer, 200, got, 4) >= 1);
    CHECK_EQ_INT(got[0].type, LINK_NAK);
    CHECK(got[0].flags & LINK_FLAG_POLL);
    CHECK_EQ_INT(wire_get_u16(got[0].payload), 0);
    CHECK_EQ_INT(b.dec.have, 0);
    CHECK_EQ_INT(b.dec.stats.stalls, 1);
    close(peer);
    board_session_close(&b);
}

/* The board's answer to a poll that names our next frame (it lacks nothing)
 * while we lack nothing either ends the polling: an idle board is not sent
 * zero bytes every LINK_ARQ_POLL_MS for ever. */
static void msg_poll_answered_in_step_stops_polling(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    b.arq->rx.known = 1;
    b.arq->naks_heard = 1; /* as on a board we booted */
    b.arq->armed = b.arq->damage_seen = 1;
    long long t0 = board_now_ms();
    while (board_now_ms() - t0 < LINK_ARQ_POLL_MS + 100)
        board_pump(&b, 50);
    struct board_frame got[4];
    CHECK(peer_frames(peer, 200, got, 4) >= 1); /* polled */
    CHECK(got[0].flags & LINK_FLAG_POLL);
    uint8_t nak[LINK_HEADER_SIZE + LINK_ACK_SIZE + LINK_CRC_SIZE];
    size_t n = link_arq_nak_encode(nak, sizeof nak, 0, b.arq->tx.next_seq);
    CHECK(write(peer, nak, n) == (ssize_t)n);
    board_pump(&b, 100);
    CHECK_EQ_INT(b.arq->armed, 0);
    t0 = board_now_ms();
    while (board_now_ms() - t0 < 2 * LINK_ARQ_POLL_MS)
        board_pump(&b, 50);
    CHECK_EQ_INT(peer_frames(peer, 50, got, 4), 0); /* no more polls */
    close(peer);
    board_session_close(&b);
}

static void msg_hello_and_fault_are_recorded(void)
{
    struct board b;
    int peer;
    CHECK(fake_session(&b, &peer) == 0);
    b.opts.ncores = 3;
    uint8_t frame[64], p[LINK_FAULT_FIXED_SIZE + 4];
    struct link_hello h = {.core = 2, .role = ROLE_NC, .variant = 0, .ncores = 3};
    link_hello_put(p, &h);
    size_t n = link_frame_encode(frame, sizeof frame, LINK_HELLO, 0, 0, p, LINK_HELLO_SIZE);
    CHECK(write(peer, frame, n) == (ssize_t)n);
    h.core = 1; /* core 1 claiming to be an NC: a wrong role */
    link_hello_put(p, &h);
    n = link_frame_encode(frame, sizeof frame, LINK_HELLO, 0, 1, p, LINK_HELLO_SIZE);
    CHECK(write(peer, frame, n) == (ssize_t)n);
    struct link_fault f = {.core = 2, .role = ROLE_NC, .kind = FAULT_UNDEF, .addr = 0x40001000};
    link_fault_put(p, &f);
    memcpy(p + LINK_FAULT_FIXED_SIZE, "udf!", 4);
    n = link_frame_encode(frame, sizeof frame, LINK_FAULT, 0, 2, p, sizeof p);
    CHECK(write(peer, frame, n) == (ssize_t)n);
    for (int i = 0; i < 20 && b.nfaults == 0; i++)
        board_pump(&b, 100);
    CHECK_EQ_INT(b.reported_count, 1);
    CHECK_EQ_INT(b.reported[2], 1);
    CHECK_EQ_INT(b.hello_errors, 1);
    CHECK_EQ_INT(b.nfaults, 1);
    CHECK_EQ_INT(b.faults[0].addr, 0x40001000u);
    close(peer);
    board_session_close(&b);
}

int main(void)
{
    RUN(msg_hello_layout_and_round_trip);
    RUN(msg_fault_layout_and_round_trip);
    RUN(msg_bulk_layout_and_round_trip);
    RUN(msg_cmd_frame_bytes_are_pinned);
    RUN(msg_result_frame_is_parsed);
    RUN(msg_dropped_frame_report_is_counted);
    RUN(msg_damaged_frame_is_asked_for_again);
    RUN(msg_gap_is_asked_for_and_silence_polled);
    RUN(msg_board_nak_gets_our_frames_again);
    RUN(msg_host_gives_up_on_a_frame_that_never_arrives);
    RUN(msg_stalled_partial_frame_leads_to_a_poll);
    RUN(msg_poll_answered_in_step_stops_polling);
    RUN(msg_hello_and_fault_are_recorded);
    return check_exit();
}
