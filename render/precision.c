/* render/precision.c: see precision.h. */
#include "render/precision.h"

#include "proto/textfmt.h"
#include "render/prim_cone.h"
#include "render/vec3.h"

#define PRECISION_INVERSE_TOL NUM_C(RENDER_INVERSE_TOLERANCE_VALUE)
#define PRECISION_LOST_TOL(s) scene_tolerance((s), NUM_C(RENDER_LOST_TOLERANCE_VALUE))
#define PRECISION_MIN_SPAN(s) scene_tolerance((s), NUM_C(RENDER_MIN_SPAN_VALUE))
#define PRECISION_ACNE_TOL(s) scene_tolerance((s), NUM_C(RENDER_RAY_EPSILON_VALUE / 2))

/* Largest |(m * inv)[i][j] - identity| over the 3x3 part. */
static num_t precision_residual(const xform_t *m, const xform_t *inv)
{
    xform_t p = xform_compose(m, inv);
    num_t worst = NUM_ZERO;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            num_t e = num_abs(num_sub(p.m[i][j], i == j ? NUM_ONE : NUM_ZERO));
            if (num_is_sat(e))
                return e;
            worst = num_max(worst, e);
        }
    return worst;
}

/* With every row scaled to unit length the map is invertible: only its
 * scale was beyond the arithmetic. */
static int precision_rows_independent(const xform_t *m)
{
    xform_t u = *m;
    for (int i = 0; i < 3; i++) {
        num_t len = num_len3(m->m[i][0], m->m[i][1], m->m[i][2]);
        if (!num_gt(len, NUM_ZERO) || num_is_sat(len))
            return 0;
        for (int j = 0; j < 4; j++)
            u.m[i][j] = j < 3 ? num_div(m->m[i][j], len) : NUM_ZERO;
    }
    xform_t inv;
    return xform_invert(&u, &inv);
}

render_status_t precision_invert(const xform_t *m, xform_t *inv)
{
    if (!xform_invert(m, inv))
        return precision_rows_independent(m) ? RENDER_ERR_SCALE : RENDER_ERR_SINGULAR;
    num_t r = precision_residual(m, inv);
    if (num_is_sat(r) || num_gt(r, PRECISION_INVERSE_TOL))
        return RENDER_ERR_SCALE;
    return RENDER_OK;
}

/* Estimated distance, in scene units, by which rounding in p's to_local
 * map moves a point at most |extent| from the eye: per local axis, half a
 * step of each entry times the extent plus half a step of the result,
 * over the row's length (local units per scene unit).  *least is the
 * smallest over the axes: the error across the flattest side, where a
 * secondary ray starting RENDER_RAY_EPSILON_VALUE off the surface would
 * hit it again (shadow acne); the largest moves a hit along a surface. */
/* What precision_hit_error finds of a map: rows[0] and rows[1] the
 * longest and the shortest row of to_local (local units per eye unit
 * along the most and the least squeezed axis), len each row's, local[k]
 * the rounding error of local coordinate k (local units) and local_worst
 * the largest of them; NUM_FAR where it gives up. */
typedef struct {
    num_t rows[2], len[3], local[3], local_worst;
} precision_local_t;

static num_t precision_hit_error(const render_prim_t *p, num_t extent, num_t *least,
                                 precision_local_t *l)
{
    num_t worst = NUM_ZERO;
    *least = NUM_FAR;
    l->local_worst = l->local[0] = l->local[1] = l->local[2] = NUM_FAR;
    l->len[0] = l->len[1] = l->len[2] = NUM_ZERO;
    l->rows[0] = NUM_ZERO;
    l->rows[1] = NUM_FAR;
    num_t local_max = NUM_ZERO, local_axis[3];
    for (int i = 0; i < 3; i++) {
        const num_t *row = p->to_local.m[i];
        num_t len = num_len3(row[0], row[1], row[2]);
        if (!num_gt(len, NUM_ZERO) || num_is_sat(len))
            return NUM_FAR;
        l->len[i] = len;
        l->rows[0] = num_max(l->rows[0], len);
        l->rows[1] = num_min(l->rows[1], len);
        num_t steps = num_add(num_add(num_ulp(row[0]), num_ulp(row[1])), num_ulp(row[2]));
        num_t local = num_add(num_mul(len, extent), num_abs(row[3]));
        if (num_is_sat(num_mul_int(local, 2))) /* local coordinates near the
                                                   range: the primitive test
                                                   saturates and misses */
            return NUM_FAR;
        num_t err = num_add(num_mul(steps, extent), num_add(num_ulp(row[3]), num_ulp(local)));
        err = num_mul(err, NUM_HALF);
        local_axis[i] = err;
        local_max = num_max(local_max, err);
        err = num_div(err, len);
        if (num_is_sat(err))
            return NUM_FAR;
        worst = num_max(worst, err);
        *least = num_min(*least, err);
    }
    l->local_worst = local_max;
    for (int i = 0; i < 3; i++)
        l->local[i] = local_axis[i];
    return worst;
}

/* A box's error per local axis (render_prim_t.box_edge_error): each
 * coordinate's rounding error with the cluster map's error (map, eye
 * units) on its axis; NUM_FAR where that overflows, or where
 * precision_hit_error gave up (its local errors NUM_FAR).  And each row's
 * length (box_row_len). */
static void precision_box_axes(render_prim_t *p, const precision_local_t *l, num_t map)
{
    for (int i = 0; i < 3; i++) {
        p->box_edge_error[i] = num_limit(num_add(l->local[i], num_mul(map, l->len[i])), NUM_FAR);
        p->box_row_len[i] = l->len[i];
    }
}

/* A triangle's barycentrics beta, gamma: each a distance in the plane over
 * a height, the point off by a few steps of the arithmetic at the scene's
 * extent.  A sliver's error across its thin side is a large part of 1. */
/* point: 4 steps at the extent, num_mul_int(num_ulp(extent), 4); h1, h2:
 * |height1|, |height2| */
static void precision_triangle_edge_error(render_prim_t *p, num_t point, num_t h1, num_t h2)
{
    p->edge_error[0] = num_div(point, h1); /* saturated: every */
    p->edge_error[1] = num_div(point, h2); /* edge test counts */
}

/* A triangle's map coordinates: u = u0 + beta (u1 - u0) + gamma (u2 - u0);
 * spread: the sum over k = 1, 2 of max(|u_k - u_0|, |v_k - v_0|), the
 * scene index's (render_scene_index: once a load). */
static num_t precision_triangle_uv_error(const render_prim_t *p, num_t spread)
{
    num_t bary = num_max(p->edge_error[0], p->edge_error[1]);
    num_t err = num_mul(bary, spread);
    return num_is_sat(err) || num_is_sat(bary) ? NUM_FAR : err;
}

num_t precision_map_error(const xform_t *to_eye, const xform_t *from_eye, const aabb_t *bounds)
{
    num_t reach = NUM_ZERO;
    for (int axis = 0; axis < 3; axis++)
        reach = num_max(reach, num_max(num_abs(vec3_get(bounds->lo, axis)),
                                       num_abs(vec3_get(bounds->hi, axis))));
    xform_t r = xform_compose(to_eye, from_eye);
    num_t worst = NUM_ZERO;
    for (int i = 0; i < 3; i++) {
        num_t lin = NUM_ZERO;
        for (int j = 0; j < 3; j++)
            lin = num_add(lin, num_abs(num_sub(r.m[i][j], i == j ? NUM_ONE : NUM_ZERO)));
        num_t e = num_add(num_mul(lin, reach), num_abs(r.m[i][3]));
        if (num_is_sat(e) || num_is_sat(reach))
            return NUM_FAR;
        worst = num_max(worst, e);
    }
    return worst;
}

/* A smooth triangle's normal, alpha n0 + beta n1 + gamma n2, turns by at
 * most |n1 - n0| / height1 + |n2 - n0| / height2 per unit moved (h1, h2:
 * the heights' absolute values). */
static inline __attribute__((always_inline)) num_t precision_triangle_curvature(const render_prim_t *p, num_t h1, num_t h2)
{
    if (!p->smooth)
        return NUM_ZERO;
    const vec3_t *n = p->normals.n;
    num_t c = num_add(num_div(vec3_length(vec3_sub(n[1], n[0])), h1),
                      num_div(vec3_length(vec3_sub(n[2], n[0])), h2));
    return num_is_sat(c) ? NUM_FAR : c;
}

/* A density sphere's excess (the field's sum minus the threshold, which
 * prim.c's root finder samples along a ray): edge_error[1] its largest
 * gradient per local unit, the sum of 2 w / d (each field's slope is
 * largest, 2 w / d, at d / 3); edge_error[0] what rounding adds at any
 * point: that gradient times the local point's error (local), and each
 * field's own steps, its q = r^2 / d^2 (a few steps of d^2, over d^2)
 * times the largest slope in q, 3 w, and its products' steps. */
static void precision_density_excess_error(render_prim_t *p, num_t local)
{
    num_t grad = NUM_ZERO, own = NUM_ZERO;
    num_t unit = num_mul_int(num_ulp(NUM_ONE), 4);
    for (uint16_t k = 0; k < p->component_count; k++) {
        const scene_density_component_t *c = &p->components[k];
        num_t w = num_abs(c->weight), d = c->radius;
        grad = num_add(grad, num_div(num_mul_int(w, 2), d));
        num_t dq = num_add(num_mul(num_mul_int(num_ulp(num_mul(d, d)), 4), p->inv_radius2[k]), unit);
        own = num_add(own, num_add(num_mul(num_mul_int(w, 3), dq),
                                   num_mul_int(num_ulp(num_max(w, NUM_ONE)), 8)));
    }
    own = num_add(own, num_mul_int(num_ulp(num_max(num_abs(p->threshold), NUM_ONE)), 2));
    num_t at = num_add(own, num_mul(grad, local));
    p->edge_error[0] = num_is_sat(at) ? NUM_FAR : at;
    p->edge_error[1] = num_is_sat(grad) ? NUM_FAR : grad;
}

/* A density sphere's surface: taken as curved no more than a sphere of a
 * quarter of its smallest component's radius (a lone component's surface
 * lies beyond a quarter of its radius for a threshold under 0.8 of its
 * weight); its components live in to_local's units. */
static num_t precision_density_curvature(const render_prim_t *p, num_t row_max)
{
    num_t r = NUM_FAR;
    for (uint16_t k = 0; k < p->component_count; k++)
        r = num_min(r, p->components[k].radius);
    num_t c = num_div(num_mul_int(row_max, 4), r);
    return num_is_sat(c) ? NUM_FAR : c;
}

num_t precision_world_extent(num_t box, vec3_t eye)
{
    num_t x = num_max(box, num_max(num_abs(eye.x), num_max(num_abs(eye.y), num_abs(eye.z))));
    if (num_is_sat(x))
        return x;
    num_t p = NUM_ONE;
    while (num_lt(p, x) && !num_is_sat(num_add(p, p)))
        p = num_add(p, p);
    for (num_t h = num_mul(p, NUM_HALF); num_gt(h, NUM_ZERO) && num_ge(h, x) && num_lt(h, p);
         h = num_mul(p, NUM_HALF))
        p = h;
    return p;
}

precision_pass_t precision_check_begin(render_frame_t *f)
{
    precision_pass_t pass;
    f->span = NUM_ZERO;
    const aabb_t *b = &f->clusters[0].bounds;
    num_t extent = NUM_ZERO;
    for (int axis = 0; f->prim_count && axis < 3; axis++) {
        num_t lo = vec3_get(b->lo, axis), hi = vec3_get(b->hi, axis);
        f->span = num_max(f->span, num_sub(hi, lo));
        extent = num_max(extent, num_max(num_abs(lo), num_abs(hi)));
    }
    if (num_is_sat(f->span) || num_is_sat(extent))
        f->precision_lost = 1;
    if (f->world) {
        f->world_box_extent = extent;
        extent = precision_world_extent(extent, f->eye);
    }
    f->precision_extent = extent;
    pass.extent = extent;
    pass.lost_tol = PRECISION_LOST_TOL(f->scene);
    pass.acne_tol = PRECISION_ACNE_TOL(f->scene);
    /* A triangle's detail (precision_detail_triangle): the steps at its
     * box's reach are at most those at the scene's extent, which holds
     * every box, so a smaller height not under the latter is not under the
     * former and needs no reach; but a box with a saturated value (the
     * flag) may have left the extent short. */
    pass.detail_fast = !f->precision_lost;
    pass.detail_at_extent = num_mul_int(num_ulp(extent), RENDER_MIN_DETAIL_STEPS);
    pass.point = num_mul_int(num_ulp(extent), 4);
    return pass;
}

/* Inline: precision_check_prims runs it for every primitive of every
 * frame. */
static inline __attribute__((always_inline)) void precision_check_one(render_frame_t *f, uint32_t i, const scene_index_t *ix,
                                       const precision_pass_t *pass)
{
    render_prim_t *p = &f->prims[i];
    if (p->kind == SCENE_PRIM_TRIANGLE) {
        /* no to_local map, and its hit error is left out: two
         * triangles hit at one distance are most often a mesh's faces
         * meeting at an edge.  So none of the estimates below (the DM
         * would make them for every triangle of every frame). */
        p->hit_error = NUM_ZERO;
        p->imprecise = 0;
        p->scale = NUM_ZERO;
        num_t h1 = num_abs(p->height1), h2 = num_abs(p->height2);
        if (!pass->detail_fast || !num_ge(num_min(h1, h2), pass->detail_at_extent))
            precision_detail_triangle(f, i);
        precision_triangle_edge_error(p, pass->point, h1, h2);
        p->uv_error = precision_triangle_uv_error(p, ix->uv_spread[i]);
        p->curvature = precision_triangle_curvature(p, h1, h2);
        return;
    }
    precision_local_t l;
    num_t least, worst = precision_hit_error(p, pass->extent, &least, &l);
    num_t *rows = l.rows;
    /* render_prepare left the cluster map's error in hit_error */
    num_t map = p->hit_error;
    worst = num_add(worst, map);
    /* the surface moved by the map, in local units: a consistent move,
     * no acne, but the decisions and map coordinates see it */
    num_t local = num_add(l.local_worst, num_mul(map, rows[0]));
    if (num_is_sat(worst) || num_is_sat(local))
        worst = local = NUM_FAR;
    p->hit_error = worst;
    p->imprecise = num_gt(worst, pass->lost_tol) || num_gt(least, pass->acne_tol);
    p->scale = rows[0];
    /* map coordinates (render/prim.c): a box face's are (q + 1) / 2 of
     * a local coordinate q, an ellipsoid's a pseudo-angle / 4 and
     * (n.y + 1) / 2 of its unit sphere's point, a density sphere's come
     * from its normal (not estimated) */
    /* the normal's curvature: an ellipsoid's largest, at the end of
     * its longest axis, is a / c^2 for radii a >= c (rows 1/c, 1/a) */
    p->curvature = NUM_ZERO;
    switch (p->kind) {
    case SCENE_PRIM_BOX:
        p->uv_error = num_mul(local, NUM_HALF);
        precision_box_axes(p, &l, map);
        p->edge_error[0] = local;
        break;
    case SCENE_PRIM_ELLIPSOID:
    case SCENE_PRIM_CONE: /* its local point as an ellipsoid's */
        p->uv_error = local;
        p->edge_error[0] = local;
        p->curvature = num_div(num_mul(rows[0], rows[0]), rows[1]);
        if (num_is_sat(p->curvature))
            p->curvature = NUM_FAR;
        break;
    default:
        p->uv_error = NUM_ZERO;
        p->curvature = precision_density_curvature(p, rows[0]);
        precision_density_excess_error(p, local);
        break;
    }
}

void precision_check_prims(render_frame_t *f, const scene_index_t *ix, const precision_pass_t *begun,
                           const uint32_t *list, uint32_t count)
{
    /* a copy whose address no call takes: its fields stay in registers */
    const precision_pass_t pass = *begun;
    if (!list) /* every primitive: precision_check */
        for (uint32_t i = 0; i < count; i++)
            precision_check_one(f, i, ix, &pass);
    else
        for (uint32_t k = 0; k < count; k++)
            precision_check_one(f, list[k], ix, &pass);
}

render_status_t precision_check_end(const render_frame_t *f)
{
    if (f->prim_count == 0)
        return RENDER_OK;
    if (num_lt(f->span, PRECISION_MIN_SPAN(f->scene)))
        return RENDER_ERR_EXTENT;
    return f->detail_prim != RENDER_NO_PRIM ? RENDER_ERR_DETAIL : RENDER_OK;
}

render_status_t precision_check(render_frame_t *f, const scene_index_t *ix)
{
    const precision_pass_t pass = precision_check_begin(f);
    precision_check_prims(f, ix, &pass, NULL, f->prim_count);
    return precision_check_end(f);
}

/* The largest |coordinate| of a box. */
static inline num_t precision_box_reach(const aabb_t *b)
{
    num_t r = NUM_ZERO;
    for (int axis = 0; axis < 3; axis++)
        r = num_max(r, num_max(num_abs(vec3_get(b->lo, axis)), num_abs(vec3_get(b->hi, axis))));
    return r;
}

/* Length in eye units of s cluster units along the cluster's axis j. */
static num_t precision_axis_len(const xform_t *to_eye, int j, num_t s)
{
    return num_mul(num_abs(s), num_len3(to_eye->m[0][j], to_eye->m[1][j], to_eye->m[2][j]));
}

/* A cone's smallest size: its larger end's radius across its two
 * directions and half its axis, in eye units and in its cluster's (its
 * smaller end may be a point). */
static void precision_detail_cone(render_frame_t *f, uint32_t i, const xform_t *to_eye,
                                  num_t reach)
{
    prim_cone_frame_t c;
    if (!prim_cone_frame(&f->scene->prims[i], &c))
        return; /* its box saturated: the precision flag */
    num_t eye = num_min(num_mul(c.half, vec3_length(xform_dir(to_eye, c.axis))),
                        num_mul(c.radius, num_min(vec3_length(xform_dir(to_eye, c.u)),
                                                  vec3_length(xform_dir(to_eye, c.w)))));
    num_t own_reach = NUM_ZERO;
    for (int j = 0; j < 3; j++)
        own_reach = num_max(own_reach, num_abs(vec3_get(c.centre, j)));
    own_reach = num_add(own_reach, num_max(c.half, c.radius));
    precision_detail_one(f, i, eye, reach);
    precision_detail_one(f, i, num_min(c.half, c.radius), own_reach);
}

void precision_detail(render_frame_t *f, uint32_t i, const xform_t *to_eye)
{
    const scene_prim_t *sp = &f->scene->prims[i];
    const render_prim_t *p = &f->prims[i];
    num_t reach = precision_box_reach(&p->bounds);
    switch (sp->kind) {
    case SCENE_PRIM_TRIANGLE:
        precision_detail_triangle(f, i);
        break; /* (render_prepare leaves it to precision_check) */
    case SCENE_PRIM_ELLIPSOID:
    case SCENE_PRIM_BOX: {
        vec3_t c, r;
        scene_prim_centre_axes(sp, &c, &r);
        num_t eye = NUM_FAR, own = NUM_FAR, own_reach = NUM_ZERO;
        for (int j = 0; j < 3; j++) {
            num_t rj = num_abs(vec3_get(r, j));
            eye = num_min(eye, precision_axis_len(to_eye, j, rj));
            own = num_min(own, rj);
            own_reach = num_max(own_reach, num_add(num_abs(vec3_get(c, j)), rj));
        }
        precision_detail_one(f, i, eye, reach);
        precision_detail_one(f, i, own, own_reach);
        break;
    }
    case SCENE_PRIM_CONE:
        precision_detail_cone(f, i, to_eye, reach);
        break;
    default: /* SCENE_PRIM_DENSITY */
        for (uint16_t k = 0; k < p->component_count; k++) {
            const scene_density_component_t *d = &p->components[k];
            num_t eye = NUM_FAR, own_reach = NUM_ZERO;
            for (int j = 0; j < 3; j++) {
                eye = num_min(eye, precision_axis_len(to_eye, j, d->radius));
                own_reach = num_max(own_reach, num_add(num_abs(vec3_get(d->centre, j)),
                                                       num_abs(d->radius)));
            }
            precision_detail_one(f, i, eye, reach);
            precision_detail_one(f, i, num_abs(d->radius), own_reach);
        }
        break;
    }
}

/* |v| * 2^-unit_exp, a length in the scene text's units, as m * 2^*b
 * with m in [2^31, 2^32); 0 for 0.  Exact in fixed point (a step is
 * 2^-NUM_FRAC_BITS), within 2^-31 of it in the IEEE builds. */
static uint64_t precision_split(const scene_t *s, num_t v, int *b)
{
    *b = -s->unit_exp;
#if defined(LINKS1_NUM_FIXED)
    uint64_t m = (uint64_t)(v < 0 ? -(int64_t)v : (int64_t)v);
    *b -= NUM_FRAC_BITS;
#else
    num_t x = num_abs(v);
    if (!num_gt(x, NUM_ZERO))
        return 0;
    for (; !num_lt(x, NUM_C(4294967296.0)); (*b)++)
        x = num_scale2(x, -1);
    for (; num_lt(x, NUM_C(2147483648.0)); (*b)--)
        x = num_scale2(x, 1);
    uint64_t m = (uint64_t)x;
#endif
    if (m == 0)
        return 0;
    for (; m < (UINT64_C(1) << 31); (*b)--)
        m <<= 1;
    for (; m >= (UINT64_C(1) << 32); (*b)++)
        m >>= 1;
    return m;
}

/* floor(m * 2^b), m < 2^33; saturates at 2^62. */
static uint64_t precision_floor(uint64_t m, int b)
{
    if (b >= 0)
        return b > 29 ? UINT64_C(1) << 62 : m << b;
    return b <= -63 ? 0 : m >> -b;
}

/* Three significant digits of v, a length in the scene's stored units,
 * given in the scene text's units (v * 2^-unit_exp): "0.122", "12.3",
 * "0.00001", "1.91e-6"; from an integer mantissa (the fixed build has no
 * floating point, and its step in a small scene's text units is below
 * what num_t holds) */
static void precision_fmt_len(const scene_t *s, num_t v, char *out, size_t cap)
{
    int b;
    if (num_is_sat(v)) {
        fmt_snprintf(out, cap, "(out of range)");
        return;
    }
    uint64_t m = precision_split(s, v, &b);
    if (m == 0) {
        fmt_snprintf(out, cap, "0");
        return;
    }
    int dec = 0; /* |v| = m * 2^b / 10^dec */
    while (precision_floor(m, b) < 100 && dec < 24) {
        for (m *= 10; m >= (UINT64_C(1) << 32); b++)
            m >>= 1;
        dec++;
    }
    uint64_t half = b < 0 && b > -63 ? UINT64_C(1) << (-b - 1) : 0;
    int64_t digits = (int64_t)precision_floor(m + half, b);
    if (digits == 0) { /* under 10^-24 */
        fmt_snprintf(out, cap, "0");
        return;
    }
    while (digits >= 1000 && dec > 0) {
        digits = (digits + 5) / 10;
        dec--;
    }
    while (dec > 0 && digits % 10 == 0) { /* no trailing zeros */
        digits /= 10;
        dec--;
    }
    if (dec <= 5) { /* down to 0.00001: plain */
        int32_t p10 = 1;
        for (int i = 0; i < dec; i++)
            p10 *= 10;
        fmt_snprintf(out, cap, dec ? "%lld.%0*lld" : "%lld", (long long)(digits / p10), dec,
                     (long long)(digits % p10));
        return;
    }
    int e = 0; /* digits to one before the point */
    int32_t p10 = 1;
    while (digits / p10 >= 10) {
        p10 *= 10;
        e++;
    }
    if (e == 0) {
        fmt_snprintf(out, cap, "%lde-%d", (long)digits, dec);
        return;
    }
    fmt_snprintf(out, cap, "%ld.%0*lde-%d", (long)(digits / p10), e, (long)(digits % p10),
                 dec - e);
}

void precision_extent_message(const render_frame_t *f, char *out, size_t cap)
{
    const scene_t *s = f->scene;
    char span[24], need[24], offset[24], what[48];
    precision_fmt_len(s, f->span, span, sizeof span);
    precision_fmt_len(s, PRECISION_MIN_SPAN(s), need, sizeof need);
    precision_fmt_len(s, f->ray_epsilon, offset, sizeof offset);
#if defined(LINKS1_NUM_FIXED)
    fmt_snprintf(what, sizeof what, "fixed Q%d.%d resolves 2^-%d", 31 - NUM_FRAC_BITS,
                 NUM_FRAC_BITS, NUM_FRAC_BITS);
#else
    fmt_snprintf(what, sizeof what, "%s resolves 2^-%d of a value", NUM_NAME,
                 (int)sizeof(num_t) == 8 ? 52 : 23);
#endif
    /* the tolerances follow the geometry down to RENDER_TOL_EXP_MIN: there
     * the eye or a light is at least 2^(SLACK - MIN - 1) times farther out
     * (scene.h tol_exp); above it the geometry's largest length in world
     * units (its clusters' powers of two included) was large enough, so it
     * lies far from the origin for its size (or a cluster map the loader
     * did not make shrinks it) */
    char cause[96];
    if (s->tol_exp <= RENDER_TOL_EXP_MIN)
        fmt_snprintf(cause, sizeof cause, "the eye or a light lies over %d times farther out than "
                     "the geometry; bring it closer",
                     1 << (RENDER_TOL_SLACK_EXP - RENDER_TOL_EXP_MIN - 1));
    else
        fmt_snprintf(cause, sizeof cause, "it lies far from the origin for its size; move it "
                     "nearer");
    fmt_snprintf(out, cap, "scene spans %s; %s (lengths scaled by 2^%ld), but secondary rays "
                 "start %s from a surface, so a scene needs a span of at least %s: %s",
                 span, what, (long)s->unit_exp, offset, need, cause);
}

/* What a primitive is and what its smallest size is called. */
static const char *precision_kind_name(const scene_prim_t *sp, const char **size)
{
    switch (sp->kind) {
    case SCENE_PRIM_TRIANGLE: *size = "height"; return "triangle";
    case SCENE_PRIM_ELLIPSOID: {
        vec3_t r = sp->shape.ellipsoid.radius;
        *size = num_eq(r.x, r.y) && num_eq(r.y, r.z) ? "radius" : "semi-axis";
        return "ellipsoid";
    }
    case SCENE_PRIM_BOX: *size = "half edge"; return "box";
    case SCENE_PRIM_CONE:
        *size = "radius or half length";
        return num_eq(sp->shape.cone.radius[0], sp->shape.cone.radius[1]) ? "cylinder" : "cone";
    default: *size = "component radius"; return "density sphere";
    }
}

void precision_detail_message(const render_frame_t *f, char *out, size_t cap)
{
    const scene_t *s = f->scene;
    if (f->detail_prim == RENDER_NO_PRIM || f->detail_prim >= s->prim_count) {
        fmt_snprintf(out, cap, "%s", render_status_name(RENDER_ERR_DETAIL));
        return;
    }
    char size[24], step[24], span[24], what[24];
    const char *size_name, *kind = precision_kind_name(&s->prims[f->detail_prim], &size_name);
    precision_fmt_len(s, f->detail_size, size, sizeof size);
    precision_fmt_len(s, f->detail_step, step, sizeof step);
    precision_fmt_len(s, f->span, span, sizeof span);
#if defined(LINKS1_NUM_FIXED)
    fmt_snprintf(what, sizeof what, "fixed Q%d.%d", 31 - NUM_FRAC_BITS, NUM_FRAC_BITS);
    const char *instead = " or use float";
#else
    fmt_snprintf(what, sizeof what, "%s", NUM_NAME);
    const char *instead = "";
#endif
    fmt_snprintf(out, cap, "%s %lu has a %s of %s; %s resolves %s there, in a scene spanning %s "
                 "(lengths scaled by 2^%ld): enlarge it%s", kind, (unsigned long)f->detail_prim,
                 size_name, size, what, step, span, (long)s->unit_exp, instead);
}

void precision_status_message(const render_frame_t *f, render_status_t st, char *out, size_t cap)
{
    if (f && st == RENDER_ERR_EXTENT)
        precision_extent_message(f, out, cap);
    else if (f && st == RENDER_ERR_DETAIL)
        precision_detail_message(f, out, cap);
    else
        fmt_snprintf(out, cap, "%s", render_status_name(st));
}
