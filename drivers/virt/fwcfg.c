/* fwcfg.c: the fw_cfg device side (see fwcfg.h). */
#include "drivers/virt/fwcfg.h"

#include <string.h>

#include "kernel/arch.h"

static void fwcfg_select(uint16_t select)
{
    /* The MMIO selector is big-endian; the core is little-endian. */
    *(volatile uint16_t *)FWCFG_SELECTOR(FWCFG_BASE) = __builtin_bswap16(select);
}

static void fwcfg_read_data(void *buf, uint32_t len)
{
    uint8_t *p = buf;
    for (uint32_t i = 0; i < len; i++)
        p[i] = *(volatile uint8_t *)FWCFG_DATA(FWCFG_BASE);
}

int fwcfg_probe(void)
{
    uint8_t sig[4];
    uint8_t id[4];
    fwcfg_select(FWCFG_SEL_SIGNATURE);
    fwcfg_read_data(sig, sizeof sig);
    if (memcmp(sig, FWCFG_SIGNATURE, sizeof sig) != 0)
        return FWCFG_ERR_ABSENT;
    fwcfg_select(FWCFG_SEL_ID);
    fwcfg_read_data(id, sizeof id);
    uint32_t features = (uint32_t)id[0] | ((uint32_t)id[1] << 8) | ((uint32_t)id[2] << 16) |
                        ((uint32_t)id[3] << 24); /* the ID item is little-endian */
    return (features & FWCFG_ID_DMA) ? FWCFG_OK : FWCFG_ERR_ABSENT;
}

/* One DMA transfer: control (selector and flags), len bytes at buf. */
static int fwcfg_dma(uint32_t control, void *buf, uint32_t len)
{
    static uint8_t record[FWCFG_DMA_RECORD_SIZE] __attribute__((aligned(16)));
    fwcfg_dma_encode(record, control, len, (uint64_t)(uintptr_t)buf);
    /* The record and the data to write must be in memory before the device
     * reads them (RAM is identity mapped: virtual = physical). */
    arch_dsb();
    uint64_t addr = (uint64_t)(uintptr_t)record;
    mmio_write32(FWCFG_DMA_ADDR_HI(FWCFG_BASE), __builtin_bswap32((uint32_t)(addr >> 32)));
    mmio_write32(FWCFG_DMA_ADDR_LO(FWCFG_BASE), __builtin_bswap32((uint32_t)addr));
    for (uint32_t i = 0; i < FWCFG_DMA_POLLS; i++) {
        /* Volatile: the device, not this code, changes the word. */
        uint32_t c = __builtin_bswap32(*(volatile uint32_t *)record);
        arch_dmb(); /* the device's data before what we read after */
        if (c & FWCFG_DMA_ERROR)
            return FWCFG_ERR_DMA;
        if (c == 0)
            return FWCFG_OK;
    }
    return FWCFG_ERR_DMA;
}

/* Reader for fwcfg_dir_search: the first read selects the directory, the
 * next ones go on where the previous stopped. */
struct fwcfg_dir_reader {
    int selected;
};

static int fwcfg_dir_read(void *ctx, void *buf, uint32_t len)
{
    struct fwcfg_dir_reader *r = ctx;
    uint32_t control = r->selected
                           ? FWCFG_DMA_READ
                           : fwcfg_dma_control(FWCFG_SEL_FILE_DIR,
                                               FWCFG_DMA_SELECT | FWCFG_DMA_READ);
    r->selected = 1;
    return fwcfg_dma(control, buf, len) == FWCFG_OK ? 0 : -1;
}

int fwcfg_find(const char *name, struct fwcfg_file *out)
{
    int rc = fwcfg_probe();
    if (rc != FWCFG_OK)
        return rc;
    struct fwcfg_dir_reader r = {0};
    return fwcfg_dir_search(fwcfg_dir_read, &r, name, out);
}

int fwcfg_write(uint16_t select, const void *data, uint32_t len)
{
    /* The device only reads the buffer; the cast drops const for the
     * shared transfer routine. */
    return fwcfg_dma(fwcfg_dma_control(select, FWCFG_DMA_SELECT | FWCFG_DMA_WRITE),
                     (void *)(uintptr_t)data, len);
}
