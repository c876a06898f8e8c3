/* ktime.h: time, and the per-core timer interrupt that wakes a sleeping
 * core at a deadline.  The counter and the timer are the machine's
 * (drivers/<machine>/timer_*.c: ktime_now, ktime_freq, ktime_arm,
 * ktime_init); the conversions are the kernel's (kernel/ktime.c). */
#ifndef LINKS1_KERNEL_KTIME_H
#define LINKS1_KERNEL_KTIME_H

#include <stdint.h>

/* Ticks of the system counter since reset (monotonic, same on every core). */
uint64_t ktime_now(void);
/* Ticks per second of that counter. */
uint32_t ktime_freq(void);
uint64_t ktime_ms_to_ticks(uint32_t ms);
uint32_t ktime_ticks_to_ms(uint64_t ticks);
/* now + ms, as a deadline for task_wait and friends. */
uint64_t ktime_deadline_ms(uint32_t ms);
/* 1 once deadline (non-zero) has passed. */
int ktime_passed(uint64_t deadline);
/* Makes this core's timer interrupt fire at deadline (0: no interrupt). */
void ktime_arm(uint64_t deadline);
/* Core 0, once: registers the timer interrupt's handler, which masks the
 * timer until the next ktime_arm. */
void ktime_init(void);

#endif
