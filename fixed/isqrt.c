/* fixed/isqrt.c: the integer square root (see isqrt.h). */
#include "fixed/isqrt.h"

uint64_t isqrt_u64(uint64_t n)
{
    if (n == 0)
        return 0;
    uint64_t root = 0;
    /* start at the highest even bit position not above n's top bit: the
     * answer has half as many bits as n */
    uint64_t bit = (uint64_t)1 << ((63 - __builtin_clzll(n)) & ~1);
    while (bit) {
        if (n >= root + bit) {
            n -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return root;
}
