/* render/maps.c: texel lookups for colour and bump maps. */
#include "render/maps.h"

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

rgb_t map_colour(const scene_map_t *m, num_t u, num_t v)
{
    int32_t x, y;
    num_t wx, wy;
    map_axis(u, m->repeat_u, m->width, &x, &wx);
    map_axis(v, m->repeat_v, m->height, &y, &wy);
    num_t ch[3];
    for (int c = 0; c < 3; c++) {
        num_t row[2];
        for (int dy = 0; dy < 2; dy++) {
            const uint8_t *line = m->texels + (size_t)map_wrap(y + dy, m->height) * m->width * 3;
            num_t a = map_byte(line[(size_t)map_wrap(x, m->width) * 3 + c]);
            num_t b = map_byte(line[(size_t)map_wrap(x + 1, m->width) * 3 + c]);
            row[dy] = num_lerp(a, b, wx);
        }
        ch[c] = num_lerp(row[0], row[1], wy);
    }
    return rgb_make(ch[0], ch[1], ch[2]);
}

static int32_t map_height(const scene_map_t *m, int32_t x, int32_t y)
{
    return m->texels[(size_t)map_wrap(y, m->height) * m->width + (size_t)map_wrap(x, m->width)];
}

vec3_t map_bump(const scene_map_t *m, num_t u, num_t v, vec3_t n, vec3_t tangent)
{
    int32_t x, y;
    num_t wx, wy;
    map_axis(u, m->repeat_u, m->width, &x, &wx);
    map_axis(v, m->repeat_v, m->height, &y, &wy);
    /* nearest texel centre */
    if (num_ge(wx, NUM_HALF))
        x++;
    if (num_ge(wy, NUM_HALF))
        y++;
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

int map_bump_uncertain(const scene_map_t *m, num_t u, num_t v, num_t uv_error)
{
    num_t texels = map_texel_error(m, uv_error);
    if (num_is_sat(texels) || !num_lt(texels, NUM_HALF))
        return 1;
    int32_t x, y;
    num_t wx, wy;
    map_axis(u, m->repeat_u, m->width, &x, &wx);
    map_axis(v, m->repeat_v, m->height, &y, &wy);
    return num_lt(num_abs(num_sub(wx, NUM_HALF)), texels) ||
           num_lt(num_abs(num_sub(wy, NUM_HALF)), texels);
}
