/* render/prim.c: intersection and surface details of the four primitives.
 * The methods are described in docs/renderer.md. */
#include "render/prim.h"

#include "render/prim_cone.h"
#include "render/vec3.h"

#define PRIM_EDGE_TOL NUM_C(RENDER_EDGE_TOLERANCE_VALUE)

/* Pick the nearest of two roots t0 <= t1 above tmin; 0 if neither. */
static int prim_pick_root(num_t t0, num_t t1, num_t tmin, num_t tmax, num_t *t_out)
{
    num_t t;
    if (num_gt(t0, tmin))
        t = t0;
    else if (num_gt(t1, tmin))
        t = t1;
    else
        return 0;
    if (num_is_sat(t) || num_gt(t, tmax))
        return 0;
    *t_out = t;
    return 1;
}

/* ------------------------------------------------------------- triangle */

static int prim_triangle_bary(const render_prim_t *p, vec3_t point, num_t *beta, num_t *gamma)
{
    vec3_t w = vec3_sub(point, p->v0);
    *beta = num_div(vec3_dot(w, p->edge_n1), p->height1);
    *gamma = num_div(vec3_dot(w, p->edge_n2), p->height2);
    return !num_is_sat(*beta) && !num_is_sat(*gamma);
}

/* A barycentric margin m with rounding error e, on an edge at height h
 * from the opposite vertex, is closer than that error plus a ray off by
 * ray_err (a point moved by ray_err moves the barycentric by ray_err / h):
 * (m - e) * h < ray_err, without a division. */
static int prim_margin_uncertain(num_t m, num_t e, num_t h, num_t ray_err)
{
    num_t left = num_sub(num_abs(m), e);
    return num_lt(left, NUM_ZERO) || num_lt(num_mul(left, num_abs(h)), ray_err);
}

/* One of the three edge tests is decided by less than the rounding error
 * of the barycentrics (render_prim_t.edge_error) and of the ray at the hit
 * (ray_err, eye units): a sliver thinner than a pixel, or a ray passing an
 * edge within its own error, may be hit or missed wrongly.  The third
 * barycentric, 1 - beta - gamma, moves by at most ray_err (1/h1 + 1/h2). */
static int prim_triangle_edge_uncertain(const render_prim_t *p, num_t beta, num_t gamma,
                                        num_t ray_err)
{
    num_t e1 = p->edge_error[0], e2 = p->edge_error[1];
    num_t h1 = num_abs(p->height1), h2 = num_abs(p->height2);
    num_t alpha_margin = num_sub(num_add(NUM_ONE, PRIM_EDGE_TOL), num_add(beta, gamma));
    if (prim_margin_uncertain(num_add(beta, PRIM_EDGE_TOL), e1, h1, ray_err) ||
        prim_margin_uncertain(num_add(gamma, PRIM_EDGE_TOL), e2, h2, ray_err))
        return 1;
    num_t left = num_sub(num_abs(alpha_margin), num_add(e1, e2));
    return num_lt(left, NUM_ZERO) ||
           num_lt(num_mul(num_mul(left, h1), h2), num_mul(ray_err, num_add(h1, h2)));
}

static int prim_triangle_intersect(const render_prim_t *p, const ray_t *ray,
                                   const ray_error_t *err, num_t tmin, num_t tmax, num_t *t_out,
                                   int *uncertain)
{
    num_t denom = vec3_dot(ray->dir, p->normal);
    if (num_eq(denom, NUM_ZERO)) /* ray in the triangle's plane: grazing */
        return 0;
    num_t t = num_div(vec3_dot(vec3_sub(p->v0, ray->origin), p->normal), denom);
    if (num_is_sat(t) || !num_gt(t, tmin) || num_gt(t, tmax))
        return 0;
    num_t beta, gamma;
    if (!prim_triangle_bary(p, vec3_madd(ray->origin, ray->dir, t), &beta, &gamma))
        return 0;
    if (uncertain)
        *uncertain = prim_triangle_edge_uncertain(p, beta, gamma, ray_error_at(err, t));
    if (num_lt(beta, num_neg(PRIM_EDGE_TOL)) || num_lt(gamma, num_neg(PRIM_EDGE_TOL)) ||
        num_gt(num_add(beta, gamma), num_add(NUM_ONE, PRIM_EDGE_TOL)))
        return 0;
    *t_out = t;
    return 1;
}

static void prim_triangle_surface(const render_prim_t *p, hit_t *hit)
{
    num_t beta, gamma;
    prim_triangle_bary(p, hit->point, &beta, &gamma);
    num_t alpha = num_sub(NUM_ONE, num_add(beta, gamma));
    hit->normal = p->normal;
    if (p->smooth) {
        /* smooth (beyond the paper): the vertex normals interpolated, on
         * the side of the plane's normal, which the tracer turns to the ray */
        const vec3_t *n = p->normals.n;
        vec3_t s = vec3_add(vec3_add(vec3_scale(n[0], alpha), vec3_scale(n[1], beta)),
                            vec3_scale(n[2], gamma));
        s = vec3_normalize(s);
        if (!vec3_is_sat(s) && num_gt(vec3_length(s), NUM_C(0.5f)))
            hit->normal = num_lt(vec3_dot(s, p->normal), NUM_ZERO) ? vec3_neg(s) : s;
    }
    hit->u = num_add(num_add(num_mul(alpha, p->tex_u[0]), num_mul(beta, p->tex_u[1])),
                     num_mul(gamma, p->tex_u[2]));
    hit->v = num_add(num_add(num_mul(alpha, p->tex_v[0]), num_mul(beta, p->tex_v[1])),
                     num_mul(gamma, p->tex_v[2]));
}

/* A normal map's frame on a triangle from its texture coordinates: the
 * edges' combination that is dP/du (times the mapping's determinant det,
 * whose sign is taken off), less its part along the hit's normal
 * (Gram-Schmidt: a smooth triangle's normal leaves the plane).  det's
 * error is the coordinates' rounding (two steps of the largest, times the
 * largest difference, in each product) and the products' own; a det no
 * larger falls back to the first edge (prim_surface's tangent), and one
 * within PRIM_TANGENT_MARGIN of it turns the tangent by more than
 * 1/PRIM_TANGENT_MARGIN radians: uncertain.  A mapping that is degenerate
 * exactly (u or v the same at all three vertices) is no uncertainty. */
#define PRIM_TANGENT_MARGIN 64
static vec3_t prim_triangle_map_tangent(const render_prim_t *p, const hit_t *hit, int *mirrored,
                                        int *uncertain)
{
    num_t du1 = num_sub(p->tex_u[1], p->tex_u[0]), du2 = num_sub(p->tex_u[2], p->tex_u[0]);
    num_t dv1 = num_sub(p->tex_v[1], p->tex_v[0]), dv2 = num_sub(p->tex_v[2], p->tex_v[0]);
    num_t a = num_mul(du1, dv2), b = num_mul(du2, dv1);
    num_t det = num_sub(a, b);
    num_t reach = NUM_ZERO, span = num_max(num_max(num_abs(du1), num_abs(du2)),
                                           num_max(num_abs(dv1), num_abs(dv2)));
    for (int k = 0; k < 3; k++)
        reach = num_max(reach, num_max(num_abs(p->tex_u[k]), num_abs(p->tex_v[k])));
    num_t err = num_add(num_mul_int(num_mul(num_ulp(reach), span), 4),
                        num_mul_int(num_ulp(num_add(num_abs(a), num_abs(b))), 2));
    int exact = num_eq(du1, NUM_ZERO) && num_eq(du2, NUM_ZERO);
    exact = exact || (num_eq(dv1, NUM_ZERO) && num_eq(dv2, NUM_ZERO));
    *mirrored = 0;
    *uncertain = !exact && (num_is_sat(det) || num_is_sat(err) ||
                            num_lt(num_abs(det), num_mul_int(err, PRIM_TANGENT_MARGIN)));
    if (num_is_sat(det) || !num_gt(num_abs(det), err))
        return prim_hit_tangent(p, hit);
    vec3_t t = vec3_sub(vec3_scale(p->e1, dv2), vec3_scale(p->e2, dv1));
    if (num_lt(det, NUM_ZERO))
        t = vec3_neg(t);
    t = vec3_normalize(vec3_sub(t, vec3_scale(hit->normal, vec3_dot(t, hit->normal))));
    if (vec3_is_sat(t) || !num_gt(vec3_length(t), NUM_HALF)) {
        *uncertain = !exact;
        return prim_hit_tangent(p, hit);
    }
    /* B, the map's y, towards decreasing v (up the image): n x T, unless
     * u and v turn the other way round the normal (det > 0: dP/dv is n x T) */
    *mirrored = num_gt(det, NUM_ZERO);
    return t;
}

vec3_t prim_map_tangent(const render_prim_t *p, const hit_t *hit, int *mirrored, int *uncertain)
{
    if (p->kind == SCENE_PRIM_TRIANGLE)
        return prim_triangle_map_tangent(p, hit, mirrored, uncertain);
    *mirrored = *uncertain = 0;
    return prim_hit_tangent(p, hit);
}

/* ------------------------------------------------------------ ellipsoid */

/* The ray in the unit sphere's space, written o' + s*dn with dn a unit
 * vector and s = t * len.  The closest approach to the centre is found
 * first, so no squared coordinate of a far origin is ever formed. */
/* The ray's closest point c to the unit sphere's centre (at t = tc / len)
 * is within the error of the surface: a ray grazing the ellipsoid may be
 * counted as a hit or a miss wrongly.  c is off by the local coordinates'
 * error (render_prim_t.edge_error), a few steps at tc and the ray's own
 * error at t in local units (times render_prim_t.scale); 1 - |c|^2 by
 * twice that.  A closest point beyond 2 is no graze: an error of a whole
 * radius makes the primitive imprecise (precision.c). */
static int prim_ellipsoid_graze_uncertain(const render_prim_t *p, vec3_t c, vec3_t dn, num_t tc,
                                          num_t len, const ray_error_t *ray_err, num_t tmin,
                                          num_t tmax)
{
    num_t e0 = num_add(p->edge_error[0], num_mul_int(num_ulp(num_abs(tc)), 4));
#if defined(LINKS1_NUM_FIXED)
    /* Fixed point: c = o + dn tc, and each component of dn is off by a
     * step, 2^-F however small it is, which the large local tc of a thin
     * ellipsoid multiplies.  And dn = d * (1/len): the reciprocal of a
     * long local direction (a thin axis scaled up) keeps few significant
     * bits, so dn's length is off by up to a step times len (2% at len 300
     * in Q17.14); with |dn| = 1 + eps, c moves by about 2 eps |tc| along
     * the ray (ellipsoid_ratio 3000 in Q17.14: a shadow ray's closest point
     * 80 radii off, unflagged).  |1 - dn.dn| is that 2 eps, give or take
     * the dot's own steps: e0 grows by (|1 - dn.dn| + 8 steps) |tc|.  The
     * ray's error in local units (times scale) can pass a whole radius
     * there, so the quick exit below 2 radii would miss a ray whose true
     * closest point is inside (ellipsoid_ratio 1000 in Q17.14: pixels
     * missed, unflagged).  The quick exit allows for both, kept free of a
     * division: |c| len against (2 + e0) len + (origin len + |tc| dir)
     * scale. */
    num_t dir_err = num_add(num_abs(num_sub(NUM_ONE, vec3_dot(dn, dn))),
                            num_mul_int(num_ulp(NUM_ONE), 8));
    e0 = num_add(e0, num_mul(dir_err, num_abs(tc)));
    num_t ray_len = num_add(num_mul(ray_err->origin, len), num_mul(num_abs(tc), ray_err->dir));
    num_t far = num_add(num_mul(num_add(NUM_C(2), e0), len), num_mul(ray_len, p->scale));
    if (num_gt(num_mul(num_abs(c.x), len), far) || num_gt(num_mul(num_abs(c.y), len), far) ||
        num_gt(num_mul(num_abs(c.z), len), far))
        return 0;
#else
    (void)dn;
    num_t two = NUM_C(2);
    if (num_gt(num_abs(c.x), two) || num_gt(num_abs(c.y), two) || num_gt(num_abs(c.z), two))
        return 0;
#endif
    num_t t = num_div(tc, len);
    if (num_is_sat(t) || !num_gt(t, tmin) || num_gt(t, tmax))
        return 0;
    num_t err = num_add(e0, num_mul(ray_error_at(ray_err, t), p->scale));
    num_t lim = num_add(NUM_ONE, err);
    if (num_gt(num_abs(c.x), lim) || num_gt(num_abs(c.y), lim) || num_gt(num_abs(c.z), lim))
        return 0;
    /* the true |c| within err of 1: (1 - err)^2 < c.c < (1 + err)^2, no
     * lower bound once err reaches 1 (|1 - c.c| < 2 err only while err is
     * small: a closest point 10 radii off by 12 passed it) */
    num_t cc = vec3_dot(c, c);
    if (!num_lt(cc, num_mul(lim, lim)))
        return 0;
    num_t below = num_sub(NUM_ONE, err);
    return !num_gt(below, NUM_ZERO) || num_gt(cc, num_mul(below, below));
}

static int prim_ellipsoid_intersect(const render_prim_t *p, const ray_t *ray,
                                    const ray_error_t *err, num_t tmin, num_t tmax, num_t *t_out,
                                    int *uncertain)
{
    vec3_t o = xform_point_inline(&p->to_local, ray->origin);
    vec3_t d = xform_dir_inline(&p->to_local, ray->dir);
    num_t len = vec3_length(d);
    if (vec3_is_sat(o) || num_is_sat(len) || !num_gt(len, NUM_ZERO))
        return 0;
    vec3_t dn = vec3_scale(d, num_recip(len));
    num_t tc = num_neg(vec3_dot(o, dn));
    vec3_t c = vec3_madd(o, dn, tc); /* closest point to the centre */
    if (uncertain)
        *uncertain = prim_ellipsoid_graze_uncertain(p, c, dn, tc, len, err, tmin, tmax);
    if (num_gt(num_abs(c.x), NUM_ONE) || num_gt(num_abs(c.y), NUM_ONE) ||
        num_gt(num_abs(c.z), NUM_ONE))
        return 0;
    num_t h2 = num_sub(NUM_ONE, vec3_dot(c, c));
    if (num_lt(h2, NUM_ZERO))
        return 0;
    num_t h = num_sqrt(h2);
    num_t t0 = num_div(num_sub(tc, h), len);
    num_t t1 = num_div(num_add(tc, h), len);
    return prim_pick_root(t0, t1, tmin, tmax, t_out);
}

/* Pseudo-angle of (x, z) in [0, 4): monotonic in the true angle, exact at
 * the axes, and needs no trigonometry (the board has no atan2). */
num_t prim_pseudo_angle(num_t x, num_t z)
{
    num_t ax = num_abs(x), az = num_abs(z);
    num_t sum = num_add(ax, az);
    if (!num_gt(sum, NUM_ZERO))
        return NUM_ZERO;
    num_t f = num_div(az, sum); /* 0 on the x axis, 1 on the z axis */
    if (num_ge(x, NUM_ZERO))
        return num_ge(z, NUM_ZERO) ? f : num_sub(NUM_C(4), f);
    return num_ge(z, NUM_ZERO) ? num_sub(NUM_C(2), f) : num_add(NUM_C(2), f);
}

/* Tangent from a local-space hint: mapped to eye space by the transposed
 * inverse (exact for rotations and uniform scales, a fair direction
 * otherwise), then made perpendicular to the normal. */
vec3_t prim_tangent(const xform_t *to_local, vec3_t hint_local, vec3_t normal)
{
    vec3_t h = xform_dir_transposed(to_local, hint_local);
    h = vec3_sub(h, vec3_scale(normal, vec3_dot(normal, h)));
    vec3_t t = vec3_normalize(h);
    if (!num_gt(vec3_length(t), NUM_HALF)) { /* hint along the normal */
        vec3_t any = num_gt(num_abs(normal.x), NUM_HALF) ? vec3_make(NUM_ZERO, NUM_ONE, NUM_ZERO)
                                                        : vec3_make(NUM_ONE, NUM_ZERO, NUM_ZERO);
        t = vec3_normalize(vec3_cross(any, normal));
    }
    return t;
}

/* The normal is M^T q / |M^T q| for the local point q = M p: a hit moved
 * by e moves q by up to scale e and M^T q by up to scale^2 e, so the
 * normal turns by up to scale^2 e / |M^T q| (a / c^2 at the end of the
 * longest axis of radii a >= c, 1 / c across the flattest side). */
static void prim_ellipsoid_surface(const render_prim_t *p, hit_t *hit)
{
    vec3_t q = xform_point(&p->to_local, hit->point);
    vec3_t g = xform_dir_transposed(&p->to_local, q);
    num_t len = vec3_length(g);
    hit->normal = num_gt(len, NUM_ZERO) ? vec3_make(num_div(g.x, len), num_div(g.y, len),
                                                    num_div(g.z, len)) : g;
    hit->curvature = num_gt(len, NUM_ZERO) ? num_div(num_mul(p->scale, p->scale), len) : NUM_FAR;
    if (num_is_sat(hit->curvature))
        hit->curvature = NUM_FAR;
    hit->tangent_hint = vec3_make(num_neg(q.z), NUM_ZERO, q.x);
    hit->u = num_mul(prim_pseudo_angle(q.x, q.z), NUM_C(0.25));
    hit->v = num_clamp01(num_mul(num_add(q.y, NUM_ONE), NUM_HALF));
}

/* ------------------------------------------------------------------ box */

/* Slab test along one axis, [lo, hi]; narrows [*tnear, *tfar].  An
 * origin already past the face the ray enters by (o >= lo going up, o <=
 * hi going down) enters at a t of 0 or less: with *tnear at 0 or more
 * that face leaves *tnear as it is, and its division is not done. */
static int prim_slab(num_t o, num_t d, num_t lo, num_t hi, num_t *tnear, num_t *tfar)
{
    if (num_eq(d, NUM_ZERO))
        return !num_lt(o, lo) && !num_gt(o, hi);
    int up = num_gt(d, NUM_ZERO);
    num_t enter = num_sub(up ? lo : hi, o);
    if (num_ge(*tnear, NUM_ZERO) && (up ? !num_gt(enter, NUM_ZERO) : !num_lt(enter, NUM_ZERO))) {
        *tfar = num_min(*tfar, num_div(num_sub(up ? hi : lo, o), d));
        return !num_gt(*tnear, *tfar);
    }
    return prim_slab_narrow(num_div(num_sub(lo, o), d), num_div(num_sub(hi, o), d), tnear, tfar);
}

/* The interval of t where the ray is inside [-1,1]^3 in local space; t is
 * the same in both spaces because the map is affine and d is not
 * renormalised.  The slabs of every axis, kept apart so that the margin of
 * the decision can be judged: near_axis and far_axis are the axes whose
 * faces give tnear and tfar (-1: none), parallel the smallest distance of
 * the origin to a face of an axis the ray runs parallel to. */
typedef struct {
    num_t tnear, tfar;
    int near_axis, far_axis;
    num_t parallel;
    int outside;     /* the ray runs parallel to a slab, outside it */
    num_t outside_by; /* by this much (the most of such slabs; 0: none) */
} prim_box_span_t;

/* One slab of prim_box_span: axis, with the ray's local oa and da on it. */
static inline __attribute__((always_inline)) void prim_box_slab(prim_box_span_t *s, int axis,
                                                                num_t oa, num_t da)
{
    if (num_eq(da, NUM_ZERO)) {
        s->outside |= num_lt(oa, num_neg(NUM_ONE)) || num_gt(oa, NUM_ONE);
        s->outside_by = num_max(s->outside_by, num_max(num_sub(num_neg(NUM_ONE), oa),
                                                       num_sub(oa, NUM_ONE)));
        s->parallel = num_min(s->parallel, num_min(num_abs(num_add(oa, NUM_ONE)),
                                                   num_abs(num_sub(NUM_ONE, oa))));
        return;
    }
    num_t t1 = num_div(num_sub(num_neg(NUM_ONE), oa), da);
    num_t t2 = num_div(num_sub(NUM_ONE, oa), da);
    if (num_gt(t1, t2)) {
        num_t t = t1;
        t1 = t2;
        t2 = t;
    }
    if (num_gt(t1, s->tnear)) {
        s->tnear = t1;
        s->near_axis = axis;
    }
    if (num_lt(t2, s->tfar)) {
        s->tfar = t2;
        s->far_axis = axis;
    }
}

/* All three slabs (the decision of prim_slab's loop, which may stop at the
 * first axis that misses, is the same: tnear only grows, tfar only shrinks),
 * written out axis by axis. */
static inline __attribute__((always_inline)) void prim_box_span(vec3_t o, vec3_t d,
                                                                prim_box_span_t *s)
{
    s->tnear = num_neg(NUM_FAR);
    s->tfar = NUM_FAR;
    s->near_axis = s->far_axis = -1;
    s->parallel = NUM_FAR;
    s->outside = 0;
    s->outside_by = NUM_ZERO;
    prim_box_slab(s, 0, o.x, d.x);
    prim_box_slab(s, 1, o.y, d.y);
    prim_box_slab(s, 2, o.z, d.z);
}

/* The error of local coordinate `axis` of the ray's point where the ray's
 * own error is e (eye units): the box's rounding on that axis and e in
 * its local units. */
static inline num_t prim_box_axis_delta(const render_prim_t *p, int axis, num_t e)
{
    return num_add(p->box_edge_error[axis], num_mul(e, p->box_row_len[axis]));
}

/* The box is hit or missed by less than the error of the ray's local
 * position at t: the entry and exit t move by delta_n / |dn| and
 * delta_f / |df|, the errors of the local coordinates of the axes that
 * give them (prim_box_axis_delta) over the direction on those axes, so
 * |tfar - tnear| |dn| |df| < delta_n |df| + delta_f |dn|, without a
 * division (fixed point: the largest axis's delta for both); a slab the
 * ray runs parallel to, by its distance to a face (outside one by more
 * than the largest axis's delta, it misses for certain, however near the
 * other slabs' t lie).  Only a decision about the part of the ray after
 * tmin and before tmax. */
static int prim_box_edge_uncertain(const render_prim_t *p, const prim_box_span_t *s, vec3_t d,
                                   const ray_error_t *err, num_t tmin, num_t tmax)
{
    if (s->near_axis < 0 || s->far_axis < 0)
        return 0;
    num_t lo = num_min(s->tnear, s->tfar), hi = num_max(s->tnear, s->tfar);
    if (!num_gt(hi, tmin) || num_gt(lo, tmax))
        return 0;
    num_t mid = num_mul(num_add(lo, hi), NUM_HALF);
    num_t e = ray_error_at(err, mid);
    num_t delta = num_add(p->edge_error[0], num_mul(e, p->scale));
    if (num_gt(s->outside_by, delta))
        return 0;
    if (num_lt(s->parallel, delta))
        return 1;
    num_t dn = num_abs(vec3_get(d, s->near_axis)), df = num_abs(vec3_get(d, s->far_axis));
    num_t gap = num_abs(num_sub(s->tfar, s->tnear));
#if defined(LINKS1_NUM_FIXED)
    /* the largest axis's delta for both: the flags the axes' own would
     * save cost fixed point more to trace on than to escalate */
    return num_lt(num_mul(num_mul(gap, dn), df), num_mul(delta, num_add(dn, df)));
#else
    num_t delta_n = prim_box_axis_delta(p, s->near_axis, e);
    num_t delta_f = prim_box_axis_delta(p, s->far_axis, e);
    return num_lt(num_mul(num_mul(gap, dn), df),
                  num_add(num_mul(delta_n, df), num_mul(delta_f, dn)));
#endif
}

static int prim_box_intersect(const render_prim_t *p, const ray_t *ray, const ray_error_t *err,
                              num_t tmin, num_t tmax, num_t *t_out, int *uncertain)
{
    vec3_t o = xform_point_inline(&p->to_local, ray->origin);
    vec3_t d = xform_dir_inline(&p->to_local, ray->dir);
    if (vec3_is_sat(o) || vec3_is_sat(d))
        return 0;
    if (!uncertain) { /* first miss ends it */
        num_t tnear = num_neg(NUM_FAR), tfar = NUM_FAR, one = NUM_ONE;
        if (!prim_slab(o.x, d.x, num_neg(one), one, &tnear, &tfar) ||
            !prim_slab(o.y, d.y, num_neg(one), one, &tnear, &tfar) ||
            !prim_slab(o.z, d.z, num_neg(one), one, &tnear, &tfar))
            return 0;
        return prim_pick_root(tnear, tfar, tmin, tmax, t_out);
    }
    prim_box_span_t s;
    prim_box_span(o, d, &s);
    *uncertain = prim_box_edge_uncertain(p, &s, d, err, tmin, tmax);
    if (s.outside || num_gt(s.tnear, s.tfar))
        return 0;
    return prim_pick_root(s.tnear, s.tfar, tmin, tmax, t_out);
}

static void prim_box_surface(const render_prim_t *p, hit_t *hit)
{
    vec3_t q = xform_point(&p->to_local, hit->point);
    int axis = 0;
    if (num_gt(num_abs(q.y), num_abs(vec3_get(q, axis))))
        axis = 1;
    if (num_gt(num_abs(q.z), num_abs(vec3_get(q, axis))))
        axis = 2;
    vec3_t n_local = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    vec3_set(&n_local, axis, num_lt(vec3_get(q, axis), NUM_ZERO) ? num_neg(NUM_ONE) : NUM_ONE);
    hit->normal = vec3_normalize(xform_dir_transposed(&p->to_local, n_local));
    /* face coordinates: the next two axes in cyclic order */
    int ua = (axis + 1) % 3, va = (axis + 2) % 3;
    vec3_t hint = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    vec3_set(&hint, ua, NUM_ONE);
    hit->tangent_hint = hint;
    hit->u = num_clamp01(num_mul(num_add(vec3_get(q, ua), NUM_ONE), NUM_HALF));
    hit->v = num_clamp01(num_mul(num_add(vec3_get(q, va), NUM_ONE), NUM_HALF));
    hit->uv_error = num_mul(num_max(p->box_edge_error[ua], p->box_edge_error[va]), NUM_HALF);
}

/* -------------------------------------------------------- density sphere */

num_t prim_density_field(num_t r2, num_t inv_radius2, num_t weight)
{
    num_t q = num_mul(r2, inv_radius2); /* (r/d)^2; a saturated r2 stays huge */
    if (!num_lt(q, NUM_ONE))
        return NUM_ZERO;
    if (!num_gt(num_mul_int(q, 9), NUM_ONE)) /* r <= d/3 */
        return num_mul(weight, num_sub(NUM_ONE, num_mul_int(q, 3)));
    num_t x = num_sub(NUM_ONE, num_sqrt(q)); /* 1 - r/d */
    return num_mul(num_mul(weight, NUM_C(1.5)), num_mul(x, x));
}

/* Sum of fields minus the threshold at local point q: > 0 inside. */
static num_t prim_density_excess(const render_prim_t *p, vec3_t q)
{
    num_t sum = num_neg(p->threshold);
    for (uint16_t k = 0; k < p->component_count; k++) {
        const scene_density_component_t *c = &p->components[k];
        vec3_t r = vec3_sub(q, c->centre);
        sum = num_add(sum, prim_density_field(vec3_dot(r, r), p->inv_radius2[k], c->weight));
    }
    return sum;
}

/* The excess at the ray's point t. */
static inline __attribute__((always_inline)) num_t prim_density_excess_at(const render_prim_t *p,
                                                                     const ray_t *ray, num_t t)
{
    return prim_density_excess(p, xform_point_inline(&p->to_local,
                                                     vec3_madd(ray->origin, ray->dir, t)));
}

num_t prim_density_sample_excess(const render_prim_t *p, const ray_t *ray, num_t t)
{
    return prim_density_excess_at(p, ray, t);
}

/* How far the excess sampled at t may be from the double build's: the
 * primitive's own (edge_error[0], precision.c) and its largest gradient
 * (edge_error[1]) times the ray's error at t in local units. */
static num_t prim_density_excess_error(const render_prim_t *p, const ray_error_t *err, num_t t)
{
    return num_add(p->edge_error[0],
                   num_mul(p->edge_error[1], num_mul(ray_error_at(err, t), p->scale)));
}

/* Sample i of steps from lo to hi, the last at hi itself. */
static inline num_t prim_density_sample_t(num_t lo, num_t hi, num_t step, int steps, int i)
{
    return i == steps ? hi : num_add(lo, num_mul_int(step, i));
}

int prim_density_ray(const render_prim_t *p, const ray_t *ray, num_t tmin, prim_density_ray_t *r)
{
    vec3_t o = xform_point_inline(&p->to_local, ray->origin);
    vec3_t d = xform_dir_inline(&p->to_local, ray->dir);
    num_t len = vec3_length(d);
    if (vec3_is_sat(o) || num_is_sat(len) || !num_gt(len, NUM_ZERO))
        return 0;
    vec3_t dn = vec3_scale(d, num_recip(len));
    int any = 0;
    num_t lo = NUM_ZERO, hi = NUM_ZERO, peak = NUM_ZERO, weights = num_abs(p->threshold);
    r->len = len;
    r->bounded = p->component_count <= PRIM_DENSITY_BOUND_MAX;
    r->count = 0;
    r->after = num_neg(NUM_FAR);
    for (uint16_t k = 0; k < p->component_count; k++) {
        const scene_density_component_t *c = &p->components[k];
        vec3_t oc = vec3_sub(o, c->centre);
        num_t tc = num_neg(vec3_dot(oc, dn));
        vec3_t close = vec3_madd(oc, dn, tc);
        /* a negative field adds nothing to the bound; nor one whose sphere
         * the line misses: at every t its r2 = cc + u^2 is no smaller, so
         * prim_density_bound would find r2 / d^2 at least 1 too */
        if (r->bounded && num_gt(c->weight, NUM_ZERO)) {
            num_t cc = vec3_dot(close, close);
            peak = num_add(peak, prim_density_field(cc, p->inv_radius2[k], c->weight));
            weights = num_add(weights, c->weight);
            if (num_lt(num_mul(cc, p->inv_radius2[k]), NUM_ONE)) {
                r->index[r->count] = k;
                r->cc[r->count] = cc;
                r->tc[r->count++] = tc;
                r->after = num_max(r->after, tc);
            }
        }
        num_t rad = c->radius;
        if (num_gt(num_abs(close.x), rad) || num_gt(num_abs(close.y), rad) ||
            num_gt(num_abs(close.z), rad))
            continue;
        num_t h2 = num_sub(num_mul(rad, rad), vec3_dot(close, close));
        if (num_lt(h2, NUM_ZERO))
            continue;
        num_t h = num_sqrt(h2);
        num_t t0 = num_div(num_sub(tc, h), len), t1 = num_div(num_add(tc, h), len);
        if (num_is_sat(t0) || num_is_sat(t1) || !num_gt(t1, tmin))
            continue;
        lo = any ? num_min(lo, t0) : t0;
        hi = any ? num_max(hi, t1) : t1;
        any = 1;
    }
    /* a few steps of each term, and of the sum, at most: 32 apiece */
    r->slack = num_mul_int(num_ulp(weights), 32 * (r->count + 1));
    r->lo = num_max(lo, tmin);
    r->hi = hi;
    r->peak = peak;
    r->margin = num_add(num_mul_int(p->edge_error[0], PRIM_DENSITY_BOUND_ERRORS),
                        num_scale2(weights, -PRIM_DENSITY_BOUND_SHIFT));
    return any;
}

num_t prim_density_bound(const render_prim_t *p, const prim_density_ray_t *r, num_t t)
{
    num_t at = num_mul(t, r->len), sum = NUM_ZERO;
    for (uint16_t j = 0; j < r->count; j++) {
        uint16_t k = r->index[j];
        num_t u = num_sub(at, r->tc[j]);
        num_t r2 = num_add(r->cc[j], num_mul(u, u));
        if (num_lt(num_mul(r2, p->inv_radius2[k]), NUM_ONE))
            sum = num_add(sum, prim_density_field(r2, p->inv_radius2[k], p->components[k].weight));
    }
    return sum;
}

/* The sample at t into *f: the excess, or -NUM_FAR where
 * prim_density_bound (plus cut: the error a sample is judged near 0 by,
 * and the bound's margin) says it is surely below -(that error), as the
 * answer the root finder draws from the sample (below 0, and not near it)
 * is the same.  1 when, besides, it and every sample after it are surely
 * below 0: past every listed closest approach (t len at or beyond
 * r->after) no term of the bound grows with t but by rounding
 * (r->slack). */
static inline __attribute__((always_inline)) int prim_density_sample_or_end(
    const render_prim_t *p, const ray_t *ray, const prim_density_ray_t *r, num_t cut, num_t t,
    num_t *f)
{
    if (r->bounded) {
        num_t b = num_add(prim_density_bound(p, r, t), cut);
        if (num_lt(b, p->threshold)) {
            *f = num_neg(NUM_FAR);
            return !num_lt(num_mul(t, r->len), r->after) &&
                   num_lt(num_add(b, r->slack), p->threshold);
        }
    }
    *f = prim_density_excess_at(p, ray, t);
    return 0;
}

/* The sample at t alone (prim_density_sample_or_end). */
static inline __attribute__((always_inline)) num_t prim_density_sample(
    const render_prim_t *p, const ray_t *ray, const prim_density_ray_t *r, num_t cut, num_t t)
{
    num_t f;
    (void)prim_density_sample_or_end(p, ray, r, cut, t, &f);
    return f;
}

/* The root bracketed by a (on the side of inside) and b, by bisection:
 * RENDER_DENSITY_BISECTIONS halvings, or fewer once the midpoint is a or
 * b (then the rest would change nothing: the excess there is the one
 * already seen, on its side). */
static num_t prim_density_bisect(const render_prim_t *p, const ray_t *ray, num_t a, num_t b,
                                 int inside)
{
    for (int j = 0; j < RENDER_DENSITY_BISECTIONS; j++) {
        num_t m = num_mul(num_add(a, b), NUM_HALF);
        if (num_eq(m, a) || num_eq(m, b))
            break;
        num_t fm = prim_density_excess_at(p, ray, m);
        if (num_gt(fm, NUM_ZERO) == inside)
            a = m;
        else
            b = m;
    }
    return num_mul(num_add(a, b), NUM_HALF);
}

/* Root finder (docs/renderer.md): the field is zero outside every
 * component sphere, so the surface lies in [lo, hi], the union of the
 * spheres' t-intervals beyond tmin.  That span is sampled at
 * density_steps equal steps (the scene's option); the first sign change
 * of the excess is bisected RENDER_DENSITY_BISECTIONS times.  Fixed
 * counts: the same steps in every build, and a result independent of
 * tmax.  A sample the bound puts surely below 0 is not computed
 * (prim_density_sample), nor any when the bound's peak is; need_t 0: the
 * crossing is not bisected when the answer is a hit wherever its root. */
static int prim_density_intersect(const render_prim_t *p, const ray_t *ray,
                                  const ray_error_t *err, num_t tmin, num_t tmax, num_t *t_out,
                                  int *uncertain, int need_t)
{
    prim_density_ray_t r;
    if (!prim_density_ray(p, ray, tmin, &r))
        return 0;
    num_t lo = r.lo, hi = r.hi;
    int steps = p->density_steps;
    num_t step = num_div(num_sub(hi, lo), num_from_int(steps));
    num_t prev_t = lo;
    /* uncertain (wanted): a sample within its error of 0 (its sign may be
     * the double build's other one) where that could change the answer:
     * before the one before the crossing (an earlier crossing, or none),
     * or at the crossing with the one before it or the one after it near
     * 0 too (a crossing that may not be); with no crossing, anywhere.  A
     * sample near 0 next to a crossing only moves the bracket, not the
     * root. */
    int near_prev = 0, near_earlier = 0;
    /* A secondary ray starts on a surface, as far off as its origin's
     * error: samples within twice that of its start are near 0 whatever
     * the arithmetic, and what they decide (a hit on the surface it left)
     * is tmin's to settle, as for every primitive. */
    num_t settled = NUM_ZERO, most = NUM_ZERO; /* the error at hi, the largest */
    if (uncertain) {
        settled = num_add(tmin, num_mul_int(err->origin, 2));
        most = prim_density_excess_error(p, err, hi);
    }
    num_t cut = num_add(most, r.margin);
    if (r.bounded && num_lt(num_add(r.peak, cut), p->threshold))
        return 0; /* every sample below -most: no crossing, none near 0 */
    num_t f0 = prim_density_sample(p, ray, &r, cut, lo);
    int inside = num_gt(f0, NUM_ZERO); /* a ray from inside looks for the exit */
    if (uncertain)
        near_prev = num_gt(lo, settled) && !num_gt(num_abs(f0), most) &&
                    !num_gt(num_abs(f0), prim_density_excess_error(p, err, lo));
    for (int i = 1; i <= steps; i++) {
        num_t t = prim_density_sample_t(lo, hi, step, steps, i), f;
        if (prim_density_sample_or_end(p, ray, &r, cut, t, &f) && !inside) {
            near_earlier |= near_prev; /* the samples left: none near 0, no crossing */
            near_prev = 0;
            break;
        }
        /* the error at t only for a sample under the largest */
        int near = uncertain && !num_gt(num_abs(f), most) && num_gt(t, settled) &&
                   !num_gt(num_abs(f), prim_density_excess_error(p, err, t));
        if (num_gt(f, NUM_ZERO) != inside) {
            if (uncertain && (near_earlier || (near && near_prev))) {
                *uncertain = 1;
            } else if (near && i == steps) {
                *uncertain = 1;
            } else if (near) { /* the sample after it: still across, and surely */
                num_t tn = prim_density_sample_t(lo, hi, step, steps, i + 1);
                num_t fn = prim_density_sample(p, ray, &r, cut, tn);
                *uncertain = num_gt(fn, NUM_ZERO) == inside ||
                             !num_gt(num_abs(fn), prim_density_excess_error(p, err, tn));
            }
            if (!need_t && num_gt(prev_t, tmin) && !num_gt(t, tmax)) {
                *t_out = t; /* the root lies in (prev_t, t]: a hit, wherever */
                return 1;
            }
            num_t root = prim_density_bisect(p, ray, prev_t, t, inside);
            if (!num_gt(root, tmin) || num_gt(root, tmax) || num_is_sat(root))
                return 0;
            *t_out = root;
            return 1;
        }
        near_earlier |= near_prev;
        near_prev = near;
        prev_t = t;
    }
    if (uncertain && (near_earlier || near_prev))
        *uncertain = 1;
    return 0;
}

/* Outward normal = minus the field gradient; each component adds
 * -df/dr * (q - c)/r, with df/dr = -6br/d^2 inside d/3 and
 * -3b(1 - r/d)/d beyond. */
static void prim_density_surface(const render_prim_t *p, hit_t *hit)
{
    vec3_t q = xform_point(&p->to_local, hit->point);
    vec3_t g = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    for (uint16_t k = 0; k < p->component_count; k++) {
        const scene_density_component_t *c = &p->components[k];
        vec3_t r = vec3_sub(q, c->centre);
        num_t q = num_mul(vec3_dot(r, r), p->inv_radius2[k]); /* (r/d)^2 */
        if (!num_lt(q, NUM_ONE))
            continue;
        num_t r2 = vec3_dot(r, r);
        num_t scale; /* -df/dr / r */
        if (!num_gt(num_mul_int(q, 9), NUM_ONE)) {
            scale = num_mul(num_mul_int(c->weight, 6), p->inv_radius2[k]);
        } else {
            num_t rl = num_sqrt(r2);
            num_t x = num_sub(NUM_ONE, num_div(rl, c->radius));
            scale = num_div(num_mul(num_mul_int(c->weight, 3), x), num_mul(c->radius, rl));
        }
        g = vec3_madd(g, r, scale);
    }
    hit->normal = vec3_normalize(xform_dir_transposed(&p->to_local, g));
    hit->tangent_hint = vec3_make(NUM_ONE, NUM_ZERO, NUM_ZERO);
    vec3_t n = hit->normal; /* map like an ellipsoid, by normal direction */
    hit->u = num_mul(prim_pseudo_angle(n.x, n.z), NUM_C(0.25));
    hit->v = num_clamp01(num_mul(num_add(n.y, NUM_ONE), NUM_HALF));
}

/* ------------------------------------------------------------- dispatch */

int prim_intersect(const render_prim_t *p, const ray_t *ray, num_t tmin, num_t tmax, num_t *t_out)
{
    return prim_intersect_uncertain(p, ray, NULL, tmin, tmax, t_out, NULL);
}

int prim_intersect_uncertain(const render_prim_t *p, const ray_t *ray, const ray_error_t *err,
                             num_t tmin, num_t tmax, num_t *t_out, int *uncertain)
{
    if (uncertain)
        *uncertain = 0;
    switch (p->kind) {
    case SCENE_PRIM_TRIANGLE:
        return prim_triangle_intersect(p, ray, err, tmin, tmax, t_out, uncertain);
    case SCENE_PRIM_ELLIPSOID:
        return prim_ellipsoid_intersect(p, ray, err, tmin, tmax, t_out, uncertain);
    case SCENE_PRIM_BOX:
        return prim_box_intersect(p, ray, err, tmin, tmax, t_out, uncertain);
    case SCENE_PRIM_DENSITY:
        return prim_density_intersect(p, ray, err, tmin, tmax, t_out, uncertain, 1);
    case SCENE_PRIM_CONE:
        return prim_cone_intersect(p, ray, err, tmin, tmax, t_out, uncertain);
    default:
        return 0;
    }
}

int prim_intersect_uncertain_whether(const render_prim_t *p, const ray_t *ray,
                                     const ray_error_t *err, num_t tmin, num_t tmax, num_t *t_out,
                                     int *uncertain)
{
    if (p->kind != SCENE_PRIM_DENSITY)
        return prim_intersect_uncertain(p, ray, err, tmin, tmax, t_out, uncertain);
    if (uncertain)
        *uncertain = 0;
    return prim_density_intersect(p, ray, err, tmin, tmax, t_out, uncertain, 0);
}

vec3_t prim_hit_tangent(const render_prim_t *p, const hit_t *hit)
{
    if (p->kind == SCENE_PRIM_TRIANGLE)
        return vec3_normalize(p->e1);
    return prim_tangent(&p->to_local, hit->tangent_hint, hit->normal);
}

void prim_surface(const render_prim_t *p, const ray_t *ray, hit_t *hit)
{
    hit->point = vec3_madd(ray->origin, ray->dir, hit->t);
    hit->curvature = p->curvature; /* an ellipsoid's: its hit's own */
    hit->uv_error = p->uv_error;   /* a box face's: its own */
    switch (p->kind) {
    case SCENE_PRIM_TRIANGLE:
        prim_triangle_surface(p, hit);
        break;
    case SCENE_PRIM_ELLIPSOID:
        prim_ellipsoid_surface(p, hit);
        break;
    case SCENE_PRIM_BOX:
        prim_box_surface(p, hit);
        break;
    case SCENE_PRIM_CONE:
        prim_cone_surface(p, hit);
        break;
    default:
        prim_density_surface(p, hit);
        break;
    }
}

int prim_face_clear(const render_prim_t *p, const ray_t *ray, const ray_error_t *err, num_t tmin,
                    num_t tmax, uint8_t face)
{
    const num_t *row = p->to_local.m[face >> 1];
    num_t o = num_add(num_dot3(row[0], row[1], row[2], ray->origin.x, ray->origin.y,
                               ray->origin.z), row[3]);
    num_t d = num_dot3(row[0], row[1], row[2], ray->dir.x, ray->dir.y, ray->dir.z);
    if (face & 1) {
        o = num_neg(o);
        d = num_neg(d);
    }
    num_t a0 = num_mul(tmin, d), y0 = num_add(o, a0);
    num_t a1 = num_mul(tmax, d), y1 = num_add(o, a1);
    if (!num_gt(y0, NUM_ONE) || !num_gt(y1, NUM_ONE)) /* before any error */
        return 0;
    /* 1, the rounding of o + a at either end, and the error at each */
    num_t one = num_add(NUM_ONE, num_mul_int(num_ulp(num_add(num_abs(o), num_max(num_abs(a0),
                                                                              num_abs(a1)))), 4));
    num_t far = num_add(one, num_add(p->edge_error[0],
                                     num_mul(ray_error_at(err, tmax), p->scale)));
    if (!num_gt(y1, far))
        return 0;
    /* the error at tmin is at most that at tmax (0 <= tmin <= tmax) */
    return num_gt(y0, far) ||
           num_gt(y0, num_add(one, num_add(p->edge_error[0],
                                           num_mul(ray_error_at(err, tmin), p->scale))));
}

int prim_aabb_entry(const aabb_t *b, const ray_t *ray, num_t tmin, num_t tmax, num_t *entry)
{
    num_t tnear = tmin, tfar = tmax;
    for (int axis = 0; axis < 3; axis++)
        if (!prim_slab(vec3_get(ray->origin, axis), vec3_get(ray->dir, axis),
                       vec3_get(b->lo, axis), vec3_get(b->hi, axis), &tnear, &tfar))
            return 0;
    *entry = tnear;
    return 1;
}

int prim_aabb_entry_ray_axes(const aabb_t *b, const ray_t *ray, const aabb_ray_t *r, num_t tmin,
                             num_t tmax, num_t *entry)
{
    num_t tnear = tmin, tfar = tmax;
    for (int axis = 0; axis < 3; axis++) {
        num_t o = vec3_get(ray->origin, axis);
        num_t lo = vec3_get(b->lo, axis), hi = vec3_get(b->hi, axis);
        if (r->use_div[axis]) {
            if (!prim_slab(o, vec3_get(ray->dir, axis), lo, hi, &tnear, &tfar))
                return 0;
            continue;
        }
        int neg = num_lt(r->inv[axis], NUM_ZERO);
        if (!prim_slab_inv_faces(o, r->inv[axis], neg ? hi : lo, neg ? lo : hi, &tnear, &tfar))
            return 0;
    }
    *entry = tnear;
    return 1;
}

int prim_aabb_hit(const aabb_t *b, const ray_t *ray, num_t tmin, num_t tmax)
{
    num_t entry;
    return prim_aabb_entry(b, ray, tmin, tmax, &entry);
}
