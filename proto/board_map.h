/* board_map.h: addresses of the board that the host tools must know too.
 * Plain #defines only: boot/start.S includes this through kernel/memlayout.h.
 */
#ifndef LINKS1_PROTO_BOARD_MAP_H
#define LINKS1_PROTO_BOARD_MAP_H

/* The 1 GiB block at this virtual address is left unmapped on purpose: any
 * access faults.  CMD_FAULT_INJECT's data and prefetch aborts touch it, so a
 * fault report from them names this address. */
#define UNMAPPED_VIRT 0x80000000u

/* The board's RAM starts here (physical = virtual).  The host tool backs
 * the whole RAM with a shared file (QEMU's memory-backend-file, share=on)
 * and maps it too: byte k of that file is guest address BOARD_RAM_BASE + k,
 * which is what a LINK_BULK offset (proto/hostlink.h) counts from. */
#define BOARD_RAM_BASE 0x40000000u

#endif
