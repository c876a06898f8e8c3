/* render/prim_cone.c: the cone frustum and the cylinder (see prim_cone.h). */
#include "render/prim_cone.h"

#include "render/vec3.h"

int prim_cone_frame(const scene_prim_t *sp, prim_cone_frame_t *f)
{
    int big = num_gt(sp->shape.cone.radius[1], sp->shape.cone.radius[0]);
    vec3_t p0 = sp->shape.cone.end[big], p1 = sp->shape.cone.end[!big];
    f->radius = sp->shape.cone.radius[big];
    num_t ratio = num_div(sp->shape.cone.radius[!big], f->radius);
    f->slope = num_mul(num_sub(NUM_ONE, num_min(ratio, NUM_ONE)), NUM_HALF);
    f->centre = vec3_scale(vec3_add(p0, p1), NUM_HALF);
    vec3_t a = vec3_sub(p1, p0);
    f->half = num_mul(vec3_length(a), NUM_HALF);
    if (!num_gt(f->half, NUM_ZERO) || num_is_sat(f->half) || num_is_sat(ratio))
        return 0;
    f->axis = vec3_normalize(a);
    /* across: the axis crossed with the coordinate axis it leans on least */
    num_t ax = num_abs(f->axis.x), ay = num_abs(f->axis.y), az = num_abs(f->axis.z);
    vec3_t any = !num_gt(ax, ay) && !num_gt(ax, az) ? vec3_make(NUM_ONE, NUM_ZERO, NUM_ZERO)
                 : !num_gt(ay, az)                  ? vec3_make(NUM_ZERO, NUM_ONE, NUM_ZERO)
                                                    : vec3_make(NUM_ZERO, NUM_ZERO, NUM_ONE);
    f->u = vec3_normalize(vec3_cross(f->axis, any));
    f->w = vec3_normalize(vec3_cross(f->u, f->axis));
    return !vec3_is_sat(f->axis) && !vec3_is_sat(f->u) && !vec3_is_sat(f->w);
}

xform_t prim_cone_shape(const prim_cone_frame_t *f)
{
    xform_t m;
    vec3_t row[3] = {f->u, f->axis, f->w};
    num_t len[3] = {f->radius, f->half, f->radius};
    for (int i = 0; i < 3; i++) {
        num_t inv = num_recip(len[i]);
        m.m[i][0] = num_mul(row[i].x, inv);
        m.m[i][1] = num_mul(row[i].y, inv);
        m.m[i][2] = num_mul(row[i].z, inv);
        m.m[i][3] = num_neg(num_div(vec3_dot(f->centre, row[i]), len[i]));
    }
    return m;
}

/* ---------------------------------------------------------- the ray test */

/* The ray in the local frame as the ellipsoid's (prim.c): o' + s dn with
 * dn a unit vector and s = t len, written from its closest point c to the
 * centre (s = tc), so that no square of a far origin is formed; the side's
 * quadratic in u = s - tc, a u^2 + 2 b u + cc = 0. */
typedef struct {
    vec3_t c, dn;
    num_t tc, len, h;
    num_t a, b, cc, rho, disc; /* rho: the radius at c.y */
    num_t delta;   /* uncertain: how far c may be off (local units) */
    num_t tmin, tmax;
    num_t best;    /* the nearest t above tmin so far */
    int want, found, uncertain; /* want: uncertain asked for */
} cone_ray_t;

/* The t of local u; 0 when it saturates. */
static int cone_t(const cone_ray_t *r, num_t u, num_t *t)
{
    *t = num_div(num_add(r->tc, u), r->len);
    return !num_is_sat(*t);
}

static void cone_take(cone_ray_t *r, num_t t)
{
    if (!num_gt(t, r->tmin) || (r->found && !num_lt(t, r->best)))
        return;
    r->best = t;
    r->found = 1;
}

/* t within the part of the ray that is asked about */
static int cone_in_span(const cone_ray_t *r, num_t t)
{
    return num_gt(t, r->tmin) && !num_gt(t, r->tmax);
}

/* How far the quadratic's discriminant may be off when c is off by delta
 * in each coordinate: b moves by up to (|dn.x| + |dn.y| + |dn.z|) delta
 * (*berr), cc by up to 2 (|c.x| + |c.z| + h |rho|) delta (*cerr), and
 * b^2 - a cc by twice the first times |b| plus |a| times the second, and a
 * few steps. */
static num_t cone_disc_error(const cone_ray_t *r, num_t *berr, num_t *cerr)
{
    num_t dsum = num_add(num_add(num_abs(r->dn.x), num_abs(r->dn.y)), num_abs(r->dn.z));
    *berr = num_mul(dsum, r->delta);
    num_t cs = num_add(num_add(num_abs(r->c.x), num_abs(r->c.z)), num_mul(r->h, num_abs(r->rho)));
    *cerr = num_mul(num_mul_int(cs, 2), r->delta);
    num_t size = num_max(num_max(num_mul(r->b, r->b), num_abs(num_mul(r->a, r->cc))), NUM_ONE);
    num_t moved = num_add(num_mul_int(num_mul(num_abs(r->b), *berr), 2),
                          num_mul(num_abs(r->a), *cerr));
    return num_add(moved, num_mul_int(num_ulp(size), 8));
}

/* A side root at u, y = c.y + u dn.y: taken when y is within the ends;
 * uncertain when y may be on the other side of an end, which moves by
 * delta plus dn.y times the root's error: the quadratic moved by
 * 2 |u| berr + cerr over its slope there, 2 sq:
 * (||y| - 1| - delta) 2 sq < |dn.y| (2 |u| berr + cerr), no division. */
static void cone_side_root(cone_ray_t *r, num_t u, num_t sq, num_t berr, num_t cerr)
{
    num_t y = num_add(r->c.y, num_mul(u, r->dn.y)), t;
    if (num_is_sat(u) || num_is_sat(y) || !cone_t(r, u, &t))
        return;
    if (r->want && cone_in_span(r, t)) {
        num_t left = num_sub(num_abs(num_sub(num_abs(y), NUM_ONE)), r->delta);
        num_t moved = num_add(num_mul(num_mul_int(num_abs(u), 2), berr), cerr);
        if (num_lt(left, NUM_ZERO) ||
            num_lt(num_mul(left, num_mul_int(sq, 2)), num_mul(num_abs(r->dn.y), moved)))
            r->uncertain = 1;
    }
    if (!num_gt(num_abs(y), NUM_ONE))
        cone_take(r, t);
}

/* The side: the quadratic's roots, the stable way (q = -(b + sign(b) sq),
 * roots q / a and cc / q); a ray that grazes it within the error of the
 * discriminant, at a place within the ends and the span asked about, is
 * uncertain. */
static void cone_side(cone_ray_t *r)
{
    num_t berr = NUM_ZERO, cerr = NUM_ZERO;
    if (r->want) {
        num_t derr = cone_disc_error(r, &berr, &cerr);
        if (!num_gt(num_abs(r->disc), derr)) {
            num_t ug = num_div(num_neg(r->b), r->a), t;
            num_t yg = num_add(r->c.y, num_mul(ug, r->dn.y));
            if (!num_is_sat(ug) && !num_is_sat(yg) && cone_t(r, ug, &t) && cone_in_span(r, t) &&
                !num_gt(num_abs(yg), num_add(NUM_ONE, r->delta)))
                r->uncertain = 1;
        }
    }
    if (num_lt(r->disc, NUM_ZERO))
        return;
    num_t sq = num_sqrt(r->disc);
    num_t q = num_lt(r->b, NUM_ZERO) ? num_sub(sq, r->b) : num_neg(num_add(r->b, sq));
    if (num_eq(q, NUM_ZERO))
        return;
    cone_side_root(r, num_div(q, r->a), sq, berr, cerr);
    cone_side_root(r, num_div(r->cc, q), sq, berr, cerr);
}

/* The end disc at y = end (+-1) of radius rad, met where u = (end - c.y) /
 * dn.y; with X, Z = x dn.y, z dn.y there (no division) it is hit when
 * X^2 + Z^2 <= (rad |dn.y|)^2, and uncertain when sqrt(X^2 + Z^2) is
 * within delta (|dn.y| + |dn.x| + |dn.z|) of rad |dn.y| (the point's error
 * and the crossing's along the ray). */
static void cone_cap(cone_ray_t *r, num_t end, num_t rad)
{
    num_t dy = num_abs(r->dn.y), gap = num_sub(end, r->c.y);
    if (num_eq(dy, NUM_ZERO))
        return;
    num_t x = num_add(num_mul(r->c.x, r->dn.y), num_mul(gap, r->dn.x));
    num_t z = num_add(num_mul(r->c.z, r->dn.y), num_mul(gap, r->dn.z));
    num_t rr = num_add(num_mul(x, x), num_mul(z, z)), edge = num_mul(rad, dy);
    num_t u = num_div(gap, r->dn.y), t = NUM_ZERO; /* set when have_t */
    int have_t = !num_is_sat(u) && cone_t(r, u, &t);
    if (r->want && (!have_t || cone_in_span(r, t))) {
        num_t e = num_mul(r->delta, num_add(dy, num_add(num_abs(r->dn.x), num_abs(r->dn.z))));
        e = num_add(e, num_mul_int(num_ulp(NUM_ONE), 8));
        if (num_lt(num_abs(num_sub(num_sqrt(rr), edge)), e))
            r->uncertain = 1;
    }
    if (have_t && !num_gt(rr, num_mul(edge, edge)))
        cone_take(r, t);
}

/* How far c may be off in local units: the local coordinates' rounding
 * (render_prim_t.edge_error), a few steps at tc, and the ray's own error
 * (at the far side of the bounding sphere) times scale; in fixed point
 * also dn's length off 1 times |tc| (as the ellipsoid's, prim.c). */
static num_t cone_delta(const render_prim_t *p, const cone_ray_t *r, const ray_error_t *err)
{
    num_t e0 = num_add(p->edge_error[0], num_mul_int(num_ulp(num_abs(r->tc)), 4));
#if defined(LINKS1_NUM_FIXED)
    num_t dir_err = num_add(num_abs(num_sub(NUM_ONE, vec3_dot(r->dn, r->dn))),
                            num_mul_int(num_ulp(NUM_ONE), 8));
    e0 = num_add(e0, num_mul(dir_err, num_abs(r->tc)));
#endif
    num_t far = num_div(num_add(num_abs(r->tc), NUM_C(3)), r->len);
    num_t d = num_add(e0, num_mul(ray_error_at(err, num_is_sat(far) ? NUM_FAR : far), p->scale));
    d = num_is_sat(d) ? NUM_FAR : d;
    return num_gt(d, NUM_ZERO) ? d : num_ulp(NUM_ONE);
}

int prim_cone_intersect(const render_prim_t *p, const ray_t *ray, const ray_error_t *err,
                        num_t tmin, num_t tmax, num_t *t_out, int *uncertain)
{
    vec3_t o = xform_point_inline(&p->to_local, ray->origin);
    vec3_t d = xform_dir_inline(&p->to_local, ray->dir);
    cone_ray_t r;
    r.len = vec3_length(d);
    if (vec3_is_sat(o) || num_is_sat(r.len) || !num_gt(r.len, NUM_ZERO))
        return 0;
    r.dn = vec3_scale(d, num_recip(r.len));
    r.tc = num_neg(vec3_dot(o, r.dn));
    r.c = vec3_madd(o, r.dn, r.tc);
    r.tmin = tmin;
    r.tmax = tmax;
    r.h = p->cone_slope;
    r.want = uncertain != NULL;
    r.delta = r.want ? cone_delta(p, &r, err) : NUM_ZERO;
    r.found = r.uncertain = 0;
    r.best = NUM_ZERO;
    /* the cone lies within the sphere of radius sqrt(2) */
    num_t lim = num_add(NUM_C(1.5), r.delta);
    if (vec3_is_sat(r.c) || num_gt(num_abs(r.c.x), lim) || num_gt(num_abs(r.c.y), lim) ||
        num_gt(num_abs(r.c.z), lim) || num_gt(vec3_dot(r.c, r.c), num_mul(lim, lim)))
        return 0;
    num_t hy = num_mul(r.h, r.dn.y);
    r.a = num_sub(num_add(num_mul(r.dn.x, r.dn.x), num_mul(r.dn.z, r.dn.z)), num_mul(hy, hy));
    r.rho = num_sub(NUM_ONE, num_mul(r.h, num_add(NUM_ONE, r.c.y)));
    r.b = num_add(num_add(num_mul(r.c.x, r.dn.x), num_mul(r.c.z, r.dn.z)), num_mul(hy, r.rho));
    r.cc = num_sub(num_add(num_mul(r.c.x, r.c.x), num_mul(r.c.z, r.c.z)), num_mul(r.rho, r.rho));
    r.disc = num_sub(num_mul(r.b, r.b), num_mul(r.a, r.cc));
    cone_side(&r);
    if (p->cone_capped) {
        cone_cap(&r, num_neg(NUM_ONE), NUM_ONE);
        num_t small = num_sub(NUM_ONE, num_mul_int(r.h, 2));
        if (num_gt(small, NUM_ZERO))
            cone_cap(&r, NUM_ONE, small);
    }
    if (uncertain)
        *uncertain = r.uncertain;
    if (!r.found || num_gt(r.best, tmax))
        return 0;
    *t_out = r.best;
    return 1;
}

/* ------------------------------------------------------------ the surface */

void prim_cone_surface(const render_prim_t *p, hit_t *hit)
{
    vec3_t q = xform_point(&p->to_local, hit->point);
    num_t h = p->cone_slope;
    num_t rho = num_sub(NUM_ONE, num_mul(h, num_add(NUM_ONE, q.y)));
    num_t across = num_sqrt(num_add(num_mul(q.x, q.x), num_mul(q.z, q.z)));
    /* a cap when the point lies nearer its plane than the side */
    int cap = 0;
    if (p->cone_capped) {
        num_t to_end = num_abs(num_sub(num_abs(q.y), NUM_ONE));
        num_t small = num_sub(NUM_ONE, num_mul_int(h, 2));
        cap = num_lt(to_end, num_abs(num_sub(across, rho))) &&
              (num_lt(q.y, NUM_ZERO) || num_gt(small, NUM_ZERO));
    }
    vec3_t g = cap ? vec3_make(NUM_ZERO, num_lt(q.y, NUM_ZERO) ? num_neg(NUM_ONE) : NUM_ONE,
                               NUM_ZERO)
                   : vec3_make(q.x, num_mul(h, rho), q.z);
    g = xform_dir_transposed(&p->to_local, g);
    num_t len = vec3_length(g);
    hit->normal = num_gt(len, NUM_ZERO) ? vec3_make(num_div(g.x, len), num_div(g.y, len),
                                                    num_div(g.z, len)) : g;
    /* as the ellipsoid's (prim.c): the side's gradient (x, h rho, z) moves
     * by at most the local point's move, so the normal turns by at most
     * scale^2 e / |M^T g|; a cap is flat */
    hit->curvature = cap ? NUM_ZERO
                     : num_gt(len, NUM_ZERO) ? num_div(num_mul(p->scale, p->scale), len)
                                             : NUM_FAR;
    if (num_is_sat(hit->curvature))
        hit->curvature = NUM_FAR;
    if (cap) {
        hit->tangent_hint = vec3_make(NUM_ONE, NUM_ZERO, NUM_ZERO);
        hit->u = num_clamp01(num_mul(num_add(q.x, NUM_ONE), NUM_HALF));
        hit->v = num_clamp01(num_mul(num_add(q.z, NUM_ONE), NUM_HALF));
        return;
    }
    hit->tangent_hint = vec3_make(num_neg(q.z), NUM_ZERO, q.x);
    hit->u = num_mul(prim_pseudo_angle(q.x, q.z), NUM_C(0.25));
    hit->v = num_clamp01(num_mul(num_add(q.y, NUM_ONE), NUM_HALF));
}
