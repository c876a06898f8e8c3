/* render/clip.c: Y and X screen clipping and the NC's area loop (see
 * clip.h).  Integer compares on the DM's screen rectangles only. */
#include "render/clip.h"

#include <string.h>

/* Two rows of corner rays, with room to align them. */
static size_t clip_corner_bytes(const render_frame_t *frame)
{
    if (!render_corner_mode(&frame->options))
        return 0;
    return 2 * sizeof(render_corner_t) * ((size_t)frame->width + 1) + _Alignof(render_corner_t);
}

size_t render_clip_bytes(const render_frame_t *frame)
{
    /* ylist and xlist, one entry per cluster each */
    return 2 * sizeof(uint32_t) * (size_t)frame->cluster_count + clip_corner_bytes(frame);
}

render_status_t render_clip_init(render_clip_t *clip, const render_frame_t *frame, void *memory,
                                 size_t bytes)
{
    memset(clip, 0, sizeof *clip);
    if (!memory || (uintptr_t)memory % _Alignof(uint32_t) != 0 || bytes < render_clip_bytes(frame))
        return RENDER_ERR_ARENA;
    clip->frame = frame;
    clip->ylist = memory;
    clip->xlist = clip->ylist + frame->cluster_count;
    clip->x = -1;
    if (render_corner_mode(&frame->options)) {
        uintptr_t at = (uintptr_t)(clip->xlist + frame->cluster_count);
        at = (at + _Alignof(render_corner_t) - 1) & ~(uintptr_t)(_Alignof(render_corner_t) - 1);
        clip->corners = (render_corner_t *)at;
    }
    return RENDER_OK;
}

/* Cluster a goes before cluster b in a Y list. */
static int clip_before(const render_cluster_t *cl, uint32_t a, uint32_t b)
{
    return cl[a].screen_x0 < cl[b].screen_x0 || (cl[a].screen_x0 == cl[b].screen_x0 && a < b);
}

/* Bottom-up merge sort of ylist by (screen_x0, index), xlist as scratch:
 * n log n compares even for the thousands of clusters of a city. */
static void clip_sort(render_clip_t *clip)
{
    const render_cluster_t *cl = clip->frame->clusters;
    uint32_t n = clip->ycount;
    uint32_t *src = clip->ylist, *dst = clip->xlist;
    for (uint32_t width = 1; width < n; width *= 2) {
        for (uint32_t lo = 0; lo < n; lo += 2 * width) {
            uint32_t mid = lo + width < n ? lo + width : n;
            uint32_t hi = lo + 2 * width < n ? lo + 2 * width : n;
            uint32_t i = lo, j = mid, k = lo;
            while (i < mid && j < hi)
                dst[k++] = clip_before(cl, src[j], src[i]) ? src[j++] : src[i++];
            while (i < mid)
                dst[k++] = src[i++];
            while (j < hi)
                dst[k++] = src[j++];
        }
        uint32_t *t = src;
        src = dst;
        dst = t;
    }
    if (src != clip->ylist)
        memcpy(clip->ylist, src, n * sizeof *src);
}

static void clip_x_restart(render_clip_t *clip)
{
    clip->xcount = 0;
    clip->next = 0;
    clip->x = -1;
}

/* The area in signed pixels, inclusive, like the rectangles. */
typedef struct {
    int32_t x0, y0, x1, y1;
} clip_rect_t;

/* Rectangle (x0, y0)-(x1, y1) is not empty and meets a. */
static int clip_meets(int32_t x0, int32_t y0, int32_t x1, int32_t y1, const clip_rect_t *a)
{
    return x0 <= x1 && y0 <= y1 && x1 >= a->x0 && x0 <= a->x1 && y1 >= a->y0 && y0 <= a->y1;
}

/* The clusters whose rectangle meets a, into ylist (in no particular
 * order): a walk down the tree from the root that skips every subtree
 * whose tree rectangle misses a, so its cost follows the clusters near the
 * area rather than the scene's size.  xlist is the walk's stack: each
 * cluster is pushed at most once. */
static uint32_t clip_walk(render_clip_t *clip, const clip_rect_t *a)
{
    const render_frame_t *f = clip->frame;
    const render_cluster_t *cl = f->clusters;
    uint32_t *stack = clip->xlist, top = 0, n = 0;
    if (f->cluster_count > 0 && clip_meets(cl[0].tree_x0, cl[0].tree_y0, cl[0].tree_x1, cl[0].tree_y1, a))
        stack[top++] = 0;
    while (top > 0) {
        uint32_t i = stack[--top];
        const render_cluster_t *c = &cl[i];
        if (clip_meets(c->screen_x0, c->screen_y0, c->screen_x1, c->screen_y1, a))
            clip->ylist[n++] = i;
        const uint32_t *kids = &f->child_list[c->first_child];
        for (uint32_t k = 0; k < c->child_count; k++) {
            const render_cluster_t *d = &cl[kids[k]];
            if (clip_meets(d->tree_x0, d->tree_y0, d->tree_x1, d->tree_y1, a))
                stack[top++] = kids[k];
        }
    }
    return n;
}

uint32_t render_clip_y(render_clip_t *clip, const render_area_t *area, int all)
{
    const render_frame_t *f = clip->frame;
    uint32_t n = 0;
    if (all) {
        for (uint32_t i = 0; i < f->cluster_count; i++) {
            const render_cluster_t *c = &f->clusters[i];
            if (c->screen_x0 <= c->screen_x1 && c->screen_y0 <= c->screen_y1)
                clip->ylist[n++] = i; /* else no primitives, or wholly behind the eye */
        }
    } else {
        clip_rect_t a = {(int32_t)area->x, (int32_t)area->y, (int32_t)(area->x + area->w) - 1,
                         (int32_t)(area->y + area->h) - 1};
        n = clip_walk(clip, &a);
    }
    clip->ycount = n;
    clip->y_kept += n;
    clip_sort(clip);
    clip_x_restart(clip);
    return n;
}

uint32_t render_clip_x(render_clip_t *clip, int32_t x)
{
    const render_cluster_t *cl = clip->frame->clusters;
    if (x < clip->x)
        clip_x_restart(clip);
    clip->x = x;
    /* drop the clusters x has passed; the rest keep their order */
    uint32_t k = 0;
    for (uint32_t i = 0; i < clip->xcount; i++)
        if (cl[clip->xlist[i]].screen_x1 >= x)
            clip->xlist[k++] = clip->xlist[i];
    /* take in those starting at or before x: the sort lets the scan stop
     * at the first one starting right of x.  Each enters the list in
     * order of its box's near z (then arrival): the primary ray meets the
     * nearest clusters first, so its nearest hit so far rejects the boxes
     * behind it sooner (fewer primitive tests, same image: ties never
     * depend on order, see trace.c) */
    uint32_t next = clip->next;
    while (next < clip->ycount && cl[clip->ylist[next]].screen_x0 <= x) {
        uint32_t c = clip->ylist[next++];
        if (cl[c].screen_x1 < x)
            continue;
        uint32_t j = k++;
        while (j > 0 && num_lt(cl[c].own_bounds.lo.z, cl[clip->xlist[j - 1]].own_bounds.lo.z)) {
            clip->xlist[j] = clip->xlist[j - 1];
            j--;
        }
        clip->xlist[j] = c;
    }
    clip->next = next;
    clip->xcount = k;
    clip->x_kept += k;
    return k;
}

render_status_t render_area(render_ctx_t *ctx, render_clip_t *clip, const render_area_t *area,
                            const render_clip_options_t *opt, rgb8_t *out)
{
    return render_area_marked(ctx, clip, area, opt, out, NULL, NULL);
}

/* The corner rays of row cy, columns x0..x1 (inclusive), into row[0..]:
 * searched as the pixels would be (in_tree: by screen; clipping: the X
 * window, or the whole Y list), counted where the area owns them (own_x1:
 * the last column's too). */
static void clip_corner_row(render_ctx_t *ctx, render_clip_t *clip, uint32_t cy, uint32_t x0,
                            uint32_t x1, int own_x1, int own_row, int in_tree, int clipping,
                            const render_clip_options_t *opt, render_corner_t *row)
{
    const render_frame_t *f = ctx->frame;
    for (uint32_t cx = x0; cx <= x1; cx++) {
        int counted = own_row && (cx < x1 || own_x1);
        render_corner_t *c = &row[cx - x0];
        if (in_tree) {
            render_corner(ctx, cx, cy, RENDER_CORNER_SCREEN, NULL, 0, counted, c);
        } else if (!clipping) {
            render_corner(ctx, cx, cy, RENDER_CORNER_TREE, NULL, 0, counted, c);
        } else if (opt->x_clip) {
            uint32_t n = render_clip_x(clip, (int32_t)(cx < f->width ? cx : cx - 1u));
            render_corner(ctx, cx, cy, RENDER_CORNER_LIST, clip->xlist, n, counted, c);
        } else {
            render_corner(ctx, cx, cy, RENDER_CORNER_LIST, clip->ylist, clip->ycount, counted, c);
        }
    }
}

/* Pixel (px, py) of corner mode from its corners c, its anti-aliasing's
 * rays (when it has any: depth > 0) searched as its own would be. */
static rgb8_t clip_pixel_of_corners(render_ctx_t *ctx, render_clip_t *clip, uint32_t px,
                                    uint32_t py, const render_corner_t c[4], int in_tree,
                                    int clipping, const render_clip_options_t *opt)
{
    if (!ctx->options.antialias || ctx->options.aa_depth == 0 || in_tree)
        return render_pixel_of_corners(ctx, px, py, c, RENDER_CORNER_SCREEN, NULL, 0);
    if (!clipping)
        return render_pixel_of_corners(ctx, px, py, c, RENDER_CORNER_TREE, NULL, 0);
    if (opt->x_clip) {
        uint32_t n = render_clip_x(clip, (int32_t)px);
        return render_pixel_of_corners(ctx, px, py, c, RENDER_CORNER_LIST, clip->xlist, n);
    }
    return render_pixel_of_corners(ctx, px, py, c, RENDER_CORNER_LIST, clip->ylist,
                                   clip->ycount);
}

/* render_area in corner mode: the top row of corners, then per pixel row
 * the row below and the pixels between the two. */
static render_status_t clip_area_corners(render_ctx_t *ctx, render_clip_t *clip,
                                         const render_area_t *area,
                                         const render_clip_options_t *opt, int in_tree,
                                         int clipping, rgb8_t *out, void (*mark)(void *arg),
                                         void *arg)
{
    const render_frame_t *f = ctx->frame;
    if (clip->frame != f || !clip->corners)
        return RENDER_ERR_AREA;
    uint32_t x1 = area->x + area->w, y1 = area->y + area->h;
    int own_x1 = x1 == f->width, own_y1 = y1 == f->height;
    render_corner_t *top = clip->corners, *bottom = clip->corners + f->width + 1;
    clip_corner_row(ctx, clip, area->y, area->x, x1, own_x1, 1, in_tree, clipping, opt, top);
    for (uint32_t py = area->y; py < y1; py++) {
        clip_corner_row(ctx, clip, py + 1, area->x, x1, own_x1, py + 1 < y1 || own_y1, in_tree,
                        clipping, opt, bottom);
        rgb8_t *row = out + (size_t)(py - area->y) * area->w;
        for (uint32_t px = area->x; px < x1; px++) {
            uint32_t i = px - area->x;
            render_corner_t c[4] = {top[i], top[i + 1], bottom[i], bottom[i + 1]};
            row[i] = clip_pixel_of_corners(ctx, clip, px, py, c, in_tree, clipping, opt);
            if (opt->progress)
                *opt->progress += 1;
            if (mark)
                mark(arg);
        }
        render_corner_t *t = top;
        top = bottom;
        bottom = t;
    }
    return RENDER_OK;
}

render_status_t render_area_marked(render_ctx_t *ctx, render_clip_t *clip,
                                   const render_area_t *area, const render_clip_options_t *opt,
                                   rgb8_t *out, void (*mark)(void *arg), void *arg)
{
    const render_frame_t *f = ctx->frame;
    if (area->w == 0 || area->h == 0 || area->x >= f->width || area->w > f->width - area->x ||
        area->y >= f->height || area->h > f->height - area->y)
        return RENDER_ERR_AREA;
    /* a world-space frame has no screen rectangles to clip by */
    int in_tree = opt->y_clip && opt->x_clip && !opt->lists && !f->world;
    int clipping = (opt->y_clip || opt->x_clip) && !in_tree && !f->world;
    if (clipping) {
        if (clip->frame != f)
            return RENDER_ERR_AREA;
        render_clip_y(clip, area, !opt->y_clip);
    }
    if (mark)
        mark(arg);
    if (render_corner_mode(&ctx->options))
        return clip_area_corners(ctx, clip, area, opt, in_tree, clipping, out, mark, arg);
    for (uint32_t py = area->y; py < area->y + area->h; py++) {
        rgb8_t *row = out + (size_t)(py - area->y) * area->w;
        for (uint32_t px = area->x; px < area->x + area->w; px++) {
            rgb8_t c;
            if (in_tree) {
                c = render_pixel_screen(ctx, px, py);
            } else if (!clipping) {
                c = render_pixel(ctx, px, py);
            } else if (opt->x_clip) {
                uint32_t n = render_clip_x(clip, (int32_t)px);
                c = render_pixel_clipped(ctx, px, py, clip->xlist, n);
            } else {
                c = render_pixel_clipped(ctx, px, py, clip->ylist, clip->ycount);
            }
            row[px - area->x] = c;
            if (opt->progress)
                *opt->progress += 1;
            if (mark)
                mark(arg);
        }
    }
    return RENDER_OK;
}
