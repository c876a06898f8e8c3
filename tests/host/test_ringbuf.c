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

/* Word records (the lines'): a record of two pieces in, its first words
 * peeked, the rest taken after them; all or nothing, across the wrap, from
 * and into unaligned memory. */
static void test_word_records(void)
{
    _Alignas(4) uint8_t mem[32];
    _Alignas(4) uint8_t hdr[4] = {'h', 'd', 'r', '!'}, out[33], body[25];
    struct ringbuf r;
    for (int i = 0; i < 25; i++)
        body[i] = (uint8_t)('a' + i);
    ringbuf_init(&r, mem, sizeof mem);
    CHECK(ringbuf_put_words(&r, hdr, 1, body, 6) == 0);
    CHECK(ringbuf_put_words(&r, hdr, 1, body, 1) == -1); /* 4 free: nothing written */
    CHECK_EQ_INT(ringbuf_used(&r), 28);
    CHECK_EQ_INT(ringbuf_words_in(&r), 7); /* the header and 6 */
    ringbuf_read_words(&r, 0, out, 1);
    CHECK(memcmp(out, hdr, 4) == 0);
    CHECK_EQ_INT(ringbuf_used(&r), 28); /* a read takes nothing */
    ringbuf_read_words(&r, 1, out, 6);
    CHECK(memcmp(out, body, 24) == 0);
    ringbuf_take_words(&r, 7);
    CHECK_EQ_INT(ringbuf_used(&r), 0);
    /* head and tail at 28: the next record wraps after its header word. */
    CHECK(ringbuf_put_words(&r, hdr, 1, body + 1, 5) == 0);
    CHECK(memcmp(mem, body + 1, 20) == 0 && memcmp(mem + 28, hdr, 4) == 0);
    ringbuf_read_words(&r, 1, out + 1, 5);
    CHECK(memcmp(out + 1, body + 1, 20) == 0);
    ringbuf_take_words(&r, 6);
    /* The byte calls see the same bytes. */
    CHECK(ringbuf_put_words(&r, hdr, 1, body, 6) == 0);
    CHECK(ringbuf_get(&r, out, 28) == 0 && memcmp(out, hdr, 4) == 0 &&
          memcmp(out + 4, body, 24) == 0);
    /* A record ending on the ring's last word, from word 1: no wrap. */
    ringbuf_init(&r, mem, sizeof mem);
    CHECK(ringbuf_put_words(&r, hdr, 1, body, 0) == 0);
    ringbuf_take_words(&r, 1);
    CHECK(ringbuf_put_words(&r, hdr, 1, body, 6) == 0);
    CHECK(memcmp(mem + 4, hdr, 4) == 0 && memcmp(mem + 8, body, 24) == 0);
    ringbuf_read_words(&r, 1, out, 6);
    CHECK(memcmp(out, body, 24) == 0);
    ringbuf_take_words(&r, 7);
    CHECK_EQ_INT(ringbuf_used(&r), 0);
}

int main(void)
{
    RUN(test_init_rejects_bad_sizes);
    RUN(test_put_get_all_or_nothing);
    RUN(test_wraps_around_the_end);
    RUN(test_indices_wrap_at_2_to_32);
    RUN(test_get_some_and_long_stream);
    RUN(test_word_records);
    return check_exit();
}
