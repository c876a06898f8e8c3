/* dc_selftest.c: the board check of the DC and FM (see dc_selftest.h). */
#include "drivers/framemem/dc_selftest.h"

#include "drivers/framemem/dc.h"
#include "kernel/ktime.h"

int dc_selftest_produce(uint32_t width, uint32_t height, uint32_t nc, uint32_t ncs)
{
    /* One scanline as r,g,b bytes, as the renderer hands them over. */
    uint8_t rgb[DC_RUN_MAX_PIXELS * 3];
    for (uint32_t y = nc; y < height; y += ncs) {
        for (uint32_t x0 = 0; x0 < width; x0 += DC_RUN_MAX_PIXELS) {
            uint32_t n = width - x0 < DC_RUN_MAX_PIXELS ? width - x0 : DC_RUN_MAX_PIXELS;
            for (uint32_t i = 0; i < n; i++) {
                uint32_t px = dc_selftest_pixel(x0 + i, y);
                rgb[3 * i] = fm_red(px);
                rgb[3 * i + 1] = fm_green(px);
                rgb[3 * i + 2] = fm_blue(px);
            }
            int rc = dc_push_span(x0, y, rgb, n);
            if (rc != DC_OK)
                return rc;
        }
    }
    return DC_OK;
}

int dc_selftest_collect(struct fm *fm, uint32_t timeout_ms, struct dc_selftest_result *r)
{
    uint32_t total = fm->width * fm->height;
    uint64_t start = ktime_now();
    uint64_t deadline = ktime_deadline_ms(timeout_ms);
    while (fm->pixels_written < total)
        if (dc_collect_wait(fm, deadline) == 0)
            break; /* timed out: a producer died, or runs were lost */
    r->ms = ktime_ticks_to_ms(ktime_now() - start);
    r->pixels = fm->pixels_written;
    r->refused = fm->runs_refused;
    r->full_waits = dc_full_waits();
    r->bad = 0;
    for (uint32_t y = 0; y < fm->height; y++)
        for (uint32_t x = 0; x < fm->width; x++)
            r->bad += fm_get(fm, x, y) != dc_selftest_pixel(x, y);
    return (r->pixels == total && r->bad == 0 && r->refused == 0) ? 0 : -1;
}
