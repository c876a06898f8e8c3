/* timer.c: the an521 board's clock (kernel/ktime.h).  The count is the
 * SSE-200's timer 0, a 32-bit down-counter at 20 MHz free running from
 * core 0's boot, made 64 bits per core by counting its wraps (it wraps
 * every 214 s; each core reads it at every tick).  Each core's SysTick
 * wakes it every AN521_TICK_US: the deadlines of task_wait are looked at
 * then. */
#include "kernel/ktime.h"

#include <stddef.h>

#include "drivers/an521/an521_board.h"
#include "drivers/an521/an521_map.h"
#include "kernel/arch.h"
#include "kernel/irq.h"

#define TIMER_CTRL(b) ((b) + 0x0u)
#define TIMER_VALUE(b) ((b) + 0x4u)
#define TIMER_RELOAD(b) ((b) + 0x8u)
#define TIMER_CTRL_EN (1u << 0)

#define SYST_CSR 0xE000E010u
#define SYST_RVR 0xE000E014u
#define SYST_CVR 0xE000E018u
#define SYST_CSR_ENABLE (1u << 0)
#define SYST_CSR_TICKINT (1u << 1)
#define SYST_CSR_CLKSOURCE (1u << 2) /* the processor's clock */

/* Per core of this board: the last 32-bit count read, the wraps so far. */
static uint32_t timer_last[AN521_CORES_PER_BOARD];
static uint32_t timer_high[AN521_CORES_PER_BOARD];

uint64_t ktime_now(void)
{
    int masked = arch_irqs_masked();
    arch_irq_disable();
    uint32_t k = an521_local_core();
    uint32_t up = ~mmio_read32(TIMER_VALUE(AN521_TIMER0)); /* counts up */
    if (up < timer_last[k])
        timer_high[k]++;
    timer_last[k] = up;
    uint64_t t = ((uint64_t)timer_high[k] << 32) | up;
    if (!masked)
        arch_irq_enable();
    return t;
}

uint32_t ktime_freq(void)
{
    return AN521_TIMER_HZ;
}

void ktime_arm(uint64_t deadline)
{
    (void)deadline; /* the tick looks at every deadline */
}

/* The tick: reading the count keeps its wraps counted; the interrupt
 * itself is the event that wakes the core's tasks. */
static void timer_tick(void *arg)
{
    (void)arg;
    (void)ktime_now();
}

void ktime_init(void)
{
    mmio_write32(TIMER_CTRL(AN521_TIMER0), 0);
    mmio_write32(TIMER_RELOAD(AN521_TIMER0), 0xFFFFFFFFu);
    mmio_write32(TIMER_VALUE(AN521_TIMER0), 0xFFFFFFFFu);
    mmio_write32(TIMER_CTRL(AN521_TIMER0), TIMER_CTRL_EN);
    irq_register(AN521_INTID_SYSTICK, timer_tick, NULL);
}

void an521_tick_start(void)
{
    mmio_write32(SYST_RVR, AN521_TIMER_HZ / 1000000u * AN521_TICK_US - 1u);
    mmio_write32(SYST_CVR, 0);
    mmio_write32(SYST_CSR, SYST_CSR_ENABLE | SYST_CSR_TICKINT | SYST_CSR_CLKSOURCE);
}
