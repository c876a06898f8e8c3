/* dc_selftest.h: a board check of the data collector and frame memory
 * that needs no renderer: every NC pushes its share of the scanlines of a
 * known pattern, the collector fills the frame memory, then every pixel is
 * compared with the pattern.  A run lost, duplicated into the wrong place,
 * or damaged shows as a wrong pixel or a frame that never completes.
 *
 * The roles call it (the RC collects, the NCs produce); the pattern itself
 * is hardware-free (dc_selftest_pixel), so the host tests check it too. */
#ifndef LINKS1_DRIVERS_FRAMEMEM_DC_SELFTEST_H
#define LINKS1_DRIVERS_FRAMEMEM_DC_SELFTEST_H

#include <stdint.h>

#include "drivers/framemem/fm.h"

/* The pattern's pixel at (x, y), packed 0x00RRGGBB: different for every
 * (x, y) of the largest frame, so a run written anywhere but its own place
 * shows. */
uint32_t dc_selftest_pixel(uint32_t x, uint32_t y);

/* NC number nc (0..ncs-1): pushes scanlines nc, nc + ncs, ... of a
 * width x height pattern through the DC.  DC_OK or a dc_status error. */
int dc_selftest_produce(uint32_t width, uint32_t height, uint32_t nc, uint32_t ncs);

struct dc_selftest_result {
    uint32_t pixels;     /* pixels the frame memory received */
    uint32_t bad;        /* pixels that differ from the pattern */
    uint32_t refused;    /* runs refused as outside the frame */
    uint32_t full_waits; /* times a producer found the FIFO full */
    uint32_t ms;         /* collect time */
};

/* Collector: empties the DC into fm until fm is complete or timeout_ms
 * passes, then compares fm with the pattern.  Returns 0 when every pixel
 * came and matched, -1 otherwise (the result says what went wrong). */
int dc_selftest_collect(struct fm *fm, uint32_t timeout_ms, struct dc_selftest_result *r);

#endif
