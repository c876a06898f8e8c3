/* ktime.c: the generic timer (non-secure physical timer, PPI 30). */
#include "kernel/ktime.h"

#include <stddef.h>

#include "kernel/arch.h"
#include "kernel/irq.h"
#include "kernel/memlayout.h"

uint64_t ktime_now(void)
{
    return arch_read_cntpct();
}

uint64_t ktime_ms_to_ticks(uint32_t ms)
{
    uint32_t frq = arch_read_cntfrq();
    /* A whole number of ticks per millisecond (QEMU's 62.5 MHz) needs no
     * 64-bit division, which the CPU does in a long library routine. */
    if (frq % 1000u == 0)
        return (uint64_t)(frq / 1000u) * ms;
    return (uint64_t)frq * ms / 1000u;
}

uint32_t ktime_ticks_to_ms(uint64_t ticks)
{
    return (uint32_t)(ticks * 1000u / arch_read_cntfrq());
}

uint64_t ktime_deadline_ms(uint32_t ms)
{
    return ktime_now() + ktime_ms_to_ticks(ms);
}

int ktime_passed(uint64_t deadline)
{
    return deadline != 0 && ktime_now() >= deadline;
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
