/* irq.c: the handler table drivers fill in, and what every interrupt taken
 * does (see irq.h). */
#include "kernel/irq.h"

#include "kernel/cpu.h"
#include "kernel/panic.h"
#include "kernel/param.h"

struct irq_entry {
    irq_handler_fn fn; /* NULL: nothing to do but count the event */
    void *arg;
};

/* Written by core 0 before the other cores start; read-only after. */
static struct irq_entry irq_table[IRQ_MAX];

void irq_register(uint32_t intid, irq_handler_fn fn, void *arg)
{
    if (intid >= IRQ_MAX)
        panic("irq_register: interrupt %u is beyond the table's %u entries", (unsigned)intid,
              (unsigned)IRQ_MAX);
    if (irq_table[intid].fn)
        panic("irq_register: interrupt %u already has a handler", (unsigned)intid);
    irq_table[intid].arg = arg;
    irq_table[intid].fn = fn;
}

void irq_handle(uint32_t intid, int is_event)
{
    struct cpu *c = mycpu();
    if (intid < IRQ_MAX && irq_table[intid].fn)
        irq_table[intid].fn(irq_table[intid].arg);
    c->irqs_taken++;
    if (is_event)
        c->events++;
}
