/* crc32.c: table-driven CRC-32 (see crc32.h).  The 1 KiB table is built at
 * compile time so the function is safe to call from any core at any time. */
#include "proto/crc32.h"

#define CRC32_POLY 0xEDB88320u

/* One table entry: eight shift/xor steps over the byte value i.  Each step
 * names its argument twice (the polynomial masked by the low bit), so an
 * entry expands to 2^8 terms, not the 3^8 a conditional would: the table
 * compiles in a fraction of a second. */
#define T1(c) (((c) >> 1) ^ (CRC32_POLY & (0u - ((c) & 1u))))
#define T8(i) T1(T1(T1(T1(T1(T1(T1(T1((uint32_t)(i)))))))))
#define R4(i) T8(i), T8(i + 1), T8(i + 2), T8(i + 3)
#define R16(i) R4(i), R4(i + 4), R4(i + 8), R4(i + 12)
#define R64(i) R16(i), R16(i + 16), R16(i + 32), R16(i + 48)

const uint32_t crc32_table[256] = {R64(0), R64(64), R64(128), R64(192)};

uint32_t crc32_update(uint32_t crc, const void *data, size_t len)
{
    const uint8_t *p = data;
    crc = ~crc;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    /* Four bytes per load: the first byte is the word's low byte, so xoring
     * the word in and taking four table steps is the four byte steps (the
     * serial lines check every message, the RC's requests included). */
    for (; len >= 4 && ((uintptr_t)p & 3u) == 0; len -= 4, p += 4) {
        uint32_t w;
        __builtin_memcpy(&w, p, 4);
        crc = crc32_step_word(crc, w);
    }
#endif
    while (len--)
        crc = crc32_step_byte(crc, *p++);
    return ~crc;
}
