/* dm_transfer.c: host-link bulk transfers (CMD_LINK_SINK, CMD_LINK_SOURCE)
 * with DATA/ACK flow control (proto/hostlink.h). */
#include <stdint.h>

#include "drivers/imsu/imsu.h"
#include "drivers/serial/hostlink_tx.h"
#include "drivers/serial/line.h"
#include "drivers/serial/uart.h"
#include "kernel/cpu.h"
#include "kernel/kmem.h"
#include "kernel/ktime.h"
#include "proto/crc32.h"
#include "proto/hostlink.h"
#include "proto/wire.h"
#include "roles/dm.h"
#include "roles/selftest.h"
#include "roles/unit.h"
#include "proto/unitmsg.h"

/* One host -> board transfer (see dm.h). */
static int dm_transfer_receive_polled(uint16_t cmd, dm_chunk_in_fn fn, void *ctx,
                                      uint64_t *bytes_out, uint32_t *crc_out)
{
    uint64_t bytes = 0;
    uint32_t crc = 0;
    int refused = 0; /* fn refused a chunk: take the rest, report at the end */
    for (;;) {
        if (dm_next_frame(ktime_deadline_ms(LINK_ACK_TIMEOUT_MS)) != 0) {
            hostlink_error(cmd, LINK_ERR_TIMEOUT, "transfer: no DATA frame for %u ms after %u bytes",
                           (unsigned)LINK_ACK_TIMEOUT_MS, (unsigned)bytes);
            return LINK_ERR_TIMEOUT;
        }
        if (dm_session_interrupts(cmd))
            return LINK_ERR_PROTOCOL;
        if (dm_frame.type != LINK_DATA) {
            hostlink_error(cmd, LINK_ERR_PROTOCOL,
                           "transfer: frame type %u in the middle of a transfer, after %u bytes",
                           (unsigned)dm_frame.type, (unsigned)bytes);
            return LINK_ERR_PROTOCOL;
        }
        if (!refused && fn(ctx, dm_frame.payload, dm_frame.length, bytes) != 0)
            refused = 1;
        crc = crc32_update(crc, dm_frame.payload, dm_frame.length);
        bytes += dm_frame.length;
        uint8_t ack[LINK_ACK_SIZE];
        wire_put_u16(ack, dm_frame.seq);
        hostlink_send(LINK_ACK, 0, ack, sizeof ack);
        if (dm_frame.flags & LINK_FLAG_LAST)
            break;
    }
    /* A frame dropped on the way in was sent again (the frames are taken in
     * seq order only, proto/link_arq.h): what came is the whole transfer. */
    *bytes_out = bytes;
    *crc_out = crc;
    return refused ? LINK_ERR_CHECK : LINK_OK;
}

int dm_transfer_receive(uint16_t cmd, dm_chunk_in_fn fn, void *ctx, uint64_t *bytes,
                        uint32_t *crc)
{
    /* Polled receive for the length of the upload (docs/firmware.md). */
    uart_rx_set_polling(1);
    int r = dm_transfer_receive_polled(cmd, fn, ctx, bytes, crc);
    uart_rx_set_polling(0);
    return r;
}

int dm_transfer_send(uint16_t cmd, dm_chunk_out_fn fn, void *ctx, uint32_t total,
                     uint32_t *crc_out)
{
    static uint8_t chunk[LINK_DATA_CHUNK];
    uint16_t inflight[LINK_DATA_WINDOW]; /* seqs of DATA frames not yet ACKed */
    uint32_t head = 0, count = 0, sent = 0, crc = 0;
    while (sent < total || count) {
        if (sent < total && count < LINK_DATA_WINDOW) {
            uint32_t n = total - sent < LINK_DATA_CHUNK ? total - sent : LINK_DATA_CHUNK;
            fn(ctx, chunk, n, sent);
            crc = crc32_update(crc, chunk, n);
            uint8_t flags = sent + n == total ? LINK_FLAG_LAST : 0;
            inflight[(head + count) % LINK_DATA_WINDOW] = hostlink_send(LINK_DATA, flags, chunk, n);
            count++;
            sent += n;
            continue;
        }
        /* Window full (or all sent): wait for an ACK. */
        if (dm_next_frame(ktime_deadline_ms(LINK_ACK_TIMEOUT_MS)) != 0) {
            hostlink_error(cmd, LINK_ERR_TIMEOUT, "transfer: no ACK for %u ms, %u frames unACKed",
                           (unsigned)LINK_ACK_TIMEOUT_MS, (unsigned)count);
            return LINK_ERR_TIMEOUT;
        }
        if (dm_session_interrupts(cmd))
            return LINK_ERR_PROTOCOL;
        if (dm_frame.type != LINK_ACK || dm_frame.length < LINK_ACK_SIZE) {
            hostlink_error(cmd, LINK_ERR_PROTOCOL,
                           "transfer: expected an ACK, got frame type %u (%u bytes)",
                           (unsigned)dm_frame.type, (unsigned)dm_frame.length);
            return LINK_ERR_PROTOCOL;
        }
        /* An ACK covers every DATA frame up to the seq it names. */
        uint16_t acked = wire_get_u16(dm_frame.payload);
        uint32_t k = 0;
        while (k < count && inflight[(head + k) % LINK_DATA_WINDOW] != acked)
            k++;
        if (k == count) {
            hostlink_error(cmd, LINK_ERR_PROTOCOL,
                           "transfer: ACK for seq %u, which is not in flight", (unsigned)acked);
            return LINK_ERR_PROTOCOL;
        }
        head = (head + k + 1) % LINK_DATA_WINDOW;
        count -= k + 1;
    }
    *crc_out = crc;
    return LINK_OK;
}

/* ---- the link tests: the known pattern each way ---- */

/* Counts the bytes of a chunk that differ from link_pattern_byte(). */
/* The success result of the sink and source checks. */
static void dm_transfer_result(uint16_t cmd, uint64_t bytes, uint32_t crc, uint32_t differ)
{
    struct link_transfer_result r = {bytes, crc, differ};
    uint8_t f[LINK_TRANSFER_RESULT_SIZE];
    link_transfer_result_put(f, &r);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

static int dm_sink_check(void *ctx, const uint8_t *data, uint32_t n, uint64_t offset)
{
    uint32_t *differ = ctx;
    for (uint32_t i = 0; i < n; i++)
        *differ += data[i] != link_pattern_byte((uint32_t)offset + i);
    return 0;
}

/* CMD_LINK_SINK on the shared path: u8 path, u32 bytes.  The pattern goes
 * into DM private memory given back at the end. */
static void dm_link_sink_shared(uint16_t cmd)
{
    if (dm_frame.length < LINK_CMD_FIXED_SIZE + 5) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_LINK_SINK on the shared path needs u8 "
                       "path, u32 bytes (5 bytes), got %u",
                       (unsigned)(dm_frame.length - LINK_CMD_FIXED_SIZE));
        return;
    }
    uint32_t want = wire_get_u32(dm_frame.payload + LINK_CMD_FIXED_SIZE + 1);
    if (want == 0 || want > (kmem_free() & ~(size_t)7)) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "sink: %u bytes: must be 1..%u (the DM's free "
                       "private memory)", (unsigned)want, (unsigned)kmem_free());
        return;
    }
    size_t mark = kmem_mark();
    uint8_t *buf = kmem_alloc(want, "link sink");
    uint32_t len = 0, crc = 0, sum = 0, differ = 0;
    int r = dm_bulk_receive(cmd, buf, want, 0, &len, &sum);
    if (r == LINK_OK) {
        dm_sink_check(&differ, buf, len, 0);
        crc = crc32(buf, len); /* the result's, as on the serial path */
    }
    kmem_release_to(mark);
    if (r != LINK_OK)
        return;
    if (differ) {
        hostlink_error(cmd, LINK_ERR_CHECK,
                       "sink: %u of %u bytes differ from the pattern, crc 0x%08x",
                       (unsigned)differ, (unsigned)len, (unsigned)crc);
        return;
    }
    dm_transfer_result(cmd, len, crc, differ);
}

void dm_cmd_link_sink(uint16_t cmd)
{
    int path = dm_bulk_path(cmd, 0);
    if (path < 0)
        return;
    if (path == LINK_PATH_SHARED) {
        dm_link_sink_shared(cmd);
        return;
    }
    uint64_t bytes = 0;
    uint32_t crc = 0, differ = 0;
    if (dm_transfer_receive(cmd, dm_sink_check, &differ, &bytes, &crc) != LINK_OK)
        return;
    if (differ) {
        hostlink_error(cmd, LINK_ERR_CHECK,
                       "sink: %u of %u bytes differ from the pattern, crc 0x%08x",
                       (unsigned)differ, (unsigned)bytes, (unsigned)crc);
        return;
    }
    dm_transfer_result(cmd, bytes, crc, differ);
}

static void dm_source_fill(void *ctx, uint8_t *data, uint32_t n, uint32_t offset)
{
    (void)ctx;
    for (uint32_t i = 0; i < n; i++)
        data[i] = link_pattern_byte(offset + i);
}

void dm_cmd_link_source(uint16_t cmd)
{
    if (dm_frame.length < LINK_CMD_FIXED_SIZE + 4) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_LINK_SOURCE needs u32 bytes (4 bytes), got %u",
                       (unsigned)(dm_frame.length - LINK_CMD_FIXED_SIZE));
        return;
    }
    uint32_t total = wire_get_u32(dm_frame.payload + LINK_CMD_FIXED_SIZE);
    int path = dm_bulk_path(cmd, 4);
    if (path < 0)
        return;
    uint32_t crc = 0;
    if (path == LINK_PATH_SHARED) {
        /* The pattern in DM private memory, given back at once: nothing
         * else allocates before the host's next command. */
        if (total == 0 || total > (kmem_free() & ~(size_t)7)) {
            hostlink_error(cmd, LINK_ERR_BAD_ARGS, "source: %u bytes: must be 1..%u (the "
                           "DM's free private memory)", (unsigned)total, (unsigned)kmem_free());
            return;
        }
        size_t mark = kmem_mark();
        uint8_t *buf = kmem_alloc(total, "link source");
        dm_source_fill(NULL, buf, total, 0);
        crc = crc32(buf, total); /* the result's, as on the serial path */
        (void)dm_bulk_send(buf, total);
        kmem_release_to(mark);
    } else if (dm_transfer_send(cmd, dm_source_fill, NULL, total, &crc) != LINK_OK) {
        return;
    }
    dm_transfer_result(cmd, total, crc, 0);
}
