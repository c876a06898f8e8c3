/* wordsum.c: the word sum (see wordsum.h). */
#include "proto/wordsum.h"

/* A word of four bytes at p, little-endian, p at any alignment. */
static inline uint32_t wordsum_word(const uint8_t *p)
{
    uint32_t w;
    __builtin_memcpy(&w, p, 4); /* a plain load: -ffreestanding would call memcpy */
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    w = __builtin_bswap32(w);
#endif
    return w;
}

/* A word-aligned u32 that may alias any other type. */
typedef uint32_t __attribute__((may_alias)) wordsum_aligned_t;

#define WORDSUM_STEP(w) (a += (w), b += a)

void wordsum_update(wordsum_t *s, const void *data, size_t len)
{
    const uint8_t *p = data;
    uint32_t a = s->a, b = s->b;
    size_t n = len / 4;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    /* eight aligned words a step, in registers (the board loads them in
     * pairs or all at once) */
    if (((uintptr_t)p & 3u) == 0)
        for (; n >= 8; n -= 8, p += 32) {
            const wordsum_aligned_t *q = (const wordsum_aligned_t *)(const void *)p;
            uint32_t w0 = q[0], w1 = q[1], w2 = q[2], w3 = q[3];
            uint32_t w4 = q[4], w5 = q[5], w6 = q[6], w7 = q[7];
            WORDSUM_STEP(w0), WORDSUM_STEP(w1), WORDSUM_STEP(w2), WORDSUM_STEP(w3);
            WORDSUM_STEP(w4), WORDSUM_STEP(w5), WORDSUM_STEP(w6), WORDSUM_STEP(w7);
        }
#endif
    for (; n > 0; n--, p += 4) {
        a += wordsum_word(p);
        b += a;
    }
    uint32_t tail = (uint32_t)(len % 4);
    if (tail) {
        uint32_t w = 0;
        for (uint32_t i = 0; i < tail; i++)
            w |= (uint32_t)p[i] << (8 * i);
        a += w;
        b += a;
    }
    s->a = a;
    s->b = b;
    s->words += (uint32_t)((len + 3) / 4);
}
