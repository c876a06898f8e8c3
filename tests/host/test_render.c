/* test_render.c: whole pixels through render_prepare and render_pixel:
 * hand-computed colours, shadows (opaque, untinted and tinted; ambient
 * shadowed or not), mirror (and a mirrored ray a leaning smooth normal
 * sends into the surface: blocked), refraction
 * and refractionless transmission, keyframes, limits, the precision flag,
 * and the speed-ups (hierarchy, boxes, screen clipping) giving the same
 * image bit for bit. */
#include <math.h>
#include <stdlib.h>

#include "render/blob.h"
#include "render/precision.h"
#include "render/prim.h"
#include "tests/check.h"
#include "tests/host/test_render_scene.h"

#define N(x) num_from_double(x)
#define INVERSE_STEPS 16

static test_scene_t ts;

static scene_material_t mat(double r, double g, double b, double dic, double drc)
{
    scene_material_t m;
    memset(&m, 0, sizeof m);
    m.colour = ts_rgb(r, g, b);
    m.dic = N(dic);
    m.drc = N(drc);
    m.ior = NUM_ONE;
    scene_material_no_maps(&m);
    return m;
}

/* A wall facing the camera at z = 10, two triangles wide enough to fill
 * the view (camera at the origin, tan(fov/2) = 0.5). */
static void wall(uint16_t cluster, uint16_t material, double z)
{
    ts_triangle(&ts, cluster, material, ts_v(-20, -20, z), ts_v(20, -20, z), ts_v(-20, 20, z));
    ts_triangle(&ts, cluster, material, ts_v(20, -20, z), ts_v(20, 20, z), ts_v(-20, 20, z));
}

static rgb8_t centre_pixel(render_frame_t *f)
{
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    return render_pixel(&ctx, f->width / 2, f->height / 2);
}

static void test_diffuse_wall(void)
{
    /* parallel light along the view: cos = 1; I = (dic + drc) F L */
    ts_init(&ts, 9, 9);
    uint16_t m = ts_material(&ts, mat(1, 0.6, 0, 0.2, 0.4));
    wall(0, m, 10);
    scene_light_t *l = ts_light(&ts, SCENE_LIGHT_PARALLEL, ts_rgb(1, 1, 1));
    l->direction = ts_v(0, 0, 1);
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    rgb8_t p = centre_pixel(f);
    CHECK_EQ_INT(p.r, 153); /* 0.6 * 255 */
    CHECK_EQ_INT(p.g, 92);  /* 0.36 * 255 = 91.8 */
    CHECK_EQ_INT(p.b, 0);
    /* a second light behind the wall: the wall shadows it from its own
     * front, ambient too (Fig. 5's ambient takes the shadowed light) */
    l = ts_light(&ts, SCENE_LIGHT_PARALLEL, ts_rgb(0.4, 0.4, 0.4));
    l->direction = ts_v(0, 0, -1);
    f = ts_prepare(&ts);
    p = centre_pixel(f);
    CHECK_EQ_INT(p.r, 153);
    /* ambient unshadowed: ambient from each light (the paper has no global
     * ambient) */
    ts.scene.options.ambient_shadowed = 0;
    f = ts_prepare(&ts);
    p = centre_pixel(f);
    CHECK_EQ_INT(p.r, 173); /* (0.6 + 0.2 * 0.4) * 255 = 173.4 */
}

/* RENDER_MAX_LIGHTS (SCN_MAX_LIGHTS, 16) lights of the three kinds, each
 * 1/16 of the light of test_diffuse_wall and each head-on at the wall's
 * centre, light it as that one light does; one more is refused. */
static void test_sixteen_lights(void)
{
    ts_init(&ts, 9, 9);
    uint16_t m = ts_material(&ts, mat(1, 0.6, 0, 0.2, 0.4));
    wall(0, m, 10);
    for (int i = 0; i < RENDER_MAX_LIGHTS; i++) {
        uint8_t kind = i % 3 == 0 ? SCENE_LIGHT_PARALLEL : i % 3 == 1 ? SCENE_LIGHT_POINT
                                                                      : SCENE_LIGHT_SPOT;
        scene_light_t *l = ts_light(&ts, kind, ts_rgb(0.0625, 0.0625, 0.0625));
        l->direction = ts_v(0, 0, 1);
        l->position = ts_v(0, 0, 0.25 * i);
        l->cos_inner = N(0.9);
        l->cos_outer = N(0.8);
    }
    CHECK_EQ_INT(RENDER_MAX_LIGHTS, 16);
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    CHECK_EQ_INT(f->light_count, 16);
    rgb8_t p = centre_pixel(f);
    CHECK_EQ_INT(p.r, 153);
    CHECK_EQ_INT(p.g, 92);
    CHECK_EQ_INT(p.b, 0);
    ts.scene.light_count = RENDER_MAX_LIGHTS + 1;
    arena_reset(&ts.arena);
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_LIGHTS);
}

static void test_shadows(void)
{
    /* wall lit head-on; a small box between the light and the wall's centre */
    ts_init(&ts, 9, 9);
    uint16_t wm = ts_material(&ts, mat(1, 1, 1, 0.2, 0.6));
    wall(0, wm, 10);
    scene_material_t glass = mat(1, 0, 0, 0, 0);
    glass.trc = N(0.5);
    uint16_t bm = ts_material(&ts, glass);
    ts_box(&ts, 0, bm, ts_v(0, 0, 8), ts_v(0.5, 0.5, 0.5));
    scene_light_t *l = ts_light(&ts, SCENE_LIGHT_POINT, ts_rgb(1, 1, 1));
    l->position = ts_v(0, 0, 0.1);
    /* look at the wall from the side so the box does not hide it */
    ts.scene.camera.eye = ts_v(0, 30, 9.5);
    ts.scene.camera.look_at = ts_v(0, 0, 10);
    ts.scene.camera.up = ts_v(0, 0, 1);
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    /* the paper's shadow: light through the box = L * trc = 0.5, grey (the
     * box's one crossing, trc 0.5); wall = (0.2 ambient + 0.6 cos) times
     * the shadowed light, cos 1 at the wall's centre: 0.4 */
    rgb8_t p = centre_pixel(f);
    CHECK_EQ_INT(p.r, 102);
    CHECK_EQ_INT(p.g, 102);
    CHECK_EQ_INT(p.b, 102);
    /* tinted: L * trc * F = (0.5, 0, 0) */
    ts.scene.options.shadow_tint = 1;
    f = ts_prepare(&ts);
    p = centre_pixel(f);
    CHECK_EQ_INT(p.r, 102);
    CHECK_EQ_INT(p.g, 0);
    /* and ambient unshadowed: wall = 0.2 + 0.6 * cos * shadowed light */
    ts.scene.options.ambient_shadowed = 0;
    f = ts_prepare(&ts);
    p = centre_pixel(f);
    CHECK_EQ_INT(p.g, 51); /* 0.2 * 255: green light blocked */
    /* red passes at half strength: (0.2 + 0.6 * 0.5) * 255 = 127.5 */
    CHECK(p.r >= 127 && p.r <= 128);
    /* opaque box: ambient only */
    ts.materials[bm].trc = NUM_ZERO;
    f = ts_prepare(&ts);
    p = centre_pixel(f);
    CHECK_EQ_INT(p.r, 51);
    CHECK_EQ_INT(p.g, 51);
    /* and nothing when ambient is shadowed too */
    ts.scene.options.ambient_shadowed = 1;
    f = ts_prepare(&ts);
    p = centre_pixel(f);
    CHECK_EQ_INT(p.r, 0);
    CHECK_EQ_INT(p.g, 0);
    /* shadows switched off: full diffuse */
    ts.scene.options.shadows = 0;
    f = ts_prepare(&ts);
    p = centre_pixel(f);
    CHECK(p.g > 51 + 100);
}

static void test_mirror(void)
{
    /* a mirror facing the camera reflects the background back */
    ts_init(&ts, 9, 9);
    scene_material_t mirror = mat(1, 1, 1, 0, 0);
    mirror.src = N(0.5);
    wall(0, ts_material(&ts, mirror), 10);
    ts.scene.background = ts_rgb(0, 0, 1);
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    rgb8_t p = centre_pixel(f);
    CHECK_EQ_INT(p.b, 128); /* 0.5 * 255 = 127.5 */
    CHECK_EQ_INT(p.r, 0);
    /* depth 0: no reflection rays at all */
    ts.scene.options.max_depth = 0;
    f = ts_prepare(&ts);
    p = centre_pixel(f);
    CHECK_EQ_INT(p.b, 0);
}

/* A mirror wall at z = 10 whose smooth normals all lean by deg degrees
 * from the camera towards +y; *ctx renders its centre pixel. */
static rgb8_t leaning_mirror_pixel(double deg, render_ctx_t *ctx)
{
    ts_init(&ts, 9, 9);
    scene_material_t mirror = mat(1, 1, 1, 0.2, 0);
    mirror.src = N(0.5);
    uint16_t m = ts_material(&ts, mirror);
    ts.scene.background = ts_rgb(0, 0, 1);
    double r = deg * 3.14159265358979323846 / 180;
    vec3_t n = ts_v(0, sin(r), -cos(r));
    wall(0, m, 10);
    for (uint32_t k = 0; k < 2; k++)
        ts_smooth(&ts, k, n, n, n);
    scene_light_t *l = ts_light(&ts, SCENE_LIGHT_PARALLEL, ts_rgb(1, 1, 1));
    l->direction = ts_v(0, 0, 1);
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return (rgb8_t){0, 0, 0};
    render_ctx_init(ctx, f);
    return render_pixel(ctx, f->width / 2, f->height / 2);
}

static void test_mirror_into_surface(void)
{
    /* leaning 20 degrees: the mirrored ray comes back towards the camera
     * and sees the background; ambient 0.2 (51) under half the blue */
    render_ctx_t ctx;
    rgb8_t p = leaning_mirror_pixel(20, &ctx);
    CHECK_EQ_INT(ctx.stats.reflection, 1);
    CHECK_EQ_INT(ctx.stats.self_blocked, 0);
    CHECK_EQ_INT(p.r, 51);
    CHECK(p.b >= 51 + 127);
    /* 60 degrees: it would go on through the wall's plane; the wall
     * blocks it (traced, it met the wall again at once, again and again,
     * each time adding its ambient) */
    p = leaning_mirror_pixel(60, &ctx);
    CHECK_EQ_INT(ctx.stats.reflection, 0);
    CHECK_EQ_INT(ctx.stats.self_blocked, 1);
    CHECK_EQ_INT(p.r, 51);
    CHECK_EQ_INT(p.b, 51);
    CHECK(!ctx.pixel_lost);
    /* 45 degrees: it runs along the plane, on either side within its
     * error: the pixel loses precision */
    (void)leaning_mirror_pixel(45, &ctx);
    CHECK(ctx.pixel_lost);
}

static void glass_pane_scene(void)
{
    ts_init(&ts, 9, 9);
    uint16_t back = ts_material(&ts, mat(0, 1, 0, 0.5, 0.5));
    wall(0, back, 20);
    scene_material_t glass = mat(1, 1, 1, 0, 0);
    glass.trc = NUM_ONE;
    glass.ior = N(1.5);
    ts_box(&ts, 0, ts_material(&ts, glass), ts_v(0, 0, 10), ts_v(5, 5, 0.5));
    scene_light_t *l = ts_light(&ts, SCENE_LIGHT_PARALLEL, ts_rgb(1, 1, 1));
    l->direction = ts_v(0, 1, 0); /* from above: the wall is lit edge-on */
    l = ts_light(&ts, SCENE_LIGHT_PARALLEL, ts_rgb(1, 1, 1));
    l->direction = ts_v(0, 0, 1);
    ts.scene.options.shadows = 0; /* so the glass does not shade the wall */
}

static void test_refraction(void)
{
    /* straight through a clear pane at normal incidence: the wall's colour
     * (ambient 0.5 * 2 lights, diffuse 0.5 from the front light) */
    glass_pane_scene();
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    rgb8_t p = centre_pixel(f);
    CHECK(p.g >= 254);
    CHECK_EQ_INT(p.r, 0);
    /* depth 1: the ray inside the pane cannot leave; without
     * refractionless transmission the glass goes dark */
    ts.scene.options.max_depth = 1;
    ts.scene.options.refractionless = 0;
    f = ts_prepare(&ts);
    CHECK_EQ_INT(centre_pixel(f).g, 0);
    /* with it, the straight ray reaches the wall: the same colour */
    ts.scene.options.refractionless = 1;
    f = ts_prepare(&ts);
    CHECK(centre_pixel(f).g >= 254);
    /* depth 0: the transmission buffer holds both pane faces */
    ts.scene.options.max_depth = 0;
    f = ts_prepare(&ts);
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    rgb8_t q = render_pixel(&ctx, 4, 4);
    CHECK(q.g >= 254);
    CHECK_EQ_INT(ctx.stats.transmission, 1);
    CHECK_EQ_INT(ctx.stats.refraction, 0);
}

static void test_refraction_off(void)
{
    /* refraction off: transmission never bends, at any depth.  At depth 1
     * without refractionless transmission a refracted ray is lost inside
     * the pane (dark, test_refraction); a straight one reaches the wall,
     * and no ray is refracted at all. */
    glass_pane_scene();
    ts.scene.options.max_depth = 1;
    ts.scene.options.refractionless = 0;
    ts.scene.options.refraction = 0;
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    rgb8_t p = render_pixel(&ctx, 4, 4);
    CHECK(p.g >= 254);
    CHECK_EQ_INT(ctx.stats.refraction, 0);
    CHECK_EQ_INT(ctx.stats.transmission, 1);
    /* at the full depth too: straight, never refracted */
    ts.scene.options.max_depth = 4;
    f = ts_prepare(&ts);
    render_ctx_init(&ctx, f);
    p = render_pixel(&ctx, 4, 4);
    CHECK(p.g >= 254);
    CHECK_EQ_INT(ctx.stats.refraction, 0);
    CHECK_EQ_INT(ctx.stats.transmission, 1);
    /* and refracting, the same depth traces refracted rays */
    ts.scene.options.refraction = 1;
    f = ts_prepare(&ts);
    render_ctx_init(&ctx, f);
    render_pixel(&ctx, 4, 4);
    CHECK(ctx.stats.refraction > 0);
}

/* A scene with nesting, every primitive kind and transparency. */
static void busy_scene(void)
{
    ts_init(&ts, 40, 30);
    uint16_t floor = ts_material(&ts, mat(0.8, 0.8, 0.6, 0.2, 0.7));
    scene_material_t shiny = mat(0.9, 0.2, 0.2, 0.1, 0.6);
    shiny.src = N(0.3);
    shiny.phong_n = 20;
    shiny.fresnel = N(0.5);
    uint16_t red = ts_material(&ts, shiny);
    scene_material_t glass = mat(0.9, 1, 0.9, 0.05, 0.1);
    glass.trc = N(0.8);
    glass.src = N(0.1);
    glass.ior = N(1.3);
    glass.fresnel = NUM_ONE;
    uint16_t clear = ts_material(&ts, glass);
    ts_triangle(&ts, 0, floor, ts_v(-50, -2, -5), ts_v(50, -2, -5), ts_v(0, -2, 80));
    uint16_t group = ts_cluster(&ts, 0, ts_translate(0, 0, 12));
    uint16_t inner = ts_cluster(&ts, group, ts_rotate_z(sqrt(0.5), sqrt(0.5), 2, 0, 0));
    ts_box(&ts, inner, red, ts_v(0, 0, 0), ts_v(1, 1, 1));
    ts_ellipsoid(&ts, group, clear, ts_v(-2, 0, -3), ts_v(1.5, 1, 1));
    const double blob[3][5] = {{-3, 1, 4, 2, 1}, {-2, 1.5, 4, 2, 1}, {-2.5, 0.5, 4.5, 1.5, 0.8}};
    uint16_t deep = ts_cluster(&ts, inner, ts_translate(0, 2, 0));
    ts_density(&ts, deep, red, 0.5, 3, blob);
    scene_light_t *l = ts_light(&ts, SCENE_LIGHT_POINT, ts_rgb(0.8, 0.8, 0.8));
    l->position = ts_v(5, 10, 0);
    l = ts_light(&ts, SCENE_LIGHT_SPOT, ts_rgb(0.6, 0.6, 0.9));
    l->position = ts_v(-5, 8, 8);
    l->direction = ts_v(0.3, -1, 0.3);
    l->cos_inner = N(0.9);
    l->cos_outer = N(0.7);
    ts.scene.camera.eye = ts_v(0, 3, -2);
    ts.scene.camera.look_at = ts_v(0, 0, 12);
}

static rgb8_t *render_all(render_frame_t *f, render_stats_t *stats)
{
    rgb8_t *img = calloc((size_t)f->width * f->height, sizeof *img);
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    for (uint32_t y = 0; y < f->height; y++)
        render_span(&ctx, y, 0, f->width, img + (size_t)y * f->width);
    if (stats)
        *stats = ctx.stats;
    return img;
}

static void test_speedups_same_image(void)
{
    busy_scene();
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    render_stats_t ref_stats;
    rgb8_t *ref = render_all(f, &ref_stats);
    size_t n = (size_t)f->width * f->height, lit = 0;
    for (size_t i = 0; i < n; i++)
        lit += ref[i].r || ref[i].g || ref[i].b;
    CHECK(lit > n / 2); /* the scene is on screen */
    CHECK(ref_stats.shadow > 0 && ref_stats.reflection > 0 && ref_stats.refraction > 0);
    for (int mode = 1; mode < 4; mode++) {
        f->options.use_hierarchy = (mode & 1) == 0;
        f->options.use_bounds = (mode & 2) == 0;
        render_stats_t st;
        rgb8_t *img = render_all(f, &st);
        CHECK(memcmp(img, ref, n * sizeof *img) == 0);
        if (!f->options.use_bounds) /* boxes only ever save work */
            CHECK(st.prim_tests >= ref_stats.prim_tests);
        free(img);
    }
    /* screen clipping for primary rays: only clusters whose rectangle
     * holds the pixel; same colours */
    f->options.use_hierarchy = 1;
    f->options.use_bounds = 1;
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    int same = 1;
    for (uint32_t y = 0; y < f->height; y++)
        for (uint32_t x = 0; x < f->width; x++) {
            uint32_t list[TS_MAX];
            uint32_t count = 0;
            for (uint32_t c = 0; c < f->cluster_count; c++) {
                const render_cluster_t *k = &f->clusters[c];
                if ((int32_t)x >= k->screen_x0 && (int32_t)x <= k->screen_x1 && (int32_t)y >= k->screen_y0 &&
                    (int32_t)y <= k->screen_y1)
                    list[count++] = c;
            }
            rgb8_t p = render_pixel_clipped(&ctx, x, y, list, count);
            rgb8_t q = ref[(size_t)y * f->width + x];
            same &= p.r == q.r && p.g == q.g && p.b == q.b;
        }
    CHECK(same);
    free(ref);
}

static void test_screen_rect(void)
{
    /* a unit box at z = 10 straight ahead, 100x100 pixels, tan = 0.5: the
     * view is 10 units wide at z = 10, the box 2 units: pixels 40..60 */
    ts_init(&ts, 100, 100);
    uint16_t c = ts_cluster(&ts, 0, ts_translate(0, 0, 10));
    ts_box(&ts, c, 0, ts_v(0, 0, 0), ts_v(1, 1, 1));
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    const render_cluster_t *k = &f->clusters[c];
    /* the front face projects to 40..60, the near corners (z = 9) slightly
     * wider: 1/9 * 10 = 1.11 units -> 38.9..61.1; plus one pixel margin */
    CHECK(k->screen_x0 >= 35 && k->screen_x0 <= 39);
    CHECK(k->screen_x1 >= 60 && k->screen_x1 <= 64);
    CHECK(k->screen_y0 >= 35 && k->screen_y0 <= 39);
    CHECK(k->screen_x1 - k->screen_x0 == k->screen_y1 - k->screen_y0);
    CHECK(f->clusters[0].screen_x0 > f->clusters[0].screen_x1); /* root: no prims */
    /* behind the eye: empty; straddling the eye plane: the whole screen */
    ts.clusters[c].local = ts_translate(0, 0, -10);
    f = ts_prepare(&ts);
    CHECK(f->clusters[c].screen_x0 > f->clusters[c].screen_x1);
    ts.clusters[c].local = ts_translate(3, 0, 0);
    f = ts_prepare(&ts);
    CHECK_EQ_INT(f->clusters[c].screen_x0, 0);
    CHECK_EQ_INT(f->clusters[c].screen_x1, 99);
    CHECK_EQ_INT(f->clusters[c].screen_y1, 99);
}

static void test_tie_break(void)
{
    /* two coincident walls, red (lower index) and green: every traversal
     * mode shows red, whichever order it tests them in */
    ts_init(&ts, 6, 6);
    uint16_t green = ts_material(&ts, mat(0, 1, 0, 1, 0));
    uint16_t red = ts_material(&ts, mat(1, 0, 0, 1, 0));
    uint16_t late = ts_cluster(&ts, 0, xform_identity());
    wall(late, red, 10);   /* prims 0, 1 in a child cluster */
    wall(0, green, 10);    /* prims 2, 3 in the root: tested first in the tree */
    scene_light_t *l = ts_light(&ts, SCENE_LIGHT_PARALLEL, ts_rgb(1, 1, 1));
    l->direction = ts_v(0, 0, 1);
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    for (int mode = 0; mode < 4; mode++) {
        f->options.use_hierarchy = (mode & 1) == 0;
        f->options.use_bounds = (mode & 2) == 0;
        rgb8_t *img = render_all(f, NULL);
        int all_red = 1;
        for (int i = 0; i < 36; i++)
            all_red &= img[i].r == 255 && img[i].g == 0;
        CHECK(all_red);
        free(img);
    }
}

static void test_keyframes(void)
{
    ts_init(&ts, 8, 8);
    uint16_t c = ts_cluster(&ts, 0, xform_identity());
    ts.clusters[c].first_key = 0;
    ts.clusters[c].key_count = 2;
    ts.scene.key_count = 2;
    scene_key_t *k = ts.keys;
    k[0].frame = 0;
    k[0].translate = ts_v(0, 0, 10);
    k[0].rot_w = NUM_ONE;
    k[0].scale = ts_v(1, 1, 1);
    k[1].frame = 10;
    k[1].translate = ts_v(10, 0, 10);
    k[1].rot_w = N(sqrt(0.5)); /* 90 degrees about z */
    k[1].rot_z = N(sqrt(0.5));
    k[1].scale = ts_v(1, 1, 1);
    ts_ellipsoid(&ts, c, 0, ts_v(0, 0, 0), ts_v(2, 1, 1));
    render_frame_t *f = NULL;
    arena_reset(&ts.arena);
    CHECK_EQ_INT(render_prepare(&ts.scene, 5, &ts.arena, &f), RENDER_OK);
    if (!f)
        return;
    /* frame 5: halfway, x = 5, turned 45 degrees: the long axis along
     * (1,1)/sqrt2; the ray along x at y = 0 through the centre meets it where
     * x'^2/4 + y'^2 = 1 with x' = y' = s/sqrt2: s = sqrt(8/5) */
    ray_t r = {ts_v(-5, 0, 10), ts_v(1, 0, 0)};
    num_t t;
    CHECK(prim_intersect(&f->prims[0], &r, NUM_ZERO, N(100), &t));
    CHECK_NEAR(num_to_double(t), 10 - sqrt(8.0 / 5), 3e-3);
    /* past the last key the last key holds */
    arena_reset(&ts.arena);
    CHECK_EQ_INT(render_prepare(&ts.scene, 99, &ts.arena, &f), RENDER_OK);
    r.origin = ts_v(10, -10, 10);
    r.dir = ts_v(0, 1, 0);
    CHECK(prim_intersect(&f->prims[0], &r, NUM_ZERO, N(100), &t));
    CHECK_NEAR(num_to_double(t), 8, 3e-3); /* long axis now along y */
}

static void test_limits_and_errors(void)
{
    render_frame_t *f;
    uint8_t small[64];
    arena_t tiny;
    busy_scene();
    arena_init(&tiny, small, sizeof small);
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &tiny, &f), RENDER_ERR_ARENA);
    CHECK(tiny.failed_request > 0);
    /* the announced size is enough, half of it is not */
    busy_scene();
    size_t need = render_prepare_bytes(&ts.scene);
    static uint8_t exact[1 << 16];
    CHECK(need <= sizeof exact);
    arena_init(&tiny, exact, need);
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &tiny, &f), RENDER_OK);
    CHECK(tiny.high_water <= need);
    arena_init(&tiny, exact, need / 2);
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &tiny, &f), RENDER_ERR_ARENA);
    busy_scene();
    ts.scene.light_count = RENDER_MAX_LIGHTS + 1;
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_LIGHTS);
    busy_scene();
    ts.clusters[2].parent = 2; /* its own parent */
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_CLUSTER);
    busy_scene();
    ts.prims[1].material = 99;
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_PRIM);
    busy_scene();
    ts.clusters[1].first_key = ts.scene.key_count; /* keys past the scene's */
    ts.clusters[1].key_count = 1;
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_KEY);
    busy_scene();
    ts.scene.camera.look_at = ts.scene.camera.eye;
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_CAMERA);
    busy_scene();
    ts.scene.width = RENDER_MAX_WIDTH + 1;
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_SIZE);
    busy_scene();
    ts.clusters[1].local.m[0][0] = NUM_ZERO; /* singular */
    ts.clusters[1].local.m[1][1] = NUM_ZERO;
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_SINGULAR);
    busy_scene();
    ts.prims[ts.scene.prim_count - 1].shape.density.threshold = NUM_ZERO;
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_DENSITY);
    busy_scene();
    ts.materials[1].colour_map = 3;
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_MAP);
    CHECK(render_status_name(RENDER_ERR_MAP)[0] != 0);
    /* nesting deeper than the limit */
    ts_init(&ts, 8, 8);
    uint16_t parent = 0;
    for (int i = 0; i <= RENDER_MAX_CLUSTER_DEPTH; i++)
        parent = ts_cluster(&ts, parent, xform_identity());
    CHECK_EQ_INT(render_prepare(&ts.scene, 0, &ts.arena, &f), RENDER_ERR_CLUSTER);
}

static void test_precision_flag(void)
{
    /* lights so bright that the sum of terms leaves the fixed range: the
     * fixed build must say so; the IEEE builds have the range */
    ts_init(&ts, 5, 5);
    wall(0, ts_material(&ts, mat(1, 1, 1, 1, 1)), 10);
    for (int i = 0; i < 2; i++) {
        scene_light_t *l = ts_light(&ts, SCENE_LIGHT_PARALLEL, ts_rgb(1500, 1500, 1500));
        l->direction = ts_v(0, 0, 1);
    }
    render_frame_t *f = ts_prepare(&ts);
    CHECK(f != NULL);
    if (!f)
        return;
    render_stats_t st;
    rgb8_t *img = render_all(f, &st);
    CHECK_EQ_INT(img[12].r, 255);
#if defined(LINKS1_NUM_FIXED)
    CHECK_EQ_INT(st.precision_lost_pixels, 25);
#else
    CHECK_EQ_INT(st.precision_lost_pixels, 0);
#endif
    free(img);
    /* a normal scene loses nothing; in fixed point a few rays reflected
     * inside the glass ellipsoid carry its hit error (3.5e-4: rounding at
     * the floor's extent of 80) and what it does to their directions, and
     * pass surfaces closer than that: under 1% of the pixels */
    busy_scene();
    f = ts_prepare(&ts);
    img = render_all(f, &st);
#if defined(LINKS1_NUM_FIXED)
    CHECK(st.precision_lost_pixels <= (uint32_t)f->width * f->height / 100);
#else
    CHECK_EQ_INT(st.precision_lost_pixels, 0);
#endif
    CHECK(!f->precision_lost);
    free(img);
}

/* A scene too small for its ray offset is refused, naming the cause: a
 * sphere a cluster map shrinks by 2^-8 (made here, not by the loader,
 * which takes a cluster's power of two into its lengths: the tolerances
 * follow the geometry as stored, so it is small for its distance from the
 * origin), or the same small sphere
 * where the loader stopped the tolerances at RENDER_TOL_EXP_MIN because
 * the eye or a light lies far out (test_scene_load: a light 1e5 from a
 * sphere within 2.5).  Both messages fit the DM's refusal line. */
static void test_extent_refused(void)
{
    for (int far = 0; far < 2; far++) {
        ts_init(&ts, 8, 8);
        uint16_t m = ts_material(&ts, mat(1, 1, 1, 0.3, 0.7));
        xform_t shrink = ts_translate(0, 0, 5);
        if (!far)
            for (int i = 0; i < 3; i++)
                shrink.m[i][i] = N(0x1p-8);
        uint16_t c = ts_cluster(&ts, 0, shrink);
        double r = far ? 0x1p-10 : 1;
        ts_ellipsoid(&ts, c, m, ts_v(0, 0, 0), ts_v(r, r, r));
        if (far)
            ts.scene.tol_exp = RENDER_TOL_EXP_MIN;
        render_frame_t *f = NULL;
        render_status_t st = render_prepare(&ts.scene, 0, &ts.arena, &f);
        char why[RENDER_BLOB_MSG_MAX];
        precision_status_message(f, st, why, sizeof why);
        printf("# %s: %s (%zu characters)\n", far ? "far light" : "shrunk", why, strlen(why));
        CHECK_EQ_INT(st, RENDER_ERR_EXTENT);
        CHECK(strncmp(why, "scene spans ", 12) == 0);
        CHECK(strlen(why) + strlen("frame 999: ") < RENDER_BLOB_MSG_MAX); /* blob.c's prefix */
        CHECK(strstr(why, far ? "the eye or a light lies over 256 times farther out than the "
                                "geometry; bring it closer"
                              : "it lies far from the origin for its size; move it nearer") != NULL);
    }
}

/* A cluster map's inverse keeps the arithmetic's precision at any scale:
 * m * inverse(m) is the identity within INVERSE_STEPS steps (fixed) or
 * ulps of one (float) times the map's largest scale (at least 1: an
 * inverse right to a step, times 20, is 20 steps off).  Before the map
 * was brought to unit size first, the fixed inverse of a map scaled by 0.1
 * was off by 6e-4 of its size (Q13.18; 606 steps of Q12.19), and maps
 * scaled by 0.03 or 20 were refused; that scene's edges were off by 35 dB.  A map the fixed range
 * cannot invert (1e4 along one axis) is refused as such. */
static void test_inverse_precision(void)
{
    static const double scales[][3] = {
        {1, 1, 1}, {0.1, 0.1, 0.1}, {0.03, 0.03, 0.03}, {0.1, 1, 4}, {5, 5, 5}, {20, 20, 20}, {0.01, 0.2, 0.05},
    };
    for (size_t k = 0; k < sizeof scales / sizeof scales[0]; k++) {
        xform_t r = ts_rotate_z(0.8, 0.6, 0.5, -1.25, 3), m = r; /* 36.87 degrees */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                m.m[i][j] = N(num_to_double(r.m[i][j]) * scales[k][j]);
        xform_t inv;
        CHECK_EQ_INT(precision_invert(&m, &inv), RENDER_OK);
        xform_t p = xform_compose(&m, &inv);
        double worst = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 4; j++) {
                double e = fabs(num_to_double(p.m[i][j]) - (i == j ? 1 : 0));
                worst = e > worst ? e : worst;
            }
        printf("# scales %g %g %g: |m inverse(m) - I| %.3g (%.1f steps)\n", scales[k][0],
               scales[k][1], scales[k][2], worst, worst / num_to_double(num_ulp(NUM_ONE)));
        double size = 1;
        for (int j = 0; j < 3; j++)
            size = scales[k][j] > size ? scales[k][j] : size;
        CHECK(worst <= INVERSE_STEPS * size * num_to_double(num_ulp(NUM_ONE)));
    }
#if defined(LINKS1_NUM_FIXED)
    xform_t flat = xform_identity();
    flat.m[2][2] = N(1e-4);
    xform_t inv;
    CHECK_EQ_INT(precision_invert(&flat, &inv), RENDER_ERR_SCALE);
#endif
}

/* Issue 11: a triangle that a cluster shrinks to 2^-19 in eye units (one
 * fixed step; under two float steps at z = 9) is refused, naming it and
 * the numbers; 2^-16 (8 fixed steps) renders in every arithmetic. */
static void test_detail_refused(void)
{
    for (int k = 0; k < 2; k++) {
        ts_init(&ts, 8, 8);
        uint16_t m = ts_material(&ts, mat(1, 1, 1, 0.3, 0.7));
        wall(0, m, 10);
        xform_t shrink = ts_translate(0, 0, 9);
        for (int i = 0; i < 3; i++)
            shrink.m[i][i] = N(0x1p-4);
        uint16_t c = ts_cluster(&ts, 0, shrink);
        double h = k == 0 ? 0x1p-15 : 0x1p-12;
        ts_triangle(&ts, c, m, ts_v(0, 0, 0), ts_v(h, 0, 0), ts_v(0, h, 0));
        render_frame_t *f = NULL;
        render_status_t st = render_prepare(&ts.scene, 0, &ts.arena, &f);
        char why[200];
        precision_status_message(f, st, why, sizeof why);
        printf("# height 2^%d: %s\n", k == 0 ? -19 : -16, st == RENDER_OK ? "ok" : why);
#if defined(LINKS1_NUM_DOUBLE)
        CHECK_EQ_INT(st, RENDER_OK);
#else
        if (k == 1) {
            CHECK_EQ_INT(st, RENDER_OK);
            continue;
        }
        CHECK_EQ_INT(st, RENDER_ERR_DETAIL);
        CHECK(f != NULL && f->detail_prim == 2);
#if defined(LINKS1_NUM_FIXED)
        const char *want = "triangle 2 has a height of 1.91e-6; fixed Q12.19 resolves 1.91e-6 "
                           "there, in a scene spanning 40 (lengths scaled by 2^0): enlarge it "
                           "or use float";
#else
        const char *want = "triangle 2 has a height of 1.91e-6; float resolves 1.07e-6 there, "
                           "in a scene spanning 40 (lengths scaled by 2^0): enlarge it";
#endif
        CHECK(strcmp(why, want) == 0);
        CHECK(strstr(render_status_name(RENDER_ERR_DETAIL), "RENDER_MIN_DETAIL_STEPS") != NULL);
#endif
    }
}

int main(void)
{
    printf("# num_t = %s\n", NUM_NAME);
    RUN(test_diffuse_wall);
    RUN(test_sixteen_lights);
    RUN(test_shadows);
    RUN(test_mirror);
    RUN(test_mirror_into_surface);
    RUN(test_refraction);
    RUN(test_refraction_off);
    RUN(test_speedups_same_image);
    RUN(test_screen_rect);
    RUN(test_tie_break);
    RUN(test_keyframes);
    RUN(test_limits_and_errors);
    RUN(test_precision_flag);
    RUN(test_detail_refused);
    RUN(test_inverse_precision);
    RUN(test_extent_refused);
    return check_exit();
}
