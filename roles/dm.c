/* dm.c: the data manipulator (DM) program: the unit computer that talks to
 * the host.  Two cooperative tasks:
 *   "hostrx"  drains the UART receive ring through the frame decoder and
 *             queues whole frames (reporting dropped frames at once);
 *   "dmcmd"   takes queued frames and carries out the host's commands,
 *             asking the RC (and through it the NCs) over the serial lines.
 * A full queue stops hostrx, which stops draining the UART ring, which
 * pauses the UART's receive interrupt: back-pressure reaches the host
 * without losing a byte. */
#include <stdint.h>
#include <string.h>

#include "drivers/imsu/imsu.h"
#include "drivers/serial/hostlink_tx.h"
#include "drivers/serial/line.h"
#include "drivers/serial/uart.h"
#include "kernel/cpu.h"
#include "kernel/kmem.h"
#include "kernel/klog.h"
#include "kernel/ktime.h"
#include "kernel/memlayout.h"
#include "kernel/psci.h"
#include "kernel/ringbuf.h"
#include "kernel/task.h"
#include "proto/crc32.h"
#include "proto/hostlink.h"
#include "proto/wire.h"
#include "roles/selftest.h"
#include "roles/unit.h"
#include "roles/unitmsg.h"

/* Queued frame record: u8 type, u8 flags, u16 seq, u16 length, payload. */
#define DM_REC_HEADER 6

struct dm_frame {
    uint8_t type, flags;
    uint16_t seq, length;
    uint8_t payload[LINK_MAX_PAYLOAD];
};

static struct ringbuf dm_queue;      /* hostrx -> dmcmd */
static struct link_decoder dm_dec;   /* host -> board frames */
static struct dm_frame dm_frame;     /* the frame dmcmd works on */
static struct line_msg dm_msg;       /* the DM's line message buffer */
static uint32_t dm_link_errors;      /* frames dropped so far (host -> board) */

/* ------------------------------------------------------------ hostrx */

static uint32_t dm_decoder_errors(void)
{
    const struct link_stats *s = &dm_dec.stats;
    return s->crc_errors + s->bad_length + s->seq_gaps;
}

static void dm_queue_frame(const struct link_frame *f)
{
    uint8_t hdr[DM_REC_HEADER];
    hdr[0] = f->type;
    hdr[1] = f->flags;
    wire_put_u16(hdr + 2, f->seq);
    wire_put_u16(hdr + 4, f->length);
    uint32_t need = DM_REC_HEADER + f->length;
    for (;;) {
        uint32_t mark = task_event_mark();
        if (ringbuf_free(&dm_queue) >= need)
            break;
        task_wait(mark, 0);
    }
    /* Header and payload go in as two puts: the reader waits for the whole
     * record (it reads the length first), and only this task puts. */
    ringbuf_put(&dm_queue, hdr, DM_REC_HEADER);
    ringbuf_put(&dm_queue, f->payload, f->length);
    task_signal_local();
}

static void dm_hostrx(void *arg)
{
    (void)arg;
    uint8_t buf[256];
    struct link_frame f;
    link_decoder_init(&dm_dec);
    for (;;) {
        uint32_t mark = task_event_mark();
        uint32_t n = uart_rx_read(buf, sizeof buf);
        if (n == 0) {
            task_wait(mark, 0);
            continue;
        }
        for (uint32_t i = 0; i < n; i++) {
            uint32_t before = dm_decoder_errors();
            int got = link_decoder_push(&dm_dec, buf[i], &f);
            uint32_t after = dm_decoder_errors();
            if (after != before) {
                dm_link_errors += after - before;
                const struct link_stats *s = &dm_dec.stats;
                hostlink_error(0, LINK_ERR_BAD_FRAME,
                               "host link: frame dropped or missing (bad CRC %u, bad length %u, "
                               "seq gaps %u so far)",
                               (unsigned)s->crc_errors, (unsigned)s->bad_length,
                               (unsigned)s->seq_gaps);
            }
            if (got)
                dm_queue_frame(&f);
        }
    }
}

/* ------------------------------------------------------------ dmcmd */

/* Takes the next queued frame into dm_frame; 0, or -1 at deadline. */
static int dm_next_frame(uint64_t deadline)
{
    uint8_t hdr[DM_REC_HEADER];
    for (;;) {
        uint32_t mark = task_event_mark();
        if (ringbuf_peek(&dm_queue, hdr, DM_REC_HEADER) == 0 &&
            ringbuf_used(&dm_queue) >= DM_REC_HEADER + (uint32_t)wire_get_u16(hdr + 4))
            break;
        if (ktime_passed(deadline))
            return -1;
        task_wait(mark, deadline);
    }
    ringbuf_get(&dm_queue, hdr, DM_REC_HEADER);
    dm_frame.type = hdr[0];
    dm_frame.flags = hdr[1];
    dm_frame.seq = wire_get_u16(hdr + 2);
    dm_frame.length = wire_get_u16(hdr + 4);
    ringbuf_get(&dm_queue, dm_frame.payload, dm_frame.length);
    task_signal_local(); /* hostrx may be waiting for room */
    return 0;
}

static int dm_rc_request(struct line_msg *m, uint16_t answer_type, uint32_t timeout_ms)
{
    int r = line_send(RC_CORE, m, ktime_deadline_ms(timeout_ms));
    if (r != LINE_OK)
        return r;
    return selftest_recv_type(RC_CORE, answer_type, m, ktime_deadline_ms(timeout_ms));
}

static void dm_cmd_status(uint16_t cmd)
{
    uint8_t f[6];
    wire_put_u16(f, (uint16_t)board_ncores);
    wire_put_u16(f + 2, (uint16_t)unit_reported_count());
    wire_put_u16(f + 4, (uint16_t)unit_halted_count());
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

static void dm_cmd_line_ping(uint16_t cmd)
{
    struct line_msg *m = &dm_msg;
    uint32_t total = line_count(), ok = 0;
    msg_set(m, MSG_PING, 4);
    wire_put_u32(m->payload, 0xD0D0u);
    int r = dm_rc_request(m, MSG_PONG, PING_TIMEOUT_MS);
    if (r != LINE_OK || wire_get_u32(m->payload) != 0xD0D0u) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "line DM<->RC: no pong (%s)", line_strerror(r));
        return;
    }
    ok++;
    msg_set(m, MSG_PING_NCS, 0);
    r = dm_rc_request(m, MSG_PING_NCS_DONE, PING_TIMEOUT_MS + REPLY_TIMEOUT_MS);
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "RC did not report its NC pings (%s)",
                       line_strerror(r));
        return;
    }
    ok += wire_get_u32(m->payload);
    uint32_t first_bad = wire_get_u32(m->payload + 8);
    if (ok != total) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT,
                       "%u of %u serial lines answered; first silent: RC<->core %u",
                       (unsigned)ok, (unsigned)total, (unsigned)first_bad);
        return;
    }
    uint8_t f[8];
    wire_put_u32(f, ok);
    wire_put_u32(f + 4, total);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

/* IMSU pair both ways (with misuse checks), then the broadcast block. */
static void dm_cmd_imsu_test(uint16_t cmd)
{
    struct imsu_pair *p = &imsu_dm_rc;
    struct line_msg *m = &dm_msg;
    const uint32_t bytes = IMSU_TEST_PAIR_BYTES;
    const uint32_t seed_out = 0xA11CE000u + p->swaps, seed_back = 0xB0B00000u + p->swaps;
    uint32_t blocks_ok = 0, misuse_failed = 0;

    int held = imsu_held(p, DM_CORE);
    uint8_t *w;
    int r = imsu_write_begin(p, DM_CORE, held, &w);
    if (r != IMSU_OK) {
        hostlink_error(cmd, LINK_ERR_CHECK, "IMSU: DM cannot write its own block: %s",
                       imsu_strerror(r));
        return;
    }
    selftest_fill(w, bytes, seed_out, 0);
    uint32_t crc_out = crc32(w, bytes);
    imsu_write_end(p, DM_CORE);
    r = imsu_swap(p, DM_CORE);
    if (r != IMSU_OK) {
        hostlink_error(cmd, LINK_ERR_CHECK, "IMSU: swap DM->RC refused: %s", imsu_strerror(r));
        return;
    }
    /* The block went to the RC: writing it now must be refused. */
    if (imsu_write_begin(p, DM_CORE, held, &w) != IMSU_ERR_NOT_HOLDER) {
        misuse_failed++;
        imsu_write_end(p, DM_CORE);
    }
    msg_set(m, MSG_IMSU_PAIR, 12);
    wire_put_u32(m->payload, bytes);
    wire_put_u32(m->payload + 4, crc_out);
    wire_put_u32(m->payload + 8, seed_back);
    r = dm_rc_request(m, MSG_IMSU_MIDWRITE, REPLY_TIMEOUT_MS);
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "IMSU: RC did not start its write (%s)",
                       line_strerror(r));
        return;
    }
    /* The RC is inside its write: our swap must be refused. */
    int swap_st = imsu_swap(p, DM_CORE);
    msg_set(m, MSG_IMSU_MIDWRITE_SEEN, 4);
    wire_put_u32(m->payload, (uint32_t)swap_st);
    r = dm_rc_request(m, MSG_IMSU_PAIR_DONE, REPLY_TIMEOUT_MS);
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "IMSU: RC did not finish the pair test (%s)",
                       line_strerror(r));
        return;
    }
    int32_t rc_status = (int32_t)wire_get_u32(m->payload);
    uint32_t crc_back = wire_get_u32(m->payload + 4);
    misuse_failed += wire_get_u32(m->payload + 8);
    blocks_ok += wire_get_u32(m->payload + 12); /* RC saw our block intact */
    if (rc_status != IMSU_OK) {
        hostlink_error(cmd, LINK_ERR_CHECK, "IMSU: RC side failed: %s", imsu_strerror(rc_status));
        return;
    }
    const uint8_t *back = imsu_read_block(p, DM_CORE);
    if (imsu_held(p, DM_CORE) == held && crc32(back, bytes) == crc_back &&
        selftest_check(back, bytes, seed_back, 0) == 0)
        blocks_ok++;

    msg_set(m, MSG_IMSU_BCAST, 8);
    wire_put_u32(m->payload, IMSU_TEST_BCAST_BYTES);
    wire_put_u32(m->payload + 4, seed_out ^ 0xCA57u);
    r = dm_rc_request(m, MSG_IMSU_BCAST_DONE, REPLY_TIMEOUT_MS * 2);
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "IMSU: RC did not finish the broadcast (%s)",
                       line_strerror(r));
        return;
    }
    uint32_t ncs_ok = wire_get_u32(m->payload), ncs = wire_get_u32(m->payload + 4);
    misuse_failed += wire_get_u32(m->payload + 8);
    blocks_ok += ncs_ok;
    uint32_t expected = 2 + ncs;
    if (blocks_ok != expected || misuse_failed) {
        hostlink_error(cmd, LINK_ERR_CHECK,
                       "IMSU: %u of %u blocks arrived intact (pair both ways + %u NC reads); "
                       "%u misuse checks not refused",
                       (unsigned)blocks_ok, (unsigned)expected, (unsigned)ncs,
                       (unsigned)misuse_failed);
        return;
    }
    uint8_t f[8];
    wire_put_u32(f, blocks_ok);
    wire_put_u32(f + 4, expected);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

static void dm_cmd_line_stress(uint16_t cmd)
{
    if (dm_frame.length < 2 + 4) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_LINE_STRESS needs u32 MiB (4 bytes), got %u",
                       (unsigned)(dm_frame.length - 2));
        return;
    }
    uint32_t mib = wire_get_u32(dm_frame.payload + 2);
    if (mib == 0 || mib > STRESS_MAX_MIB) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_LINE_STRESS: %u MiB is outside 1..%u",
                       (unsigned)mib, (unsigned)STRESS_MAX_MIB);
        return;
    }
    /* Both directions of every live line carry an equal share. */
    uint32_t live = line_count();
    for (uint32_t k = FIRST_NC; k < board_ncores; k++)
        live -= (uint32_t)unit_is_halted(k);
    uint64_t total = (uint64_t)mib << 20;
    uint64_t per_stream = (total + 2u * live - 1) / (2u * live);
    uint32_t msgs = (uint32_t)((per_stream + LINE_MAX_PAYLOAD - 1) / LINE_MAX_PAYLOAD);

    struct line_msg *m = &dm_msg;
    msg_set(m, MSG_STRESS, 4);
    wire_put_u32(m->payload, msgs);
    int r = line_send(RC_CORE, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "stress: cannot reach the RC (%s)", line_strerror(r));
        return;
    }
    struct stress_stream s[2];
    stress_stream_init(&s[0], RC_CORE, 1, msgs);
    stress_stream_init(&s[1], RC_CORE, 0, msgs);
    int stalled = stress_run(s, 2);
    r = selftest_recv_type(RC_CORE, MSG_STRESS_REPORT, m, ktime_deadline_ms(STRESS_STALL_MS * 2));
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "stress: no report from the RC (%s)",
                       line_strerror(r));
        return;
    }
    uint64_t bytes = s[1].bytes + wire_get_u64(m->payload);
    uint32_t errors = s[1].errors + s[1].left + wire_get_u32(m->payload + 8);
    uint32_t skipped = wire_get_u32(m->payload + 12);
    if (errors || stalled || bytes < total) {
        hostlink_error(cmd, LINK_ERR_CHECK,
                       "stress: %u errors, %u KiB of %u KiB checked%s",
                       (unsigned)errors, (unsigned)(bytes >> 10), (unsigned)(total >> 10),
                       stalled ? ", a line stalled" : "");
        return;
    }
    uint8_t f[16];
    wire_put_u64(f, bytes);
    wire_put_u32(f + 8, errors);
    wire_put_u32(f + 12, skipped);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

/* Host -> board bulk transfer: ACK every DATA frame, check the pattern. */
static void dm_cmd_link_sink(uint16_t cmd)
{
    uint64_t bytes = 0;
    uint32_t crc = 0, differ = 0, errors_before = dm_link_errors;
    for (;;) {
        if (dm_next_frame(ktime_deadline_ms(LINK_ACK_TIMEOUT_MS)) != 0) {
            hostlink_error(cmd, LINK_ERR_TIMEOUT,
                           "sink: no DATA frame for %u ms after %u bytes",
                           (unsigned)LINK_ACK_TIMEOUT_MS, (unsigned)bytes);
            return;
        }
        if (dm_frame.type != LINK_DATA) {
            hostlink_error(cmd, LINK_ERR_PROTOCOL,
                           "sink: frame type %u in the middle of a transfer, after %u bytes",
                           (unsigned)dm_frame.type, (unsigned)bytes);
            return;
        }
        for (uint32_t i = 0; i < dm_frame.length; i++)
            differ += dm_frame.payload[i] != link_pattern_byte((uint32_t)bytes + i);
        crc = crc32_update(crc, dm_frame.payload, dm_frame.length);
        bytes += dm_frame.length;
        uint8_t ack[LINK_ACK_SIZE];
        wire_put_u16(ack, dm_frame.seq);
        hostlink_send(LINK_ACK, 0, ack, sizeof ack);
        if (dm_frame.flags & LINK_FLAG_LAST)
            break;
    }
    uint32_t dropped = dm_link_errors - errors_before;
    if (differ || dropped) {
        hostlink_error(cmd, LINK_ERR_CHECK,
                       "sink: %u bytes, %u differ from the pattern, %u frames dropped, crc 0x%08x",
                       (unsigned)bytes, (unsigned)differ, (unsigned)dropped, (unsigned)crc);
        return;
    }
    uint8_t f[16];
    wire_put_u64(f, bytes);
    wire_put_u32(f + 8, crc);
    wire_put_u32(f + 12, differ);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

/* Board -> host bulk transfer with at most LINK_DATA_WINDOW frames unACKed. */
static void dm_cmd_link_source(uint16_t cmd)
{
    if (dm_frame.length < 2 + 4) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_LINK_SOURCE needs u32 bytes (4 bytes), got %u",
                       (unsigned)(dm_frame.length - 2));
        return;
    }
    uint32_t total = wire_get_u32(dm_frame.payload + 2);
    uint16_t inflight[LINK_DATA_WINDOW];
    uint32_t head = 0, count = 0, sent = 0, crc = 0;
    static uint8_t chunk[LINK_DATA_CHUNK];
    while (sent < total || count) {
        if (sent < total && count < LINK_DATA_WINDOW) {
            uint32_t n = total - sent < LINK_DATA_CHUNK ? total - sent : LINK_DATA_CHUNK;
            for (uint32_t i = 0; i < n; i++)
                chunk[i] = link_pattern_byte(sent + i);
            crc = crc32_update(crc, chunk, n);
            uint8_t flags = sent + n == total ? LINK_FLAG_LAST : 0;
            inflight[(head + count) % LINK_DATA_WINDOW] = hostlink_send(LINK_DATA, flags, chunk, n);
            count++;
            sent += n;
            continue;
        }
        /* Window full (or all sent): wait for an ACK. */
        if (dm_next_frame(ktime_deadline_ms(LINK_ACK_TIMEOUT_MS)) != 0) {
            hostlink_error(cmd, LINK_ERR_TIMEOUT, "source: no ACK for %u ms, %u frames unACKed",
                           (unsigned)LINK_ACK_TIMEOUT_MS, (unsigned)count);
            return;
        }
        if (dm_frame.type != LINK_ACK || dm_frame.length < LINK_ACK_SIZE) {
            hostlink_error(cmd, LINK_ERR_PROTOCOL,
                           "source: expected an ACK, got frame type %u (%u bytes)",
                           (unsigned)dm_frame.type, (unsigned)dm_frame.length);
            return;
        }
        /* An ACK covers every DATA frame up to the seq it names. */
        uint16_t acked = wire_get_u16(dm_frame.payload);
        uint32_t k = 0;
        while (k < count && inflight[(head + k) % LINK_DATA_WINDOW] != acked)
            k++;
        if (k == count) {
            hostlink_error(cmd, LINK_ERR_PROTOCOL, "source: ACK for seq %u, which is not in flight",
                           (unsigned)acked);
            return;
        }
        head = (head + k + 1) % LINK_DATA_WINDOW;
        count -= k + 1;
    }
    uint8_t f[12];
    wire_put_u64(f, total);
    wire_put_u32(f + 8, crc);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

static void dm_cmd_fault_inject(uint16_t cmd)
{
    if (dm_frame.length < 2 + 3) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS,
                       "CMD_FAULT_INJECT needs u16 core, u8 kind (3 bytes), got %u",
                       (unsigned)(dm_frame.length - 2));
        return;
    }
    uint16_t core = wire_get_u16(dm_frame.payload + 2);
    uint8_t kind = wire_get_u8(dm_frame.payload + 4);
    if (core >= board_ncores || !selftest_fault_kind_valid(kind)) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS,
                       "CMD_FAULT_INJECT: core %u (board has %u) or kind %u (1..4, 0x10, 0x11) out of range",
                       (unsigned)core, (unsigned)board_ncores, (unsigned)kind);
        return;
    }
    if (unit_is_halted(core)) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_FAULT_INJECT: core %u has already halted",
                       (unsigned)core);
        return;
    }
    if (core == DM_CORE) {
        hostlink_result(cmd, LINK_OK, NULL, 0);
        selftest_fault_now(kind);
        return;
    }
    struct line_msg *m = &dm_msg;
    msg_set(m, MSG_FAULT, 3);
    wire_put_u16(m->payload, core);
    wire_put_u8(m->payload + 2, kind);
    int r = dm_rc_request(m, MSG_FAULT_ACK, REPLY_TIMEOUT_MS);
    if (r == LINE_OK)
        r = (int32_t)wire_get_u32(m->payload);
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "CMD_FAULT_INJECT: core %u did not confirm (%s)",
                       (unsigned)core, line_strerror(r));
        return;
    }
    hostlink_result(cmd, LINK_OK, NULL, 0);
}

static void dm_cmd_shutdown(uint16_t cmd)
{
    hostlink_result(cmd, LINK_OK, NULL, 0);
    uart_tx_drain();
    psci_call(PSCI_SYSTEM_OFF, 0, 0, 0);
    hostlink_error(cmd, LINK_ERR_PROTOCOL, "PSCI SYSTEM_OFF returned");
}

static void dm_command(void)
{
    if (dm_frame.length < LINK_CMD_FIXED_SIZE) {
        hostlink_error(0, LINK_ERR_BAD_ARGS, "LINK_CMD frame of %u bytes has no command number",
                       (unsigned)dm_frame.length);
        return;
    }
    uint16_t cmd = wire_get_u16(dm_frame.payload);
    switch (cmd) {
    case CMD_STATUS: dm_cmd_status(cmd); break;
    case CMD_LINE_PING: dm_cmd_line_ping(cmd); break;
    case CMD_IMSU_TEST: dm_cmd_imsu_test(cmd); break;
    case CMD_LINE_STRESS: dm_cmd_line_stress(cmd); break;
    case CMD_LINK_SINK: dm_cmd_link_sink(cmd); break;
    case CMD_LINK_SOURCE: dm_cmd_link_source(cmd); break;
    case CMD_FAULT_INJECT: dm_cmd_fault_inject(cmd); break;
    case CMD_SHUTDOWN: dm_cmd_shutdown(cmd); break;
    default:
        hostlink_error(cmd, LINK_ERR_UNKNOWN_CMD, "unknown command %u", (unsigned)cmd);
        break;
    }
}

static void dm_cmd_task(void *arg)
{
    (void)arg;
    for (;;) {
        dm_next_frame(0);
        if (dm_frame.type == LINK_CMD)
            dm_command();
        else
            hostlink_error(0, LINK_ERR_PROTOCOL,
                           "frame type %u (%u bytes) outside a transfer; expected LINK_CMD",
                           (unsigned)dm_frame.type, (unsigned)dm_frame.length);
    }
}

void dm_start(void)
{
    uint8_t *q = kmem_alloc(DM_FRAME_QUEUE_SIZE, "host frame queue");
    ringbuf_init(&dm_queue, q, DM_FRAME_QUEUE_SIZE);
    task_create("hostrx", dm_hostrx, NULL);
    task_create("dmcmd", dm_cmd_task, NULL);
}
