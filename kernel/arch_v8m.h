/* arch_v8m.h: the ARMv8-M Mainline (Cortex-M33) instructions and core
 * registers the kernel uses, the same functions as kernel/arch_v7a.h. */
#ifndef LINKS1_KERNEL_ARCH_V8M_H
#define LINKS1_KERNEL_ARCH_V8M_H

#include <stdint.h>

/* The "memory" clobbers keep the compiler from moving accesses across the
 * points where interrupts change state. */
static inline void arch_irq_disable(void) { __asm__ volatile("cpsid i" ::: "memory"); }
static inline void arch_irq_enable(void) { __asm__ volatile("cpsie i" ::: "memory"); }
/* Sleeps until an interrupt is pending, even one PRIMASK holds off. */
static inline void arch_wfi(void) { __asm__ volatile("wfi" ::: "memory"); }
static inline void arch_sev(void) { __asm__ volatile("sev" ::: "memory"); }
static inline void arch_wfe(void) { __asm__ volatile("wfe" ::: "memory"); }
/* M-profile barriers have one domain, the whole system. */
static inline void arch_dmb(void) { __asm__ volatile("dmb" ::: "memory"); }
static inline void arch_dsb(void) { __asm__ volatile("dsb" ::: "memory"); }
static inline void arch_isb(void) { __asm__ volatile("isb" ::: "memory"); }

/* 1 while this core's interrupts are masked (PRIMASK). */
static inline int arch_irqs_masked(void)
{
    uint32_t v;
    __asm__ volatile("mrs %0, primask" : "=r"(v));
    return (v & 1u) != 0;
}

/* This core's struct cpu (kernel/cpu.h).  The M33 has no thread register;
 * the firmware never uses the process stack (everything runs on MSP), so
 * the process stack's limit register PSPLIM, one per core, holds the
 * pointer (8-byte aligned: its low three bits read as zero). */
static inline void arch_set_cpu_ptr(void *c)
{
    __asm__ volatile("msr psplim, %0" ::"r"(c) : "memory");
}
static inline void *arch_cpu_ptr(void)
{
    void *v;
    __asm__ volatile("mrs %0, psplim" : "=r"(v));
    return v;
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

/* ---- fault status (System Control Block) ---- */
#define ARCH_SCB_CFSR 0xE000ED28u  /* configurable fault status */
#define ARCH_SCB_MMFAR 0xE000ED34u /* memory management fault address */
#define ARCH_SCB_BFAR 0xE000ED38u  /* bus fault address */
#define ARCH_CFSR_MMARVALID (1u << 7)
#define ARCH_CFSR_BFARVALID (1u << 15)

/* Where a fault happened and why: CFSR as the status, the bus or memory
 * management fault address when the CFSR says it is valid. */
static inline void arch_fault_info(uint32_t kind, uint32_t *addr, uint32_t *status)
{
    (void)kind;
    uint32_t cfsr = mmio_read32(ARCH_SCB_CFSR);
    *status = cfsr;
    if (cfsr & ARCH_CFSR_BFARVALID)
        *addr = mmio_read32(ARCH_SCB_BFAR);
    else if (cfsr & ARCH_CFSR_MMARVALID)
        *addr = mmio_read32(ARCH_SCB_MMFAR);
}

#endif
