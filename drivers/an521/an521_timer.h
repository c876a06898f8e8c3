/* an521_timer.h: this core's tick on an an521 board (drivers/an521/timer.c). */
#ifndef LINKS1_DRIVERS_AN521_AN521_TIMER_H
#define LINKS1_DRIVERS_AN521_AN521_TIMER_H

/* Starts this core's SysTick: an interrupt every AN521_TICK_US. */
void an521_tick_start(void);

#endif
