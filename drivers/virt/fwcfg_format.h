/* fwcfg_format.h: the byte formats of QEMU's fw_cfg device and of the
 * ramfb configuration it carries (QEMU docs/specs/fw_cfg.rst, ramfb).
 *
 * Everything fw_cfg exchanges by DMA is big-endian whatever the guest:
 *   DMA access record (16 bytes): be32 control, be32 length, be64 address.
 *     control = (selector << 16) | FWCFG_DMA_* flags; the device clears it
 *     to 0 when done, or leaves FWCFG_DMA_ERROR set.
 *   File directory (selector FWCFG_SEL_FILE_DIR): be32 count, then count
 *     entries of 64 bytes: be32 size, be16 select, be16 reserved,
 *     char name[56] (NUL-terminated).
 *   ramfb configuration (file "etc/ramfb", exactly 28 bytes): be64 address,
 *     be32 fourcc, be32 flags, be32 width, be32 height, be32 stride.
 *
 * No hardware access: the host tests build this file; fwcfg.c does the
 * device side. */
#ifndef LINKS1_DRIVERS_VIRT_FWCFG_FORMAT_H
#define LINKS1_DRIVERS_VIRT_FWCFG_FORMAT_H

#include <stddef.h>
#include <stdint.h>

/* Well-known selectors. */
#define FWCFG_SEL_SIGNATURE 0x0000u /* reads "QEMU" */
#define FWCFG_SEL_ID 0x0001u        /* le32 feature bitmap */
#define FWCFG_SEL_FILE_DIR 0x0019u

#define FWCFG_SIGNATURE "QEMU"
#define FWCFG_ID_TRADITIONAL (1u << 0)
#define FWCFG_ID_DMA (1u << 1)

/* DMA control flags. */
#define FWCFG_DMA_ERROR 0x01u
#define FWCFG_DMA_READ 0x02u
#define FWCFG_DMA_SKIP 0x04u
#define FWCFG_DMA_SELECT 0x08u
#define FWCFG_DMA_WRITE 0x10u

#define FWCFG_DMA_RECORD_SIZE 16u
#define FWCFG_DIR_ENTRY_SIZE 64u
#define FWCFG_FILE_NAME_SIZE 56u

#define RAMFB_FILE_NAME "etc/ramfb"
#define RAMFB_CONFIG_SIZE 28u
/* DRM fourcc 'X','R','2','4': 32-bit pixels 0x00RRGGBB in memory order of
 * a little-endian word (the frame memory's own format, fm.h). */
#define RAMFB_FOURCC_XR24 0x34325258u

enum fwcfg_status {
    FWCFG_OK = 0,
    FWCFG_ERR_ABSENT = -1,   /* no fw_cfg, or no DMA interface */
    FWCFG_ERR_NOT_FOUND = -2,/* no such file in the directory */
    FWCFG_ERR_DIR = -3,      /* directory count above FWCFG_MAX_FILES */
    FWCFG_ERR_READ = -4,     /* a read of the directory failed */
    FWCFG_ERR_DMA = -5,      /* the device reported a DMA error */
    FWCFG_ERR_SIZE = -6,     /* the file is not the size expected */
};

struct fwcfg_file {
    uint32_t size;   /* bytes */
    uint16_t select; /* selector to read/write it by */
    char name[FWCFG_FILE_NAME_SIZE]; /* always NUL-terminated here */
};

/* The DMA access record for a transfer of length bytes at guest address
 * addr; control from fwcfg_dma_control. */
uint32_t fwcfg_dma_control(uint16_t select, uint32_t flags);
void fwcfg_dma_encode(uint8_t out[FWCFG_DMA_RECORD_SIZE], uint32_t control, uint32_t length,
                      uint64_t addr);

/* One 64-byte directory entry. */
void fwcfg_file_decode(const uint8_t entry[FWCFG_DIR_ENTRY_SIZE], struct fwcfg_file *out);

/* Walks the file directory, read front to back through read(ctx, buf, len)
 * (0 on success), and fills *out with the entry called name.  The device
 * reader on the board, a memory reader in the tests. */
int fwcfg_dir_search(int (*read)(void *ctx, void *buf, uint32_t len), void *ctx,
                     const char *name, struct fwcfg_file *out);

/* The 28-byte ramfb configuration. */
void ramfb_config_encode(uint8_t out[RAMFB_CONFIG_SIZE], uint64_t addr, uint32_t fourcc,
                         uint32_t width, uint32_t height, uint32_t stride);

/* Big-endian field access. */
uint32_t fwcfg_be32(const uint8_t *p);
void fwcfg_put_be32(uint8_t *p, uint32_t v);
void fwcfg_put_be64(uint8_t *p, uint64_t v);

const char *fwcfg_strerror(int status);

#endif
