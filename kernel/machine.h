/* machine.h: what the kernel, the drivers and the roles ask of the machine
 * they run on, and nothing else.  Each machine implements it once, in its
 * own folders (boot/<machine>/ and drivers/<machine>/): on the virt board
 * the GICv3 and PSCI (drivers/virt/, boot/virt/), on the an521 boards the
 * NVIC, the MHU and the SSE-200's registers (drivers/an521/, boot/an521/;
 * docs/machines.md).  The kernel names no device: it calls these, and the
 * machine's drivers answer.
 *
 * Wake-ups.  A unit computer that waits sleeps (task_wait, WFI) until an
 * interrupt.  Another unit that has put something where it will look (a
 * line ring, an IMSU block, the data collector's FIFO) rings its doorbell;
 * where no interrupt can reach the sleeper (another an521 board), its own
 * tick wakes it to look again.
 */
#ifndef LINKS1_KERNEL_MACHINE_H
#define LINKS1_KERNEL_MACHINE_H

#include <stddef.h>
#include <stdint.h>

/* This core's number on the whole machine (0 = the DM, 1 = the RC, then
 * the NCs), read from the hardware: what the boot code uses before any
 * per-core state exists, and a fault with none. */
uint32_t machine_core_id(void);
/* The hardware's own name of this core (MPIDR on the virt board), which
 * the core's LINK_HELLO reports. */
uint32_t machine_core_hwid(void);

/* Wakes the tasks of core (its event counter moves).  The memory writes
 * the doorbell announces are visible to core before it can wake. */
void machine_doorbell(uint32_t core);
/* Wakes core if it sleeps for a spinlock's turn (kernel/spinlock.c); not
 * an event for its tasks. */
void machine_lock_turn(uint32_t core);
/* This core saw its turn: a lock-turn wake-up still pending has nothing
 * more to say. */
void machine_lock_turn_seen(void);

/* The private memory of unit computer core on a machine of ncores cores:
 * where it starts and how big it is (kernel/kmem.c hands it out). */
void machine_private_memory(uint32_t core, uint32_t ncores, uint8_t **base, size_t *size);

/* Stops the whole machine (the host's CMD_POWER_OFF).  Returns only if the
 * machine cannot. */
void machine_power_off(void);

#endif
