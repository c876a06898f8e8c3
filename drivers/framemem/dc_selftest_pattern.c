/* dc_selftest_pattern.c: the DC self-test's pattern (see dc_selftest.h);
 * hardware-free, so the host tests build it. */
#include "drivers/framemem/dc_selftest.h"

/* Red and green carry the low 8 bits of x and y, blue's low nibble their
 * top 2 bits each (FM_MAX_* = 1024 = 2^10), so no two pixels of a frame are
 * alike; blue's high nibble adds a checkerboard of 16-pixel squares to make
 * a misplaced run visible on the ramfb view too. */
uint32_t dc_selftest_pixel(uint32_t x, uint32_t y)
{
    uint32_t b = ((x >> 8) & 3u) | (((y >> 8) & 3u) << 2) | ((((x ^ y) >> 4) & 1u) << 7);
    return fm_pack((uint8_t)x, (uint8_t)y, (uint8_t)b);
}
