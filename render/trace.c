/* render/trace.c: nearest-hit search, shadows, recursion and pixels.
 *
 * trace_nearest() finds the nearest hit through the cluster tree (or a flat
 * list), testing bounding boxes first when enabled.  Ties between equal
 * distances go to the lower primitive index, so the answer does not depend
 * on the order things are tested in: hierarchy and boxes on or off, or the
 * NC's screen-clipped list, give the same image.  Products over several
 * objects (shadow transmittance) are taken in primitive-index order for the
 * same reason.
 */
#include "render/haze.h"
#include "render/lightbuf.h"
#include "render/maps.h"
#include "render/prim.h"
#include "render/shade.h"
#include "render/vec3.h"

#define TRACE_FAR NUM_FAR /* beyond everything */
#define TRACE_NO_PRIM UINT32_MAX
/* A unit vector's rounding, as an angle: a few steps of the arithmetic at 1
 * (a camera ray's direction, a normal, a direction towards a light). */
#define TRACE_DIR_ROUND num_mul_int(num_ulp(NUM_ONE), 4)
#define TRACE_COS_FLOOR NUM_C(1.0 / 1024) /* trace_surface_error's most grazing incidence */

enum trace_kind { TRACE_PRIMARY, TRACE_REFLECTION, TRACE_REFRACTION };

typedef struct {
    int found;
    num_t t;
    uint32_t prim;
    int runner_up;   /* another primitive was hit too: the nearest of them */
    num_t runner_t;  /* at runner_t, on runner_prim */
    uint32_t runner_prim;
} nearest_t;

/* Crossings of one straight ray: each primitive once, at its first t. */
typedef struct {
    uint32_t count;
    int overflow;    /* more transparent objects than the buffer holds */
    int opaque;      /* an opaque object was crossed (shadow use only) */
    num_t t[RENDER_MAX_TRANSPARENT];
    uint32_t prim[RENDER_MAX_TRANSPARENT];
} crossings_t;

static const scene_material_t *trace_material(const render_ctx_t *ctx, uint32_t prim)
{
    return &ctx->frame->scene->materials[ctx->frame->prims[prim].material];
}

/* ------------------------------------------------------------ traversal */

/* Callback-free traversal: mode NEAREST keeps the nearest hit; mode
 * COLLECT records every primitive crossed in (tmin, tmax]. */
enum trace_mode { TRACE_NEAREST, TRACE_COLLECT_SHADOW, TRACE_COLLECT_STRAIGHT };

typedef struct {
    render_ctx_t *ctx;
    const ray_t *ray;
    const ray_error_t *err; /* the ray's error bound: widens every decision */
    num_t tmin, tmax;
    enum trace_mode mode;
    nearest_t nearest;
    crossings_t *cross;
    aabb_ray_t box_ray; /* the ray's reciprocals for box tests */
    int screen;         /* 1: a primary ray through pixel (px, py): subtrees
                           whose screen rectangles miss it are skipped */
    int32_t px, py;
    num_t cut;          /* box tests' far end: tmax, or in a NEAREST walk
                           the nearest hit so far (it only comes nearer) */
    uint32_t box_tests; /* this walk's, added to ctx->stats at its end */
    uint32_t screen_tests, prim_tests; /* likewise */
    int use_bounds;     /* ctx->options.use_bounds */
    int by_list;        /* a camera ray walking a clipping list's clusters
                           (their own_bounds tested first) */
    const render_lightbuf_t *lb; /* a shadow ray walking its light buffer's
                                    cell (lb_mask), or NULL */
    uint32_t lb_mask;
    const uint8_t *lb_face; /* its light's render_lb_light_t.face */
    uint32_t left;      /* the primitive the ray leaves and cannot meet
                           again (trace_left), or TRACE_NO_PRIM: untested */
} trace_walk_t;

/* A walk of mode over ray in (tmin, tmax], field by field: an initializer
 * clears the whole struct, which the compiler does with a call to memset
 * once it is this large (a few hundred instructions a ray).  What is not
 * set here is written before it is read: nearest's values once found (or
 * runner_up) says so, box_ray by trace_walk. */
static void trace_walk_setup(trace_walk_t *w, render_ctx_t *ctx, const ray_t *ray,
                             const ray_error_t *err, num_t tmin, num_t tmax, enum trace_mode mode,
                             crossings_t *cross)
{
    w->ctx = ctx;
    w->ray = ray;
    w->err = err;
    w->tmin = tmin;
    w->tmax = tmax;
    w->mode = mode;
    w->nearest.found = 0;
    w->nearest.runner_up = 0;
    w->cross = cross;
    w->screen = 0;
    w->px = w->py = 0;
    w->cut = tmax;
    w->box_tests = w->screen_tests = w->prim_tests = 0;
    w->use_bounds = ctx->options.use_bounds;
    w->left = TRACE_NO_PRIM;
    w->by_list = 0;
    w->lb = NULL;
}

static void trace_record(trace_walk_t *w, uint32_t prim, num_t t)
{
    crossings_t *c = w->cross;
    if (w->mode == TRACE_COLLECT_SHADOW) {
        if (!num_gt(trace_material(w->ctx, prim)->trc, NUM_ZERO)) {
            c->opaque = 1;
            return;
        }
        if (c->count == RENDER_MAX_TRANSPARENT) {
            c->overflow = 1;
            return;
        }
        c->prim[c->count] = prim;
        c->t[c->count++] = t;
        return;
    }
    /* straight ray: keep the nearest RENDER_MAX_TRANSPARENT, sorted by
     * (t, prim) with an insertion step */
    uint32_t n = c->count;
    if (n == RENDER_MAX_TRANSPARENT) {
        c->overflow = 1;
        num_t lt = c->t[n - 1];
        if (num_gt(t, lt) || (num_eq(t, lt) && prim > c->prim[n - 1]))
            return;
        n--;
    }
    uint32_t i = n;
    while (i > 0 && (num_lt(t, c->t[i - 1]) || (num_eq(t, c->t[i - 1]) && prim < c->prim[i - 1]))) {
        c->t[i] = c->t[i - 1];
        c->prim[i] = c->prim[i - 1];
        i--;
    }
    c->t[i] = t;
    c->prim[i] = prim;
    c->count = n + 1;
}

/* A shadow ray that met an opaque object is done: its answer is 0
 * whatever else it would cross.  mode: w->mode (the tree walk passes it
 * as a constant, so that each mode's walk is compiled apart). */
static inline __attribute__((always_inline)) int trace_walk_done_as(const trace_walk_t *w,
                                                                     enum trace_mode mode)
{
    return mode == TRACE_COLLECT_SHADOW && w->cross->opaque;
}

/* A primitive tested in a walk of mode (w->mode: a constant where the
 * walk is compiled apart for each mode). */
static inline __attribute__((always_inline)) void trace_test_prim_as(trace_walk_t *w,
                                                                      enum trace_mode mode,
                                                                      uint32_t prim)
{
    const render_prim_t *p = &w->ctx->frame->prims[prim];
    if (trace_walk_done_as(w, mode) || prim == w->left)
        return;
    num_t t;
    w->prim_tests++;
    /* an imprecise primitive may be missed wrongly: a ray that meets its
     * box (whatever was found before: the same in every traversal mode)
     * loses precision */
    if (p->imprecise && prim_aabb_hit(&p->bounds, w->ray, w->tmin, w->tmax))
        w->ctx->pixel_lost = 1;
    /* tested up to w->tmax, not the nearest hit so far, so that an
     * uncertain edge counts whatever the order (prim.h: only the final
     * t <= tmax depends on tmax) */
    int uncertain, found;
    if (p->kind == SCENE_PRIM_DENSITY && mode == TRACE_COLLECT_SHADOW &&
        !num_gt(trace_material(w->ctx, prim)->trc, NUM_ZERO))
        found = prim_intersect_uncertain_whether(p, w->ray, w->err, w->tmin, w->tmax, &t,
                                                 &uncertain); /* opaque: t is not used */
    else
        found = prim_intersect_uncertain(p, w->ray, w->err, w->tmin, w->tmax, &t, &uncertain);
    if (uncertain)
        w->ctx->pixel_lost = 1;
    if (!found || (mode != TRACE_NEAREST && num_gt(t, w->tmax)))
        return;
    if (mode != TRACE_NEAREST) {
        trace_record(w, prim, t);
        return;
    }
    nearest_t *n = &w->nearest;
    if (!n->found || num_lt(t, n->t) || (num_eq(t, n->t) && prim < n->prim)) {
        if (n->found && (!n->runner_up || !num_gt(n->t, n->runner_t))) {
            n->runner_up = 1;
            n->runner_t = n->t;
            n->runner_prim = n->prim;
        }
        n->found = 1;
        n->t = t;
        n->prim = prim;
        w->cut = t;
    } else if (!n->runner_up || num_lt(t, n->runner_t)) {
        n->runner_up = 1;
        n->runner_t = t;
        n->runner_prim = prim;
    }
}

/* Box test against the nearest hit so far; *entry the t where the ray
 * enters the box (tmin when bounds are off). */
static inline __attribute__((always_inline)) int trace_box_entry(trace_walk_t *w, const aabb_t *b,
                                                                  num_t *entry)
{
    *entry = w->tmin;
    if (!w->use_bounds)
        return 1;
    w->box_tests++;
    return prim_aabb_entry_ray(b, w->ray, &w->box_ray, w->tmin, w->cut, entry);
}

static inline __attribute__((always_inline)) int trace_box(trace_walk_t *w, const aabb_t *b)
{
    num_t entry;
    return trace_box_entry(w, b, &entry);
}

/* trace_box of a box the ray starts well inside of (prim_aabb_around: the
 * root's, for every ray that starts on a surface): a hit, counted, without
 * its slabs. */
static inline __attribute__((always_inline)) int trace_box_around(trace_walk_t *w, const aabb_t *b)
{
    if (!w->use_bounds || !prim_aabb_around(b, w->ray->origin, w->tmin, w->cut))
        return trace_box(w, b);
    w->box_tests++;
    return 1;
}

/* A box entered at t can still hold a hit: not past the nearest so far
 * (equal t may still win the tie on the primitive index). */
static inline __attribute__((always_inline)) int trace_still_open(const trace_walk_t *w,
                                                                   enum trace_mode mode,
                                                                   num_t entry)
{
    return mode != TRACE_NEAREST || !w->nearest.found || !num_gt(entry, w->nearest.t);
}

/* The primary ray's pixel lies in cluster c's tree rectangle (all of it
 * and below), or it is no primary ray walked by screen (screen: w->screen,
 * a constant in the tree walk as mode is). */
static inline __attribute__((always_inline)) int trace_screen_tree_as(trace_walk_t *w, int screen,
                                                                       const render_cluster_t *c)
{
    if (!screen)
        return 1;
    w->screen_tests++;
    return w->px >= c->tree_x0 && w->px <= c->tree_x1 && w->py >= c->tree_y0 &&
           w->py <= c->tree_y1;
}

static inline int trace_screen_tree(trace_walk_t *w, const render_cluster_t *c)
{
    return trace_screen_tree_as(w, w->screen, c);
}

static void trace_test_prim(trace_walk_t *w, uint32_t prim)
{
    if (w->mode == TRACE_NEAREST)
        trace_test_prim_as(w, TRACE_NEAREST, prim);
    else if (w->mode == TRACE_COLLECT_SHADOW)
        trace_test_prim_as(w, TRACE_COLLECT_SHADOW, prim);
    else
        trace_test_prim_as(w, TRACE_COLLECT_STRAIGHT, prim);
}

/* Cluster c's own primitives in a walk of mode, by screen or not (as
 * trace_test_prim_as). */
static inline __attribute__((always_inline)) void trace_own_prims_as(trace_walk_t *w,
                                                                      enum trace_mode mode,
                                                                      int screen,
                                                                      const render_cluster_t *c)
{
    const render_frame_t *f = w->ctx->frame;
    /* by screen: the pixel must lie in the cluster's own rectangle, and
     * the ray meet its own box (where it is not the box just tested, that
     * of the cluster and its children), before its primitives are tested */
    if (screen && (c->prim_count == 0 || w->px < c->screen_x0 || w->px > c->screen_x1 ||
                      w->py < c->screen_y0 || w->py > c->screen_y1 ||
                      (c->child_count && !trace_box(w, &c->own_bounds))))
        return;
    /* each primitive's own box first, unless the box just tested is its
     * alone (a leaf of one primitive; by screen or by list, own_bounds)
     * or it is a box or a triangle, whose own test costs about as much
     * (measured: demo, SPD teapot 32); in a flat walk every primitive's,
     * standing in for the tree */
    int flat = !w->ctx->options.use_hierarchy;
    int by_prim = flat || c->prim_count > 1 || (c->child_count && !screen && !w->by_list);
    for (uint32_t k = 0; k < c->prim_count; k++) {
        uint32_t prim = f->prim_list[c->first_prim + k];
        uint8_t kind = f->prims[prim].kind; /* enum scene_prim_kind */
        if (by_prim && (flat || (kind != SCENE_PRIM_BOX && kind != SCENE_PRIM_TRIANGLE)) &&
            !trace_box(w, &f->prims[prim].bounds))
            continue;
        trace_test_prim_as(w, mode, prim);
    }
}

/* trace_own_prims_as once for each walk there is: trace_own_prims_NAME */
#define TRACE_OWN_PRIMS_FOR(name, mode, screen)                                          \
    static __attribute__((noinline)) void trace_own_prims_##name(trace_walk_t *w,        \
                                                                 const render_cluster_t *c) \
    {                                                                                    \
        trace_own_prims_as(w, mode, screen, c);                                          \
    }
TRACE_OWN_PRIMS_FOR(nearest, TRACE_NEAREST, 0)
TRACE_OWN_PRIMS_FOR(screen, TRACE_NEAREST, 1)
TRACE_OWN_PRIMS_FOR(shadow, TRACE_COLLECT_SHADOW, 0)
TRACE_OWN_PRIMS_FOR(straight, TRACE_COLLECT_STRAIGHT, 0)

/* The one of those for mode and screen (constants in the tree walk). */
static inline __attribute__((always_inline)) void trace_own_prims_of(trace_walk_t *w,
                                                                      enum trace_mode mode,
                                                                      int screen,
                                                                      const render_cluster_t *c)
{
    if (mode == TRACE_COLLECT_SHADOW)
        trace_own_prims_shadow(w, c);
    else if (mode == TRACE_COLLECT_STRAIGHT)
        trace_own_prims_straight(w, c);
    else if (screen)
        trace_own_prims_screen(w, c);
    else
        trace_own_prims_nearest(w, c);
}

static void trace_own_prims(trace_walk_t *w, const render_cluster_t *c)
{
    trace_own_prims_of(w, w->mode, w->screen, c);
}

/* A visit the walk has put off: the farther child of a two-child node
 * (its box entered at entry: TRACE_LATER_FAR), or the children of a node
 * of more, from the k-th on.  The tree is at most
 * RENDER_MAX_CLUSTER_DEPTH deep below the root (render/prepare.c checks),
 * and each level of the path holds at most one. */
#define TRACE_LATER_FAR UINT32_MAX
typedef struct {
    uint32_t node;
    uint32_t k;
    num_t entry;
} trace_later_t;

/* The tree walk's copies of the ray for its box tests and of the frame's
 * tree: in locals, which no store through a pointer can change, the
 * compiler keeps them in registers. */
typedef struct {
    vec3_t origin;
    aabb_ray_t r;
    int by_inv; /* r.all_inv and bounds on: prim_aabb_entry_inv */
    const render_cluster_t *clusters;
    const uint32_t *child_list;
} trace_box_ray_t;

/* trace_box_entry by the walk's copy br of the ray. */
static inline __attribute__((always_inline)) int trace_box_entry_by(trace_walk_t *w,
                                                                     const trace_box_ray_t *br,
                                                                     const aabb_t *b, num_t *entry)
{
    if (!br->by_inv)
        return trace_box_entry(w, b, entry);
    w->box_tests++;
    return prim_aabb_entry_inv(b, br->origin, &br->r, w->tmin, w->cut, entry);
}

/* A child of the tree walk (mode, screen: as trace_walk_done_as) whose
 * box the ray meets, *entry where it enters. */
static inline __attribute__((always_inline)) int trace_kid_met(trace_walk_t *w,
                                                                enum trace_mode mode, int screen,
                                                                const trace_box_ray_t *br,
                                                                uint32_t kid, num_t *entry)
{
    const render_cluster_t *k = &br->clusters[kid];
    return !trace_walk_done_as(w, mode) && trace_screen_tree_as(w, screen, k) &&
           trace_box_entry_by(w, br, &k->bounds, entry);
}

/* A two-child node c: the nearer child whose box the ray meets in *next
 * (1), the farther one put off on later (*n grows); 0 when neither is
 * met. */
static inline __attribute__((always_inline)) int trace_two(trace_walk_t *w, enum trace_mode mode,
                                                            int screen, const trace_box_ray_t *br,
                                                            const render_cluster_t *c,
                                                            uint32_t *next, trace_later_t *later,
                                                            uint32_t *n)
{
    const uint32_t *kids = &br->child_list[c->first_child];
    uint32_t a = kids[0], b = kids[1];
    num_t ta, tb;
    int ha = trace_kid_met(w, mode, screen, br, a, &ta);
    int hb = trace_kid_met(w, mode, screen, br, b, &tb);
    if (ha && hb && num_lt(tb, ta)) {
        uint32_t k = a;
        num_t t = ta;
        a = b, ta = tb;
        b = k, tb = t;
    } else if (!ha) {
        a = b, ta = tb, ha = hb, hb = 0;
    }
    if (hb)
        later[(*n)++] = (trace_later_t){b, TRACE_LATER_FAR, tb};
    *next = a;
    return ha;
}

/* The next child of later's node, from its k-th, whose box the ray meets,
 * in *next (1; later moves past it), or 0 when none is left. */
static inline __attribute__((always_inline)) int trace_next_kid(trace_walk_t *w,
                                                                 enum trace_mode mode, int screen,
                                                                 const trace_box_ray_t *br,
                                                                 trace_later_t *later,
                                                                 uint32_t *next)
{
    const render_cluster_t *c = &br->clusters[later->node];
    const uint32_t *kids = &br->child_list[c->first_child];
    while (later->k < c->child_count) {
        uint32_t kid = kids[later->k++];
        num_t entry;
        if (!trace_kid_met(w, mode, screen, br, kid, &entry))
            continue;
        const render_cluster_t *leaf = &br->clusters[kid];
        if (leaf->child_count == 0) { /* its visit is its own primitives */
            if (leaf->prim_count)
                trace_own_prims_of(w, mode, screen, leaf);
            continue;
        }
        *next = kid;
        return 1;
    }
    return 0;
}

/* The visit to make after a subtree is done, from later (*n of them), in
 * *next: 0 when none is left. */
static inline __attribute__((always_inline)) int trace_resume(trace_walk_t *w,
                                                               enum trace_mode mode, int screen,
                                                               const trace_box_ray_t *br,
                                                               trace_later_t *later, uint32_t *n,
                                                               uint32_t *next)
{
    while (*n) {
        trace_later_t *l = &later[*n - 1];
        if (l->k == TRACE_LATER_FAR) {
            (*n)--;
            if (!trace_walk_done_as(w, mode) && trace_still_open(w, mode, l->entry)) {
                *next = l->node;
                return 1;
            }
        } else if (trace_next_kid(w, mode, screen, br, l, next)) {
            return 1;
        } else {
            (*n)--;
        }
    }
    return 0;
}

/* Everything below cluster index, whose box the ray has already passed,
 * depth first without recursion.  Two children (a node of the automatic
 * hierarchy, docs/scene-format.md) are visited nearer box first; the
 * farther one is skipped when its entry lies beyond the nearest hit found
 * in the nearer.  A node of more children tests each one's box when the
 * subtree before it is done (the nearest hit so far cuts it). */
static inline __attribute__((always_inline)) void trace_tree_as(trace_walk_t *w,
                                                                 enum trace_mode mode, int screen,
                                                                 int from_eye, uint32_t index)
{
    const render_frame_t *f = w->ctx->frame;
    /* from_eye (a constant): the ray starts at +0, +0, +0, so a face's
     * distance from its origin is the face itself, bit for bit */
    const trace_box_ray_t br = {.origin = from_eye ? vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO)
                                                   : w->ray->origin,
                                .r = w->box_ray,
                                .by_inv = w->box_ray.all_inv && w->use_bounds,
                                .clusters = f->clusters, .child_list = f->child_list};
    trace_later_t later[RENDER_MAX_CLUSTER_DEPTH + 1];
    uint32_t n = 0;
    for (;;) {
        const render_cluster_t *c = &br.clusters[index];
        if (c->prim_count) /* an inner node of the automatic hierarchy has none */
            trace_own_prims_of(w, mode, screen, c);
        if (c->child_count == 2 && trace_two(w, mode, screen, &br, c, &index, later, &n))
            continue;
        if (c->child_count > 2 || c->child_count == 1)
            later[n++] = (trace_later_t){index, 0, NUM_ZERO};
        if (!trace_resume(w, mode, screen, &br, later, &n, &index))
            return;
    }
}

/* The ray starts at the eye of eye space: its origin's bits are +0's
 * (not -0, whose difference from a face can differ in sign). */
static int trace_from_eye(const ray_t *ray)
{
    return num_is_plus_zero(ray->origin.x) && num_is_plus_zero(ray->origin.y) &&
           num_is_plus_zero(ray->origin.z);
}

/* trace_tree_as compiled once for each walk there is: a camera ray's by
 * screen (from the eye of eye space or not) or not, other nearest-hit
 * rays', shadow rays', straight rays'. */
static void trace_cluster(trace_walk_t *w, uint32_t index)
{
    if (w->mode == TRACE_COLLECT_SHADOW)
        trace_tree_as(w, TRACE_COLLECT_SHADOW, 0, 0, index);
    else if (w->mode == TRACE_COLLECT_STRAIGHT)
        trace_tree_as(w, TRACE_COLLECT_STRAIGHT, 0, 0, index);
    else if (w->screen && trace_from_eye(w->ray))
        trace_tree_as(w, TRACE_NEAREST, 1, 1, index);
    else if (w->screen)
        trace_tree_as(w, TRACE_NEAREST, 1, 0, index);
    else
        trace_tree_as(w, TRACE_NEAREST, 0, 0, index);
}

/* A shadow ray's walk of the items its light buffer's cell lists, each
 * box first (render/lightbuf.h); a primitive beyond the face of its local
 * cube that the light lies beyond, at both ends of the ray, not at all. */
static void trace_walk_items(trace_walk_t *w, const render_frame_t *f)
{
    int box_ray = 0; /* w->box_ray worked out: before the first box test */
    for (uint32_t mask = w->lb_mask; mask && !trace_walk_done_as(w, TRACE_COLLECT_SHADOW);
         mask &= mask - 1) {
        uint32_t k = (uint32_t)__builtin_ctz(mask), item = w->lb->item[k];
        int prim = !(item & RENDER_LB_CLUSTER);
        if (item == w->left ||
            (prim && w->lb_face[k] && prim_face_clear(&f->prims[item], w->ray, w->err, w->tmin,
                                                      w->tmax, (uint8_t)(w->lb_face[k] - 1))))
            continue; /* left, or beyond the face its light lies beyond, all of it */
        if (!box_ray) {
            prim_aabb_ray(w->ray, &w->box_ray);
            box_ray = 1;
        }
        if (!prim) {
            uint32_t c = item & ~RENDER_LB_CLUSTER;
            if (trace_box(w, &f->clusters[c].bounds))
                trace_cluster(w, c);
        } else if (trace_box(w, &f->prims[item].bounds)) {
            trace_test_prim(w, item);
        }
    }
}

/* The walk itself: a light buffer's items, the clusters given (clip), the
 * hierarchy, or every primitive. */
static void trace_walk_boxes(trace_walk_t *w, const render_frame_t *f, const uint32_t *clip,
                             uint32_t clip_count)
{
    if (w->lb) {
        trace_walk_items(w, f);
    } else if (clip) {
        w->by_list = 1;
        for (uint32_t k = 0; k < clip_count; k++) {
            const render_cluster_t *c = &f->clusters[clip[k]];
            if (!trace_box(w, &c->own_bounds))
                continue;
            trace_own_prims(w, c);
        }
    } else if (w->ctx->options.use_hierarchy) {
        if (trace_screen_tree(w, &f->clusters[0]) && trace_box_around(w, &f->clusters[0].bounds))
            trace_cluster(w, 0);
    } else {
        for (uint32_t prim = 0; prim < f->prim_count; prim++)
            if (trace_box(w, &f->prims[prim].bounds))
                trace_test_prim(w, prim);
    }
}

static void trace_walk(trace_walk_t *w, const uint32_t *clip, uint32_t clip_count)
{
    const render_frame_t *f = w->ctx->frame;
    if (!w->lb) /* a light buffer's walk works it out when it first needs it */
        prim_aabb_ray(w->ray, &w->box_ray);
    trace_walk_boxes(w, f, clip, clip_count);
    w->ctx->stats.box_tests += w->box_tests;
    w->ctx->stats.screen_tests += w->screen_tests;
    w->ctx->stats.prim_tests += w->prim_tests;
}

/* A ray of weight below RENDER_LOST_WEIGHT_VALUE changes the pixel by
 * less than 2/255 whatever its decisions: they are judged by the
 * primitives' own errors only, not by the error it carries (nor do the
 * rays it spawns, which weigh less still). */
static const ray_error_t *trace_err_if_heavy(const ray_error_t *err, const ray_error_t *none,
                                             num_t weight)
{
    return num_lt(weight, NUM_C(RENDER_LOST_WEIGHT_VALUE)) ? none : err;
}

/* An error bound no larger than NUM_FAR: a saturated or runaway one flags
 * every decision without overflowing what is computed from it. */
static num_t trace_err_clamp(num_t e) { return num_limit(e, NUM_FAR); }

/* The error a walk's decisions are widened by: the ray's, times
 * ctx->error_margin when that is over 1 (escalation's wider net:
 * render/wide.h), in *scaled. */
static const ray_error_t *trace_err_margin(const render_ctx_t *ctx, const ray_error_t *err,
                                           ray_error_t *scaled)
{
    if (!err || ctx->error_margin <= 1)
        return err;
    scaled->origin = trace_err_clamp(num_mul_int(err->origin, ctx->error_margin));
    scaled->dir = trace_err_clamp(num_mul_int(err->dir, ctx->error_margin));
    return scaled;
}

/* left: the primitive the ray leaves (trace_left), or TRACE_NO_PRIM.
 * screen (may be NULL): the pixel {x, y} a primary ray goes through, for
 * a walk that skips the subtrees whose screen rectangles miss it.  Not
 * inlined: its frame stays out of trace_ray's, which every level of the
 * recursion pays for (render/limits.h). */
static __attribute__((noinline)) int trace_nearest(render_ctx_t *ctx, const ray_t *ray, const ray_error_t *err, uint32_t left,
                         const uint32_t *clip, uint32_t clip_count, const int32_t *screen,
                         hit_t *hit)
{
    ray_error_t scaled;
    err = trace_err_margin(ctx, err, &scaled);
    trace_walk_t w;
    trace_walk_setup(&w, ctx, ray, err, NUM_ZERO, TRACE_FAR, TRACE_NEAREST, NULL);
    w.left = left;
    if (screen) {
        w.screen = 1;
        w.px = screen[0];
        w.py = screen[1];
    }
    trace_walk(&w, clip, clip_count);
    if (!w.nearest.found)
        return 0;
    hit->t = w.nearest.t;
    hit->prim = w.nearest.prim;
    /* two primitives hit at distances closer than their hit errors (where
     * two spheres cut each other), and the ray's own error on both (two
     * triangles carry none: a mesh's faces meet at one distance): either
     * may be the nearest */
    const render_prim_t *prims = ctx->frame->prims;
    if (w.nearest.runner_up) {
        num_t margin = num_add(prims[hit->prim].hit_error, prims[w.nearest.runner_prim].hit_error);
        if (num_gt(margin, NUM_ZERO))
            margin = num_add(margin, num_mul_int(ray_error_at(err, w.nearest.runner_t), 2));
        if (num_lt(num_sub(w.nearest.runner_t, w.nearest.t), margin))
            ctx->pixel_lost = 1;
    }
    prim_surface(&ctx->frame->prims[hit->prim], ray, hit);
    if (vec3_is_sat(hit->normal) || vec3_is_sat(hit->point) || ctx->frame->prims[hit->prim].imprecise)
        ctx->pixel_lost = 1;
    return 1;
}

/* ------------------------------------------------------------- shading */

/* One attribute map's value at the hit times coefficient c (c itself
 * without a map). */
static num_t trace_attribute(render_ctx_t *ctx, const hit_t *hit, uint16_t map, num_t c,
                             num_t uv_error)
{
    if (map == SCENE_NONE)
        return c;
    const scene_map_t *a = &ctx->frame->scene->maps[map];
    if (map_imprecise(a, uv_error))
        ctx->pixel_lost = 1;
    return num_mul(c, map_attribute(a, hit->u, hit->v));
}

/* Which ctx->look a hit's material goes to: the shaded hit's (a deeper
 * level's overwrites it once the level has used it), the straight
 * transmission's crossings', a shadow ray's crossings'. */
enum trace_look { TRACE_LOOK_SHADE, TRACE_LOOK_STRAIGHT, TRACE_LOOK_SHADOW };

/* Colour F at the hit (material colour times colour map), the shading
 * normal (bump or normal map applied) and the material there: m, or a copy
 * in ctx->look[slot] with dic, drc, src, trc times their attribute maps. */
static const scene_material_t *trace_surface_look(render_ctx_t *ctx, const hit_t *hit,
                                                  const scene_material_t *m, rgb_t *colour,
                                                  vec3_t *normal, enum trace_look slot)
{
    const scene_t *s = ctx->frame->scene;
    num_t uv_error = hit->uv_error;
    *colour = m->colour;
    if (m->colour_map != SCENE_NONE) {
        *colour = rgb_mul(*colour, map_colour(&s->maps[m->colour_map], hit->u, hit->v));
        if (map_imprecise(&s->maps[m->colour_map], uv_error))
            ctx->pixel_lost = 1;
    }
    *normal = hit->normal;
    if (m->bump_map != SCENE_NONE) {
        const scene_map_t *b = &s->maps[m->bump_map];
        *normal = map_bump(b, hit->u, hit->v, hit->normal,
                           prim_hit_tangent(&ctx->frame->prims[hit->prim], hit));
        if (map_bump_uncertain(b, hit->u, hit->v, uv_error))
            ctx->pixel_lost = 1;
    }
    if (m->normal_map != SCENE_NONE) {
        const scene_map_t *nm = &s->maps[m->normal_map];
        int mirrored, frame_uncertain;
        vec3_t t = prim_map_tangent(&ctx->frame->prims[hit->prim], hit, &mirrored, &frame_uncertain);
        *normal = map_normal(nm, hit->u, hit->v, hit->normal, t, mirrored);
        if (frame_uncertain || map_normal_uncertain(nm, hit->u, hit->v, uv_error))
            ctx->pixel_lost = 1;
    }
    if (m->dic_map == SCENE_NONE && m->drc_map == SCENE_NONE && m->src_map == SCENE_NONE &&
        m->trc_map == SCENE_NONE)
        return m;
    scene_material_t *here = &ctx->look[slot];
    *here = *m;
    here->dic = trace_attribute(ctx, hit, m->dic_map, m->dic, uv_error);
    here->drc = trace_attribute(ctx, hit, m->drc_map, m->drc, uv_error);
    here->src = trace_attribute(ctx, hit, m->src_map, m->src, uv_error);
    here->trc = trace_attribute(ctx, hit, m->trc_map, m->trc, uv_error);
    return here;
}

/* Whether the shading normal at hit may not be its shape's
 * (trace_shape_normal): turned by material m's bump or normal map, or
 * interpolated on a smooth triangle. */
static inline int trace_normal_turned(const render_ctx_t *ctx, const hit_t *hit,
                                      const scene_material_t *m)
{
    return m->bump_map != SCENE_NONE || m->normal_map != SCENE_NONE ||
           ctx->frame->prims[hit->prim].smooth;
}

/* The normal of the surface's own shape at hit: a triangle's plane's (a
 * smooth triangle's hit->normal is interpolated), else hit->normal. */
static inline __attribute__((always_inline)) vec3_t trace_shape_normal(const render_ctx_t *ctx,
                                                                        const hit_t *hit)
{
    const render_prim_t *p = &ctx->frame->prims[hit->prim];
    return p->kind == SCENE_PRIM_TRIANGLE ? p->normal : hit->normal;
}

/* The primitive a ray from hit cannot meet again, which its walk need not
 * test: the hit's, when the ray starts off its surface on the side of off
 * (the ray's origin is the hit moved along off) and moves away from it
 * (dir): a triangle's plane it does not cross again, and a convex
 * primitive (ellipsoid, box) lies wholly behind the plane that touches it
 * at the hit.  Otherwise TRACE_NO_PRIM. */
static inline __attribute__((always_inline)) uint32_t trace_left(const render_ctx_t *ctx,
                                                                   const hit_t *hit, vec3_t off,
                                                                   vec3_t dir)
{
    const render_prim_t *p = &ctx->frame->prims[hit->prim];
    vec3_t g = trace_shape_normal(ctx, hit);
    num_t a = vec3_dot(off, g), b = vec3_dot(dir, g);
    int away = num_gt(a, NUM_ZERO) && num_gt(b, NUM_ZERO);
    if (p->kind == SCENE_PRIM_TRIANGLE) /* a plane: either side */
        away = away || (num_lt(a, NUM_ZERO) && num_lt(b, NUM_ZERO));
    else if (p->kind != SCENE_PRIM_ELLIPSOID && p->kind != SCENE_PRIM_BOX)
        away = 0;
    return away ? hit->prim : TRACE_NO_PRIM;
}

/* Whether anything lies between origin and light `light` along dir over
 * distance: 0 when the light arrives whole, else 1 with *pass the fraction
 * that reaches origin, the product of trc(th) of every object crossed
 * (trc(th) F with options.shadow_tint) in primitive order.  err: the
 * shadow ray's error bound; left: the primitive it leaves (trace_left). */
static int trace_shadow(render_ctx_t *ctx, uint32_t light, vec3_t origin, vec3_t dir,
                        num_t distance, const ray_error_t *err, uint32_t left, rgb_t *pass)
{
    if (!ctx->options.shadows)
        return 0;
    ctx->stats.shadow++;
    const render_lightbuf_t *lb = ctx->light_buffer;
    uint32_t mask = 0;
    if (lb && ctx->options.use_bounds && ctx->options.use_hierarchy) {
        mask = render_lightbuf_mask(lb, light, origin, dir);
        if (!mask || (!(mask & (mask - 1)) && lb->item[__builtin_ctz(mask)] == left))
            return 0; /* its cell lists nothing, or only what it leaves */
    }
    ray_t ray = {origin, dir};
    crossings_t cross;
    cross.count = 0;
    cross.overflow = 0;
    cross.opaque = 0;
    ray_error_t scaled;
    trace_walk_t w;
    trace_walk_setup(&w, ctx, &ray, trace_err_margin(ctx, err, &scaled), ctx->frame->ray_epsilon,
                     distance, TRACE_COLLECT_SHADOW, &cross);
    w.left = left;
    if (mask) {
        w.lb = lb;
        w.lb_mask = mask;
        w.lb_face = lb->light[light].face;
    }
    trace_walk(&w, NULL, 0);
    if (cross.opaque || cross.overflow) {
        *pass = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        return 1;
    }
    if (!cross.count)
        return 0;
    *pass = rgb_make(NUM_ONE, NUM_ONE, NUM_ONE);
    /* primitive order: sort the few indices */
    for (uint32_t i = 1; i < cross.count; i++)
        for (uint32_t j = i; j > 0 && cross.prim[j] < cross.prim[j - 1]; j--) {
            uint32_t p = cross.prim[j];
            num_t t = cross.t[j];
            cross.prim[j] = cross.prim[j - 1];
            cross.t[j] = cross.t[j - 1];
            cross.prim[j - 1] = p;
            cross.t[j - 1] = t;
        }
    for (uint32_t i = 0; i < cross.count; i++) {
        hit_t hit;
        hit.t = cross.t[i];
        hit.prim = cross.prim[i];
        prim_surface(&ctx->frame->prims[hit.prim], &ray, &hit);
        rgb_t colour;
        vec3_t n;
        const scene_material_t *m = trace_surface_look(ctx, &hit, trace_material(ctx, hit.prim),
                                                       &colour, &n, TRACE_LOOK_SHADOW);
        num_t src, trc;
        shade_src_trc(m, num_abs(vec3_dot(n, dir)), &src, &trc);
        *pass = ctx->options.shadow_tint ? rgb_mul(*pass, rgb_scale(colour, trc))
                                         : rgb_scale(*pass, trc);
    }
    return 1;
}

/* A pixel that lost precision and will be traced again in the wide
 * arithmetic (ctx->escalate), which then gives its colour: the rest of
 * its rays here would be thrown away (not with options.check_lost, which
 * keeps this arithmetic's colour). */
static int trace_settled_elsewhere(const render_ctx_t *ctx)
{
    return ctx->pixel_lost && ctx->escalate && !ctx->options.check_lost;
}

/* Sum over lights of Fig. 5's per-light terms at a hit.  hit_err: how far
 * the hit point may be off (trace_hit_error): each shadow ray starts that
 * far off, and towards a point light its direction turns by hit_err over
 * the distance.  With options.ambient_shadowed the ambient term takes the
 * shadowed light too, and a light behind the surface (cos <= 0) is
 * shadowed by the surface itself: 0, no ray traced. */
static rgb_t trace_lights(render_ctx_t *ctx, const hit_t *hit, num_t hit_err,
                          const scene_material_t *m, rgb_t colour, vec3_t n, vec3_t view, num_t src)
{
    const render_frame_t *f = ctx->frame;
    rgb_t sum = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    vec3_t origin = vec3_madd(hit->point, n, ctx->frame->ray_epsilon);
    for (uint16_t i = 0; i < f->light_count; i++) {
        vec3_t to_light;
        num_t distance;
        rgb_t unshadowed;
        if (!shade_light_at(&f->lights[i], hit->point, &to_light, &distance, &unshadowed))
            continue;
        rgb_t shadowed = unshadowed, pass;
        int whole = 1; /* shadowed is unshadowed */
        if (num_gt(vec3_dot(n, to_light), NUM_ZERO)) {
            ray_error_t err = {hit_err, trace_err_clamp(num_add(num_div(hit_err, distance),
                                                               TRACE_DIR_ROUND))};
            if (trace_shadow(ctx, i, origin, to_light, distance, &err,
                             trace_left(ctx, hit, n, to_light), &pass)) {
                shadowed = rgb_mul(unshadowed, pass);
                whole = 0;
            }
            if (trace_settled_elsewhere(ctx))
                break; /* the other lights' shadow rays too */
        } else if (ctx->options.shadows) {
            shadowed = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
            whole = 0;
        }
        /* the ambient term takes the shadowed light, or the whole */
        const rgb_t *ambient = whole || ctx->options.ambient_shadowed ? NULL : &unshadowed;
        sum = rgb_add(sum, shade_light_term(m, colour, n, view, to_light, ambient, shadowed, src));
    }
    return sum;
}

static rgb_t trace_ray(render_ctx_t *ctx, const ray_t *ray, const ray_error_t *err, uint32_t left,
                       int depth, num_t weight);

/* How far a hit may lie from the double build's: the ray's error at its t
 * plus the primitive's own (render_prim_t.hit_error). */
static num_t trace_hit_error_along(const render_ctx_t *ctx, num_t along, const hit_t *hit)
{
    return trace_err_clamp(num_add(along, ctx->frame->prims[hit->prim].hit_error));
}

static num_t trace_hit_error(const render_ctx_t *ctx, const ray_error_t *err, const hit_t *hit)
{
    return trace_hit_error_along(ctx, ray_error_at(err, hit->t), hit);
}

/* How far a hit may lie from the double build's along its surface: a ray
 * moved sideways by e (along: ray_error_at at the hit) meets a surface at
 * incidence cos c up to e / c away (c at least TRACE_COS_FLOOR), plus the
 * primitive's own.
 * The shadow rays start there, the normal turns by it and a refracted ray
 * starts there; a mirrored ray, parallel to the double build's out of the
 * mirror, keeps e (trace_hit_error). */
static num_t trace_surface_error(const render_ctx_t *ctx, num_t along, const hit_t *hit, vec3_t dir)
{
    num_t c = num_max(num_abs(vec3_dot(dir, hit->normal)), TRACE_COS_FLOOR);
    return trace_hit_error_along(ctx, num_div(along, c), hit);
}

/* Where the shadow rays of a hit start, for their decisions: the hit's
 * error along the surface (surface_err), unless what a shadow changes
 * there (diffuse drc, highlight src(th) and, when shadowed, ambient dic,
 * times the weight of the ray that made the hit, for lights of colour at
 * most 1) is under RENDER_LOST_WEIGHT_VALUE: then only the primitive's
 * own, as for a light ray (trace_err_if_heavy). */
static num_t trace_shadow_error(const render_ctx_t *ctx, num_t surface_err, const hit_t *hit,
                                const scene_material_t *m, num_t weight, num_t src)
{
    num_t shaded = num_add(m->drc, src);
    if (ctx->options.ambient_shadowed)
        shaded = num_add(shaded, m->dic);
    if (num_lt(num_mul(weight, shaded), NUM_C(RENDER_LOST_WEIGHT_VALUE)))
        return ctx->frame->prims[hit->prim].hit_error;
    return surface_err;
}

/* Refractionless transmission past the depth limit: the straight ray
 * registers every object it crosses (the transmission buffer, nearest
 * first); each adds its local shading weighted by the transmittance so
 * far, until an opaque one or the background ends the ray. */
__attribute__((noinline)) /* its buffers stay out of trace_shade's frame,
                             which every recursion level pays for */
static rgb_t trace_straight(render_ctx_t *ctx, const ray_t *ray, const ray_error_t *err,
                            num_t ray_weight)
{
    ctx->stats.transmission++;
    crossings_t cross;
    cross.count = 0;
    cross.overflow = 0;
    cross.opaque = 0;
    ray_error_t scaled;
    trace_walk_t w;
    trace_walk_setup(&w, ctx, ray, trace_err_margin(ctx, err, &scaled), ctx->frame->ray_epsilon,
                     TRACE_FAR, TRACE_COLLECT_STRAIGHT, &cross);
    trace_walk(&w, NULL, 0);
    rgb_t sum = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    rgb_t weight = rgb_make(NUM_ONE, NUM_ONE, NUM_ONE);
    num_t from = NUM_ZERO; /* with haze: each crossing starts a ray of its own */
    for (uint32_t i = 0; i < cross.count; i++) {
        hit_t hit;
        hit.t = cross.t[i];
        hit.prim = cross.prim[i];
        prim_surface(&ctx->frame->prims[hit.prim], ray, &hit);
        rgb_t colour;
        vec3_t n;
        const scene_material_t *m = trace_surface_look(ctx, &hit, trace_material(ctx, hit.prim),
                                                       &colour, &n, TRACE_LOOK_STRAIGHT);
        if (num_gt(vec3_dot(ray->dir, n), NUM_ZERO))
            n = vec3_neg(n);
        num_t src, trc;
        shade_src_trc(m, num_neg(vec3_dot(ray->dir, n)), &src, &trc);
        num_t along = ray_error_at(err, hit.t);
        num_t hit_err = trace_shadow_error(ctx, trace_surface_error(ctx, along, &hit, ray->dir),
                                           &hit, m, ray_weight, src);
        rgb_t local = trace_lights(ctx, &hit, hit_err, m, colour, n, ray->dir, src);
        if (ctx->frame->scene->haze) { /* this crossing's share and the haze's before it */
            num_t seg = num_sub(hit.t, from), w = haze_weight(ctx, seg);
            rgb_t hazed = haze_apply(ctx, local, seg, trace_hit_error_along(ctx, along, &hit),
                                     ray_weight);
            sum = rgb_add(sum, rgb_mul(weight, hazed));
            weight = rgb_scale(weight, w);
            from = hit.t;
        } else {
            sum = rgb_add(sum, rgb_mul(weight, local));
        }
        if (!num_gt(trc, NUM_ZERO))
            return sum;
        weight = rgb_mul(weight, rgb_scale(colour, trc));
    }
    if (cross.overflow) /* the objects past the buffer are unknown: stop dark */
        return sum;
    return rgb_add(sum, rgb_mul(weight, haze_miss(ctx)));
}

/* Adaptive depth: a secondary ray of weight w (the product of src and trc
 * along its path) is traced only while w >= min_weight; min_weight 0 keeps
 * every ray max_depth allows. */
static int trace_worth(const render_ctx_t *ctx, num_t weight)
{
    return !num_lt(weight, ctx->options.min_weight);
}

/* A refracted direction's error.  In the plane of incidence Snell's law
 * turns the ray by g = eta cos_i / cos_t times the change of the angle of
 * incidence; the direction out is the normal's turned by that angle, so it
 * moves by g times the ray's error and (1 - g) times the normal's.  Across
 * that plane the factor is eta instead of g.  Without bound at the
 * critical angle. */
static num_t trace_refract_error(const ray_error_t *err, num_t normal_err, num_t eta,
                                 num_t cos_i, vec3_t refracted, vec3_t n)
{
    num_t cos_t = num_neg(vec3_dot(refracted, n));
    if (!num_gt(cos_t, NUM_ZERO))
        return NUM_FAR;
    num_t g = trace_err_clamp(num_div(num_mul(eta, cos_i), cos_t));
    num_t dir_gain = num_max(g, eta);
    num_t normal_gain = num_max(num_abs(num_sub(NUM_ONE, g)), num_abs(num_sub(NUM_ONE, eta)));
    return trace_err_clamp(num_add(num_mul(dir_gain, err->dir), num_mul(normal_gain, normal_err)));
}

/* Whether the surface itself blocks a ray spawned at hit along dir, the
 * ray that made the hit arriving along in: through 0 for a mirrored ray
 * (it should leave on the side in came from) and 1 for a refracted one
 * (the other side), both sides of the surface's own shape
 * (trace_shape_normal).  A shading normal turned by a bump map or a
 * smooth mesh can send it to the wrong side, into the surface it leaves or
 * back out of it; traced, it would meet that surface again a hair away
 * and shade it as if seen (a grazing mirrored ray, again and again: a
 * sparkle).  Blocked, it is not traced, as a light behind the surface is
 * not (counted in stats.self_blocked).  A normal not turned (turned 0:
 * trace_normal_turned) sends none there.  A direction within its error of
 * the shape's plane (err_in: in's, err_dir: dir's) may lie on the other
 * side in another arithmetic: the pixel loses precision, unless the ray's
 * weight is too low to matter (trace_err_if_heavy).  Under Haines's SPD
 * rules every ray is spawned. */
static int trace_self_blocked(render_ctx_t *ctx, const hit_t *hit, int turned, vec3_t in,
                              num_t err_in, vec3_t dir, num_t err_dir, int through, num_t weight)
{
    if (!turned || ctx->options.spd_rules)
        return 0;
    vec3_t g = trace_shape_normal(ctx, hit);
    num_t a = num_neg(vec3_dot(in, g)), b = vec3_dot(dir, g);
    if (through)
        b = num_neg(b);
    if ((!num_gt(num_abs(a), num_add(err_in, TRACE_DIR_ROUND)) ||
         !num_gt(num_abs(b), num_add(err_dir, TRACE_DIR_ROUND))) &&
        !num_lt(weight, NUM_C(RENDER_LOST_WEIGHT_VALUE)))
        ctx->pixel_lost = 1;
    int blocked = (num_gt(a, NUM_ZERO) && num_lt(b, NUM_ZERO)) ||
                  (num_lt(a, NUM_ZERO) && num_gt(b, NUM_ZERO));
    ctx->stats.self_blocked += (uint64_t)blocked;
    return blocked;
}

/* weight: the product of src and trc along the path of the ray that made
 * this hit (1 for a camera ray); err: that ray's error bound.  The hit
 * point's error starts a mirrored ray, its error along the surface
 * (trace_surface_error) the shadow and refracted rays; the normal's (that
 * times the surface's curvature) turns a mirrored ray by twice as much. */
static rgb_t trace_shade(render_ctx_t *ctx, const ray_t *ray, const ray_error_t *err,
                         const hit_t *hit, int depth, num_t weight)
{
    if (trace_settled_elsewhere(ctx))
        return rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    rgb_t colour;
    vec3_t n;
    const scene_material_t *m = trace_surface_look(ctx, hit, trace_material(ctx, hit->prim),
                                                   &colour, &n, TRACE_LOOK_SHADE);
    int turned = trace_normal_turned(ctx, hit, m);
    int entering = num_lt(vec3_dot(ray->dir, n), NUM_ZERO);
    if (!entering)
        n = vec3_neg(n); /* shade the side the ray arrives on */
    num_t cos_theta = num_neg(vec3_dot(ray->dir, n));
    num_t src, trc;
    shade_src_trc(m, cos_theta, &src, &trc);
    num_t along = ray_error_at(err, hit->t);
    num_t hit_err = trace_hit_error_along(ctx, along, hit);
    num_t surface_err = trace_surface_error(ctx, along, hit, ray->dir);
    /* From the inside of a closed surface (its concave side) a ray moved
     * or turned meets a normal turned so as to fold it back: a chord of a
     * sphere meets the surface at the same angle at both ends, so the
     * error grows only along the chord (through the origin's error), not
     * by the normal again at every bounce.  There only the surface's own
     * error turns the normal. */
    const render_prim_t *p = &ctx->frame->prims[hit->prim];
    num_t moved = entering ? surface_err : p->hit_error;
    num_t normal_err = trace_err_clamp(num_add(num_mul(moved, hit->curvature), TRACE_DIR_ROUND));
    rgb_t out = trace_lights(ctx, hit, trace_shadow_error(ctx, surface_err, hit, m, weight, src), m,
                             colour, n, ray->dir, src);

    int can_recurse = depth < ctx->options.max_depth;
    /* Where a refracted ray would go, or total internal reflection: then
     * the mirrored ray carries the transmitted share too, and its weight
     * is the sum of both. */
    vec3_t refracted_dir;
    int refracts = 0, tir = 0;
    num_t eta = NUM_ONE;
    if (num_gt(trc, NUM_ZERO) && can_recurse && ctx->options.refraction) {
        eta = entering ? num_recip(m->ior) : m->ior; /* m's last use: the levels below
                                                        reuse ctx->look[TRACE_LOOK_SHADE] */
        refracts = shade_refract(ray->dir, n, eta, &refracted_dir);
        tir = !refracts;
    }
    num_t w_mirror = num_mul(weight, tir ? num_add(src, trc) : src);
    rgb_t reflected = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    vec3_t outside = vec3_madd(hit->point, n, ctx->frame->ray_epsilon);
    /* under Haines's SPD rules a transmitting surface spawns a reflected
     * ray too (its share src may be 0) */
    int mirror = can_recurse && (num_gt(src, NUM_ZERO) || tir ||
                                 (ctx->options.spd_rules && num_gt(trc, NUM_ZERO)));
    if (mirror && !trace_worth(ctx, w_mirror)) {
        ctx->stats.weight_cut++; /* too faint to matter: not traced */
    } else if (mirror) {
        ray_t r = {outside, shade_reflect(ray->dir, n)};
        ray_error_t r_err = {hit_err, trace_err_clamp(num_add(err->dir, num_mul_int(normal_err, 2)))};
        if (!trace_self_blocked(ctx, hit, turned, ray->dir, err->dir, r.dir, r_err.dir, 0,
                                w_mirror)) {
            ctx->stats.reflection++;
            reflected = trace_ray(ctx, &r, &r_err, trace_left(ctx, hit, n, r.dir), depth + 1,
                                  w_mirror);
            if (num_gt(src, NUM_ZERO))
                out = rgb_add(out, rgb_scale(reflected, src));
        }
    }
    if (num_gt(trc, NUM_ZERO)) {
        rgb_t through = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        vec3_t inside = vec3_madd(hit->point, n, num_neg(ctx->frame->ray_epsilon));
        num_t w_trc = num_mul(weight, trc);
        ray_error_t straight_err = {hit_err, err->dir}, none = {NUM_ZERO, NUM_ZERO};
        const ray_error_t *s_err = trace_err_if_heavy(&straight_err, &none, w_trc);
        if (!ctx->options.refraction) { /* never bends: straight through, any depth */
            ray_t r = {inside, ray->dir};
            through = trace_straight(ctx, &r, s_err, w_trc);
        } else if (tir) { /* total internal reflection: the light stays inside */
            through = reflected;
        } else if (refracts && !trace_worth(ctx, w_trc)) {
            ctx->stats.weight_cut++;
        } else if (refracts) {
            ray_t r = {inside, refracted_dir};
            ray_error_t r_err = {surface_err, trace_refract_error(err, normal_err, eta, cos_theta,
                                                              refracted_dir, n)};
            if (!trace_self_blocked(ctx, hit, turned, ray->dir, err->dir, r.dir, r_err.dir, 1,
                                    w_trc)) {
                ctx->stats.refraction++;
                through = trace_ray(ctx, &r, &r_err, trace_left(ctx, hit, vec3_neg(n), r.dir),
                                    depth + 1, w_trc);
            }
        } else if (!can_recurse && ctx->options.refractionless) {
            ray_t r = {inside, ray->dir};
            through = trace_straight(ctx, &r, s_err, w_trc);
        }
        out = rgb_add(out, rgb_scale(rgb_mul(colour, through), trc));
    }
    if (rgb_is_sat(out))
        ctx->pixel_lost = 1;
    return out;
}

static rgb_t trace_ray(render_ctx_t *ctx, const ray_t *ray, const ray_error_t *err, uint32_t left,
                       int depth, num_t weight)
{
    if (trace_settled_elsewhere(ctx))
        return rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    ray_error_t none = {NUM_ZERO, NUM_ZERO};
    err = trace_err_if_heavy(err, &none, weight);
    hit_t hit;
    if (!trace_nearest(ctx, ray, err, left, NULL, 0, NULL, &hit))
        return haze_miss(ctx);
    rgb_t c = trace_shade(ctx, ray, err, &hit, depth, weight);
    if (ctx->frame->scene->haze)
        c = haze_apply(ctx, c, hit.t, trace_hit_error(ctx, err, &hit), weight);
    return c;
}

/* --------------------------------------------------------------- pixels */

void render_ctx_init(render_ctx_t *ctx, const render_frame_t *frame)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->frame = frame;
    ctx->options = frame->options;
}

/* How a camera ray looks for its nearest hit. */
typedef enum {
    PIXEL_SEARCH_TREE,   /* the hierarchy from its root */
    PIXEL_SEARCH_SCREEN, /* the hierarchy, its boxes first tested by the pixel on the screen */
    PIXEL_SEARCH_LIST,   /* only the clusters of the area's clipping list (clip, clip_count) */
} pixel_search_t;

/* The colour along the camera ray through screen point (sx, sy), screen
 * coordinates in [-1, 1]; pixel: the pixel a search by screen tests.
 * ctx->pixel_lost says whether it lost precision. */
static rgb_t render_eye(render_ctx_t *ctx, num_t sx, num_t sy, pixel_search_t search,
                        const int32_t pixel[2], const uint32_t *clip, uint32_t clip_count)
{
    const render_frame_t *f = ctx->frame;
    /* scaled by the half extents of the view at z = 1 */
    ray_t ray;
    vec3_t through = vec3_make(num_mul(sx, f->screen_half_w), num_mul(sy, f->screen_half_h), NUM_ONE);
    ray_error_t err = {NUM_ZERO, TRACE_DIR_ROUND}; /* from the eye, exactly */
    if (f->world) {
        /* from the eye (its coordinates rounded to the arithmetic: a step
         * at the extent), turned by the camera's axes (a unit vector's
         * rounding more) */
        ray.origin = f->eye;
        ray.dir = vec3_normalize(xform_dir(&f->eye_to_world, through));
        err.origin = num_ulp(f->precision_extent);
        err.dir = num_mul_int(TRACE_DIR_ROUND, 2);
    } else {
        ray.origin = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        ray.dir = vec3_normalize(through);
    }
    ctx->pixel_lost = f->precision_lost; /* preparing lost it: every pixel */
    ctx->stats.primary++;
    /* trace_ray at depth 0, split so the camera ray's own search is
     * counted apart from the secondary rays of its shading */
    uint64_t boxes = ctx->stats.box_tests, prims = ctx->stats.prim_tests;
    hit_t hit;
    int found = trace_nearest(ctx, &ray, &err, TRACE_NO_PRIM,
                              search == PIXEL_SEARCH_LIST ? clip : NULL, clip_count,
                              search == PIXEL_SEARCH_SCREEN ? pixel : NULL, &hit);
    ctx->stats.primary_box_tests += ctx->stats.box_tests - boxes;
    ctx->stats.primary_prim_tests += ctx->stats.prim_tests - prims;
    ctx->stats.primary_hit += found != 0;
    rgb_t c = found ? trace_shade(ctx, &ray, &err, &hit, 0, NUM_ONE) : haze_miss(ctx);
    if (found && f->scene->haze)
        c = haze_apply(ctx, c, hit.t, trace_hit_error(ctx, &err, &hit), NUM_ONE);
    if (rgb_is_sat(c))
        ctx->pixel_lost = 1;
    return c;
}

/* A pixel's colour c as bytes, counted (and painted, with mark_lost) when
 * it lost precision and no escalation settles it. */
static rgb8_t render_pixel_out(render_ctx_t *ctx, rgb_t c)
{
    rgb8_t out = {num_to_u8(c.r), num_to_u8(c.g), num_to_u8(c.b)};
    if (ctx->pixel_lost && ctx->escalate) /* settled by the caller: render_pixel_settled */
        return out;
    if (ctx->pixel_lost) {
        ctx->stats.precision_lost_pixels++;
        if (ctx->options.mark_lost)
            return RENDER_LOST_COLOUR;
    }
    return out;
}

/* Where a sample of a pixel's anti-aliasing searches: as the pixel
 * would (render_eye's search, pixel and list). */
typedef struct {
    pixel_search_t how;
    int32_t pixel[2];
    const uint32_t *clip;
    uint32_t clip_count;
} render_aa_search_t;

/* Screen coordinate 0..2 of grid line g of a grid scale steps a pixel
 * side, over n pixels.  g and scale are halved while both are even, so
 * that a point has one representation, and so one value, whoever traces
 * it: a corner is (cx, 1), as it was before any grid.  scale is a power
 * of two (anti-aliasing), or g is odd (supersampling's centres). */
static num_t render_grid(uint32_t g, uint32_t scale, uint32_t n)
{
    while (scale > 1 && (g & 1) == 0) {
        g >>= 1;
        scale >>= 1;
    }
    return num_from_ratio((int32_t)(2 * g), (int32_t)(n * scale));
}

/* The camera ray through grid point (gx, gy) (render_grid), into *out. */
static void render_sample(render_ctx_t *ctx, uint32_t gx, uint32_t gy, uint32_t scale,
                          const render_aa_search_t *s, render_corner_t *out)
{
    const render_frame_t *f = ctx->frame;
    num_t sx = num_sub(render_grid(gx, scale, f->width), NUM_ONE);
    num_t sy = num_sub(NUM_ONE, render_grid(gy, scale, f->height));
    out->colour = render_eye(ctx, sx, sy, s->how, s->pixel, s->clip, s->clip_count);
    out->lost = ctx->pixel_lost;
}

/* The mean of four colours, *lost set when it saturates: a pixel's of
 * its corners, an anti-aliased quad's of its corners or its quarters. */
static rgb_t render_mean4(rgb_t a, rgb_t b, rgb_t c, rgb_t d, uint8_t *lost)
{
    rgb_t mean = rgb_scale(rgb_add(rgb_add(a, b), rgb_add(c, d)), NUM_C(0.25));
    if (rgb_is_sat(mean))
        *lost = 1;
    return mean;
}

/* 1 when in one channel the largest of q[0], q[1], q[k], q[k + 1] is
 * more than t above the smallest. */
static int render_aa_apart(const render_corner_t *q, uint32_t k, num_t t)
{
    const rgb_t *c[4] = {&q[0].colour, &q[1].colour, &q[k].colour, &q[k + 1].colour};
    for (int ch = 0; ch < 3; ch++) {
        num_t lo = ch == 0 ? c[0]->r : ch == 1 ? c[0]->g : c[0]->b, hi = lo;
        for (int i = 1; i < 4; i++) {
            num_t v = ch == 0 ? c[i]->r : ch == 1 ? c[i]->g : c[i]->b;
            lo = num_min(lo, v);
            hi = num_max(hi, v);
        }
        if (num_gt(num_sub(hi, lo), t))
            return 1;
    }
    return 0;
}

/* Whitted's adaptive anti-aliasing of a quad of side grid steps whose
 * top-left is grid point (gx, gy), its corners q[0], q[1] (top) and q[k],
 * q[k + 1] (bottom): their mean when side is 1 (the depth limit) or they
 * do not differ by more than the threshold; else the mean of its four
 * quarters, the five new points (edge midpoints, centre) traced here. */
static rgb_t render_aa_quad(render_ctx_t *ctx, const render_aa_search_t *s, uint32_t scale,
                            uint32_t gx, uint32_t gy, uint32_t side, const render_corner_t *q,
                            uint32_t k, uint8_t *lost)
{
    if (side == 1 || !render_aa_apart(q, k, ctx->options.aa_threshold))
        return render_mean4(q[0].colour, q[1].colour, q[k].colour, q[k + 1].colour, lost);
    uint32_t h = side / 2;
    render_corner_t g[9]; /* 3 x 3: corners, edge midpoints, centre */
    g[0] = q[0];
    g[2] = q[1];
    g[6] = q[k];
    g[8] = q[k + 1];
    static const uint8_t at[5][3] = {{1, 1, 0}, {3, 0, 1}, {4, 1, 1}, {5, 2, 1}, {7, 1, 2}};
    for (int i = 0; i < 5; i++) {
        render_corner_t *p = &g[at[i][0]];
        render_sample(ctx, gx + at[i][1] * h, gy + at[i][2] * h, scale, s, p);
        *lost |= p->lost;
    }
    rgb_t c[4];
    for (uint32_t i = 0; i < 4; i++) {
        uint32_t cx = i & 1, cy = i >> 1;
        c[i] = render_aa_quad(ctx, s, scale, gx + cx * h, gy + cy * h, h, &g[cy * 3 + cx], 3,
                              lost);
    }
    return render_mean4(c[0], c[1], c[2], c[3], lost);
}

/* Pixel (x, y) from its corners c[0..3] (top-left, top-right,
 * bottom-left, bottom-right): their mean, or with options.antialias,
 * Whitted's subdivision (render_aa_quad) searched as s says; lost
 * precision when any ray did. */
static rgb8_t render_pixel_corners(render_ctx_t *ctx, uint32_t x, uint32_t y,
                                   const render_corner_t c[4], const render_aa_search_t *s)
{
    uint8_t lost = c[0].lost || c[1].lost || c[2].lost || c[3].lost;
    rgb_t colour;
    if (ctx->options.antialias) {
        uint32_t scale = 1u << ctx->options.aa_depth;
        colour = render_aa_quad(ctx, s, scale, x * scale, y * scale, scale, c, 2, &lost);
    } else {
        colour = render_mean4(c[0].colour, c[1].colour, c[2].colour, c[3].colour, &lost);
    }
    ctx->pixel_lost = lost;
    return render_pixel_out(ctx, colour);
}

/* Not inlined: its frame (the camera ray's hit and more) is gone before an
 * escalation traces the pixel again on the same stack. */
static __attribute__((noinline)) rgb8_t render_pixel_impl(render_ctx_t *ctx, uint32_t x,
                                                         uint32_t y, pixel_search_t search,
                                                         const uint32_t *clip,
                                                         uint32_t clip_count)
{
    const render_frame_t *f = ctx->frame;
    const render_aa_search_t s = {search, {(int32_t)x, (int32_t)y}, clip, clip_count};
    if (render_corner_mode(&ctx->options)) { /* its four corners, none shared */
        render_corner_t c[4];
        for (uint32_t k = 0; k < 4; k++)
            render_corner(ctx, x + (k & 1), y + (k >> 1), RENDER_CORNER_TREE, NULL, 0, 1, &c[k]);
        return render_pixel_corners(ctx, x, y, c, &s);
    }
    /* through the pixel centre */
    num_t sx = num_sub(num_from_ratio((int32_t)(2 * x + 1), f->width), NUM_ONE);
    num_t sy = num_sub(NUM_ONE, num_from_ratio((int32_t)(2 * y + 1), f->height));
    return render_pixel_out(ctx, render_eye(ctx, sx, sy, search, s.pixel, clip, clip_count));
}

/* The pixel search a render_corner_search_t names. */
static pixel_search_t render_search_of(const render_ctx_t *ctx, render_corner_search_t search)
{
    return search == RENDER_CORNER_LIST ? PIXEL_SEARCH_LIST
           : search == RENDER_CORNER_SCREEN && ctx->options.use_hierarchy ? PIXEL_SEARCH_SCREEN
                                                                           : PIXEL_SEARCH_TREE;
}

/* Search how at pixel (x, y) through the list clusters (count); NULL is
 * clipping that kept nothing: a non-NULL empty list. */
static render_aa_search_t render_aa_search(pixel_search_t how, uint32_t x, uint32_t y,
                                           const uint32_t *clusters, uint32_t count)
{
    static const uint32_t none[1] = {0};
    return (render_aa_search_t){how, {(int32_t)x, (int32_t)y}, clusters ? clusters : none,
                                clusters ? count : 0};
}

void render_corner(render_ctx_t *ctx, uint32_t cx, uint32_t cy, render_corner_search_t search,
                   const uint32_t *clusters, uint32_t count, int counted, render_corner_t *out)
{
    const render_frame_t *f = ctx->frame;
    /* the corner lies in the closed square of this pixel, which every
     * screen rectangle holding the corner holds (render/prepare.c widens
     * them by a pixel) */
    const render_aa_search_t s =
        render_aa_search(render_search_of(ctx, search), cx < f->width ? cx : cx - 1u,
                         cy < f->height ? cy : cy - 1u, clusters, count);
    render_stats_t before;
    if (!counted)
        before = ctx->stats;
    render_sample(ctx, cx, cy, 1, &s, out);
    if (!counted)
        ctx->stats = before;
}

/* 1 when a and b differ by more than RENDER_CHECK_LOST_STEPS in a channel. */
static int rgb8_apart(rgb8_t a, rgb8_t b)
{
    int d[3] = {a.r - b.r, a.g - b.g, a.b - b.b};
    for (int i = 0; i < 3; i++)
        if (d[i] > RENDER_CHECK_LOST_STEPS || d[i] < -RENDER_CHECK_LOST_STEPS)
            return 1;
    return 0;
}

/* A pixel that lost precision, with ctx->escalate set: traced again in
 * the wide arithmetic, whose colour (and loss) it takes; with
 * options.check_lost it keeps its own colour c and stays lost only when
 * the wide one is apart from it (or lost too). */
static rgb8_t render_pixel_settled(render_ctx_t *ctx, uint32_t x, uint32_t y, rgb8_t c)
{
    if (!ctx->escalate || !ctx->pixel_lost)
        return c;
    uint8_t lost = 0;
    rgb8_t wide = ctx->escalate(ctx->escalate_arg, x, y, &lost);
    ctx->stats.escalated_pixels++;
    if (ctx->options.check_lost)
        lost = lost || rgb8_apart(c, wide);
    ctx->stats.precision_lost_pixels += lost != 0;
    ctx->pixel_lost = lost != 0;
    if (!ctx->options.check_lost)
        return wide;
    return lost && ctx->options.mark_lost ? RENDER_LOST_COLOUR : c;
}

rgb8_t render_pixel_of_corners(render_ctx_t *ctx, uint32_t x, uint32_t y,
                               const render_corner_t c[4], render_corner_search_t search,
                               const uint32_t *clusters, uint32_t count)
{
    const render_aa_search_t s =
        render_aa_search(render_search_of(ctx, search), x, y, clusters, count);
    return render_pixel_settled(ctx, x, y, render_pixel_corners(ctx, x, y, c, &s));
}

rgb8_t render_pixel_supersampled(render_ctx_t *ctx, uint32_t x, uint32_t y, uint32_t n)
{
    const render_aa_search_t s = {PIXEL_SEARCH_TREE, {(int32_t)x, (int32_t)y}, NULL, 0};
    uint32_t scale = 2 * n; /* the sub-squares' centres: odd grid points */
    rgb_t sum = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    uint8_t lost = 0;
    for (uint32_t j = 0; j < n; j++) {
        rgb_t row = rgb_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        for (uint32_t i = 0; i < n; i++) {
            render_corner_t c;
            render_sample(ctx, scale * x + 2 * i + 1, scale * y + 2 * j + 1, scale, &s, &c);
            row = rgb_add(row, c.colour);
            lost |= c.lost;
        }
        sum = rgb_add(sum, row);
    }
    rgb_t mean = rgb_scale(sum, num_from_ratio(1, (int32_t)(n * n)));
    ctx->pixel_lost = lost || rgb_is_sat(mean);
    return render_pixel_out(ctx, mean);
}

rgb8_t render_pixel(render_ctx_t *ctx, uint32_t x, uint32_t y)
{
    return render_pixel_settled(ctx, x, y,
                                render_pixel_impl(ctx, x, y, PIXEL_SEARCH_TREE, NULL, 0));
}

rgb8_t render_pixel_screen(render_ctx_t *ctx, uint32_t x, uint32_t y)
{
    pixel_search_t search = ctx->options.use_hierarchy ? PIXEL_SEARCH_SCREEN : PIXEL_SEARCH_TREE;
    return render_pixel_settled(ctx, x, y, render_pixel_impl(ctx, x, y, search, NULL, 0));
}

rgb8_t render_pixel_clipped(render_ctx_t *ctx, uint32_t x, uint32_t y, const uint32_t *clusters, uint32_t count)
{
    const render_aa_search_t s = render_aa_search(PIXEL_SEARCH_LIST, x, y, clusters, count);
    return render_pixel_settled(ctx, x, y,
                                render_pixel_impl(ctx, x, y, s.how, s.clip, s.clip_count));
}

void render_span(render_ctx_t *ctx, uint32_t y, uint32_t x0, uint32_t x1, rgb8_t *out)
{
    for (uint32_t x = x0; x < x1; x++)
        out[x - x0] = render_pixel(ctx, x, y);
}
