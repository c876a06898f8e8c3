/* kmem.h: the private memory of each unit computer (carved by
 * linker/virt-memory.ld): a bump allocator with a high-water mark.  Only
 * the owning core allocates from its region. */
#ifndef LINKS1_KERNEL_KMEM_H
#define LINKS1_KERNEL_KMEM_H

#include <stddef.h>
#include <stdint.h>

/* Gives core its region: the DM and RC their own, each NC an equal share of
 * the NC pool for ncores cores. */
void kmem_init(uint32_t core, uint32_t ncores);
/* n bytes, 8-byte aligned, from this core's region; what names the use in
 * the panic when the region is exhausted. */
void *kmem_alloc(size_t n, const char *what);
/* Bytes of this core's region, and the most ever in use. */
size_t kmem_size(void);
size_t kmem_high_water(void);
/* Per-scene memory: kmem_mark() is the bytes in use now; kmem_release_to()
 * gives back everything allocated after that mark (a new scene replaces the
 * old one's buffers).  The high-water mark keeps counting across. */
size_t kmem_mark(void);
void kmem_release_to(size_t mark);
/* Bytes still free in this core's region. */
size_t kmem_free(void);

#endif
