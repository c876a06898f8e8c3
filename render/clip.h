/* render/clip.h: the NC's screen clipping (paper, section 4, item 4) and
 * the NC's whole job on one area.
 *
 * The DM's render_prepare projected every cluster's own bounding box to a
 * screen rectangle (render_cluster_t.screen_*, inclusive, conservative).
 * With render_clip_options_t.lists clear the NC clips in the hierarchy:
 * per pixel, render_pixel_screen (render.h) skips every subtree whose
 * rectangle misses the pixel, with no set-up per area.  With lists set,
 * the paper's way (the NC chooses per frame: roles/nc_render.c,
 * render/limits.h); an NC given an area:
 *   Y clipping, once per area: keeps the clusters whose rectangle meets the
 *     area's scanlines (and columns), sorted by screen_x0 (ties: index).
 *     It walks down the hierarchy and skips each subtree whose tree
 *     rectangle (render_cluster_t.tree_*) misses the area, so it costs
 *     about the clusters near the area, not every cluster of the scene;
 *   X clipping, per pixel: of those, the clusters whose [screen_x0,
 *     screen_x1] holds the pixel's x.  Integer compares only; along a row
 *     the sort makes it a moving window: clusters enter when x reaches
 *     their screen_x0 and leave once x passes their screen_x1.  Entering
 *     clusters are kept in order of their box's near depth, so the primary
 *     ray finds near hits first and rejects the boxes behind them.
 * The primary ray then tests only those clusters' own primitives
 * (render_pixel_clipped); secondary rays use the whole hierarchy.  The
 * image is the same bit for bit with clipping on or off.
 *
 * Memory: the caller gives render_clip_bytes(frame) bytes (two lists of
 * cluster indices); nothing else is allocated.
 */
#ifndef LINKS1_RENDER_CLIP_H
#define LINKS1_RENDER_CLIP_H

#include <stddef.h>
#include <stdint.h>

#include "render/render.h"

/* A rectangle of whole pixels: top-left (x, y), w x h, both >= 1 (the
 * same shape as the RC's areas). */
typedef struct {
    uint32_t x, y, w, h;
} render_area_t;

typedef struct {
    const render_frame_t *frame;
    uint32_t *ylist;      /* Y-clipped clusters, sorted by (screen_x0, index) */
    uint32_t ycount;
    uint32_t *xlist;      /* X-clipped: those of ylist whose X range holds x,
                             nearest own box (own_bounds.lo.z) first; also
                             the merge sort's scratch */
    uint32_t xcount;
    uint32_t next;        /* ylist[next..] start right of x */
    int32_t x;            /* x of the last X clipping; -1 after Y clipping */
    uint64_t y_kept;      /* sum of ycount over Y clippings (statistics) */
    uint64_t x_kept;      /* sum of xcount over X clippings (statistics) */
    render_corner_t *corners; /* corner mode (render_corner_mode): two rows
                                 of width + 1 corner rays (render_area),
                                 else NULL */
} render_clip_t;

/* Switches of render_area, each a speed-up that can be turned off for
 * measurement without changing the image.  Bounding boxes and the
 * hierarchy are ctx->options.use_bounds / use_hierarchy. */
typedef struct {
    uint8_t y_clip; /* 1: Y clipping per area; 0: every cluster with a
                       rectangle, sorted the same way */
    uint8_t x_clip; /* 1: X clipping per pixel; 0: the whole Y list */
    volatile uint32_t *progress; /* if set, +1 per pixel done: whoever watches
                                    for a stalled renderer reads it */
    uint8_t lists;  /* with y_clip and x_clip: 1, the paper's lists (a Y list
                       per area, an X window per pixel); 0, the same
                       clipping done in the hierarchy per pixel
                       (render_pixel_screen): no set-up per area, and a cost
                       per pixel that follows the tree's depth, not the
                       clusters near the area */
} render_clip_options_t;

/* Working-set bytes an NC needs for this frame's clipping (and with
 * corner mode, render_corner_mode, two rows of corner rays). */
size_t render_clip_bytes(const render_frame_t *frame);

/* Sets up clipping for frame in memory[0..bytes) (4-byte aligned);
 * RENDER_ERR_ARENA when bytes < render_clip_bytes(frame). */
render_status_t render_clip_init(render_clip_t *clip, const render_frame_t *frame, void *memory,
                                 size_t bytes);

/* Y clipping: ylist = the clusters whose screen rectangle meets the area
 * (rows y..y+h-1, columns x..x+w-1), sorted by (screen_x0, index); with
 * all = 1, every cluster with a non-empty rectangle instead.  Returns
 * ycount; resets the X window. */
uint32_t render_clip_y(render_clip_t *clip, const render_area_t *area, int all);

/* X clipping at column x: the clusters of ylist whose [screen_x0,
 * screen_x1] holds x, in clip->xlist; returns their count.  Cheapest when
 * x does not decrease between calls (one row left to right); a smaller x
 * restarts the window. */
uint32_t render_clip_x(render_clip_t *clip, int32_t x);

/* The NC's job on one area: Y clipping once, then for each pixel X
 * clipping, tracing, and its colour into out[(py - y) * w + (px - x)].
 * RENDER_ERR_AREA if the area is empty or not inside the screen.  With
 * both clip switches off, the primary ray walks the tree like render_pixel.
 * Statistics go to ctx->stats and clip->y_kept / x_kept.
 * In corner mode (render_corner_mode) it traces the area's (w + 1) x
 * (h + 1) corner rays, each once, and each pixel is made of its four
 * (render_pixel_of_corners: their mean, or anti-aliased); a corner counts
 * in ctx->stats when the area owns it: its pixel's top-left corner, and
 * the corners on the screen's right and bottom edges, so that any areas
 * covering the screen count each corner once (an anti-aliased pixel's own
 * rays always count).  It needs clip set up (render_clip_init) whatever
 * the switches. */
render_status_t render_area(render_ctx_t *ctx, render_clip_t *clip, const render_area_t *area,
                            const render_clip_options_t *opt, rgb8_t *out);
/* render_area, calling mark(arg) (when mark is not NULL) once after the
 * area's set-up (Y clipping) and once after each pixel, in raster order:
 * the NC's trace marks and its asking ahead (roles/nc_render.c,
 * docs/trace.md). */
render_status_t render_area_marked(render_ctx_t *ctx, render_clip_t *clip,
                                   const render_area_t *area, const render_clip_options_t *opt,
                                   rgb8_t *out, void (*mark)(void *arg), void *arg);

#endif
