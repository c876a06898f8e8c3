/* crc32.h: CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320, initial value
 * and final xor 0xFFFFFFFF), the checksum of host-link frames and of compiled
 * scenes.  crc32("123456789") == 0xCBF43926.
 *
 * Incremental use: crc = crc32_update(0, a, n); crc = crc32_update(crc, b, m);
 * gives the same value as one call over a then b.
 */
#ifndef LINKS1_PROTO_CRC32_H
#define LINKS1_PROTO_CRC32_H

#include <stddef.h>
#include <stdint.h>

uint32_t crc32_update(uint32_t crc, const void *data, size_t len);

/* The table (crc32.c) and the steps crc32_update takes over it, on the
 * running value (not inverted): a byte, and a little-endian word whose
 * first byte is its low byte (four byte steps). */
extern const uint32_t crc32_table[256];
static inline uint32_t crc32_step_byte(uint32_t crc, uint8_t b)
{
    return crc32_table[(crc ^ b) & 0xFFu] ^ (crc >> 8);
}
static inline uint32_t crc32_step_word(uint32_t crc, uint32_t w)
{
    crc ^= w;
    crc = crc32_table[crc & 0xFFu] ^ (crc >> 8);
    crc = crc32_table[crc & 0xFFu] ^ (crc >> 8);
    crc = crc32_table[crc & 0xFFu] ^ (crc >> 8);
    return crc32_table[crc & 0xFFu] ^ (crc >> 8);
}

/* crc32 of a few words at a word-aligned p, len bytes (len <= 4 * words
 * and whole words only: the bytes past len are not read): inline, for the
 * serial lines' short messages, where a call would cost as much as the
 * steps.  Longer data goes to crc32_update. */
#define CRC32_SHORT_WORDS 4u
static inline uint32_t crc32_short(const void *p, size_t len)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    if (len <= 4u * CRC32_SHORT_WORDS && len % 4u == 0 && ((uintptr_t)p & 3u) == 0) {
        uint32_t crc = ~0u, w;
        for (size_t i = 0; i < len; i += 4) {
            __builtin_memcpy(&w, (const uint8_t *)p + i, 4);
            crc = crc32_step_word(crc, w);
        }
        return ~crc;
    }
#endif
    return crc32_update(0, p, len);
}

static inline uint32_t crc32(const void *data, size_t len)
{
    return crc32_update(0, data, len);
}

#endif
