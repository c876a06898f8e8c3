/* kernel/mem.c: the firmware's memcpy and memset, 128 or 32 bytes a step.
 *
 * The board's C libraries (picolibc, newlib-nano) copy and fill a byte at
 * a time, about four instructions a byte.  Every copy of a unit computer
 * goes through these two instead: the arrays the DM loads and prepares a
 * frame into, the prepared blob the RC forwards, the struct copies gcc
 * turns into calls, the rows the RC moves into frame memory.  While both
 * ends are word-aligned they move 128 bytes a step where the core has 32
 * VFP double registers (the Cortex-A15 builds with their FPU: a VFP
 * load-multiple and store-multiple of d16-d31, registers a call may
 * clobber and the IRQ entry saves), else 32 bytes a step (a load-multiple
 * and a store-multiple of eight core registers); then 32 bytes, a word,
 * and a byte at a time.  The VFP moves bits as they are: no value is
 * read as a number.
 * The few words of a line message stay inline (kernel/kcopy.h), where a
 * call's set-up would cost as much as the copy.
 *
 * gcc may turn a loop that copies or fills into a call of these very
 * functions: not in this file (no-tree-loop-distribute-patterns). */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define MEM_STEP_BYTES 32

/* The 128-byte steps: the Cortex-A hard-float builds (VFPv4 with 32
 * double registers); not the builds without an FPU, nor the M33's. */
#if defined(__arm__) && defined(__ARM_PCS_VFP) && defined(__ARM_ARCH_PROFILE) &&                 \
    __ARM_ARCH_PROFILE == 'A'
#define MEM_WIDE_BYTES 128
/* A fill sets its sixteen registers first: worth it from four steps. */
#define MEM_WIDE_FILL_MIN (4 * MEM_WIDE_BYTES)
#define MEM_WIDE_REGS "{d16-d31}"
#define MEM_WIDE_CLOBBERS                                                                          \
    "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28",     \
        "d29", "d30", "d31", "cc", "memory"
#else
#define MEM_WIDE_BYTES 0
#endif

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

#if MEM_WIDE_BYTES
/* steps whole 128-byte steps from s to d, both word-aligned, steps > 0:
 * two steps a loop turn, as mem_copy_steps. */
static void mem_copy_wide(uint8_t *d, const uint8_t *s, size_t steps)
{
    if (steps & 1)
        __asm__ volatile("vldmia %[s]!, " MEM_WIDE_REGS "\n\t"
                         "vstmia %[d]!, " MEM_WIDE_REGS
                         : [s] "+r"(s), [d] "+r"(d)
                         :
                         : MEM_WIDE_CLOBBERS);
    size_t pairs = steps / 2;
    if (pairs)
        __asm__ volatile("1:\n\t"
                         "vldmia %[s]!, " MEM_WIDE_REGS "\n\t"
                         "vstmia %[d]!, " MEM_WIDE_REGS "\n\t"
                         "vldmia %[s]!, " MEM_WIDE_REGS "\n\t"
                         "vstmia %[d]!, " MEM_WIDE_REGS "\n\t"
                         "subs %[n], %[n], #1\n\t"
                         "bne 1b"
                         : [s] "+r"(s), [d] "+r"(d), [n] "+r"(pairs)
                         :
                         : MEM_WIDE_CLOBBERS);
}

/* steps whole 128-byte steps of word w at d, word-aligned, steps > 0:
 * the sixteen registers set from w once. */
static void mem_fill_wide(uint8_t *d, uint32_t w, size_t steps)
{
    __asm__ volatile("vmov d16, %[w], %[w]\n\t"
                     "vmov.f64 d17, d16\n\t"
                     "vmov.f64 d18, d16\n\t"
                     "vmov.f64 d19, d16\n\t"
                     "vmov.f64 d20, d16\n\t"
                     "vmov.f64 d21, d16\n\t"
                     "vmov.f64 d22, d16\n\t"
                     "vmov.f64 d23, d16\n\t"
                     "vmov.f64 d24, d16\n\t"
                     "vmov.f64 d25, d16\n\t"
                     "vmov.f64 d26, d16\n\t"
                     "vmov.f64 d27, d16\n\t"
                     "vmov.f64 d28, d16\n\t"
                     "vmov.f64 d29, d16\n\t"
                     "vmov.f64 d30, d16\n\t"
                     "vmov.f64 d31, d16\n"
                     "1:\n\t"
                     "vstmia %[d]!, " MEM_WIDE_REGS "\n\t"
                     "subs %[n], %[n], #1\n\t"
                     "bne 1b"
                     : [d] "+r"(d), [n] "+r"(steps)
                     : [w] "r"(w)
                     : MEM_WIDE_CLOBBERS);
}
#endif

__attribute__((optimize("no-tree-loop-distribute-patterns")))
void *memcpy(void *restrict dst, const void *restrict src, size_t n)
{
    uint8_t *d = dst;
    const uint8_t *s = src;
    if ((((uintptr_t)d | (uintptr_t)s) & 3u) == 0) {
#if MEM_WIDE_BYTES
        size_t wide = n / MEM_WIDE_BYTES;
        if (wide) {
            mem_copy_wide(d, s, wide);
            d += wide * MEM_WIDE_BYTES;
            s += wide * MEM_WIDE_BYTES;
            n -= wide * MEM_WIDE_BYTES;
        }
#endif
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
#if MEM_WIDE_BYTES
    if (n >= MEM_WIDE_FILL_MIN) {
        size_t wide = n / MEM_WIDE_BYTES;
        mem_fill_wide(d, w, wide);
        d += wide * MEM_WIDE_BYTES;
        n -= wide * MEM_WIDE_BYTES;
    }
#endif
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
