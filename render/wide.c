/* render/wide.c: the wide arithmetic's entry points (render/wide.h).  Built
 * only into the wide copy of the renderer (LINKS1_NUM_DOUBLE), whose global
 * symbols the link renames wide_NAME. */
#define LINKS1_WIDE_COPY
#include "render/wide.h"

#include <string.h>

#include "proto/textfmt.h"
#include "render/blob.h"
#include "render/limits.h"

#ifndef LINKS1_NUM_DOUBLE
#error "render/wide.c is the wide copy: compile it with LINKS1_NUM_DOUBLE"
#endif

const char RENDER_WIDE(wide_arith_name)[] = NUM_NAME;

/* The blob call's status as 0 / -1, its message into msg. */
static int wide_result(render_blob_status_t st, const render_blob_error_t *err, char *msg,
                       size_t cap)
{
    if (st == RENDER_BLOB_OK)
        return 0;
    fmt_snprintf(msg, cap, "%s (%s)", err->message, NUM_NAME);
    return -1;
}

int RENDER_WIDE(wide_blob_bytes)(const uint8_t *compiled, size_t len, size_t *bytes, char *msg,
                                 size_t cap)
{
    render_blob_error_t err;
    return wide_result(render_blob_bytes(compiled, len, bytes, &err), &err, msg, cap);
}

int RENDER_WIDE(wide_blob_load)(const uint8_t *compiled, size_t len,
                                const scene_load_known_t *known, void *block, size_t size,
                                const char *limit_name, uint32_t scene_id, char *msg, size_t cap)
{
    render_blob_error_t err;
    render_blob_t *blob;
    render_blob_status_t st =
        render_blob_load_summed(compiled, len, known, block, size, limit_name, &blob, &err);
    if (st == RENDER_BLOB_OK)
        blob->scene_id = scene_id;
    return wide_result(st, &err, msg, cap);
}

int RENDER_WIDE(wide_blob_prepare)(void *block, uint32_t frame_index, size_t size, char *msg,
                                   size_t cap)
{
    render_blob_error_t err;
    const render_blob_t *open;
    render_blob_status_t st = render_blob_open(block, size, &open, &err);
    /* no screen rectangles: wide_pixel (render_pixel) walks without them */
    if (st == RENDER_BLOB_OK)
        st = render_blob_prepare_parts((render_blob_t *)block, frame_index, size,
                                       RENDER_PREP_NO_SCREEN, &err);
    return wide_result(st, &err, msg, cap);
}

int RENDER_WIDE(wide_blob_copy_frame)(void *block, size_t size, const void *src, char *msg,
                                      size_t cap)
{
    render_blob_error_t err;
    const render_blob_t *from;
    render_blob_t *out;
    /* the source as an NC would open it: a blob valid where it lies */
    render_blob_status_t st = render_blob_open(src, size, &from, &err);
    if (st == RENDER_BLOB_OK)
        st = render_blob_copy_frame(block, size, from, &out, NULL, &err);
    return wide_result(st, &err, msg, cap);
}

size_t RENDER_WIDE(wide_stack_bytes)(uint32_t max_depth)
{
    return RENDER_STACK_BYTES(max_depth);
}

size_t RENDER_WIDE(wide_ctx_bytes)(void)
{
    return sizeof(render_ctx_t);
}

_Static_assert(_Alignof(render_ctx_t) <= RENDER_WIDE_CTX_ALIGN,
               "RENDER_WIDE_CTX_ALIGN is below the wide context's alignment");

int RENDER_WIDE(wide_ctx_open)(void *ctx_mem, const void *block, size_t size, int use_bounds,
                               int use_hierarchy, int mark_lost, char *msg, size_t cap)
{
    render_blob_error_t err;
    const render_blob_t *blob;
    if (!ctx_mem || (uintptr_t)ctx_mem % RENDER_WIDE_CTX_ALIGN) {
        fmt_snprintf(msg, cap, "wide context memory NULL or not aligned to %u",
                     (unsigned)RENDER_WIDE_CTX_ALIGN);
        return -1;
    }
    render_blob_status_t st = render_blob_open(block, size, &blob, &err);
    if (st == RENDER_BLOB_OK && !blob->frame) {
        fmt_snprintf(msg, cap, "the wide blob holds no prepared frame (%s)", NUM_NAME);
        return -1;
    }
    if (st != RENDER_BLOB_OK)
        return wide_result(st, &err, msg, cap);
    render_ctx_t *ctx = ctx_mem;
    render_ctx_init(ctx, blob->frame);
    ctx->options.use_bounds = use_bounds != 0;
    ctx->options.use_hierarchy = use_hierarchy != 0;
    ctx->options.mark_lost = mark_lost != 0;
    return 0;
}

rgb8_t RENDER_WIDE(wide_pixel)(void *arg, uint32_t x, uint32_t y, uint8_t *lost)
{
    render_ctx_t *ctx = arg;
    uint32_t before = ctx->stats.precision_lost_pixels;
    rgb8_t c = render_pixel(ctx, x, y);
    *lost = ctx->stats.precision_lost_pixels != before;
    return c;
}

void RENDER_WIDE(wide_stats_add)(const void *ctx_mem, render_stats_t *into)
{
    const render_stats_t *s = &((const render_ctx_t *)ctx_mem)->stats;
    into->primary += s->primary;
    into->primary_hit += s->primary_hit;
    into->shadow += s->shadow;
    into->reflection += s->reflection;
    into->refraction += s->refraction;
    into->transmission += s->transmission;
    into->box_tests += s->box_tests;
    into->prim_tests += s->prim_tests;
    into->primary_box_tests += s->primary_box_tests;
    into->primary_prim_tests += s->primary_prim_tests;
    into->weight_cut += s->weight_cut;
    into->self_blocked += s->self_blocked;
    into->screen_tests += s->screen_tests;
}
