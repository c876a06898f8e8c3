/* task.h: cooperative tasks on one core.
 *
 * Each core runs a few tasks; a task runs until it yields or waits.  A
 * waiting task sleeps until an "event" happens on its core: any interrupt
 * the core takes (a doorbell from another core, the UART, the timer)
 * and any task_signal_local() bumps the core's event counter.  To wait for
 * a condition without losing a wake-up:
 *
 *     for (;;) {
 *         uint32_t mark = task_event_mark();   // before looking
 *         if (condition holds) break;
 *         task_wait(mark, deadline);           // returns at once if an
 *     }                                        // event came after mark
 *
 * When no task can run, the core sleeps in WFI (never spins) until an
 * interrupt, with the generic timer set for the earliest deadline. */
#ifndef LINKS1_KERNEL_TASK_H
#define LINKS1_KERNEL_TASK_H

#include <stdint.h>

#include "kernel/param.h"

/* Registers a task keeps across task_switch_context (callee-saved, AAPCS). */
struct task_ctx {
    uint32_t r4_r11[8];
    uint32_t sp;
    uint32_t lr;
    uint64_t d8_d15[8]; /* VFP callee-saved; used by the hard-float build */
};

enum task_state {
    TASK_FREE = 0,  /* slot unused */
    TASK_RUNNABLE,  /* ready to run */
    TASK_WAITING,   /* waiting for an event after wait_mark, or deadline */
    TASK_DONE,      /* returned; slot reusable */
};

struct task {
    struct task_ctx ctx;       /* saved registers while not running */
    enum task_state state;     /* see enum task_state */
    uint32_t wait_mark;        /* event counter value it waits to change */
    uint64_t deadline;         /* timer tick to wake at, 0 = none */
    void (*fn)(void *);        /* entry point */
    void *arg;                 /* its argument */
    uint8_t *stack;            /* TASK_STACK_SIZE bytes, from kmem */
    char name[TASK_NAME_MAX];  /* for logs and panics */
};

/* Creates a task on this core.  Returns 0, or panics if the core has no
 * free slot or no private memory left for the stack. */
int task_create(const char *name, void (*fn)(void *), void *arg);
/* Lets the other runnable tasks of this core run. */
void task_yield(void);
/* The core's event counter, to pass to task_wait. */
uint32_t task_event_mark(void);
/* Sleeps until the core's event counter differs from mark, or the generic
 * timer reaches deadline (ticks; 0 = no deadline). */
void task_wait(uint32_t mark, uint64_t deadline);
/* Wakes the waiting tasks of this core (for hand-offs between tasks). */
void task_signal_local(void);
/* Runs the core's tasks forever; the boot code calls it last. */
void task_schedule_forever(void) __attribute__((noreturn));
/* Name of the running task, or "boot". */
const char *task_current_name(void);

/* boot/virt/vectors.S: saves the running context in from, resumes to. */
void task_switch_context(struct task_ctx *from, struct task_ctx *to);
/* boot/virt/vectors.S: first code of a new task; calls fn(arg), then
 * task_exit_current(), which marks the task done and never returns. */
void task_entry_trampoline(void);
void task_exit_current(void) __attribute__((noreturn));

#endif
