/* fm.c: the frame memory (see fm.h). */
#include "drivers/framemem/fm.h"

#include <string.h>

int fm_init(struct fm *fm, void *storage, size_t size, uint32_t width, uint32_t height)
{
    memset(fm, 0, sizeof *fm);
    if (width == 0 || height == 0 || width > FM_MAX_WIDTH || height > FM_MAX_HEIGHT)
        return FM_ERR_SIZE;
    if (storage == NULL || ((uintptr_t)storage & (FM_BYTES_PER_PIXEL - 1)) != 0 ||
        size < FM_BYTES(width, height))
        return FM_ERR_STORAGE;
    fm->pixels = storage;
    fm->width = width;
    fm->height = height;
    fm_clear(fm);
    return FM_OK;
}

void fm_clear(struct fm *fm)
{
    memset(fm->pixels, 0, fm_bytes(fm));
    fm->runs_written = 0;
    fm->pixels_written = 0;
    fm->runs_refused = 0;
}

/* x + n is computed only after x < width, so it cannot wrap. */
static int fm_span_inside(const struct fm *fm, uint32_t x, uint32_t y, uint32_t n)
{
    return y < fm->height && x < fm->width && n <= fm->width - x;
}

int fm_write_run(struct fm *fm, uint32_t x, uint32_t y, const uint32_t *px, uint32_t n)
{
    if (!fm_span_inside(fm, x, y, n)) {
        fm->runs_refused++;
        return FM_ERR_BOUNDS;
    }
    /* One 32-bit store a pixel: the board's C library copies byte by
     * byte, and the live view (ramfb, read by QEMU while the NCs run)
     * caught a pixel with some bytes new and some old (render_view.sh).
     * volatile keeps the compiler from making the loop a memcpy call. */
    volatile uint32_t *dst = &fm->pixels[(size_t)y * fm->width + x];
    for (uint32_t i = 0; i < n; i++)
        dst[i] = px[i];
    fm->runs_written++;
    fm->pixels_written += n;
    return FM_OK;
}

uint32_t fm_get(const struct fm *fm, uint32_t x, uint32_t y)
{
    if (!fm_span_inside(fm, x, y, 1))
        return 0;
    return fm->pixels[(size_t)y * fm->width + x];
}

int fm_read_rgb(const struct fm *fm, uint32_t x, uint32_t y, uint32_t n, uint8_t *out)
{
    if (!fm_span_inside(fm, x, y, n))
        return FM_ERR_BOUNDS;
    const uint32_t *row = &fm->pixels[(size_t)y * fm->width + x];
    for (uint32_t i = 0; i < n; i++) {
        out[3 * i] = fm_red(row[i]);
        out[3 * i + 1] = fm_green(row[i]);
        out[3 * i + 2] = fm_blue(row[i]);
    }
    return FM_OK;
}

size_t fm_bytes(const struct fm *fm)
{
    return FM_BYTES(fm->width, fm->height);
}

uint32_t fm_stride(const struct fm *fm)
{
    return fm->width * FM_BYTES_PER_PIXEL;
}

const char *fm_strerror(int status)
{
    switch (status) {
    case FM_OK:
        return "ok";
    case FM_ERR_SIZE:
        _Static_assert(FM_MAX_WIDTH == 1024u && FM_MAX_HEIGHT == 1024u,
                       "update the message below");
        return "frame size must be 1..1024 x 1..1024 (FM_MAX_WIDTH x FM_MAX_HEIGHT)";
    case FM_ERR_STORAGE:
        return "frame memory storage missing, not 4-byte aligned, or smaller than "
               "FM_BYTES(w, h)";
    case FM_ERR_BOUNDS:
        return "pixel run reaches outside the frame";
    default:
        return "unknown frame memory error";
    }
}
