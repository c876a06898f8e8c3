/* virt_map.h: the address map of QEMU's virt board (QEMU 7.2,
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
 *   0x64000000 | PRIVATE: DM, RC, then the NC pool shared out per NC
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
 * symbols of kernel/memlayout.h.  Plain #defines only: boot/virt/start.S
 * includes this file.
 */
#ifndef LINKS1_DRIVERS_VIRT_VIRT_MAP_H
#define LINKS1_DRIVERS_VIRT_VIRT_MAP_H

#include "kernel/memlayout.h"

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

/* The first-level LPAE blocks. */
/* QEMU's device tree sits at the start of RAM; linker/virt-memory.ld keeps
 * this much free for it. */
#define DTB_BASE RAM_BASE
#define DTB_MAX_SIZE 0x00100000u
#define MMU_BLOCK_SIZE 0x40000000u  /* 1 GiB first-level block */

/* Generic timer: non-secure physical timer PPI. */
#define TIMER_INTID 30u

#endif
