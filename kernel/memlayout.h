/* memlayout.h: the regions every machine's linker script carves
 * (linker/<machine>-memory.ld), under the same names on every machine:
 * per-core stacks, the serial lines' rings, the IMSU blocks and the unit
 * computers' private memory.  What else a machine has (its devices, its
 * address map) is its own: drivers/<machine>/ and boot/<machine>/.
 *
 * The machine's own map and why it is laid out so: drivers/virt/virt_map.h.
 */
#ifndef LINKS1_KERNEL_MEMLAYOUT_H
#define LINKS1_KERNEL_MEMLAYOUT_H

/* UNMAPPED_VIRT and BOARD_RAM_BASE, which the host tools know too. */
#include "proto/board_map.h"

/* RAM: where the board's memory starts (proto/board_map.h). */
#define RAM_BASE BOARD_RAM_BASE

#ifndef __ASSEMBLER__
#include <stdint.h>

/* Symbols of linker/virt-memory.ld: regions (start/end addresses) and
 * sizes (absolute symbols: use the address as the value). */
extern char __stacks_start[], __stacks_end[];
extern char __lines_start[], __lines_end[];
extern char __imsu_pair_start[], __imsu_bcast_start[], __imsu_end[];
extern char __dm_private_start[], __rc_private_start[];
extern char __nc_pool_start[], __nc_pool_end[];
extern char LINKS1_MAX_CORES[], LINKS1_CORE_STACK[], LINKS1_LINE_RING[];
extern char LINKS1_IMSU_PAIR_BLOCK[], LINKS1_IMSU_BCAST_BLOCK[];
extern char LINKS1_DM_PRIVATE[], LINKS1_RC_PRIVATE[], LINKS1_NC_PRIVATE_MIN[];

/* An absolute linker symbol's value. */
#define LINKER_VALUE(sym) ((uintptr_t)(sym))
#endif

#endif
