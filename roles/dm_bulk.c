/* dm_bulk.c: the DM's side of the shared-memory path of the host link
 * (LINK_BULK, proto/hostlink.h).  The host maps the board's RAM, so bulk
 * bytes need no frames: the DM says where they are (or where to put them)
 * and checks their word sum (proto/wordsum.h). */
#include <stdint.h>

#include "drivers/serial/hostlink_tx.h"
#include "kernel/ktime.h"
#include "proto/insn_mark.h"
#include "kernel/memlayout.h"
#include "kernel/param.h"
#include "proto/hostlink.h"
#include "proto/wire.h"
#include "proto/wordsum.h"
#include "roles/dm.h"

uint64_t dm_bulk_check_ticks;

int dm_bulk_path(uint16_t cmd, uint32_t args)
{
    uint32_t at = LINK_CMD_FIXED_SIZE + args;
    if (dm_frame.length <= at)
        return LINK_PATH_SERIAL;
    uint8_t path = dm_frame.payload[at];
    if (path > LINK_PATH_SHARED) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "command %u: path %u (0 serial, 1 shared)",
                       (unsigned)cmd, (unsigned)path);
        return -1;
    }
    return path;
}

/* Where p lies in the RAM the host maps. */
static uint32_t dm_bulk_offset(const void *p)
{
    return (uint32_t)((uintptr_t)p - RAM_BASE);
}

static void dm_bulk_frame(const void *buf, uint32_t len, uint32_t sum)
{
    struct link_bulk k = {dm_bulk_offset(buf), len, sum};
    uint8_t p[LINK_BULK_SIZE];
    link_bulk_put(p, &k);
    hostlink_send(LINK_BULK, 0, p, sizeof p);
}

/* The word sum of len bytes at buf, and in *tail that of those from split
 * on: one pass over the bytes. */
static uint32_t dm_bulk_sum(const uint8_t *buf, uint32_t len, uint32_t split, uint32_t *tail)
{
    uint32_t at = split < len ? split : len;
    wordsum_t head = WORDSUM_EMPTY, rest = WORDSUM_EMPTY;
    wordsum_update(&head, buf, at);
    wordsum_update(&rest, buf + at, len - at);
    *tail = wordsum_value(rest);
    return wordsum_value(wordsum_join(head, rest));
}

/* One offer of buf and the host's answer; LINK_ERR_CHECK (not yet answered)
 * when the bytes found do not have the host's word sum. */
static int dm_bulk_take(uint16_t cmd, uint8_t *buf, uint32_t room, uint32_t split, uint32_t *len,
                        uint32_t *tail_sum, int last_try)
{
    dm_bulk_frame(buf, room, 0);
    if (dm_next_frame(ktime_deadline_ms(LINK_ACK_TIMEOUT_MS)) != 0) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "shared path: no LINK_BULK from the host for "
                       "%u ms after the offer", (unsigned)LINK_ACK_TIMEOUT_MS);
        return LINK_ERR_TIMEOUT;
    }
    if (dm_session_interrupts(cmd))
        return LINK_ERR_PROTOCOL;
    if (dm_frame.type != LINK_BULK || dm_frame.length < LINK_BULK_SIZE) {
        hostlink_error(cmd, LINK_ERR_PROTOCOL, "shared path: expected LINK_BULK, got frame "
                       "type %u (%u bytes)", (unsigned)dm_frame.type, (unsigned)dm_frame.length);
        return LINK_ERR_PROTOCOL;
    }
    struct link_bulk k;
    link_bulk_get(dm_frame.payload, &k);
    if (k.offset != dm_bulk_offset(buf) || k.length > room) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "shared path: %u bytes at offset 0x%x, but the "
                       "board offered %u bytes at 0x%x", (unsigned)k.length,
                       (unsigned)k.offset, (unsigned)room, (unsigned)dm_bulk_offset(buf));
        return LINK_ERR_BAD_ARGS;
    }
    uint64_t t0 = ktime_now();
    insn_mark_trace_span_begin(); /* the upload's check (docs/trace.md) */
    uint32_t c = dm_bulk_sum(buf, k.length, split, tail_sum);
    insn_mark_trace_span_end();
    dm_bulk_check_ticks += ktime_now() - t0;
    if (c != k.sum) {
        if (!last_try)
            return LINK_ERR_CHECK; /* offered again */
        hostlink_error(cmd, LINK_ERR_CHECK, "shared path: %u bytes at offset 0x%x have word "
                       "sum 0x%08x, the host says 0x%08x (%u offers)", (unsigned)k.length,
                       (unsigned)k.offset, (unsigned)c, (unsigned)k.sum,
                       (unsigned)LINK_BULK_TRIES);
        return LINK_ERR_CHECK;
    }
    uint8_t ack[LINK_ACK_SIZE];
    wire_put_u16(ack, dm_frame.seq);
    hostlink_send(LINK_ACK, 0, ack, sizeof ack);
    *len = k.length;
    return LINK_OK;
}

int dm_bulk_receive(uint16_t cmd, uint8_t *buf, uint32_t room, uint32_t split, uint32_t *len,
                    uint32_t *tail_sum)
{
    /* Bytes whose sum fails are offered for again (proto/hostlink.h). */
    dm_bulk_check_ticks = 0;
    for (int t = 1;; t++) {
        int r = dm_bulk_take(cmd, buf, room, split, len, tail_sum, t == LINK_BULK_TRIES);
        if (r != LINK_ERR_CHECK || t == LINK_BULK_TRIES)
            return r;
    }
}

uint32_t dm_bulk_send(const void *buf, uint32_t len)
{
    uint32_t sum = wordsum(buf, len);
    dm_bulk_frame(buf, len, sum);
    return sum;
}
