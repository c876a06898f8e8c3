/* test_num_exact.c: the fixed point's sum, difference, product, division,
 * square roots and dot product (fixed/num.h, fixed/num.c, fixed/isqrt.c)
 * against plain exact references, bit for bit: 64-bit sums and products
 * with the markers looked at first, 64-bit division, a square root one bit
 * a step, and the products each divided by 4 in 64 bits.  These are the definitions the fast forms
 * must keep (every fixed image depends on them), over edge inputs (zero,
 * one step, powers of two and their neighbours, the largest valid values,
 * the markers, INT32_MIN) and millions of random ones of every bit length.
 * Built once per fixed format (Q12.19 and the links1-ref-fixedN ones). */
#include <stdint.h>
#include <stdio.h>

#include "fixed/isqrt.h"
#include "fixed/num.h"
#include "tests/check.h"

#if !defined(LINKS1_NUM_FIXED)
#error "test_num_exact is for the fixed builds"
#endif

#define RANDOM_PAIRS 2000000

/* ----------------------------------------------------------- references */

static num_t ref_add(num_t a, num_t b)
{
    if (num_is_sat(a) || num_is_sat(b))
        return num_is_sat(a) ? a : b;
    return num__from_wide((int64_t)a + b);
}

static num_t ref_sub(num_t a, num_t b)
{
    if (num_is_sat(a) || num_is_sat(b))
        return num_is_sat(a) ? a : -b;
    return num__from_wide((int64_t)a - b);
}

static num_t ref_mul(num_t a, num_t b)
{
    if (num_is_sat(a) || num_is_sat(b))
        return num__sticky(a, b);
    return num__from_wide(num__round_shift((int64_t)a * b, NUM_FRAC_BITS));
}

/* num/den for integers: the rounded quotient in 64 bits (the definition
 * num_from_ratio's 32-bit paths must give; num_div's for reals but
 * markers) */
static num_t ref_ratio(int32_t num, int32_t den)
{
    if (den == 0)
        return num < 0 ? -NUM_RAW_SAT : NUM_RAW_SAT;
    int negative = (num < 0) != (den < 0);
    uint64_t un = (uint64_t)(num < 0 ? -(int64_t)num : num) << NUM_FRAC_BITS;
    uint64_t ud = (uint64_t)(den < 0 ? -(int64_t)den : den);
    uint64_t q = (un + ud / 2) / ud;
    if (q > (uint64_t)NUM_RAW_MAX)
        return negative ? -NUM_RAW_SAT : NUM_RAW_SAT;
    return negative ? -(num_t)q : (num_t)q;
}

static num_t ref_div(num_t a, num_t b)
{
    if (num_is_sat(a) || num_is_sat(b))
        return num__sticky(a, b);
    return ref_ratio(a, b); /* b == 0: the marker of a's sign, num__sticky's */
}

/* floor(sqrt(n)), one result bit a step */
static uint64_t ref_isqrt(uint64_t n)
{
    uint64_t root = 0;
    for (uint64_t bit = (uint64_t)1 << 62; bit; bit >>= 2) {
        if (n >= root + bit) {
            n -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
    }
    return root;
}

static num_t ref_sqrt_wide(uint64_t n)
{
    uint64_t r = ref_isqrt(n);
    if (n - r * r > r)
        r++;
    return r > (uint64_t)NUM_RAW_MAX ? NUM_RAW_SAT : (num_t)r;
}

static num_t ref_sqrt(num_t a)
{
    if (a == NUM_RAW_SAT || a == -NUM_RAW_SAT)
        return NUM_RAW_SAT;
    if (a <= 0)
        return 0;
    return ref_sqrt_wide((uint64_t)a << NUM_FRAC_BITS);
}

static num_t ref_len3(num_t x, num_t y, num_t z)
{
    if (num_is_sat(x) || num_is_sat(y) || num_is_sat(z))
        return NUM_RAW_SAT;
    return ref_sqrt_wide((uint64_t)((int64_t)x * x) + (uint64_t)((int64_t)y * y) +
                         (uint64_t)((int64_t)z * z));
}

static num_t ref_dot3(num_t ax, num_t ay, num_t az, num_t bx, num_t by, num_t bz)
{
    if (num_is_sat(ax) || num_is_sat(ay) || num_is_sat(az) || num_is_sat(bx) ||
        num_is_sat(by) || num_is_sat(bz))
        return NUM_RAW_SAT;
    int64_t s = ((int64_t)ax * bx) / 4 + ((int64_t)ay * by) / 4 + ((int64_t)az * bz) / 4;
    return num__from_wide(num__round_shift(s, NUM_FRAC_BITS - 2));
}

/* -------------------------------------------------------------- inputs */

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;

static uint64_t rng_next(void) /* xorshift64* */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 0x2545F4914F6CDD1Dull;
}

/* A random raw value of a random bit length (0..31), either sign. */
static num_t rng_num(void)
{
    uint64_t r = rng_next();
    int bits = (int)(r & 31u);
    uint32_t v = (uint32_t)(r >> 32) & (bits ? 0xFFFFFFFFu >> (32 - bits) : 0u);
    if (v > (uint32_t)NUM_RAW_SAT)
        v = (uint32_t)NUM_RAW_SAT;
    return (r & 32u) ? -(num_t)v : (num_t)v;
}

/* Zero, steps, powers of two and their neighbours, one, the largest valid
 * values, the markers and INT32_MIN (never produced, but defined). */
static num_t edges[200];
static int n_edges;

static void edges_add(int64_t v)
{
    if (v >= -(int64_t)NUM_RAW_SAT && v <= NUM_RAW_SAT && n_edges < (int)(sizeof edges / sizeof edges[0]))
        edges[n_edges++] = (num_t)v;
}

static void edges_make(void)
{
    n_edges = 0;
    for (int b = 0; b < 31; b += 2)
        for (int d = -1; d <= 1; d++) {
            edges_add(((int64_t)1 << b) + d);
            edges_add(-(((int64_t)1 << b) + d));
        }
    int64_t special[] = {NUM_ONE_RAW, NUM_ONE_RAW - 1, NUM_ONE_RAW + 1, NUM_RAW_MAX,
                         NUM_RAW_MAX - 1, (int64_t)1 << 30, ((int64_t)1 << 30) - 1,
                         3 * NUM_ONE_RAW / 2,
                         /* where num_mul's and num_dot3's fast paths end */
                         (int64_t)1 << NUM__MUL_FAST_BITS, ((int64_t)1 << NUM__MUL_FAST_BITS) - 1,
                         ((int64_t)1 << NUM__MUL_FAST_BITS) + 1, (int64_t)1 << NUM__DOT3_FAST_BITS,
                         ((int64_t)1 << NUM__DOT3_FAST_BITS) - 1,
                         ((int64_t)1 << NUM__DOT3_FAST_BITS) + 1};
    for (size_t i = 0; i < sizeof special / sizeof special[0]; i++) {
        edges_add(special[i]);
        edges_add(-special[i]);
    }
    edges[n_edges++] = NUM_RAW_SAT;
    edges[n_edges++] = -NUM_RAW_SAT;
    edges[n_edges++] = INT32_MIN;
}

/* ---------------------------------------------------------------- tests */

#define SAME(got, want, what, a, b)                                                 \
    do {                                                                            \
        num_t g_ = (got), w_ = (want);                                              \
        if (g_ != w_ && fails_shown++ < 5) {                                        \
            char m_[160];                                                           \
            snprintf(m_, sizeof m_, "%s(%ld, %ld) = %ld, want %ld", what, (long)(a), \
                     (long)(b), (long)g_, (long)w_);                                \
            check_fail(__FILE__, __LINE__, m_);                                     \
        }                                                                           \
    } while (0)

static int fails_shown;

/* a + b, a - b and a * b for a pair (INT32_MIN is not negated: the
 * references' -b of it is undefined) */
static void same_add_sub_mul(num_t a, num_t b)
{
    SAME(num_add(a, b), ref_add(a, b), "num_add", a, b);
    if (b != INT32_MIN)
        SAME(num_sub(a, b), ref_sub(a, b), "num_sub", a, b);
    SAME(num_mul(a, b), ref_mul(a, b), "num_mul", a, b);
}

static void test_add_sub_mul(void)
{
    fails_shown = 0;
    for (int i = 0; i < n_edges; i++)
        for (int j = 0; j < n_edges; j++)
            same_add_sub_mul(edges[i], edges[j]);
    for (int i = 0; i < RANDOM_PAIRS; i++)
        same_add_sub_mul(rng_num(), rng_num());
    /* every product across rounding boundaries, both signs */
    for (num_t k = -(1 << 20) - 40; k <= (1 << 20) + 40; k++) {
        same_add_sub_mul(k, 1);
        same_add_sub_mul(k, -3);
        same_add_sub_mul(k, 1 << 11);
    }
}

static void test_div_edges(void)
{
    fails_shown = 0;
    for (int i = 0; i < n_edges; i++)
        for (int j = 0; j < n_edges; j++)
            SAME(num_div(edges[i], edges[j]), ref_div(edges[i], edges[j]), "num_div", edges[i],
                 edges[j]);
}

static void test_div_random(void)
{
    fails_shown = 0;
    for (int i = 0; i < RANDOM_PAIRS; i++) {
        num_t a = rng_num(), b = rng_num();
        SAME(num_div(a, b), ref_div(a, b), "num_div", a, b);
    }
}

/* num_from_ratio against its definition: the edges' raw values as
 * integers, every small numerator over every small denominator (a map's
 * bytes over 255, a normal map's signed bytes), and random pairs */
static void test_ratio(void)
{
    fails_shown = 0;
    for (int i = 0; i < n_edges; i++)
        for (int j = 0; j < n_edges; j++)
            SAME(num_from_ratio(edges[i], edges[j]), ref_ratio(edges[i], edges[j]),
                 "num_from_ratio", edges[i], edges[j]);
    for (int32_t n = -600; n <= 5000; n++)
        for (int32_t d = -40; d <= 600; d++)
            SAME(num_from_ratio(n, d), ref_ratio(n, d), "num_from_ratio", n, d);
    for (int i = 0; i < RANDOM_PAIRS; i++) {
        num_t a = rng_num(), b = rng_num();
        SAME(num_from_ratio(a, b), ref_ratio(a, b), "num_from_ratio", a, b);
        SAME(num_from_ratio(a >> 18, b >> 20), ref_ratio(a >> 18, b >> 20), "num_from_ratio",
             a >> 18, b >> 20);
    }
}

static void test_sqrt_all_edges(void)
{
    fails_shown = 0;
    for (int i = 0; i < n_edges; i++)
        SAME(num_sqrt(edges[i]), ref_sqrt(edges[i]), "num_sqrt", edges[i], 0);
    for (int i = 0; i < RANDOM_PAIRS; i++) {
        num_t a = rng_num();
        SAME(num_sqrt(a), ref_sqrt(a), "num_sqrt", a, 0);
    }
}

static void test_isqrt_random(void)
{
    fails_shown = 0;
    for (int i = 0; i < RANDOM_PAIRS; i++) {
        uint64_t r = rng_next();
        uint64_t n = r >> (rng_next() & 63u);
        SAME((num_t)(isqrt_u64(n) - ref_isqrt(n)), 0, "isqrt_u64 - ref", (long)(n >> 32),
             (long)(n & 0xFFFFFFFFu));
        /* the squares and their neighbours, where a root changes */
        uint64_t s = (r >> 32) * (r >> 32);
        for (uint64_t k = s - 1; k != s + 2; k++)
            SAME((num_t)(isqrt_u64(k) - ref_isqrt(k)), 0, "isqrt_u64 - ref", (long)(k >> 32),
                 (long)(k & 0xFFFFFFFFu));
    }
}

static void test_len3(void)
{
    fails_shown = 0;
    for (int i = 0; i < n_edges; i++)
        for (int j = 0; j < n_edges; j++)
            SAME(num_len3(edges[i], edges[j], edges[(i + j) % n_edges]),
                 ref_len3(edges[i], edges[j], edges[(i + j) % n_edges]), "num_len3", edges[i],
                 edges[j]);
    for (int i = 0; i < RANDOM_PAIRS; i++) {
        num_t x = rng_num(), y = rng_num(), z = rng_num();
        SAME(num_len3(x, y, z), ref_len3(x, y, z), "num_len3", x, y);
    }
    /* the roots that round at a half: k^4 + k^2 = r^2 + r for r = k^2 (up),
     * then one more (up) and one less (down) */
    for (int32_t k = 1; k < 46341; k += 3)
        for (int32_t z = -1; z <= 1; z++) {
            num_t x = k * k, y = k;
            if (z < 0)
                y = k - 1;
            SAME(num_len3(x, y, z), ref_len3(x, y, z), "num_len3", x, y);
        }
}

/* -v, INT32_MIN kept as it is (its negation is undefined) */
static num_t flip(num_t v) { return v == INT32_MIN ? v : -v; }

static void test_dot3_edges(void)
{
    fails_shown = 0;
    for (int i = 0; i < n_edges; i++)
        for (int j = 0; j < n_edges; j++) {
            num_t a = edges[i], b = edges[j], c = edges[(i * 7 + j) % n_edges];
            SAME(num_dot3(a, b, c, b, c, a), ref_dot3(a, b, c, b, c, a), "num_dot3", a, b);
            SAME(num_dot3(a, flip(b), c, a, b, flip(c)), ref_dot3(a, flip(b), c, a, b, flip(c)),
                 "num_dot3", a, b);
        }
}

static void test_dot3_random(void)
{
    fails_shown = 0;
    for (int i = 0; i < RANDOM_PAIRS; i++) {
        num_t v[6];
        for (int k = 0; k < 6; k++)
            v[k] = rng_num();
        SAME(num_dot3(v[0], v[1], v[2], v[3], v[4], v[5]),
             ref_dot3(v[0], v[1], v[2], v[3], v[4], v[5]), "num_dot3", v[0], v[3]);
    }
}

/* Every sum across a few rounding boundaries, with products whose
 * remainders by 4 are all 3 (or all -3, or mixed): where the four
 * truncations decide the rounding. */
static void test_dot3_dense(void)
{
    static const num_t k_mul[] = {3, -3, 1, 5, -7, 4};
    static const num_t rest[][4] = {{3, 1, 7, 1}, {-3, 1, -7, 1}, {3, -1, 7, 1}, {0, 0, 0, 0},
                                    {11, 1, 1, 3}, {-5, 3, 2, 9}};
    fails_shown = 0;
    for (size_t m = 0; m < sizeof k_mul / sizeof k_mul[0]; m++)
        for (size_t r = 0; r < sizeof rest / sizeof rest[0]; r++)
            for (num_t k = -(1 << 19) - 40; k <= (1 << 19) + 40; k++) {
                const num_t *o = rest[r];
                SAME(num_dot3(k, o[0], o[2], k_mul[m], o[1], o[3]),
                     ref_dot3(k, o[0], o[2], k_mul[m], o[1], o[3]), "num_dot3", k, k_mul[m]);
            }
}

int main(void)
{
    edges_make();
    RUN(test_add_sub_mul);
    RUN(test_div_edges);
    RUN(test_div_random);
    RUN(test_ratio);
    RUN(test_sqrt_all_edges);
    RUN(test_isqrt_random);
    RUN(test_len3);
    RUN(test_dot3_edges);
    RUN(test_dot3_random);
    RUN(test_dot3_dense);
    return check_exit();
}
