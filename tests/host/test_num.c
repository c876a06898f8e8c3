/* test_num.c: every num_t operation against double over tables of edge
 * cases.  Built three times (double, float, fixed); the tolerance is the
 * arithmetic's own rounding: half a step (2^-NUM_FRAC_BITS) for fixed
 * point, a relative 2^-24 for float.  Inputs beyond the fixed range are
 * skipped in the operation tables (they are markers, tested on their own). */
#include <stdint.h>
#include <string.h>

#include "fixed/num.h"
#include "tests/check.h"

#if defined(LINKS1_NUM_FIXED)
#define STEP (1.0 / NUM_ONE_RAW)
#define MAXV ((double)NUM_INT_MAX)
#endif

#if defined(LINKS1_NUM_FIXED)
#define MAXV_ANY MAXV
#else
#define MAXV_ANY 4000.0
#endif

/* Allowed error for a result of magnitude want. */
static double tol_for(double want)
{
#if defined(LINKS1_NUM_FIXED)
    (void)want;
    return 0.5 * STEP + 1e-12;
#elif defined(LINKS1_NUM_FLOAT)
    return fabs(want) * 6e-8 + 1e-37;
#else
    return fabs(want) * 1.2e-16 + 1e-300;
#endif
}

/* In fixed point a result beyond the range must come back as a marker;
 * otherwise it must be a valid value close to the exact one. */
static void check_result(num_t got, double want, const char *op, double a, double b)
{
    char msg[200];
#if defined(LINKS1_NUM_FIXED)
    if (fabs(want) >= MAXV + 0.99999) {
        if (!num_is_sat(got) || (want > 0) != (got > 0)) {
            snprintf(msg, sizeof msg, "%s(%.9g, %.9g): want saturation of sign %+d, got raw %d", op, a,
                     b, want > 0 ? 1 : -1, (int)got);
            check_fail(__FILE__, __LINE__, msg);
        }
        return;
    }
    if (num_is_sat(got) && fabs(want) < MAXV - 0.001) {
        snprintf(msg, sizeof msg, "%s(%.9g, %.9g): saturated, want %.9g", op, a, b, want);
        check_fail(__FILE__, __LINE__, msg);
        return;
    }
#endif
    double g = num_to_double(got);
    if (!(fabs(g - want) <= tol_for(want))) {
        snprintf(msg, sizeof msg, "%s(%.9g, %.9g) = %.12g, want %.12g", op, a, b, g, want);
        check_fail(__FILE__, __LINE__, msg);
    }
}

/* Edge values: zero, one step, halves (rounding carries), signs, powers of
 * two, values near the fixed range limit, tiny and huge. */
static const double values[] = {
    0.0, 1.0, -1.0, 0.5, -0.5, 1.5 / 65536, -1.5 / 65536, 1.0 / 65536, 3.0 / 65536,
    0.1, -0.1, 2.0, 3.0, 7.25, -7.25, 100.0, -181.0, 181.0, 255.0, 1000.0, -1000.0,
    1.0 / 3.0, 32767.0, -32767.0, 16384.0, 0.999984741, 12345.678, -0.0001,
    /* the default Q12.19: one step, a step and a half, the range edge */
    1.0 / 524288, -1.0 / 524288, 1.5 / 524288, 3.0 / 524288, 4095.0, -4095.0, 2047.999, 4000.0,
    63.99, -64.01,
};
#define N_VALUES (sizeof values / sizeof values[0])

static void test_add_sub(void)
{
    for (size_t i = 0; i < N_VALUES; i++)
        for (size_t j = 0; j < N_VALUES; j++) {
            num_t a = num_from_double(values[i]), b = num_from_double(values[j]);
            double da = num_to_double(a), db = num_to_double(b);
            if (num_is_sat(a) || num_is_sat(b))
                continue;
            check_result(num_add(a, b), da + db, "add", da, db);
            check_result(num_sub(a, b), da - db, "sub", da, db);
        }
}

static void test_mul(void)
{
    for (size_t i = 0; i < N_VALUES; i++)
        for (size_t j = 0; j < N_VALUES; j++) {
            num_t a = num_from_double(values[i]), b = num_from_double(values[j]);
            double da = num_to_double(a), db = num_to_double(b);
            if (num_is_sat(a) || num_is_sat(b))
                continue;
            check_result(num_mul(a, b), da * db, "mul", da, db);
        }
}

static void test_div(void)
{
    for (size_t i = 0; i < N_VALUES; i++)
        for (size_t j = 0; j < N_VALUES; j++) {
            num_t a = num_from_double(values[i]), b = num_from_double(values[j]);
            double da = num_to_double(a), db = num_to_double(b);
            if (num_is_sat(a) || num_is_sat(b))
                continue;
            if (db == 0) {
                CHECK(num_is_sat(num_div(a, b))); /* x/0: marker or inf/NaN */
                continue;
            }
            check_result(num_div(a, b), da / db, "div", da, db);
        }
}

static void test_sqrt_recip(void)
{
    for (size_t i = 0; i < N_VALUES; i++) {
        num_t a = num_from_double(values[i]);
        double da = num_to_double(a);
        if (num_is_sat(a))
            continue;
        if (da >= 0)
            check_result(num_sqrt(a), sqrt(da), "sqrt", da, 0);
        else
            CHECK_NEAR(num_to_double(num_sqrt(a)), 0.0, 0.0); /* documented: < 0 gives 0 */
        if (da != 0)
            check_result(num_recip(a), 1.0 / da, "recip", da, 0);
    }
}

static void test_dot3_len3(void)
{
    /* wide intermediates: each product would overflow fixed point alone */
    double big = 0.6 * MAXV_ANY;
    num_t a = num_from_double(big), b = num_from_double(-big), c = num_from_double(0.5);
    check_result(num_len3(a, b, c), sqrt(2 * big * big + 0.25), "len3", big, -big);
    check_result(num_dot3(c, c, c, c, c, c), 0.75, "dot3", 0.5, 0.5);
    check_result(num_dot3(a, NUM_ONE, NUM_ZERO, num_from_double(0.001), b, NUM_ONE),
                 num_to_double(a) * num_to_double(num_from_double(0.001)) - big, "dot3", big, 0.001);
    for (size_t i = 0; i < N_VALUES; i++)
        for (size_t j = 0; j < N_VALUES; j++) {
            num_t x = num_from_double(values[i]), y = num_from_double(values[j]);
            double dx = num_to_double(x), dy = num_to_double(y);
            if (num_is_sat(x) || num_is_sat(y))
                continue;
            /* IEEE: three products, two sums and a root each round once */
            double want = sqrt(2 * dx * dx + dy * dy);
            num_t got = num_len3(x, y, x);
#if defined(LINKS1_NUM_FIXED)
            check_result(got, want, "len3", dx, dy);
#else
            CHECK_NEAR(num_to_double(got), want, tol_for(want) * 4);
#endif
        }
}

static void test_from_f32(void)
{
    static const float fs[] = {0.0f, -0.0f, 1.0f, -2.5f, 0.1f, 1e-10f, 3.0e-5f, 1000.25f, -4095.0f,
                               7.62939453125e-06f, 9.5367431640625e-07f /* 2^-17, 2^-20 */};
    for (size_t i = 0; i < sizeof fs / sizeof fs[0]; i++) {
        uint32_t bits;
        memcpy(&bits, &fs[i], sizeof bits);
        num_t v = num_from_f32_bits(bits);
        check_result(v, (double)fs[i], "from_f32", fs[i], 0);
        CHECK(num_from_float(fs[i]) == v);
    }
    CHECK(num_is_sat(num_from_f32_bits(0x7f800000u))); /* +inf */
    CHECK(num_is_sat(num_from_f32_bits(0xff800000u))); /* -inf */
    CHECK(num_is_sat(num_from_f32_bits(0x7fc00000u))); /* NaN */
    CHECK_NEAR(num_to_double(num_from_f32_bits(0x00000001u)), 0.0, 1e-40); /* subnormal */
#if defined(LINKS1_NUM_FIXED)
    CHECK(num_is_sat(num_from_float(1e10f)) && num_from_float(1e10f) > 0);
    CHECK(num_is_sat(num_from_float(-40000.0f)) && num_from_float(-40000.0f) < 0);
    /* half a step rounds away from zero, a quarter to zero */
    CHECK_EQ_INT(num_from_float(ldexpf(1.0f, -NUM_FRAC_BITS - 1)), 1);
    CHECK_EQ_INT(num_from_float(ldexpf(-1.0f, -NUM_FRAC_BITS - 1)), -1);
    CHECK_EQ_INT(num_from_float(ldexpf(1.0f, -NUM_FRAC_BITS - 2)), 0);
#endif
}

static void test_to_u8(void)
{
    CHECK_EQ_INT(num_to_u8(NUM_ZERO), 0);
    CHECK_EQ_INT(num_to_u8(NUM_ONE), 255);
    CHECK_EQ_INT(num_to_u8(NUM_HALF), 128); /* 127.5 rounds up */
    CHECK_EQ_INT(num_to_u8(num_from_double(-3)), 0);
    CHECK_EQ_INT(num_to_u8(num_from_double(7)), 255);
    CHECK_EQ_INT(num_to_u8(num_from_double(100.0 / 255)), 100);
    CHECK_EQ_INT(num_to_u8(num_div(NUM_ONE, NUM_ZERO)), 255); /* +marker/inf clamps */
    for (int i = 0; i <= 255; i++)
        CHECK_EQ_INT(num_to_u8(num_div(num_from_int(i), num_from_int(255))), i);
}

static void test_pow_int(void)
{
    static const double bases[] = {0.0, 1.0, 0.5, 0.9, 0.99, -0.5, 0.999};
    static const uint32_t exps[] = {0, 1, 2, 5, 10, 50, 100};
    for (size_t i = 0; i < sizeof bases / sizeof bases[0]; i++)
        for (size_t j = 0; j < sizeof exps / sizeof exps[0]; j++) {
            num_t b = num_from_double(bases[i]);
            double want = pow(num_to_double(b), exps[j]);
            /* fixed keeps 30 bits inside: one final rounding plus a little;
             * IEEE: a rounding of an early square is raised to the power
             * n/2, so the relative error grows like n ulps */
#if defined(LINKS1_NUM_FIXED)
            double tol = tol_for(want) * 2;
#else
            double tol = tol_for(want) * (2.0 * exps[j] + 16);
#endif
            CHECK_NEAR(num_to_double(num_pow_int(b, exps[j])), want, tol);
        }
}

static void test_floor_compare(void)
{
    CHECK_EQ_INT(num_floor_int(num_from_double(2.75)), 2);
    CHECK_EQ_INT(num_floor_int(num_from_double(-2.25)), -3);
    CHECK_EQ_INT(num_floor_int(num_from_double(-2.0)), -2);
    CHECK_EQ_INT(num_floor_int(NUM_ZERO), 0);
    /* of a >= 0, as num_floor_int: below, at and above an integer */
    int32_t off = 0;
    for (int32_t k = 0; k < 40; k++)
        for (int e = -1; e <= 1; e++) {
            num_t a = num_add(num_from_int(k), num_mul_int(num_ulp(num_from_int(k)), e));
            off += num_ge(a, NUM_ZERO) && num_floor_nonneg_int(a) != num_floor_int(a);
        }
    CHECK_EQ_INT(off, 0);
    CHECK(num_lt(num_from_double(-1), NUM_ZERO) && num_gt(NUM_ONE, NUM_HALF));
    CHECK(num_le(NUM_ONE, NUM_ONE) && num_ge(NUM_ONE, NUM_ONE) && num_eq(NUM_HALF, NUM_C(0.5)));
    CHECK_NEAR(num_to_double(num_min(NUM_ONE, NUM_HALF)), 0.5, 0);
    CHECK_NEAR(num_to_double(num_max(NUM_ONE, NUM_HALF)), 1.0, 0);
    CHECK_NEAR(num_to_double(num_clamp01(num_from_int(-4))), 0.0, 0);
    CHECK_NEAR(num_to_double(num_mul_int(NUM_C(0.25), -6)), -1.5, 0);
    CHECK_NEAR(num_to_double(num_from_ratio(3, 4)), 0.75, 0);
    CHECK_NEAR(num_to_double(num_from_ratio(1, 3)), 1.0 / 3, tol_for(1.0 / 3));
}

static void test_saturation_markers(void)
{
#if defined(LINKS1_NUM_FIXED)
    num_t big = num_from_int(NUM_INT_MAX - 10);
    num_t sat = num_add(big, big);
    CHECK(num_is_sat(sat) && sat == NUM_RAW_SAT);
    CHECK(num_sub(num_neg(big), big) == -NUM_RAW_SAT);
    /* the largest valid value is not a marker, and no sum produces a marker
     * by landing exactly on it */
    CHECK(!num_is_sat(NUM_RAW_MAX) && !num_is_sat(-NUM_RAW_MAX));
    CHECK(num_is_sat(num_add(NUM_RAW_MAX, 1)));
    CHECK(num_add(NUM_RAW_MAX - 1, 1) == NUM_RAW_MAX);
    /* sticky: a marker never turns back into a value */
    CHECK(num_is_sat(num_mul(sat, NUM_ZERO)));
    CHECK(num_is_sat(num_sub(sat, sat)));
    CHECK(num_is_sat(num_div(NUM_ONE, sat)));
    CHECK(num_is_sat(num_sqrt(sat)));
    CHECK(num_is_sat(num_dot3(sat, 0, 0, 0, 0, 0)));
    CHECK(num_mul(sat, num_from_int(-1)) == -NUM_RAW_SAT);
    /* rounding of products: half a step goes away from zero */
    CHECK_EQ_INT(num_mul(1, NUM_HALF), 1);
    CHECK_EQ_INT(num_mul(-1, NUM_HALF), -1);
    CHECK_EQ_INT(num_mul(1, NUM_C(0.25)), 0); /* underflow rounds to 0 */
    CHECK_EQ_INT(num_div(1, num_from_int(2)), 1);
    CHECK(num_div(num_from_int(-3), NUM_ZERO) == -NUM_RAW_SAT);
    CHECK(num_is_sat(num_div(NUM_ONE, 1))); /* 2^NUM_FRAC_BITS is out of range */
    CHECK_EQ_INT(num_from_int(NUM_INT_MAX), (int64_t)NUM_INT_MAX * NUM_ONE_RAW);
    CHECK(num_is_sat(num_from_int(NUM_INT_MAX + 1)));
    CHECK_EQ_INT(num_from_ratio(1, 3), (NUM_ONE_RAW + 1) / 3);
    CHECK_EQ_INT(num_from_ratio(-7, 2), -(7 * NUM_ONE_RAW / 2));
    CHECK(num_from_ratio(5, 0) == NUM_RAW_SAT);
#else
    num_t inf = num_div(NUM_ONE, NUM_ZERO);
    CHECK(num_is_sat(inf) && num_is_sat(num_sub(inf, inf)) && !num_is_sat(NUM_ONE));
#endif
}

int main(void)
{
    printf("# num_t = %s\n", NUM_NAME);
    RUN(test_add_sub);
    RUN(test_mul);
    RUN(test_div);
    RUN(test_sqrt_recip);
    RUN(test_dot3_len3);
    RUN(test_from_f32);
    RUN(test_to_u8);
    RUN(test_pow_int);
    RUN(test_floor_compare);
    RUN(test_saturation_markers);
    return check_exit();
}
