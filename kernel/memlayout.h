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

#include "proto/board_map_an521.h"

/* RAM_BASE: where the memory the host maps too starts (a LINK_BULK offset
 * counts from it); MACHINE_UNMAPPED: an address where any access faults
 * (the fault tests); MACHINE_IMSU_BLOCK_NAME: the definition that sizes an
 * IMSU block, named when a scene does not fit one. */
#if defined(LINKS1_MACHINE_AN521)
#define RAM_BASE AN521_SHARED_BASE
#define MACHINE_UNMAPPED AN521_UNMAPPED
#define MACHINE_IMSU_BLOCK_NAME AN521_IMSU_BLOCK_NAME
#else
#define RAM_BASE BOARD_RAM_BASE
#define MACHINE_UNMAPPED UNMAPPED_VIRT
#define MACHINE_IMSU_BLOCK_NAME BOARD_IMSU_BLOCK_NAME
#endif

/* What unit computers share with units of other boards: the an521 boards
 * keep it in the shared file (linker/an521-memory.ld); on the virt board,
 * where all memory is shared, it is ordinary zeroed data.  Zero at start,
 * set up at run time: it is never loaded. */
#define UNIT_SHARED __attribute__((section(".unit_shared")))

#ifndef __ASSEMBLER__
#include <stdint.h>

/* Symbols of linker/<machine>-memory.ld: regions (start/end addresses) and
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
