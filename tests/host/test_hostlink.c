/* Host tests of the host-link framing (proto/hostlink.c): encoder, streaming
 * decoder, resynchronisation and the error counters. */
#include <stdlib.h>
#include <string.h>

#include "proto/crc32.h"
#include "proto/hostlink.h"
#include "proto/wire.h"
#include "tests/check.h"

/* A decoded frame copied out of the decoder. */
struct got_frame {
    uint8_t type, flags;
    uint16_t seq, length;
    uint8_t payload[LINK_MAX_PAYLOAD];
};

#define MAX_GOT 64
static struct got_frame got[MAX_GOT];

/* Pushes n bytes; copies each delivered frame into got[]; returns how many. */
static int push_all(struct link_decoder *d, const uint8_t *p, size_t n, int start)
{
    int k = start;
    for (size_t i = 0; i < n; i++) {
        struct link_frame f;
        if (!link_decoder_push(d, p[i], &f))
            continue;
        if (k < MAX_GOT) {
            got[k].type = f.type;
            got[k].flags = f.flags;
            got[k].seq = f.seq;
            got[k].length = f.length;
            memcpy(got[k].payload, f.payload, f.length);
        }
        k++;
    }
    return k;
}

static void fill(uint8_t *p, size_t n, unsigned salt)
{
    for (size_t i = 0; i < n; i++)
        p[i] = (uint8_t)(i * 131u + salt * 7u + (i >> 8));
}

static void frame_round_trip_every_length(void)
{
    static uint8_t payload[LINK_MAX_PAYLOAD], frame[LINK_MAX_FRAME];
    struct link_decoder d;
    link_decoder_init(&d);
    int bad = 0;
    for (size_t len = 0; len <= LINK_MAX_PAYLOAD; len++) {
        fill(payload, len, (unsigned)len);
        size_t n = link_frame_encode(frame, sizeof frame, LINK_DATA, (uint8_t)(len & 1),
                                     (uint16_t)len, payload, len);
        if (n != LINK_HEADER_SIZE + len + LINK_CRC_SIZE) {
            bad++;
            continue;
        }
        int k = push_all(&d, frame, n, 0);
        if (k != 1 || got[0].type != LINK_DATA || got[0].flags != (len & 1) ||
            got[0].seq != len || got[0].length != len || memcmp(got[0].payload, payload, len))
            bad++;
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(d.stats.frames, LINK_MAX_PAYLOAD + 1);
    CHECK_EQ_INT(d.stats.seq_gaps + d.stats.crc_errors + d.stats.junk_bytes, 0);
}

static void frame_header_layout_is_pinned(void)
{
    uint8_t frame[32];
    size_t n = link_frame_encode(frame, sizeof frame, LINK_LOG, 0x5a, 0x1234, "hi", 2);
    static const uint8_t head[] = {'L', '1', LINK_LOG, 0x5a, 0x34, 0x12, 0x02, 0x00, 'h', 'i'};
    CHECK_EQ_INT(n, 14);
    CHECK(memcmp(frame, head, sizeof head) == 0);
    CHECK_EQ_INT(wire_get_u32(frame + 10), crc32(frame + 2, 8));
}

static void frame_max_size_and_oversize(void)
{
    static uint8_t payload[LINK_MAX_PAYLOAD + 1], frame[LINK_MAX_FRAME + 16];
    fill(payload, sizeof payload, 3);
    CHECK_EQ_INT(link_frame_encode(frame, sizeof frame, LINK_DATA, 0, 0, payload,
                                   LINK_MAX_PAYLOAD), LINK_MAX_FRAME);
    CHECK_EQ_INT(link_frame_encode(frame, sizeof frame, LINK_DATA, 0, 0, payload,
                                   LINK_MAX_PAYLOAD + 1), 0);
    /* A buffer one byte short is refused, not overrun. */
    CHECK_EQ_INT(link_frame_encode(frame, LINK_MAX_FRAME - 1, LINK_DATA, 0, 0, payload,
                                   LINK_MAX_PAYLOAD), 0);
    struct link_decoder d;
    link_decoder_init(&d);
    link_frame_encode(frame, sizeof frame, LINK_DATA, 0, 0, payload, LINK_MAX_PAYLOAD);
    CHECK_EQ_INT(push_all(&d, frame, LINK_MAX_FRAME, 0), 1);
    CHECK_EQ_INT(got[0].length, LINK_MAX_PAYLOAD);
    CHECK(memcmp(got[0].payload, payload, LINK_MAX_PAYLOAD) == 0);
}

static void frame_resync_after_junk(void)
{
    uint8_t junk[100], frame[64];
    for (size_t i = 0; i < sizeof junk; i++)
        junk[i] = (uint8_t)(i % 2 ? 'x' : '1'); /* no 'L': every byte is junk */
    struct link_decoder d;
    link_decoder_init(&d);
    size_t n = link_frame_encode(frame, sizeof frame, LINK_LOG, 0, 7, "boot", 4);
    int k = push_all(&d, junk, sizeof junk, 0);
    k = push_all(&d, frame, n, k);
    CHECK_EQ_INT(k, 1);
    CHECK_EQ_INT(got[0].seq, 7);
    CHECK(memcmp(got[0].payload, "boot", 4) == 0);
    CHECK_EQ_INT(d.stats.junk_bytes, sizeof junk);
    /* Sync-like junk: lone 'L's and an "L1" with a short truncated header. */
    static const uint8_t tricky[] = {'L', 'L', 'x', 'L', '1', LINK_LOG, 0};
    k = push_all(&d, tricky, sizeof tricky, 0);
    n = link_frame_encode(frame, sizeof frame, LINK_LOG, 0, 8, "ok", 2);
    k = push_all(&d, frame, n, k);
    /* The truncated header swallows bytes of the good frame; the decoder must
     * find it inside once that header proves bad, and lose nothing after it. */
    uint8_t next[64];
    size_t m = link_frame_encode(next, sizeof next, LINK_LOG, 0, 9, "more", 4);
    for (int i = 0; i < 40 && k < 2; i++)
        k = push_all(&d, next, m, k);
    CHECK(k >= 2);
    CHECK_EQ_INT(got[0].seq, 8);
    CHECK(memcmp(got[0].payload, "ok", 2) == 0);
    CHECK_EQ_INT(got[1].seq, 9);
}

/* A damaged header whose length field swallows a whole good frame and part
 * of the next: both good frames must still come out, in order. */
static void frame_resync_keeps_bytes_after_recovered_frame(void)
{
    uint8_t bad[LINK_HEADER_SIZE] = {'L', '1', LINK_LOG, 0, 0, 0, 20, 0};
    uint8_t a[32], b[32];
    size_t na = link_frame_encode(a, sizeof a, LINK_LOG, 0, 1, "ok", 2);
    size_t nb = link_frame_encode(b, sizeof b, LINK_LOG, 0, 2, "next", 4);
    struct link_decoder d;
    link_decoder_init(&d);
    int k = push_all(&d, bad, sizeof bad, 0);
    k = push_all(&d, a, na, k);
    k = push_all(&d, b, nb, k);
    CHECK_EQ_INT(k, 2);
    CHECK_EQ_INT(d.stats.crc_errors, 1);
    CHECK_EQ_INT(got[0].seq, 1);
    CHECK(memcmp(got[0].payload, "ok", 2) == 0);
    CHECK_EQ_INT(got[1].seq, 2);
    CHECK(memcmp(got[1].payload, "next", 4) == 0);
}

static void frame_bad_crc_counted(void)
{
    uint8_t a[64], b[64];
    size_t na = link_frame_encode(a, sizeof a, LINK_RESULT, 0, 1, "abcdef", 6);
    size_t nb = link_frame_encode(b, sizeof b, LINK_RESULT, 0, 2, "ghij", 4);
    a[LINK_HEADER_SIZE + 2] ^= 0x10;
    struct link_decoder d;
    link_decoder_init(&d);
    int k = push_all(&d, a, na, 0);
    CHECK_EQ_INT(k, 0);
    k = push_all(&d, b, nb, k);
    CHECK_EQ_INT(k, 1);
    CHECK_EQ_INT(got[0].seq, 2);
    CHECK_EQ_INT(d.stats.crc_errors, 1);
    CHECK_EQ_INT(d.stats.frames, 1);
}

static void frame_bad_length_counted(void)
{
    uint8_t bad[LINK_HEADER_SIZE] = {'L', '1', LINK_DATA, 0, 0, 0, 0, 0};
    wire_put_u16(bad + 6, LINK_MAX_PAYLOAD + 1);
    uint8_t good[32];
    size_t n = link_frame_encode(good, sizeof good, LINK_ACK, 0, 3, "\x01\x00", 2);
    struct link_decoder d;
    link_decoder_init(&d);
    int k = push_all(&d, bad, sizeof bad, 0);
    k = push_all(&d, good, n, k);
    CHECK_EQ_INT(d.stats.bad_length, 1);
    CHECK_EQ_INT(k, 1);
    CHECK_EQ_INT(got[0].type, LINK_ACK);
}

static void frame_seq_gap_counted(void)
{
    static const uint16_t seqs[] = {65534, 65535, 0, 1, 3, 3, 1, 4, 6};
    struct link_decoder d;
    link_decoder_init(&d);
    int k = 0;
    for (size_t i = 0; i < sizeof seqs / sizeof seqs[0]; i++) {
        uint8_t f[32];
        size_t n = link_frame_encode(f, sizeof f, LINK_LOG, 0, seqs[i], "s", 1);
        k = push_all(&d, f, n, k);
    }
    CHECK_EQ_INT(k, 9);
    /* 1 -> 3 and 4 -> 6 skip one each; 3 again and 1 again are frames sent
     * again (behind the expected one), no gap, and 4 after them is the
     * expected one; the wrap 65535 -> 0 is no gap. */
    CHECK_EQ_INT(d.stats.seq_gaps, 2);
    CHECK_EQ_INT(d.next_seq, 7);
}

/* A frame flagged LINK_FLAG_SESSION starts the numbering again: no gap is
 * counted at it, and the frames after it follow from its seq. */
static void frame_session_restarts_seq(void)
{
    static const uint16_t seqs[] = {40, 41, 0, 1, 2, 9};
    static const uint8_t flags[] = {0, 0, LINK_FLAG_SESSION, 0, 0, 0};
    struct link_decoder d;
    link_decoder_init(&d);
    int k = 0;
    for (size_t i = 0; i < sizeof seqs / sizeof seqs[0]; i++) {
        uint8_t f[32];
        size_t n = link_frame_encode(f, sizeof f, LINK_CMD, flags[i], seqs[i], "s", 1);
        k = push_all(&d, f, n, k);
    }
    CHECK_EQ_INT(k, 6);
    /* 41 -> 0 is a new session, 2 -> 9 is a gap. */
    CHECK_EQ_INT(d.stats.seq_gaps, 1);
}

/* Many frames of assorted sizes back to back, handed to the decoder in
 * chunks of random sizes; every frame comes out intact and in order. */
static void frame_stream_split_at_random_boundaries(void)
{
    enum { NFRAMES = 48 };
    static uint8_t stream[NFRAMES * LINK_MAX_FRAME], payload[LINK_MAX_PAYLOAD];
    size_t len = 0, lens[NFRAMES];
    srand(12345);
    for (int i = 0; i < NFRAMES; i++) {
        lens[i] = (size_t)(rand() % 5 == 0 ? LINK_MAX_PAYLOAD : rand() % 300);
        fill(payload, lens[i], (unsigned)i);
        len += link_frame_encode(stream + len, sizeof stream - len, LINK_DATA, 0,
                                 (uint16_t)i, payload, lens[i]);
    }
    struct link_decoder d;
    link_decoder_init(&d);
    int k = 0;
    for (size_t off = 0; off < len;) {
        size_t chunk = 1 + (size_t)rand() % 700;
        if (chunk > len - off)
            chunk = len - off;
        k = push_all(&d, stream + off, chunk, k);
        off += chunk;
    }
    CHECK_EQ_INT(k, NFRAMES);
    int bad = 0;
    for (int i = 0; i < NFRAMES && i < MAX_GOT; i++) {
        fill(payload, lens[i], (unsigned)i);
        bad += got[i].seq != i || got[i].length != lens[i] ||
               memcmp(got[i].payload, payload, lens[i]) != 0;
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(d.stats.seq_gaps + d.stats.crc_errors + d.stats.junk_bytes, 0);
}

int main(void)
{
    RUN(frame_round_trip_every_length);
    RUN(frame_header_layout_is_pinned);
    RUN(frame_max_size_and_oversize);
    RUN(frame_resync_after_junk);
    RUN(frame_resync_keeps_bytes_after_recovered_frame);
    RUN(frame_bad_crc_counted);
    RUN(frame_bad_length_counted);
    RUN(frame_seq_gap_counted);
    RUN(frame_session_restarts_seq);
    RUN(frame_stream_split_at_random_boundaries);
    return check_exit();
}
