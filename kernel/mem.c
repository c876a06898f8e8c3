/* kernel/mem.c: the firmware's memcpy and memset, eight words a step.
 *
 * The board's C libraries (picolibc, newlib-nano) copy and fill a byte at
 * a time, about four instructions a byte.  Every copy of a unit computer
 * goes through these two instead: the arrays the DM loads and prepares a
 * frame into, the prepared blob the RC forwards, the struct copies gcc
 * turns into calls, the rows the RC moves into frame memory.  While both
 * ends are word-aligned they move 32 bytes a step (a load-multiple and a
 * store-multiple of eight registers), then a word, then a byte at a time.
 * The few words of a line message stay inline (kernel/kcopy.h), where a
 * call's set-up would cost as much as the copy.
 *
 * gcc may turn a loop that copies or fills into a call of these very
 * functions: not in this file (no-tree-loop-distribute-patterns). */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define MEM_STEP_BYTES 32

/* A word that may alias whatever the bytes hold. */
typedef uint32_t __attribute__((may_alias)) mem_word_t;

/* One step: eight registers (r7 left alone: Thumb code may keep its frame
 * pointer there). */
#define MEM_STEP_REGS "{r3, r4, r5, r6, r8, r9, r10, r12}"
#define MEM_STEP_CLOBBERS "r3", "r4", "r5", "r6", "r8", "r9", "r10", "r12", "cc", "memory"

/* steps whole steps from s to d, both word-aligned, steps > 0: two steps a
 * loop turn (the loop's own two instructions shared by 64 bytes). */
static void mem_copy_steps(uint8_t *d, const uint8_t *s, size_t steps)
{
    if (steps & 1)
        __asm__ volatile("ldmia %[s]!, " MEM_STEP_REGS "\n\t"
                         "stmia %[d]!, " MEM_STEP_REGS
                         : [s] "+r"(s), [d] "+r"(d)
                         :
                         : MEM_STEP_CLOBBERS);
    size_t pairs = steps / 2;
    if (pairs)
        __asm__ volatile("1:\n\t"
                         "ldmia %[s]!, " MEM_STEP_REGS "\n\t"
                         "stmia %[d]!, " MEM_STEP_REGS "\n\t"
                         "ldmia %[s]!, " MEM_STEP_REGS "\n\t"
                         "stmia %[d]!, " MEM_STEP_REGS "\n\t"
                         "subs %[n], %[n], #1\n\t"
                         "bne 1b"
                         : [s] "+r"(s), [d] "+r"(d), [n] "+r"(pairs)
                         :
                         : MEM_STEP_CLOBBERS);
}

/* steps whole steps of word w at d, word-aligned, steps > 0. */
static void mem_fill_steps(uint8_t *d, uint32_t w, size_t steps)
{
    __asm__ volatile("mov r3, %[w]\n\t"
                     "mov r4, %[w]\n\t"
                     "mov r5, %[w]\n\t"
                     "mov r6, %[w]\n\t"
                     "mov r8, %[w]\n\t"
                     "mov r9, %[w]\n\t"
                     "mov r10, %[w]\n\t"
                     "mov r12, %[w]\n"
                     "1:\n\t"
                     "stmia %[d]!, " MEM_STEP_REGS "\n\t"
                     "subs %[n], %[n], #1\n\t"
                     "bne 1b"
                     : [d] "+r"(d), [n] "+r"(steps)
                     : [w] "r"(w)
                     : MEM_STEP_CLOBBERS);
}

__attribute__((optimize("no-tree-loop-distribute-patterns")))
void *memcpy(void *restrict dst, const void *restrict src, size_t n)
{
    uint8_t *d = dst;
    const uint8_t *s = src;
    if ((((uintptr_t)d | (uintptr_t)s) & 3u) == 0) {
        size_t steps = n / MEM_STEP_BYTES;
        if (steps) {
            mem_copy_steps(d, s, steps);
            d += steps * MEM_STEP_BYTES;
            s += steps * MEM_STEP_BYTES;
            n -= steps * MEM_STEP_BYTES;
        }
        for (; n >= 4; n -= 4, d += 4, s += 4)
            *(mem_word_t *)(void *)d = *(const mem_word_t *)(const void *)s;
    }
    while (n--)
        *d++ = *s++;
    return dst;
}

__attribute__((optimize("no-tree-loop-distribute-patterns")))
void *memset(void *dst, int c, size_t n)
{
    uint8_t *d = dst, b = (uint8_t)c;
    uint32_t w = 0x01010101u * b;
    for (; n && ((uintptr_t)d & 3u); n--)
        *d++ = b;
    size_t steps = n / MEM_STEP_BYTES;
    if (steps) {
        mem_fill_steps(d, w, steps);
        d += steps * MEM_STEP_BYTES;
        n -= steps * MEM_STEP_BYTES;
    }
    for (; n >= 4; n -= 4, d += 4)
        *(mem_word_t *)(void *)d = w;
    while (n--)
        *d++ = b;
    return dst;
}
