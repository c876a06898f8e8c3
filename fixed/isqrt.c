/* fixed/isqrt.c: the integer square root (see isqrt.h).
 *
 * The input is shifted left by an even count until its top two bits are
 * not both zero (m in [2^62, 2^64)); floor(sqrt(n)) is floor(sqrt(m)) shifted
 * back by half that count.  The root of m's top 32 bits comes from a table
 * seed, one Newton step (one 32-bit division) and a correction; the low
 * 16 bits of the root come from one step of Zimmermann's "Karatsuba square
 * root" (one 32-bit division), then at most one correction down (where
 * the remainder m - s*s is below 0).  The top root's correction makes it
 * exact whatever the seed; the seed only makes it short.  Every division
 * is 32-bit (the A15's UDIV), no 64-bit division and no floating point. */
#include "fixed/isqrt.h"

/* round(4096 * sqrt(i + 0.5)) for i = 64..255: sqrt of the middle of
 * [i * 2^24, (i + 1) * 2^24), a top word's range given its top 8 bits */
static const uint16_t isqrt_seed[192] = {
    32896, 33150, 33402, 33652, 33900, 34147, 34392, 34635, 34876, 35116, 35354, 35590,
    35825, 36059, 36291, 36521, 36750, 36978, 37204, 37429, 37652, 37874, 38095, 38315,
    38533, 38750, 38966, 39181, 39394, 39606, 39818, 40028, 40237, 40445, 40652, 40857,
    41062, 41266, 41469, 41671, 41871, 42071, 42270, 42468, 42665, 42861, 43057, 43251,
    43445, 43637, 43829, 44020, 44210, 44400, 44588, 44776, 44963, 45149, 45334, 45519,
    45703, 45886, 46069, 46250, 46431, 46612, 46791, 46970, 47149, 47326, 47503, 47679,
    47855, 48030, 48204, 48378, 48551, 48723, 48895, 49067, 49237, 49407, 49577, 49746,
    49914, 50082, 50249, 50416, 50582, 50747, 50912, 51077, 51241, 51404, 51567, 51730,
    51892, 52053, 52214, 52374, 52534, 52694, 52853, 53011, 53169, 53327, 53484, 53640,
    53797, 53952, 54108, 54262, 54417, 54571, 54724, 54877, 55030, 55182, 55334, 55485,
    55636, 55787, 55937, 56087, 56236, 56385, 56534, 56682, 56830, 56977, 57124, 57271,
    57417, 57563, 57709, 57854, 57999, 58143, 58287, 58431, 58574, 58717, 58860, 59002,
    59144, 59286, 59427, 59568, 59709, 59849, 59989, 60129, 60268, 60407, 60546, 60684,
    60822, 60960, 61098, 61235, 61372, 61508, 61644, 61780, 61916, 62051, 62186, 62321,
    62456, 62590, 62724, 62857, 62991, 63124, 63256, 63389, 63521, 63653, 63785, 63916,
    64047, 64178, 64309, 64439, 64569, 64699, 64828, 64957, 65086, 65215, 65344, 65472,
};

/* floor(sqrt(h)) for h in [2^30, 2^32): a result in [2^15, 2^16). */
static uint32_t isqrt_top(uint32_t h)
{
    uint32_t x = isqrt_seed[(h >> 24) - 64];
    /* (x + h/x) / 2 >= sqrt(h) for any x > 0, so x is never below the root */
    x = (x + h / x) >> 1;
    if (x > 0xFFFFu)
        x = 0xFFFFu; /* the root is below 2^16: x*x stays in 32 bits */
    while (x * x > h)
        x--;
    return x;
}

uint64_t isqrt_u64(uint64_t n)
{
    if (n == 0)
        return 0;
    int shift = __builtin_clzll(n) & ~1;
    uint64_t m = n << shift;
    uint32_t hi = (uint32_t)(m >> 32), lo = (uint32_t)m;
    uint32_t s1 = isqrt_top(hi); /* in [2^15, 2^16): hi >= 2^30 */
    uint32_t r1 = hi - s1 * s1;  /* 0..2 s1 */
    /* the next 16 bits: q = (r1 * 2^16 + a1) / (2 s1), a1 = lo's top half;
     * halved, the dividend fits 32 bits (r1 < 2^17).  q <= 2^16 (r1 <= 2
     * s1, s1 >= 2^15) */
    uint32_t a1 = lo >> 16;
    uint32_t half = (r1 << 15) | (a1 >> 1);
    uint32_t q = half / s1;
    uint32_t u = ((half - q * s1) << 1) | (a1 & 1u); /* remainder, < 2 s1 */
    /* s = s1 2^16 + q is the root or one above it (Zimmermann's step,
     * s1 exact and normalised): one above when the remainder m - s^2 = u
     * 2^16 + lo's low half - q^2 is below 0 */
    uint64_t s = ((uint64_t)s1 << 16) + q;
    s -= ((uint64_t)u << 16) + (lo & 0xFFFFu) < (uint64_t)q * q;
    return (uint32_t)s >> (shift / 2);
}
