/* crc32.c: table-driven CRC-32 (see crc32.h).  The 1 KiB table is built at
 * compile time so the function is safe to call from any core at any time. */
#include "proto/crc32.h"

#define CRC32_POLY 0xEDB88320u

/* One table entry: eight shift/xor steps over the byte value i. */
#define T1(c) (((c) & 1u) ? (((c) >> 1) ^ CRC32_POLY) : ((c) >> 1))
#define T8(i) T1(T1(T1(T1(T1(T1(T1(T1((uint32_t)(i)))))))))
#define R4(i) T8(i), T8(i + 1), T8(i + 2), T8(i + 3)
#define R16(i) R4(i), R4(i + 4), R4(i + 8), R4(i + 12)
#define R64(i) R16(i), R16(i + 16), R16(i + 32), R16(i + 48)

static const uint32_t crc32_table[256] = {R64(0), R64(64), R64(128), R64(192)};

uint32_t crc32_update(uint32_t crc, const void *data, size_t len)
{
    const uint8_t *p = data;
    crc = ~crc;
    while (len--)
        crc = crc32_table[(crc ^ *p++) & 0xFFu] ^ (crc >> 8);
    return ~crc;
}
