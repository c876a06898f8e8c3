/* ramfb.h: shows the frame memory live in QEMU's display through
 * `-device ramfb`.
 *
 * ramfb scans out guest RAM: once told (through fw_cfg's "etc/ramfb" file)
 * where the frame memory is, its format (XR24 = the FM's 0x00RRGGBB
 * words), size and stride, every refresh of the display, and every monitor
 * `screendump`, shows the frame memory as it is at that moment.  Nothing is
 * copied: pixels appear as the data collector writes them. */
#ifndef LINKS1_DRIVERS_VIRT_RAMFB_H
#define LINKS1_DRIVERS_VIRT_RAMFB_H

#include "drivers/framemem/fm.h"
#include "drivers/virt/fwcfg_format.h" /* its status codes */

/* Points ramfb at fm.  FWCFG_OK; FWCFG_ERR_NOT_FOUND when QEMU runs without
 * -device ramfb (not an error for the caller: there is just no view);
 * other fwcfg_status values when the device misbehaves. */
int ramfb_show(const struct fm *fm);

#endif
