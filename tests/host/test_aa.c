/* test_aa.c: anti-aliasing (options.antialias, render/trace.c): an image
 * rendered as one area equals the image rendered as areas of other shapes,
 * clipped every way, and pixel by pixel, bit for bit with the same rays;
 * depth 0 and the SPD rules are the mean of the corner rays, computed here
 * from render_corner; a pixel cut once is the mean of the four quarter
 * pixels of the frame at twice the size; a threshold below 0 cuts every
 * pixel to the limit (5 (4^d - 1) / 3 rays a pixel beyond the shared
 * corners), a threshold over every difference cuts none; supersampling
 * with one sample a pixel is render_pixel's image. */
#include "tests/check.h"
#include "tests/host/render_fixture.h"
#include "tests/host/test_blob_util.h"
#include "render/vec3.h"

#define TA_DIV 8 /* demo and glass at 40x30 */

/* Scene name at 1/div of its size, with anti-aliasing at depth and
 * threshold (the test's own frame), clipping set up for it. */
static int ta_open(rf_scene_t *t, const char *name, int div, int depth, double threshold)
{
    if (!rf_load(t, name, 0, div))
        return 0;
    t->f->options.antialias = depth >= 0;
    t->f->options.aa_depth = (uint8_t)(depth >= 0 ? depth : 0);
    t->f->options.aa_threshold = num_from_double(threshold);
    return rf_clip(t);
}

/* One area over the screen, areas of five shapes clipped four ways, and
 * render_pixel alone: one image, and over the areas the same rays. */
static void test_aa_areas_same(void)
{
    const char *names[] = {"demo", "glass"};
    static const uint32_t shapes[5][2] = {{16, 16}, {7, 5}, {1000, 1}, {1, 1000}, {33, 9}};
    for (int s = 0; s < 2; s++) {
        rf_scene_t t;
        CHECK(ta_open(&t, names[s], TA_DIV, 2, 0.1));
        if (!t.blob)
            continue;
        size_t n = (size_t)t.f->width * t.f->height;
        render_clip_options_t tree = {1, 1, NULL, 0}, lists = {1, 1, NULL, 1},
                              ylist = {1, 0, NULL, 1}, none = {0, 0, NULL, 0};
        const render_clip_options_t *modes[4] = {&tree, &lists, &ylist, &none};
        render_stats_t whole_st, st;
        rgb8_t *whole = rf_areas(&t, t.f->width, t.f->height, NULL, &tree, &whole_st);
        uint64_t corners = (uint64_t)(t.f->width + 1) * (t.f->height + 1);
        CHECK(whole_st.primary > corners);
        int same = 1, rays = 1;
        for (int k = 0; k < 5; k++) { /* each shape one way, each way at least once */
            int m = k % 4;
            rgb8_t *img = rf_areas(&t, shapes[k][0], shapes[k][1], NULL, modes[m], &st);
            if (!tb_same(whole, img, n) || !rf_same_rays(&whole_st, &st))
                printf("%s: areas %ux%u (mode %d) differ from the whole screen's\n", names[s],
                       shapes[k][0], shapes[k][1], m);
            same &= tb_same(whole, img, n);
            rays &= rf_same_rays(&whole_st, &st);
            free(img);
        }
        CHECK(same);
        CHECK(rays);
        rgb8_t *plain = tb_render_plain(t.f, &st); /* four corners of its own a pixel */
        CHECK(tb_same(whole, plain, n));
        CHECK_EQ_INT(st.primary - 4 * (uint64_t)n, whole_st.primary - corners);
        printf("%s %ux%u aa 2: %llu camera rays (%llu corners)\n", names[s], t.f->width,
               t.f->height, (unsigned long long)whole_st.primary, (unsigned long long)corners);
        free(plain);
        free(whole);
        rf_close(&t);
    }
}

/* Pixel (x, y) as the mean of its corner rays, from render_corner. */
static rgb8_t ta_corner_mean(render_ctx_t *ctx, uint32_t x, uint32_t y)
{
    render_corner_t c[4];
    for (uint32_t k = 0; k < 4; k++)
        render_corner(ctx, x + (k & 1), y + (k >> 1), RENDER_CORNER_TREE, NULL, 0, 1, &c[k]);
    rgb_t top = rgb_add(c[0].colour, c[1].colour), bottom = rgb_add(c[2].colour, c[3].colour);
    rgb_t m = rgb_scale(rgb_add(top, bottom), NUM_C(0.25));
    return (rgb8_t){num_to_u8(m.r), num_to_u8(m.g), num_to_u8(m.b)};
}

/* 1 when img is the corner mean at every pixel. */
static int ta_is_corner_mean(const render_frame_t *f, const rgb8_t *img)
{
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    for (uint32_t y = 0; y < f->height; y++)
        for (uint32_t x = 0; x < f->width; x++) {
            rgb8_t want = ta_corner_mean(&ctx, x, y), got = img[(size_t)y * f->width + x];
            if (want.r != got.r || want.g != got.g || want.b != got.b)
                return 0;
        }
    return 1;
}

/* Depth 0, a threshold no difference passes, and the SPD rules (their
 * pixels unchanged by anti-aliasing): each pixel the mean of its corners,
 * (w + 1) x (h + 1) camera rays. */
static void test_aa_corner_mean(void)
{
    double settings[3][2] = {{0, 0.1}, {3, 1000}, {-1, 0}}; /* depth -1: spd_rules */
    for (int k = 0; k < 3; k++) {
        rf_scene_t t;
        CHECK(ta_open(&t, "demo", TA_DIV, (int)settings[k][0], settings[k][1]));
        if (!t.blob)
            continue;
        if (settings[k][0] < 0) {
            t.f->options.spd_rules = 1;
            CHECK(rf_clip(&t));
        }
        render_clip_options_t tree = {1, 1, NULL, 0};
        render_stats_t st;
        rgb8_t *img = rf_areas(&t, 16, 16, NULL, &tree, &st);
        CHECK_EQ_INT(st.primary, (uint64_t)(t.f->width + 1) * (t.f->height + 1));
        if (!ta_is_corner_mean(t.f, img))
            printf("setting %d: not the mean of the corners\n", k);
        CHECK(ta_is_corner_mean(t.f, img));
        free(img);
        rf_close(&t);
    }
}

/* A threshold below 0 cuts every quad: depth d traces 5 (4^d - 1) / 3
 * rays a pixel besides its shared corners (each quad cut traces its five
 * new points; the midpoint of an edge two cut quarters share is traced by
 * both); threshold 0 cuts fewer, and more than none; the image is not the
 * corners' mean.  Depth 1, every pixel
 * cut: the mean of the four pixels the frame at twice the size has there,
 * each the mean of its corners (render_corner): the same points. */
static void test_aa_cut_counts(void)
{
    rf_scene_t t;
    CHECK(ta_open(&t, "demo", TA_DIV, 2, -1));
    if (!t.blob)
        return;
    uint64_t n = (uint64_t)t.f->width * t.f->height;
    uint64_t corners = (uint64_t)(t.f->width + 1) * (t.f->height + 1);
    render_clip_options_t tree = {1, 1, NULL, 0};
    render_stats_t all, zero;
    rgb8_t *cut = rf_areas(&t, 16, 16, NULL, &tree, &all);
    CHECK_EQ_INT(all.primary, corners + n * (5 + 4 * 5));
    t.f->options.aa_threshold = NUM_ZERO;
    rgb8_t *some = rf_areas(&t, 16, 16, NULL, &tree, &zero);
    CHECK(zero.primary > corners && zero.primary < all.primary);
    CHECK(!ta_is_corner_mean(t.f, some));
    free(some);
    free(cut);
    /* depth 1 against the frame at twice the size */
    t.f->options.aa_depth = 1;
    t.f->options.aa_threshold = num_from_double(-1);
    cut = rf_areas(&t, 16, 16, NULL, &tree, &all);
    rf_scene_t fine;
    CHECK(ta_open(&fine, "demo", TA_DIV / 2, -1, 0));
    if (fine.blob) {
        render_ctx_t ctx;
        render_ctx_init(&ctx, fine.f);
        int same = 1;
        for (uint32_t y = 0; y < t.f->height; y++)
            for (uint32_t x = 0; x < t.f->width; x++) {
                render_corner_t c[9];
                for (uint32_t k = 0; k < 9; k++)
                    render_corner(&ctx, 2 * x + k % 3, 2 * y + k / 3, RENDER_CORNER_TREE, NULL, 0,
                                  1, &c[k]);
                rgb_t q[4];
                for (uint32_t k = 0; k < 4; k++) {
                    const render_corner_t *a = &c[(k >> 1) * 3 + (k & 1)];
                    q[k] = rgb_scale(rgb_add(rgb_add(a[0].colour, a[1].colour),
                                             rgb_add(a[3].colour, a[4].colour)), NUM_C(0.25));
                }
                rgb_t m = rgb_scale(rgb_add(rgb_add(q[0], q[1]), rgb_add(q[2], q[3])), NUM_C(0.25));
                rgb8_t got = cut[(size_t)y * t.f->width + x];
                same &= got.r == num_to_u8(m.r) && got.g == num_to_u8(m.g) &&
                        got.b == num_to_u8(m.b);
            }
        CHECK(same);
        rf_close(&fine);
    }
    free(cut);
    rf_close(&t);
}

/* render_pixel_supersampled: one sample a pixel is its centre ray (the
 * same point, a grid of two steps), render_pixel's image; n x n samples
 * trace n^2 camera rays a pixel and give another image. */
static void test_supersample(void)
{
    rf_scene_t t;
    CHECK(ta_open(&t, "demo", TA_DIV, -1, 0));
    if (!t.blob)
        return;
    size_t n = (size_t)t.f->width * t.f->height;
    render_stats_t st;
    rgb8_t *plain = tb_render_plain(t.f, &st);
    rgb8_t *img[2];
    for (uint32_t k = 0; k < 2; k++) {
        img[k] = calloc(n, sizeof *img[k]);
        render_ctx_t ctx;
        render_ctx_init(&ctx, t.f);
        for (uint32_t y = 0; y < t.f->height; y++)
            for (uint32_t x = 0; x < t.f->width; x++)
                img[k][(size_t)y * t.f->width + x] =
                    render_pixel_supersampled(&ctx, x, y, 3 * k + 1);
        CHECK_EQ_INT(ctx.stats.primary, (uint64_t)n * (3 * k + 1) * (3 * k + 1));
    }
    CHECK(tb_same(plain, img[0], n));
    CHECK(!tb_same(plain, img[1], n));
    free(img[0]);
    free(img[1]);
    free(plain);
    rf_close(&t);
}

int main(void)
{
    RUN(test_aa_areas_same);
    RUN(test_aa_corner_mean);
    RUN(test_aa_cut_counts);
    RUN(test_supersample);
    return check_exit();
}
