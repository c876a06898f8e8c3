/* board_map.h: addresses of the board that the host tools must know too.
 * Plain #defines only: boot/start.S includes this through kernel/memlayout.h.
 */
#ifndef LINKS1_PROTO_BOARD_MAP_H
#define LINKS1_PROTO_BOARD_MAP_H

/* The 1 GiB block at this virtual address is left unmapped on purpose: any
 * access faults.  CMD_FAULT_INJECT's data and prefetch aborts touch it, so a
 * fault report from them names this address. */
#define UNMAPPED_VIRT 0x80000000u

#endif
