/* dm.c: the data manipulator (DM) program: the unit computer that talks to
 * the host.  Two cooperative tasks:
 *   "hostrx"  drains the UART receive ring through the frame decoder, takes
 *             the host's frames in seq order only and queues them
 *             (reporting dropped frames at once and asking for them again
 *             with LINK_NAK), and answers the host's LINK_NAKs by sending
 *             the board's frames again (proto/link_arq.h, go-back-N);
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
#include "kernel/machine.h"
#include "kernel/ringbuf.h"
#include "kernel/task.h"
#include "proto/crc32.h"
#include "proto/hostlink.h"
#include "proto/link_arq.h"
#include "proto/wire.h"
#include "roles/dm.h"
#include "roles/gigs.h"
#include "roles/selftest.h"
#include "roles/unit.h"
#include "proto/unitmsg.h"

/* Queued frame record: u8 type, u8 flags, u16 seq, u16 length, payload. */
#define DM_REC_HEADER 6

static struct ringbuf dm_queue;      /* hostrx -> dmcmd */
static struct link_decoder dm_dec;   /* host -> board frames */
struct dm_frame dm_frame;            /* the frame dmcmd works on */
struct line_msg dm_msg;              /* the DM's line message buffer */
uint32_t dm_link_errors;             /* frames dropped so far (host -> board) */
static uint64_t dm_poll_ticks;       /* UART_RX_POLL_US in timer ticks */
/* The host's frames are taken in seq order: it numbers from 0 at our boot,
 * or from a frame flagged LINK_FLAG_SESSION. */
static struct link_arq_rx dm_arq_rx = {1, 0};
static struct link_arq_nak dm_nak;   /* our NAKs' rate limit */

/* ------------------------------------------------------------ hostrx */

static uint32_t dm_decoder_errors(void)
{
    const struct link_stats *s = &dm_dec.stats;
    return s->crc_errors + s->bad_length; /* gaps: dm_host_frame NAKs them */
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

/* Asks the host for the frame we expect, at most once per LINK_ARQ_NAK_MS. */
static void dm_nak_expected(void)
{
    uint64_t now = ktime_ticks_to_ms(ktime_now());
    if (link_arq_nak_due(&dm_nak, dm_arq_rx.expect, now, LINK_ARQ_NAK_MS))
        hostlink_send_nak(0, dm_arq_rx.expect);
}

/* A good frame from the host: a NAK is answered here, a numbered frame is
 * queued if it is the one expected, dropped if taken already, and NAKed if
 * it comes after a gap. */
static void dm_host_frame(const struct link_frame *f)
{
    if (f->type == LINK_NAK) {
        if (f->length < LINK_ACK_SIZE || (f->flags & LINK_FLAG_GONE))
            return; /* the host gives up on its own */
        hostlink_resend_from(wire_get_u16(f->payload));
        if (f->flags & LINK_FLAG_POLL)
            hostlink_send_nak(0, dm_arq_rx.expect);
        return;
    }
    switch (link_arq_rx_take(&dm_arq_rx, f)) {
    case LINK_ARQ_NEW: dm_queue_frame(f); break;
    case LINK_ARQ_DUP: break;
    default: dm_nak_expected(); break;
    }
}

/* Feeds one byte to the decoder; reports and NAKs a damaged frame, and NAKs
 * junk. */
static void dm_host_byte(uint8_t b)
{
    struct link_frame f;
    uint32_t before = dm_decoder_errors(), junk = dm_dec.stats.junk_bytes;
    int got = link_decoder_push(&dm_dec, b, &f);
    uint32_t after = dm_decoder_errors();
    /* Junk is what is left of a frame whose sync was damaged: maybe the
     * host's last frame, which no later frame would show missing. */
    if (dm_dec.stats.junk_bytes != junk)
        dm_nak_expected();
    if (after != before) {
        dm_link_errors += after - before;
        const struct link_stats *s = &dm_dec.stats;
        hostlink_error(0, LINK_ERR_BAD_FRAME,
                       "host link: frame dropped or missing (bad CRC %u, bad length %u, "
                       "seq gaps %u so far)",
                       (unsigned)s->crc_errors, (unsigned)s->bad_length,
                       (unsigned)s->seq_gaps);
        dm_nak_expected();
    }
    if (got)
        dm_host_frame(&f);
}

static void dm_hostrx(void *arg)
{
    (void)arg;
    uint8_t buf[256];
    link_decoder_init(&dm_dec);
    for (;;) {
        uint32_t mark = task_event_mark();
        uint32_t n = uart_rx_read(buf, sizeof buf);
        if (n == 0) {
            /* Polled (bulk upload): look again soon; otherwise the
             * receive interrupt wakes us.  (A partial frame whose length
             * field was damaged is completed by the zero bytes the host
             * sends before a poll: proto/link_arq.h.) */
            task_wait(mark, uart_rx_is_polling() ? ktime_now() + dm_poll_ticks : 0);
            continue;
        }
        for (uint32_t i = 0; i < n; i++)
            dm_host_byte(buf[i]);
    }
}

static int dm_frame_held; /* 1: dm_frame is to be taken again */

int dm_session_interrupts(uint16_t cmd)
{
    if (!(dm_frame.flags & LINK_FLAG_SESSION))
        return 0;
    dm_frame_held = 1;
    hostlink_error(cmd, LINK_ERR_PROTOCOL, "transfer: a new host session began (the host of "
                   "this transfer went away)");
    return 1;
}

/* Takes the next queued frame into dm_frame; 0, or -1 at deadline. */
int dm_next_frame(uint64_t deadline)
{
    if (dm_frame_held) {
        dm_frame_held = 0;
        return 0;
    }
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

int dm_rc_request(struct line_msg *m, uint16_t answer_type, uint32_t timeout_ms)
{
    int r = line_send(UNITS_RC_CORE, m, ktime_deadline_ms(timeout_ms));
    if (r != LINE_OK)
        return r;
    return selftest_recv_type(UNITS_RC_CORE, answer_type, m, ktime_deadline_ms(timeout_ms));
}
static void dm_cmd_status(uint16_t cmd)
{
    struct link_status_result r = {(uint16_t)board_ncores, (uint16_t)unit_reported_count(),
                                   (uint16_t)unit_halted_count()};
    uint8_t f[LINK_STATUS_RESULT_SIZE];
    link_status_result_put(f, &r);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}
static void dm_cmd_fault_inject(uint16_t cmd)
{
    if (dm_frame.length < LINK_CMD_FIXED_SIZE + 3) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS,
                       "CMD_FAULT_INJECT needs u16 core, u8 kind (3 bytes), got %u",
                       (unsigned)(dm_frame.length - LINK_CMD_FIXED_SIZE));
        return;
    }
    uint16_t core = wire_get_u16(dm_frame.payload + LINK_CMD_FIXED_SIZE);
    uint8_t kind = wire_get_u8(dm_frame.payload + LINK_CMD_FIXED_SIZE + 2);
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
    if (core == UNITS_DM_CORE) {
        hostlink_result(cmd, LINK_OK, NULL, 0);
        selftest_fault_now(kind);
        return;
    }
    struct line_msg *m = &dm_msg;
    selftest_msg_set(m, MSG_FAULT, 3);
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
    machine_power_off();
    hostlink_error(cmd, LINK_ERR_PROTOCOL, "the machine did not power off");
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
    case CMD_LINE_LATENCY: dm_cmd_line_latency(cmd); break;
    case CMD_IMSU_TEST: dm_cmd_imsu_test(cmd); break;
    case CMD_LINE_STRESS: dm_cmd_line_stress(cmd); break;
    case CMD_LINK_SINK: dm_cmd_link_sink(cmd); break;
    case CMD_LINK_SOURCE: dm_cmd_link_source(cmd); break;
    case CMD_FAULT_INJECT: dm_cmd_fault_inject(cmd); break;
    case CMD_SHUTDOWN: dm_cmd_shutdown(cmd); break;
    case CMD_SCENE_LOAD: dm_cmd_scene_load(cmd); break;
    case CMD_RENDER: dm_cmd_render(cmd); break;
    case CMD_FRAME_PULL: dm_cmd_frame_pull(cmd); break;
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
    dm_poll_ticks = ktime_ms_to_ticks(1) * UART_RX_POLL_US / 1000u;
    uint8_t *q = kmem_alloc(DM_FRAME_QUEUE_SIZE, "host frame queue");
    ringbuf_init(&dm_queue, q, DM_FRAME_QUEUE_SIZE);
    task_create("hostrx", dm_hostrx, NULL);
    task_create("dmcmd", dm_cmd_task, NULL);
}
