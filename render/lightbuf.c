/* render/lightbuf.c: the light buffer (render/lightbuf.h). */
#include "render/lightbuf.h"

#include <string.h>

#include "render/vec3.h"

#define LB_N RENDER_LB_CELLS
/* The cells an item's rectangle is widened by on every side: a 32nd of
 * the grid, as wide as one cell of a grid of 32. */
#define LB_MARGIN (LB_N / 32)

size_t render_lightbuf_bytes(const render_frame_t *f)
{
    return sizeof(render_lightbuf_t) + (size_t)f->light_count * sizeof(render_lb_light_t);
}

/* The top of the tree as items: the root, then any cluster item replaced
 * by its own primitives and children while the count stays within
 * RENDER_LB_ITEMS (the last item moves into its place). */
static uint32_t lb_items(const render_frame_t *f, uint32_t *item)
{
    uint32_t n = 1;
    item[0] = RENDER_LB_CLUSTER; /* the root, cluster 0 */
    for (uint32_t i = 0; i < n;) {
        if (!(item[i] & RENDER_LB_CLUSTER)) {
            i++;
            continue;
        }
        const render_cluster_t *c = &f->clusters[item[i] & ~RENDER_LB_CLUSTER];
        if ((uint64_t)n - 1 + c->prim_count + c->child_count > RENDER_LB_ITEMS) {
            i++;
            continue;
        }
        item[i] = item[--n];
        for (uint32_t k = 0; k < c->prim_count; k++)
            item[n++] = f->prim_list[c->first_prim + k];
        for (uint32_t k = 0; k < c->child_count; k++)
            item[n++] = f->child_list[c->first_child + k] | RENDER_LB_CLUSTER;
    }
    return n;
}

static const aabb_t *lb_item_box(const render_frame_t *f, uint32_t item)
{
    if (item & RENDER_LB_CLUSTER)
        return &f->clusters[item & ~RENDER_LB_CLUSTER].bounds;
    return &f->prims[item].bounds;
}

static int lb_box_sat(const aabb_t *b)
{
    return vec3_is_sat(b->lo) || vec3_is_sat(b->hi);
}

static void lb_box_points(const aabb_t *b, vec3_t c[8])
{
    for (int k = 0; k < 8; k++)
        c[k] = vec3_make(k & 1 ? b->hi.x : b->lo.x, k & 2 ? b->hi.y : b->lo.y,
                         k & 4 ? b->hi.z : b->lo.z);
}

/* Eight points whose hull holds an item: a box's or an ellipsoid's local
 * cube mapped back (tighter than its box where it is turned), or its box's
 * corners.  The mapped cube is kept only while its own box reaches that
 * of the item within a sixteenth of the item's size on every side: a
 * map inverted badly falls back to the box. */
static void lb_item_corners(const render_frame_t *f, uint32_t item, vec3_t c[8])
{
    const aabb_t *b = lb_item_box(f, item);
    lb_box_points(b, c);
    const render_prim_t *p = item & RENDER_LB_CLUSTER ? NULL : &f->prims[item];
    xform_t back;
    if (!p || p->imprecise || (p->kind != SCENE_PRIM_BOX && p->kind != SCENE_PRIM_ELLIPSOID) ||
        !xform_invert(&p->to_local, &back))
        return;
    vec3_t m[8], lo, hi;
    for (int k = 0; k < 8; k++) {
        num_t one = NUM_ONE, less = num_neg(NUM_ONE);
        m[k] = xform_point(&back, vec3_make(k & 1 ? one : less, k & 2 ? one : less,
                                            k & 4 ? one : less));
        lo = k ? vec3_min(lo, m[k]) : m[k];
        hi = k ? vec3_max(hi, m[k]) : m[k];
    }
    for (int i = 0; i < 3; i++) {
        num_t slack = num_scale2(num_sub(vec3_get(b->hi, i), vec3_get(b->lo, i)), -4);
        if (num_gt(vec3_get(lo, i), num_add(vec3_get(b->lo, i), slack)) ||
            num_lt(vec3_get(hi, i), num_sub(vec3_get(b->hi, i), slack)) ||
            num_is_sat(slack) || vec3_is_sat(lo) || vec3_is_sat(hi))
            return;
    }
    for (int k = 0; k < 8; k++)
        c[k] = m[k];
}

/* Marks the cells of g that the rectangle r (u0, u1, v0, v1) covers,
 * mu more on each side along u and mv along v: its columns and its rows. */
static void lb_mark(const render_lb_grid_t *g, uint32_t (*cells)[LB_N], const num_t r[4],
                    uint32_t bit, int mu, int mv)
{
    int u0 = render_lb_grid_cell(r[0], g->u0, g->su) - mu;
    int u1 = render_lb_grid_cell(r[1], g->u0, g->su) + mu;
    int v0 = render_lb_grid_cell(r[2], g->v0, g->sv) - mv;
    int v1 = render_lb_grid_cell(r[3], g->v0, g->sv) + mv;
    for (int u = u0 < 0 ? 0 : u0; u <= u1 && u < LB_N; u++)
        cells[0][u] |= bit;
    for (int v = v0 < 0 ? 0 : v0; v <= v1 && v < LB_N; v++)
        cells[1][v] |= bit;
}

/* The range [*lo, *hi] of a / m for a in [a0, a1] and m in [m0, m1]
 * (m1 > 0; only m > 0 is on the face, so with m0 <= 0 the quotient runs
 * off to either infinity whose side a reaches), within [-1, 1]. */
static void lb_quotient_range(num_t a0, num_t a1, num_t m0, num_t m1, num_t *lo, num_t *hi)
{
    num_t one = NUM_ONE, less = num_neg(NUM_ONE);
    if (num_gt(m0, NUM_ZERO)) {
        *lo = num_div(a0, num_ge(a0, NUM_ZERO) ? m1 : m0);
        *hi = num_div(a1, num_ge(a1, NUM_ZERO) ? m0 : m1);
    } else {
        *lo = num_ge(a0, NUM_ZERO) ? num_div(a0, m1) : less;
        *hi = num_gt(a1, NUM_ZERO) ? one : num_div(a1, m1);
    }
    *lo = num_min(num_max(*lo, less), one);
    *hi = num_min(num_max(*hi, less), one);
}

/* Eight points relative to a light, by axis: at[k][i] (lb_face_rect reads
 * them by a face's axes), and each axis's least and greatest of them. */
typedef struct {
    num_t at[8][3];
    num_t lo[3], hi[3];
} lb_rel_t;

static void lb_relative(const vec3_t *c, vec3_t light, lb_rel_t *p)
{
    for (int k = 0; k < 8; k++) {
        vec3_t d = vec3_sub(c[k], light);
        p->at[k][0] = d.x;
        p->at[k][1] = d.y;
        p->at[k][2] = d.z;
    }
    for (int i = 0; i < 3; i++) {
        p->lo[i] = p->hi[i] = p->at[0][i];
        for (int k = 1; k < 8; k++) {
            p->lo[i] = num_min(p->lo[i], p->at[k][i]);
            p->hi[i] = num_max(p->hi[i], p->at[k][i]);
        }
    }
}

/* Where points p show on cube face `face`, as r (u0, u1, v0, v1): by the
 * points themselves when all lie in front of it (the hull's view is
 * theirs), else by their box; 0 when all lie behind. */
static int lb_face_rect(int face, const lb_rel_t *p, num_t r[4])
{
    int m = face / 2, a = (m + 1) % 3, w = (m + 2) % 3, back = face % 2;
    /* The points' least and greatest depth in front of the face: negation
     * reverses the order and keeps ties' first, so these are the very
     * values a loop over the eight depths would keep. */
    num_t near = back ? num_neg(p->hi[m]) : p->lo[m];
    num_t far = back ? num_neg(p->lo[m]) : p->hi[m];
    if (!num_gt(far, NUM_ZERO))
        return 0;
    if (!num_gt(near, NUM_ZERO)) {
        lb_quotient_range(p->lo[a], p->hi[a], near, far, &r[0], &r[1]);
        lb_quotient_range(p->lo[w], p->hi[w], near, far, &r[2], &r[3]);
        return 1;
    }
    num_t one = NUM_ONE, less = num_neg(NUM_ONE);
    for (int k = 0; k < 8; k++) {
        num_t inv = num_recip(back ? num_neg(p->at[k][m]) : p->at[k][m]);
        num_t u = num_mul(p->at[k][a], inv), v = num_mul(p->at[k][w], inv);
        r[0] = k ? num_min(r[0], u) : u;
        r[1] = k ? num_max(r[1], u) : u;
        r[2] = k ? num_min(r[2], v) : v;
        r[3] = k ? num_max(r[3], v) : v;
    }
    for (int i = 0; i < 4; i++)
        r[i] = num_min(num_max(r[i], less), one);
    return 1;
}

/* The projection's rectangle of eight points. */
static void lb_project_points(const render_lb_light_t *l, const vec3_t *c, num_t r[4])
{
    for (int k = 0; k < 8; k++) {
        num_t u, v;
        render_lb_project(l, c[k], &u, &v);
        r[0] = k ? num_min(r[0], u) : u;
        r[1] = k ? num_max(r[1], u) : u;
        r[2] = k ? num_min(r[2], v) : v;
        r[3] = k ? num_max(r[3], v) : v;
    }
}

/* A grid of LB_N x LB_N cells over rectangle r; 0 when r is flat or does
 * not fit the arithmetic. */
static int lb_grid(render_lb_grid_t *g, const num_t r[4])
{
    num_t wu = num_sub(r[1], r[0]), wv = num_sub(r[3], r[2]);
    g->u0 = r[0];
    g->v0 = r[2];
    g->su = g->sv = NUM_ZERO;
    if (!num_gt(wu, NUM_ZERO) || !num_gt(wv, NUM_ZERO) || num_is_sat(wu) || num_is_sat(wv))
        return 0;
    g->su = num_div(num_from_int(LB_N), wu);
    g->sv = num_div(num_from_int(LB_N), wv);
    return !num_is_sat(g->su) && !num_is_sat(g->sv);
}

/* A point or spot light's cube: each face's grid across the root's box as
 * seen there (a face that does not see it keeps an empty grid). */
static int lb_cube_setup(render_lb_light_t *l, const aabb_t *root)
{
    vec3_t c[8];
    lb_rel_t rel;
    lb_box_points(root, c);
    lb_relative(c, l->at, &rel);
    l->faces = 0;
    for (int face = 0; face < 6; face++) {
        num_t r[4];
        render_lb_grid_t *g = &l->grid[face];
        g->u0 = g->v0 = g->su = g->sv = NUM_ZERO;
        if (!lb_face_rect(face, &rel, r))
            continue;
        l->faces |= (uint8_t)(1u << face);
        if (!lb_grid(g, r) && (num_gt(r[0], r[1]) || num_gt(r[2], r[3]) ||
                               num_is_sat(r[0]) || num_is_sat(r[2])))
            return 0;
    }
    return 1;
}

/* The axis d is largest on in magnitude (of equals, the first). */
static int lb_major_axis(vec3_t d)
{
    num_t ax = num_abs(d.x), ay = num_abs(d.y), az = num_abs(d.z);
    return num_ge(ax, ay) && num_ge(ax, az) ? 0 : num_ge(ay, az) ? 1 : 2;
}

/* A parallel light's plane: the major axis of its direction, and a grid
 * across the root's box's projection (0 when that is flat or does not fit
 * the arithmetic). */
static int lb_plane_setup(render_lb_light_t *l, const render_light_t *src, const aabb_t *root)
{
    vec3_t d = src->to_light;
    int m = lb_major_axis(d);
    num_t dm = vec3_get(d, m);
    if (!num_gt(num_abs(dm), NUM_ZERO))
        return 0;
    /* u = p_a - p_m d_a / d_m, v likewise for the third axis */
    int a = (m + 1) % 3, w = (m + 2) % 3;
    l->pu = l->pv = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    vec3_set(&l->pu, a, NUM_ONE);
    vec3_set(&l->pu, m, num_neg(num_div(vec3_get(d, a), dm)));
    vec3_set(&l->pv, w, NUM_ONE);
    vec3_set(&l->pv, m, num_neg(num_div(vec3_get(d, w), dm)));
    vec3_t c[8];
    num_t r[4];
    lb_box_points(root, c);
    lb_project_points(l, c, r);
    return lb_grid(&l->grid[0], r);
}

/* The cells around an item's rectangle along an axis of s cells a unit
 * on a point light's cube that a shadow ray passing offset beside the
 * light may still look it up in, the item lying at least gap from the
 * light: LB_MARGIN (for rounding, and for the primitives' uncertain
 * edges), and more where the ray turns further.  Such a ray turns by at
 * most offset / gap on its way to the item, which moves a face's
 * coordinates by up to twice that: x cells.  Within half LB_MARGIN,
 * LB_MARGIN covers it with half of it to spare; further, LB_MARGIN and one
 * cell more than x; LB_N (the whole axis) when x does not fit. */
static int lb_margin(num_t s, num_t offset, num_t gap)
{
    num_t x = num_div(num_mul_int(num_mul(offset, s), 2), gap);
    if (!num_gt(num_mul_int(x, 2), num_from_int(LB_MARGIN)))
        return LB_MARGIN;
    if (num_is_sat(x) || !num_lt(x, num_from_int(LB_N)))
        return LB_N;
    return LB_MARGIN + 1 + num_floor_nonneg_int(x);
}

/* An item of points c (lb_item_corners) and box b on a point light's cube,
 * with the margin lb_margin gives it on each face.  One that a ray passing
 * offset beside the light may meet turned by an eighth of a radian or
 * more (the light within 8 offsets of its box, or in it) goes in every
 * cell: turned by less, the item lies in front of the face the ray looks
 * it up on, whose cells across it hold the item's rectangle and margin. */
static void lb_mark_cube(render_lb_light_t *l, const aabb_t *b, const vec3_t *c, num_t offset,
                         uint32_t bit)
{
    num_t gap = NUM_ZERO; /* along the axis where the box lies furthest off */
    for (int i = 0; i < 3; i++) {
        num_t lo = num_sub(vec3_get(b->lo, i), vec3_get(l->at, i));
        num_t hi = num_sub(vec3_get(b->hi, i), vec3_get(l->at, i));
        gap = num_max(gap, num_max(lo, num_neg(hi)));
    }
    if (!num_gt(gap, num_mul_int(offset, 8)) || num_is_sat(gap)) {
        l->always |= bit;
        return;
    }
    lb_rel_t rel;
    lb_relative(c, l->at, &rel);
    for (int face = 0; face < 6; face++) {
        num_t r[4];
        const render_lb_grid_t *g = &l->grid[face];
        if ((l->faces >> face & 1) && lb_face_rect(face, &rel, r))
            lb_mark(g, l->mask[face], r, bit, lb_margin(g->su, offset, gap),
                    lb_margin(g->sv, offset, gap));
    }
}

/* How far a shadow ray may pass beside its light: its origin is moved off
 * the hit by ray_epsilon, and its direction and length are rounded (a few
 * steps of the arithmetic at 1 times the scene's extent, and at it). */
static num_t lb_offset(const render_frame_t *f, const aabb_t *root)
{
    num_t extent = NUM_ZERO;
    for (int i = 0; i < 3; i++)
        extent = num_max(extent, num_max(num_abs(vec3_get(root->lo, i)),
                                         num_abs(vec3_get(root->hi, i))));
    for (uint16_t i = 0; i < f->light_count; i++)
        for (int k = 0; k < 3; k++)
            extent = num_max(extent, num_abs(vec3_get(f->lights[i].position, k)));
    num_t round = num_add(num_mul(num_mul_int(extent, 8), num_ulp(NUM_ONE)),
                          num_mul_int(num_ulp(extent), 16));
    return num_add(num_mul_int(f->ray_epsilon, 2), round);
}

static void lb_mark_plane(render_lb_light_t *l, const vec3_t *c, uint32_t bit)
{
    num_t r[4];
    lb_project_points(l, c, r);
    lb_mark(&l->grid[0], l->mask[0], r, bit, LB_MARGIN, LB_MARGIN);
}

/* Light i's kind and grid, its cells empty. */
static void lb_setup_light(const render_frame_t *f, uint32_t i, render_lb_light_t *l)
{
    const render_light_t *src = &f->lights[i];
    const aabb_t *root = &f->clusters[0].bounds;
    l->always = 0;
    memset(l->mask, 0, sizeof l->mask);
    l->at = src->position;
    l->kind = RENDER_LB_ALL;
    if (src->kind == SCENE_LIGHT_PARALLEL && lb_plane_setup(l, src, root))
        l->kind = RENDER_LB_PLANE;
    else if (src->kind != SCENE_LIGHT_PARALLEL && !vec3_is_sat(l->at) && lb_cube_setup(l, root))
        l->kind = RENDER_LB_CUBE;
}

/* The face of item's local cube that light l (src) lies beyond
 * (render_lb_light_t.face): the axis its local position (direction, for a
 * parallel light) is largest on, beyond 1 (0); 0 for an item that is not
 * a box, or is imprecise.  (An ellipsoid's would do, but its own test
 * costs about as little: measured on demo, its faces cost more than they
 * saved.) */
static uint8_t lb_item_face(const render_frame_t *f, uint32_t item, const render_lb_light_t *l,
                            const render_light_t *src)
{
    if (item & RENDER_LB_CLUSTER || l->kind == RENDER_LB_ALL)
        return 0;
    const render_prim_t *p = &f->prims[item];
    if (p->imprecise || p->kind != SCENE_PRIM_BOX)
        return 0;
    int cube = l->kind == RENDER_LB_CUBE;
    vec3_t q = cube ? xform_point(&p->to_local, l->at) : xform_dir(&p->to_local, src->to_light);
    if (vec3_is_sat(q))
        return 0;
    int axis = lb_major_axis(q);
    num_t v = vec3_get(q, axis);
    if (!num_gt(num_abs(v), cube ? NUM_ONE : NUM_ZERO))
        return 0;
    return (uint8_t)(1 + 2 * axis + num_lt(v, NUM_ZERO));
}

/* Item k (bit) in the cells of every light; offset: lb_offset's. */
static void lb_place_item(const render_frame_t *f, render_lightbuf_t *lb, uint32_t k,
                          num_t offset)
{
    uint32_t bit = UINT32_C(1) << k;
    const aabb_t *b = lb_item_box(f, lb->item[k]);
    if (num_gt(b->lo.x, b->hi.x) || num_gt(b->lo.y, b->hi.y) || num_gt(b->lo.z, b->hi.z))
        return; /* empty: no ray meets it */
    vec3_t c[8];
    int corners = 0; /* c worked out, once for every light */
    for (uint32_t i = 0; i < lb->light_count; i++) {
        render_lb_light_t *l = &lb->light[i];
        l->face[k] = lb_item_face(f, lb->item[k], l, &f->lights[i]);
        if (l->kind == RENDER_LB_ALL || lb_box_sat(b) || num_is_sat(offset)) {
            l->always |= bit;
            continue;
        }
        if (!corners)
            lb_item_corners(f, lb->item[k], c);
        corners = 1;
        if (l->kind == RENDER_LB_CUBE)
            lb_mark_cube(l, b, c, offset, bit);
        else
            lb_mark_plane(l, c, bit);
    }
}

const render_lightbuf_t *render_lightbuf_build(const render_frame_t *f, void *mem, size_t bytes)
{
    if (!mem || bytes < render_lightbuf_bytes(f) || f->cluster_count == 0)
        return NULL;
    render_lightbuf_t *lb = mem;
    lb->item_count = lb_items(f, lb->item);
    lb->light_count = f->light_count;
    num_t offset = lb_offset(f, &f->clusters[0].bounds);
    for (uint32_t i = 0; i < lb->light_count; i++)
        lb_setup_light(f, i, &lb->light[i]);
    for (uint32_t k = 0; k < lb->item_count; k++)
        lb_place_item(f, lb, k, offset);
    return lb;
}
