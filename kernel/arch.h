/* arch.h: the instructions and core registers the kernel uses, one inline
 * function each, for the CPU it is built for: the virt board's Cortex-A15
 * (ARMv7-A, kernel/arch_v7a.h) or the an521 boards' Cortex-M33 (ARMv8-M
 * Mainline, kernel/arch_v8m.h).  Both give the same functions. */
#ifndef LINKS1_KERNEL_ARCH_H
#define LINKS1_KERNEL_ARCH_H

#if defined(__ARM_ARCH_PROFILE) && __ARM_ARCH_PROFILE == 'M'
#include "kernel/arch_v8m.h"
#else
#include "kernel/arch_v7a.h"
#endif

#endif
