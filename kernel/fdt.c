/* fdt.c: the memory node of a flattened device tree (see fdt.h).  The
 * format: a big-endian header, a structure block of 4-byte-aligned tokens
 * (BEGIN_NODE name, PROP len nameoff value, END_NODE, NOP, END) and a
 * strings block holding property names. */
#include "kernel/fdt.h"

#include <string.h>

#define FDT_MAGIC 0xD00DFEEDu
#define FDT_HEADER_SIZE 40u
#define FDT_BEGIN_NODE 1u
#define FDT_END_NODE 2u
#define FDT_PROP 3u
#define FDT_NOP 4u
#define FDT_END 9u
#define FDT_MEMORY_REG_SIZE 16u /* 2 address + 2 size cells */

static uint32_t fdt_be32(const uint8_t *p)
{
    return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
}

static uint64_t fdt_be64(const uint8_t *p)
{
    return ((uint64_t)fdt_be32(p) << 32) | fdt_be32(p + 4);
}

static size_t fdt_align4(size_t n)
{
    return (n + 3u) & ~(size_t)3u;
}

int fdt_find_memory(const uint8_t *fdt, size_t cap, uint64_t *base, uint64_t *size)
{
    if (cap < FDT_HEADER_SIZE || fdt_be32(fdt) != FDT_MAGIC)
        return FDT_ERR_MAGIC;
    size_t total = fdt_be32(fdt + 4);
    size_t off_struct = fdt_be32(fdt + 8), off_strings = fdt_be32(fdt + 12);
    if (total > cap || off_struct >= total || off_strings >= total)
        return FDT_ERR_TRUNCATED;
    size_t pos = off_struct;
    int depth = 0, in_memory = 0; /* in_memory: depth of the memory node, or 0 */
    while (pos + 4 <= total) {
        uint32_t tok = fdt_be32(fdt + pos);
        pos += 4;
        if (tok == FDT_BEGIN_NODE) {
            const char *name = (const char *)fdt + pos;
            size_t n = strnlen(name, total - pos);
            if (pos + n >= total)
                return FDT_ERR_TRUNCATED;
            depth++;
            /* Top-level "memory" or "memory@<address>". */
            if (depth == 2 && strncmp(name, "memory", 6) == 0 &&
                (name[6] == '\0' || name[6] == '@'))
                in_memory = depth;
            pos = fdt_align4(pos + n + 1);
        } else if (tok == FDT_END_NODE) {
            if (in_memory == depth)
                in_memory = 0;
            depth--;
        } else if (tok == FDT_PROP) {
            if (pos + 8 > total)
                return FDT_ERR_TRUNCATED;
            uint32_t len = fdt_be32(fdt + pos), nameoff = fdt_be32(fdt + pos + 4);
            pos += 8;
            if (pos + len > total || off_strings + nameoff >= total)
                return FDT_ERR_TRUNCATED;
            if (in_memory && len >= FDT_MEMORY_REG_SIZE &&
                strcmp((const char *)fdt + off_strings + nameoff, "reg") == 0) {
                *base = fdt_be64(fdt + pos);
                *size = fdt_be64(fdt + pos + 8);
                return FDT_OK;
            }
            pos = fdt_align4(pos + len);
        } else if (tok == FDT_END) {
            break;
        } else if (tok != FDT_NOP) {
            return FDT_ERR_TRUNCATED; /* unknown token: not a tree we understand */
        }
    }
    return FDT_ERR_NO_MEMORY;
}

const char *fdt_strerror(int status)
{
    switch (status) {
    case FDT_OK: return "ok";
    case FDT_ERR_MAGIC: return "no device tree (bad magic)";
    case FDT_ERR_TRUNCATED: return "device tree truncated or malformed";
    case FDT_ERR_NO_MEMORY: return "device tree has no memory node";
    }
    return "unknown device tree status";
}
