/* render/maps.c: texel lookups for colour, bump, normal and attribute
 * maps. */
#include "render/maps.h"

#include "proto/scene_format.h"
#include "render/vec3.h"

/* Texel coordinate along one axis: fractional position in texels of
 * frac(coord * repeat) over size texels, minus 1/2 so texel centres sit at
 * integers.  *i is the texel left of it, *w the weight of the right one. */
static void map_axis(num_t coord, num_t repeat, uint16_t size, int32_t *i, num_t *w)
{
    num_t c = num_mul(coord, repeat);
    num_t frac = num_sub(c, num_from_int(num_floor_int(c)));
    num_t pos = num_sub(num_mul_int(frac, size), NUM_HALF);
    int32_t base = num_floor_int(pos);
    *w = num_sub(pos, num_from_int(base));
    *i = base;
}

static int32_t map_wrap(int32_t i, uint16_t size)
{
    int32_t r = i % size;
    return r < 0 ? r + size : r;
}

static num_t map_byte(uint8_t b) { return num_from_ratio(b, 255); }

/* Bilinear value of byte c of the bpt-byte texels around texel (x, y),
 * weights wx, wy towards x + 1, y + 1. */
static num_t map_bilinear(const scene_map_t *m, int32_t x, int32_t y, num_t wx, num_t wy,
                          unsigned bpt, unsigned c)
{
    num_t row[2];
    for (int dy = 0; dy < 2; dy++) {
        const uint8_t *line = m->texels + (size_t)map_wrap(y + dy, m->height) * m->width * bpt;
        num_t a = map_byte(line[(size_t)map_wrap(x, m->width) * bpt + c]);
        num_t b = map_byte(line[(size_t)map_wrap(x + 1, m->width) * bpt + c]);
        row[dy] = num_lerp(a, b, wx);
    }
    return num_lerp(row[0], row[1], wy);
}

rgb_t map_colour(const scene_map_t *m, num_t u, num_t v)
{
    int32_t x, y;
    num_t wx, wy;
    map_axis(u, m->repeat_u, m->width, &x, &wx);
    map_axis(v, m->repeat_v, m->height, &y, &wy);
    num_t ch[3];
    for (unsigned c = 0; c < 3; c++)
        ch[c] = map_bilinear(m, x, y, wx, wy, 3, c);
    return rgb_make(ch[0], ch[1], ch[2]);
}

num_t map_attribute(const scene_map_t *m, num_t u, num_t v)
{
    int32_t x, y;
    num_t wx, wy;
    map_axis(u, m->repeat_u, m->width, &x, &wx);
    map_axis(v, m->repeat_v, m->height, &y, &wy);
    return map_bilinear(m, x, y, wx, wy, 1, 0);
}

/* The texel nearest (u, v): *x, *y (not yet wrapped). */
static void map_nearest(const scene_map_t *m, num_t u, num_t v, int32_t *x, int32_t *y)
{
    num_t wx, wy;
    map_axis(u, m->repeat_u, m->width, x, &wx);
    map_axis(v, m->repeat_v, m->height, y, &wy);
    if (num_ge(wx, NUM_HALF))
        (*x)++;
    if (num_ge(wy, NUM_HALF))
        (*y)++;
}

static const uint8_t *map_texel(const scene_map_t *m, int32_t x, int32_t y)
{
    size_t bpt = scene_map_texel_bytes(m->kind);
    return m->texels + ((size_t)map_wrap(y, m->height) * m->width + (size_t)map_wrap(x, m->width)) * bpt;
}

/* A NORMAL texel's signed byte as a component: b / SCN_MAP_NORMAL_ONE. */
static num_t map_normal_component(uint8_t b)
{
    return num_from_ratio(b < 128 ? (int32_t)b : (int32_t)b - 256, SCN_MAP_NORMAL_ONE);
}

vec3_t map_normal(const scene_map_t *m, num_t u, num_t v, vec3_t n, vec3_t tangent, int mirrored)
{
    int32_t x, y;
    map_nearest(m, u, v, &x, &y);
    const uint8_t *t = map_texel(m, x, y);
    if (t[0] == 0 && t[1] == 0) /* (0, 0, z): along n, which is n itself */
        return n;
    vec3_t b = vec3_cross(n, tangent);
    if (mirrored)
        b = vec3_neg(b);
    vec3_t out = vec3_add(vec3_add(vec3_scale(tangent, map_normal_component(t[0])),
                                   vec3_scale(b, map_normal_component(t[1]))),
                          vec3_scale(n, map_normal_component(t[2])));
    return vec3_normalize(out);
}

static int32_t map_height(const scene_map_t *m, int32_t x, int32_t y)
{
    return m->texels[(size_t)map_wrap(y, m->height) * m->width + (size_t)map_wrap(x, m->width)];
}

vec3_t map_bump(const scene_map_t *m, num_t u, num_t v, vec3_t n, vec3_t tangent)
{
    int32_t x, y;
    map_nearest(m, u, v, &x, &y);
    num_t su = num_from_ratio(map_height(m, x + 1, y) - map_height(m, x - 1, y), 2 * 255);
    num_t sv = num_from_ratio(map_height(m, x, y + 1) - map_height(m, x, y - 1), 2 * 255);
    vec3_t b = vec3_cross(n, tangent);
    vec3_t tilt = vec3_add(vec3_scale(tangent, su), vec3_scale(b, sv));
    return vec3_normalize(vec3_sub(n, vec3_scale(tilt, m->bump_depth)));
}

num_t map_texel_error(const scene_map_t *m, num_t uv_error)
{
    num_t step = num_add(num_mul_int(num_ulp(NUM_ONE), 8), uv_error);
    num_t side = num_from_int(m->width > m->height ? m->width : m->height);
    num_t repeat = num_max(m->repeat_u, m->repeat_v);
    return num_mul(num_mul(step, repeat), side);
}

int map_imprecise(const scene_map_t *m, num_t uv_error)
{
    num_t texels = map_texel_error(m, uv_error);
    return num_is_sat(texels) || num_gt(texels, NUM_C(RENDER_MAP_TEXEL_TOLERANCE_VALUE));
}

/* Where a nearest-texel lookup at (u, v) with uv_error falls: 1 when its
 * error is half a texel or more (or saturated), so any texel may be taken;
 * else 0, with the texel and fraction of each axis (map_axis) and whether a
 * texel border lies closer than the error in each. */
static int map_lookup_spread(const scene_map_t *m, num_t u, num_t v, num_t uv_error, int32_t *x,
                             int32_t *y, num_t *wx, num_t *wy, int *near_x, int *near_y)
{
    num_t texels = map_texel_error(m, uv_error);
    if (num_is_sat(texels) || !num_lt(texels, NUM_HALF))
        return 1;
    map_axis(u, m->repeat_u, m->width, x, wx);
    map_axis(v, m->repeat_v, m->height, y, wy);
    *near_x = num_lt(num_abs(num_sub(*wx, NUM_HALF)), texels);
    *near_y = num_lt(num_abs(num_sub(*wy, NUM_HALF)), texels);
    return 0;
}

int map_bump_uncertain(const scene_map_t *m, num_t u, num_t v, num_t uv_error)
{
    int32_t x, y;
    num_t wx, wy;
    int near_x, near_y;
    if (map_lookup_spread(m, u, v, uv_error, &x, &y, &wx, &wy, &near_x, &near_y))
        return 1;
    return near_x || near_y;
}

int map_normal_uncertain(const scene_map_t *m, num_t u, num_t v, num_t uv_error)
{
    int32_t x, y;
    num_t wx, wy;
    int near_x, near_y;
    if (map_lookup_spread(m, u, v, uv_error, &x, &y, &wx, &wy, &near_x, &near_y))
        return 1;
    /* the columns and rows the lookup may take: the nearest, and across a
     * texel border closer than the error both sides of it */
    int32_t x0 = near_x ? x : x + num_ge(wx, NUM_HALF), x1 = near_x ? x + 1 : x0;
    int32_t y0 = near_y ? y : y + num_ge(wy, NUM_HALF), y1 = near_y ? y + 1 : y0;
    const uint8_t *first = map_texel(m, x0, y0);
    for (int32_t j = y0; j <= y1; j++)
        for (int32_t i = x0; i <= x1; i++) {
            const uint8_t *t = map_texel(m, i, j);
            if (t[0] != first[0] || t[1] != first[1] || t[2] != first[2])
                return 1;
        }
    return 0;
}
