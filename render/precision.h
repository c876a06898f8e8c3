/* render/precision.h: render_prepare's guards against a wrong image that
 * looks right (docs/renderer.md, "Precision never fails silently").
 *
 *   precision_invert   a cluster map's inverse, refused when the arithmetic
 *                      cannot form it to RENDER_INVERSE_TOLERANCE_VALUE
 *                      (RENDER_ERR_SCALE) or it is singular
 *   precision_detail   a primitive smaller than the arithmetic resolves
 *                      where it lies (RENDER_ERR_DETAIL)
 *   precision_check    the scene's span (RENDER_ERR_EXTENT under
 *                      RENDER_MIN_SPAN_VALUE) and each primitive's estimated
 *                      hit error (render_prim_t.imprecise)
 */
#ifndef LINKS1_RENDER_PRECISION_H
#define LINKS1_RENDER_PRECISION_H

#include "render/render.h"
#include "render/vec3.h"

render_status_t precision_invert(const xform_t *m, xform_t *inv);

/* How far a primitive mapped into its cluster by from_eye (the inverse the
 * arithmetic formed) may lie from where to_eye puts it: |to_eye o from_eye
 * - I| at the farthest point of its eye-space bounds, in eye units (a
 * fixed-point inverse of a cluster scaled by 0.1 was off by 6e-4 of its
 * values before xform_invert worked at unit size; a few steps now).
 * render_prepare leaves it in the primitive's hit_error. */
num_t precision_map_error(const xform_t *to_eye, const xform_t *from_eye, const aabb_t *bounds);

/* After the boxes are known: sets frame->span and every prim's imprecise
 * flag, hit, edge and uv errors, scale and curvature; RENDER_ERR_EXTENT
 * when the scene is too small.  ix: the scene's index (render_prepare's,
 * the loader's or its own). */
render_status_t precision_check(render_frame_t *f, const scene_index_t *ix);

/* precision_check in three parts, for a frame that prepares only some of
 * its primitives again (render_prepare_again): _begin sets the span and
 * the extent from the root's box (and f->precision_lost when they
 * saturate) and what every primitive's check needs; _prims checks the
 * count primitives list names (0 to count - 1 when list is NULL), once
 * render_prepare has mapped them; _end is precision_check's status. */
typedef struct {
    num_t extent, lost_tol, acne_tol, detail_at_extent, point;
    int detail_fast;
} precision_pass_t;
precision_pass_t precision_check_begin(render_frame_t *f);
void precision_check_prims(render_frame_t *f, const scene_index_t *ix, const precision_pass_t *pass,
                           const uint32_t *list, uint32_t count);
render_status_t precision_check_end(const render_frame_t *f);

/* A world-space frame's extent (render_frame_t.precision_extent): the
 * power of two at or above the box's largest coordinate magnitude and the
 * eye's, so that a camera moving within it leaves every bound the same. */
num_t precision_world_extent(num_t box, vec3_t eye);

/* For prim i, once its eye-space bounds are known (to_eye: its cluster's
 * map): records it in f->detail_* when its smallest size, in eye units or
 * in its cluster's, is under RENDER_MIN_DETAIL_STEPS steps of the
 * arithmetic where it lies; precision_check then returns
 * RENDER_ERR_DETAIL.  f->detail_prim starts as RENDER_NO_PRIM.  A
 * triangle's is precision_check's (render_prepare calls this for the
 * other kinds). */
void precision_detail(render_frame_t *f, uint32_t i, const xform_t *to_eye);

/* Records prim i in f->detail_* when size, at a place whose largest
 * |coordinate| is reach, is under RENDER_MIN_DETAIL_STEPS steps there
 * (fixed: one step anywhere; float, double: 2^-23, 2^-52 of reach), and
 * no primitive before it is recorded (triangles are checked after the
 * others: the first in index order wins either way).  A saturated value
 * is left to the precision flag.  Inline: the DM runs it for every
 * primitive of every frame. */
static inline void precision_detail_one(render_frame_t *f, uint32_t i, num_t size, num_t reach)
{
    num_t step = num_ulp(reach);
    if (f->detail_prim <= i || num_is_sat(size) || num_is_sat(reach) ||
        num_is_sat(step) || !num_lt(size, num_mul_int(step, RENDER_MIN_DETAIL_STEPS)))
        return;
    f->detail_prim = i;
    f->detail_size = size;
    f->detail_step = step;
}

/* precision_detail of a triangle (precision_check runs it for the few
 * triangles whose smaller height is under the steps at the scene's
 * extent): its smaller height, in eye units (in its own the loader
 * refuses slivers), where its box reaches.  A triangle's box has lo <= hi
 * (its vertices' least and largest, padded), so its largest |coordinate|
 * on an axis is max(-lo, hi): the value max(|lo|, |hi|) has, without the
 * two absolute values.  A box with a NaN has NaN heights too, which
 * precision_detail_one passes over before it looks at the reach. */
static inline void precision_detail_triangle(render_frame_t *f, uint32_t i)
{
    const render_prim_t *p = &f->prims[i];
    const aabb_t *b = &p->bounds;
    num_t reach = NUM_ZERO;
    reach = num_max(reach, num_max(num_neg(b->lo.x), b->hi.x));
    reach = num_max(reach, num_max(num_neg(b->lo.y), b->hi.y));
    reach = num_max(reach, num_max(num_neg(b->lo.z), b->hi.z));
    precision_detail_one(f, i, num_min(num_abs(p->height1), num_abs(p->height2)), reach);
}

/* The message of RENDER_ERR_DETAIL with the numbers: the primitive (kind,
 * index), its size, the arithmetic's step there and the scene's span. */
void precision_detail_message(const render_frame_t *f, char *out, size_t cap);

/* The message of RENDER_ERR_EXTENT with the numbers: the scene's span,
 * what the arithmetic resolves and the span needed. */
void precision_extent_message(const render_frame_t *f, char *out, size_t cap);

/* render_prepare's status st as a message: with the numbers for
 * RENDER_ERR_EXTENT and RENDER_ERR_DETAIL (f: the frame render_prepare
 * set), else render_status_name. */
void precision_status_message(const render_frame_t *f, render_status_t st, char *out, size_t cap);

#endif
