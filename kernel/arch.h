/* arch.h: the ARMv7-A (AArch32, cortex-a15) instructions and coprocessor
 * registers the kernel uses, one inline function each. */
#ifndef LINKS1_KERNEL_ARCH_H
#define LINKS1_KERNEL_ARCH_H

#include <stdint.h>

static inline uint32_t arch_read_mpidr(void)
{
    uint32_t v;
    __asm__ volatile("mrc p15, 0, %0, c0, c0, 5" : "=r"(v));
    return v;
}

/* TPIDRPRW: PL1-only thread register; holds this core's struct cpu *. */
static inline void arch_write_tpidrprw(uintptr_t v)
{
    __asm__ volatile("mcr p15, 0, %0, c13, c0, 4" ::"r"(v) : "memory");
}
static inline uintptr_t arch_read_tpidrprw(void)
{
    uintptr_t v;
    __asm__ volatile("mrc p15, 0, %0, c13, c0, 4" : "=r"(v));
    return v;
}

static inline uint32_t arch_read_cpsr(void)
{
    uint32_t v;
    __asm__ volatile("mrs %0, cpsr" : "=r"(v));
    return v;
}
#define ARCH_CPSR_I (1u << 7) /* IRQs masked */

/* The "memory" clobbers keep the compiler from moving accesses across the
 * points where interrupts change state. */
static inline void arch_irq_disable(void) { __asm__ volatile("cpsid i" ::: "memory"); }
static inline void arch_irq_enable(void) { __asm__ volatile("cpsie i" ::: "memory"); }
static inline void arch_wfi(void) { __asm__ volatile("wfi" ::: "memory"); }
static inline void arch_sev(void) { __asm__ volatile("sev" ::: "memory"); }
static inline void arch_wfe(void) { __asm__ volatile("wfe" ::: "memory"); }
/* Orders this core's memory accesses as seen by the other cores
 * (inner shareable domain: every core of the board). */
static inline void arch_dmb(void) { __asm__ volatile("dmb ish" ::: "memory"); }
/* Completes memory accesses (before WFI, SEV, or a device write that must
 * follow them). */
static inline void arch_dsb(void) { __asm__ volatile("dsb ish" ::: "memory"); }
static inline void arch_isb(void) { __asm__ volatile("isb" ::: "memory"); }

/* ---- fault status ---- */
static inline uint32_t arch_read_dfar(void)
{
    uint32_t v;
    __asm__ volatile("mrc p15, 0, %0, c6, c0, 0" : "=r"(v));
    return v;
}
static inline uint32_t arch_read_dfsr(void)
{
    uint32_t v;
    __asm__ volatile("mrc p15, 0, %0, c5, c0, 0" : "=r"(v));
    return v;
}
static inline uint32_t arch_read_ifar(void)
{
    uint32_t v;
    __asm__ volatile("mrc p15, 0, %0, c6, c0, 2" : "=r"(v));
    return v;
}
static inline uint32_t arch_read_ifsr(void)
{
    uint32_t v;
    __asm__ volatile("mrc p15, 0, %0, c5, c0, 1" : "=r"(v));
    return v;
}

/* ---- generic timer (non-secure physical timer) ---- */
static inline uint64_t arch_read_cntpct(void)
{
    uint32_t lo, hi;
    arch_isb(); /* the count must not be read ahead of earlier code */
    __asm__ volatile("mrrc p15, 0, %0, %1, c14" : "=r"(lo), "=r"(hi));
    return ((uint64_t)hi << 32) | lo;
}
static inline uint32_t arch_read_cntfrq(void)
{
    uint32_t v;
    __asm__ volatile("mrc p15, 0, %0, c14, c0, 0" : "=r"(v));
    return v;
}
static inline void arch_write_cntp_cval(uint64_t v)
{
    __asm__ volatile("mcrr p15, 2, %0, %1, c14" ::"r"((uint32_t)v), "r"((uint32_t)(v >> 32)));
}
static inline void arch_write_cntp_ctl(uint32_t v)
{
    __asm__ volatile("mcr p15, 0, %0, c14, c2, 1" ::"r"(v));
    arch_isb();
}
#define CNTP_CTL_ENABLE (1u << 0)
#define CNTP_CTL_IMASK (1u << 1)

/* ---- GICv3 CPU interface (system registers) ---- */
static inline void arch_write_icc_sre(uint32_t v)
{
    __asm__ volatile("mcr p15, 0, %0, c12, c12, 5" ::"r"(v));
    arch_isb();
}
static inline uint32_t arch_read_icc_sre(void)
{
    uint32_t v;
    __asm__ volatile("mrc p15, 0, %0, c12, c12, 5" : "=r"(v));
    return v;
}
static inline void arch_write_icc_pmr(uint32_t v)
{
    __asm__ volatile("mcr p15, 0, %0, c4, c6, 0" ::"r"(v));
}
static inline void arch_write_icc_bpr1(uint32_t v)
{
    __asm__ volatile("mcr p15, 0, %0, c12, c12, 3" ::"r"(v));
}
static inline void arch_write_icc_igrpen1(uint32_t v)
{
    __asm__ volatile("mcr p15, 0, %0, c12, c12, 7" ::"r"(v));
    arch_isb();
}
static inline uint32_t arch_read_icc_iar1(void)
{
    uint32_t v;
    __asm__ volatile("mrc p15, 0, %0, c12, c12, 0" : "=r"(v)::"memory");
    return v;
}
static inline void arch_write_icc_eoir1(uint32_t v)
{
    __asm__ volatile("mcr p15, 0, %0, c12, c12, 1" ::"r"(v) : "memory");
}
static inline void arch_write_icc_sgi1r(uint64_t v)
{
    __asm__ volatile("mcrr p15, 0, %0, %1, c12" ::"r"((uint32_t)v), "r"((uint32_t)(v >> 32))
                     : "memory");
    arch_isb();
}

/* ---- memory-mapped device registers ---- */
static inline uint32_t mmio_read32(uintptr_t addr)
{
    return *(volatile uint32_t *)addr;
}
static inline void mmio_write32(uintptr_t addr, uint32_t v)
{
    *(volatile uint32_t *)addr = v;
}

#endif
