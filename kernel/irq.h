/* irq.h: the table of interrupt handlers, and what every interrupt taken
 * does.
 *
 * The kernel knows no device: a driver registers the handler of its
 * interrupt (as xv6's uart does through its console), and the machine's
 * timer registers the same way.  The machine's interrupt controller driver
 * (drivers/<machine>/) takes each interrupt and hands it to irq_handle.  A
 * doorbell needs no handler: the event count every interrupt bumps is what
 * wakes the waiting tasks. */
#ifndef LINKS1_KERNEL_IRQ_H
#define LINKS1_KERNEL_IRQ_H

#include <stdint.h>

typedef void (*irq_handler_fn)(void *arg);

/* Sets the handler of interrupt intid (below IRQ_MAX) and its argument;
 * it runs on whichever core takes the interrupt, with interrupts masked,
 * and must take no lock (kernel/spinlock.h).  Core 0 registers at boot,
 * before it wakes the other cores.  Panics if intid is out of range or
 * already has a handler. */
void irq_register(uint32_t intid, irq_handler_fn fn, void *arg);

/* One interrupt taken on this core: runs its handler, if any, and counts
 * it; with is_event (every interrupt but a spinlock's turn, which is for
 * the lock waiter only) bumps the core's event counter, which is what wakes
 * the waiting tasks. */
void irq_handle(uint32_t intid, int is_event);

#endif
