/* psci.h: calls into the PSCI firmware interface of QEMU's virt board,
 * implemented in boot/virt/start.S with HVC, the conduit the board uses
 * when it has no EL3 firmware. */
#ifndef LINKS1_BOOT_VIRT_PSCI_H
#define LINKS1_BOOT_VIRT_PSCI_H

#include <stdint.h>

/* PSCI 0.2 function ids (SMC32 convention), called with HVC. */
#define PSCI_CPU_ON 0x84000003u
#define PSCI_AFFINITY_INFO 0x84000004u
#define PSCI_SYSTEM_OFF 0x84000008u
#define PSCI_RET_SUCCESS 0
#define PSCI_RET_INVALID_PARAMS (-2)
#define PSCI_RET_ALREADY_ON (-4)

/* Returns the PSCI status (PSCI_RET_*) or the function's result. */
int psci_call(uint32_t fn, uint32_t a1, uint32_t a2, uint32_t a3);

#endif
