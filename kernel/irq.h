/* irq.h: the interrupt entry every core runs. */
#ifndef LINKS1_KERNEL_IRQ_H
#define LINKS1_KERNEL_IRQ_H

/* Called by boot/vectors.S on an IRQ: acknowledges and handles every
 * pending interrupt (timer, UART, doorbell SGI) and bumps the core's event
 * counter once per interrupt, which is what wakes the waiting tasks. */
void irq_dispatch(void);

#endif
