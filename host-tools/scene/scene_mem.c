/* host-tools/scene/scene_mem.c: large arrays on transparent huge pages
 * (scene_mem.h). */
#include "host-tools/scene/scene_mem.h"

#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

/* The advice is only advice: where the kernel has no huge pages (or
 * refuses), the block is ordinary memory and nothing else changes.  It
 * covers the whole pages the block lies in: a block malloc maps alone is
 * then one mapping still, which realloc can move and grow (mremap)
 * without copying it. */
static void *scene_mem_advise(void *p, size_t n)
{
#if defined(MADV_HUGEPAGE)
    if (p && n >= SCENE_MEM_HUGE) {
        uintptr_t page = (uintptr_t)sysconf(_SC_PAGESIZE);
        uintptr_t lo = (uintptr_t)p & ~(page - 1);
        uintptr_t hi = ((uintptr_t)p + n + page - 1) & ~(page - 1);
        (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE);
    }
#endif
    return p;
}

void *scene_mem_alloc(size_t n)
{
    return scene_mem_advise(malloc(n), n);
}

void *scene_mem_zalloc(size_t n)
{
    return scene_mem_advise(calloc(1, n), n);
}

void *scene_mem_realloc(void *p, size_t n)
{
    return scene_mem_advise(realloc(p, n), n);
}
