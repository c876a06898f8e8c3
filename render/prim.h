/* render/prim.h: ray-primitive intersection and surface details.
 *
 * A ray is o + t*d in eye coordinates with d of unit length, so t is a
 * distance.  prim_intersect finds only the distance (all a shadow ray
 * needs); prim_surface then fills normal and map coordinates for the one
 * hit that is shaded.  prim_intersect's answer never depends on tmax except
 * for the final "t <= tmax" check, so the nearest hit is the same whatever
 * order primitives are tested in and whatever boxes were skipped.
 */
#ifndef LINKS1_RENDER_PRIM_H
#define LINKS1_RENDER_PRIM_H

#include "render/render.h"

typedef struct {
    vec3_t origin;
    vec3_t dir;      /* unit length */
} ray_t;

typedef struct {
    num_t t;         /* distance along the ray */
    uint32_t prim;   /* index into frame->prims */
    vec3_t point;    /* eye-space hit point */
    vec3_t normal;   /* unit outward geometric normal (may face the ray or not) */
    vec3_t tangent_hint; /* local: what prim_hit_tangent makes the tangent of
                            (prim_surface's; not a triangle's) */
    num_t u, v;      /* map coordinates, u and v in [0,1] */
    num_t uv_error;  /* their rounding error (render_prim_t.uv_error, a box
                        face's own) */
    num_t curvature; /* the normal turns by at most this times the hit's
                        move (render_prim_t.curvature, an ellipsoid's here) */
} hit_t;

/* Nearest t with tmin < t <= tmax where the ray meets the surface; 1 if
 * found (and *t_out set), 0 otherwise.  Rays starting inside a closed
 * primitive find the exit point. */
int prim_intersect(const render_prim_t *p, const ray_t *ray, num_t tmin, num_t tmax, num_t *t_out);

/* How far rounding may have moved a ray from the double build's (an error
 * bound, eye units): its origin by up to `origin`, its direction turned by
 * up to `dir` radians, so its point at t by up to origin + t * dir.  A
 * camera ray's is a few steps of its direction; a secondary ray's the hit
 * point's error and what the normal's error does to the new direction
 * (render/trace.c). */
typedef struct {
    num_t origin;
    num_t dir;
} ray_error_t;

static inline num_t ray_error_at(const ray_error_t *e, num_t t)
{
    return num_add(e->origin, num_mul(num_abs(t), e->dir));
}

/* prim_intersect, and *uncertain = 1 when a decision between tmin and tmax
 * was closer than the error of what it compares: the primitive's own
 * rounding (a triangle's edge test, a ray grazing an ellipsoid or passing
 * a box's edge: render_prim_t.edge_error) plus the ray's error at that t
 * (err): the answer may be wrong. */
int prim_intersect_uncertain(const render_prim_t *p, const ray_t *ray, const ray_error_t *err,
                             num_t tmin, num_t tmax, num_t *t_out, int *uncertain);
/* The same where only whether it hits matters (an opaque density sphere
 * on a shadow ray): *t_out is some t of (tmin, tmax], a density sphere's
 * not bisected when its crossing's bracket lies within them; the answer
 * and *uncertain are prim_intersect_uncertain's. */
int prim_intersect_uncertain_whether(const render_prim_t *p, const ray_t *ray,
                                     const ray_error_t *err, num_t tmin, num_t tmax, num_t *t_out,
                                     int *uncertain);

/* A box or an ellipsoid p the ray misses for certain on [tmin, tmax],
 * here and in double: its local coordinate on axis face / 2 stays beyond
 * that face of [-1, 1] (face & 1: the - one), which bounds both shapes,
 * by more than its error (edge_error[0] and err times scale, the largest
 * axis's, plus the rounding of the coordinate) at both ends.  Then
 * prim_intersect_uncertain finds no hit, and only doubts that cannot
 * change that.  Cheap: one row of the map, no division. */
int prim_face_clear(const render_prim_t *p, const ray_t *ray, const ray_error_t *err, num_t tmin,
                    num_t tmax, uint8_t face);

/* Fill hit->point, normal, tangent_hint, u, v for hit->t on primitive p. */
void prim_surface(const render_prim_t *p, const ray_t *ray, hit_t *hit);

/* The unit tangent at a hit prim_surface filled, perpendicular to its
 * normal, along increasing u: a triangle's first edge, every other
 * primitive's from its local hint (prim_tangent).  Worked out only where
 * a bump or normal map turns the normal. */
vec3_t prim_hit_tangent(const render_prim_t *p, const hit_t *hit);

/* The tangent a NORMAL map is read in at the hit (map_normal): a
 * triangle's from its texture coordinates, unit dP/du made perpendicular
 * to hit->normal, with *mirrored = 1 when the map's y must be -(n x T) to
 * point up the image (towards decreasing v); a triangle whose mapping is
 * degenerate, and every other primitive, prim_hit_tangent with *mirrored = 0.
 * *uncertain = 1 when the arithmetic's rounding could turn a triangle's
 * tangent by more than 1/64 radian or make the other choice (lost
 * precision). */
vec3_t prim_map_tangent(const render_prim_t *p, const hit_t *hit, int *mirrored, int *uncertain);

/* Ray-box test: 1 if the ray meets box b at some t in [tmin, tmax]. */
int prim_aabb_hit(const aabb_t *b, const ray_t *ray, num_t tmin, num_t tmax);
/* The same, with *entry the t where the ray enters the box (>= tmin). */
int prim_aabb_entry(const aabb_t *b, const ray_t *ray, num_t tmin, num_t tmax, num_t *entry);

/* A ray's reciprocal direction for many box tests: a product replaces
 * each slab's division.  In float and double its rounding, well below
 * RENDER_BOUNDS_PAD_VALUE at any coordinate in range, never makes a padded
 * box miss a surface it holds; in fixed point, whose reciprocal is coarse
 * far from the eye, each slab's t is widened by num_recip_mul_slack, so
 * that every box the divisions pass passes (prim_slab_inv_faces). */
typedef struct {
    num_t inv[3];
    uint8_t use_div[3]; /* 1: divide on this axis (d = 0, or its reciprocal beyond NUM_FAR) */
    uint8_t all_inv;    /* no axis divides */
} aabb_ray_t;

/* One axis of prim_aabb_ray: d the direction's component on it. */
static inline __attribute__((always_inline)) void prim_aabb_ray_axis(aabb_ray_t *r, int axis,
                                                                     num_t d)
{
    r->inv[axis] = NUM_ZERO;
    r->use_div[axis] = 1;
    if (!num_eq(d, NUM_ZERO)) {
        num_t inv = num_recip(d);
        if (num_lt(num_abs(inv), NUM_FAR)) {
            r->inv[axis] = inv;
            r->use_div[axis] = 0;
        }
    }
}

/* r for ray (inline: once a walk) */
static inline void prim_aabb_ray(const ray_t *ray, aabb_ray_t *r)
{
    prim_aabb_ray_axis(r, 0, ray->dir.x);
    prim_aabb_ray_axis(r, 1, ray->dir.y);
    prim_aabb_ray_axis(r, 2, ray->dir.z);
    r->all_inv = !r->use_div[0] && !r->use_div[1] && !r->use_div[2];
}

/* prim_aabb_entry with r from prim_aabb_ray(ray): inline where no axis
 * divides (float and double, a direction with no tiny component), else
 * prim_aabb_entry_ray_axes. */
int prim_aabb_entry_ray_axes(const aabb_t *b, const ray_t *ray, const aabb_ray_t *r, num_t tmin,
                             num_t tmax, num_t *entry);

/* 1 when prim_aabb_entry_ray(b, ray, r, tmin, tmax) surely returns 1 for
 * a ray from origin of unit direction: origin more than 2 tmin inside b on
 * every axis (tmin >= 0) and tmin <= tmax.  Then every slab's entry is at
 * most 0 and, a direction's component being at most 1 (its reciprocal at
 * least 1, give or take a step), its exit at least tmin, each rounding
 * monotonic.  Six comparisons for the three slabs' work. */
static inline int prim_aabb_around(const aabb_t *b, vec3_t origin, num_t tmin, num_t tmax)
{
    num_t m = num_mul_int(tmin, 2);
    return !num_lt(tmax, tmin) && num_gt(num_sub(origin.x, b->lo.x), m) &&
           num_gt(num_sub(b->hi.x, origin.x), m) && num_gt(num_sub(origin.y, b->lo.y), m) &&
           num_gt(num_sub(b->hi.y, origin.y), m) && num_gt(num_sub(origin.z, b->lo.z), m) &&
           num_gt(num_sub(b->hi.z, origin.z), m);
}

/* [*tnear, *tfar] narrowed by a slab the ray crosses at t1 and t2 (in
 * either order); 0 when nothing is left.  A saturated t compares as the
 * most extreme value: the right answer for a ray nearly parallel to the
 * slab. */
static inline int prim_slab_narrow(num_t t1, num_t t2, num_t *tnear, num_t *tfar)
{
    if (num_gt(t1, t2)) {
        num_t s = t1;
        t1 = t2;
        t2 = s;
    }
    *tnear = num_max(*tnear, t1);
    *tfar = num_min(*tfar, t2);
    return !num_gt(*tnear, *tfar);
}

/* One slab by the reciprocal (prim.c's prim_slab with a product for the
 * division), which the ray enters by face near_face and leaves by far_face:
 * lo and hi, swapped where the reciprocal is negative.  Rounding is
 * monotonic, so of a box that is not empty the first product is never the
 * larger (nor, widened, in fixed point): the t of both faces, in
 * prim_slab_narrow's order without its comparison. */
static inline int prim_slab_inv_faces(num_t o, num_t inv, num_t near_face, num_t far_face,
                                      num_t *tnear, num_t *tfar)
{
    num_t a = num_sub(near_face, o), b = num_sub(far_face, o);
    num_t t1 = num_mul(a, inv), t2 = num_mul(b, inv);
#if defined(LINKS1_NUM_FIXED)
    t1 = num_sub(t1, num_recip_mul_slack(a));
    t2 = num_add(t2, num_recip_mul_slack(b));
#endif
    *tnear = num_max(*tnear, t1);
    *tfar = num_min(*tfar, t2);
    return !num_gt(*tnear, *tfar);
}

/* prim_aabb_entry_ray where r->all_inv, the ray's origin o passed by
 * value (a walk keeps it and r in registers).  An empty box (lo > hi:
 * render/prepare.c's) is missed. */
static inline __attribute__((always_inline)) int prim_aabb_entry_inv(const aabb_t *b, vec3_t o,
                                                                      const aabb_ray_t *r,
                                                                      num_t tmin, num_t tmax,
                                                                      num_t *entry)
{
    num_t tnear = tmin, tfar = tmax;
    /* inv < 0: the ray enters the slab by its high face */
    int nx = num_lt(r->inv[0], NUM_ZERO), ny = num_lt(r->inv[1], NUM_ZERO),
        nz = num_lt(r->inv[2], NUM_ZERO);
    if (!prim_slab_inv_faces(o.x, r->inv[0], nx ? b->hi.x : b->lo.x, nx ? b->lo.x : b->hi.x,
                             &tnear, &tfar) ||
        !prim_slab_inv_faces(o.y, r->inv[1], ny ? b->hi.y : b->lo.y, ny ? b->lo.y : b->hi.y,
                             &tnear, &tfar) ||
        !prim_slab_inv_faces(o.z, r->inv[2], nz ? b->hi.z : b->lo.z, nz ? b->lo.z : b->hi.z,
                             &tnear, &tfar))
        return 0;
    *entry = tnear;
    return 1;
}

static inline int prim_aabb_entry_ray(const aabb_t *b, const ray_t *ray, const aabb_ray_t *r,
                                      num_t tmin, num_t tmax, num_t *entry)
{
    if (!r->all_inv)
        return prim_aabb_entry_ray_axes(b, ray, r, tmin, tmax, entry);
    return prim_aabb_entry_inv(b, ray->origin, r, tmin, tmax, entry);
}

/* Pseudo-angle of (x, z) in [0, 4): monotonic in the true angle, exact at
 * the axes, no trigonometry (an ellipsoid's and a cone's u). */
num_t prim_pseudo_angle(num_t x, num_t z);
/* A unit tangent at a hit of normal `normal` from a hint in the local
 * frame of to_local (an ellipsoid's, a box's, a cone's). */
vec3_t prim_tangent(const xform_t *to_local, vec3_t hint_local, vec3_t normal);
/* A ray against a density sphere, for its root finder (prim.c): where it
 * runs within a component's sphere, and what bounds the field's sum along
 * it from above.  The sum at the ray's point t is at most
 * prim_density_bound(t): each component of weight above 0 with the
 * distance of that point to its centre taken from the ray's closest
 * approach, sqrt(cc + (t len - tc)^2) (a negative weight adds at most 0).
 * The sampled excess and the bound differ by what rounding does to
 * either: the excess's own error, edge_error[0] (precision.c), a few times
 * over, and 2^-PRIM_DENSITY_BOUND_SHIFT of the threshold and weights
 * (margin); where the bound plus margin plus the error a sample is
 * judged by stays below the threshold, the sample is surely below
 * -(that error) and needs no computing.  Only for a primitive of at most
 * PRIM_DENSITY_BOUND_MAX components (bounded); the rest sample every step. */
#define PRIM_DENSITY_BOUND_MAX 16
#define PRIM_DENSITY_BOUND_ERRORS 4
#define PRIM_DENSITY_BOUND_SHIFT 10
typedef struct {
    num_t len;    /* |d| in local units: s = t len */
    num_t lo, hi; /* from the first sphere's entry (or tmin) to the last one's exit */
    num_t peak;   /* the bound's largest: each component at its closest approach */
    num_t margin; /* what the bound is widened by (above) */
    num_t after;  /* s at or past every listed closest approach (-NUM_FAR:
                     none listed): from there on every term of the bound
                     only falls as t grows */
    num_t slack;  /* what rounding may raise the bound by there all the
                     same: where a term's two formulas meet */
    int bounded;  /* the lists below hold every component that adds to the bound */
    /* The components of weight above 0 whose sphere the ray's line meets
     * (cc within its radius; each other one adds 0 at every t), in rising
     * index: count of them, each one's index, the squared local distance
     * of its closest approach and that approach's s. */
    uint16_t count;
    uint16_t index[PRIM_DENSITY_BOUND_MAX];
    num_t cc[PRIM_DENSITY_BOUND_MAX];
    num_t tc[PRIM_DENSITY_BOUND_MAX];
} prim_density_ray_t;
/* Fills *r; 0 when the ray meets no component's sphere beyond tmin. */
int prim_density_ray(const render_prim_t *p, const ray_t *ray, num_t tmin, prim_density_ray_t *r);
/* The bound of the field's sum at t (r from prim_density_ray, bounded). */
num_t prim_density_bound(const render_prim_t *p, const prim_density_ray_t *r, num_t t);
/* The excess (the field's sum minus the threshold) the root finder
 * computes at the ray's point t. */
num_t prim_density_sample_excess(const render_prim_t *p, const ray_t *ray, num_t t);

/* LINKS-1 density field of one component of weight b at squared distance
 * r2, given inv_radius2 = 1/d^2. */
num_t prim_density_field(num_t r2, num_t inv_radius2, num_t weight);

#endif
