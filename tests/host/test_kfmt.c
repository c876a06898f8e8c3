/* test_kfmt.c: the firmware's log formatter (kernel/kfmt.c) against the
 * host's snprintf for the conversions it supports. */
#include <stdio.h>
#include <string.h>

#include "kernel/kfmt.h"
#include "tests/check.h"

#define SAME(...)                                                             \
    do {                                                                      \
        char a_[128], b_[128];                                                \
        int na_ = kfmt_snprintf(a_, sizeof a_, __VA_ARGS__);                  \
        int nb_ = snprintf(b_, sizeof b_, __VA_ARGS__);                       \
        if (strcmp(a_, b_) != 0 || na_ != nb_) {                              \
            char m_[400];                                                     \
            snprintf(m_, sizeof m_, "kfmt '%s' (%d) != libc '%s' (%d)", a_,   \
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

static void test_truncation(void)
{
    char buf[8];
    int n = kfmt_snprintf(buf, sizeof buf, "%s", "0123456789");
    CHECK_EQ_INT(n, 10);
    CHECK(strcmp(buf, "0123456") == 0);
    n = kfmt_snprintf(buf, 1, "%d", 12345);
    CHECK_EQ_INT(n, 5);
    CHECK(buf[0] == '\0');
}

int main(void)
{
    RUN(test_integers);
    RUN(test_strings_and_chars);
    RUN(test_truncation);
    return check_exit();
}
