/* render/render.h: what the host tool and the board's DM and NCs call.
 *
 *   DM:  render_prepare(scene, frame_index, arena, &frame)
 *        evaluates keyframes, maps everything to world then eye coordinates,
 *        computes every cluster's bounding box and screen rectangle.
 *   NC:  render_ctx_init(&ctx, frame); then per pixel
 *        render_pixel(&ctx, x, y)            full traversal, or
 *        render_pixel_clipped(&ctx, x, y, list, n)
 *                                            primary ray tests only the
 *                                            listed clusters (screen clipping)
 *        ctx.stats counts rays and pixels whose precision was lost.
 *        render_area (render/clip.h) does an NC's whole area: Y clipping
 *        once, X clipping per pixel, render_pixel_clipped.
 *   The DM's scene and frame travel as one relocatable block:
 *        render/blob.h (build, size bound, relocate after a copy).
 *
 * No global or static mutable state anywhere in render/ and fixed/: every
 * core may run these at once on shared memory.  A prepared frame is read-only
 * once render_prepare returns; each core keeps its own render_ctx_t.
 * Memory: render_prepare_bytes(scene) of arena for the DM's frame; tracing
 * allocates nothing but needs RENDER_STACK_BYTES(max_depth) of stack
 * (render/limits.h).  Same scene, same arithmetic: the same pixels on any
 * core, in any traversal mode (docs/renderer.md).
 */
#ifndef LINKS1_RENDER_RENDER_H
#define LINKS1_RENDER_RENDER_H

#include <stddef.h>
#include <stdint.h>

#include "fixed/num.h"
#include "render/arena.h"
#include "render/layout.h"
#include "render/scene.h"

typedef struct {
    uint8_t r, g, b;
} rgb8_t;

/* The warning colour of options.mark_lost: magenta. */
#define RENDER_LOST_COLOUR ((rgb8_t){255, 0, 255})
/* Axis-aligned box; empty when lo.x > hi.x. */
typedef struct {
    vec3_t lo, hi;
} aabb_t;

/* A light in eye coordinates. */
typedef struct {
    uint8_t kind;        /* enum scene_light_kind */
    rgb_t intensity;
    vec3_t position;     /* POINT, SPOT */
    vec3_t to_light;     /* PARALLEL: unit vector towards the light */
    vec3_t axis;         /* SPOT: unit cone axis, away from the light */
    num_t cos_inner, cos_outer;
} render_light_t;

/* A primitive in eye coordinates. */
typedef struct {
    uint8_t kind;        /* enum scene_prim_kind */
    uint8_t smooth;      /* TRIANGLE: 1 if normals holds its vertex normals
                            (a smooth triangle), 0 when flat */
    uint16_t material;
    uint32_t index;      /* its index in scene->prims: breaks ties between
                            equal hit distances the same way in every order */
    aabb_t bounds;       /* eye-space box around it */
    union {
        /* ELLIPSOID: eye -> unit sphere; BOX: eye -> [-1,1]^3; CONE: eye
         * -> the cone whose axis runs along y from -1 (its larger end,
         * radius 1) to 1 (radius 1 - 2 cone_slope);
         * DENSITY: eye -> the cluster's coordinates (components live there). */
        xform_t to_local;
        /* TRIANGLE, smooth: its eye-space vertex normals, unit length, held
         * here rather than pointed to, so that the RC moves no pointer of a
         * triangle when it copies a frame (render/relocate.c) */
        scene_normals_t normals;
    };
    /* TRIANGLE: eye-space vertex 0, edges to vertices 1 and 2, unit normal */
    vec3_t v0, e1, e2, normal;
    /* TRIANGLE barycentrics of a point w = p - v0 in the plane:
     * beta = (w . edge_n1) / height1, gamma = (w . edge_n2) / height2, with
     * edge_n1 the unit in-plane normal of e2 and height1 = e1 . edge_n1
     * (likewise for e1).  Unit vectors and heights rather than one scaled
     * vector keep the fixed build precise on very large or small triangles. */
    vec3_t edge_n1, edge_n2;
    num_t height1, height2;
    union {
        struct {
            num_t tex_u[3], tex_v[3]; /* TRIANGLE: map coordinates */
        };
        /* BOX, per local axis k: the rounding error of local coordinate
         * k (edge_error[0] is the largest), and the length of to_local's
         * row k (local units per eye unit along it; scale is the
         * longest).  A face's u and v come from the other two axes, which
         * on a thin box may be far less squeezed than its thin one
         * (prim_box_surface's hit uv_error); an edge's decision from the
         * two axes whose slabs give the entry and the exit
         * (prim_box_edge_uncertain). */
        struct {
            num_t box_edge_error[3];
            num_t box_row_len[3];
        };
        struct {
            /* CONE: its local radius at y is 1 - cone_slope (1 + y):
             * (1 - k) / 2 for a smaller end of k times the larger's
             * radius, 0 for a cylinder, 1/2 for a pointed cone */
            num_t cone_slope;
            uint8_t cone_capped; /* 1: its ends closed by discs */
        };
    };
    /* DENSITY.  Pointer fields: render_relocate (render/relocate.c) moves
     * each one; a new pointer field must be added there too. */
    const scene_density_component_t *components; /* -> scene density_components;
                                                    NULL unless DENSITY */
    const num_t *inv_radius2;  /* -> frame density_inv_radius2: 1/d^2 of each
                                  component, by render_prepare; NULL unless
                                  DENSITY */
    uint16_t component_count;
    uint16_t density_steps; /* DENSITY: the scene's options.density_steps */
    num_t threshold;
    uint8_t imprecise;   /* 1: render_prepare estimates that rounding in its
                            to_local map can move a hit point by more than
                            RENDER_LOST_TOLERANCE_VALUE: pixels that see it
                            count as lost precision */
    num_t uv_error;      /* render_prepare's estimate of the rounding error
                            of a hit's map coordinates u, v (render/maps.h);
                            a BOX face's its own (box_edge_error): hit_t's */
    num_t edge_error[2]; /* render_prepare's estimate of the rounding error
                            of what a hit-or-miss decision compares (a
                            TRIANGLE's beta and gamma; an ELLIPSOID's or a
                            BOX's local coordinates, [0]): a decision closer
                            than that plus the ray's own error
                            counts as lost precision (prim_intersect_uncertain) */
    num_t hit_error;     /* render_prepare's estimate of how far rounding
                            moves a hit on it, in eye units (rounding in its
                            to_local map, and the error of its cluster's
                            inverse map: precision_map_error): two primitives
                            hit closer than the sum of theirs count as lost
                            precision (either may be the nearest), and a
                            secondary ray starts that far off (trace.c) */
    num_t scale;         /* local units per eye unit, the longest row of
                            to_local (ELLIPSOID, BOX): a ray's error in
                            local units for the decisions above */
    num_t curvature;     /* the largest curvature of the surface (1/eye
                            units): a hit moved by e turns the normal by at
                            most e * curvature radians (0: flat; an
                            ELLIPSOID's hit has its own, hit_t.curvature) */
} render_prim_t;

/* A cluster in eye coordinates. */
typedef struct {
    aabb_t bounds;        /* around everything below it (prims and clusters) */
    aabb_t own_bounds;    /* around its own primitives only */
    /* Projected own_bounds, in pixels, inclusive and widened by one pixel so
     * that it is conservative; x0 > x1 (empty) when it has no primitives or
     * lies wholly behind the eye.  Covers the whole screen when the box
     * straddles the eye plane. */
    int32_t screen_x0, screen_y0, screen_x1, screen_y1;
    /* The smallest rectangle holding the screen rectangles of this cluster
     * and of every cluster below it (empty, x0 > x1, when all of them are):
     * Y clipping skips a whole subtree whose tree rectangle misses the
     * area (render/clip.c). */
    int32_t tree_x0, tree_y0, tree_x1, tree_y1;
    uint32_t first_child, child_count; /* into frame->child_list */
    uint32_t first_prim, prim_count;   /* into frame->prim_list */
} render_cluster_t;

/* Pointer fields (marked "reloc"): render_relocate (render/relocate.c)
 * moves each one when a blob is copied; a new pointer field must be added
 * there too (test_relocate_no_stale_pointer catches one that is not). */
typedef struct {
    const scene_t *scene;          /* reloc */
    uint32_t frame_index;
    render_options_t options;      /* copied from the scene; callers may
                                      change it before rendering */
    uint16_t width, height;
    num_t screen_half_w, screen_half_h; /* eye-space half extents at z = 1 */
    uint16_t light_count;
    render_light_t lights[RENDER_MAX_LIGHTS];
    uint32_t cluster_count;
    render_cluster_t *clusters;    /* reloc; index = scene cluster index */
    const uint32_t *child_list;    /* reloc; cluster indices, grouped by
                                      parent (the scene index's) */
    uint32_t prim_count;
    render_prim_t *prims;          /* reloc; index = scene prim index */
    uint32_t pointer_lo, pointer_hi; /* every primitive with pointers of its
                                        own (all but triangles) lies in
                                        [pointer_lo, pointer_hi): the only
                                        ones relocation looks into (the
                                        scene index's) */
    const uint32_t *prim_list;     /* reloc; prim indices, grouped by
                                      cluster (the scene index's) */
    num_t *density_inv_radius2;    /* reloc; 1/d^2 per scene density component:
                                      the field then needs no division */
    uint8_t precision_lost;        /* 1 if preparing hit a saturation (camera,
                                      cluster maps, boxes): every pixel then
                                      counts as lost precision */
    num_t span;                    /* largest side of the scene's eye-space box */
    num_t ray_epsilon;             /* RENDER_RAY_EPSILON_VALUE (in the
                                      scene's stored units, render/limits.h) */
    uint32_t detail_prim;          /* the first primitive smaller than the
                                      arithmetic resolves where it lies
                                      (RENDER_ERR_DETAIL), RENDER_NO_PRIM
                                      when none */
    num_t detail_size, detail_step; /* its smallest size and the step of the
                                      arithmetic there, in stored units */
    uint32_t clip_coverage;        /* the clusters' own screen rectangles over
                                      a pixel, on average (rounded up): the
                                      length of the paper's X list */
    uint32_t clip_rows;            /* the same over a scanline: the length
                                      of the paper's Y list for an area of
                                      one row.  The two choose how an NC
                                      clips (render/clip.h) */
    uint64_t clip_covered;         /* the pixels, and the rows, under the */
    uint64_t clip_covered_rows;    /* clusters' own screen rectangles: the
                                      sums behind the two (a later frame
                                      updates them by its moved clusters) */
    /* options.world_space: primitives, boxes and lights stay in world
     * coordinates (the world part), camera rays start at eye and turn by
     * eye_to_world; no screen rectangles (every one the whole screen:
     * render_area traces without clipping).  A frame prepared again over
     * the frame before of the same scene (render_prepare_again) keeps that
     * frame's world part (eye space: its primitives and boxes, when the
     * camera is the same) when no keyed cluster map differs and the extent
     * is the same; when some differ (under them at most half the
     * primitives and a quarter of the clusters, or 256) it prepares only
     * those clusters' primitives again and the boxes above them.  Either way: the bytes a fresh preparation writes
     * but kept. */
    uint8_t world;
    uint8_t world_lost;            /* world: precision_lost of the world part
                                      alone (the camera's added after) */
    uint8_t screenless;            /* RENDER_PREP_NO_SCREEN: no screen
                                      rectangles (every one the whole
                                      screen), no clip coverage */
    uint8_t kept;                  /* 1 if this frame kept the world part
                                      (eye space: the primitives and boxes)
                                      of the frame before, 2 if it prepared
                                      only the clusters that moved (a count
                                      for the trace, not part of the
                                      picture) */
    vec3_t eye;                    /* world: the camera's position */
    xform_t eye_to_world;          /* world: the camera's axes as columns */
    num_t world_box_extent;        /* world: the largest coordinate magnitude
                                      of the scene's box */
    num_t precision_extent;        /* the extent precision_check bounds
                                      rounding at: the box's (eye space), or
                                      the power of two at or above the box's
                                      and the eye's (world) */
} render_frame_t;

#define RENDER_NO_PRIM UINT32_MAX

typedef struct {
    uint64_t primary;       /* camera rays */
    uint64_t shadow;        /* rays towards lights */
    uint64_t reflection;
    uint64_t refraction;
    uint64_t transmission;  /* straight refractionless rays past max depth */
    uint64_t box_tests;     /* bounding-box tests */
    uint64_t prim_tests;    /* primitive intersection tests */
    uint64_t primary_box_tests;  /* the part of box_tests made by camera
                                    rays' nearest-hit search */
    uint64_t primary_prim_tests; /* the part of prim_tests made by it:
                                    what screen clipping cuts down */
    uint32_t precision_lost_pixels; /* pixels where a saturated value reached
                                       a hit distance or a colour, whose frame
                                       lost precision in preparing, or whose
                                       rays met an imprecise primitive */
    uint64_t weight_cut;    /* reflected or refracted rays not traced: their
                               weight fell below min_weight (adaptive depth);
                               host only, not summed over the serial lines */
    uint64_t self_blocked;  /* reflected or refracted rays not traced:
                               their own surface blocks them
                               (trace_self_blocked); host only, like
                               weight_cut */
    uint64_t screen_tests;  /* tree rectangles looked at by primary rays
                               walked by screen (render_pixel_screen); host
                               only, like weight_cut */
    uint32_t escalated_pixels; /* pixels that lost precision and were traced
                                  again in the wide arithmetic (ctx.escalate);
                                  precision_lost_pixels then counts those
                                  the wide one lost too */
    uint64_t primary_hit;   /* camera rays that hit something */
} render_stats_t;

typedef struct {
    const render_frame_t *frame;
    render_options_t options; /* copied from frame->options by
                                 render_ctx_init: one core may switch a
                                 speed-up off without writing the shared
                                 frame */
    render_stats_t stats;
    uint8_t pixel_lost;     /* set while tracing one pixel; after
                               render_pixel*, whether that pixel lost
                               precision (in the wide arithmetic when it
                               was escalated) */
    /* Escalation (render/wide.h): when escalate is set, a pixel that lost
     * precision is traced again by escalate(escalate_arg, x, y, &lost),
     * the renderer in a wider arithmetic, and takes its colour; lost says
     * whether that one lost precision too.  NULL: the pixel keeps this
     * arithmetic's colour (or RENDER_LOST_COLOUR with mark_lost). */
    rgb8_t (*escalate)(void *arg, uint32_t x, uint32_t y, uint8_t *lost);
    void *escalate_arg;
    /* Over 1: every ray's error bound counts this many times over in the
     * hit-or-miss decisions (a wider net for escalation, whose bounds
     * can fall short: RENDER_ESCALATE_MARGIN); 0 or 1: as estimated. */
    uint8_t error_margin;
    /* render/trace.c's: a hit's material with its attribute maps applied,
     * one per nesting of the hits that use one at a time (shading, the
     * straight transmission past the depth limit, a shadow ray's
     * crossings); here rather than in every level's stack frame */
    scene_material_t look[3];
    /* The frame's light buffer (render/lightbuf.h), built by whoever owns
     * the context, or NULL: shadow rays walk the whole tree */
    const struct render_lightbuf *light_buffer;
} render_ctx_t;

typedef enum {
    RENDER_OK = 0,
    RENDER_ERR_ARENA,        /* the arena is too small for the frame */
    RENDER_ERR_SIZE,         /* width/height out of 1..RENDER_MAX_* */
    RENDER_ERR_LIGHTS,       /* more than RENDER_MAX_LIGHTS lights */
    RENDER_ERR_DEPTH,        /* max_depth above RENDER_MAX_DEPTH */
    RENDER_ERR_CLUSTER,      /* bad parent index or nesting > RENDER_MAX_CLUSTER_DEPTH */
    RENDER_ERR_PRIM,         /* bad kind, cluster or material index */
    RENDER_ERR_DENSITY,      /* component range outside the scene's array,
                                more than RENDER_MAX_DENSITY_COMPONENTS, a
                                threshold <= 0, or options.density_steps
                                outside SCN_MIN..SCN_MAX_DENSITY_STEPS */
    RENDER_ERR_MAP,          /* bad map index/kind/size */
    RENDER_ERR_KEY,          /* key range outside the scene's array */
    RENDER_ERR_CAMERA,       /* eye == look_at, or up parallel to the view */
    RENDER_ERR_SINGULAR,     /* a transform that cannot be inverted */
    RENDER_ERR_RELOCATE,     /* a pointer of a blob lies outside the blob
                                (not self-contained), or a bad base */
    RENDER_ERR_AREA,         /* an area empty or not inside the screen */
    RENDER_ERR_EXTENT,       /* the scene spans less than RENDER_MIN_SPAN_VALUE
                                (render/limits.h): its detail is
                                finer than the ray offset (render_prepare
                                then still sets *out, for frame->span only) */
    RENDER_ERR_SCALE,        /* a cluster transform scales so little (or so
                                much) that the arithmetic cannot invert it
                                to RENDER_INVERSE_TOLERANCE_VALUE */
    RENDER_ERR_DETAIL,       /* a primitive smaller than
                                RENDER_MIN_DETAIL_STEPS steps of the
                                arithmetic where it lies: its shape would be
                                off by more than a quarter (render_prepare
                                then still sets *out, for frame->detail_*) */
} render_status_t;

/* A constant string naming the status, for error messages. */
const char *render_status_name(render_status_t status);

/* Prepare frame frame_index of the scene: every allocation comes from arena,
 * *out points into it.  The scene must stay alive and unchanged while the
 * frame is used. */
render_status_t render_prepare(const scene_t *scene, uint32_t frame_index,
                               arena_t *arena, render_frame_t **out);
/* The same, where prev (or NULL) is the frame render_prepare or this
 * returned RENDER_OK for at the same arena position before, of the same
 * scene, and still lies there: with options.world_space its world part is
 * kept when it would come out the same (render_frame_t.world). */
render_status_t render_prepare_again(const scene_t *scene, uint32_t frame_index, arena_t *arena,
                                     const render_frame_t *prev, render_frame_t **out);
/* What render_prepare_parts leaves out of a frame. */
enum render_prep_parts {
    RENDER_PREP_WHOLE,     /* nothing */
    RENDER_PREP_NO_SCREEN, /* the screen rectangles (each cluster's the
                              whole screen) and clip coverage: a frame
                              only render_pixel walks, which searches the
                              tree without them (escalation's wide frame,
                              render/wide.h) */
};
/* render_prepare_again leaving parts out; prev is kept from only when it
 * left out the same. */
render_status_t render_prepare_parts(const scene_t *scene, uint32_t frame_index, arena_t *arena,
                                     const render_frame_t *prev, enum render_prep_parts parts,
                                     render_frame_t **out);

/* 1 when world-space frames a and b of scene s have the same world part,
 * byte for byte as a fresh preparation writes it: every keyed cluster map
 * is the same at their frames, and so is the extent (what the world part
 * is made of); only their headers (camera, lights) may differ.  The RC
 * then forwards b's header alone over a (render_blob_copy_frame). */
int render_world_same(const scene_t *s, const render_frame_t *a, const render_frame_t *b);

/* Arena bytes render_prepare needs for this scene, at most (frame, arrays,
 * scratch and alignment): what a unit computer must set aside.  Rendering
 * itself allocates nothing (stack: RENDER_STACK_BYTES in limits.h). */
size_t render_prepare_bytes(const scene_t *scene);
/* The same with another machine's record sizes (render/layout.h). */
size_t render_prepare_bytes_layout(const scene_t *scene, const render_layout_t *layout);
/* The frame alone, for a scene that has its index (scene_load's): what
 * render_prepare needs beyond the scene's memory, at most. */
size_t render_prepare_frame_bytes_layout(const scene_t *scene, const render_layout_t *layout);

/* The scene's static structure (scene_index_t, render/scene.h) into arena:
 * what every frame's preparation would otherwise work out again.
 * scene_load calls it; a scene built by hand may go without (render_prepare
 * then works it out into each frame's arena).  RENDER_ERR_CLUSTER,
 * RENDER_ERR_PRIM for a tree or a primitive render_prepare would refuse,
 * RENDER_ERR_ARENA when arena lacks render_scene_index_bytes. */
render_status_t render_scene_index(const scene_t *scene, arena_t *arena, scene_index_t *out);
/* render_scene_index of a scene whose bytes another arithmetic's load
 * indexed already, with its checks: same, that index's integer part (its
 * counts the scene's: the caller checks), is copied, and what depends on
 * the arithmetic (uv_spread, parent_maps) worked out.  RENDER_ERR_ARENA,
 * or a parent map precision_invert cannot invert. */
render_status_t render_scene_index_same(const scene_t *scene, arena_t *arena,
                                        const scene_index_ints_t *same, scene_index_t *out);
/* The integer part of scene's index (scene->index), for render_scene_index_same. */
scene_index_ints_t render_scene_index_ints(const scene_t *scene);
/* Arena bytes render_scene_index needs at most (its arrays, its scratch
 * and alignment): its parent maps as scene->index.parent_map_count says in
 * a shape that carries it (scene_load_shape_maps), else two a cluster;
 * with another machine's record sizes (render/layout.h). */
size_t render_scene_index_bytes(const scene_t *scene);
size_t render_scene_index_bytes_layout(const scene_t *scene, const render_layout_t *layout);

void render_ctx_init(render_ctx_t *ctx, const render_frame_t *frame);

/* Corner mode: camera rays at the pixel corners, which render_area traces
 * once each and shares between neighbouring pixels (render/clip.c), under
 * the SPD rules and with anti-aliasing. */
static inline int render_corner_mode(const render_options_t *o)
{
    return o->spd_rules || o->antialias;
}

/* Colour of pixel (x, y), y = 0 the top row.  In corner mode
 * (render_corner_mode) from its four corner rays, traced here (render_area
 * shares them between neighbours): their mean under the SPD rules, with
 * options.antialias Whitted's subdivision of the pixel (render/trace.c,
 * docs/renderer.md). */
rgb8_t render_pixel(render_ctx_t *ctx, uint32_t x, uint32_t y);

/* Same, with the primary ray testing only the clusters listed (their own
 * primitives, not their children): the NC's X-clipped candidates.  Gives
 * the same colour as render_pixel when the list holds every cluster whose
 * screen rectangle contains the pixel. */
rgb8_t render_pixel_clipped(render_ctx_t *ctx, uint32_t x, uint32_t y,
                            const uint32_t *clusters, uint32_t count);

/* Same, with Y and X clipping done in the hierarchy: the primary ray walks
 * the cluster tree and skips every subtree whose tree rectangle
 * (render_cluster_t.tree_*) misses the pixel, and a cluster's own
 * primitives when its own rectangle does, before any box test.  Its cost
 * follows the tree's depth near the pixel, not the clusters around it, so
 * it does not grow with the scene as lists of clusters do.  The colour is
 * render_pixel's (without the hierarchy, it is render_pixel). */
rgb8_t render_pixel_screen(render_ctx_t *ctx, uint32_t x, uint32_t y);

/* Corner mode: the camera ray through corner (cx, cy) of the pixel
 * grid (cx 0..width, cy 0..height), its colour and whether it lost
 * precision; render_area keeps two rows of them (render/clip.c). */
typedef struct {
    rgb_t colour;
    uint8_t lost;
} render_corner_t;

/* How render_corner looks for a corner ray's nearest hit. */
typedef enum {
    RENDER_CORNER_TREE,   /* the hierarchy from its root (render_pixel's) */
    RENDER_CORNER_SCREEN, /* by screen, as render_pixel_screen does, at
                             the pixel whose top-left corner it is (the
                             last row and column: the pixel before) */
    RENDER_CORNER_LIST,   /* only the clusters listed (render_pixel_clipped's) */
} render_corner_search_t;

/* The corner ray (cx, cy) traced into *out.  counted 0: ctx->stats stay as
 * they were (a corner an area shares with its neighbour, counted by the
 * area that owns it), so that the counts over a frame are each corner's
 * once whatever the areas. */
void render_corner(render_ctx_t *ctx, uint32_t cx, uint32_t cy, render_corner_search_t search,
                   const uint32_t *clusters, uint32_t count, int counted, render_corner_t *out);

/* Pixel (x, y) from its four corners c[0..3] (top-left, top-right,
 * bottom-left, bottom-right): their mean colour, or with options.antialias
 * the pixel cut into four where its corners differ by more than
 * aa_threshold, down to aa_depth, each new ray searched as the pixel's
 * would be (search, clusters, count as render_corner's, at the pixel;
 * always counted in ctx->stats); lost precision when a ray did (escalated
 * then as render_pixel would be). */
rgb8_t render_pixel_of_corners(render_ctx_t *ctx, uint32_t x, uint32_t y,
                               const render_corner_t c[4], render_corner_search_t search,
                               const uint32_t *clusters, uint32_t count);

/* Pixel (x, y) as the box mean of n x n camera rays (1..RENDER_MAX_SUPERSAMPLE)
 * through the centres of its n x n sub-squares (the grid points of
 * anti-aliasing's sample function at scale 2n), each searching the whole
 * tree: a reference to measure anti-aliasing against (links1 ref
 * --supersample, the double build).  No escalation: a pixel that lost
 * precision is counted (and painted, with mark_lost). */
#define RENDER_MAX_SUPERSAMPLE 16
rgb8_t render_pixel_supersampled(render_ctx_t *ctx, uint32_t x, uint32_t y, uint32_t n);

/* Pixels x0..x1-1 of row y into out[0..x1-x0-1]. */
void render_span(render_ctx_t *ctx, uint32_t y, uint32_t x0, uint32_t x1, rgb8_t *out);

#endif
