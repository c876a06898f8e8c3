/* render/prepare.c: the DM's preprocessing (paper, section 4).
 *
 * For one frame: evaluate each cluster's keys, compose transforms down the
 * tree, map every primitive and light to eye coordinates, compute each
 * cluster's bounding box and screen rectangle.  Inverse maps are composed
 * from the inverses of each level (rather than inverting the composed map)
 * to keep precision.  What does not change from frame to frame (children
 * and primitives grouped by cluster, which clusters have maps of their
 * own, a cluster's maps to its parent and back where it has no keys (its
 * local map's inverse where it has), which vertex normals are equal, the
 * static checks) is the scene index's, worked out once a load
 * (render_scene_index).
 * With options.world_space the primitives stay in world coordinates and
 * the camera turns the rays instead.  A frame prepared over the frame
 * before in the same block (render_prepare_again) keeps what that one
 * prepared where no keyed map changed (in eye space, when the camera is
 * the same) and prepares again only the clusters that moved.
 */
#include <string.h>

#include "proto/scene_format.h"
#include "render/precision.h"
#include "render/prim_cone.h"
#include "render/prim.h"
#include "render/vec3.h"

#define PREP_PIXEL_LIMIT num_from_int(2 * RENDER_MAX_WIDTH) /* beyond any screen */

const char *render_status_name(render_status_t status)
{
    switch (status) {
    case RENDER_OK: return "ok";
    case RENDER_ERR_ARENA: return "render arena too small for the frame";
    case RENDER_ERR_SIZE: return "image size outside 1..RENDER_MAX_WIDTH x 1..RENDER_MAX_HEIGHT";
    case RENDER_ERR_LIGHTS: return "more lights than RENDER_MAX_LIGHTS";
    case RENDER_ERR_DEPTH: return "max_depth above RENDER_MAX_DEPTH";
    case RENDER_ERR_CLUSTER: return "bad cluster parent, or nesting deeper than RENDER_MAX_CLUSTER_DEPTH";
    case RENDER_ERR_PRIM: return "primitive with a bad kind, cluster or material index";
    case RENDER_ERR_DENSITY: return "density sphere: components out of range or above RENDER_MAX_DENSITY_COMPONENTS, threshold <= 0, or density_steps outside SCN_MIN_DENSITY_STEPS..SCN_MAX_DENSITY_STEPS";
    case RENDER_ERR_MAP: return "material map index, kind or size invalid (RENDER_MAX_MAP_SIZE), or both a bump and a normal map";
    case RENDER_ERR_KEY: return "cluster keys outside the scene's key array";
    case RENDER_ERR_CAMERA: return "camera eye equals look_at, or up is parallel to the view";
    case RENDER_ERR_SINGULAR: return "a cluster transform cannot be inverted";
    case RENDER_ERR_RELOCATE: return "a pointer of the blob lies outside it (not self-contained), or a bad base";
    case RENDER_ERR_AREA: return "area empty or not inside the screen";
    case RENDER_ERR_EXTENT: return "the scene spans less than RENDER_MIN_SPAN_VALUE (500 ray offsets; both follow the geometry's largest length): it lies far from the origin for its size";
    case RENDER_ERR_DETAIL: return "a primitive smaller than RENDER_MIN_DETAIL_STEPS (2) steps of the arithmetic where it lies: its shape would be off by more than a quarter; enlarge it or use another arithmetic";
    case RENDER_ERR_SCALE: return "a cluster transform scales beyond what the arithmetic can invert (it is not exactly singular: scale the scene instead of the cluster, or use another arithmetic)";
    }
    return "unknown render status";
}

static inline aabb_t prep_aabb_empty(void)
{
    aabb_t b;
    b.lo = vec3_make(NUM_ONE, NUM_ONE, NUM_ONE);
    b.hi = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    return b;
}

static int prep_aabb_is_empty(const aabb_t *b) { return num_gt(b->lo.x, b->hi.x); }

/* A coordinate of b saturated: vec3_is_sat of either corner.  In the
 * IEEE builds a - a is 0 for a finite a and NaN otherwise, and a sum of
 * them 0 unless one is NaN: one test, not six (every primitive of every
 * frame). */
static inline int prep_aabb_is_sat(const aabb_t *b)
{
#if defined(LINKS1_NUM_FIXED)
    return vec3_is_sat(b->lo) || vec3_is_sat(b->hi);
#else
    num_t z = num_add(num_add(num_sub(b->lo.x, b->lo.x), num_sub(b->lo.y, b->lo.y)),
                      num_sub(b->lo.z, b->lo.z));
    z = num_add(num_add(num_add(z, num_sub(b->hi.x, b->hi.x)), num_sub(b->hi.y, b->hi.y)),
                num_sub(b->hi.z, b->hi.z));
    return num_is_sat(z);
#endif
}

/* b grown to hold o, both not empty */
static inline void prep_aabb_grow(aabb_t *b, const aabb_t *o)
{
    b->lo = vec3_min(b->lo, o->lo);
    b->hi = vec3_max(b->hi, o->hi);
}

/* inline: the DM grows boxes four times a triangle, every frame */
static inline void prep_aabb_add_box(aabb_t *b, const aabb_t *o)
{
    if (prep_aabb_is_empty(o))
        return;
    if (prep_aabb_is_empty(b)) {
        *b = *o;
        return;
    }
    prep_aabb_grow(b, o);
}

/* Box of centre c with half extents e, grown by the pad
 * (RENDER_BOUNDS_PAD_VALUE scaled to the scene). */
static aabb_t prep_aabb_around(vec3_t c, vec3_t e, num_t pad)
{
    e = vec3_add(e, vec3_make(pad, pad, pad));
    aabb_t b = {vec3_sub(c, e), vec3_add(c, e)};
    return b;
}

/* Half extents of the image of the unit sphere (round=1) or the cube
 * [-1,1]^3 (round=0) under the 3x3 matrix m. */
static vec3_t prep_extent(const num_t m[3][3], int round)
{
    num_t e[3];
    for (int i = 0; i < 3; i++)
        e[i] = round ? num_len3(m[i][0], m[i][1], m[i][2])
                     : num_add(num_add(num_abs(m[i][0]), num_abs(m[i][1])), num_abs(m[i][2]));
    return vec3_make(e[0], e[1], e[2]);
}

/* Rows of the 3x3 part of to_eye, columns scaled by s. */
static void prep_scaled_linear(const xform_t *to_eye, vec3_t s, num_t out[3][3])
{
    for (int i = 0; i < 3; i++) {
        out[i][0] = num_mul(to_eye->m[i][0], s.x);
        out[i][1] = num_mul(to_eye->m[i][1], s.y);
        out[i][2] = num_mul(to_eye->m[i][2], s.z);
    }
}

/* The two keys frame f lies between and its weight w from the first to
 * the second, the one rule of every key (a cluster's, the camera's, a
 * light's): keys[0..n) of stride bytes each, frames rising, each key's
 * frame its first field; *ia = *ib = the end key outside them (w = 0). */
static num_t prep_key_span(const void *keys, size_t stride, uint32_t n, uint32_t f,
                           uint32_t *ia, uint32_t *ib)
{
#define PREP_KEY_FRAME(i) (*(const uint32_t *)((const uint8_t *)keys + (size_t)(i) * stride))
    *ia = *ib = 0;
    if (f >= PREP_KEY_FRAME(n - 1)) {
        *ia = *ib = n - 1;
    } else if (f > PREP_KEY_FRAME(0)) {
        uint32_t i = 0;
        while (i + 1 < n && PREP_KEY_FRAME(i + 1) <= f)
            i++;
        *ia = i;
        *ib = i + 1;
        return num_from_ratio((int32_t)(f - PREP_KEY_FRAME(i)),
                              (int32_t)(PREP_KEY_FRAME(i + 1) - PREP_KEY_FRAME(i)));
    }
    return NUM_ZERO;
#undef PREP_KEY_FRAME
}

/* a + (b - a) w, per component: the interpolation of every key's values */
static vec3_t prep_lerp3(vec3_t a, vec3_t b, num_t w)
{
    return vec3_add(a, vec3_scale(vec3_sub(b, a), w));
}

/* Keyframed TRS of a cluster at frame f (identity without keys). */
static xform_t prep_key_xform(const scene_t *s, const scene_cluster_t *c, uint32_t f)
{
    if (c->key_count == 0)
        return xform_identity();
    const scene_key_t *k = &s->keys[c->first_key];
    uint32_t ia, ib;
    num_t w = prep_key_span(k, sizeof *k, c->key_count, f, &ia, &ib);
    const scene_key_t *a = &k[ia], *b = &k[ib];
    vec3_t t = prep_lerp3(a->translate, b->translate, w);
    vec3_t sc = prep_lerp3(a->scale, b->scale, w);
    /* nlerp along the shorter arc */
    num_t bw = b->rot_w, bx = b->rot_x, by = b->rot_y, bz = b->rot_z;
    num_t dot = num_add(num_dot3(a->rot_x, a->rot_y, a->rot_z, bx, by, bz), num_mul(a->rot_w, bw));
    if (num_lt(dot, NUM_ZERO)) {
        bw = num_neg(bw);
        bx = num_neg(bx);
        by = num_neg(by);
        bz = num_neg(bz);
    }
    num_t qw = num_lerp(a->rot_w, bw, w), qx = num_lerp(a->rot_x, bx, w);
    num_t qy = num_lerp(a->rot_y, by, w), qz = num_lerp(a->rot_z, bz, w);
    num_t len = num_sqrt(num_add(num_dot3(qx, qy, qz, qx, qy, qz), num_mul(qw, qw)));
    if (num_gt(len, NUM_ZERO)) {
        qw = num_div(qw, len);
        qx = num_div(qx, len);
        qy = num_div(qy, len);
        qz = num_div(qz, len);
    }
    return xform_from_trs(t, qw, qx, qy, qz, sc);
}

/* 1 when every keyed cluster's map is the same, bit for bit, at frames a
 * and b (a world-space frame keeps its world part then). */
static int prep_keys_same(const scene_t *s, uint32_t a, uint32_t b)
{
    if (a == b)
        return 1;
    /* the index's range of keyed clusters, when the scene has its index */
    uint32_t lo = 0, hi = s->cluster_count;
    if (s->index.groups) {
        lo = s->index.keyed_lo;
        hi = s->index.keyed_hi < hi ? s->index.keyed_hi : hi;
    }
    for (uint32_t i = lo; i < hi; i++) {
        const scene_cluster_t *c = &s->clusters[i];
        if (c->key_count == 0)
            continue;
        xform_t ka = prep_key_xform(s, c, a), kb = prep_key_xform(s, c, b);
        if (memcmp(&ka, &kb, sizeof ka) != 0)
            return 0;
    }
    return 1;
}

int render_world_same(const scene_t *s, const render_frame_t *a, const render_frame_t *b)
{
    return a->world && b->world && a->world_lost == b->world_lost &&
           !memcmp(&a->precision_extent, &b->precision_extent, sizeof(num_t)) &&
           prep_keys_same(s, a->frame_index, b->frame_index);
}

/* The camera and the lights at frame f: each target with keys
 * (scene_view_key_t) interpolated between the two keys f lies between,
 * the others as the scene gives them.  Keys are grouped by target (the
 * loader checks it), so one pass finds every target's. */
static void prep_view_at(const scene_t *s, uint32_t f, scene_camera_t *camera,
                         scene_light_t *lights)
{
    *camera = s->camera;
    for (uint16_t i = 0; i < s->light_count; i++)
        lights[i] = s->lights[i];
    const scene_view_key_t *k = s->view_keys;
    for (uint32_t first = 0, end; first < s->view_key_count; first = end) {
        uint16_t target = k[first].target;
        for (end = first + 1; end < s->view_key_count && k[end].target == target;)
            end++;
        uint32_t ia, ib;
        num_t w = prep_key_span(&k[first], sizeof *k, end - first, f, &ia, &ib);
        const scene_view_key_t *a = &k[first + ia], *b = &k[first + ib];
        if (target == SCENE_VIEW_KEY_CAMERA) {
            camera->eye = prep_lerp3(a->v.camera.eye, b->v.camera.eye, w);
            camera->look_at = prep_lerp3(a->v.camera.look_at, b->v.camera.look_at, w);
            camera->up = prep_lerp3(a->v.camera.up, b->v.camera.up, w);
            camera->tan_half_fov_y = num_lerp(a->v.camera.tan_half_fov_y,
                                              b->v.camera.tan_half_fov_y, w);
        } else if (target < s->light_count) {
            const scene_light_t *la = &a->v.light, *lb = &b->v.light;
            scene_light_t *l = &lights[target];
            l->intensity.r = num_lerp(la->intensity.r, lb->intensity.r, w);
            l->intensity.g = num_lerp(la->intensity.g, lb->intensity.g, w);
            l->intensity.b = num_lerp(la->intensity.b, lb->intensity.b, w);
            l->position = prep_lerp3(la->position, lb->position, w);
            l->direction = prep_lerp3(la->direction, lb->direction, w);
            l->cos_inner = num_lerp(la->cos_inner, lb->cos_inner, w);
            l->cos_outer = num_lerp(la->cos_outer, lb->cos_outer, w);
        }
    }
}

/* World -> eye and its inverse from the camera. */
static render_status_t prep_camera(const scene_camera_t *c, xform_t *world_to_eye,
                                   xform_t *eye_to_world)
{
    vec3_t f = vec3_normalize(vec3_sub(c->look_at, c->eye));
    if (!num_gt(vec3_length(f), NUM_HALF))
        return RENDER_ERR_CAMERA;
    vec3_t r = vec3_normalize(vec3_cross(c->up, f)); /* left-handed: x right */
    if (!num_gt(vec3_length(r), NUM_HALF))
        return RENDER_ERR_CAMERA;
    vec3_t u = vec3_cross(f, r);
    vec3_t rows[3] = {r, u, f};
    for (int i = 0; i < 3; i++) {
        world_to_eye->m[i][0] = rows[i].x;
        world_to_eye->m[i][1] = rows[i].y;
        world_to_eye->m[i][2] = rows[i].z;
        world_to_eye->m[i][3] = num_neg(vec3_dot(rows[i], c->eye));
        eye_to_world->m[0][i] = rows[i].x;
        eye_to_world->m[1][i] = rows[i].y;
        eye_to_world->m[2][i] = rows[i].z;
    }
    eye_to_world->m[0][3] = c->eye.x;
    eye_to_world->m[1][3] = c->eye.y;
    eye_to_world->m[2][3] = c->eye.z;
    return RENDER_OK;
}

/* The identity map, compared word by word below. */
static const xform_t prep_identity = {{{NUM_ONE, NUM_ZERO, NUM_ZERO, NUM_ZERO},
                                       {NUM_ZERO, NUM_ONE, NUM_ZERO, NUM_ZERO},
                                       {NUM_ZERO, NUM_ZERO, NUM_ONE, NUM_ZERO}}};

/* No keys and the identity matrix: the cluster only groups.  Asked of
 * every cluster every frame: the identity's exact bits answer at integer
 * compares; a matrix with other bits still may be the identity (-0 for 0)
 * and is compared as numbers. */
static int prep_is_plain(const scene_cluster_t *c)
{
    if (c->key_count != 0)
        return 0;
    const uint8_t *a = (const uint8_t *)&c->local, *id = (const uint8_t *)&prep_identity;
    size_t at = 0;
#pragma GCC unroll 24 /* every word against an immediate: no loop, no loads of the identity */
    for (; at < sizeof prep_identity; at += sizeof(uint32_t)) {
        uint32_t wa, wi;
        __builtin_memcpy(&wa, a + at, sizeof wa);
        __builtin_memcpy(&wi, id + at, sizeof wi);
        if (wa != wi)
            break;
    }
    if (at == sizeof prep_identity)
        return 1;
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 4; k++)
            if (!num_eq(c->local.m[r][k], r == k ? NUM_ONE : NUM_ZERO))
                return 0;
    return 1;
}

/* What render_prepare checks every frame; the clusters and primitives,
 * which do not change from frame to frame, render_scene_index checks once
 * as it builds the index. */
static render_status_t prep_check(const scene_t *s)
{
    if (s->width < 1 || s->width > RENDER_MAX_WIDTH || s->height < 1 || s->height > RENDER_MAX_HEIGHT)
        return RENDER_ERR_SIZE;
    if (s->light_count > RENDER_MAX_LIGHTS)
        return RENDER_ERR_LIGHTS;
    if (s->options.max_depth > RENDER_MAX_DEPTH)
        return RENDER_ERR_DEPTH;
    if (s->options.density_steps < SCN_MIN_DENSITY_STEPS ||
        s->options.density_steps > SCN_MAX_DENSITY_STEPS)
        return RENDER_ERR_DENSITY;
    if (s->cluster_count < 1 || s->clusters[0].parent != SCENE_NO_CLUSTER)
        return RENDER_ERR_CLUSTER;
    for (uint32_t i = 0; i < s->material_count; i++) {
        const scene_material_t *m = &s->materials[i];
        uint16_t maps[7] = {m->colour_map, m->bump_map, m->normal_map, m->dic_map,
                            m->drc_map,    m->src_map,  m->trc_map};
        static const uint8_t kinds[7] = {SCENE_MAP_COLOUR,    SCENE_MAP_BUMP,      SCENE_MAP_NORMAL,
                                         SCENE_MAP_ATTRIBUTE, SCENE_MAP_ATTRIBUTE, SCENE_MAP_ATTRIBUTE,
                                         SCENE_MAP_ATTRIBUTE};
        if (m->bump_map != SCENE_NONE && m->normal_map != SCENE_NONE)
            return RENDER_ERR_MAP;
        for (int k = 0; k < 7; k++) {
            if (maps[k] == SCENE_NONE)
                continue;
            if (maps[k] >= s->map_count)
                return RENDER_ERR_MAP;
            const scene_map_t *map = &s->maps[maps[k]];
            if (map->kind != kinds[k] || !map->texels || map->width < 1 ||
                map->width > RENDER_MAX_MAP_SIZE || map->height < 1 ||
                map->height > RENDER_MAX_MAP_SIZE)
                return RENDER_ERR_MAP;
        }
    }
    return RENDER_OK;
}

/* Primitive p as render_prepare needs it: RENDER_OK, RENDER_ERR_PRIM or
 * RENDER_ERR_DENSITY (render_scene_index checks each one once, as it
 * counts the primitives of each cluster). */
static inline __attribute__((always_inline)) render_status_t prep_prim_check(const scene_t *s,
                                                                            const scene_prim_t *p)
{
    if (p->kind > SCENE_PRIM_CONE || p->cluster >= s->cluster_count ||
        p->material >= s->material_count)
        return RENDER_ERR_PRIM;
    if (p->kind == SCENE_PRIM_DENSITY &&
        (p->shape.density.count < 1 || p->shape.density.count > RENDER_MAX_DENSITY_COMPONENTS ||
         !num_gt(p->shape.density.threshold, NUM_ZERO) || /* the root finder needs > 0 */
         (uint64_t)p->shape.density.first + p->shape.density.count > s->density_component_count))
        return RENDER_ERR_DENSITY;
    if (p->kind == SCENE_PRIM_TRIANGLE && p->shape.triangle.smooth > s->normals_count)
        return RENDER_ERR_PRIM;
    return RENDER_OK;
}

/* A cone's eye-space form: its local map, slope and caps, and the box of
 * its two end discs (which holds their convex hull, the cone): a disc of
 * radius r across unit u, w has the half extent r sqrt(Tu_i^2 + Tw_i^2) on
 * eye axis i, T to_eye's linear part.  A cone whose frame saturates gets
 * a saturated box (the frame's precision flag). */
static void prep_cone(const scene_prim_t *sp, const xform_t *to_eye, const xform_t *from_eye,
                      num_t pad, render_prim_t *p)
{
    prim_cone_frame_t f;
    if (!prim_cone_frame(sp, &f)) {
        num_t sat = num_div(NUM_ONE, NUM_ZERO); /* a saturated value */
        p->bounds.lo = p->bounds.hi = vec3_make(sat, sat, sat);
        return;
    }
    xform_t shape = prim_cone_shape(&f);
    p->to_local = xform_compose(&shape, from_eye);
    p->cone_slope = f.slope;
    p->cone_capped = sp->shape.cone.capped;
    vec3_t tu = xform_dir(to_eye, f.u), tw = xform_dir(to_eye, f.w);
    num_t tu3[3] = {tu.x, tu.y, tu.z}, tw3[3] = {tw.x, tw.y, tw.z}, e[3];
    for (int i = 0; i < 3; i++)
        e[i] = num_len3(tu3[i], tw3[i], NUM_ZERO);
    vec3_t across = vec3_make(e[0], e[1], e[2]);
    num_t small = num_mul(f.radius, num_sub(NUM_ONE, num_mul_int(f.slope, 2)));
    vec3_t big_end = vec3_madd(f.centre, f.axis, num_neg(f.half));
    vec3_t small_end = vec3_madd(f.centre, f.axis, f.half);
    p->bounds = prep_aabb_around(xform_point(to_eye, big_end), vec3_scale(across, f.radius), pad);
    aabb_t b = prep_aabb_around(xform_point(to_eye, small_end), vec3_scale(across, small), pad);
    prep_aabb_grow(&p->bounds, &b);
}

/* Eye-space form of one primitive; to_eye/from_eye map its cluster; pad
 * grows its box (RENDER_BOUNDS_PAD_VALUE scaled to the scene: the caller
 * scales it once a frame, not once a primitive). */
static inline __attribute__((always_inline)) void prep_prim(const scene_prim_t *sp, uint32_t index, const render_frame_t *f, const xform_t *to_eye,
                      const xform_t *from_eye, num_t pad, const scene_index_t *ix,
                      scene_normals_t *normals, render_prim_t *p)
{
    num_t lin[3][3];
    p->kind = sp->kind;
    p->smooth = 0; /* flat, unless a smooth triangle below */
    p->material = sp->material;
    p->index = index;
    switch (sp->kind) {
    case SCENE_PRIM_TRIANGLE: {
        /* the three vertices before any store to p, which could alias the
         * map: it is loaded once, not once a vertex */
        vec3_t v[3];
        for (int k = 0; k < 3; k++)
            v[k] = xform_point_inline(to_eye, sp->shape.triangle.v[k]);
        for (int k = 0; k < 3; k++) {
            p->tex_u[k] = sp->shape.triangle.tex_u[k];
            p->tex_v[k] = sp->shape.triangle.tex_v[k];
        }
        /* The vertices' box grown by the pad once (the DM bounds every
         * triangle of every frame): rounding is monotone, so min(v) - pad
         * is the least of the three v - pad, bit for bit. */
        vec3_t lo = v[0], hi = v[0];
        for (int k = 1; k < 3; k++) {
            lo = vec3_min(lo, v[k]);
            hi = vec3_max(hi, v[k]);
        }
        aabb_t b = {vec3_sub(lo, vec3_make(pad, pad, pad)), vec3_add(hi, vec3_make(pad, pad, pad))};
        p->v0 = v[0];
        p->e1 = vec3_sub(v[1], v[0]);
        p->e2 = vec3_sub(v[2], v[0]);
        p->normal = vec3_normalize(vec3_cross(vec3_normalize(p->e1), vec3_normalize(p->e2)));
        /* smooth: the vertex normals by the inverse transpose of to_eye,
         * each distinct one (bits and maps) once: a vertex normal met
         * before, in an earlier primitive, is copied (normal_src) from the
         * scratch array normals, by the scene's normals index */
        if (sp->shape.triangle.smooth) {
            uint32_t j = sp->shape.triangle.smooth - 1;
            for (uint32_t k = 0; k < 3; k++) {
                uint32_t src = ix->normal_src[3 * j + k];
                normals[j].n[k] =
                    src == (j << 2 | k)
                        ? vec3_normalize(xform_dir_transposed(from_eye, f->scene->normals[j].n[k]))
                        : normals[src >> 2].n[src & 3];
            }
            for (int k = 0; k < 3; k++) /* a vector at a time: the wide copy's
                                           whole struct copy is the C
                                           library's, a byte at a time */
                p->normals.n[k] = normals[j].n[k];
            p->smooth = 1;
        }
        p->edge_n1 = vec3_normalize(vec3_cross(p->e2, p->normal));
        p->edge_n2 = vec3_normalize(vec3_cross(p->normal, p->e1));
        p->height1 = vec3_dot(p->e1, p->edge_n1);
        p->height2 = vec3_dot(p->e2, p->edge_n2);
        p->bounds = b;
        break;
    }
    case SCENE_PRIM_ELLIPSOID:
    case SCENE_PRIM_BOX: {
        int round = sp->kind == SCENE_PRIM_ELLIPSOID;
        vec3_t c, r;
        scene_prim_centre_axes(sp, &c, &r);
        /* local = diag(1/r) * (cluster point - c) */
        xform_t shape = xform_identity();
        num_t rr[3] = {r.x, r.y, r.z}, cc[3] = {c.x, c.y, c.z};
        for (int i = 0; i < 3; i++) {
            shape.m[i][i] = num_recip(rr[i]);
            shape.m[i][3] = num_neg(num_div(cc[i], rr[i]));
        }
        p->to_local = xform_compose(&shape, from_eye);
        prep_scaled_linear(to_eye, r, lin);
        p->bounds = prep_aabb_around(xform_point(to_eye, c), prep_extent(lin, round), pad);
        break;
    }
    case SCENE_PRIM_CONE:
        prep_cone(sp, to_eye, from_eye, pad, p);
        break;
    default: { /* SCENE_PRIM_DENSITY */
        p->to_local = *from_eye;
        p->components = &f->scene->density_components[sp->shape.density.first];
        p->inv_radius2 = &f->density_inv_radius2[sp->shape.density.first];
        p->component_count = sp->shape.density.count;
        p->density_steps = f->scene->options.density_steps;
        p->threshold = sp->shape.density.threshold;
        aabb_t b = prep_aabb_empty();
        for (uint16_t k = 0; k < p->component_count; k++) {
            num_t d = p->components[k].radius;
            prep_scaled_linear(to_eye, vec3_make(d, d, d), lin);
            aabb_t one = prep_aabb_around(xform_point(to_eye, p->components[k].centre), prep_extent(lin, 1), pad);
            prep_aabb_add_box(&b, &one);
        }
        p->bounds = b;
        break;
    }
    }
}

static num_t prep_project(num_t v, num_t z, num_t half, uint16_t size)
{
    /* pixel coordinate whose centre the eye ray through (v/z) passes:
     * ((v/z)/half + 1) * size/2 - 1/2 */
    num_t s = num_div(num_div(v, z), half);
    return num_sub(num_mul(num_add(s, NUM_ONE), num_mul_int(NUM_HALF, size)), NUM_HALF);
}

/* A corner's column (x = 1) or row (x = 0) on the screen, clamped to
 * PREP_PIXEL_LIMIT; *sat set when the projection saturates. */
static inline num_t prep_corner(const render_frame_t *f, num_t v, num_t z, int x, int *sat)
{
    num_t p = x ? prep_project(v, z, f->screen_half_w, f->width)
                /* image rows grow downwards while eye y grows upwards */
                : num_sub(num_from_int(f->height - 1), prep_project(v, z, f->screen_half_h, f->height));
    if (num_is_sat(p))
        *sat = 1;
    /* A corner far off the screen (a huge eye-space box): clamped to the
     * screen below either way, and too large for an int as it is. */
    return num_min(num_max(p, num_neg(PREP_PIXEL_LIMIT)), PREP_PIXEL_LIMIT);
}

/* The least and the largest column and row of the box's corners (its
 * lo.z at least the near plane); 0 when one saturates (the cluster then
 * covers the whole screen).  A column depends on a corner's x and z only,
 * a row on its y and z.  Each step of a projection (v / z, / half, + 1,
 * * size / 2, - 1/2, the clamps) is monotone, so of a finite box with
 * lo <= hi and positive halves the least column is lo.x's at the z where
 * lo.x / z is least (hi.z when lo.x >= 0, lo.z when below) and the
 * largest hi.x's at the z where hi.x / z is largest: four projections
 * give the values the four (x, z) pairs' eight would (the DM projects
 * every cluster of every frame), and they meet integers only through
 * num_floor_int.  Any other box takes all eight. */
static inline __attribute__((always_inline)) int prep_screen_extremes(const render_frame_t *f,
                                                                     const aabb_t *b, num_t *x0,
                                                                     num_t *x1, num_t *y0,
                                                                     num_t *y1)
{
    int sat = 0;
    if (!num_is_sat(b->lo.x) && !num_is_sat(b->hi.x) && !num_is_sat(b->lo.y) &&
        !num_is_sat(b->hi.y) && !num_is_sat(b->lo.z) && !num_is_sat(b->hi.z) &&
        !num_gt(b->lo.x, b->hi.x) && !num_gt(b->lo.y, b->hi.y) && !num_gt(b->lo.z, b->hi.z) && num_gt(b->lo.z, NUM_ZERO) &&
        num_gt(f->screen_half_w, NUM_ZERO) && num_gt(f->screen_half_h, NUM_ZERO)) {
        *x0 = prep_corner(f, b->lo.x, num_lt(b->lo.x, NUM_ZERO) ? b->lo.z : b->hi.z, 1, &sat);
        *x1 = prep_corner(f, b->hi.x, num_gt(b->hi.x, NUM_ZERO) ? b->lo.z : b->hi.z, 1, &sat);
        /* rows fall as y rises: the least row is hi.y's */
        *y0 = prep_corner(f, b->hi.y, num_gt(b->hi.y, NUM_ZERO) ? b->lo.z : b->hi.z, 0, &sat);
        *y1 = prep_corner(f, b->lo.y, num_lt(b->lo.y, NUM_ZERO) ? b->lo.z : b->hi.z, 0, &sat);
        return !sat;
    }
    for (int k = 0; k < 4; k++) {
        num_t x = (k & 1) ? b->hi.x : b->lo.x;
        num_t y = (k & 1) ? b->hi.y : b->lo.y;
        num_t z = (k & 2) ? b->hi.z : b->lo.z;
        num_t px = prep_corner(f, x, z, 1, &sat);
        num_t py = prep_corner(f, y, z, 0, &sat);
        if (sat)
            return 0;
        *x0 = k ? num_min(*x0, px) : px;
        *x1 = k ? num_max(*x1, px) : px;
        *y0 = k ? num_min(*y0, py) : py;
        *y1 = k ? num_max(*y1, py) : py;
    }
    return 1;
}

static inline __attribute__((always_inline)) void prep_screen_rect(const render_frame_t *f,
                                                                  render_cluster_t *c)
{
    const aabb_t *b = &c->own_bounds;
    if (prep_aabb_is_empty(b)) {
        c->screen_x0 = c->screen_y0 = 1;
        c->screen_x1 = c->screen_y1 = 0;
        return;
    }
    c->screen_x0 = 0;
    c->screen_y0 = 0;
    c->screen_x1 = f->width - 1;
    c->screen_y1 = f->height - 1;
    if (num_lt(b->hi.z, NUM_ZERO)) { /* wholly behind the eye: primary rays
                                        (z grows along them) never reach it */
        c->screen_x0 = c->screen_y0 = 1;
        c->screen_x1 = c->screen_y1 = 0;
        return;
    }
    if (num_lt(b->lo.z, scene_tolerance(f->scene, NUM_C(RENDER_NEAR_PLANE_VALUE))))
        return; /* reaches behind the eye: whole screen */
    num_t x0 = NUM_ZERO, x1 = NUM_ZERO, y0 = NUM_ZERO, y1 = NUM_ZERO;
    if (!prep_screen_extremes(f, b, &x0, &x1, &y0, &y1))
        return;
    /* one pixel of margin either side keeps it conservative under rounding */
    int32_t ix0 = num_floor_int(x0) - 1, ix1 = num_floor_int(x1) + 2;
    int32_t iy0 = num_floor_int(y0) - 1, iy1 = num_floor_int(y1) + 2;
    c->screen_x0 = ix0 < 0 ? 0 : ix0;
    c->screen_y0 = iy0 < 0 ? 0 : iy0;
    c->screen_x1 = ix1 > f->width - 1 ? f->width - 1 : ix1;
    c->screen_y1 = iy1 > f->height - 1 ? f->height - 1 : iy1;
}

/* Grows c's tree rectangle to hold the rectangle (x0, y0)-(x1, y1), which
 * is ignored when empty (x0 > x1 or y0 > y1). */
static void prep_tree_rect_add(render_cluster_t *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    if (x0 > x1 || y0 > y1)
        return;
    if (c->tree_x0 > c->tree_x1 || c->tree_y0 > c->tree_y1) {
        c->tree_x0 = x0;
        c->tree_y0 = y0;
        c->tree_x1 = x1;
        c->tree_y1 = y1;
        return;
    }
    c->tree_x0 = x0 < c->tree_x0 ? x0 : c->tree_x0;
    c->tree_y0 = y0 < c->tree_y0 ? y0 : c->tree_y0;
    c->tree_x1 = x1 > c->tree_x1 ? x1 : c->tree_x1;
    c->tree_y1 = y1 > c->tree_y1 ? y1 : c->tree_y1;
}

static void prep_lights(const scene_t *s, const scene_light_t *lights, const xform_t *world_to_eye,
                        render_frame_t *f)
{
    f->light_count = s->light_count;
    for (uint16_t i = 0; i < s->light_count; i++) {
        const scene_light_t *l = &lights[i];
        render_light_t *e = &f->lights[i];
        e->kind = l->kind;
        e->intensity = l->intensity;
        e->position = xform_point(world_to_eye, l->position);
        vec3_t dir = vec3_normalize(xform_dir(world_to_eye, l->direction));
        e->to_light = vec3_neg(dir);
        e->axis = dir;
        e->cos_inner = l->cos_inner;
        e->cos_outer = l->cos_outer;
    }
}

/* ------------------------------------------ the scene's static structure */

/* Vertex normals remembered while indexing: the last distinct one of each
 * hash, direct-mapped (a mesh's neighbours share vertices close together
 * in primitive order, so a small table finds nearly all of them).  An
 * entry: the code (j << 2 | k) + 1 of the first one, 0 when empty, and
 * its maps. */
#define PREP_SHARE_CACHE 4096u

static int prep_vec3_same(const vec3_t *a, const vec3_t *b)
{
    const uint8_t *x = (const uint8_t *)a, *y = (const uint8_t *)b;
    for (size_t at = 0; at < sizeof *a; at += sizeof(uint32_t)) {
        uint32_t u, w;
        __builtin_memcpy(&u, x + at, sizeof u);
        __builtin_memcpy(&w, y + at, sizeof w);
        if (u != w)
            return 0;
    }
    return 1;
}

/* The code of vertex normal v's first equal (bits and maps) met before,
 * or code itself (remembered) when none: normal_src's entry. */
static uint32_t prep_share(uint32_t *cache, const vec3_t *v, uint32_t tag, uint32_t code,
                           const scene_t *s)
{
    const uint8_t *b = (const uint8_t *)v;
    uint32_t h = 2166136261u ^ tag;
    for (size_t i = 0; i < sizeof *v; i += sizeof(uint32_t)) {
        uint32_t w;
        __builtin_memcpy(&w, b + i, sizeof w);
        h = (h ^ w) * 16777619u;
    }
    uint32_t *e = &cache[2 * ((h ^ (h >> 13)) & (PREP_SHARE_CACHE - 1))];
    if (e[0] != 0 && e[1] == tag &&
        prep_vec3_same(&s->normals[(e[0] - 1) >> 2].n[(e[0] - 1) & 3], v))
        return e[0] - 1;
    e[0] = code + 1;
    e[1] = tag;
    return code;
}

size_t render_scene_index_bytes_layout(const scene_t *s, const render_layout_t *lay)
{
    size_t c = s->cluster_count ? s->cluster_count : 1;
    size_t p = s->prim_count ? s->prim_count : 1;
    size_t n = s->normals_count ? s->normals_count : 1;
    /* parent_maps: a shape's bound (scene_load_shape_maps), or 2 a cluster */
    size_t maps = s->index.parent_map_count ? s->index.parent_map_count : 2 * c;
    return sizeof(scene_group_t) * c + sizeof(uint32_t) * (c + p + 3 * n) + lay->num * p + /* kept */
           lay->xform * maps + sizeof(uint32_t) * ((maps + 1) / 2) + /* own_list */
           c + n + 2 * sizeof(uint32_t) * PREP_SHARE_CACHE + /* scratch */
           10 * ARENA_MAX_ALIGN; /* 10 allocations, each padded at most that */
}

size_t render_scene_index_bytes(const scene_t *s)
{
    return render_scene_index_bytes_layout(s, &render_layout_native);
}

/* Each cluster's children and primitives listed from its first, the
 * counts render_scene_index made turned into offsets (a counting sort:
 * ascending index). */
static void prep_index_lists(const scene_t *s, scene_group_t *g, uint32_t *child,
                             uint32_t *plist)
{
    uint32_t nc = s->cluster_count, np = s->prim_count, kids = 0, prims = 0;
    for (uint32_t i = 0; i < nc; i++) {
        g[i].first_child = kids;
        kids += g[i].child_count;
        g[i].child_count = 0;
        g[i].first_prim = prims;
        prims += g[i].prim_count;
        g[i].prim_count = 0;
    }
    for (uint32_t i = 1; i < nc; i++) {
        scene_group_t *p = &g[s->clusters[i].parent];
        child[p->first_child + p->child_count++] = i;
    }
    for (uint32_t i = 0; i < np; i++) {
        scene_group_t *c = &g[s->prims[i].cluster];
        plist[c->first_prim + c->prim_count++] = i;
    }
}

/* A triangle's spread of map coordinates (scene_index_t.uv_spread). */
static num_t prep_uv_spread(const scene_prim_t *sp)
{
    const num_t *u = sp->shape.triangle.tex_u, *v = sp->shape.triangle.tex_v;
    num_t spread = NUM_ZERO;
    for (int k = 1; k < 3; k++)
        spread = num_add(spread, num_max(num_abs(num_sub(u[k], u[0])),
                                         num_abs(num_sub(v[k], v[0]))));
    return spread;
}

/* Every triangle's spread (scene_index_t.uv_spread) where a map may read
 * it; without maps they stay 0. */
static void prep_uv_spreads(const scene_t *s, num_t *spread)
{
    for (uint32_t i = 0; i < s->prim_count && s->map_count; i++)
        if (s->prims[i].kind == SCENE_PRIM_TRIANGLE)
            spread[i] = prep_uv_spread(&s->prims[i]);
}

/* Each triangle's texture spread (prep_uv_spreads), and each vertex
 * normal's first equal (named: the records a triangle took; cache:
 * prep_share's); the range of the other primitives (out->pointer_lo,
 * pointer_hi).  RENDER_OK, or RENDER_ERR_PRIM for a record named twice or
 * out of range. */
static render_status_t prep_index_triangles(const scene_t *s, const scene_group_t *g,
                                            uint8_t *named, uint32_t *cache, uint32_t *src,
                                            num_t *spread, scene_index_t *out)
{
    uint32_t np = s->prim_count, nn = s->normals_count;
    prep_uv_spreads(s, spread);
    for (uint32_t j = 0; j < nn; j++)
        for (uint32_t k = 0; k < 3; k++)
            src[3 * j + k] = j << 2 | k;
    for (uint32_t i = 0; i < np; i++) {
        const scene_prim_t *sp = &s->prims[i];
        if (sp->kind != SCENE_PRIM_TRIANGLE) {
            if (!out->pointer_hi)
                out->pointer_lo = i;
            out->pointer_hi = i + 1;
            continue;
        }
        if (!sp->shape.triangle.smooth)
            continue;
        uint32_t maps = g[sp->cluster].maps_of;
        uint32_t j = sp->shape.triangle.smooth - 1;
        if (j >= nn || named[j]) /* one record, one triangle (the loader's rule) */
            return RENDER_ERR_PRIM;
        named[j] = 1;
        for (uint32_t k = 0; k < 3; k++)
            src[3 * j + k] = prep_share(cache, &s->normals[j].n[k], maps, j << 2 | k, s);
    }
    return RENDER_OK;
}

/* What of each cluster's maps stays from frame to frame (scene_index_t's
 * parent_maps), for the clusters with maps of their own (own of them,
 * listed in own_list), into the arena.  The same operations on the same
 * operands as prep_cluster_maps would do each frame, so the same bits.
 * RENDER_OK, or precision_invert's error for a local map it cannot
 * invert. */
static render_status_t prep_index_maps(const scene_t *s, const scene_group_t *g, uint32_t own,
                                       arena_t *arena, scene_index_t *out)
{
    xform_t *maps = ARENA_NEW_ARRAY(arena, xform_t, own ? 2 * (size_t)own : 1);
    uint32_t *list = ARENA_NEW_ARRAY(arena, uint32_t, own ? own : 1);
    if (!maps || !list)
        return RENDER_ERR_ARENA;
    const xform_t id = xform_identity(); /* the key of a cluster without keys */
    xform_t id_inv;
    render_status_t st = precision_invert(&id, &id_inv);
    for (uint32_t i = 0, n = 0; n < 2 * own && st == RENDER_OK; i++) {
        if (g[i].maps_of != i)
            continue;
        const scene_cluster_t *c = &s->clusters[i];
        xform_t *m = &maps[n];
        list[n / 2] = i;
        n += 2;
        xform_t local_inv;
        st = precision_invert(&c->local, &local_inv);
        if (st == RENDER_OK && c->key_count) {
            m[1] = local_inv;
        } else if (st == RENDER_OK) {
            m[0] = xform_compose(&id, &c->local);
            m[1] = xform_compose(&local_inv, &id_inv);
        }
    }
    out->parent_maps = maps;
    out->parent_map_count = own ? 2 * own : 1;
    out->own_list = list;
    out->own_count = own;
    return st;
}

/* The index's arrays (scene_index_t's groups to uv_spread) for s, zeroed
 * in arena: 1, or 0 when it lacks room.  prep_index_keep puts them in the
 * index once filled. */
typedef struct {
    scene_group_t *groups;
    uint32_t *child, *plist, *src;
    num_t *spread;
} prep_index_arrays_t;

static int prep_index_arrays(const scene_t *s, arena_t *arena, prep_index_arrays_t *a)
{
    uint32_t nc = s->cluster_count, np = s->prim_count, nn = s->normals_count;
    a->groups = ARENA_NEW_ARRAY(arena, scene_group_t, nc);
    a->child = ARENA_NEW_ARRAY(arena, uint32_t, nc);
    a->plist = ARENA_NEW_ARRAY(arena, uint32_t, np ? np : 1);
    a->src = ARENA_NEW_ARRAY(arena, uint32_t, nn ? 3 * (size_t)nn : 1);
    a->spread = ARENA_NEW_ARRAY(arena, num_t, np ? np : 1);
    return a->groups && a->child && a->plist && a->src && a->spread;
}

static void prep_index_keep(const prep_index_arrays_t *a, scene_index_t *out)
{
    out->groups = a->groups;
    out->child_list = a->child;
    out->prim_list = a->plist;
    out->normal_src = a->src;
    out->uv_spread = a->spread;
}

render_status_t render_scene_index(const scene_t *s, arena_t *arena, scene_index_t *out)
{
    __builtin_memset(out, 0, sizeof *out);
    uint32_t nc = s->cluster_count, np = s->prim_count, nn = s->normals_count, own = 0;
    render_status_t st = RENDER_OK;
    if (nc < 1 || s->clusters[0].parent != SCENE_NO_CLUSTER)
        return RENDER_ERR_CLUSTER;
    if (nn >= (1u << 29)) /* (j << 2 | k) must fit: 18 GB of normals, more
                             than any arena holds */
        return RENDER_ERR_ARENA;
    prep_index_arrays_t a;
    if (!prep_index_arrays(s, arena, &a))
        return RENDER_ERR_ARENA;
    scene_group_t *g = a.groups;
    size_t mark = arena->used; /* scratch from here, released below */
    uint8_t *depth = ARENA_NEW_ARRAY(arena, uint8_t, nc);
    uint8_t *named = ARENA_NEW_ARRAY(arena, uint8_t, nn ? nn : 1);
    uint32_t *cache = ARENA_NEW_ARRAY(arena, uint32_t, 2 * PREP_SHARE_CACHE);
    if (!depth || !named || !cache)
        return RENDER_ERR_ARENA;
    for (uint32_t i = 0; i < nc && st == RENDER_OK; i++) {
        const scene_cluster_t *c = &s->clusters[i];
        if (i > 0 && c->parent >= i) {
            st = RENDER_ERR_CLUSTER;
            break;
        }
        if ((uint64_t)c->first_key + c->key_count > s->key_count) {
            st = RENDER_ERR_KEY;
            break;
        }
        depth[i] = i == 0 ? 0 : (uint8_t)(depth[c->parent] + 1);
        if (depth[i] > RENDER_MAX_CLUSTER_DEPTH)
            st = RENDER_ERR_CLUSTER;
        /* a plain cluster has exactly its parent's maps, so its primitives
         * come out bit for bit as in the parent: the DM copies no maps */
        g[i].maps_of = i > 0 && prep_is_plain(c) ? g[c->parent].maps_of : i;
        own += g[i].maps_of == i;
        if (c->key_count) {
            if (!out->keyed_hi)
                out->keyed_lo = i;
            out->keyed_hi = i + 1;
        }
    }
    /* children and primitives grouped by owner, each with a counting sort
     * (stable: ascending index) */
    for (uint32_t i = 1; i < nc && st == RENDER_OK; i++)
        g[s->clusters[i].parent].child_count++;
    for (uint32_t i = 0; i < np && st == RENDER_OK; i++) { /* each checked once, here */
        st = prep_prim_check(s, &s->prims[i]);
        if (st == RENDER_OK)
            g[s->prims[i].cluster].prim_count++;
    }
    if (st != RENDER_OK) {
        arena_release_to(arena, mark);
        return st;
    }
    prep_index_lists(s, g, a.child, a.plist);
    /* each vertex normal's first equal (bits and maps), in the order
     * render_prepare maps them: rising primitive index.  (Vertices shared
     * likewise cost more to copy than to map: measured, not kept.) */
    st = prep_index_triangles(s, g, named, cache, a.src, a.spread, out);
    arena_release_to(arena, mark);
    if (st == RENDER_OK)
        st = prep_index_maps(s, g, own, arena, out);
    if (st == RENDER_OK)
        prep_index_keep(&a, out);
    return st;
}

scene_index_ints_t render_scene_index_ints(const scene_t *s)
{
    const scene_index_t *x = &s->index;
    scene_index_ints_t ints = {s->cluster_count, s->prim_count,  s->normals_count,
                               x->groups,        x->child_list,  x->prim_list,
                               x->normal_src,    x->own_count,   x->pointer_lo,
                               x->pointer_hi,    x->keyed_lo,    x->keyed_hi};
    return ints;
}

render_status_t render_scene_index_same(const scene_t *s, arena_t *arena,
                                        const scene_index_ints_t *same, scene_index_t *out)
{
    __builtin_memset(out, 0, sizeof *out);
    uint32_t nc = s->cluster_count, np = s->prim_count, nn = s->normals_count;
    prep_index_arrays_t a;
    if (!prep_index_arrays(s, arena, &a))
        return RENDER_ERR_ARENA;
    memcpy(a.groups, same->groups, sizeof *a.groups * nc);
    memcpy(a.child, same->child_list, sizeof *a.child * nc);
    memcpy(a.plist, same->prim_list, sizeof *a.plist * np);
    memcpy(a.src, same->normal_src, sizeof *a.src * 3 * (size_t)nn);
    prep_uv_spreads(s, a.spread);
    render_status_t st = prep_index_maps(s, a.groups, same->own_count, arena, out);
    if (st != RENDER_OK)
        return st;
    prep_index_keep(&a, out);
    out->pointer_lo = same->pointer_lo;
    out->pointer_hi = same->pointer_hi;
    out->keyed_lo = same->keyed_lo;
    out->keyed_hi = same->keyed_hi;
    return RENDER_OK;
}

/* Keep in step with the allocations of render_prepare below: every array
 * plus the worst alignment padding of each (64 bytes is the most the
 * arena pads). */
size_t render_prepare_frame_bytes_layout(const scene_t *s, const render_layout_t *lay)
{
    size_t prims = s->prim_count ? s->prim_count : 1;
    size_t comps = s->density_component_count ? s->density_component_count : 1;
    size_t normals = s->normals_count ? s->normals_count : 1;
    size_t n = lay->frame + lay->frame_cluster * (size_t)s->cluster_count + lay->frame_prim * prims +
               lay->num * comps;
    /* (and a byte and a word a cluster: which maps and clusters moved) */
    size_t scratch = (2 * lay->xform + 1 + sizeof(uint32_t)) * (size_t)s->cluster_count +
                     lay->normals * normals;
    return n + scratch + 9 * ARENA_MAX_ALIGN; /* 9 allocations, each padded at most that */
}

size_t render_prepare_bytes_layout(const scene_t *s, const render_layout_t *lay)
{
    /* a scene without its index: render_prepare works it out into the frame's arena */
    return render_prepare_frame_bytes_layout(s, lay) +
           (s->index.groups ? 0 : render_scene_index_bytes_layout(s, lay));
}

size_t render_prepare_bytes(const scene_t *s)
{
    return render_prepare_bytes_layout(s, &render_layout_native);
}

/* moved[] of render_prepare_again, a byte a cluster: its maps moved (a
 * cluster with maps of its own, prep_cluster_maps), its own primitives
 * moved (a cluster of such a one's maps: prep_moved_members), its box
 * moved (its own primitives' or a descendant's: prep_moved_ancestors). */
#define PREP_MAPS_MOVED 1u
#define PREP_OWN_MOVED 2u
#define PREP_BOX_MOVED 4u

/* Clusters a frame prepared again in part may make again however few
 * the scene has (prep_moved_members): a small scene's moving parts. */
#define PREP_MOVED_CLUSTERS 256u

/* What moved since the frame before (prep_cluster_maps, prep_moved). */
typedef struct {
    uint32_t before; /* the frame before's index */
    uint8_t *moved;  /* a byte a cluster, PREP_*_MOVED, zeroed before */
    uint32_t *order; /* a cluster_count array: the clusters with maps of
                        their own that moved (heads of it), then the
                        clusters of their maps (prep_moved_members) */
    uint32_t heads;  /* how many of order are those */
} prep_moves_t;

/* The scratch maps a primitive is prepared with (prep_one_prim). */
typedef struct {
    const xform_t *to_eye, *from_eye;
    scene_normals_t *normals;
} prep_run_maps_t;

/* A keyed cluster's maps to its parent and back at frame_index, into
 * maps; *key its key's map.  local_inv: its local map's inverse (the
 * index's parent_maps). */
static render_status_t prep_keyed_maps(const scene_t *s, const scene_cluster_t *c,
                                       uint32_t frame_index, const xform_t *local_inv,
                                       xform_t *key, xform_t maps[2])
{
    xform_t key_inv;
    *key = prep_key_xform(s, c, frame_index);
    render_status_t st = precision_invert(key, &key_inv);
    if (st != RENDER_OK)
        return st;
    maps[0] = xform_compose(key, &c->local);
    maps[1] = xform_compose(local_inv, &key_inv);
    return RENDER_OK;
}

/* The maps of every cluster that has its own (to_eye[i], from_eye[i]
 * for ix->groups[i].maps_of == i), composed from root_to and root_from
 * and each one's maps to its parent and back (a cluster without keys has
 * them in the index); f->precision_lost set when one saturates.  With mv
 * (not NULL): mv->moved[i] set for each of them whose map differs from
 * its map at frame mv->before, its own key's or an ancestor's, and listed
 * in mv->order (rising index). */
static render_status_t prep_cluster_maps(const scene_t *s, const scene_index_t *ix, uint32_t frame_index,
                                         const xform_t *root_to, const xform_t *root_from,
                                         prep_moves_t *mv, xform_t *to_eye, xform_t *from_eye,
                                         render_frame_t *f)
{
    uint8_t *moved = mv ? mv->moved : NULL;
    for (uint32_t k = 0; k < ix->own_count; k++) {
        uint32_t i = ix->own_list[k];
        const scene_cluster_t *c = &s->clusters[i];
        const xform_t *parent = &ix->parent_maps[2 * k];
        xform_t key, keyed[2];
        if (c->key_count) {
            render_status_t st = prep_keyed_maps(s, c, frame_index, &parent[1], &key, keyed);
            if (st != RENDER_OK)
                return st;
            parent = keyed;
        }
        uint32_t pm = i == 0 ? 0 : ix->groups[c->parent].maps_of;
        const xform_t *parent_to_eye = i == 0 ? root_to : &to_eye[pm];
        const xform_t *eye_to_parent = i == 0 ? root_from : &from_eye[pm];
        to_eye[i] = xform_compose(parent_to_eye, &parent[0]);
        from_eye[i] = xform_compose(&parent[1], eye_to_parent);
        if (xform_is_sat(&to_eye[i]) || xform_is_sat(&from_eye[i]))
            f->precision_lost = 1;
        if (moved) {
            moved[i] = i > 0 ? moved[pm] & PREP_MAPS_MOVED : 0;
            if (!moved[i] && c->key_count) {
                xform_t was = prep_key_xform(s, c, mv->before);
                moved[i] = memcmp(&was, &key, sizeof key) != 0 ? PREP_MAPS_MOVED : 0;
            }
            if (moved[i])
                mv->order[mv->heads++] = i;
        }
    }
    return RENDER_OK;
}

/* Primitive i of the frame from its cluster's maps (f->prims[i] zeroed
 * before): its form, its map's error, the saturation flag, and (but a
 * triangle, precision_check's) its detail. */
static inline __attribute__((always_inline)) void prep_one_prim(const scene_t *s, uint32_t i, render_frame_t *f, const scene_index_t *ix,
                          const xform_t *to_eye, const xform_t *from_eye, num_t pad,
                          scene_normals_t *normals)
{
    const scene_prim_t *sp = &s->prims[i];
    uint32_t m = ix->groups[sp->cluster].maps_of;
    prep_prim(sp, i, f, &to_eye[m], &from_eye[m], pad, ix, normals, &f->prims[i]);
    /* the error of the cluster's inverse map, for precision_check (a
     * triangle's vertices are mapped forward: none, and precision_check
     * sets its 0) */
    if (sp->kind != SCENE_PRIM_TRIANGLE)
        f->prims[i].hit_error = precision_map_error(&to_eye[m], &from_eye[m], &f->prims[i].bounds);
    if (prep_aabb_is_sat(&f->prims[i].bounds))
        f->precision_lost = 1;
    if (sp->kind != SCENE_PRIM_TRIANGLE) /* a triangle's: precision_check */
        precision_detail(f, i, &to_eye[m]);
}

/* Cluster i's lists (the index's) and the box of its own primitives,
 * grown in rising primitive index as ever; its tree box and rectangle
 * emptied for prep_cluster_tree. */
static inline __attribute__((always_inline)) void prep_own_bounds(render_frame_t *f, const scene_index_t *ix, uint32_t i)
{
    render_cluster_t *c = &f->clusters[i];
    const scene_group_t *g = &ix->groups[i];
    c->first_child = g->first_child;
    c->child_count = g->child_count;
    c->first_prim = g->first_prim;
    c->prim_count = g->prim_count;
    c->own_bounds = prep_aabb_empty();
    for (uint32_t k = 0, have = 0; k < g->prim_count; k++) {
        /* prep_aabb_add_box without asking of own_bounds what have
         * says: a box grown by one not empty is not empty */
        const aabb_t *o = &f->prims[ix->prim_list[g->first_prim + k]].bounds;
        if (prep_aabb_is_empty(o))
            continue;
        if (have)
            prep_aabb_grow(&c->own_bounds, o);
        else
            c->own_bounds = *o;
        have = 1;
    }
    c->bounds = prep_aabb_empty();
    c->tree_x0 = c->tree_y0 = 1;
    c->tree_x1 = c->tree_y1 = 0;
}

/* Adds cluster c's own screen rectangle to the pixels and rows it covers
 * (nothing when it is empty). */
static inline __attribute__((always_inline)) void prep_rect_cover(const render_cluster_t *c,
                                                                 uint64_t *covered,
                                                                 uint64_t *rows)
{
    if (c->screen_x0 <= c->screen_x1 && c->screen_y0 <= c->screen_y1) {
        *covered += (uint64_t)(uint32_t)(c->screen_x1 - c->screen_x0 + 1) *
                    (uint32_t)(c->screen_y1 - c->screen_y0 + 1);
        *rows += (uint32_t)(c->screen_y1 - c->screen_y0 + 1);
    }
}

/* The frame's clip coverage (eye space) from the pixels and rows the
 * clusters' own rectangles cover, kept in f->clip_covered and
 * clip_covered_rows: covered / pixels and rows / height, rounded up, in
 * 32 bits (covered < 2^32 * pixels would need 2^32 clusters over every
 * pixel). */
static void prep_clip_coverage_set(render_frame_t *f, uint64_t covered, uint64_t rows)
{
    f->clip_covered = covered;
    f->clip_covered_rows = rows;
    uint32_t pixels = (uint32_t)f->width * f->height;
    uint64_t mean = (covered + pixels - 1) / pixels;
    f->clip_coverage = mean > UINT32_MAX ? UINT32_MAX : (uint32_t)mean;
    mean = (rows + f->height - 1) / f->height;
    f->clip_rows = mean > UINT32_MAX ? UINT32_MAX : (uint32_t)mean;
}

/* Every cluster's box over its subtree, its screen rectangle (whole: the
 * whole screen, as world space and RENDER_PREP_NO_SCREEN have it) and
 * tree rectangle, from the own boxes (prep_own_bounds emptied the others);
 * the frame's clip coverage (not whole). */
static void prep_cluster_tree(const scene_t *s, render_frame_t *f, int whole)
{
    /* children have larger indices than parents: one backward pass */
    uint64_t covered = 0, rows = 0; /* pixels, rows under the clusters' own rectangles */
    for (uint32_t i = s->cluster_count; i-- > 0;) {
        render_cluster_t *c = &f->clusters[i];
        prep_aabb_add_box(&c->bounds, &c->own_bounds);
        if (whole) {
            c->screen_x0 = c->screen_y0 = 0;
            c->screen_x1 = f->width - 1;
            c->screen_y1 = f->height - 1;
        } else {
            prep_screen_rect(f, c);
        }
        prep_rect_cover(c, &covered, &rows);
        prep_tree_rect_add(c, c->screen_x0, c->screen_y0, c->screen_x1, c->screen_y1);
        if (i > 0) {
            render_cluster_t *p = &f->clusters[s->clusters[i].parent];
            prep_aabb_add_box(&p->bounds, &c->bounds);
            prep_tree_rect_add(p, c->tree_x0, c->tree_y0, c->tree_x1, c->tree_y1);
        }
    }
    if (!whole)
        prep_clip_coverage_set(f, covered, rows);
}

/* The clusters of the moved heads' maps (each head, and its descendants
 * through plain clusters, which use its maps: ix->groups[].maps_of) into
 * mv->order after the heads; *n how many in all.  1 when their primitives
 * are at most half the scene's, and they at most a quarter of its
 * clusters or PREP_MOVED_CLUSTERS (a frame where more moved is cheaper
 * whole: the walk stops there), else 0.  Each cluster has one parent, so
 * none is listed twice. */
static int prep_moved_members(const scene_t *s, const scene_index_t *ix, prep_moves_t *mv,
                              uint32_t *n)
{
    uint32_t count = 0, most = s->prim_count / 2; /* (a count of primitives fits) */
    uint32_t end = mv->heads, clusters = s->cluster_count / 4;
    if (clusters < PREP_MOVED_CLUSTERS)
        clusters = PREP_MOVED_CLUSTERS;
    for (uint32_t q = 0; q < end; q++) { /* the list is its own queue */
        if (count > most || q > clusters)
            return 0;
        const scene_group_t *g = &ix->groups[mv->order[q]];
        count += g->prim_count;
        for (uint32_t k = 0; k < g->child_count; k++) {
            uint32_t kid = ix->child_list[g->first_child + k];
            if (ix->groups[kid].maps_of == g->maps_of)
                mv->order[end++] = kid;
        }
    }
    *n = end;
    return count <= most;
}

/* Each of the n clusters of mv->order and its ancestors marked
 * PREP_BOX_MOVED (a walk up stops at one marked already). */
static void prep_moved_ancestors(const scene_t *s, prep_moves_t *mv, uint32_t n)
{
    for (uint32_t q = 0; q < n; q++)
        for (uint32_t c = mv->order[q]; !(mv->moved[c] & PREP_BOX_MOVED); c = s->clusters[c].parent) {
            mv->moved[c] |= PREP_BOX_MOVED;
            if (c == 0)
                break;
        }
}

/* Cluster c's box, grown as prep_cluster_tree grows it: by its children
 * in falling index, then by its own primitives' box; its rectangles:
 * world, the whole screen's, as prep_cluster_tree makes them; eye space,
 * its own box's (prep_screen_rect, made again when its own primitives
 * moved, the pixels and rows it covers taken off and added back) and the
 * tree rectangle over it and its children's (screenless: as world). */
static void prep_moved_cluster(render_frame_t *f, const scene_index_t *ix, uint32_t c,
                               int own_moved)
{
    render_cluster_t *cl = &f->clusters[c];
    const scene_group_t *g = &ix->groups[c];
    cl->bounds = prep_aabb_empty();
    for (uint32_t k = g->child_count; k-- > 0;)
        prep_aabb_add_box(&cl->bounds, &f->clusters[ix->child_list[g->first_child + k]].bounds);
    prep_aabb_add_box(&cl->bounds, &cl->own_bounds);
    if (f->world || f->screenless) {
        cl->tree_x0 = cl->tree_y0 = 0;
        cl->tree_x1 = f->width - 1;
        cl->tree_y1 = f->height - 1;
        return;
    }
    if (own_moved) {
        uint64_t was = 0, was_rows = 0, now = 0, now_rows = 0;
        prep_rect_cover(cl, &was, &was_rows);
        prep_screen_rect(f, cl);
        prep_rect_cover(cl, &now, &now_rows);
        f->clip_covered += now - was;
        f->clip_covered_rows += now_rows - was_rows;
    }
    cl->tree_x0 = cl->tree_y0 = 1;
    cl->tree_x1 = cl->tree_y1 = 0;
    for (uint32_t k = 0; k < g->child_count; k++) {
        const render_cluster_t *kid = &f->clusters[ix->child_list[g->first_child + k]];
        prep_tree_rect_add(cl, kid->tree_x0, kid->tree_y0, kid->tree_x1, kid->tree_y1);
    }
    prep_tree_rect_add(cl, cl->screen_x0, cl->screen_y0, cl->screen_x1, cl->screen_y1);
}

/* The clusters marked PREP_BOX_MOVED made again (prep_moved_cluster),
 * children first: a walk from the root down the marked ones, each done
 * once its marked children are; then the clip coverage (eye space). */
static void prep_moved_boxes(render_frame_t *f, const scene_index_t *ix, const uint8_t *moved)
{
    struct {
        uint32_t c, next; /* the cluster, and its next child to look at */
    } stack[RENDER_MAX_CLUSTER_DEPTH + 1];
    int top = 0;
    stack[0].c = 0;
    stack[0].next = 0;
    while (top >= 0) {
        uint32_t c = stack[top].c;
        const scene_group_t *g = &ix->groups[c];
        if (stack[top].next < g->child_count) {
            uint32_t kid = ix->child_list[g->first_child + stack[top].next++];
            if ((moved[kid] & PREP_BOX_MOVED) && top < RENDER_MAX_CLUSTER_DEPTH) {
                stack[++top].c = kid;
                stack[top].next = 0;
            }
            continue;
        }
        prep_moved_cluster(f, ix, c, moved[c] & PREP_OWN_MOVED);
        top--;
    }
    if (!f->world && !f->screenless)
        prep_clip_coverage_set(f, f->clip_covered, f->clip_covered_rows);
}

/* The primitives of the n clusters of mv->order (their own boxes made
 * again with them, each marked PREP_OWN_MOVED); 1 when one saturated
 * (f->precision_lost). */
static int prep_moved_prims(const scene_t *s, render_frame_t *f, const scene_index_t *ix,
                            prep_moves_t *mv, uint32_t n, const prep_run_maps_t *maps, num_t pad)
{
    f->detail_prim = RENDER_NO_PRIM;
    for (uint32_t q = 0; q < n; q++) {
        uint32_t c = mv->order[q];
        mv->moved[c] |= PREP_OWN_MOVED;
        const scene_group_t *g = &ix->groups[c];
        for (uint32_t k = 0; k < g->prim_count; k++) {
            uint32_t i = ix->prim_list[g->first_prim + k];
            memset(&f->prims[i], 0, sizeof f->prims[i]);
            prep_one_prim(s, i, f, ix, maps->to_eye, maps->from_eye, pad, maps->normals);
        }
        prep_own_bounds(f, ix, c);
    }
    return f->precision_lost;
}

/* A frame over the frame before (old, at the same address, prepared
 * whole: no saturation, no detail refused; in eye space seen from the
 * same camera), when at most half the primitives moved: only the
 * primitives of the clusters whose maps moved (prep_moved_members) are
 * prepared again, then the boxes of those clusters and their ancestors
 * (prep_moved_boxes), and the precision checks of the primitives
 * prepared: work for what moved, not for every cluster.  Sets f->kept = 2
 * and returns precision_check's status when the extent came out as
 * old's; leaves kept 0 otherwise (more moved, the extent moved or a bound
 * saturated), and the caller prepares the frame whole.  Every box is
 * grown in the order a whole preparation grows it, and the primitives
 * and their checks do not depend on the order they come in, so the bytes
 * are the same. */
static __attribute__((noinline)) render_status_t prep_moved(const scene_t *s, render_frame_t *f,
                                                            const scene_index_t *ix,
                                                            const render_frame_t *old,
                                                            prep_moves_t *mv,
                                                            const prep_run_maps_t *maps, num_t pad)
{
    uint32_t n;
    if (!prep_moved_members(s, ix, mv, &n)) /* cheaper whole */
        return RENDER_OK;
    if (prep_moved_prims(s, f, ix, mv, n, maps, pad))
        return RENDER_OK;
    prep_moved_ancestors(s, mv, n);
    f->clip_covered = old->clip_covered;
    f->clip_covered_rows = old->clip_covered_rows;
    prep_moved_boxes(f, ix, mv->moved);
    const precision_pass_t pass = precision_check_begin(f);
    if (f->precision_lost || memcmp(&f->precision_extent, &old->precision_extent, sizeof(num_t)) != 0)
        return RENDER_OK;
    for (uint32_t q = 0; q < n; q++) {
        const scene_group_t *g = &ix->groups[mv->order[q]];
        precision_check_prims(f, ix, &pass, &ix->prim_list[g->first_prim], g->prim_count);
    }
    f->kept = 2;
    return precision_check_end(f);
}

render_status_t render_prepare(const scene_t *s, uint32_t frame_index, arena_t *arena, render_frame_t **out)
{
    return render_prepare_again(s, frame_index, arena, NULL, out);
}

/* One frame's preparation under way (render_prepare_again's steps). */
typedef struct {
    const scene_t *s;
    uint32_t frame_index;
    arena_t *arena;
    render_frame_t *f;
    render_frame_t old;     /* the frame before's header, when may_keep */
    int may_keep;           /* what it prepared may be kept: its world
                               part, or in eye space its primitives and
                               boxes seen from the same camera */
    int world;              /* options.world_space */
    int screenless;         /* RENDER_PREP_NO_SCREEN */
    scene_index_t ix;
    scene_camera_t camera;
    scene_light_t lights[RENDER_MAX_LIGHTS];
    size_t mark;            /* the scratch below is released to here */
    xform_t *to_eye, *from_eye;
    scene_normals_t *normals;
    uint8_t *moved;         /* which maps moved since the frame before */
    uint32_t *order;        /* and which clusters (prep_moves_t) */
    int camera_lost;
    const xform_t *root_to, *root_from; /* what the scene's root maps to and from */
} prep_run_t;

/* The frame's header and arrays (allocated again at the frame before's
 * addresses, not cleared until it is known they are not kept), and the
 * scene's static structure: the loader's, or worked out here (a scene
 * built by hand) into the frame's arena. */
static render_status_t prep_frame_alloc(prep_run_t *r, const render_frame_t *prev)
{
    const scene_t *s = r->s;
    r->may_keep = prev && prev->world == r->world && prev->screenless == r->screenless &&
                  prev->scene == s;
    if (r->may_keep)
        r->old = *prev;
    render_frame_t *f = ARENA_NEW_ARRAY(r->arena, render_frame_t, 1);
    if (!f)
        return RENDER_ERR_ARENA;
    r->f = f;
    f->clusters = ARENA_NEW_ARRAY_RAW(r->arena, render_cluster_t, s->cluster_count);
    f->prims = ARENA_NEW_ARRAY_RAW(r->arena, render_prim_t, s->prim_count ? s->prim_count : 1);
    r->may_keep = r->may_keep && f == prev && f->clusters == r->old.clusters &&
                  f->prims == r->old.prims;
    uint32_t ncomp = s->density_component_count;
    f->density_inv_radius2 = ARENA_NEW_ARRAY(r->arena, num_t, ncomp ? ncomp : 1);
    if (!f->clusters || !f->prims || !f->density_inv_radius2)
        return RENDER_ERR_ARENA;
    r->ix = s->index;
    if (!r->ix.groups)
        return render_scene_index(s, r->arena, &r->ix);
    return RENDER_OK;
}

/* The header's fields that come from the scene and the frame's keys. */
static void prep_frame_header(prep_run_t *r)
{
    const scene_t *s = r->s;
    render_frame_t *f = r->f;
    f->child_list = r->ix.child_list;
    f->prim_list = r->ix.prim_list;
    /* (1/d)/d rather than 1/(d*d): d*d of a small radius would keep few
     * significant bits in fixed point */
    for (uint32_t k = 0; k < s->density_component_count; k++) {
        num_t d = s->density_components[k].radius;
        f->density_inv_radius2[k] = num_div(num_recip(d), d);
    }
    f->scene = s;
    f->screenless = (uint8_t)r->screenless;
    f->frame_index = r->frame_index;
    f->options = s->options;
    f->width = s->width;
    f->height = s->height;
    f->cluster_count = s->cluster_count;
    f->prim_count = s->prim_count;
    f->pointer_lo = r->ix.pointer_lo;
    f->pointer_hi = r->ix.pointer_hi;
    f->ray_epsilon = scene_tolerance(s, NUM_C(RENDER_RAY_EPSILON_VALUE));
    prep_view_at(s, r->frame_index, &r->camera, r->lights);
    f->screen_half_h = r->camera.tan_half_fov_y;
    f->screen_half_w = num_mul(r->camera.tan_half_fov_y, num_from_ratio(s->width, s->height));
}

/* Scratch: per-cluster maps and the smooth triangles' eye-space vertex
 * normals (each written before it is read; each triangle keeps a copy of
 * its own), released before returning; not zero-filled: only the
 * clusters with maps of their own are written, and only they are read
 * (ix.groups[].maps_of).  Which maps and clusters moved (allocated
 * whether or not it is asked, so that the block's high water is a fresh
 * preparation's). */
static render_status_t prep_scratch(prep_run_t *r)
{
    const scene_t *s = r->s;
    r->mark = r->arena->used;
    r->to_eye = ARENA_NEW_ARRAY_RAW(r->arena, xform_t, s->cluster_count);
    r->from_eye = ARENA_NEW_ARRAY_RAW(r->arena, xform_t, s->cluster_count);
    r->normals = ARENA_NEW_ARRAY_RAW(r->arena, scene_normals_t,
                                     s->normals_count ? s->normals_count : 1);
    r->moved = ARENA_NEW_ARRAY_RAW(r->arena, uint8_t, s->cluster_count);
    r->order = ARENA_NEW_ARRAY_RAW(r->arena, uint32_t, s->cluster_count);
    if (!r->to_eye || !r->from_eye || !r->normals || !r->moved || !r->order)
        return RENDER_ERR_ARENA;
    return RENDER_OK;
}

/* The camera's maps; in world space the frame's eye.  The root's maps. */
static render_status_t prep_view(prep_run_t *r, xform_t *world_to_eye, xform_t *eye_to_world)
{
    render_status_t st = prep_camera(&r->camera, world_to_eye, eye_to_world);
    if (st != RENDER_OK)
        return st;
    r->camera_lost = xform_is_sat(world_to_eye) || xform_is_sat(eye_to_world);
    if (r->camera_lost && !r->world)
        r->f->precision_lost = 1;
    r->root_to = r->world ? &prep_identity : world_to_eye;
    r->root_from = r->world ? &prep_identity : eye_to_world;
    if (r->world) {
        r->f->world = 1;
        r->f->eye = r->camera.eye;
        r->f->eye_to_world = *eye_to_world;
        r->f->clip_coverage = r->f->clip_rows = UINT32_MAX; /* no clipping lists */
    }
    return RENDER_OK;
}

/* Eye space: the camera at the frame before's index is this frame's, bit
 * for bit (its primitives and boxes then depend on the cluster maps
 * alone). */
static int prep_same_view(const prep_run_t *r)
{
    if (r->old.frame_index == r->frame_index)
        return 1;
    scene_camera_t was;
    scene_light_t lights[RENDER_MAX_LIGHTS];
    prep_view_at(r->s, r->old.frame_index, &was, lights);
    return memcmp(&was, &r->camera, sizeof was) == 0;
}

/* The frame before's kept part lost precision: its world part (world),
 * or the frame (eye space). */
static int prep_old_lost(const prep_run_t *r)
{
    return r->world ? r->old.world_lost : r->old.precision_lost;
}

/* The frame before's part kept whole when its keys are this frame's and
 * its precision is whole; in world space, also when its precision extent
 * (the eye's moved) is this frame's.  1 when kept (the lights are this
 * frame's), else 0. */
static int prep_keep_whole(prep_run_t *r)
{
    const render_frame_t *old = &r->old;
    render_frame_t *f = r->f;
    if (!r->may_keep || !prep_keys_same(r->s, old->frame_index, r->frame_index))
        return 0;
    if (r->world ? memcmp(&old->precision_extent,
                          &(num_t){precision_world_extent(old->world_box_extent, r->camera.eye)},
                          sizeof(num_t)) != 0
                 : prep_old_lost(r))
        return 0;
    arena_release_to(r->arena, r->mark);
    f->kept = 1;
    f->world_lost = old->world_lost;
    f->precision_lost = r->world ? old->world_lost || r->camera_lost : old->precision_lost;
    f->span = old->span;
    f->detail_prim = old->detail_prim;
    f->detail_size = old->detail_size;
    f->detail_step = old->detail_step;
    f->world_box_extent = old->world_box_extent;
    f->precision_extent = old->precision_extent;
    f->clip_coverage = old->clip_coverage;
    f->clip_rows = old->clip_rows;
    f->clip_covered = old->clip_covered;
    f->clip_covered_rows = old->clip_covered_rows;
    prep_lights(r->s, r->lights, r->root_to, f);
    return 1;
}

/* Every primitive, bound and light prepared anew, then the precision
 * checked. */
static render_status_t prep_whole(prep_run_t *r, num_t pad)
{
    const scene_t *s = r->s;
    render_frame_t *f = r->f;
    memset(f->clusters, 0, sizeof *f->clusters * s->cluster_count);
    memset(f->prims, 0, sizeof *f->prims * (s->prim_count ? s->prim_count : 1));
    f->detail_prim = RENDER_NO_PRIM;
    for (uint32_t i = 0; i < s->prim_count; i++)
        prep_one_prim(s, i, f, &r->ix, r->to_eye, r->from_eye, pad, r->normals);
    arena_release_to(r->arena, r->mark);
    for (uint32_t i = 0; i < s->cluster_count; i++)
        prep_own_bounds(f, &r->ix, i);
    prep_cluster_tree(s, f, r->world || r->screenless);
    prep_lights(s, r->lights, r->root_to, f);
    render_status_t st = precision_check(f, &r->ix);
    if (r->world) {
        f->world_lost = f->precision_lost;
        f->precision_lost = f->precision_lost || r->camera_lost;
    }
    return st;
}

/* The maps of every cluster that has its own (a plain cluster's
 * primitives use its ancestor's, ix.groups[].maps_of); a frame before
 * that may be kept tells which maps moved since, and this one is
 * prepared again in part where few did.  Then whole where it was not.
 * *out is the frame once the maps are made, whatever the status. */
static render_status_t prep_maps_and_prims(prep_run_t *r, render_frame_t **out)
{
    render_frame_t *f = r->f;
    int partly = r->may_keep && !prep_old_lost(r) && r->old.detail_prim == RENDER_NO_PRIM;
    prep_moves_t mv = {r->old.frame_index, r->moved, r->order, 0};
    if (partly)
        memset(r->moved, 0, r->s->cluster_count);
    render_status_t st = prep_cluster_maps(r->s, &r->ix, r->frame_index, r->root_to,
                                           r->root_from, partly ? &mv : NULL, r->to_eye,
                                           r->from_eye, f);
    if (st != RENDER_OK)
        return st;
    *out = f;
    num_t pad = scene_tolerance(r->s, NUM_C(RENDER_BOUNDS_PAD_VALUE));
    if (partly && !f->precision_lost) {
        const prep_run_maps_t maps = {r->to_eye, r->from_eye, r->normals};
        st = prep_moved(r->s, f, &r->ix, &r->old, &mv, &maps, pad);
        if (st != RENDER_OK || f->kept) {
            arena_release_to(r->arena, r->mark);
            if (r->world) {
                f->world_lost = f->precision_lost;
                f->precision_lost = f->precision_lost || r->camera_lost;
            }
            prep_lights(r->s, r->lights, r->root_to, f);
            return st;
        }
        /* more than half moved, the extent moved or a bound saturated:
         * prepared whole below */
        f->precision_lost = 0;
        f->detail_prim = RENDER_NO_PRIM;
    }
    return prep_whole(r, pad);
}

render_status_t render_prepare_again(const scene_t *s, uint32_t frame_index, arena_t *arena,
                                     const render_frame_t *prev, render_frame_t **out)
{
    return render_prepare_parts(s, frame_index, arena, prev, RENDER_PREP_WHOLE, out);
}

render_status_t render_prepare_parts(const scene_t *s, uint32_t frame_index, arena_t *arena,
                                     const render_frame_t *prev, enum render_prep_parts parts,
                                     render_frame_t **out)
{
    *out = NULL;
    render_status_t st = prep_check(s);
    if (st != RENDER_OK)
        return st;
    prep_run_t r; /* not cleared (on the board that costs as much as a kept frame's
                     preparation): each step sets what the next ones read */
    r.s = s;
    r.frame_index = frame_index;
    r.arena = arena;
    r.world = s->options.world_space != 0;
    r.screenless = parts == RENDER_PREP_NO_SCREEN;
    st = prep_frame_alloc(&r, prev);
    if (st != RENDER_OK)
        return st;
    prep_frame_header(&r);
    if (r.may_keep && !r.world)
        r.may_keep = prep_same_view(&r);
    st = prep_scratch(&r);
    if (st != RENDER_OK)
        return st;
    xform_t world_to_eye, eye_to_world;
    st = prep_view(&r, &world_to_eye, &eye_to_world);
    if (st != RENDER_OK)
        return st;
    if (prep_keep_whole(&r)) {
        *out = r.f;
        return RENDER_OK;
    }
    return prep_maps_and_prims(&r, out);
}
