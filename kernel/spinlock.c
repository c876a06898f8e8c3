/* spinlock.c: named, owner-checked spinlocks (see spinlock.h). */
#include "kernel/spinlock.h"

#include "kernel/arch.h"
#include "kernel/cpu.h"
#include "kernel/machine.h"
#include "kernel/panic.h"

void spin_init(struct spinlock *l, const char *name)
{
    l->next = 0;
    l->serving = 0;
    l->name = name;
    l->owner = SPIN_NO_OWNER;
    for (int i = 0; i < UNITS_MAX_CORES; i++)
        l->sleeper[i] = 0;
}

int spin_holding(const struct spinlock *l)
{
    /* Only the holder writes its own number here. */
    return l->owner == (int)mycpu()->core;
}

/* Sleeps until ticket t is served.  The sleeper slot is written before
 * serving is looked at, and the releaser writes serving before it looks at
 * the slot; with a full barrier on each side, either this core sees its
 * turn or the releaser sees this core and rings its doorbell. */
static void spin_wait_turn(struct spinlock *l, uint32_t t, struct cpu *c)
{
    volatile uint16_t *slot = &l->sleeper[t % UNITS_MAX_CORES];
    *slot = (uint16_t)(c->core + 1);
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    /* Interrupts stay deliverable while asleep if the caller had them on
     * and this is its only lock: no handler takes a lock (spinlock.h). */
    int window = c->irq_depth == 1 && c->irq_were_enabled;
    int slept = 0;
    while (__atomic_load_n(&l->serving, __ATOMIC_ACQUIRE) != t) {
        if (!c->wake_ready)
            continue; /* no doorbell can reach this core yet: look again */
        slept = 1;
        c->lock_sleeps++;
        arch_wfi(); /* masked, a pending interrupt still ends it */
        if (window) {
            arch_irq_enable(); /* the pending interrupt is taken here */
            arch_irq_disable();
        }
    }
    *slot = 0;
    /* The turn was seen: its wake-up, still pending if interrupts stayed
     * masked, has nothing more to say. */
    if (slept)
        machine_lock_turn_seen();
}

void spin_lock(struct spinlock *l)
{
    irq_push_off();
    struct cpu *c = mycpu();
    if (spin_holding(l))
        panic("spin_lock: lock '%s' already held by this core", l->name);
    if (c->locks_held >= LOCKS_HELD_MAX)
        panic("spin_lock: '%s' would be lock %d held at once by this core (max %d)",
              l->name, c->locks_held + 1, LOCKS_HELD_MAX);
    /* The ticket is an acquire: nothing inside the critical section can be
     * seen by other cores before the lock is ours. */
    uint32_t t = __atomic_fetch_add(&l->next, 1u, __ATOMIC_ACQ_REL);
    if (__atomic_load_n(&l->serving, __ATOMIC_ACQUIRE) != t)
        spin_wait_turn(l, t, c);
    l->owner = (int)c->core;
    c->held[c->locks_held++] = l;
}

/* Serves the next ticket and wakes the core asleep for it, if any. */
static void spin_pass_on(struct spinlock *l)
{
    l->owner = SPIN_NO_OWNER;
    uint32_t t = l->serving + 1u;
    /* Release: every write of the critical section is visible before the
     * next ticket reads served. */
    __atomic_store_n(&l->serving, t, __ATOMIC_RELEASE);
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    uint16_t sleeper = l->sleeper[t % UNITS_MAX_CORES];
    if (sleeper)
        machine_lock_turn((uint32_t)sleeper - 1u);
}

/* Forgets l in this core's list of held locks. */
static void spin_forget(struct cpu *c, struct spinlock *l)
{
    for (int i = c->locks_held - 1; i >= 0; i--) {
        if (c->held[i] == l) {
            for (int j = i; j + 1 < c->locks_held; j++)
                c->held[j] = c->held[j + 1];
            c->locks_held--;
            return;
        }
    }
}

void spin_unlock(struct spinlock *l)
{
    if (!spin_holding(l))
        panic("spin_unlock: lock '%s' not held by this core (owner %d)", l->name,
              l->owner);
    spin_forget(mycpu(), l);
    spin_pass_on(l);
    irq_pop_off();
}

int spin_release_all_mine(void)
{
    struct cpu *c = mycpu();
    int n = 0;
    while (c->locks_held > 0) {
        spin_pass_on(c->held[--c->locks_held]);
        n++;
    }
    return n;
}

void irq_push_off(void)
{
    int enabled = !arch_irqs_masked();
    arch_irq_disable();
    struct cpu *c = mycpu();
    if (c->irq_depth == 0)
        c->irq_were_enabled = enabled;
    c->irq_depth++;
}

void irq_pop_off(void)
{
    struct cpu *c = mycpu();
    if (arch_irqs_masked()) {
        if (c->irq_depth < 1)
            panic("irq_pop_off: not pushed");
        c->irq_depth--;
        if (c->irq_depth == 0 && c->irq_were_enabled)
            arch_irq_enable();
    } else {
        panic("irq_pop_off: interrupts enabled inside a push_off section");
    }
}
