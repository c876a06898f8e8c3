/* render/words.c: large blocks copied and zeroed eight words a step (see
 * words.h). */
#include "render/words.h"

#include <stdint.h>

/* One step in C: eight words through registers (the host build's loop). */
typedef struct {
    uint32_t w[WORDS_STEP_BYTES / 4];
} words_step_t;

_Static_assert(WORDS_STEP_BYTES == 32, "the board's loops move eight registers a step");

/* One step on the board: one load-multiple and one store-multiple of
 * eight registers (r7 left alone: Thumb code may keep its frame pointer
 * there). */
#define WORDS_STEP_ASM                                          \
    "ldmia %[s]!, {r3, r4, r5, r6, r8, r9, r10, r12}\n\t"       \
    "stmia %[d]!, {r3, r4, r5, r6, r8, r9, r10, r12}\n\t"
#define WORDS_STEP_CLOBBERS "r3", "r4", "r5", "r6", "r8", "r9", "r10", "r12", "cc", "memory"

/* steps whole steps from s to d, both word-aligned, steps > 0.  On the
 * board two steps a loop turn (the loop's own two instructions shared by
 * 64 bytes); gcc -O2 makes the C loop sixteen single loads and stores a
 * step. */
static void words_copy_steps(uint8_t *d, const uint8_t *s, size_t steps)
{
#if defined(__arm__)
    if (steps & 1)
        __asm__ volatile(WORDS_STEP_ASM : [s] "+r"(s), [d] "+r"(d) : : WORDS_STEP_CLOBBERS);
    size_t pairs = steps / 2;
    if (pairs)
        __asm__ volatile("1:\n\t" WORDS_STEP_ASM WORDS_STEP_ASM
                         "subs %[n], %[n], #1\n\t"
                         "bne 1b"
                         : [s] "+r"(s), [d] "+r"(d), [n] "+r"(pairs)
                         :
                         : WORDS_STEP_CLOBBERS);
#else
    for (; steps; steps--, d += WORDS_STEP_BYTES, s += WORDS_STEP_BYTES) {
        words_step_t t;
        __builtin_memcpy(&t, s, sizeof t);
        __builtin_memcpy(d, &t, sizeof t);
    }
#endif
}

/* steps whole steps of zeros at d, word-aligned, steps > 0. */
static void words_zero_steps(uint8_t *d, size_t steps)
{
#if defined(__arm__)
    __asm__ volatile("mov r3, #0\n\t"
                     "mov r4, #0\n\t"
                     "mov r5, #0\n\t"
                     "mov r6, #0\n\t"
                     "mov r8, #0\n\t"
                     "mov r9, #0\n\t"
                     "mov r10, #0\n\t"
                     "mov r12, #0\n"
                     "1:\n\t"
                     "stmia %[d]!, {r3, r4, r5, r6, r8, r9, r10, r12}\n\t"
                     "subs %[n], %[n], #1\n\t"
                     "bne 1b"
                     : [d] "+r"(d), [n] "+r"(steps)
                     :
                     : WORDS_STEP_CLOBBERS);
#else
    static const words_step_t zero;
    for (; steps; steps--, d += WORDS_STEP_BYTES)
        __builtin_memcpy(d, &zero, sizeof zero);
#endif
}

void words_copy(void *dst, const void *src, size_t n)
{
    uint8_t *d = dst;
    const uint8_t *s = src;
    if ((((uintptr_t)d | (uintptr_t)s) & 3u) == 0) {
        size_t steps = n / WORDS_STEP_BYTES;
        if (steps) {
            words_copy_steps(d, s, steps);
            d += steps * WORDS_STEP_BYTES;
            s += steps * WORDS_STEP_BYTES;
            n -= steps * WORDS_STEP_BYTES;
        }
        for (; n >= 4; n -= 4, d += 4, s += 4) {
            uint32_t w;
            __builtin_memcpy(&w, s, 4);
            __builtin_memcpy(d, &w, 4);
        }
    }
    while (n--)
        *d++ = *s++;
}

void words_zero(void *dst, size_t n)
{
    uint8_t *d = dst;
    for (; n && ((uintptr_t)d & 3u); n--)
        *d++ = 0;
    size_t steps = n / WORDS_STEP_BYTES;
    if (steps) {
        words_zero_steps(d, steps);
        d += steps * WORDS_STEP_BYTES;
        n -= steps * WORDS_STEP_BYTES;
    }
    for (; n >= 4; n -= 4, d += 4) {
        uint32_t w = 0;
        __builtin_memcpy(d, &w, 4);
    }
    while (n--)
        *d++ = 0;
}
