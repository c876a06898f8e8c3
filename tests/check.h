/* check.h: the tiny harness every host unit test uses.
 *
 * A test is a function; RUN(fn) runs it and prints one line, "PASS fn" or
 * "FAIL fn: file:line: what", which tests/run.sh counts.  CHECK* never abort a
 * test early, so one run shows every broken assertion.  main() ends with
 * "return check_exit();", non-zero when anything failed.
 */
#ifndef LINKS1_TESTS_CHECK_H
#define LINKS1_TESTS_CHECK_H

#include <math.h>
#include <stdio.h>

static int check_failures_in_test;  /* failed CHECKs in the running test */
static int check_failed_tests;      /* tests with at least one failure */
static const char *check_test_name; /* name of the running test */

static inline void check_fail(const char *file, int line, const char *what)
{
    /* The first failure names the test; later ones add detail lines. */
    printf("%s %s: %s:%d: %s\n", check_failures_in_test ? "  also" : "FAIL",
           check_test_name, file, line, what);
    check_failures_in_test++;
}

#define CHECK(cond)                                                          \
    do {                                                                     \
        if (!(cond))                                                         \
            check_fail(__FILE__, __LINE__, #cond);                           \
    } while (0)

/* |got - want| <= tol, with both values printed on failure. */
#define CHECK_NEAR(got, want, tol)                                           \
    do {                                                                     \
        double g_ = (double)(got), w_ = (double)(want);                      \
        if (!(fabs(g_ - w_) <= (double)(tol))) {                             \
            char m_[256];                                                    \
            snprintf(m_, sizeof m_, "%s = %.9g, want %.9g (tol %g)", #got,   \
                     g_, w_, (double)(tol));                                 \
            check_fail(__FILE__, __LINE__, m_);                              \
        }                                                                    \
    } while (0)

#define CHECK_EQ_INT(got, want)                                              \
    do {                                                                     \
        long long g_ = (long long)(got), w_ = (long long)(want);             \
        if (g_ != w_) {                                                      \
            char m_[256];                                                    \
            snprintf(m_, sizeof m_, "%s = %lld, want %lld", #got, g_, w_);   \
            check_fail(__FILE__, __LINE__, m_);                              \
        }                                                                    \
    } while (0)

#define RUN(fn)                                                              \
    do {                                                                     \
        check_test_name = #fn;                                               \
        check_failures_in_test = 0;                                          \
        fn();                                                                \
        if (check_failures_in_test)                                          \
            check_failed_tests++;                                            \
        else                                                                 \
            printf("PASS %s\n", #fn);                                        \
        fflush(stdout);                                                      \
    } while (0)

static inline int check_exit(void) { return check_failed_tests ? 1 : 0; }

#endif
