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
 * when the scene is too small. */
render_status_t precision_check(render_frame_t *f);

/* For prim i, once its eye-space bounds are known (to_eye: its cluster's
 * map): records it in f->detail_* when its smallest size, in eye units or
 * in its cluster's, is under RENDER_MIN_DETAIL_STEPS steps of the
 * arithmetic where it lies; precision_check then returns
 * RENDER_ERR_DETAIL.  f->detail_prim starts as RENDER_NO_PRIM. */
void precision_detail(render_frame_t *f, uint32_t i, const xform_t *to_eye);

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
