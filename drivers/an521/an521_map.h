/* an521_map.h: the devices of an an521 board (QEMU 7.2's mps2-an521: an
 * SSE-200 with two Cortex-M33 cores) that links1 uses, at their Secure
 * addresses: the firmware runs in the Secure world, and the peripheral
 * protection controllers let only Secure accesses through until told
 * otherwise.  The memory map is linker/an521-memory.ld's. */
#ifndef LINKS1_DRIVERS_AN521_AN521_MAP_H
#define LINKS1_DRIVERS_AN521_AN521_MAP_H

#include "kernel/memlayout.h"

/* SSE-200 CPU identity block: CPUID reads 0 on core 0, 1 on core 1. */
#define AN521_CPUID 0x5001F000u
/* SSE-200 system control: CPUWAIT holds core 1 at reset until cleared;
 * INITSVTOR1 is where it finds its vector table (0x10000000 at reset). */
#define AN521_SYSCTL 0x50021000u
#define AN521_SYSCTL_INITSVTOR1 (AN521_SYSCTL + 0x114u)
#define AN521_SYSCTL_CPUWAIT (AN521_SYSCTL + 0x118u)

/* SSE-200 message handling unit 0: each core's interrupt is raised while
 * a bit of its register is set (by the other core) and NVIC interrupt 6
 * on that core. */
#define AN521_MHU0 0x50003000u
#define AN521_MHU_CPU_STAT(k) (AN521_MHU0 + 0x10u * (k))
#define AN521_MHU_CPU_SET(k) (AN521_MHU0 + 0x10u * (k) + 0x4u)
#define AN521_MHU_CPU_CLR(k) (AN521_MHU0 + 0x10u * (k) + 0x8u)
#define AN521_MHU_IRQN 6u

/* CMSDK APB timer 0 (SSE-200, clocked by the 20 MHz system clock): the
 * board's counter. */
#define AN521_TIMER0 0x50000000u
#define AN521_TIMER_HZ 20000000u

/* CMSDK APB UART 0 (the FPGA's, behind a protection controller): the host
 * link on board 0.  Its receive interrupt is expansion interrupt 0, which
 * the SSE-200 gives each core as NVIC interrupt 32. */
#define AN521_UART0 0x50200000u
#define AN521_UART0_RX_IRQN 32u

/* Interrupt ids of kernel/irq.h: the exception number (IPSR), so SysTick
 * is 15 and NVIC interrupt n is 16 + n. */
#define AN521_INTID_SYSTICK 15u
#define AN521_INTID_IRQ(n) (16u + (n))
/* External interrupts the vector table covers. */
#define AN521_VECTOR_IRQS 48u

/* The core's own SysTick wakes it this often: no interrupt crosses from
 * one board's process to another's, so a unit waiting on a unit of another
 * board looks again at each tick (the two cores of one board ring each
 * other through the MHU). */
#define AN521_TICK_US 1000u

#endif
