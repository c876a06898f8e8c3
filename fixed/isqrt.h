/* fixed/isqrt.h: the integer square root, for the fixed-point num_t
 * (fixed/num.c) and for anyone else who needs one without floating point
 * (the RC's area schedules, proto/areas.c). */
#ifndef LINKS1_FIXED_ISQRT_H
#define LINKS1_FIXED_ISQRT_H

#include <stdint.h>

/* floor(sqrt(n)) for any 64-bit n, exact, with two 32-bit divisions and
 * no floating point: a table seed, a Newton step and a Karatsuba step,
 * each corrected (fixed/isqrt.c). */
uint64_t isqrt_u64(uint64_t n);

#endif
