/* link_transfer.c: pattern transfers both ways over the host link. */
#include "host-tools/link/link_transfer.h"

#include <stdio.h>

#include "proto/crc32.h"
#include "proto/wire.h"

/* seq a is at or before seq b in 16-bit wrapping order. */
static int link_transfer_seq_not_after(uint16_t a, uint16_t b)
{
    return (uint16_t)(b - a) < 0x8000u;
}

/* Waits for one ACK and drops every in-flight seq it covers. */
static int link_transfer_take_ack(struct board *b, uint16_t *inflight, int *n)
{
    struct board_frame f;
    if (board_wait_frame(b, LINK_ACK, BOARD_FRAME_TIMEOUT_MS, &f, "ACK of a DATA frame") < 0)
        return -1;
    if (f.length != LINK_ACK_SIZE) {
        fprintf(stderr, "links1: ACK frame of %u bytes, want %d\n", f.length, LINK_ACK_SIZE);
        return -1;
    }
    /* An ACK names one DATA frame in flight and covers it and all before. */
    uint16_t acked = wire_get_u16(f.payload);
    int drop = 0;
    while (drop < *n && inflight[drop] != acked)
        drop++;
    if (drop == *n) {
        fprintf(stderr, "links1: ACK for seq %u, which is not a DATA frame in flight "
                "(oldest in flight: seq %u)\n", acked, *n ? inflight[0] : 0);
        return -1;
    }
    drop++;
    for (int i = drop; i < *n; i++)
        inflight[i - drop] = inflight[i];
    *n -= drop;
    return 0;
}

/* The bytes of [off, off + len) of a transfer: a pointer to them (the
 * source itself, or buf filled). */
typedef const uint8_t *(*link_transfer_chunk_fn)(void *ctx, size_t off, uint8_t *buf, size_t len);

/* total bytes as DATA frames of LINK_DATA_CHUNK, at most LINK_DATA_WINDOW
 * unacknowledged, the last flagged LINK_FLAG_LAST. */
static int link_transfer_send_chunks(struct board *b, size_t total, link_transfer_chunk_fn chunk,
                                     void *ctx)
{
    uint16_t inflight[LINK_DATA_WINDOW];
    int n = 0;
    uint8_t buf[LINK_DATA_CHUNK];
    for (size_t off = 0; off < total;) {
        size_t len = total - off < LINK_DATA_CHUNK ? total - off : LINK_DATA_CHUNK;
        const uint8_t *p = chunk(ctx, off, buf, len);
        while (n >= LINK_DATA_WINDOW)
            if (link_transfer_take_ack(b, inflight, &n) < 0)
                return -1;
        int last = off + len == total;
        int seq = board_send(b, LINK_DATA, last ? LINK_FLAG_LAST : 0, p, len);
        if (seq < 0)
            return -1;
        inflight[n++] = (uint16_t)seq;
        off += len;
    }
    while (n > 0)
        if (link_transfer_take_ack(b, inflight, &n) < 0)
            return -1;
    return 0;
}

static const uint8_t *link_transfer_bytes(void *ctx, size_t off, uint8_t *buf, size_t len)
{
    (void)buf;
    (void)len;
    return (const uint8_t *)ctx + off;
}

int link_transfer_send(struct board *b, const void *data, size_t len)
{
    return link_transfer_send_chunks(b, len, link_transfer_bytes, (void *)data);
}

/* The test pattern, its CRC kept as it goes. */
static const uint8_t *link_transfer_pattern(void *ctx, size_t off, uint8_t *buf, size_t len)
{
    for (size_t i = 0; i < len; i++)
        buf[i] = link_pattern_byte((uint32_t)(off + i));
    uint32_t *crc = ctx;
    *crc = crc32_update(*crc, buf, len);
    return buf;
}

int link_transfer_send_pattern(struct board *b, uint32_t total, uint32_t *crc)
{
    if (total == 0) {
        fprintf(stderr, "links1: a transfer carries at least one byte\n");
        return -1;
    }
    uint32_t c = 0;
    if (link_transfer_send_chunks(b, total, link_transfer_pattern, &c) < 0)
        return -1;
    *crc = c;
    return 0;
}

int link_transfer_receive_pattern(struct board *b, uint64_t *bytes, uint32_t *crc)
{
    uint64_t off = 0;
    uint32_t c = 0;
    int have_prev = 0;
    uint16_t prev = 0;
    for (;;) {
        struct board_frame f;
        if (board_wait_frame(b, LINK_DATA, BOARD_FRAME_TIMEOUT_MS, &f, "DATA frame") < 0) {
            fprintf(stderr, "links1: the transfer stopped after %llu bytes\n",
                    (unsigned long long)off);
            return -1;
        }
        if (have_prev && (f.seq == prev || !link_transfer_seq_not_after(prev, f.seq))) {
            fprintf(stderr, "links1: DATA frame seq %u after seq %u at byte %llu: "
                    "repeated or out of order\n", f.seq, prev, (unsigned long long)off);
            return -1;
        }
        have_prev = 1;
        prev = f.seq;
        if (f.length == 0) {
            fprintf(stderr, "links1: empty DATA frame (seq %u) at byte %llu\n", f.seq,
                    (unsigned long long)off);
            return -1;
        }
        for (uint32_t i = 0; i < f.length; i++) {
            uint8_t want = link_pattern_byte((uint32_t)(off + i));
            if (f.payload[i] != want) {
                fprintf(stderr, "links1: byte %llu of the board's transfer is 0x%02x, "
                        "the pattern says 0x%02x (DATA seq %u)\n",
                        (unsigned long long)(off + i), f.payload[i], want, f.seq);
                return -1;
            }
        }
        c = crc32_update(c, f.payload, f.length);
        off += f.length;
        uint8_t ack[LINK_ACK_SIZE];
        wire_put_u16(ack, f.seq);
        if (board_send(b, LINK_ACK, 0, ack, sizeof ack) < 0)
            return -1;
        if (f.flags & LINK_FLAG_LAST)
            break;
    }
    *bytes = off;
    *crc = c;
    return 0;
}
