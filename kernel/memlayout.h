/* memlayout.h: the address map of QEMU's virt board (QEMU 7.2,
 * -M virt,gic-version=3 -cpu cortex-a15 -m 1024) as links1 uses it.
 *
 *   physical                          virtual (LPAE identity map + window)
 *   0x00000000 +-------------------+  0x00000000  1 GiB block, Device-nGnRE
 *              | flash (unused)    |
 *   0x08000000 | GICv3 distributor |
 *   0x080A0000 | redistributors    |  123 frames of 128 KiB: cores 0..122
 *   0x09000000 | PL011 UART (host) |  SPI 1 = INTID 33
 *   0x40000000 +-------------------+  0x40000000  1 GiB block, Normal WB,
 *              | DTB from QEMU     |               inner shareable
 *   0x40100000 | IMAGE: code, data, bss (linker/sections.ld)
 *   0x41000000 | STACKS: per core SVC/IRQ/ABT/UND stacks
 *   0x41400000 | LINES: inter-unit serial line rings
 *   0x41800000 | IMSU: DM<->RC block pair, RC->NC broadcast block
 *   0x62800000 | PRIVATE: DM, RC, then the NC pool shared out per NC
 *   0x80000000 +-------------------+  (end of 1 GiB RAM)
 *                                     0x80000000  1 GiB unmapped: any access
 *                                                 faults (fault tests use it)
 *   0x40_0000_0000 second redistributor region (cores 123..)
 *                                  -> 0xC0000000  1 GiB block, Device-nGnRE
 *
 * Why an MMU with LPAE: QEMU's low redistributor region holds only 123
 * redistributors; for more cores it adds VIRT_HIGH_GIC_REDIST2, placed after
 * the legacy RAM limit at 256 GiB (0x40_0000_0000, 64 MiB, up to 512
 * frames).  A 32-bit core reaches a 40-bit physical address only through
 * LPAE long descriptors, so every core runs with TTBCR.EAE=1 and a
 * four-entry first-level table of 1 GiB blocks, one of them the window onto
 * the high redistributors.  Turning the MMU and caches on also gives RAM the
 * Normal, shareable type that LDREX/STREX and barriers need on real
 * hardware.  Each core finds its own redistributor by matching
 * GICR_TYPER.Affinity against its MPIDR, so the window's contents are
 * checked at boot rather than trusted.
 *
 * The carve sizes live in linker/virt-memory.ld; C reaches them through the
 * symbols declared at the end of this file.
 */
#ifndef LINKS1_KERNEL_MEMLAYOUT_H
#define LINKS1_KERNEL_MEMLAYOUT_H

/* UNMAPPED_VIRT and BOARD_RAM_BASE, which the host tools know too. */
#include "proto/board_map.h"

/* Devices (physical = virtual below 1 GiB). */
#define UART0_BASE 0x09000000u
#define UART0_INTID 33u /* SPI 1 */

#define GICD_BASE 0x08000000u
#define GICR_LOW_BASE 0x080A0000u
#define GICR_LOW_SIZE 0x00F60000u /* 123 frames */
#define GICR_FRAME_SIZE 0x20000u  /* RD_base + SGI_base, 64 KiB each */

/* The high redistributor region: physical address, and the virtual window
 * the MMU maps it to. */
#define GICR_HIGH_PHYS 0x4000000000ull
#define GICR_HIGH_SIZE 0x04000000u /* 64 MiB = 512 frames */
#define GICR_HIGH_VIRT 0xC0000000u

/* RAM and the first-level LPAE blocks. */
#define RAM_BASE BOARD_RAM_BASE /* proto/board_map.h */
/* QEMU's device tree sits at the start of RAM; linker/virt-memory.ld keeps
 * this much free for it. */
#define DTB_BASE RAM_BASE
#define DTB_MAX_SIZE 0x00100000u
#define MMU_BLOCK_SIZE 0x40000000u  /* 1 GiB first-level block */

/* Generic timer: non-secure physical timer PPI. */
#define TIMER_INTID 30u

/* PSCI 0.2 function ids (SMC32 convention), called with HVC. */
#define PSCI_CPU_ON 0x84000003u
#define PSCI_AFFINITY_INFO 0x84000004u
#define PSCI_SYSTEM_OFF 0x84000008u
#define PSCI_RET_SUCCESS 0
#define PSCI_RET_INVALID_PARAMS (-2)
#define PSCI_RET_ALREADY_ON (-4)

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
