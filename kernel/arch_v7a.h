/* arch_v7a.h: the ARMv7-A (AArch32, cortex-a15) instructions and coprocessor
 * registers the kernel uses, one inline function each.  The registers of
 * the machine's own timer and interrupt controller are its drivers'
 * (drivers/virt/virt_sysreg.h). */
#ifndef LINKS1_KERNEL_ARCH_V7A_H
#define LINKS1_KERNEL_ARCH_V7A_H

#include <stdint.h>

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
/* 1 while this core's interrupts are masked. */
static inline int arch_irqs_masked(void)
{
    return (arch_read_cpsr() & ARCH_CPSR_I) != 0;
}

/* This core's struct cpu (kernel/cpu.h), kept in TPIDRPRW. */
static inline void arch_set_cpu_ptr(void *c)
{
    arch_write_tpidrprw((uintptr_t)c);
}
static inline void *arch_cpu_ptr(void)
{
    return (void *)arch_read_tpidrprw();
}

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

/* Where a fault happened and why: the data abort's DFAR/DFSR or the
 * prefetch abort's IFAR/IFSR (kind: enum link_fault_kind). */
static inline void arch_fault_info(uint32_t kind, uint32_t *addr, uint32_t *status)
{
    if (kind == 3u) { /* FAULT_DATA_ABORT */
        *addr = arch_read_dfar();
        *status = arch_read_dfsr();
    } else if (kind == 2u) { /* FAULT_PREFETCH_ABORT */
        *addr = arch_read_ifar();
        *status = arch_read_ifsr();
    }
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
