/* irq.c: the IRQ dispatcher every core runs (called by boot/vectors.S). */
#include "kernel/irq.h"

#include "drivers/serial/uart.h"
#include "kernel/cpu.h"
#include "kernel/gic.h"
#include "kernel/ktime.h"
#include "kernel/memlayout.h"

void irq_dispatch(void)
{
    struct cpu *c = mycpu();
    for (;;) {
        uint32_t id = gic_ack();
        if (id >= GIC_INTID_SPURIOUS_MIN)
            break;
        if (id == TIMER_INTID)
            ktime_irq();
        else if (id == UART0_INTID)
            uart_irq();
        /* SGI_DOORBELL needs no work here: the event count below is what
         * wakes the waiting tasks, which then look at their lines. */
        gic_eoi(id);
        c->irqs_taken++;
        c->events++;
    }
}
