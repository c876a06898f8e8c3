/* render/blob.c: scene + prepared frame in one self-contained block (see
 * blob.h). */
#include "render/blob.h"

#include <stdarg.h>
#include <string.h>

#include "proto/textfmt.h"
#include "render/precision.h"
#include "render/scene_load.h"

/* ------------------------------------------------------------ messages */

/* Sets the status and the message (cut to RENDER_BLOB_MSG_MAX - 1). */
static void blob_fail(render_blob_error_t *err, render_blob_status_t st, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void blob_fail(render_blob_error_t *err, render_blob_status_t st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fmt_vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    err->status = st;
}

static void blob_ok(render_blob_error_t *err)
{
    err->status = RENDER_BLOB_OK;
    err->message[0] = 0;
}

static int blob_aligned(const void *block)
{
    return block && (uintptr_t)block % RENDER_RELOCATE_ALIGN == 0;
}

/* ----------------------------------------------------------------- API */

render_blob_status_t render_blob_bytes(const uint8_t *compiled, size_t len, size_t *bytes,
                                       render_blob_error_t *err)
{
    return render_blob_bytes_layout(compiled, len, &render_layout_native, bytes, err);
}

/* How blob_bound counts the index's parent maps. */
enum blob_maps {
    BLOB_MAPS_EACH,   /* two a cluster: the header alone */
    BLOB_MAPS_COUNTED /* the clusters that may have maps of their own, from
                         their records (scene_load_shape_maps) */
};

/* The blob's bytes for a scene of this shape: the header first (alignment
 * of the block start: none), then the loader's arrays, then the frame
 * with its scratch. */
static size_t blob_shape_bytes(const scene_t *shape, uint32_t texel_bytes,
                               const render_layout_t *layout)
{
    return layout->blob + scene_load_bytes_layout(shape, texel_bytes, layout) +
           render_prepare_frame_bytes_layout(shape, layout);
}

/* render_blob_bytes_layout; crc_later: scene_load follows on the same
 * bytes and checks the word sum (render_blob_load).  least, unless NULL:
 * the bytes with the root's two maps alone, the fewest a scene has (a
 * bound from below, from the same header). */
static render_blob_status_t blob_bound(const uint8_t *compiled, size_t len,
                                       const render_layout_t *layout, int crc_later,
                                       enum blob_maps maps, size_t *bytes, size_t *least,
                                       render_blob_error_t *err)
{
    scene_t shape;
    uint32_t texel_bytes;
    scene_load_error_t lerr;
    *bytes = 0;
    blob_ok(err);
    scene_load_status_t st =
        maps == BLOB_MAPS_COUNTED
            ? scene_load_shape_maps(compiled, len, crc_later, &shape, &texel_bytes, &lerr)
        : crc_later ? scene_load_shape_before_load(compiled, len, &shape, &texel_bytes, &lerr)
                    : scene_load_shape(compiled, len, &shape, &texel_bytes, &lerr);
    if (st != SCENE_LOAD_OK) {
        blob_fail(err, RENDER_BLOB_ERR_LOAD, "scene refused: %s", lerr.message);
        return err->status;
    }
    *bytes = blob_shape_bytes(&shape, texel_bytes, layout);
    if (least) {
        shape.index.parent_map_count = 2;
        *least = blob_shape_bytes(&shape, texel_bytes, layout);
    }
    return RENDER_BLOB_OK;
}

render_blob_status_t render_blob_bytes_layout(const uint8_t *compiled, size_t len,
                                              const render_layout_t *layout, size_t *bytes,
                                              render_blob_error_t *err)
{
    return blob_bound(compiled, len, layout, 0, BLOB_MAPS_COUNTED, bytes, NULL, err);
}

render_blob_status_t render_blob_load(const uint8_t *compiled, size_t len, void *block,
                                      size_t size, const char *limit_name, render_blob_t **out,
                                      render_blob_error_t *err)
{
    return render_blob_load_summed(compiled, len, NULL, block, size, limit_name, out, err);
}

render_blob_status_t render_blob_load_summed(const uint8_t *compiled, size_t len,
                                             const scene_load_known_t *known, void *block,
                                             size_t size,
                                             const char *limit_name, render_blob_t **out,
                                             render_blob_error_t *err)
{
    size_t need, least = 0;
    *out = NULL;
    if (!blob_aligned(block)) {
        blob_fail(err, RENDER_BLOB_ERR_BLOCK,
                  "blob block NULL or not aligned to RENDER_RELOCATE_ALIGN");
        return err->status;
    }
    /* The bound without the word sum (scene_load checks it next); a
     * refusal asks again with the sum, so a damaged scene is refused as
     * render_blob_bytes refuses it (the sum before the section table).
     * A caller that gives the sum has checked it (the DM's upload check,
     * or its narrow load before the wide one): a scene too big is that. */
    int bounded = blob_bound(compiled, len, &render_layout_native, 1, BLOB_MAPS_EACH, &need,
                             &least, err) == RENDER_BLOB_OK;
    /* the root's maps alone too many (a checked scene: the DM's): too big
     * however many maps its clusters have */
    if (bounded && known && least > size) {
        blob_fail(err, RENDER_BLOB_ERR_TOO_BIG,
                  "the scene needs at least %zu bytes, more than the %zu bytes of %s", least,
                  size, limit_name ? limit_name : "the block");
        return err->status;
    }
    /* two maps a cluster too many: the clusters' records say which may
     * have maps (a pass over them, only for a scene near the limit) */
    if (bounded && need > size)
        bounded = blob_bound(compiled, len, &render_layout_native, 1, BLOB_MAPS_COUNTED, &need,
                             NULL, err) == RENDER_BLOB_OK;
    if ((!bounded || (need > size && !known)) &&
        render_blob_bytes(compiled, len, &need, err) != RENDER_BLOB_OK)
        return err->status;
    if (need > size) {
        blob_fail(err, RENDER_BLOB_ERR_TOO_BIG,
                  "the scene needs %zu bytes, more than the %zu bytes of %s", need, size,
                  limit_name ? limit_name : "the block");
        return err->status;
    }
    arena_t arena;
    arena_init(&arena, block, size);
    render_blob_t *blob = ARENA_NEW_ARRAY(&arena, render_blob_t, 1);
    scene_load_error_t lerr;
    if (!blob ||
        scene_load_summed(compiled, len, known, &arena, &blob->scene, &lerr) != SCENE_LOAD_OK) {
        blob_fail(err, RENDER_BLOB_ERR_LOAD, "scene refused: %s",
                  blob ? lerr.message : "no room for the blob header");
        return err->status;
    }
    blob->magic = RENDER_BLOB_MAGIC;
    blob->home = (uintptr_t)block;
    blob->scene_bytes = blob->bytes = blob->peak = arena.used;
    blob->bound = need;
    blob->scene_id = 0; /* the caller numbers its loads */
    blob->wide_offset = 0;
    blob->frame = NULL;
    *out = blob;
    return RENDER_BLOB_OK;
}

render_blob_status_t render_blob_prepare(render_blob_t *blob, uint32_t frame_index, size_t size,
                                         render_blob_error_t *err)
{
    return render_blob_prepare_parts(blob, frame_index, size, RENDER_PREP_WHOLE, err);
}

render_blob_status_t render_blob_prepare_parts(render_blob_t *blob, uint32_t frame_index,
                                               size_t size, enum render_prep_parts parts,
                                               render_blob_error_t *err)
{
    blob_ok(err);
    /* the arena as render_blob_load left it: the scene in use, the rest free */
    arena_t arena;
    arena_init(&arena, blob, size);
    arena.used = arena.high_water = blob->scene_bytes;
    /* the frame before in this block, whose world part a world-space frame
     * may keep (render_prepare_again checks it is where the frame goes) */
    const render_frame_t *prev = blob->frame;
    blob->frame = NULL;
    render_frame_t *frame;
    render_status_t st =
        render_prepare_parts(&blob->scene, frame_index, &arena, prev, parts, &frame);
    if (st != RENDER_OK) {
        char why[RENDER_BLOB_MSG_MAX];
        precision_status_message(frame, st, why, sizeof why);
        blob_fail(err, RENDER_BLOB_ERR_PREPARE, "frame %lu: %s", (unsigned long)frame_index, why);
        return err->status;
    }
    blob->frame_index = frame_index;
    blob->bytes = arena.used;
    blob->peak = arena.high_water;
    blob->frame = frame;
    return RENDER_BLOB_OK;
}

render_blob_status_t render_blob_build(const uint8_t *compiled, size_t len, uint32_t frame_index,
                                       void *block, size_t size, const char *limit_name,
                                       render_blob_t **out, render_blob_error_t *err)
{
    render_blob_t *blob;
    *out = NULL;
    if (render_blob_load(compiled, len, block, size, limit_name, &blob, err) != RENDER_BLOB_OK ||
        render_blob_prepare(blob, frame_index, size, err) != RENDER_BLOB_OK)
        return err->status;
    *out = blob;
    return RENDER_BLOB_OK;
}

/* The header at block, if it is one that fits in size bytes. */
static render_blob_t *blob_header(const void *block, size_t size, render_blob_error_t *err)
{
    if (!blob_aligned(block)) {
        blob_fail(err, RENDER_BLOB_ERR_BLOCK,
                  "blob block NULL or not aligned to RENDER_RELOCATE_ALIGN");
        return NULL;
    }
    render_blob_t *blob = (render_blob_t *)(uintptr_t)block;
    if (size < sizeof *blob || blob->magic != RENDER_BLOB_MAGIC) {
        blob_fail(err, RENDER_BLOB_ERR_NOT_BLOB, "no blob in the block (magic)");
        return NULL;
    }
    if (blob->bytes < sizeof *blob || blob->bytes > size) {
        blob_fail(err, RENDER_BLOB_ERR_NOT_BLOB, "the blob's %zu bytes do not fit the block of %zu",
                  blob->bytes, size);
        return NULL;
    }
    return blob;
}

render_blob_status_t render_blob_relocate(void *block, size_t size, render_blob_t **out,
                                          render_blob_error_t *err)
{
    *out = NULL;
    blob_ok(err);
    render_blob_t *blob = blob_header(block, size, err);
    if (!blob)
        return err->status;
    uintptr_t home = blob->home;
    /* old addresses of the header's scene and frame pointer targets */
    const scene_t *scene = (const scene_t *)(home + offsetof(render_blob_t, scene));
    render_frame_t *frame = blob->frame;
    const char *bad;
    if (render_relocate(block, blob->bytes, home, &scene, &frame, &bad) != RENDER_OK) {
        blob_fail(err, RENDER_BLOB_ERR_RELOCATE, "blob not self-contained: %s", bad);
        return err->status;
    }
    blob->frame = frame;
    blob->home = (uintptr_t)block;
    *out = blob;
    return RENDER_BLOB_OK;
}

render_blob_status_t render_blob_copy(void *block, size_t size, const render_blob_t *src,
                                      render_blob_t **out, render_blob_error_t *err)
{
    *out = NULL;
    if (!blob_aligned(block) || src->bytes > size) {
        blob_fail(err, RENDER_BLOB_ERR_BLOCK, "the blob's %zu bytes do not fit the block of %zu, "
                  "or the block is not aligned to RENDER_RELOCATE_ALIGN", src->bytes, size);
        return err->status;
    }
    memcpy(block, src, src->bytes);
    return render_blob_relocate(block, size, out, err);
}

render_blob_status_t render_blob_copy_frame(void *block, size_t size, const render_blob_t *src,
                                            render_blob_t **out, int *partial,
                                            render_blob_error_t *err)
{
    *out = NULL;
    if (partial)
        *partial = 0;
    render_blob_t *dst = (render_blob_t *)block;
    if (!blob_aligned(block) || src->bytes > size || size < sizeof *dst ||
        dst->magic != RENDER_BLOB_MAGIC || dst->home != (uintptr_t)block || src->scene_id == 0 ||
        dst->scene_id != src->scene_id || dst->scene_bytes != src->scene_bytes ||
        src->scene_bytes > src->bytes || !src->frame)
        return render_blob_copy(block, size, src, out, err);
    blob_ok(err);
    render_frame_t *frame = src->frame;
    const char *bad;
    render_status_t st;
    /* world space: a frame whose world part the block holds already (the
     * frame there at the same offset, the same layout, render_world_same)
     * needs its header alone, read where src lies (not at its home) */
    uintptr_t fat = (uintptr_t)src->frame - src->home;
    if (dst->frame && dst->bytes == src->bytes && fat == (uintptr_t)dst->frame - (uintptr_t)block &&
        fat >= src->scene_bytes && src->bytes >= sizeof(render_frame_t) &&
        fat <= src->bytes - sizeof(render_frame_t) &&
        render_world_same(&dst->scene, dst->frame,
                          (const render_frame_t *)(const void *)((const uint8_t *)src + fat))) {
        memcpy((uint8_t *)block + fat, (const uint8_t *)src + fat, sizeof(render_frame_t));
        st = render_relocate_frame_header(block, src->bytes, src->home, &frame, &bad);
        if (partial && st == RENDER_OK)
            *partial = 2;
    } else {
        /* the frame part: from the first word boundary at or after the
         * scene's end (the frame's first array is aligned past it; what
         * lies between is padding) */
        size_t at = (src->scene_bytes + sizeof(uint32_t) - 1) & ~(sizeof(uint32_t) - 1);
        if (at < src->bytes)
            memcpy((uint8_t *)block + at, (const uint8_t *)src + at, src->bytes - at);
        st = render_relocate_frame(block, src->bytes, src->home, &frame, &bad);
        if (partial && st == RENDER_OK)
            *partial = 1;
    }
    if (st != RENDER_OK) {
        dst->magic = 0; /* the next frame is copied whole */
        blob_fail(err, RENDER_BLOB_ERR_RELOCATE, "blob not self-contained: %s", bad);
        return err->status;
    }
    dst->frame_index = src->frame_index;
    dst->bytes = src->bytes;
    dst->bound = src->bound;
    dst->peak = src->peak;
    dst->wide_offset = src->wide_offset;
    dst->frame = frame;
    *out = dst;
    return RENDER_BLOB_OK;
}

render_blob_status_t render_blob_open(const void *block, size_t size, const render_blob_t **out,
                                      render_blob_error_t *err)
{
    *out = NULL;
    blob_ok(err);
    const render_blob_t *blob = blob_header(block, size, err);
    if (!blob)
        return err->status;
    if (blob->home != (uintptr_t)block) {
        blob_fail(err, RENDER_BLOB_ERR_NOT_BLOB,
                  "the blob was built elsewhere and not relocated here");
        return err->status;
    }
    *out = blob;
    return RENDER_BLOB_OK;
}
