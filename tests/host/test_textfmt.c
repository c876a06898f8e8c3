/* test_textfmt.c: the shared formatter (proto/textfmt.c) against the
 * host's snprintf for the conversions it supports. */
#include <stdio.h>
#include <string.h>

#include "proto/textfmt.h"
#include "tests/check.h"

#define SAME(...)                                                             \
    do {                                                                      \
        char a_[128], b_[128];                                                \
        int na_ = fmt_snprintf(a_, sizeof a_, __VA_ARGS__);                  \
        int nb_ = snprintf(b_, sizeof b_, __VA_ARGS__);                       \
        if (strcmp(a_, b_) != 0 || na_ != nb_) {                              \
            char m_[400];                                                     \
            snprintf(m_, sizeof m_, "fmt '%s' (%d) != libc '%s' (%d)", a_,   \
                     na_, b_, nb_);                                           \
            check_fail(__FILE__, __LINE__, m_);                               \
        }                                                                     \
    } while (0)

static void test_integers(void)
{
    SAME("%d %d %d", 0, -1, 2147483647);
    SAME("%d", (int)-2147483647 - 1);
    SAME("%u %x %X", 4294967295u, 0xdeadbeefu, 0xabcu);
    SAME("%08x|%-6d|%6d|%05d", 0x1234u, 42, -42, -42);
    SAME("%lld %llu %llx", -9223372036854775807ll - 1, 18446744073709551615ull,
         0x123456789abcdefull);
    SAME("%ld %lu %zu", -5l, 7ul, (size_t)123456);
}

static void test_strings_and_chars(void)
{
    SAME("[%s] [%8s] [%-8s] [%c] %%", "abc", "right", "left", 'z');
    SAME("%s", "");
}

static void test_precision_and_star(void)
{
    SAME("[%.3s] [%.0s] [%.10s] [%8.2s] [%-6.1s]", "abcdef", "xyz", "short", "abc", "q");
    SAME("[%.*s] [%*s] [%-*s]", 4, "0123456789", 6, "ab", 5, "cd");
    SAME("[%.5d] [%.3u] [%8.4x] [%-8.3d] [%.0d]", 42, 7u, 0xabu, -5, 0);
    SAME("%.*s|", -1, "negative precision is none");
}

/* %.*s must read no byte past the precision: the text may be a payload
 * without a NUL (ASan flags a read past the array). */
static void test_precision_reads_no_further(void)
{
    char payload[4] = {'w', 'h', 'y', '!'};
    char buf[32];
    int n = fmt_snprintf(buf, sizeof buf, "NC %u: %.*s", 3u, (int)sizeof payload, payload);
    CHECK_EQ_INT(n, 10);
    CHECK(strcmp(buf, "NC 3: why!") == 0);
}

static void test_truncation(void)
{
    char buf[8];
    int n = fmt_snprintf(buf, sizeof buf, "%s", "0123456789");
    CHECK_EQ_INT(n, 10);
    CHECK(strcmp(buf, "0123456") == 0);
    n = fmt_snprintf(buf, 1, "%d", 12345);
    CHECK_EQ_INT(n, 5);
    CHECK(buf[0] == '\0');
}

int main(void)
{
    RUN(test_integers);
    RUN(test_strings_and_chars);
    RUN(test_precision_and_star);
    RUN(test_precision_reads_no_further);
    RUN(test_truncation);
    return check_exit();
}
