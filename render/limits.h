/* render/limits.h: every limit of the renderer, in one place.
 *
 * The scene compiler checks a scene against these before it is uploaded, and
 * render_prepare() checks them again so a bad scene fails with a named limit
 * instead of reading out of bounds.
 */
#ifndef LINKS1_RENDER_LIMITS_H
#define LINKS1_RENDER_LIMITS_H

#include "proto/scene_format.h"

#define RENDER_MAX_WIDTH 1024         /* frame memory: 1024x1024 pixels */
#define RENDER_MAX_HEIGHT 1024
#define RENDER_MAX_LIGHTS SCN_MAX_LIGHTS /* one limit, defined once in
                                         proto/scene_format.h (16) */
#define RENDER_MAX_DEPTH 16           /* reflection/refraction recursion */
#define RENDER_MAX_CLUSTER_DEPTH 32   /* nesting of clusters below the root */
#define RENDER_MAX_TRANSPARENT 16     /* transmission buffer: objects crossed
                                         by one refractionless straight ray */
#define RENDER_MAX_DENSITY_COMPONENTS 64 /* components of one density sphere */
#define RENDER_MAX_PHONG_N 1024       /* highlight sharpness exponent */
#define RENDER_MAX_MAP_SIZE 1024      /* texels along one side of a map */
/* The NCs clip with the paper's lists while a frame's clusters cover a
 * pixel at most RENDER_CLIP_LISTS_MAX_COVERAGE times on average and a
 * scanline at most RENDER_CLIP_LISTS_MAX_ROWS times
 * (render_frame_t.clip_coverage, clip_rows), in the hierarchy above: on
 * the SPD tetra at 8 NCs the lists cost less a ray up to 264 clusters a
 * scanline, the hierarchy less from 401 (docs/results/board-scale.md). */
#define RENDER_CLIP_LISTS_MAX_COVERAGE 16
#define RENDER_CLIP_LISTS_MAX_ROWS 320

/* Density-sphere root finder: fixed iteration counts keep every build and
 * every core on exactly the same path.  The march steps that bracket a
 * root are the scene's option density_steps (proto/scene_format.h
 * SCN_DEFAULT_DENSITY_STEPS). */
#define RENDER_DENSITY_BISECTIONS 24  /* bisection steps once bracketed */



/* Stack a tracing core needs (render_pixel and everything below it),
 * measured with arm-none-eabi-gcc 12 -O2 -fstack-usage (float and fixed
 * builds): per level of reflection/refraction depth (the recursion,
 * trace_ray + trace_shade) 392 bytes in float, 416 in fixed since rays
 * carry their error bound (328 and 352 before), plus the deepest leaf
 * (refractionless transmission, lights, a shadow walk through up to
 * RENDER_MAX_CLUSTER_DEPTH clusters at 32 bytes each, a primitive test;
 * the walk itself is one frame, trace_cluster's 488 bytes in float with
 * its stack of put-off visits, well inside those 32 levels' 1,024):
 * 4096 before the near-first walk, which adds 8 bytes a level and keeps
 * trace_straight's 160 more bytes out of every level; the error bound
 * adds 56 to the leaf (trace_lights, trace_straight, trace_nearest), the
 * ambient's choice of light 8 more in float (trace_lights: 600 bytes in
 * float, 592 in fixed); the attribute maps' material (render_ctx_t.look)
 * 8 more in float's trace_shade and trace_lights (trace_ray 144 +
 * trace_shade 264 = 408 a level, trace_lights 616), none in fixed.  A
 * density sphere's test (its bound's per-component values, render/prim.h
 * PRIM_DENSITY_BOUND_MAX) makes the leaf's primitive test
 * prim_intersect_uncertain + prim_density_intersect + prim_density_ray:
 * 584 bytes in float, 672 in fixed on the A15 (664 on the M33), against
 * 312 and 400 before: 312 more. */
/* The firmware's render/ at -O3 (Makefile FW_HOT_SRCS; trace_nearest
 * kept out of the recursion's frames) has its own frames, measured
 * (-fstack-usage, gcc 12, every firmware build): a level of the recursion
 * (trace_ray + trace_shade) at most 496 bytes outside double (fixed on
 * the A15: 144 + 352) and 792 in double (the M33's software double: 248 +
 * 544); the leaf's frames grow in fixed by about 170 bytes against -O2
 * (trace_cluster 544, trace_lights 592, render_pixel_impl 208), in float
 * by under 60, in double by about 185 (the M33's trace_cluster 784,
 * trace_lights 1056). */
#define RENDER_STACK_O3 192
#define RENDER_STACK_O3_DOUBLE 256
#if defined(LINKS1_NUM_DOUBLE)
/* double (the board's double-precision VFP build, and the an521 boards'
 * software double): every num_t twice as wide; on the Cortex-A15
 * trace_ray + trace_shade take 216 + 472 = 688 bytes a level, and the
 * frames of the deepest leaf 1,168 more than in float (trace_lights 1048,
 * trace_straight 728, prim_intersect_uncertain 368, prim_surface 280,
 * render_pixel_impl 272), and the ambient's choice of light up to 16 more;
 * on the M33 (-fstack-usage) 224 + 512 = 736 a level and the leaf's
 * frames 216 bytes more (trace_lights 1144, trace_straight 856,
 * prim_intersect_uncertain 520, prim_surface 296), libgcc's double
 * routines a few words: the larger of the two; a density sphere's test 504
 * more (its leaf 992 bytes on the A15, 1,128 on the M33, against 544 and
 * 624 before).  About 22 KiB at max_depth 16 with RENDER_STACK_AA, within
 * TASK_STACK_SIZE (24 KiB; roles/dm_render.c checks it) */
#define RENDER_STACK_PER_DEPTH 792
#define RENDER_STACK_BASE (6920 + RENDER_STACK_O3_DOUBLE)
#define RENDER_STACK_AA 2048
#else
#define RENDER_STACK_PER_DEPTH 496
#define RENDER_STACK_BASE (4992 + RENDER_STACK_O3)
#define RENDER_STACK_AA 1216
#endif
/* Anti-aliasing (render/trace.c) between the pixel and its camera ray, at
 * SCN_MAX_AA_DEPTH 4 (-fstack-usage): four render_aa_quad frames (296
 * bytes in float and fixed, 504 in double on the Cortex-A15, 496 in the
 * M33's software double: its 3 x 3 samples), render_pixel_corners and
 * render_sample, less render_corner's frame they replace: 1,144 more in
 * float, 1,180 in fixed, 1,976 in double on the A15; 1,160 in fixed and
 * 1,976 in double on the M33; counted whether or not a scene
 * anti-aliases. */
#define RENDER_STACK_BYTES(max_depth) \
    (RENDER_STACK_BASE + RENDER_STACK_AA + RENDER_STACK_PER_DEPTH * ((max_depth) + 1))

/* Tolerances, in the units the scene is stored in (its largest length
 * scaled to 8..16, below; the fixed-point step is 2^-19 = 1.9e-6) times
 * 2^tol_exp (scene.h: the geometry's largest length at 8..16). */
#define RENDER_RAY_EPSILON_VALUE 2e-3   /* secondary rays start this far from
                                           the surface so they do not hit it
                                           again through rounding */
#define RENDER_BOUNDS_PAD_VALUE 1e-3    /* boxes grow by this so rounding
                                           never makes them cut a surface */
#define RENDER_EDGE_TOLERANCE_VALUE 1e-5 /* triangle edge slack: no cracks
                                           between triangles sharing an edge */
#define RENDER_NEAR_PLANE_VALUE 1e-2    /* boxes reaching nearer than this to
                                           the eye plane project to the whole
                                           screen */

/* Scaled to the scene (docs/renderer.md, "Lengths scaled to the scene"):
 * the loader multiplies every length by the power of two 2^unit_exp that
 * brings the scene's largest |length| into [2^RENDER_NORM_EXP,
 * 2^(RENDER_NORM_EXP+1)); the tolerances above apply to the scaled scene
 * (times 2^tol_exp), so a scene scaled by any power of two renders the
 * same, bit for bit. */
#ifndef RENDER_NORM_EXP /* overridable to measure (docs/results/sweeps.md) */
#define RENDER_NORM_EXP 3
#endif
#define RENDER_TOL_SLACK_EXP 3 /* the tolerances follow the scene's largest
                                    length, but stay within 2^3 of the
                                    geometry's (scene_t.tol_exp) */
#define RENDER_TOL_EXP_MIN (-6) /* and down to 2^-6 of the above: in fixed
                                     point the ray offset stays 16 steps or
                                     more */
#define RENDER_NORM_EXP_MIN (-100) /* 2^unit_exp stays within (a scene whose
                                      clusters' scales take it beyond is
                                      refused by the loader) */
#define RENDER_NORM_EXP_MAX 120

/* Precision (docs/renderer.md, "Precision never fails silently"). */
#define RENDER_MIN_SPAN_VALUE 1.0       /* a scene spans at least this (its
                                           stored units, as the tolerances):
                                           500 ray offsets; smaller scenes are
                                           refused (RENDER_ERR_EXTENT) */
#define RENDER_MIN_DETAIL_STEPS 2        /* a primitive's smallest size
                                           (semi-axis, half edge, triangle
                                           height, component radius) in
                                           steps of the arithmetic where it
                                           lies: rounded by half a step, a
                                           smaller one is off by more than a
                                           quarter (RENDER_ERR_DETAIL) */
#define RENDER_INVERSE_TOLERANCE_VALUE 1e-3 /* |M * M^-1 - I| of a cluster map
                                           beyond this: RENDER_ERR_SCALE */
#define RENDER_MAP_TEXEL_TOLERANCE_VALUE (1.0 / 64) /* map lookups: render/maps.h;
                                           a bilinear colour moves by at most
                                           this times the step between two
                                           texels: 4/255 at a full-scale step */
#define RENDER_LOST_WEIGHT_VALUE (1.0 / 128) /* a reflected, refracted or
                                           straight ray weighing less (its
                                           src and trc along the path) moves
                                           a pixel by under 2/255 when its
                                           colour is at most 1: the error it
                                           carries is not counted in its
                                           decisions (render/trace.c) */
#define RENDER_HAZE_LOST_VALUE (1.0 / 255) /* a pixel whose haze weight's
                                           uncertainty, times how far its
                                           colour lies from the haze's and
                                           the ray's weight, may reach this
                                           is flagged (render/haze.c) */
/* Escalating (render/wide.h), a decision counts as lost when it is closer
 * than this many times the ray's error bound.  On demo.scn at 320x240
 * fixed point's bounds missed 10 pixels beyond 2/255 of double, in
 * secondary rays: 3 at 8 times, none at 16.  Float's missed one, an edge
 * moved by under a pixel, at 1 and at 16 alike (docs/renderer.md). */
/* --check-lost (render_options_t.check_lost): a pixel that lost precision
 * stays lost when its double colour is more than this many 1/255 steps
 * away in a channel: what RENDER_LOST_MEANING calls off. */
#define RENDER_CHECK_LOST_STEPS 2
#ifndef RENDER_ESCALATE_MARGIN
#ifdef LINKS1_NUM_FIXED
#define RENDER_ESCALATE_MARGIN 16
#else
#define RENDER_ESCALATE_MARGIN 1
#endif
#endif
#define RENDER_LOST_TOLERANCE_VALUE 5e-2 /* a primitive whose estimated hit
                                           point error exceeds this (stored
                                           units) is imprecise; so is one whose
                                           error across its flattest side
                                           exceeds half the ray offset */
#endif
