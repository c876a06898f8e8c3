/* Host tests of the scene's large arrays (host-tools/scene/scene_mem.c):
 * a block grown from a few bytes to 64 MiB keeps every byte; a zeroed one
 * is zero; and a large block lies in memory the kernel may back with huge
 * pages (its mapping's THPeligible in /proc/self/smaps), where the kernel
 * offers them at all. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_mem.h"
#include "tests/check.h"

static unsigned char pattern(size_t i)
{
    return (unsigned char)(i * 131u + (i >> 12));
}

static void mem_grow_keeps_bytes(void)
{
    size_t have = 1000;
    unsigned char *p = scene_mem_alloc(have);
    CHECK(p != NULL);
    if (!p)
        return;
    for (size_t i = 0; i < have; i++)
        p[i] = pattern(i);
    for (size_t size = (size_t)3 << 20; size <= (size_t)64 << 20; size *= 2) {
        unsigned char *q = scene_mem_realloc(p, size);
        CHECK(q != NULL);
        if (!q)
            break;
        p = q;
        size_t wrong = 0;
        for (size_t i = 0; i < have; i++)
            wrong += p[i] != pattern(i);
        CHECK(wrong == 0);
        for (size_t i = have; i < size; i++)
            p[i] = pattern(i);
        have = size;
    }
    free(p);
}

static void mem_zalloc_zero(void)
{
    size_t n = (size_t)24 << 20;
    unsigned char *p = scene_mem_zalloc(n);
    CHECK(p != NULL);
    if (!p)
        return;
    size_t nonzero = 0;
    for (size_t i = 0; i < n; i++)
        nonzero += p[i] != 0;
    CHECK(nonzero == 0);
    free(p);
}

/* The THPeligible line of the mapping holding address a: 1 or 0, or -1
 * when there is none to read. */
static int thp_eligible(uintptr_t a)
{
    FILE *f = fopen("/proc/self/smaps", "r");
    if (!f)
        return -1;
    char line[512];
    int inside = 0, found = -1;
    while (fgets(line, sizeof line, f)) {
        unsigned long lo, hi;
        char perms[8];
        if (sscanf(line, "%lx-%lx %7s", &lo, &hi, perms) == 3) /* a mapping's first line */
            inside = a >= lo && a < hi;
        int v;
        if (inside && sscanf(line, "THPeligible: %d", &v) == 1) {
            found = v;
            break;
        }
    }
    fclose(f);
    return found;
}

/* The kernel's THP setting ("always [madvise] never"): 1 when it is not
 * [never]. */
static int thp_offered(void)
{
    FILE *f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (!f)
        return 0;
    char line[128] = "";
    int got = fgets(line, sizeof line, f) != NULL;
    fclose(f);
    return got && !strstr(line, "[never]");
}

static void mem_large_block_advised(void)
{
    size_t n = (size_t)16 << 20;
    unsigned char *p = scene_mem_alloc(n);
    CHECK(p != NULL);
    if (!p)
        return;
    memset(p, 1, n);
    CHECK(thp_eligible((uintptr_t)p + n / 2) == 1);
    free(p);
}

int main(void)
{
    RUN(mem_grow_keeps_bytes);
    RUN(mem_zalloc_zero);
    if (thp_offered())
        RUN(mem_large_block_advised);
    else
        printf("SKIP mem_large_block_advised: this kernel offers no transparent huge pages\n");
    return check_exit();
}
