/* spinlock.h: named locks shared between cores.
 *
 * A lock knows its name and its owner (core number), so misuse is caught:
 * taking a lock this core already holds, or releasing one it does not hold,
 * panics with the lock's name.  Interrupts stay masked on the holding core
 * while it holds any lock (as in xv6).
 *
 * Waiting never spins.  The lock hands out tickets and serves them in
 * order; a core whose ticket is not yet served writes its number into the
 * ticket's wait slot and sleeps in WFI.  The releaser serves the next
 * ticket and wakes that core (and only that core) with machine_lock_turn
 * (kernel/machine.h; an SGI on the virt board).  (WFE
 * would not do: QEMU's TCG runs WFE as a no-op, so a WFE loop is a busy
 * loop, and WFI does not wake on SEV.)  While it
 * sleeps for its turn a core takes its interrupts if it had them enabled
 * before asking for the lock and holds no other lock; so interrupt handlers
 * must take no lock (none does: they only touch their own device's state).
 * Until the machine can wake it (cpu->wake_ready) a core waits by looking
 * again instead. */
#ifndef LINKS1_KERNEL_SPINLOCK_H
#define LINKS1_KERNEL_SPINLOCK_H

#include <stdint.h>

#include "kernel/param.h"

#define SPIN_NO_OWNER (-1)

struct spinlock {
    volatile uint32_t next;    /* next ticket to hand out (atomic add) */
    volatile uint32_t serving; /* ticket that holds, or may take, the lock */
    const char *name;          /* for panics */
    volatile int owner;        /* core number of the holder, SPIN_NO_OWNER */
    /* Core number + 1 of the core asleep waiting for ticket t, at
     * t % UNITS_MAX_CORES (a core waits for one ticket at a time, so no two
     * waiting tickets share a slot); 0 = nobody asleep there. */
    volatile uint16_t sleeper[UNITS_MAX_CORES];
};

#define SPINLOCK_INIT(n) { 0, 0, (n), SPIN_NO_OWNER, {0} }

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
