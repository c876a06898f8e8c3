/* apu.h: Table 1 of the paper on the board's CPU (tests/bench/bench_apu.sh,
 * docs/results/paper-figures.md): the four operations of its Table 1 on
 * 3-vectors and 3x3 matrices, done by one core locally (soft float, fixed
 * point, VFP) or handed to a neighbour core, the "APU", through shared
 * memory.  A bare-metal semihosting program of its own (links1 semihost
 * --cores 2); it uses no part of the firmware. */
#ifndef LINKS1_TESTS_BENCH_APU_H
#define LINKS1_TESTS_BENCH_APU_H

#include <stdint.h>

enum apu_op { APU_VADD = 0, APU_VDOT = 1, APU_MADD = 2, APU_MMUL = 3, APU_OPS = 4, APU_STOP = 9 };

/* Words of each operand and of the result. */
static inline int apu_in_words(int op) { return op <= APU_VDOT ? 3 : 9; }
static inline int apu_out_words(int op) { return op == APU_VADD ? 3 : op == APU_VDOT ? 1 : 9; }

/* Fixed point: the firmware's fixed build's num_add and num_mul
 * (fixed/num.h), raw words in and out. */
void apu_fixed(int op, const int32_t *a, const int32_t *b, int32_t *r);
/* The raw word of 1.0 in that format (NUM_ONE_RAW). */
int32_t apu_fixed_one(void);

#endif
