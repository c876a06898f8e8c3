/* fwcfg_format.c: fw_cfg and ramfb byte formats (see fwcfg_format.h). */
#include "drivers/virt/fwcfg_format.h"

#include <string.h>

#include "drivers/framemem/fm_param.h"

uint32_t fwcfg_be32(const uint8_t *p)
{
    return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
}

static uint16_t fwcfg_be16(const uint8_t *p)
{
    return (uint16_t)((p[0] << 8) | p[1]);
}

void fwcfg_put_be32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
}

void fwcfg_put_be64(uint8_t *p, uint64_t v)
{
    fwcfg_put_be32(p, (uint32_t)(v >> 32));
    fwcfg_put_be32(p + 4, (uint32_t)v);
}

uint32_t fwcfg_dma_control(uint16_t select, uint32_t flags)
{
    return ((uint32_t)select << 16) | flags;
}

void fwcfg_dma_encode(uint8_t out[FWCFG_DMA_RECORD_SIZE], uint32_t control, uint32_t length,
                      uint64_t addr)
{
    fwcfg_put_be32(out, control);
    fwcfg_put_be32(out + 4, length);
    fwcfg_put_be64(out + 8, addr);
}

void fwcfg_file_decode(const uint8_t entry[FWCFG_DIR_ENTRY_SIZE], struct fwcfg_file *out)
{
    out->size = fwcfg_be32(entry);
    out->select = fwcfg_be16(entry + 4);
    memcpy(out->name, entry + 8, FWCFG_FILE_NAME_SIZE);
    /* A name filling all 56 bytes has no NUL: cut it rather than let a
     * compare run past the entry. */
    out->name[FWCFG_FILE_NAME_SIZE - 1] = '\0';
}

int fwcfg_dir_search(int (*read)(void *ctx, void *buf, uint32_t len), void *ctx,
                     const char *name, struct fwcfg_file *out)
{
    uint8_t buf[FWCFG_DIR_ENTRY_SIZE];
    if (read(ctx, buf, 4) != 0)
        return FWCFG_ERR_READ;
    uint32_t count = fwcfg_be32(buf);
    if (count > FWCFG_MAX_FILES)
        return FWCFG_ERR_DIR;
    for (uint32_t i = 0; i < count; i++) {
        if (read(ctx, buf, FWCFG_DIR_ENTRY_SIZE) != 0)
            return FWCFG_ERR_READ;
        fwcfg_file_decode(buf, out);
        if (strcmp(out->name, name) == 0)
            return FWCFG_OK;
    }
    memset(out, 0, sizeof *out);
    return FWCFG_ERR_NOT_FOUND;
}

void ramfb_config_encode(uint8_t out[RAMFB_CONFIG_SIZE], uint64_t addr, uint32_t fourcc,
                         uint32_t width, uint32_t height, uint32_t stride)
{
    fwcfg_put_be64(out, addr);
    fwcfg_put_be32(out + 8, fourcc);
    fwcfg_put_be32(out + 12, 0); /* flags: none defined */
    fwcfg_put_be32(out + 16, width);
    fwcfg_put_be32(out + 20, height);
    fwcfg_put_be32(out + 24, stride);
}

const char *fwcfg_strerror(int status)
{
    switch (status) {
    case FWCFG_OK:
        return "ok";
    case FWCFG_ERR_ABSENT:
        return "no fw_cfg device with DMA at the board's address";
    case FWCFG_ERR_NOT_FOUND:
        return "no such fw_cfg file (for etc/ramfb: QEMU started without -device ramfb)";
    case FWCFG_ERR_DIR:
        return "fw_cfg directory claims more than FWCFG_MAX_FILES files";
    case FWCFG_ERR_READ:
        return "fw_cfg directory read failed";
    case FWCFG_ERR_DMA:
        return "fw_cfg DMA transfer reported an error";
    case FWCFG_ERR_SIZE:
        return "fw_cfg file has an unexpected size";
    default:
        return "unknown fw_cfg error";
    }
}
