/* host-tools/scene/scene_mem.h: memory for a scene's large arrays (the
 * text read, the primitives, the hierarchy's items, the compiled bytes).
 *
 * The same as malloc, calloc and realloc, and a block of SCENE_MEM_HUGE
 * bytes or more is asked to be backed by transparent huge pages
 * (madvise MADV_HUGEPAGE on the 2 MiB extents inside it), where the kernel
 * offers them: a scene of 262,144 triangles touches some 200 MB, and a
 * fault for every 4 KiB page of it took about a quarter of its compile
 * (perf).  The blocks are freed with free(). */
#ifndef LINKS1_SCENE_MEM_H
#define LINKS1_SCENE_MEM_H

#include <stddef.h>

#define SCENE_MEM_HUGE ((size_t)4 << 20)

void *scene_mem_alloc(size_t n);
void *scene_mem_zalloc(size_t n);
void *scene_mem_realloc(void *p, size_t n);

#endif
