/* render/vec3.h: 3-vectors, colours and affine maps over num_t. */
#ifndef LINKS1_RENDER_VEC3_H
#define LINKS1_RENDER_VEC3_H

#include "fixed/num.h"
#include "render/scene.h"

static inline vec3_t vec3_make(num_t x, num_t y, num_t z)
{
    vec3_t v = {x, y, z};
    return v;
}
static inline vec3_t vec3_add(vec3_t a, vec3_t b)
{
    return vec3_make(num_add(a.x, b.x), num_add(a.y, b.y), num_add(a.z, b.z));
}
static inline vec3_t vec3_sub(vec3_t a, vec3_t b)
{
    return vec3_make(num_sub(a.x, b.x), num_sub(a.y, b.y), num_sub(a.z, b.z));
}
static inline vec3_t vec3_scale(vec3_t a, num_t s)
{
    return vec3_make(num_mul(a.x, s), num_mul(a.y, s), num_mul(a.z, s));
}
static inline vec3_t vec3_neg(vec3_t a) { return vec3_make(num_neg(a.x), num_neg(a.y), num_neg(a.z)); }

/* Componentwise least and greatest. */
static inline vec3_t vec3_min(vec3_t a, vec3_t b)
{
    return vec3_make(num_min(a.x, b.x), num_min(a.y, b.y), num_min(a.z, b.z));
}
static inline vec3_t vec3_max(vec3_t a, vec3_t b)
{
    return vec3_make(num_max(a.x, b.x), num_max(a.y, b.y), num_max(a.z, b.z));
}
/* a + b*s */
static inline vec3_t vec3_madd(vec3_t a, vec3_t b, num_t s) { return vec3_add(a, vec3_scale(b, s)); }
static inline num_t vec3_dot(vec3_t a, vec3_t b) { return num_dot3(a.x, a.y, a.z, b.x, b.y, b.z); }
static inline vec3_t vec3_cross(vec3_t a, vec3_t b)
{
    return vec3_make(num_sub(num_mul(a.y, b.z), num_mul(a.z, b.y)),
                     num_sub(num_mul(a.z, b.x), num_mul(a.x, b.z)),
                     num_sub(num_mul(a.x, b.y), num_mul(a.y, b.x)));
}
static inline num_t vec3_length(vec3_t a) { return num_len3(a.x, a.y, a.z); }
/* Unit vector along a; the zero vector stays zero. */
static inline vec3_t vec3_normalize(vec3_t a)
{
#if defined(LINKS1_NUM_FIXED)
    num_t len = vec3_length(a);
    if (!num_gt(len, NUM_ZERO))
        return a;
#else
    /* the IEEE square root is above 0 exactly when its operand is: one
     * test, not two (the DM normalises five vectors a triangle a frame) */
    num_t sq = num_dot3(a.x, a.y, a.z, a.x, a.y, a.z);
    if (!num_gt(sq, NUM_ZERO))
        return a;
    num_t len = num_sqrt(sq);
#endif
    return vec3_make(num_div(a.x, len), num_div(a.y, len), num_div(a.z, len));
}
static inline int vec3_is_sat(vec3_t a) { return num_any_sat3(a.x, a.y, a.z); }
static inline num_t vec3_get(vec3_t a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
static inline void vec3_set(vec3_t *a, int axis, num_t v)
{
    if (axis == 0)
        a->x = v;
    else if (axis == 1)
        a->y = v;
    else
        a->z = v;
}

static inline rgb_t rgb_make(num_t r, num_t g, num_t b)
{
    rgb_t c = {r, g, b};
    return c;
}
static inline rgb_t rgb_add(rgb_t a, rgb_t b) { return rgb_make(num_add(a.r, b.r), num_add(a.g, b.g), num_add(a.b, b.b)); }
static inline rgb_t rgb_mul(rgb_t a, rgb_t b) { return rgb_make(num_mul(a.r, b.r), num_mul(a.g, b.g), num_mul(a.b, b.b)); }
static inline rgb_t rgb_scale(rgb_t a, num_t s) { return rgb_make(num_mul(a.r, s), num_mul(a.g, s), num_mul(a.b, s)); }
static inline int rgb_is_sat(rgb_t a) { return num_any_sat3(a.r, a.g, a.b); }
static inline int rgb_is_zero(rgb_t a)
{
    return !num_gt(a.r, NUM_ZERO) && !num_gt(a.g, NUM_ZERO) && !num_gt(a.b, NUM_ZERO);
}

/* Affine maps (xform.c).  Applied inline: m to the direction d (its 3x3
 * part), to the point p, and its 3x3 part's transpose to d (normals
 * through an inverse map); the DM maps every vertex of every frame, the
 * NCs a ray or a normal at every test and hit. */
static inline vec3_t xform_dir_inline(const xform_t *m, vec3_t d)
{
    return vec3_make(num_dot3(m->m[0][0], m->m[0][1], m->m[0][2], d.x, d.y, d.z),
                     num_dot3(m->m[1][0], m->m[1][1], m->m[1][2], d.x, d.y, d.z),
                     num_dot3(m->m[2][0], m->m[2][1], m->m[2][2], d.x, d.y, d.z));
}
static inline vec3_t xform_point_inline(const xform_t *m, vec3_t p)
{
    vec3_t d = xform_dir_inline(m, p);
    return vec3_make(num_add(d.x, m->m[0][3]), num_add(d.y, m->m[1][3]), num_add(d.z, m->m[2][3]));
}
static inline vec3_t xform_dir(const xform_t *m, vec3_t d) { return xform_dir_inline(m, d); }
static inline vec3_t xform_point(const xform_t *m, vec3_t p) { return xform_point_inline(m, p); }
static inline vec3_t xform_dir_transposed(const xform_t *m, vec3_t d)
{
    return vec3_make(num_dot3(m->m[0][0], m->m[1][0], m->m[2][0], d.x, d.y, d.z),
                     num_dot3(m->m[0][1], m->m[1][1], m->m[2][1], d.x, d.y, d.z),
                     num_dot3(m->m[0][2], m->m[1][2], m->m[2][2], d.x, d.y, d.z));
}
xform_t xform_identity(void);
/* a after b: (a*b)(p) = a(b(p)). */
xform_t xform_compose(const xform_t *a, const xform_t *b);
/* Inverse of m into *out; 0 if m is singular (or too ill-conditioned). */
int xform_invert(const xform_t *m, xform_t *out);
/* translate * rotate(unit quaternion w,x,y,z) * scale */
xform_t xform_from_trs(vec3_t t, num_t qw, num_t qx, num_t qy, num_t qz, vec3_t s);
int xform_is_sat(const xform_t *m);

#endif
