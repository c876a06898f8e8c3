/* render/arena.h: a bump allocator over caller-provided memory.
 *
 * The renderer never calls malloc: the host tool hands it a buffer, the board
 * a region of a unit computer's memory.  Allocation fails cleanly (NULL, and
 * the arena remembers it) instead of overrunning; used and high_water let the
 * caller report how much a scene needed.
 */
#ifndef LINKS1_RENDER_ARENA_H
#define LINKS1_RENDER_ARENA_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    uint8_t *base;     /* start of the memory */
    size_t size;       /* bytes available */
    size_t used;       /* bytes handed out so far (with alignment padding) */
    size_t high_water; /* largest "used" ever seen, survives arena_reset */
    size_t failed_request; /* bytes of the first request that did not fit, 0 if none */
} arena_t;

void arena_init(arena_t *a, void *memory, size_t size);
/* The largest alignment arena_alloc gives, and so the most padding one
 * allocation can cost: what memory bounds add per allocation. */
#define ARENA_MAX_ALIGN 64

/* size bytes aligned to align (a power of two, <= ARENA_MAX_ALIGN); zero-filled.
 * NULL when the arena is exhausted (and failed_request is set). */
void *arena_alloc(arena_t *a, size_t size, size_t align);
/* The same, not zero-filled: scratch whose every element the caller
 * writes before reading it. */
void *arena_alloc_raw(arena_t *a, size_t size, size_t align);
/* Forget every allocation made after mark = a->used was taken. */
void arena_release_to(arena_t *a, size_t mark);
void arena_reset(arena_t *a);

#define ARENA_NEW_ARRAY(a, type, n) ((type *)arena_alloc((a), sizeof(type) * (size_t)(n), _Alignof(type)))
#define ARENA_NEW_ARRAY_RAW(a, type, n) \
    ((type *)arena_alloc_raw((a), sizeof(type) * (size_t)(n), _Alignof(type)))

#endif
