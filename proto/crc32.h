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

static inline uint32_t crc32(const void *data, size_t len)
{
    return crc32_update(0, data, len);
}

#endif
