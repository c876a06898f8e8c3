/* spinlock.c: named, owner-checked spinlocks (see spinlock.h). */
#include "kernel/spinlock.h"

#include "kernel/arch.h"
#include "kernel/cpu.h"
#include "kernel/panic.h"

void spin_init(struct spinlock *l, const char *name)
{
    l->locked = 0;
    l->name = name;
    l->owner = SPIN_NO_OWNER;
}

int spin_holding(const struct spinlock *l)
{
    return l->locked && l->owner == (int)mycpu()->core;
}

void spin_lock(struct spinlock *l)
{
    irq_push_off();
    if (spin_holding(l))
        panic("spin_lock: lock '%s' already held by this core", l->name);
    /* The exchange is an acquire: nothing inside the critical section can
     * be seen by other cores before the lock is ours. */
    while (__atomic_exchange_n(&l->locked, 1u, __ATOMIC_ACQUIRE) != 0) {
        /* Another core holds it: wait for its SEV instead of hammering the
         * line (a held lock is held for a few microseconds at most). */
        while (__atomic_load_n(&l->locked, __ATOMIC_RELAXED) != 0)
            arch_wfe();
    }
    struct cpu *c = mycpu();
    if (c->locks_held >= LOCKS_HELD_MAX)
        panic("spin_lock: '%s' would be lock %d held at once by this core (max %d)",
              l->name, c->locks_held + 1, LOCKS_HELD_MAX);
    l->owner = (int)c->core;
    c->held[c->locks_held++] = l;
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
    l->owner = SPIN_NO_OWNER;
    spin_forget(mycpu(), l);
    /* Release: every write of the critical section is visible before the
     * lock reads free.  The DSB completes the store before SEV wakes the
     * cores waiting in WFE. */
    __atomic_store_n(&l->locked, 0u, __ATOMIC_RELEASE);
    arch_dsb();
    arch_sev();
    irq_pop_off();
}

int spin_release_all_mine(void)
{
    struct cpu *c = mycpu();
    int n = 0;
    while (c->locks_held > 0) {
        struct spinlock *l = c->held[--c->locks_held];
        l->owner = SPIN_NO_OWNER;
        __atomic_store_n(&l->locked, 0u, __ATOMIC_RELEASE);
        n++;
    }
    arch_dsb();
    arch_sev();
    return n;
}

void irq_push_off(void)
{
    int enabled = (arch_read_cpsr() & ARCH_CPSR_I) == 0;
    arch_irq_disable();
    struct cpu *c = mycpu();
    if (c->irq_depth == 0)
        c->irq_were_enabled = enabled;
    c->irq_depth++;
}

void irq_pop_off(void)
{
    struct cpu *c = mycpu();
    if (arch_read_cpsr() & ARCH_CPSR_I) {
        if (c->irq_depth < 1)
            panic("irq_pop_off: not pushed");
        c->irq_depth--;
        if (c->irq_depth == 0 && c->irq_were_enabled)
            arch_irq_enable();
    } else {
        panic("irq_pop_off: interrupts enabled inside a push_off section");
    }
}
