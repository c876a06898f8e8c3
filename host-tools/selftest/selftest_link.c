/* selftest_link.c: the host-link checks of `links1 selftest` (pattern
 * transfers both ways). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/link/link_shared.h"
#include "host-tools/link/link_transfer.h"
#include "host-tools/selftest/selftest.h"
#include "proto/crc32.h"
#include "proto/wire.h"

/* The pattern into the board's shared RAM (CMD_LINK_SINK: u8 path, u32
 * bytes); *crc of what was put there. */
static int selftest_link_sink_shared(struct board *b, uint32_t total, uint32_t *crc)
{
    uint8_t arg[5];
    arg[0] = LINK_PATH_SHARED;
    wire_put_u32(arg + 1, total);
    uint8_t *pattern = malloc(total ? total : 1);
    if (!pattern) {
        fprintf(stderr, "links1: out of memory for %u pattern bytes\n", total);
        return -1;
    }
    for (uint32_t i = 0; i < total; i++)
        pattern[i] = link_pattern_byte(i);
    *crc = crc32(pattern, total);
    int r = board_send_cmd(b, CMD_LINK_SINK, arg, sizeof arg);
    if (r == 0)
        r = link_shared_send(b, pattern, total);
    free(pattern);
    return r; /* 1: the board refused; selftest_result shows why */
}

/* The pattern read from the board's shared RAM after CMD_LINK_SOURCE. */
static int selftest_link_source_shared(struct board *b, uint64_t *bytes, uint32_t *crc,
                                       char *why, size_t cap)
{
    struct link_bulk k;
    const uint8_t *data;
    int r = link_shared_receive(b, &k, &data);
    if (r < 0) {
        snprintf(why, cap, "reading the pattern from the board's shared RAM failed");
        return -1;
    }
    if (r > 0) {
        *bytes = 0;
        *crc = 0;
        return 0; /* the board's reason comes with its result */
    }
    for (uint32_t i = 0; i < k.length; i++) {
        if (data[i] != link_pattern_byte(i)) {
            snprintf(why, cap, "byte %u of the board's shared bytes is 0x%02x, the pattern "
                     "says 0x%02x", i, data[i], link_pattern_byte(i));
            return -1;
        }
    }
    *bytes = k.length;
    *crc = crc32(data, k.length); /* the result's check, as on the serial path */
    return 0;
}

int selftest_link_sink(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    uint32_t crc;
    struct board_frame r;
    const uint8_t *f;
    long long t0 = board_now_ms();
    if (b->opts.link == LINK_PATH_SHARED) {
        if (selftest_link_sink_shared(b, a->link_bytes, &crc) < 0) {
            snprintf(why, cap, "putting %u bytes into the board's shared RAM failed",
                     a->link_bytes);
            return -1;
        }
    } else if (board_send_cmd(b, CMD_LINK_SINK, NULL, 0) < 0 ||
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
    uint8_t arg[5];
    uint64_t bytes;
    uint32_t crc;
    struct board_frame r;
    const uint8_t *f;
    long long t0 = board_now_ms();
    wire_put_u32(arg, a->link_bytes);
    arg[4] = (uint8_t)b->opts.link;
    if (b->opts.link == LINK_PATH_SHARED) {
        if (board_send_cmd(b, CMD_LINK_SOURCE, arg, sizeof arg) < 0 ||
            selftest_link_source_shared(b, &bytes, &crc, why, cap) < 0)
            return -1;
    } else if (board_send_cmd(b, CMD_LINK_SOURCE, arg, sizeof arg) < 0 ||
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
