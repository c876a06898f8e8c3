/* timer_generic.c: the virt board's clock (kernel/ktime.h): the ARM
 * generic timer, its non-secure physical timer and PPI 30. */
#include "kernel/ktime.h"

#include <stddef.h>

#include "drivers/virt/virt_map.h"
#include "drivers/virt/virt_sysreg.h"
#include "kernel/irq.h"

uint64_t ktime_now(void)
{
    return arch_read_cntpct();
}

uint32_t ktime_freq(void)
{
    return arch_read_cntfrq();
}

void ktime_arm(uint64_t deadline)
{
    if (deadline == 0) {
        arch_write_cntp_ctl(0);
        return;
    }
    arch_write_cntp_cval(deadline);
    arch_write_cntp_ctl(CNTP_CTL_ENABLE);
}

/* The timer's interrupt. */
static void ktime_irq(void *arg)
{
    (void)arg;
    /* The timer's output stays asserted while CVAL <= count: mask it, or
     * the interrupt would fire again at once.  Whoever waits rearms it. */
    arch_write_cntp_ctl(CNTP_CTL_ENABLE | CNTP_CTL_IMASK);
}

void ktime_init(void)
{
    irq_register(TIMER_INTID, ktime_irq, NULL);
}
