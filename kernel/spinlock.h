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
/* For the fault path only: drops every lock this core holds, so a core
 * that faults inside a critical section can still report and the other
 * cores are not left waiting on it forever.  Returns how many. */
int spin_release_all_mine(void);

/* Interrupt masking that nests: the outermost irq_pop_off restores the
 * state the outermost irq_push_off found. */
void irq_push_off(void);
void irq_pop_off(void);

#endif
