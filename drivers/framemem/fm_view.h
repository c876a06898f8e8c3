/* fm_view.h: the frame memory shown live on the machine's display, where
 * it has one (on the virt board QEMU's ramfb: drivers/virt/ramfb.c). */
#ifndef LINKS1_DRIVERS_FRAMEMEM_FM_VIEW_H
#define LINKS1_DRIVERS_FRAMEMEM_FM_VIEW_H

#include "drivers/framemem/fm.h"

enum fm_view_status {
    FM_VIEW_SHOWN = 0,  /* the display now shows fm as it is written */
    FM_VIEW_ABSENT = 1, /* the machine has no display (not an error) */
    FM_VIEW_FAILED = 2, /* the display refused; *why says how */
};

/* Points the display at fm; returns an fm_view_status. */
int fm_view_show(const struct fm *fm, const char **why);

#endif
