/* test_fdt.c: the device tree memory lookup (kernel/fdt.c) on small trees
 * built here the way QEMU lays them out. */
#include <string.h>

#include "kernel/fdt.h"
#include "tests/check.h"

struct fdt_builder {
    uint8_t buf[1024];
    size_t len;
    char strings[128];
    size_t slen;
};

static void put32(struct fdt_builder *b, uint32_t v)
{
    b->buf[b->len++] = (uint8_t)(v >> 24);
    b->buf[b->len++] = (uint8_t)(v >> 16);
    b->buf[b->len++] = (uint8_t)(v >> 8);
    b->buf[b->len++] = (uint8_t)v;
}

static void begin_node(struct fdt_builder *b, const char *name)
{
    put32(b, 1);
    size_t n = strlen(name) + 1;
    memcpy(b->buf + b->len, name, n);
    b->len += n;
    while (b->len % 4)
        b->buf[b->len++] = 0;
}

static void prop(struct fdt_builder *b, const char *name, const uint32_t *cells, int n)
{
    put32(b, 3);
    put32(b, (uint32_t)(4 * n));
    put32(b, (uint32_t)b->slen);
    memcpy(b->strings + b->slen, name, strlen(name) + 1);
    b->slen += strlen(name) + 1;
    for (int i = 0; i < n; i++)
        put32(b, cells[i]);
}

/* Header + struct block + strings, with the memory node named mem. */
static size_t build(struct fdt_builder *b, const char *mem, uint32_t size_lo)
{
    memset(b, 0, sizeof *b);
    b->len = 40;
    begin_node(b, "");
    uint32_t two = 2;
    prop(b, "#address-cells", &two, 1);
    begin_node(b, "cpus");
    put32(b, 2);
    begin_node(b, mem);
    uint32_t reg[4] = {0, 0x40000000u, 0, size_lo};
    prop(b, "device_type", reg, 1);
    prop(b, "reg", reg, 4);
    put32(b, 2);
    put32(b, 2);
    put32(b, 9);
    size_t off_strings = b->len;
    memcpy(b->buf + b->len, b->strings, b->slen);
    b->len += b->slen;
    size_t total = b->len;
    b->len = 0;
    put32(b, 0xD00DFEEDu);
    put32(b, (uint32_t)total);
    put32(b, 40);
    put32(b, (uint32_t)off_strings);
    b->len = total;
    return total;
}

static void test_finds_memory_node(void)
{
    static struct fdt_builder b;
    size_t n = build(&b, "memory@40000000", 0x20000000u);
    uint64_t base = 0, size = 0;
    CHECK_EQ_INT(fdt_find_memory(b.buf, n, &base, &size), FDT_OK);
    CHECK(base == 0x40000000u);
    CHECK(size == 0x20000000u);
}

static void test_rejects_bad_trees(void)
{
    static struct fdt_builder b;
    uint64_t base, size;
    size_t n = build(&b, "memory@40000000", 0x20000000u);
    CHECK_EQ_INT(fdt_find_memory(b.buf, n - 1, &base, &size), FDT_ERR_TRUNCATED);
    CHECK_EQ_INT(fdt_find_memory(b.buf, 10, &base, &size), FDT_ERR_MAGIC);
    b.buf[0] ^= 0xFF;
    CHECK_EQ_INT(fdt_find_memory(b.buf, n, &base, &size), FDT_ERR_MAGIC);
    n = build(&b, "memoryless", 0x1000u); /* not a memory node */
    CHECK_EQ_INT(fdt_find_memory(b.buf, n, &base, &size), FDT_ERR_NO_MEMORY);
    CHECK(strlen(fdt_strerror(FDT_ERR_NO_MEMORY)) > 0);
}

int main(void)
{
    RUN(test_finds_memory_node);
    RUN(test_rejects_bad_trees);
    return check_exit();
}
