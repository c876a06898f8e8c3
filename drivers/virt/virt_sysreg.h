/* virt_sysreg.h: the Cortex-A15 system registers of the virt board's
 * devices: MPIDR (the core's place in the GICv3 affinity layout), the
 * generic timer and the GICv3 CPU interface, one inline function each. */
#ifndef LINKS1_DRIVERS_VIRT_VIRT_SYSREG_H
#define LINKS1_DRIVERS_VIRT_VIRT_SYSREG_H

#include <stdint.h>

#include "kernel/arch.h"

static inline uint32_t arch_read_mpidr(void)
{
    uint32_t v;
    __asm__ volatile("mrc p15, 0, %0, c0, c0, 5" : "=r"(v));
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

#endif
