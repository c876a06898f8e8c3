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

/* Four-lane integer vectors where the target has them: x86-64 (SSE2),
 * AArch64, and the Cortex-A firmware with its FPU (whose Advanced SIMD
 * this file alone uses).  Not the builds without an FPU. */
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ &&                     \
    (defined(__SSE2__) || defined(__aarch64__) ||                                               \
     (defined(__arm__) && defined(__ARM_PCS_VFP) && defined(__ARM_ARCH_PROFILE) &&              \
      __ARM_ARCH_PROFILE == 'A'))
#define WORDSUM_LANES 1
#if defined(__arm__) && !defined(__clang__)
#define WORDSUM_SIMD __attribute__((target("fpu=neon-vfpv4")))
#else
#define WORDSUM_SIMD
#endif
typedef uint32_t wordsum_v4_t __attribute__((vector_size(16), aligned(4), may_alias));

/* groups (a multiple of 4) of four aligned words at data into *a and *b,
 * as WORDSUM_STEP word by word would: lane j of va sums the words 4g + j,
 * of vb those sums after each group.  With m words in all, word 4g + j
 * weighs m - 4g - j in b, which is 4 (groups - g) - j: 4 times vb's lanes
 * less j times va's. */
static WORDSUM_SIMD void wordsum_lanes(uint32_t *a, uint32_t *b, const void *data, size_t groups)
{
    const wordsum_v4_t *q = data;
    wordsum_v4_t va = {0, 0, 0, 0}, vb = {0, 0, 0, 0};
    for (size_t g = 0; g < groups; g += 4, q += 4) {
        va += q[0], vb += va;
        va += q[1], vb += va;
        va += q[2], vb += va;
        va += q[3], vb += va;
    }
    uint32_t sa = va[0] + va[1] + va[2] + va[3], sb = vb[0] + vb[1] + vb[2] + vb[3];
    *b += 4u * (uint32_t)groups * *a + 4u * sb - (va[1] + 2u * va[2] + 3u * va[3]);
    *a += sa;
}
#endif

void wordsum_update(wordsum_t *s, const void *data, size_t len)
{
    const uint8_t *p = data;
    uint32_t a = s->a, b = s->b;
    size_t n = len / 4;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#if WORDSUM_LANES
    /* sixteen aligned words a step in four lanes */
    if (((uintptr_t)p & 3u) == 0 && n >= 16) {
        size_t groups = n / 16 * 4;
        wordsum_lanes(&a, &b, p, groups);
        n -= 4 * groups;
        p += 16 * groups;
    }
#endif
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
