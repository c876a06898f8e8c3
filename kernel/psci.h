/* psci.h: calls into the PSCI firmware interface of QEMU's virt board
 * (function ids in kernel/memlayout.h).  Implemented in boot/start.S with
 * HVC, the conduit the board uses when it has no EL3 firmware. */
#ifndef LINKS1_KERNEL_PSCI_H
#define LINKS1_KERNEL_PSCI_H

#include <stdint.h>

/* Returns the PSCI status (PSCI_RET_*) or the function's result. */
int psci_call(uint32_t fn, uint32_t a1, uint32_t a2, uint32_t a3);

#endif
