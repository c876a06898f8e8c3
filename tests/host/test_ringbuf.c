/* test_ringbuf.c: the SPSC byte ring (kernel/ringbuf.c). */
#include <stdint.h>
#include <string.h>

#include "kernel/ringbuf.h"
#include "tests/check.h"

static void test_init_rejects_bad_sizes(void)
{
    uint8_t mem[16];
    struct ringbuf r;
    CHECK(ringbuf_init(&r, mem, 0) == -1);
    CHECK(ringbuf_init(&r, mem, 1) == -1);
    CHECK(ringbuf_init(&r, mem, 12) == -1);
    CHECK(ringbuf_init(&r, mem, 16) == 0);
    CHECK_EQ_INT(ringbuf_used(&r), 0);
    CHECK_EQ_INT(ringbuf_free(&r), 16);
}

static void test_put_get_all_or_nothing(void)
{
    uint8_t mem[8], out[8];
    struct ringbuf r;
    ringbuf_init(&r, mem, sizeof mem);
    CHECK(ringbuf_put(&r, "abcde", 5) == 0);
    CHECK(ringbuf_put(&r, "xyzw", 4) == -1); /* only 3 free: nothing written */
    CHECK_EQ_INT(ringbuf_used(&r), 5);
    CHECK(ringbuf_get(&r, out, 6) == -1);    /* only 5 there: nothing taken */
    CHECK_EQ_INT(ringbuf_used(&r), 5);
    CHECK(ringbuf_peek(&r, out, 2) == 0 && memcmp(out, "ab", 2) == 0);
    CHECK_EQ_INT(ringbuf_used(&r), 5);
    CHECK(ringbuf_get(&r, out, 5) == 0 && memcmp(out, "abcde", 5) == 0);
    CHECK_EQ_INT(ringbuf_used(&r), 0);
}

static void test_wraps_around_the_end(void)
{
    uint8_t mem[8], out[8];
    struct ringbuf r;
    ringbuf_init(&r, mem, sizeof mem);
    ringbuf_put(&r, "123456", 6);
    ringbuf_get(&r, out, 6);
    /* head and tail at 6: the next 5 bytes wrap after 2. */
    CHECK(ringbuf_put(&r, "ABCDE", 5) == 0);
    CHECK(ringbuf_get(&r, out, 5) == 0 && memcmp(out, "ABCDE", 5) == 0);
    CHECK(ringbuf_put(&r, "12345678", 8) == 0); /* completely full */
    CHECK_EQ_INT(ringbuf_free(&r), 0);
    CHECK(ringbuf_put_byte(&r, 'x') == -1);
    CHECK(ringbuf_get(&r, out, 8) == 0 && memcmp(out, "12345678", 8) == 0);
}

static void test_indices_wrap_at_2_to_32(void)
{
    uint8_t mem[16], out[16];
    struct ringbuf r;
    ringbuf_init(&r, mem, sizeof mem);
    r.head = r.tail = 0xFFFFFFF9u; /* 7 bytes before the counters wrap */
    CHECK(ringbuf_put(&r, "0123456789", 10) == 0);
    CHECK_EQ_INT(ringbuf_used(&r), 10);
    CHECK_EQ_INT(ringbuf_free(&r), 6);
    CHECK(ringbuf_get(&r, out, 10) == 0 && memcmp(out, "0123456789", 10) == 0);
    CHECK_EQ_INT(ringbuf_used(&r), 0);
}

static void test_get_some_and_long_stream(void)
{
    uint8_t mem[64], out[64];
    struct ringbuf r;
    ringbuf_init(&r, mem, sizeof mem);
    uint32_t next_in = 0, next_out = 0, bad = 0;
    /* Push 100000 bytes through in uneven pieces; every byte must come out
     * once, in order. */
    while (next_out < 100000u) {
        uint32_t n = 1 + (next_in * 7u) % 23u;
        uint8_t in[32];
        for (uint32_t i = 0; i < n; i++)
            in[i] = (uint8_t)(next_in + i);
        if (next_in < 100000u && ringbuf_put(&r, in, n) == 0)
            next_in += n;
        uint32_t got = ringbuf_get_some(&r, out, 1 + next_out % 41u);
        for (uint32_t i = 0; i < got; i++)
            bad += out[i] != (uint8_t)(next_out + i);
        next_out += got;
        if (next_in >= 100000u && ringbuf_used(&r) == 0)
            break;
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(next_out, next_in);
    CHECK_EQ_INT(ringbuf_get_some(&r, out, 10), 0);
}

/* A record of two pieces in, then out skipping a peeked header: all or
 * nothing, across the wrap, word-aligned or not. */
static void test_put2_and_get_after(void)
{
    _Alignas(4) uint8_t mem[32];
    _Alignas(4) uint8_t hdr[4] = {'h', 'd', 'r', '!'}, out[32], body[24];
    struct ringbuf r;
    for (int i = 0; i < 24; i++)
        body[i] = (uint8_t)('a' + i);
    ringbuf_init(&r, mem, sizeof mem);
    CHECK(ringbuf_put2(&r, hdr, 4, body, 24) == 0);
    CHECK(ringbuf_put2(&r, hdr, 4, body, 1) == -1); /* 4 free: nothing written */
    CHECK_EQ_INT(ringbuf_used(&r), 28);
    CHECK(ringbuf_get_after(&r, 4, out, 25) == -1);  /* only 24 after the header */
    CHECK(ringbuf_peek(&r, out, 4) == 0 && memcmp(out, hdr, 4) == 0);
    CHECK(ringbuf_get_after(&r, 4, out, 24) == 0 && memcmp(out, body, 24) == 0);
    CHECK_EQ_INT(ringbuf_used(&r), 0);
    /* head and tail at 28: the next record wraps inside its body. */
    CHECK(ringbuf_put2(&r, hdr, 4, body, 20) == 0);
    CHECK(ringbuf_get_after(&r, 4, out, 20) == 0 && memcmp(out, body, 20) == 0);
    /* Odd sizes: the byte-by-byte path, then the ring no longer aligned. */
    CHECK(ringbuf_put2(&r, hdr + 1, 3, body + 1, 5) == 0);
    CHECK(ringbuf_get_after(&r, 3, out + 1, 5) == 0 && memcmp(out + 1, body + 1, 5) == 0);
    CHECK(ringbuf_put2(&r, hdr, 4, body, 24) == 0);
    CHECK(ringbuf_get(&r, out, 28) == 0 && memcmp(out, hdr, 4) == 0 &&
          memcmp(out + 4, body, 24) == 0);
}

int main(void)
{
    RUN(test_init_rejects_bad_sizes);
    RUN(test_put_get_all_or_nothing);
    RUN(test_wraps_around_the_end);
    RUN(test_indices_wrap_at_2_to_32);
    RUN(test_get_some_and_long_stream);
    RUN(test_put2_and_get_after);
    return check_exit();
}
