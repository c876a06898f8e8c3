/* render/blob.h: a loaded scene and one prepared frame in one block of
 * memory, holding no pointer outside itself: the unit that travels through
 * the IMSU.
 *
 *   DM: render_blob_bytes() to refuse a scene too big for the block, then
 *       render_blob_load() into each IMSU block once per scene (the loader's
 *       checks, the scene's arrays at the block's start) and
 *       render_blob_prepare() every frame (render_prepare into the rest of
 *       the block: the per-frame work grows with the triangles only by what
 *       preparing them needs; a world-space scene's frame keeps the world
 *       part of the block's frame before when it would come out the same,
 *       render_prepare_again); render_blob_build() is both at once.  The
 *       IMSU swap hands the block to the RC at the same address.
 *   RC: render_blob_copy() into the broadcast block: blob->bytes bytes,
 *       (memcpy: on the board kernel/mem.c's, 128 or 32 bytes a step), then every pointer moved by
 *       the distance between the blocks (render_blob_relocate); for the
 *       next frames of the same scene render_blob_copy_frame() copies and
 *       relocates the frame part alone.
 *   NC: render_blob_open() on the broadcast block (read-only), then
 *       render_ctx_init(&ctx, blob->frame) and render_area() (render/clip.h).
 *
 *   block: | render_blob_t | scene arrays (scene_load) | frame (render_prepare) |
 *          ^ home                                        bytes in use ^
 *
 * No malloc, no stdio, no mutable globals: runs on the board and the host.
 */
#ifndef LINKS1_RENDER_BLOB_H
#define LINKS1_RENDER_BLOB_H

#include <stddef.h>
#include <stdint.h>

#include "render/relocate.h"
#include "render/render.h"
#include "render/scene_load.h"

#define RENDER_BLOB_MAGIC 0x4c42314cu /* "L1BL" in memory, little-endian */
#define RENDER_BLOB_MSG_MAX 272 /* with the DM's "scene refused: " within
                                   its log line (KLOG_MAX, 288; asserted in
                                   roles/dm_render.c) */

typedef struct {
    uint32_t magic;        /* RENDER_BLOB_MAGIC once built */
    uint32_t frame_index;  /* the frame prepared */
    uintptr_t home;        /* address of the block the pointers are valid at */
    size_t bytes;          /* bytes in use from the block's start: what a
                              copy must take */
    size_t scene_bytes;    /* of those, the header and the loaded scene:
                              where each frame's preparation starts */
    size_t bound;          /* render_blob_bytes of the scene: what any frame
                              of it needs at most */
    size_t peak;           /* most bytes of the block the build used at
                              once (scratch included): the DM's high-water
                              mark for this frame */
    uint32_t scene_id;     /* which load of which scene this is (the DM
                              numbers its loads; 0: unnumbered): two blobs
                              of one id hold the same scene part, byte for
                              byte at the same offsets */
    uint32_t wide_offset;  /* 0, or the offset from this blob's start of
                              the same scene and frame prepared in the wide
                              arithmetic (escalation, render/wide.h): its
                              blob lies after this one's bound, in the same
                              block, and travels with it */
    scene_t scene;         /* the loaded scene; its arrays are in the block */
    render_frame_t *frame; /* reloc; the prepared frame, in the block */
} render_blob_t;

typedef enum {
    RENDER_BLOB_OK = 0,
    RENDER_BLOB_ERR_TOO_BIG,  /* the scene needs more bytes than the block */
    RENDER_BLOB_ERR_LOAD,     /* the compiled scene was refused (scene_load) */
    RENDER_BLOB_ERR_PREPARE,  /* render_prepare failed */
    RENDER_BLOB_ERR_BLOCK,    /* block NULL or not aligned to RENDER_RELOCATE_ALIGN */
    RENDER_BLOB_ERR_NOT_BLOB, /* no blob in the block (magic), it overruns the
                                 block, or (open) it is not relocated there */
    RENDER_BLOB_ERR_RELOCATE, /* a pointer outside the blob (render_relocate) */
} render_blob_status_t;

typedef struct {
    render_blob_status_t status;
    char message[RENDER_BLOB_MSG_MAX]; /* e.g. "the scene needs 812544 bytes,
                                          more than the 524288 bytes of
                                          IMSU_BLOCK_BYTES" */
} render_blob_error_t;

/* Bytes a blob of this compiled scene needs at most (header, loaded scene,
 * prepared frame, scratch and alignment), from its header and section
 * table alone; any frame of the animation fits in it. */
render_blob_status_t render_blob_bytes(const uint8_t *compiled, size_t len, size_t *bytes,
                                       render_blob_error_t *err);
/* The same bound for a machine with other record sizes: with
 * &render_layout_board, what the board's DM will need (render/layout.h). */
render_blob_status_t render_blob_bytes_layout(const uint8_t *compiled, size_t len,
                                              const render_layout_t *layout, size_t *bytes,
                                              render_blob_error_t *err);

/* Loads the compiled scene and prepares frame_index into block[0..size),
 * which must be aligned to RENDER_RELOCATE_ALIGN.  A scene whose
 * render_blob_bytes exceeds size is refused before anything is written,
 * with RENDER_BLOB_ERR_TOO_BIG and a message naming limit_name (the caller's
 * name for the block's size, e.g. "IMSU_BLOCK_BYTES"; NULL: "the block").
 * *out = the blob at the block's start. */
render_blob_status_t render_blob_build(const uint8_t *compiled, size_t len, uint32_t frame_index,
                                       void *block, size_t size, const char *limit_name,
                                       render_blob_t **out, render_blob_error_t *err);

/* render_blob_build in two halves, for a block that keeps its scene from
 * frame to frame.  render_blob_load: the checks and the size bound of
 * render_blob_build, then the scene alone (no frame: blob->frame NULL).
 * render_blob_prepare: frame_index into the rest of the block (size bytes
 * from the blob's start, as given to render_blob_load), replacing the frame
 * prepared there before. */
render_blob_status_t render_blob_load(const uint8_t *compiled, size_t len, void *block,
                                      size_t size, const char *limit_name, render_blob_t **out,
                                      render_blob_error_t *err);
render_blob_status_t render_blob_prepare(render_blob_t *blob, uint32_t frame_index, size_t size,
                                         render_blob_error_t *err);
/* render_blob_prepare leaving parts of the frame out (render_prepare_parts). */
render_blob_status_t render_blob_prepare_parts(render_blob_t *blob, uint32_t frame_index,
                                               size_t size, enum render_prep_parts parts,
                                               render_blob_error_t *err);
/* render_blob_load with what the caller knows of the bytes already
 * (scene_load_summed's known: the body's word sum, checked, and perhaps
 * what another arithmetic's load of them found; NULL: nothing). */
render_blob_status_t render_blob_load_summed(const uint8_t *compiled, size_t len,
                                             const scene_load_known_t *known, void *block,
                                             size_t size,
                                             const char *limit_name, render_blob_t **out,
                                             render_blob_error_t *err);

/* The RC's forwarding: the blob at src (src->bytes bytes, at most size)
 * copied to block and relocated there.  Leaves the
 * copy as render_blob_relocate leaves it on failure. */
render_blob_status_t render_blob_copy(void *block, size_t size, const render_blob_t *src,
                                      render_blob_t **out, render_blob_error_t *err);

/* The RC's forwarding of a frame of the scene the broadcast block already
 * holds: when block holds a blob relocated there (render_blob_copy) whose
 * scene_id is src's (not 0) and whose scene part is as long, only src's
 * frame part (from scene_bytes on) is copied and only the frame's pointers
 * are moved: the scene part, already there and relocated, is neither
 * copied nor walked again.  A world-space frame whose world part the
 * block's frame has (render_world_same, at the same offset, the blob as
 * long) needs its header alone: only that is copied and relocated.
 * Otherwise as render_blob_copy.  *partial (when not NULL) says which was
 * done: 0 whole, 1 the frame part, 2 the frame header. */
render_blob_status_t render_blob_copy_frame(void *block, size_t size, const render_blob_t *src,
                                            render_blob_t **out, int *partial,
                                            render_blob_error_t *err);

/* After a byte copy of a blob (its first blob->bytes bytes) to block:
 * moves every pointer from the address it was built at (blob->home) to
 * block, and sets home.  Leaves the copy untouched on failure. */
render_blob_status_t render_blob_relocate(void *block, size_t size, render_blob_t **out,
                                          render_blob_error_t *err);

/* Checks that block holds a blob valid at this address (magic, home,
 * bytes within size): what an NC does before reading it. */
render_blob_status_t render_blob_open(const void *block, size_t size, const render_blob_t **out,
                                      render_blob_error_t *err);

#endif
