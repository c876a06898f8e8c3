/* test_shade.c: the terms of the paper's Fig. 5, src/trc, lights, mirror
 * and Snell directions, and the maps, against hand-computed values. */
#include <string.h>

#include "render/maps.h"
#include "render/prim.h"
#include "render/shade.h"
#include "render/vec3.h"
#include "tests/check.h"
#include "tests/host/test_render_scene.h"

#if defined(LINKS1_NUM_FIXED)
#define TOL 2e-4
#elif defined(LINKS1_NUM_FLOAT)
#define TOL 2e-6
#else
#define TOL 1e-12
#endif

#define N(x) num_from_double(x)
#define D(x) num_to_double(x)

static scene_material_t material(double dic, double drc, double src, double trc, double fresnel, int n)
{
    scene_material_t m;
    memset(&m, 0, sizeof m);
    m.colour = ts_rgb(1, 0.5, 0.25);
    m.dic = N(dic);
    m.drc = N(drc);
    m.src = N(src);
    m.trc = N(trc);
    m.fresnel = N(fresnel);
    m.phong_n = (uint16_t)n;
    m.ior = NUM_ONE;
    scene_material_no_maps(&m);
    return m;
}

static void test_src_trc(void)
{
    scene_material_t m = material(0, 0, 0.2, 0.6, 0, 0);
    num_t src, trc;
    shade_src_trc(&m, N(0.3), &src, &trc); /* fresnel 0: constants */
    CHECK_NEAR(D(src), 0.2, TOL);
    CHECK_NEAR(D(trc), 0.6, TOL);
    m.fresnel = NUM_ONE;
    shade_src_trc(&m, NUM_ONE, &src, &trc); /* normal incidence: the base values */
    CHECK_NEAR(D(src), 0.2, TOL);
    CHECK_NEAR(D(trc), 0.6, TOL);
    shade_src_trc(&m, NUM_ZERO, &src, &trc); /* grazing: all reflected */
    CHECK_NEAR(D(src), 1.0, TOL);
    CHECK_NEAR(D(trc), 0.0, TOL);
    shade_src_trc(&m, N(0.5), &src, &trc); /* s = 0.5^5 */
    CHECK_NEAR(D(src), 0.2 + 0.8 * 0.03125, TOL);
    CHECK_NEAR(D(trc), 0.6 * (1 - 0.03125), TOL);
    m.fresnel = N(0.5); /* half weight */
    shade_src_trc(&m, N(0.5), &src, &trc);
    CHECK_NEAR(D(src), 0.2 + 0.8 * 0.015625, TOL);
}

static void test_light_term(void)
{
    scene_material_t m = material(0.2, 0.7, 0.4, 0, 0, 2);
    vec3_t n = ts_v(0, 0, -1), view = ts_v(0, 0, 1);
    rgb_t white = ts_rgb(1, 1, 1), black = ts_rgb(0, 0, 0), green = ts_rgb(0, 1, 0);
    /* head-on: ambient 0.2 F + diffuse 0.7 F + highlight 1^2 * src */
    rgb_t c = shade_light_term(&m, m.colour, n, view, ts_v(0, 0, -1), &white, white, m.src);
    CHECK_NEAR(D(c.r), 0.9 * 1 + 0.4, TOL);
    CHECK_NEAR(D(c.g), 0.9 * 0.5 + 0.4, TOL);
    CHECK_NEAR(D(c.b), 0.9 * 0.25 + 0.4, TOL);
    /* light 60 degrees off: cos 0.5; mirrored light makes 60 degrees with
     * the view too: highlight 0.5^2 src */
    vec3_t l = ts_v(sqrt(0.75), 0, -0.5);
    c = shade_light_term(&m, m.colour, n, view, l, &white, white, m.src);
    CHECK_NEAR(D(c.r), 0.2 + 0.35 + 0.25 * 0.4, TOL);
    CHECK_NEAR(D(c.b), (0.2 + 0.35) * 0.25 + 0.25 * 0.4, TOL);
    /* fully shadowed: ambient only, from the unshadowed light */
    c = shade_light_term(&m, m.colour, n, view, l, &white, black, m.src);
    CHECK_NEAR(D(c.r), 0.2, TOL);
    CHECK_NEAR(D(c.g), 0.1, TOL);
    /* tinted shadow light (0.5, 0, 0): diffuse and highlight scaled by it */
    c = shade_light_term(&m, m.colour, n, view, l, &white, ts_rgb(0.5, 0, 0), m.src);
    CHECK_NEAR(D(c.r), 0.2 + 0.5 * (0.35 + 0.1), TOL);
    CHECK_NEAR(D(c.g), 0.1, TOL);
    /* light behind the surface: ambient only */
    c = shade_light_term(&m, m.colour, n, view, ts_v(0, 0, 1), &white, white, m.src);
    CHECK_NEAR(D(c.r), 0.2, TOL);
    /* coloured light multiplies the colour */
    c = shade_light_term(&m, m.colour, n, view, ts_v(0, 0, -1), &green, green, m.src);
    CHECK_NEAR(D(c.r), 0.0, TOL);
    CHECK_NEAR(D(c.g), 0.9 * 0.5 + 0.4, TOL);
    /* no ambient light of its own (NULL): the shadowed light's, the same bits */
    rgb_t same = shade_light_term(&m, m.colour, n, view, l, NULL, green, m.src);
    c = shade_light_term(&m, m.colour, n, view, l, &green, green, m.src);
    CHECK(num_eq(same.r, c.r) && num_eq(same.g, c.g) && num_eq(same.b, c.b));
    CHECK_NEAR(D(same.g), 0.5 * (0.2 + 0.35) + 0.25 * 0.4, TOL);
    /* n = 0: no highlight */
    m.phong_n = 0;
    c = shade_light_term(&m, m.colour, n, view, ts_v(0, 0, -1), NULL, white, m.src);
    CHECK_NEAR(D(c.r), 0.9, TOL);
}

static void test_lights(void)
{
    render_light_t l;
    memset(&l, 0, sizeof l);
    l.kind = SCENE_LIGHT_POINT;
    l.intensity = ts_rgb(1, 1, 1);
    l.position = ts_v(0, 10, 0);
    vec3_t dir;
    num_t dist;
    rgb_t in;
    CHECK(shade_light_at(&l, ts_v(0, 0, 0), &dir, &dist, &in));
    CHECK_NEAR(D(dist), 10, TOL * 10);
    CHECK_NEAR(D(dir.y), 1, TOL);
    CHECK_NEAR(D(in.r), 1, TOL); /* no distance falloff */
    /* spotlight pointing down, full inside cos 0.9, none outside cos 0.8 */
    l.kind = SCENE_LIGHT_SPOT;
    l.axis = ts_v(0, -1, 0);
    l.cos_inner = N(0.9);
    l.cos_outer = N(0.8);
    CHECK(shade_light_at(&l, ts_v(0, 0, 0), &dir, &dist, &in));
    CHECK_NEAR(D(in.g), 1, TOL);
    /* cos 0.85: halfway, smoothstep(0.5) = 0.5 */
    double x = 10 * sqrt(1 - 0.85 * 0.85) / 0.85;
    CHECK(shade_light_at(&l, ts_v(x, 0, 0), &dir, &dist, &in));
    CHECK_NEAR(D(in.g), 0.5, TOL * 50);
    CHECK(!shade_light_at(&l, ts_v(20, 0, 0), &dir, &dist, &in)); /* outside the cone */
    CHECK_NEAR(D(shade_spot_falloff(N(0.8), N(0.8), N(0.9))), 0, 0);
    CHECK_NEAR(D(shade_spot_falloff(N(0.825), N(0.8), N(0.9))), 0.25 * 0.25 * 2.5, TOL * 10);
    /* parallel light: direction fixed, far away */
    l.kind = SCENE_LIGHT_PARALLEL;
    l.to_light = ts_v(0, 1, 0);
    CHECK(shade_light_at(&l, ts_v(5, 5, 5), &dir, &dist, &in));
    CHECK_NEAR(D(dir.y), 1, 0);
    CHECK(D(dist) >= 1000);
}

static void test_reflect_refract(void)
{
    double s = sqrt(0.5);
    vec3_t r = shade_reflect(ts_v(s, -s, 0), ts_v(0, 1, 0));
    CHECK_NEAR(D(r.x), s, TOL);
    CHECK_NEAR(D(r.y), s, TOL);
    /* 30 degrees into glass of index 1.5: sin t = 0.5/1.5 */
    vec3_t t;
    CHECK(shade_refract(ts_v(0.5, -sqrt(0.75), 0), ts_v(0, 1, 0), N(1 / 1.5), &t));
    CHECK_NEAR(D(t.x), 1 / 3.0, TOL * 5);
    CHECK_NEAR(D(t.y), -sqrt(1 - 1 / 9.0), TOL * 5);
    /* normal incidence goes straight */
    CHECK(shade_refract(ts_v(0, -1, 0), ts_v(0, 1, 0), N(1 / 1.5), &t));
    CHECK_NEAR(D(t.y), -1, TOL);
    /* leaving glass at 60 degrees: 1.5 sin 60 > 1, total internal reflection */
    CHECK(!shade_refract(ts_v(sqrt(0.75), -0.5, 0), ts_v(0, 1, 0), N(1.5), &t));
    /* just below the critical angle (41.8 degrees) still refracts */
    CHECK(shade_refract(ts_v(0.66, -sqrt(1 - 0.66 * 0.66), 0), ts_v(0, 1, 0), N(1.5), &t));
}

static void test_colour_map(void)
{
    /* 2x1 map: red, green; texel centres at u = 0.25 and 0.75 */
    static const uint8_t texels[] = {255, 0, 0, 0, 255, 0};
    scene_map_t m = {SCENE_MAP_COLOUR, 2, 1, texels, NUM_ONE, NUM_ONE, NUM_ZERO};
    rgb_t c = map_colour(&m, N(0.25), N(0.5));
    CHECK_NEAR(D(c.r), 1, TOL);
    CHECK_NEAR(D(c.g), 0, TOL);
    c = map_colour(&m, N(0.75), N(0.5));
    CHECK_NEAR(D(c.g), 1, TOL);
    c = map_colour(&m, N(0.5), N(0.5)); /* halfway: bilinear mix */
    CHECK_NEAR(D(c.r), 0.5, TOL);
    CHECK_NEAR(D(c.g), 0.5, TOL);
    c = map_colour(&m, N(0.0), N(0.5)); /* wraps: between green and red */
    CHECK_NEAR(D(c.r), 0.5, TOL);
    c = map_colour(&m, N(1.25), N(0.5)); /* repeats */
    CHECK_NEAR(D(c.r), 1, TOL);
    m.repeat_u = N(2); /* two tiles: u = 0.125 is the first texel centre */
    c = map_colour(&m, N(0.125 + 0.5), N(0.5));
    CHECK_NEAR(D(c.r), 1, TOL);
}

static void test_bump_map(void)
{
    static const uint8_t flat[] = {7, 7, 7, 7, 7, 7, 7, 7, 7};
    static const uint8_t ramp[] = {0, 51, 102, 0, 51, 102, 0, 51, 102}; /* rises along u */
    scene_map_t m = {SCENE_MAP_BUMP, 3, 3, flat, NUM_ONE, NUM_ONE, N(2)};
    vec3_t n = ts_v(0, 0, -1), t = ts_v(1, 0, 0);
    vec3_t b = map_bump(&m, N(0.5), N(0.5), n, t);
    CHECK_NEAR(D(b.x), 0, TOL);
    CHECK_NEAR(D(b.z), -1, TOL);
    /* centre texel: su = (102 - 0) / 510 = 0.2; n - 2*0.2*T = (-0.4, 0, -1) */
    m.texels = ramp;
    b = map_bump(&m, N(0.5), N(0.5), n, t);
    double len = sqrt(0.16 + 1);
    CHECK_NEAR(D(b.x), -0.4 / len, TOL * 5);
    CHECK_NEAR(D(b.y), 0, TOL);
    CHECK_NEAR(D(b.z), -1 / len, TOL * 5);
}

/* Exactly the same number (every arithmetic's num_t converts exactly). */
#define SAME(a, b) CHECK(D(a) == D(b))
#define SAME_VEC(a, b) CHECK(D((a).x) == D((b).x) && D((a).y) == D((b).y) && D((a).z) == D((b).z))

static void test_normal_map(void)
{
    /* the flat normal (0, 0, 1) gives n itself, bit for bit, anywhere */
    static const uint8_t flat[] = {0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127};
    scene_map_t m = {SCENE_MAP_NORMAL, 2, 2, flat, N(3), N(3), NUM_ZERO};
    vec3_t n = vec3_normalize(ts_v(0.3, -0.5, 0.8));
    vec3_t t = vec3_normalize(vec3_cross(n, ts_v(0, 1, 0)));
    for (int i = 0; i < 5; i++) {
        vec3_t got = map_normal(&m, N(0.13 * i), N(0.41 - 0.07 * i), n, t, 0);
        SAME_VEC(got, n);
    }
    /* tilted texels in the frame T, B = n x T, n: with n = -z, T = x, B = -y */
    n = ts_v(0, 0, -1);
    t = ts_v(1, 0, 0);
    double h = sqrt(0.5);
    static const uint8_t tilt_x[] = {90, 0, 90};
    static const uint8_t tilt_minus_x[] = {256 - 90, 0, 90};
    static const uint8_t tilt_y[] = {0, 90, 90};
    m = (scene_map_t){SCENE_MAP_NORMAL, 1, 1, tilt_x, NUM_ONE, NUM_ONE, NUM_ZERO};
    vec3_t got = map_normal(&m, N(0.5), N(0.5), n, t, 0);
    CHECK_NEAR(D(got.x), h, TOL * 5);
    CHECK_NEAR(D(got.y), 0, TOL);
    CHECK_NEAR(D(got.z), -h, TOL * 5);
    m.texels = tilt_minus_x;
    got = map_normal(&m, N(0.5), N(0.5), n, t, 0);
    CHECK_NEAR(D(got.x), -h, TOL * 5);
    CHECK_NEAR(D(got.z), -h, TOL * 5);
    m.texels = tilt_y;
    got = map_normal(&m, N(0.5), N(0.5), n, t, 0);
    CHECK_NEAR(D(got.x), 0, TOL);
    CHECK_NEAR(D(got.y), -h, TOL * 5);
    CHECK_NEAR(D(got.z), -h, TOL * 5);
    /* nearest texel, not a blend: a 2x1 map of flat then tilted */
    static const uint8_t two[] = {0, 0, 127, 90, 0, 90};
    m = (scene_map_t){SCENE_MAP_NORMAL, 2, 1, two, NUM_ONE, NUM_ONE, NUM_ZERO};
    SAME_VEC(map_normal(&m, N(0.49), N(0.5), n, t, 0), n);
    got = map_normal(&m, N(0.51), N(0.5), n, t, 0);
    CHECK_NEAR(D(got.x), h, TOL * 5);
}

/* A normal map's frame on a triangle (prim_map_tangent): T along dP/du of
 * its uv, mirrored when u and v turn the other way round n, perpendicular
 * to a smooth normal; a degenerate mapping gives the first edge. */
static void ts_tangent(const double uv[6], vec3_t n, vec3_t *t, int *mirrored, int *uncertain)
{
    render_prim_t p;
    memset(&p, 0, sizeof p);
    p.kind = SCENE_PRIM_TRIANGLE;
    p.e1 = ts_v(2, 0, 0);
    p.e2 = ts_v(0, 2, 0);
    for (int k = 0; k < 3; k++)
        p.tex_u[k] = N(uv[2 * k]), p.tex_v[k] = N(uv[2 * k + 1]);
    hit_t h;
    memset(&h, 0, sizeof h);
    h.normal = n;
    *t = prim_map_tangent(&p, &h, mirrored, uncertain);
}

static void test_map_tangent(void)
{
    vec3_t n = ts_v(0, 0, 1), t;
    int mir, unc;
    /* u grows from vertex 2 to 0 (along -e2), v from 0 to 1 (along e1):
     * T = -y, and n x T = +x is dP/dv, down the picture: mirrored */
    static const double turned[6] = {1, 0, 1, 1, 0, 0};
    ts_tangent(turned, n, &t, &mir, &unc);
    CHECK_NEAR(D(t.x), 0, TOL);
    CHECK_NEAR(D(t.y), -1, TOL);
    CHECK(mir == 1 && unc == 0);
    /* u along e2, v along e1: T = +y, n x T = -x, up the picture */
    static const double plain[6] = {0, 0, 0, 1, 1, 0};
    ts_tangent(plain, n, &t, &mir, &unc);
    CHECK_NEAR(D(t.y), 1, TOL);
    CHECK(mir == 0 && unc == 0);
    /* a smooth normal out of the plane: T made perpendicular to it */
    static const double along_e1[6] = {0, 0, 1, 0, 0, 1};
    vec3_t tilted = vec3_normalize(ts_v(0.3, 0, 1));
    ts_tangent(along_e1, tilted, &t, &mir, &unc);
    CHECK_NEAR(D(vec3_dot(t, tilted)), 0, TOL);
    CHECK_NEAR(D(vec3_length(t)), 1, TOL);
    CHECK(D(t.x) > 0.9 && mir == 1 && unc == 0);
    /* all three uv the same: the first edge, exactly, and no doubt */
    static const double same[6] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    ts_tangent(same, n, &t, &mir, &unc);
    SAME_VEC(t, ts_v(1, 0, 0));
    CHECK(mir == 0 && unc == 0);
    /* on one line but not exactly (0.1 steps round): uncertain */
    static const double line[6] = {0, 0, 0.3, 0.1, 0.6, 0.2};
    ts_tangent(line, n, &t, &mir, &unc);
    CHECK(unc == 1);
}

static void test_normal_map_uncertain(void)
{
    /* 2x1: u = 0.5 is the border between texel 0 (centre 0.25) and 1 */
    static const uint8_t two[] = {0, 0, 127, 90, 0, 90};
    static const uint8_t flat[] = {0, 0, 127, 0, 0, 127};
    scene_map_t m = {SCENE_MAP_NORMAL, 2, 1, two, NUM_ONE, NUM_ONE, NUM_ZERO};
    CHECK(map_normal_uncertain(&m, N(0.5), N(0.5), NUM_ZERO));
    CHECK(!map_normal_uncertain(&m, N(0.25), N(0.5), NUM_ZERO));
    CHECK(!map_normal_uncertain(&m, N(0.75), N(0.5), N(0.01)));
    CHECK(map_normal_uncertain(&m, N(0.51), N(0.5), N(0.02))); /* 0.04 texels off */
    /* (u wraps: u = 0 is the border between texel 1 and texel 0 again) */
    CHECK(map_normal_uncertain(&m, N(0.0), N(0.5), NUM_ZERO));
    /* the same borders of a map whose neighbours hold the same normal: no doubt */
    m.texels = flat;
    CHECK(!map_normal_uncertain(&m, N(0.5), N(0.5), NUM_ZERO));
    CHECK(!map_normal_uncertain(&m, N(0.0), N(0.5), N(0.02)));
    /* an error of half a texel or more: any texel, always in doubt */
    CHECK(map_normal_uncertain(&m, N(0.25), N(0.5), N(0.3)));
}

static void test_attribute_map(void)
{
    /* a constant map gives the constant, bit for bit, everywhere; a map of
     * 1 leaves a coefficient as it is */
    static const uint8_t c102[] = {102, 102, 102, 102, 102, 102};
    static const uint8_t c255[] = {255, 255, 255, 255, 255, 255};
    scene_map_t m = {SCENE_MAP_ATTRIBUTE, 3, 2, c102, N(2), N(5), NUM_ZERO};
    num_t src = N(0.37);
    for (int i = 0; i < 7; i++) {
        num_t u = N(0.11 * i), v = N(0.9 - 0.13 * i);
        m.texels = c102;
        SAME(map_attribute(&m, u, v), num_from_ratio(102, 255));
        m.texels = c255;
        SAME(map_attribute(&m, u, v), NUM_ONE);
        SAME(num_mul(src, map_attribute(&m, u, v)), src);
    }
    /* 2x1 of 0 and 1: texel centres at u = 0.25 and 0.75, bilinear between */
    static const uint8_t two[] = {0, 255};
    m = (scene_map_t){SCENE_MAP_ATTRIBUTE, 2, 1, two, NUM_ONE, NUM_ONE, NUM_ZERO};
    CHECK_NEAR(D(map_attribute(&m, N(0.25), N(0.5))), 0, TOL);
    CHECK_NEAR(D(map_attribute(&m, N(0.75), N(0.5))), 1, TOL);
    CHECK_NEAR(D(map_attribute(&m, N(0.5), N(0.5))), 0.5, TOL);
    CHECK_NEAR(D(map_attribute(&m, N(0.375), N(0.5))), 0.25, TOL);
}

int main(void)
{
    printf("# num_t = %s\n", NUM_NAME);
    RUN(test_src_trc);
    RUN(test_light_term);
    RUN(test_lights);
    RUN(test_reflect_refract);
    RUN(test_colour_map);
    RUN(test_bump_map);
    RUN(test_normal_map);
    RUN(test_map_tangent);
    RUN(test_normal_map_uncertain);
    RUN(test_attribute_map);
    return check_exit();
}
