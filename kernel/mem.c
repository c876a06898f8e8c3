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

/* steps whole steps from s to d, both word-aligned, steps > 0, each a
 * load-multiple (ld) and a store-multiple (st) of regs: two steps a loop
 * turn (the loop's own two instructions shared by two steps). */
#define MEM_COPY_STEPS(d, s, steps, ld, st, regs, ...)                                             \
    do {                                                                                           \
        if ((steps) & 1)                                                                           \
            __asm__ volatile(ld " %[s]!, " regs "\n\t" st " %[d]!, " regs                          \
                             : [s] "+r"(s), [d] "+r"(d)                                            \
                             :                                                                     \
                             : __VA_ARGS__);                                                       \
        size_t pairs = (steps) / 2;                                                                \
        if (pairs)                                                                                 \
            __asm__ volatile("1:\n\t" ld " %[s]!, " regs "\n\t" st " %[d]!, " regs "\n\t" ld     \
                             " %[s]!, " regs "\n\t" st " %[d]!, " regs "\n\t"                    \
                             "subs %[n], %[n], #1\n\t"                                             \
                             "bne 1b"                                                              \
                             : [s] "+r"(s), [d] "+r"(d), [n] "+r"(pairs)                           \
                             :                                                                     \
                             : __VA_ARGS__);                                                       \
    } while (0)

/* 32-byte steps: eight core registers. */
static void mem_copy_steps(uint8_t *d, const uint8_t *s, size_t steps)
{
    MEM_COPY_STEPS(d, s, steps, "ldmia", "stmia", MEM_STEP_REGS, MEM_STEP_CLOBBERS);
}

/* steps whole steps of word w at d, word-aligned, steps > 0: regs set
 * from w once (set), then a store-multiple (st) of them a step. */
#define MEM_FILL_STEPS(d, w, steps, set, st, regs, ...)                                           \
    __asm__ volatile(set "1:\n\t" st " %[d]!, " regs "\n\t"                                       \
                         "subs %[n], %[n], #1\n\t"                                                 \
                         "bne 1b"                                                                  \
                     : [d] "+r"(d), [n] "+r"(steps)                                                \
                     : [w] "r"(w)                                                                  \
                     : __VA_ARGS__)

static void mem_fill_steps(uint8_t *d, uint32_t w, size_t steps)
{
    MEM_FILL_STEPS(d, w, steps,
                   "mov r3, %[w]\n\tmov r4, %[w]\n\tmov r5, %[w]\n\tmov r6, %[w]\n\t"
                   "mov r8, %[w]\n\tmov r9, %[w]\n\tmov r10, %[w]\n\tmov r12, %[w]\n",
                   "stmia", MEM_STEP_REGS, MEM_STEP_CLOBBERS);
}

#if MEM_WIDE_BYTES
/* 128-byte steps: sixteen VFP double registers. */
static void mem_copy_wide(uint8_t *d, const uint8_t *s, size_t steps)
{
    MEM_COPY_STEPS(d, s, steps, "vldmia", "vstmia", MEM_WIDE_REGS, MEM_WIDE_CLOBBERS);
}

/* 128-byte fills: the sixteen registers set from w once. */
static void mem_fill_wide(uint8_t *d, uint32_t w, size_t steps)
{
    MEM_FILL_STEPS(d, w, steps,
                   "vmov d16, %[w], %[w]\n\tvmov.f64 d17, d16\n\tvmov.f64 d18, d16\n\t"
                   "vmov.f64 d19, d16\n\tvmov.f64 d20, d16\n\tvmov.f64 d21, d16\n\t"
                   "vmov.f64 d22, d16\n\tvmov.f64 d23, d16\n\tvmov.f64 d24, d16\n\t"
                   "vmov.f64 d25, d16\n\tvmov.f64 d26, d16\n\tvmov.f64 d27, d16\n\t"
                   "vmov.f64 d28, d16\n\tvmov.f64 d29, d16\n\tvmov.f64 d30, d16\n\t"
                   "vmov.f64 d31, d16\n",
                   "vstmia", MEM_WIDE_REGS, MEM_WIDE_CLOBBERS);
}
#endif

/* The whole steps (step bytes each) of n bytes from *s to *d by copy,
 * both moved past them: the bytes left. */
static inline __attribute__((always_inline)) size_t
mem_copy_by(uint8_t **d, const uint8_t **s, size_t n, size_t step,
            void (*copy)(uint8_t *, const uint8_t *, size_t))
{
    size_t steps = n / step;
    if (steps) {
        copy(*d, *s, steps);
        *d += steps * step;
        *s += steps * step;
        n -= steps * step;
    }
    return n;
}

/* The whole steps of n bytes at *d filled by fill with word w, *d moved
 * past them: the bytes left. */
static inline __attribute__((always_inline)) size_t
mem_fill_by(uint8_t **d, size_t n, size_t step, uint32_t w,
            void (*fill)(uint8_t *, uint32_t, size_t))
{
    size_t steps = n / step;
    if (steps) {
        fill(*d, w, steps);
        *d += steps * step;
        n -= steps * step;
    }
    return n;
}

__attribute__((optimize("no-tree-loop-distribute-patterns")))
void *memcpy(void *restrict dst, const void *restrict src, size_t n)
{
    uint8_t *d = dst;
    const uint8_t *s = src;
    if ((((uintptr_t)d | (uintptr_t)s) & 3u) == 0) {
#if MEM_WIDE_BYTES
        n = mem_copy_by(&d, &s, n, MEM_WIDE_BYTES, mem_copy_wide);
#endif
        n = mem_copy_by(&d, &s, n, MEM_STEP_BYTES, mem_copy_steps);
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
    if (n >= MEM_WIDE_FILL_MIN)
        n = mem_fill_by(&d, n, MEM_WIDE_BYTES, w, mem_fill_wide);
#endif
    n = mem_fill_by(&d, n, MEM_STEP_BYTES, w, mem_fill_steps);
    for (; n >= 4; n -= 4, d += 4)
        *(mem_word_t *)(void *)d = w;
    while (n--)
        *d++ = b;
    return dst;
}
