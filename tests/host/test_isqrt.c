/* test_isqrt.c: fixed/isqrt.c, the one integer square root, against its
 * definition r*r <= n < (r+1)*(r+1) over small numbers, the squares of every
 * bit width and their neighbours, and the largest input. */
#include <stdint.h>
#include <stdio.h>

#include "fixed/isqrt.h"
#include "tests/check.h"

/* r is floor(sqrt(n)): r*r <= n and (r+1)^2 > n, computed without overflow. */
static int is_floor_root(uint64_t n, uint64_t r)
{
    if (r > 0xFFFFFFFFull)
        return 0;
    if (r * r > n)
        return 0;
    uint64_t next = r + 1;
    return next > 0xFFFFFFFFull || next * next > n;
}

static void check_one(uint64_t n)
{
    uint64_t r = isqrt_u64(n);
    if (!is_floor_root(n, r)) {
        char m[120];
        snprintf(m, sizeof m, "isqrt_u64(%llu) = %llu", (unsigned long long)n,
                 (unsigned long long)r);
        check_fail(__FILE__, __LINE__, m);
    }
}

static void test_small(void)
{
    for (uint64_t n = 0; n <= 70000; n++)
        check_one(n);
    CHECK_EQ_INT(isqrt_u64(0), 0);
    CHECK_EQ_INT(isqrt_u64(1), 1);
    CHECK_EQ_INT(isqrt_u64(3), 1);
    CHECK_EQ_INT(isqrt_u64(4), 2);
}

static void test_squares_and_neighbours(void)
{
    for (int b = 0; b < 32; b++) {
        for (uint64_t r = (1ull << b) - 2; r <= (1ull << b) + 2; r++) {
            if (r > 0xFFFFFFFFull)
                continue;
            uint64_t sq = r * r;
            check_one(sq);
            check_one(sq + 1);
            if (sq > 0)
                check_one(sq - 1);
        }
    }
    CHECK_EQ_INT(isqrt_u64(0xFFFFFFFE00000001ull), 0xFFFFFFFFull); /* (2^32-1)^2 */
}

static void test_largest(void)
{
    CHECK_EQ_INT(isqrt_u64(UINT64_MAX), 0xFFFFFFFFull);
    CHECK_EQ_INT(isqrt_u64(1ull << 63), 3037000499ull);
    for (int b = 0; b < 64; b++)
        check_one(1ull << b);
}

int main(void)
{
    RUN(test_small);
    RUN(test_squares_and_neighbours);
    RUN(test_largest);
    return check_exit();
}
