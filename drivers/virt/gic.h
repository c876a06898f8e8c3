/* gic.h: the GICv3 interrupt controller of the virt board: distributor
 * (shared), one redistributor per core, and the CPU interface through
 * system registers.  All interrupts are Group 1 (IRQ); the board's GIC has
 * no security extensions (virt without secure=on), so one group does. */
#ifndef LINKS1_DRIVERS_VIRT_GIC_H
#define LINKS1_DRIVERS_VIRT_GIC_H

#include <stdint.h>

/* Software-generated interrupts the kernel uses. */
#define SGI_DOORBELL 1 /* "look at your lines / IMSU": wakes a sleeping core */
/* "your turn for the lock" (kernel/spinlock.c): wakes a core asleep for a
 * lock.  Not an event for the core's tasks (they wait for doorbells). */
#define SGI_LOCK_TURN 2

#define GIC_INTID_SPURIOUS_MIN 1020u /* IAR values >= this are not interrupts */

/* Core 0, once: distributor on, affinity routing. */
void gic_dist_init(void);
/* Every core: finds and wakes its redistributor, enables SGIs and the
 * timer PPI, opens the CPU interface.  Panics naming the core if its
 * redistributor is not where memlayout.h says. */
void gic_cpu_init(void);
/* Routes shared interrupt intid (level, priority default) to core. */
void gic_route_spi(uint32_t intid, uint32_t core);
/* Sends SGI intid to one core. */
void gic_send_sgi(uint32_t core, uint32_t intid);
/* Drops SGI intid if it is pending on this core (it was seen otherwise). */
void gic_clear_sgi(uint32_t intid);
/* The IRQ entry of every core (boot/virt/vectors.S): acknowledges and
 * handles (kernel/irq.h) every pending interrupt. */
void gic_irq_dispatch(void);

#endif
