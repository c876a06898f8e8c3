/* spinlock.h: named spinlocks shared between cores.
 *
 * A lock knows its name and its owner (core number), so misuse is caught:
 * taking a lock this core already holds, or releasing one it does not hold,
 * panics with the lock's name.  Interrupts stay masked on the holding core
 * while it holds any lock (as in xv6), so an interrupt handler that takes a
 * lock can never deadlock against the code it interrupted. */
#ifndef LINKS1_KERNEL_SPINLOCK_H
#define LINKS1_KERNEL_SPINLOCK_H

#include <stdint.h>

#define SPIN_NO_OWNER (-1)

struct spinlock {
    volatile uint32_t locked; /* 0 free, 1 held; changed only with atomics */
    const char *name;         /* for panics */
    volatile int owner;       /* core number of the holder, SPIN_NO_OWNER */
};

#define SPINLOCK_INIT(n) { 0, (n), SPIN_NO_OWNER }

void spin_init(struct spinlock *l, const char *name);
void spin_lock(struct spinlock *l);
void spin_unlock(struct spinlock *l);
/* 1 if this core holds l. */
int spin_holding(const struct spinlock *l);
/* For the fault path only: drops l if this core holds it, so a core that
 * faults while sending can still report.  Returns 1 if it did. */
int spin_force_release_if_mine(struct spinlock *l);

/* Interrupt masking that nests: the outermost irq_pop_off restores the
 * state the outermost irq_push_off found. */
void irq_push_off(void);
void irq_pop_off(void);

#endif
