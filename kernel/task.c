/* task.c: cooperative tasks and the per-core scheduler (see task.h). */
#include "kernel/task.h"

#include <string.h>

#include "kernel/arch.h"
#include "kernel/cpu.h"
#include "kernel/kmem.h"
#include "kernel/ktime.h"
#include "kernel/panic.h"

int task_create(const char *name, void (*fn)(void *), void *arg)
{
    struct cpu *c = mycpu();
    struct task *t = NULL;
    for (int i = 0; i < TASKS_PER_CORE; i++) {
        if (c->tasks[i].state == TASK_FREE || c->tasks[i].state == TASK_DONE) {
            t = &c->tasks[i];
            break;
        }
    }
    if (!t)
        panic("task_create '%s': all %d task slots of core %u in use", name,
              TASKS_PER_CORE, (unsigned)c->core);
    if (!t->stack)
        t->stack = kmem_alloc(TASK_STACK_SIZE, name);
    memset(&t->ctx, 0, sizeof t->ctx);
    t->ctx.sp = (uint32_t)(uintptr_t)(t->stack + TASK_STACK_SIZE) & ~7u;
    t->ctx.lr = (uint32_t)(uintptr_t)task_entry_trampoline;
    t->ctx.r4_r11[0] = (uint32_t)(uintptr_t)fn; /* trampoline calls r4(r5) */
    t->ctx.r4_r11[1] = (uint32_t)(uintptr_t)arg;
    t->fn = fn;
    t->arg = arg;
    t->deadline = 0;
    size_t n = strlen(name);
    if (n >= TASK_NAME_MAX)
        n = TASK_NAME_MAX - 1;
    memcpy(t->name, name, n);
    t->name[n] = '\0';
    t->state = TASK_RUNNABLE;
    return 0;
}

static struct task *task_current(struct cpu *c)
{
    return c->current >= 0 ? &c->tasks[c->current] : NULL;
}

const char *task_current_name(void)
{
    struct task *t = task_current(mycpu());
    return t ? t->name : "boot";
}

void task_exit_current(void)
{
    struct cpu *c = mycpu();
    struct task *t = task_current(c);
    t->state = TASK_DONE;
    task_switch_context(&t->ctx, &c->sched_ctx);
    panic("task_exit_current: a finished task was resumed");
}

void task_yield(void)
{
    struct cpu *c = mycpu();
    struct task *t = task_current(c);
    if (!t)
        return;
    task_switch_context(&t->ctx, &c->sched_ctx);
}

uint32_t task_event_mark(void)
{
    return mycpu()->events;
}

void task_signal_local(void)
{
    mycpu()->events++;
}

/* 1 if waiting task t may run now. */
static int task_ready(const struct cpu *c, const struct task *t)
{
    if (t->state == TASK_RUNNABLE)
        return 1;
    if (t->state != TASK_WAITING)
        return 0;
    return c->events != t->wait_mark || ktime_passed(t->deadline);
}

/* Sleeps in WFI until an interrupt when no task is ready.  Interrupts are
 * masked while we decide, so one arriving between the check and the WFI
 * still ends the WFI (a pending interrupt wakes WFI even when masked). */
static void task_idle(struct cpu *c, uint32_t mark, uint64_t deadline)
{
    arch_irq_disable();
    if (c->events == mark && !ktime_passed(deadline)) {
        ktime_arm(deadline);
        c->sleeps++;
        arch_dsb();
        arch_wfi();
    }
    arch_irq_enable(); /* the pending interrupt is taken here */
}

void task_wait(uint32_t mark, uint64_t deadline)
{
    struct cpu *c = mycpu();
    if (c->locks_held)
        panic("task_wait in task '%s' while holding %d spinlock(s)",
              task_current_name(), c->locks_held);
    struct task *t = task_current(c);
    if (!t) {
        /* Boot code before the scheduler: sleep right here. */
        while (c->events == mark && !ktime_passed(deadline))
            task_idle(c, mark, deadline);
        return;
    }
    t->wait_mark = mark;
    t->deadline = deadline;
    t->state = TASK_WAITING;
    task_switch_context(&t->ctx, &c->sched_ctx);
}

void task_schedule_forever(void)
{
    struct cpu *c = mycpu();
    for (;;) {
        int ran = 0;
        for (int i = 0; i < TASKS_PER_CORE; i++) {
            struct task *t = &c->tasks[i];
            if (!task_ready(c, t))
                continue;
            t->state = TASK_RUNNABLE;
            c->current = i;
            task_switch_context(&c->sched_ctx, &t->ctx);
            c->current = -1;
            ran = 1;
        }
        if (ran)
            continue;
        /* Nothing ready: sleep until the earliest deadline or an event. */
        uint64_t earliest = 0;
        for (int i = 0; i < TASKS_PER_CORE; i++) {
            struct task *t = &c->tasks[i];
            if (t->state == TASK_WAITING && t->deadline &&
                (!earliest || t->deadline < earliest))
                earliest = t->deadline;
        }
        uint32_t mark = c->events;
        int ready = 0;
        for (int i = 0; i < TASKS_PER_CORE; i++)
            ready |= task_ready(c, &c->tasks[i]);
        if (!ready) {
            if (!c->boot_done)
                cpu_boot_done(); /* first time idle: the next core may boot */
            task_idle(c, mark, earliest);
        }
    }
}
