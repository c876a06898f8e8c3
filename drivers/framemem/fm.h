/* fm.h: the frame memory (FM) of LINKS-1: up to FM_MAX_WIDTH x
 * FM_MAX_HEIGHT pixels, 8 bits per channel.
 *
 * A pixel is one 32-bit word 0x00RRGGBB (DRM fourcc XR24), so the frame
 * memory doubles as the framebuffer that ramfb shows live (ramfb.h).  The
 * memory itself comes from the caller (on the board: kmem_alloc of the unit
 * computer that collects, FM_BYTES(w, h) bytes), so no worst-case array
 * sits in the image.  Only the data collector's consumer writes it (dc.h).
 *
 * No hardware access: the host tests build this file. */
#ifndef LINKS1_DRIVERS_FRAMEMEM_FM_H
#define LINKS1_DRIVERS_FRAMEMEM_FM_H

#include <stddef.h>
#include <stdint.h>

#include "drivers/framemem/fm_param.h"

/* Bytes of frame memory for a w x h frame. */
#define FM_BYTES(w, h) ((size_t)(w) * (size_t)(h) * FM_BYTES_PER_PIXEL)

enum fm_status {
    FM_OK = 0,
    FM_ERR_SIZE = -1,    /* width/height 0 or above FM_MAX_WIDTH/HEIGHT */
    FM_ERR_STORAGE = -2, /* storage missing, misaligned or too small */
    FM_ERR_BOUNDS = -3,  /* a run reaching outside the frame */
};

struct fm {
    uint32_t *pixels; /* row-major, stride = width pixels */
    uint32_t width, height;
    uint32_t runs_written;  /* runs stored since fm_init/fm_clear */
    uint32_t pixels_written;/* their pixels (a frame is complete when this
                             * reaches width * height, areas never overlap) */
    uint32_t runs_refused;  /* runs refused with FM_ERR_BOUNDS */
};

/* 0x00RRGGBB from 8-bit channels, and back. */
static inline uint32_t fm_pack(uint8_t r, uint8_t g, uint8_t b)
{
    return ((uint32_t)r << 16) | ((uint32_t)g << 8) | b;
}
static inline uint8_t fm_red(uint32_t px) { return (uint8_t)(px >> 16); }
static inline uint8_t fm_green(uint32_t px) { return (uint8_t)(px >> 8); }
static inline uint8_t fm_blue(uint32_t px) { return (uint8_t)px; }

/* Takes size bytes of 4-byte-aligned storage for a width x height frame
 * and clears it to black. */
int fm_init(struct fm *fm, void *storage, size_t size, uint32_t width, uint32_t height);
/* Black frame, counters reset. */
void fm_clear(struct fm *fm);
/* Stores n packed pixels at (x..x+n-1, y); FM_ERR_BOUNDS (nothing stored,
 * runs_refused counted) if any of them lies outside the frame. */
int fm_write_run(struct fm *fm, uint32_t x, uint32_t y, const uint32_t *px, uint32_t n);
/* Pixel (x, y), packed; 0 (black) outside the frame. */
uint32_t fm_get(const struct fm *fm, uint32_t x, uint32_t y);
/* n pixels from (x, y) as r, g, b bytes (3n bytes), for the host link;
 * FM_ERR_BOUNDS if the span leaves the frame. */
int fm_read_rgb(const struct fm *fm, uint32_t x, uint32_t y, uint32_t n, uint8_t *out);
/* Frame bytes and row stride, for ramfb. */
size_t fm_bytes(const struct fm *fm);
uint32_t fm_stride(const struct fm *fm);

const char *fm_strerror(int status);

#endif
