/* ktime.c: time in milliseconds, from the machine's counter (ktime.h). */
#include "kernel/ktime.h"

uint64_t ktime_ms_to_ticks(uint32_t ms)
{
    uint32_t frq = ktime_freq();
    /* A whole number of ticks per millisecond (QEMU's 62.5 MHz) needs no
     * 64-bit division, which the CPU does in a long library routine. */
    if (frq % 1000u == 0)
        return (uint64_t)(frq / 1000u) * ms;
    return (uint64_t)frq * ms / 1000u;
}

uint32_t ktime_ticks_to_ms(uint64_t ticks)
{
    return (uint32_t)(ticks * 1000u / ktime_freq());
}

uint64_t ktime_deadline_ms(uint32_t ms)
{
    return ktime_now() + ktime_ms_to_ticks(ms);
}

int ktime_passed(uint64_t deadline)
{
    return deadline != 0 && ktime_now() >= deadline;
}
