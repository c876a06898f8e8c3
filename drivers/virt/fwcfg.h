/* fwcfg.h: QEMU's fw_cfg device on the virt board, through its DMA
 * interface (byte formats in fwcfg_format.h).
 *
 * Registers (MMIO, at FWCFG_BASE): data at +0 (reads the selected item byte
 * by byte), selector at +8 (16-bit, big-endian), DMA address at +16 (64-bit
 * big-endian: the high word first, writing the low word at +20 starts the
 * transfer).  QEMU performs a DMA transfer before the starting write
 * returns; the driver still waits for the record's control word to read 0
 * (done) or FWCFG_DMA_ERROR, as the spec asks, up to FWCFG_DMA_POLLS reads.
 *
 * Not thread-safe: one core configures the device (the one that owns the
 * frame memory), before or between frames. */
#ifndef LINKS1_DRIVERS_VIRT_FWCFG_H
#define LINKS1_DRIVERS_VIRT_FWCFG_H

#include <stdint.h>

#include "drivers/virt/fwcfg_format.h"

/* The virt board's fw_cfg (QEMU hw/arm/virt.c VIRT_FW_CFG; also in the
 * device tree QEMU passes, node fw-cfg@9020000). */
#define FWCFG_BASE 0x09020000u
#define FWCFG_DATA(base) ((base) + 0x0u)
#define FWCFG_SELECTOR(base) ((base) + 0x8u)
#define FWCFG_DMA_ADDR_HI(base) ((base) + 0x10u)
#define FWCFG_DMA_ADDR_LO(base) ((base) + 0x14u)
/* Reads of a DMA record's control word before giving up. */
#define FWCFG_DMA_POLLS 1000000u

/* FWCFG_OK if the device answers with its signature and offers DMA, else
 * FWCFG_ERR_ABSENT. */
int fwcfg_probe(void);
/* Looks file name up in the device's file directory. */
int fwcfg_find(const char *name, struct fwcfg_file *out);
/* Writes len bytes of data to the item select (a writable file). */
int fwcfg_write(uint16_t select, const void *data, uint32_t len);

#endif
