/* render/wide.h: the renderer a second time, in the wide arithmetic
 * (double), in the same program: escalation.
 *
 * A pixel whose error bound is over its margin (it "lost precision") is
 * traced again in the wide arithmetic by the same unit computer and takes
 * that colour (render_ctx_t.escalate, render/render.h).  The wide copy is
 * not written twice: render/wide.c and the rest of the renderer are
 * compiled once more with LINKS1_NUM_DOUBLE, and every global symbol of
 * that copy is renamed wide_NAME when it is linked (the Makefile's "wide
 * renderer" rules), so the two copies live side by side.  The entry points
 * below are the only way in, and they take and give only types that are
 * the same in every arithmetic (bytes, sizes, rgb8_t, render_stats_t,
 * scene_load_known_t).
 *
 *   DM: wide_blob_bytes, then wide_blob_load once per scene and block and
 *       wide_blob_prepare every frame (without screen rectangles:
 *       RENDER_PREP_NO_SCREEN), into the part of the IMSU block past
 *       the narrow blob's bound (render_blob_t.wide_offset says where).
 *   RC: wide_blob_copy_frame, after render_blob_copy_frame, at the same
 *       offset of the broadcast block.
 *   NC: wide_ctx_open on the broadcast block's wide blob, then
 *       ctx.escalate = wide_pixel, ctx.escalate_arg = the wide context.
 *
 * Board = host: wide_pixel is the double build's render_pixel, so an
 * escalated pixel is the double build's pixel bit for bit.
 */
#ifndef LINKS1_RENDER_WIDE_H
#define LINKS1_RENDER_WIDE_H

#include <stddef.h>
#include <stdint.h>

#include "render/limits.h"
#include "render/render.h"
#include "render/scene_load.h"

/* The names the wide copy's entry points have once renamed; render/wide.c
 * itself (compiled before the renaming) defines them as written. */
#ifdef LINKS1_WIDE_COPY
#define RENDER_WIDE(name) name
#define RENDER_WIDE_WEAK
#else
#define RENDER_WIDE(name) wide_##name
/* Weak references: a program without the wide copy links, and
 * render_wide_linked() tells it so. */
#define RENDER_WIDE_WEAK __attribute__((weak))
#endif

/* The wide arithmetic's name ("double"). */
RENDER_WIDE_WEAK extern const char RENDER_WIDE(wide_arith_name)[];

/* Each entry point returns 0, or -1 with a message (at most cap bytes,
 * NUL-terminated) naming the problem. */

/* Bytes the wide blob of this compiled scene needs at most (any frame). */
RENDER_WIDE_WEAK int RENDER_WIDE(wide_blob_bytes)(const uint8_t *compiled, size_t len, size_t *bytes, char *msg,
                                 size_t cap);
/* render_blob_load_summed in the wide arithmetic into block[0..size)
 * (aligned to RENDER_RELOCATE_ALIGN), numbered scene_id; known: what the
 * narrow load of the same bytes found (scene_load_known_of), or NULL. */
RENDER_WIDE_WEAK int RENDER_WIDE(wide_blob_load)(const uint8_t *compiled, size_t len,
                                                 const scene_load_known_t *known, void *block,
                                                 size_t size,
                                                 const char *limit_name, uint32_t scene_id,
                                                 char *msg, size_t cap);
/* render_blob_prepare of frame_index in the wide blob at block. */
RENDER_WIDE_WEAK int RENDER_WIDE(wide_blob_prepare)(void *block, uint32_t frame_index, size_t size, char *msg,
                                   size_t cap);
/* render_blob_copy_frame of the wide blob at src into block[0..size). */
RENDER_WIDE_WEAK int RENDER_WIDE(wide_blob_copy_frame)(void *block, size_t size, const void *src, char *msg,
                                      size_t cap);

/* Stack between an NC's render_area and the wide renderer, on top of the
 * wide renderer's own: the narrow render_pixel and wide_pixel frames. */
#define RENDER_WIDE_CALL_STACK 256
/* Stack the wide renderer takes for max_depth (its RENDER_STACK_BYTES). */
RENDER_WIDE_WEAK size_t RENDER_WIDE(wide_stack_bytes)(uint32_t max_depth);
/* Bytes of a wide context (for wide_ctx_open), and its alignment. */
RENDER_WIDE_WEAK size_t RENDER_WIDE(wide_ctx_bytes)(void);
#define RENDER_WIDE_CTX_ALIGN 8
/* A wide context in ctx_mem (wide_ctx_bytes, RENDER_WIDE_CTX_ALIGN) on
 * the wide blob at block (relocated there), with the narrow context's
 * switches: bounding boxes, the hierarchy, mark_lost. */
RENDER_WIDE_WEAK int RENDER_WIDE(wide_ctx_open)(void *ctx_mem, const void *block, size_t size, int use_bounds,
                               int use_hierarchy, int mark_lost, char *msg, size_t cap);
/* The escalation: pixel (x, y) in the wide arithmetic (arg: the wide
 * context); *lost = 1 when it lost precision there too. */
RENDER_WIDE_WEAK rgb8_t RENDER_WIDE(wide_pixel)(void *arg, uint32_t x, uint32_t y, uint8_t *lost);
/* Adds the wide context's rays and tests to *into (not its lost or
 * escalated pixels: the narrow context counts those). */
RENDER_WIDE_WEAK void RENDER_WIDE(wide_stats_add)(const void *ctx_mem, render_stats_t *into);

#ifndef LINKS1_WIDE_COPY
/* ctx escalating into the wide context wide_ctx (wide_ctx_open), its
 * decisions' error bounds widened RENDER_ESCALATE_MARGIN times. */
static inline void render_wide_escalate(render_ctx_t *ctx, void *wide_ctx)
{
    ctx->escalate = RENDER_WIDE(wide_pixel);
    ctx->escalate_arg = wide_ctx;
    ctx->error_margin = RENDER_ESCALATE_MARGIN;
}

/* 1 when this program carries the wide copy (the escalating firmware
 * builds, links1-ref-float and -fixed), 0 when it does not. */
static inline int render_wide_linked(void)
{
    return &RENDER_WIDE(wide_pixel) != 0;
}
#endif

#endif
