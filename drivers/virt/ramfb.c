/* ramfb.c: the frame memory on QEMU's ramfb display (see ramfb.h). */
#include "drivers/virt/ramfb.h"

#include "drivers/framemem/fm_view.h"
#include "drivers/virt/fwcfg.h"

int ramfb_show(const struct fm *fm)
{
    struct fwcfg_file f;
    int rc = fwcfg_find(RAMFB_FILE_NAME, &f);
    if (rc != FWCFG_OK)
        return rc;
    if (f.size != RAMFB_CONFIG_SIZE)
        return FWCFG_ERR_SIZE; /* QEMU ignores a config of any other length */
    /* Static: the device reads it during the transfer only, but keep it off
     * the stack of whichever task calls. */
    static uint8_t cfg[RAMFB_CONFIG_SIZE] __attribute__((aligned(8)));
    ramfb_config_encode(cfg, (uint64_t)(uintptr_t)fm->pixels, RAMFB_FOURCC_XR24, fm->width,
                        fm->height, fm_stride(fm));
    return fwcfg_write(f.select, cfg, RAMFB_CONFIG_SIZE);
}

int fm_view_show(const struct fm *fm, const char **why)
{
    int r = ramfb_show(fm);
    if (r == FWCFG_OK)
        return FM_VIEW_SHOWN;
    if (r == FWCFG_ERR_NOT_FOUND)
        return FM_VIEW_ABSENT;
    *why = fwcfg_strerror(r);
    return FM_VIEW_FAILED;
}
