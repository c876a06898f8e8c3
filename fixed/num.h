/* fixed/num.h: the renderer's one number type, num_t, and every operation on it.
 *
 * The Makefile passes exactly one of
 *   LINKS1_NUM_DOUBLE  num_t = double (the host reference)
 *   LINKS1_NUM_FLOAT   num_t = float  (VFP on the board, or soft float)
 *   LINKS1_NUM_FIXED   num_t = int32_t fixed point, pure integer code
 * and the same renderer source builds in each.  The renderer never uses a
 * C operator on num_t: always num_add(), num_mul(), num_lt()...
 *
 * Bit-for-bit equality between host and board (same arithmetic): the IEEE
 * builds use only + - * / and sqrt (all correctly rounded), compiled with
 * -ffp-contract=off so no fused multiply-add sneaks in; the fixed build is
 * integer code whose results do not depend on the compiler.
 *
 * Fixed format (docs/fixed-point.md says why): signed Q12.19 in an int32_t,
 * value = raw / 2^NUM_FRAC_BITS: 1 sign bit, 12 integer bits, 19 fraction
 * bits.  Range +-4095.999998, step 2^-19 (1.9e-6).  Every routine is written
 * for any NUM_FRAC_BITS from 8 to 24.
 *
 * Overflow, fixed build: every operation that can overflow SATURATES to a
 * reserved marker, +NUM_RAW_SAT or -NUM_RAW_SAT (= +-INT32_MAX).  Those two
 * raw values are never produced by an in-range result (valid results lie in
 * [-(INT32_MAX-1), INT32_MAX-1]; INT32_MIN is never produced), so a marker
 * cannot be confused with a real value, and the marker is sticky: any
 * operation given a marker returns a marker.  num_is_sat() tells; the
 * renderer checks it where results are used (hit distances, pixel colours)
 * and counts pixels with lost precision.  In the IEEE builds the markers are
 * infinities and NaNs, and num_is_sat() is "not finite".
 * Underflow (a result smaller than one step) rounds to 0 silently.
 */
#ifndef LINKS1_FIXED_NUM_H
#define LINKS1_FIXED_NUM_H

#include <stdint.h>
#include <string.h>

#if defined(LINKS1_NUM_DOUBLE) + defined(LINKS1_NUM_FLOAT) + defined(LINKS1_NUM_FIXED) != 1
#error "define exactly one of LINKS1_NUM_DOUBLE, LINKS1_NUM_FLOAT, LINKS1_NUM_FIXED"
#endif

/* Scene coordinates (world and eye, as stored: the loader scales the
 * scene's lengths to a largest of 8..16, render/limits.h) and values without
 * a unit (proto/scene_format.h SCN_MAX_FACTOR) must stay within
 * +-NUM_COORD_LIMIT in every build so the fixed build keeps room for sums
 * of a few coordinates (lengths and dot products use 64-bit
 * intermediates).  NUM_FAR, the
 * distance treated as "beyond everything", is 4 NUM_COORD_LIMIT and must
 * stay below the fixed range (4096). */
#define NUM_COORD_LIMIT 1000
#define NUM_FAR NUM_C(4 * NUM_COORD_LIMIT)

#if defined(LINKS1_NUM_FIXED)
/* ------------------------------------------------------------ fixed point */
typedef int32_t num_t;

#ifndef NUM_FRAC_BITS /* overridable to measure other formats */
#define NUM_FRAC_BITS 19
#endif
#if NUM_FRAC_BITS < 8 || NUM_FRAC_BITS > 24
#error "NUM_FRAC_BITS must be 8..24"
#endif
#define NUM_ONE_RAW ((int32_t)1 << NUM_FRAC_BITS)
#define NUM_INT_MAX ((int32_t)(INT32_MAX >> NUM_FRAC_BITS)) /* largest whole value */
_Static_assert(4 * NUM_COORD_LIMIT < NUM_INT_MAX, "NUM_FAR must fit the fixed format");
#define NUM_RAW_SAT INT32_MAX         /* saturation marker magnitude */
#define NUM_RAW_MAX (INT32_MAX - 1)   /* largest valid magnitude */
#define NUM_NAME "fixed"

/* Literal constant: rounded at compile time, no floating point at run time. */
#define NUM_C(x)                                                              \
    ((num_t)((x) >= 0 ? (x) * (double)NUM_ONE_RAW + 0.5                       \
                      : (x) * (double)NUM_ONE_RAW - 0.5))
#define NUM_EPSILON ((num_t)1) /* one step */
/* Spacing of representable values near a: half of it is the most one
 * rounding changes a result (error estimates, render/prepare.c). */
static inline num_t num_ulp(num_t a) { (void)a; return NUM_EPSILON; }

static inline int num_is_sat(num_t a) { return a == NUM_RAW_SAT || a == -NUM_RAW_SAT; }
static inline int num_any_sat3(num_t a, num_t b, num_t c)
{
    return num_is_sat(a) || num_is_sat(b) || num_is_sat(c);
}

/* Clamp a wide result into range; out of range becomes the marker. */
static inline num_t num__from_wide(int64_t r)
{
    if (r > NUM_RAW_MAX)
        return NUM_RAW_SAT;
    if (r < -NUM_RAW_MAX)
        return -NUM_RAW_SAT;
    return (num_t)r;
}

/* Marker result for an operation given a marker; sign is that of the product
 * of the signs (0 counts as +). */
static inline num_t num__sticky(num_t a, num_t b)
{
    return ((a < 0) != (b < 0)) ? -NUM_RAW_SAT : NUM_RAW_SAT;
}

/* |a| in one's complement (a ^ sign): below 2^k for a in [-2^k, 2^k).  An
 * OR of several is below 2^k when each is: the fast paths' one test that
 * no input is a marker (magnitude INT32_MAX) and nothing can overflow. */
static inline uint32_t num__mag(num_t a) { return (uint32_t)(a ^ (a >> 31)); }

/* How far num_mul(a, num_recip(d)) may lie from num_div(a, d), for a
 * num_recip(d) that did not saturate, in steps: the reciprocal's rounding
 * (half a step) times |a|, and half a step for each of the three
 * roundings; one more for num__mag's one's complement.  A box test that
 * widens each slab's t by it passes every box the divisions pass. */
static inline num_t num_recip_mul_slack(num_t a)
{
    return (num_t)((num__mag(a) >> (NUM_FRAC_BITS + 1)) + 3);
}

/* saturates (a marker stays that marker) */
static inline num_t num__add_wide(num_t a, num_t b)
{
    if (num_is_sat(a) || num_is_sat(b))
        return num_is_sat(a) ? a : b;
    return num__from_wide((int64_t)a + b);
}

/* num__add_wide and num__sub_wide, not inlined (fixed/num.c) */
num_t num__add_rest(num_t a, num_t b);
num_t num__sub_rest(num_t a, num_t b);

/* saturates; within 2^29 each the sum is in range at once */
static inline num_t num_add(num_t a, num_t b)
{
    if ((num__mag(a) | num__mag(b)) < (uint32_t)1 << 29)
        return a + b;
    return num__add_rest(a, b);
}

static inline num_t num__sub_wide(num_t a, num_t b)
{
    if (num_is_sat(a) || num_is_sat(b))
        return num_is_sat(a) ? a : -b;
    return num__from_wide((int64_t)a - b);
}

/* saturates; within 2^29 each the difference is in range at once */
static inline num_t num_sub(num_t a, num_t b)
{
    if ((num__mag(a) | num__mag(b)) < (uint32_t)1 << 29)
        return a - b;
    return num__sub_rest(a, b);
}

/* exact (the marker negates to the other marker) */
static inline num_t num_neg(num_t a) { return -a; }
static inline num_t num_abs(num_t a) { return a < 0 ? -a : a; }

/* Round-to-nearest (halves away from zero) shift of a 64-bit product. */
static inline int64_t num__round_shift(int64_t p, int bits)
{
    int64_t half = (int64_t)1 << (bits - 1);
    if (p >= 0)
        return (p + half) >> bits;
    return -((-p + half) >> bits);
}

static inline num_t num__mul_wide(num_t a, num_t b)
{
    if (num_is_sat(a) || num_is_sat(b))
        return num__sticky(a, b);
    return num__from_wide(num__round_shift((int64_t)a * b, NUM_FRAC_BITS));
}

/* saturates; rounds to nearest (halves away from zero).  With a and b in
 * [-2^k, 2^k), k = (NUM_FRAC_BITS + 30) / 2 (no marker: in Q12.19 below
 * 32 either way), the product is at most 2^(NUM_FRAC_BITS + 30) and the
 * result in range: rounded with one add (a half, less one below 0) and
 * one shift, num__mul_wide's result without its checks. */
#define NUM__MUL_FAST_BITS ((NUM_FRAC_BITS + 30) / 2)
num_t num__mul_rest(num_t a, num_t b); /* num__mul_wide, not inlined (fixed/num.c) */
static inline num_t num_mul(num_t a, num_t b)
{
    int64_t p = (int64_t)a * b;
    if ((num__mag(a) | num__mag(b)) < (uint32_t)1 << NUM__MUL_FAST_BITS)
        return (num_t)((p + ((int64_t)1 << (NUM_FRAC_BITS - 1)) - (p < 0)) >> NUM_FRAC_BITS);
    return num__mul_rest(a, b);
}

num_t num_div(num_t a, num_t b); /* saturates; x/0 is a marker; rounds (halves up) */

num_t num_sqrt(num_t a);          /* exact rounding; a < 0 gives 0 */
num_t num__dot3_exact(num_t ax, num_t ay, num_t az, num_t bx, num_t by, num_t bz);
num_t num_from_f32_bits(uint32_t bits); /* integer decode; saturates;
                                           NaN/inf give a marker */

/* saturates */
static inline num_t num_from_int(int32_t i)
{
    return num__from_wide((int64_t)i * NUM_ONE_RAW);
}

num_t num__from_ratio_wide(int32_t num, int32_t den); /* every case (fixed/num.c) */

/* num/den for integers, rounded (halves away from zero); saturates (den
 * == 0 gives a marker).  Inline, 0 <= num < 2^(31 - NUM_FRAC_BITS) and den
 * > 0 (a map's byte over 255): the dividend num 2^NUM_FRAC_BITS + den/2
 * fits 32 bits, and the quotient the range. */
static inline num_t num_from_ratio(int32_t num, int32_t den)
{
    if ((uint32_t)num < (uint32_t)1 << (31 - NUM_FRAC_BITS) && den > 0)
        return (num_t)((((uint32_t)num << NUM_FRAC_BITS) + (uint32_t)den / 2) / (uint32_t)den);
    return num__from_ratio_wide(num, den);
}

/* a.b, one rounding at the end; saturates; a marker gives +NUM_RAW_SAT.
 * The definition is num__dot3_exact's (fixed/num.c): the products each
 * divided by 4 toward zero, summed, rounded half away from zero.  Those
 * four truncations and the sign of the rounding move the exact sum S by
 * at most 13 units of the product's last place, so when every input lies
 * in [-2^k, 2^k), k = (NUM_FRAC_BITS + 29) / 2 (no marker; S below 3
 * 2^(NUM_FRAC_BITS + 29), a result in range) and S sits at least 16
 * units from a rounding boundary, floor((S + half) / 2^NUM_FRAC_BITS) is
 * the same result with one 64-bit sum and one shift. */
#define NUM__DOT3_FAST_BITS ((NUM_FRAC_BITS + 29) / 2)
static inline num_t num_dot3(num_t ax, num_t ay, num_t az, num_t bx, num_t by, num_t bz)
{
    /* (a's | b's: the b half is shared by the three rows of a transform) */
    uint32_t mag = (num__mag(ax) | num__mag(ay) | num__mag(az)) |
                   (num__mag(bx) | num__mag(by) | num__mag(bz));
    if (mag < (uint32_t)1 << NUM__DOT3_FAST_BITS) {
        int64_t x = (int64_t)ax * bx + (int64_t)ay * by + (int64_t)az * bz +
                    ((int64_t)1 << (NUM_FRAC_BITS - 1));
        uint32_t low = (uint32_t)x & (((uint32_t)1 << NUM_FRAC_BITS) - 1);
        /* clear of a boundary (the result is in range: above) */
        if (low - 16u < ((uint32_t)1 << NUM_FRAC_BITS) - 32u)
            return (num_t)(x >> NUM_FRAC_BITS);
    }
    return num__dot3_exact(ax, ay, az, bx, by, bz);
}

/* floor(a) as an integer; markers give +-INT32_MAX >> NUM_FRAC_BITS */
static inline int32_t num_floor_int(num_t a) { return a >> NUM_FRAC_BITS; }
/* The same of an a >= 0 (the IEEE builds' is cheaper) */
static inline int32_t num_floor_nonneg_int(num_t a) { return a >> NUM_FRAC_BITS; }

/* a * 2^e: a shift, rounded to nearest when e < 0; saturates */
static inline num_t num_scale2(num_t a, int e)
{
    if (num_is_sat(a) || a == 0)
        return a;
    if (e >= 0)
        return e > 31 ? num__sticky(a, 1) : num__from_wide((int64_t)a * ((int64_t)1 << e));
    return e < -62 ? 0 : (num_t)num__round_shift(a, -e);
}

/* a * i for a small integer i; saturates */
static inline num_t num_mul_int(num_t a, int32_t i)
{
    if (num_is_sat(a))
        return num__sticky(a, i);
    return num__from_wide((int64_t)a * i);
}

static inline int num_lt(num_t a, num_t b) { return a < b; }
static inline int num_le(num_t a, num_t b) { return a <= b; }
static inline int num_gt(num_t a, num_t b) { return a > b; }
static inline int num_ge(num_t a, num_t b) { return a >= b; }
static inline int num_eq(num_t a, num_t b) { return a == b; }
/* a is +0 (the fixed build has one zero) */
static inline int num_is_plus_zero(num_t a) { return a == 0; }
/* a, or lim (0 < lim below the markers) where a is a marker or |a| > lim:
 * one sum and one unsigned comparison */
static inline num_t num_limit(num_t a, num_t lim)
{
    return (uint32_t)a + (uint32_t)lim > 2 * (uint32_t)lim ? lim : a;
}

/* 8-bit channel: clamp to [0,1], round(a * 255). */
static inline uint8_t num_to_u8(num_t a)
{
    if (a <= 0)
        return 0;
    if (a >= NUM_ONE_RAW)
        return 255;
    return (uint8_t)(((int64_t)a * 255 + NUM_ONE_RAW / 2) >> NUM_FRAC_BITS);
}

/* For tests and host tools only. */
static inline double num_to_double(num_t a) { return (double)a / NUM_ONE_RAW; }
static inline num_t num_from_double(double d)
{
    double r = d * NUM_ONE_RAW;
    if (!(r < (double)NUM_RAW_MAX + 0.5)) /* also catches NaN */
        return NUM_RAW_SAT;
    if (r <= -(double)NUM_RAW_MAX - 0.5)
        return -NUM_RAW_SAT;
    return (num_t)(r >= 0 ? r + 0.5 : r - 0.5);
}

#else
/* ------------------------------------------------------------ IEEE builds */
#if defined(LINKS1_NUM_DOUBLE)
typedef double num_t;
#define NUM_NAME "double"
#define NUM_C(x) ((num_t)(x))
#define NUM_EPSILON ((num_t)1e-12)
#define NUM__REL_STEP 0x1p-52 /* spacing relative to the value */
static inline num_t num_sqrt(num_t a) { return a > 0 ? __builtin_sqrt(a) : 0; }
#else
typedef float num_t;
#define NUM_NAME "float"
#define NUM_C(x) ((num_t)(x))
#define NUM_EPSILON ((num_t)1e-6f)
#define NUM__REL_STEP 0x1p-23f
static inline num_t num_sqrt(num_t a) { return a > 0 ? __builtin_sqrtf(a) : 0; }
#endif

/* Not finite: an overflow, a division by zero or an invalid operation. */
static inline int num_is_sat(num_t a) { return !(a - a == 0); }
/* Any of three not finite, with one comparison: x - x is 0 for every
 * finite x and NaN otherwise, and a sum of zeros and NaNs is 0 only when
 * no term is NaN. */
static inline int num_any_sat3(num_t a, num_t b, num_t c)
{
    return !((a - a) + (b - b) + (c - c) == 0);
}

static inline num_t num_add(num_t a, num_t b) { return a + b; }
static inline num_t num_sub(num_t a, num_t b) { return a - b; }
static inline num_t num_neg(num_t a) { return -a; }
/* |a| by its sign bit (one instruction; -0 gives +0) */
#if defined(LINKS1_NUM_DOUBLE)
static inline num_t num_abs(num_t a) { return __builtin_fabs(a); }
#else
static inline num_t num_abs(num_t a) { return __builtin_fabsf(a); }
#endif
/* Spacing of representable values near a (at most; normal numbers). */
static inline num_t num_ulp(num_t a) { return num_abs(a) * NUM__REL_STEP; }
static inline num_t num_mul(num_t a, num_t b) { return a * b; }
static inline num_t num_div(num_t a, num_t b) { return a / b; }
static inline num_t num_mul_int(num_t a, int32_t i) { return a * (num_t)i; }

/* Left to right, no fused multiply-add: the same bits on host and board. */
static inline num_t num_dot3(num_t ax, num_t ay, num_t az, num_t bx, num_t by, num_t bz)
{
    num_t s = ax * bx;
    s = s + ay * by;
    return s + az * bz;
}

static inline num_t num_from_int(int32_t i) { return (num_t)i; }
/* num/den, one rounding; den == 0 gives an infinity or NaN */
static inline num_t num_from_ratio(int32_t num, int32_t den) { return (num_t)num / (num_t)den; }
static inline num_t num_from_f32_bits(uint32_t bits)
{
    float f;
    __builtin_memcpy(&f, &bits, sizeof f); /* a bit cast: the firmware's
                                             -ffreestanding would call memcpy */
    return (num_t)f;
}

/* floor as an integer; callers keep |a| < 2^31 */
static inline int32_t num_floor_int(num_t a)
{
    int32_t i = (int32_t)a;
    return ((num_t)i > a) ? i - 1 : i;
}
/* The same of an a >= 0: the conversion's truncation is the floor */
static inline int32_t num_floor_nonneg_int(num_t a) { return (int32_t)a; }

static inline int num_lt(num_t a, num_t b) { return a < b; }
static inline int num_le(num_t a, num_t b) { return a <= b; }
static inline int num_gt(num_t a, num_t b) { return a > b; }
static inline int num_ge(num_t a, num_t b) { return a >= b; }
static inline int num_eq(num_t a, num_t b) { return a == b; }
/* a is +0, not -0 */
static inline int num_is_plus_zero(num_t a) { return a == 0 && !__builtin_signbit(a); }
/* a, or lim (lim > 0) where a is not finite or |a| > lim */
static inline num_t num_limit(num_t a, num_t lim) { return num_abs(a) <= lim ? a : lim; }

static inline uint8_t num_to_u8(num_t a)
{
    if (!(a > 0)) /* also NaN */
        return 0;
    if (a >= 1)
        return 255;
    return (uint8_t)(int32_t)(a * (num_t)255 + (num_t)0.5);
}

static inline double num_to_double(num_t a) { return (double)a; }
static inline num_t num_from_double(double d) { return (num_t)d; }

/* a * 2^e, exact (barring overflow and underflow): multiplications by 2
 * or 1/2, no libm ldexp */
static inline num_t num_scale2(num_t a, int e)
{
    for (; e > 0; e--)
        a = a * (num_t)2;
    for (; e < 0; e++)
        a = a * (num_t)0.5;
    return a;
}
#endif

/* ----------------------------------------------- built from the above */
#define NUM_ZERO NUM_C(0)
#define NUM_ONE NUM_C(1)
#define NUM_HALF NUM_C(0.5)

static inline num_t num_from_float(float f)
{
    uint32_t bits;
    __builtin_memcpy(&bits, &f, sizeof bits); /* a bit cast, not a call */
    return num_from_f32_bits(bits);
}

/* 1/a; saturates (fixed) or infinite (IEEE) for a == 0 */
static inline num_t num_recip(num_t a) { return num_div(NUM_ONE, a); }
static inline num_t num_min(num_t a, num_t b) { return num_lt(b, a) ? b : a; }
static inline num_t num_max(num_t a, num_t b) { return num_gt(b, a) ? b : a; }
static inline num_t num_clamp01(num_t a) { return num_min(num_max(a, NUM_ZERO), NUM_ONE); }
static inline num_t num_lerp(num_t a, num_t b, num_t t)
{
    return num_add(a, num_mul(num_sub(b, a), t));
}

/* a^n by repeated squaring, n >= 0 (0^0 = 1): the highlight's cos^n with no
 * libm pow().  Same operation order in every build.  The fixed build keeps
 * 30 fraction bits between the steps when |a| <= 1 (the cos^n case), so
 * the rounding of each squaring does not pile up over large n. */
#if defined(LINKS1_NUM_FIXED)
num_t num_pow_int_fixed_unit(num_t a, uint32_t n);
#endif
static inline num_t num_pow_int(num_t a, uint32_t n)
{
#if defined(LINKS1_NUM_FIXED)
    if (a <= NUM_ONE_RAW && a >= -NUM_ONE_RAW)
        return num_pow_int_fixed_unit(a, n);
#endif
    num_t r = NUM_ONE;
    while (n) {
        if (n & 1u)
            r = num_mul(r, a);
        n >>= 1;
        if (n)
            a = num_mul(a, a);
    }
    return r;
}

/* |(x, y, z)|: fixed uses one 64-bit sum of squares, so it does not overflow
 * before the length itself does; float and double are inline (every
 * normalize of the DM's preparation and the NCs' shading uses it). */
#if defined(LINKS1_NUM_FIXED)
num_t num_len3(num_t x, num_t y, num_t z);
#else
static inline num_t num_len3(num_t x, num_t y, num_t z)
{
    return num_sqrt(num_dot3(x, y, z, x, y, z));
}
#endif

#endif
