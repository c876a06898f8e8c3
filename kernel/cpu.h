/* cpu.h: per-core state.  Every core is one unit computer; its state is
 * cpus[core], reached only through mycpu() (own core) or cpu_of(core). */
#ifndef LINKS1_KERNEL_CPU_H
#define LINKS1_KERNEL_CPU_H

#include <stddef.h>
#include <stdint.h>

#include "kernel/arch.h"
#include "kernel/param.h"
#include "kernel/spinlock.h"
#include "kernel/task.h"

struct cpu {
    uint32_t core;             /* core number 0..ncores-1 (= index in cpus) */
    uint32_t hwid;             /* the hardware's name of the core (machine_core_hwid) */
    uint8_t role;              /* enum unit_role: 0 DM, 1 RC, 2 NC */
    volatile uint8_t started;  /* 1 once the core runs its role program */
    volatile uint8_t reported; /* 1 once its LINK_HELLO went out */
    volatile uint8_t halted;   /* 1 once it faulted and stopped for good */
    volatile uint8_t boot_done; /* 1 once booted and idle (cpu_boot_done) */
    int irq_depth;             /* nesting of irq_push_off() */
    int irq_were_enabled;      /* IRQ state before the outermost push_off */
    int locks_held;            /* spinlocks held now (checked by task_wait) */
    struct spinlock *held[LOCKS_HELD_MAX]; /* those locks, innermost last, so
                                * a faulting core can drop them all */
    volatile uint32_t events;  /* bumped by every interrupt taken here and
                                * by task_signal_local(); tasks wait on it */
    volatile uint8_t wake_ready; /* 1 once a doorbell can wake this core (set by
                                * the machine's interrupt set-up) */
    uint64_t irqs_taken;       /* interrupts handled (statistics) */
    uint64_t sleeps;           /* times the scheduler slept in WFI */
    uint64_t lock_sleeps;      /* times a lock wait slept in WFI */
    struct task tasks[TASKS_PER_CORE]; /* this core's tasks */
    int current;               /* index in tasks of the running task, -1 none */
    struct task_ctx sched_ctx; /* the scheduler's own context */
    uint8_t *mem_base;         /* private memory of this unit computer */
    size_t mem_size;           /* its size */
    size_t mem_used;           /* bytes handed out (bump allocator) */
    size_t mem_high;           /* high-water mark of mem_used */
    char logbuf[KLOG_MAX];     /* klog() formats here (owner core only) */
};

extern struct cpu cpus[UNITS_MAX_CORES];

/* Number of cores on the board; set by core 0 before any other core runs. */
extern volatile uint32_t board_ncores;

/* This core's state (a core register holds the pointer, set by cpu_init:
 * kernel/arch.h). */
static inline struct cpu *mycpu(void)
{
    return (struct cpu *)arch_cpu_ptr();
}

static inline struct cpu *cpu_of(uint32_t core)
{
    return &cpus[core];
}

/* Fills cpus[core] and points TPIDRPRW at it; first thing each core does in C. */
void cpu_init(uint32_t core);
/* This core's boot is over: it reported in, started its tasks and for the
 * first time has nothing to do (task_schedule_forever calls this).  Tells
 * core 0, which starts the next core only then (boot/virt/boot.c): no two cores
 * report in at once, none waits for the host link's lock, and the work of
 * an idle boot is the same every time. */
void cpu_boot_done(void);

#endif
