/* selftest_link.c: the host-link checks of `links1 selftest` (pattern
 * transfers both ways). */
#include <stdio.h>
#include <string.h>

#include "host-tools/link_transfer.h"
#include "host-tools/selftest.h"
#include "proto/wire.h"

int selftest_link_sink(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    uint32_t crc;
    struct board_frame r;
    const uint8_t *f;
    long long t0 = board_now_ms();
    if (board_send_cmd(b, CMD_LINK_SINK, NULL, 0) < 0 ||
        link_transfer_send_pattern(b, a->link_bytes, &crc) < 0) {
        snprintf(why, cap, "sending %u bytes to the board failed", a->link_bytes);
        return -1;
    }
    if (selftest_result(b, CMD_LINK_SINK, BOARD_FRAME_TIMEOUT_MS, LINK_TRANSFER_RESULT_SIZE,
                        &r, &f, why, cap) < 0)
        return -1;
    struct link_transfer_result res;
    link_transfer_result_get(f, &res);
    uint64_t got = res.bytes;
    uint32_t got_crc = res.crc;
    double secs = (double)(board_now_ms() - t0) / 1000.0;
    snprintf(why, cap, "sent %u bytes crc 0x%08x; board took %llu bytes crc 0x%08x "
             "(%.0f KiB/s)", a->link_bytes, crc, (unsigned long long)got, got_crc,
             secs > 0 ? a->link_bytes / 1024.0 / secs : 0.0);
    return got == a->link_bytes && got_crc == crc && res.differ == 0 ? 0 : -1;
}

int selftest_link_source(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    uint8_t arg[4];
    uint64_t bytes;
    uint32_t crc;
    struct board_frame r;
    const uint8_t *f;
    long long t0 = board_now_ms();
    wire_put_u32(arg, a->link_bytes);
    if (board_send_cmd(b, CMD_LINK_SOURCE, arg, sizeof arg) < 0 ||
        link_transfer_receive_pattern(b, &bytes, &crc) < 0) {
        snprintf(why, cap, "receiving %u pattern bytes from the board failed", a->link_bytes);
        return -1;
    }
    double secs = (double)(board_now_ms() - t0) / 1000.0;
    if (selftest_result(b, CMD_LINK_SOURCE, BOARD_FRAME_TIMEOUT_MS, LINK_TRANSFER_RESULT_SIZE,
                        &r, &f, why, cap) < 0)
        return -1;
    struct link_transfer_result res;
    link_transfer_result_get(f, &res);
    uint64_t said = res.bytes;
    uint32_t said_crc = res.crc;
    snprintf(why, cap, "received %llu bytes crc 0x%08x, all the pattern in order; board "
             "says it sent %llu bytes crc 0x%08x (%.0f KiB/s)", (unsigned long long)bytes,
             crc, (unsigned long long)said, said_crc, secs > 0 ? bytes / 1024.0 / secs : 0.0);
    return bytes == a->link_bytes && said == bytes && said_crc == crc ? 0 : -1;
}
