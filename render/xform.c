/* render/xform.c: affine maps: apply, compose, invert, build from keys. */
#include "render/vec3.h"

/* Bounds the power of two a row or column is scaled by before inversion
 * (float builds: far inside the exponent range). */
#define XFORM_MAX_EXPONENT 60

xform_t xform_identity(void)
{
    xform_t m;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++)
            m.m[r][c] = r == c ? NUM_ONE : NUM_ZERO;
    return m;
}

xform_t xform_compose(const xform_t *a, const xform_t *b)
{
    xform_t r;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++)
            r.m[i][j] = num_dot3(a->m[i][0], a->m[i][1], a->m[i][2],
                                 b->m[0][j], b->m[1][j], b->m[2][j]);
        r.m[i][3] = num_add(r.m[i][3], a->m[i][3]);
    }
    return r;
}

int xform_is_sat(const xform_t *m)
{
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++)
            if (num_is_sat(m->m[r][c]))
                return 1;
    return 0;
}

/* The power of two that brings big (> 0) into [1/2, 2). */
static int xform_unit_exponent(num_t big)
{
    int k = 0;
    if (num_eq(big, NUM_ZERO) || num_is_sat(big))
        return 0;
    while (num_lt(big, NUM_HALF) && k < XFORM_MAX_EXPONENT) {
        big = num_scale2(big, 1);
        k++;
    }
    while (num_ge(big, NUM_C(2)) && k > -XFORM_MAX_EXPONENT) {
        big = num_scale2(big, -1);
        k--;
    }
    return k;
}

/* Cofactor inverse.  The map is first brought to about unit size, rows
 * then columns, by powers of two (A = Dr m Dc, inverse(m) = Dc inverse(A)
 * Dr): in fixed point the cofactors and determinant of a map scaled by
 * 0.1 would otherwise keep only a few hundred steps (m inverse(m) off the
 * identity by 606 steps of Q12.19, 4 now) and maps scaled by 0.03 or 20
 * could not be inverted at all (test_render test_inverse_precision); in
 * float the scaling is exact and changes no bit.  The determinant is
 * divided out of each cofactor separately (cofactor / det), not through
 * 1/det, which would lose the fixed build's precision for large
 * determinants. */
int xform_invert(const xform_t *m, xform_t *out)
{
    int kr[3], kc[3];
    for (int r = 0; r < 3; r++)
        kr[r] = xform_unit_exponent(num_max(num_abs(m->m[r][0]),
                                            num_max(num_abs(m->m[r][1]), num_abs(m->m[r][2]))));
    for (int c = 0; c < 3; c++) {
        num_t big = NUM_ZERO;
        for (int r = 0; r < 3; r++)
            big = num_max(big, num_abs(num_scale2(m->m[r][c], kr[r])));
        kc[c] = xform_unit_exponent(big);
    }
    num_t a[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            a[r][c] = num_scale2(m->m[r][c], kr[r] + kc[c]);
    num_t c00 = num_sub(num_mul(a[1][1], a[2][2]), num_mul(a[1][2], a[2][1]));
    num_t c01 = num_sub(num_mul(a[1][2], a[2][0]), num_mul(a[1][0], a[2][2]));
    num_t c02 = num_sub(num_mul(a[1][0], a[2][1]), num_mul(a[1][1], a[2][0]));
    num_t det = num_dot3(a[0][0], a[0][1], a[0][2], c00, c01, c02);
    if (num_is_sat(det) || num_eq(det, NUM_ZERO))
        return 0;
    num_t inv[3][3];
    inv[0][0] = c00;
    inv[1][0] = c01;
    inv[2][0] = c02;
    inv[0][1] = num_sub(num_mul(a[0][2], a[2][1]), num_mul(a[0][1], a[2][2]));
    inv[1][1] = num_sub(num_mul(a[0][0], a[2][2]), num_mul(a[0][2], a[2][0]));
    inv[2][1] = num_sub(num_mul(a[0][1], a[2][0]), num_mul(a[0][0], a[2][1]));
    inv[0][2] = num_sub(num_mul(a[0][1], a[1][2]), num_mul(a[0][2], a[1][1]));
    inv[1][2] = num_sub(num_mul(a[0][2], a[1][0]), num_mul(a[0][0], a[1][2]));
    inv[2][2] = num_sub(num_mul(a[0][0], a[1][1]), num_mul(a[0][1], a[1][0]));
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            out->m[r][c] = num_scale2(num_div(inv[r][c], det), kc[r] + kr[c]);
    vec3_t t = vec3_make(m->m[0][3], m->m[1][3], m->m[2][3]);
    vec3_t it = xform_dir(out, t);
    out->m[0][3] = num_neg(it.x);
    out->m[1][3] = num_neg(it.y);
    out->m[2][3] = num_neg(it.z);
    return !xform_is_sat(out);
}

xform_t xform_from_trs(vec3_t t, num_t w, num_t x, num_t y, num_t z, vec3_t s)
{
    /* rotation matrix of a unit quaternion */
    num_t two = NUM_C(2);
    num_t xx = num_mul(x, x), yy = num_mul(y, y), zz = num_mul(z, z);
    num_t xy = num_mul(x, y), xz = num_mul(x, z), yz = num_mul(y, z);
    num_t wx = num_mul(w, x), wy = num_mul(w, y), wz = num_mul(w, z);
    num_t r[3][3] = {
        {num_sub(NUM_ONE, num_mul(two, num_add(yy, zz))), num_mul(two, num_sub(xy, wz)), num_mul(two, num_add(xz, wy))},
        {num_mul(two, num_add(xy, wz)), num_sub(NUM_ONE, num_mul(two, num_add(xx, zz))), num_mul(two, num_sub(yz, wx))},
        {num_mul(two, num_sub(xz, wy)), num_mul(two, num_add(yz, wx)), num_sub(NUM_ONE, num_mul(two, num_add(xx, yy)))},
    };
    num_t sc[3] = {s.x, s.y, s.z};
    xform_t m;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m.m[i][j] = num_mul(r[i][j], sc[j]);
    m.m[0][3] = t.x;
    m.m[1][3] = t.y;
    m.m[2][3] = t.z;
    return m;
}
