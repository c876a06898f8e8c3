/* fixed/isqrt.h: the integer square root, for the fixed-point num_t
 * (fixed/num.c) and for anyone else who needs one without floating point
 * (the RC's area schedules, proto/areas.c). */
#ifndef LINKS1_FIXED_ISQRT_H
#define LINKS1_FIXED_ISQRT_H

#include <stdint.h>

/* floor(sqrt(n)) for any 64-bit n, exact, no division and no floating
 * point.  One result bit per step, starting at n's top bit, so small
 * inputs take few steps. */
uint64_t isqrt_u64(uint64_t n);

#endif
