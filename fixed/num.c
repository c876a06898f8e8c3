/* fixed/num.c: the num_t operations too long to inline (fixed point). */
#include "fixed/num.h"

#include "fixed/isqrt.h"

#if defined(LINKS1_NUM_FIXED)

/* sqrt of a value given with 2*NUM_FRAC_BITS fraction bits, rounded to
 * nearest: r = floor(sqrt(n)); round up when n > r^2 + r, i.e. when
 * sqrt(n) > r + 1/2. */
static num_t num__sqrt_wide(uint64_t n)
{
    uint64_t r = isqrt_u64(n);
    if (n - r * r > r)
        r++;
    if (r > (uint64_t)NUM_RAW_MAX)
        return NUM_RAW_SAT;
    return (num_t)r;
}

/* One 16-bit digit of a quotient (Knuth's algorithm D, base 2^16):
 * floor((u * 2^16 + x) / d) for u < d, d normalised (top bit set), d1 and
 * d0 its halves; *rem gets the remainder.  The estimate u / d1 is never
 * low; the loop lowers it until the product with the whole of d fits. */
static uint32_t num__div_digit(uint32_t u, uint32_t x, uint32_t d, uint32_t *rem)
{
    uint32_t d1 = d >> 16, d0 = d & 0xFFFFu;
    uint32_t q = u / d1, rhat = u - q * d1;
    while (q > 0xFFFFu || q * d0 > ((rhat << 16) | x)) {
        q--;
        rhat += d1;
        if (rhat > 0xFFFFu)
            break;
    }
    *rem = (u << 16) + x - q * d; /* the true remainder is below d: exact mod 2^32 */
    return q;
}

/* floor(n / d) for n >> 32 < d (so the quotient fits 32 bits), exact,
 * with two 32-bit divisions: libgcc's 64-bit division is a long loop on
 * a board whose multilib has no divide instruction. */
static uint32_t num__udiv_64_32(uint64_t n, uint32_t d)
{
    uint32_t hi = (uint32_t)(n >> 32), lo = (uint32_t)n;
    if (hi == 0)
        return lo / d;
    int s = __builtin_clz(d); /* normalise: d's top bit set */
    d <<= s;
    if (s)
        hi = (hi << s) | (lo >> (32 - s));
    lo <<= s;
    uint32_t rem;
    uint32_t q1 = num__div_digit(hi, lo >> 16, d, &rem);
    uint32_t q0 = num__div_digit(rem, lo & 0xFFFFu, d, &rem);
    return (q1 << 16) | q0;
}

/* The fraction bits of a quotient in two 32-bit steps of these many bits
 * (the first the larger), for a divisor below 2^(32 - NUM__DIV_STEP1). */
#define NUM__DIV_STEP1 ((NUM_FRAC_BITS + 1) / 2)
#define NUM__DIV_STEP2 (NUM_FRAC_BITS / 2)

/* round(ua 2^NUM_FRAC_BITS / ub) (halves up) for 0 < ub < 2^(32 -
 * NUM__DIV_STEP1), or UINT32_MAX when that is 2^31 or more: ua = qa ub + ra,
 * then ra 2^NUM_FRAC_BITS / ub by long division in two steps whose
 * dividends fit 32 bits (each remainder is below ub); the last remainder
 * r2 and ub/2 decide the rounding. */
static uint32_t num__quot_narrow(uint32_t ua, uint32_t ub)
{
    uint32_t qa = ua / ub, ra = ua - qa * ub;
    if (qa >> (31 - NUM_FRAC_BITS))
        return UINT32_MAX;
    uint32_t x1 = ra << NUM__DIV_STEP1, f1 = x1 / ub, r1 = x1 - f1 * ub;
    uint32_t x2 = r1 << NUM__DIV_STEP2, f2 = x2 / ub, r2 = x2 - f2 * ub;
    return (qa << NUM_FRAC_BITS) + (f1 << NUM__DIV_STEP2) + f2 + (r2 >= ub - ub / 2);
}

/* The same for any ub > 0: the 64-bit dividend ua 2^NUM_FRAC_BITS + ub/2
 * divided at once; a quotient of 2^32 or more gives UINT32_MAX. */
static uint32_t num__quot_wide(uint32_t ua, uint32_t ub)
{
    uint64_t n = ((uint64_t)ua << NUM_FRAC_BITS) + ub / 2;
    if ((uint32_t)(n >> 32) >= ub)
        return UINT32_MAX;
    return num__udiv_64_32(n, ub);
}

/* num_add's, num_sub's and num_mul's every case but their fast paths:
 * out of line, so that the fast paths inline small wherever they are
 * used. */
num_t num__add_rest(num_t a, num_t b) { return num__add_wide(a, b); }
num_t num__sub_rest(num_t a, num_t b) { return num__sub_wide(a, b); }
num_t num__mul_rest(num_t a, num_t b) { return num__mul_wide(a, b); }

/* num_div of magnitudes ua and ub, of the sign s (0, or all ones when the
 * signs differ), where num_div's common case does not hold: a marker
 * (magnitude INT32_MAX) or a zero divisor gives a marker of that sign,
 * anything else the rounded quotient (num__quot_wide: any divisor).  Not
 * inlined, so that num_div keeps to a few registers. */
static __attribute__((noinline)) num_t num__div_rest(uint32_t ua, uint32_t ub, uint32_t s)
{
    uint32_t q = UINT32_MAX;
    if (ua != (uint32_t)INT32_MAX && ub != (uint32_t)INT32_MAX && ub != 0)
        q = num__quot_wide(ua, ub);
    if (q > (uint32_t)NUM_RAW_MAX)
        q = (uint32_t)NUM_RAW_SAT;
    return (num_t)((q ^ s) - s);
}

/* The common case at once, with num__quot_narrow: a divisor of magnitude
 * 0 < |b| < 2^(32 - NUM__DIV_STEP1) and a dividend no marker (|a| below
 * INT32_MAX: (|a| + 1) >> 31 is 0); a quotient out of range is a marker. */
num_t num_div(num_t a, num_t b)
{
    uint32_t s = (uint32_t)((a ^ b) >> 31); /* 0, or all ones: -q is (q ^ s) - s */
    uint32_t ua = a < 0 ? -(uint32_t)a : (uint32_t)a, ub = b < 0 ? -(uint32_t)b : (uint32_t)b;
    if (((ub - 1u) >> (32 - NUM__DIV_STEP1)) | ((ua + 1u) >> 31))
        return num__div_rest(ua, ub, s);
    uint32_t q = num__quot_narrow(ua, ub);
    if (q > (uint32_t)NUM_RAW_MAX)
        q = (uint32_t)NUM_RAW_SAT;
    return (num_t)((q ^ s) - s);
}

num_t num__from_ratio_wide(int32_t num, int32_t den)
{
    if (den == 0)
        return num < 0 ? -NUM_RAW_SAT : NUM_RAW_SAT;
    uint32_t s = (uint32_t)((num ^ den) >> 31); /* 0, or all ones: -q is (q ^ s) - s */
    uint32_t q = num__quot_wide(num < 0 ? -(uint32_t)num : (uint32_t)num,
                                den < 0 ? -(uint32_t)den : (uint32_t)den);
    if (q > (uint32_t)NUM_RAW_MAX)
        q = (uint32_t)NUM_RAW_SAT;
    return (num_t)((q ^ s) - s);
}

num_t num_sqrt(num_t a)
{
    if (a == NUM_RAW_SAT)
        return NUM_RAW_SAT;
    if (a <= 0) /* includes -marker: square roots of small negative
                   rounding residue are meant to be 0 */
        return a == -NUM_RAW_SAT ? NUM_RAW_SAT : 0;
    return num__sqrt_wide((uint64_t)a << NUM_FRAC_BITS);
}

/* The definition (num_dot3 in fixed/num.h is its fast form): the
 * products, each divided by 4 toward zero, summed, rounded to
 * NUM_FRAC_BITS - 2 fewer bits.  Each product is below 2^62; dropping 2 of
 * its 32 fraction bits keeps the sum of three below 2^63. */
num_t num__dot3_exact(num_t ax, num_t ay, num_t az, num_t bx, num_t by, num_t bz)
{
    if (num_is_sat(ax) || num_is_sat(ay) || num_is_sat(az) ||
        num_is_sat(bx) || num_is_sat(by) || num_is_sat(bz))
        return NUM_RAW_SAT;
    int64_t s = ((int64_t)ax * bx) / 4 + ((int64_t)ay * by) / 4 +
                ((int64_t)az * bz) / 4;
    return num__from_wide(num__round_shift(s, NUM_FRAC_BITS - 2));
}

num_t num_len3(num_t x, num_t y, num_t z)
{
    if (num_is_sat(x) || num_is_sat(y) || num_is_sat(z))
        return NUM_RAW_SAT;
    /* three squares below 2^62 each: the unsigned sum cannot wrap */
    uint64_t s = (uint64_t)((int64_t)x * x) + (uint64_t)((int64_t)y * y) +
                 (uint64_t)((int64_t)z * z);
    return num__sqrt_wide(s);
}

/* a^n for |a| <= 1 with Q30 intermediates: every value stays within
 * [-1, 1], so a Q30 x Q30 product (< 2^60) fits an int64. */
num_t num_pow_int_fixed_unit(num_t a, uint32_t n)
{
    const int wide = 30;
    int64_t base = (int64_t)a * ((int64_t)1 << (wide - NUM_FRAC_BITS));
    int64_t r = (int64_t)1 << wide;
    while (n) {
        if (n & 1u)
            r = num__round_shift(r * base, wide);
        n >>= 1;
        if (n)
            base = num__round_shift(base * base, wide);
    }
    return (num_t)num__round_shift(r, wide - NUM_FRAC_BITS);
}

num_t num_from_f32_bits(uint32_t bits)
{
    int negative = (bits >> 31) != 0;
    int32_t exponent = (int32_t)((bits >> 23) & 0xffu);
    uint32_t mantissa = bits & 0x7fffffu;
    if (exponent == 0xff) /* infinity or NaN */
        return negative ? -NUM_RAW_SAT : NUM_RAW_SAT;
    if (exponent == 0) /* zero or subnormal: far below one step */
        return 0;
    mantissa |= 0x800000u;
    /* value = mantissa * 2^(exponent - 150); raw = value * 2^NUM_FRAC_BITS */
    int32_t shift = exponent - 150 + NUM_FRAC_BITS;
    uint64_t raw;
    if (shift >= 0) {
        if (shift > 31)
            return negative ? -NUM_RAW_SAT : NUM_RAW_SAT;
        raw = (uint64_t)mantissa << shift;
    } else {
        if (-shift > 40)
            return 0;
        /* round to nearest, halves away from zero */
        raw = ((uint64_t)mantissa + ((uint64_t)1 << (-shift - 1))) >> -shift;
    }
    if (raw > (uint64_t)NUM_RAW_MAX)
        return negative ? -NUM_RAW_SAT : NUM_RAW_SAT;
    return negative ? -(num_t)raw : (num_t)raw;
}

#endif
