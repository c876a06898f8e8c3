/* an521_nvic.h: this core's NVIC and fault handling on an an521 board. */
#ifndef LINKS1_DRIVERS_AN521_AN521_NVIC_H
#define LINKS1_DRIVERS_AN521_AN521_NVIC_H

#include <stdint.h>

/* Every exception of the vector table but the faults: the kernel's
 * irq_handle with the exception number. */
void an521_irq_entry(void);
/* Lets NVIC interrupt irqn reach this core. */
void an521_nvic_enable(uint32_t irqn);
/* This core's doorbell from the other core of its board (MHU0) on. */
void an521_mhu_start(void);
/* MemManage, BusFault and UsageFault reported as such on this core. */
void an521_faults_enable(void);

#endif
