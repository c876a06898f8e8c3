/* wire.h: little-endian field access for everything that crosses a link or
 * sits in a file (host-link payloads, inter-unit messages, compiled scenes).
 * Payloads are built and read with these, never by casting a buffer to a
 * struct, so host (x86-64) and board (ARMv7) agree byte for byte whatever the
 * compilers do with padding and alignment.
 */
#ifndef LINKS1_PROTO_WIRE_H
#define LINKS1_PROTO_WIRE_H

#include <stdint.h>
#include <string.h>

static inline void wire_put_u8(uint8_t *p, uint8_t v) { p[0] = v; }

static inline void wire_put_u16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

static inline void wire_put_u32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
}

static inline void wire_put_u64(uint8_t *p, uint64_t v)
{
    wire_put_u32(p, (uint32_t)v);
    wire_put_u32(p + 4, (uint32_t)(v >> 32));
}

/* IEEE 754 binary32, stored as its bit pattern. */
static inline void wire_put_f32(uint8_t *p, float v)
{
    uint32_t bits;
    __builtin_memcpy(&bits, &v, sizeof bits); /* a bit cast: the firmware's
                                                -ffreestanding would call memcpy */
    wire_put_u32(p, bits);
}

static inline uint8_t wire_get_u8(const uint8_t *p) { return p[0]; }

static inline uint16_t wire_get_u16(const uint8_t *p)
{
    return (uint16_t)(p[0] | (p[1] << 8));
}

static inline uint32_t wire_get_u32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) |
           ((uint32_t)p[3] << 24);
}

static inline uint64_t wire_get_u64(const uint8_t *p)
{
    return (uint64_t)wire_get_u32(p) | ((uint64_t)wire_get_u32(p + 4) << 32);
}

static inline float wire_get_f32(const uint8_t *p)
{
    uint32_t bits = wire_get_u32(p);
    float v;
    __builtin_memcpy(&v, &bits, sizeof v); /* a bit cast, not a call */
    return v;
}

#endif
