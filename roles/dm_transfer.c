/* dm_transfer.c: host-link bulk transfers (CMD_LINK_SINK, CMD_LINK_SOURCE)
 * with DATA/ACK flow control (proto/hostlink.h). */
#include <stdint.h>

#include "drivers/imsu/imsu.h"
#include "drivers/serial/hostlink_tx.h"
#include "drivers/serial/line.h"
#include "drivers/serial/uart.h"
#include "kernel/cpu.h"
#include "kernel/ktime.h"
#include "proto/crc32.h"
#include "proto/hostlink.h"
#include "proto/wire.h"
#include "roles/dm.h"
#include "roles/selftest.h"
#include "roles/unit.h"
#include "roles/unitmsg.h"

/* Host -> board bulk transfer: ACK every DATA frame, check the pattern. */
static void dm_link_sink(uint16_t cmd)
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

void dm_cmd_link_sink(uint16_t cmd)
{
    uart_rx_set_polling(1);
    dm_link_sink(cmd);
    uart_rx_set_polling(0);
}

/* Board -> host bulk transfer with at most LINK_DATA_WINDOW frames unACKed. */
void dm_cmd_link_source(uint16_t cmd)
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

