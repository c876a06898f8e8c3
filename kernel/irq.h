/* irq.h: the interrupt entry every core runs, and the table of handlers.
 *
 * The kernel knows no device: a driver registers the handler of its
 * interrupt (as xv6's uart does through its console), and the kernel's own
 * timer registers the same way.  The doorbell SGI needs no handler: the
 * event count every interrupt bumps is what wakes the waiting tasks. */
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

/* Called by boot/vectors.S on an IRQ: acknowledges and handles every
 * pending interrupt and bumps the core's event counter once per interrupt
 * (but SGI_LOCK_TURN, which is for lock waiters only), which is what wakes
 * the waiting tasks. */
void irq_dispatch(void);

#endif
