/* render/arena.c: bump allocator (see arena.h). */
#include "render/arena.h"

#include <string.h>

void arena_init(arena_t *a, void *memory, size_t size)
{
    a->base = memory;
    a->size = memory ? size : 0;
    a->used = 0;
    a->high_water = 0;
    a->failed_request = 0;
}

void *arena_alloc_raw(arena_t *a, size_t size, size_t align)
{
    if (align == 0 || (align & (align - 1)) != 0 || align > ARENA_MAX_ALIGN)
        align = ARENA_MAX_ALIGN; /* a bad alignment request still gets a safe one */
    if (!a->base) {
        if (!a->failed_request)
            a->failed_request = size ? size : 1;
        return NULL;
    }
    uintptr_t start = (uintptr_t)a->base + a->used;
    size_t pad = (size_t)((align - (start & (align - 1))) & (align - 1));
    /* compare by subtraction so a huge size cannot wrap the sum */
    if (pad > a->size - a->used || size > a->size - a->used - pad) {
        if (!a->failed_request)
            a->failed_request = size ? size : 1;
        return NULL;
    }
    uint8_t *p = a->base + a->used + pad;
    a->used += pad + size;
    if (a->used > a->high_water)
        a->high_water = a->used;
    return p;
}

void *arena_alloc(arena_t *a, size_t size, size_t align)
{
    void *p = arena_alloc_raw(a, size, align);
    if (p)
        memset(p, 0, size);
    return p;
}

void arena_release_to(arena_t *a, size_t mark)
{
    if (mark <= a->used)
        a->used = mark;
}

void arena_reset(arena_t *a)
{
    a->used = 0;
    a->failed_request = 0;
}
