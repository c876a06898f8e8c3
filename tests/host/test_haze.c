/* test_haze.c: haze (render/haze.h) in each arithmetic: its exp against
 * libm's, the blend towards the haze colour, the colour of a miss, and the
 * flag of an uncertain haze weight. */
#include <string.h>

#include "render/haze.h"
#include "render/vec3.h"
#include "tests/check.h"

#if defined(LINKS1_NUM_FIXED)
#define TOL 2e-5
#elif defined(LINKS1_NUM_FLOAT)
#define TOL 1e-6
#else
#define TOL 1e-15
#endif

#define N(x) num_from_double(x)
#define D(x) num_to_double(x)

static void test_haze_exp(void)
{
    CHECK(num_eq(haze_exp_neg(NUM_ZERO), NUM_ONE));
    CHECK(num_eq(haze_exp_neg(N(-2)), NUM_ONE));
    CHECK(num_eq(haze_exp_neg(N(40)), NUM_ZERO));
    double worst = 0;
    for (int i = 0; i <= 4000; i++) { /* 0 .. 40 by 0.01 */
        num_t x = N(i / 100.0);
        double err = fabs(D(haze_exp_neg(x)) - exp(-D(x)));
        worst = err > worst ? err : worst;
    }
    printf("# haze_exp_neg: worst |error| %.3g over 0..40\n", worst);
    CHECK_NEAR(worst, 0, TOL);
}

/* A scene of nothing but haze (or none) and a context on it. */
struct haze_fixture {
    scene_t scene;
    render_frame_t frame;
    render_ctx_t ctx;
};

static void haze_fixture(struct haze_fixture *h, int haze, double distance)
{
    memset(h, 0, sizeof *h);
    h->scene.background = rgb_make(N(0.1), N(0.2), N(0.3));
    h->scene.haze = (uint8_t)haze;
    h->scene.haze_colour = rgb_make(N(0.6), N(0.65), N(0.7));
    h->scene.haze_k = N(1.0 / distance);
    h->frame.scene = &h->scene;
    h->ctx.frame = &h->frame;
}

static void test_haze_blend(void)
{
    struct haze_fixture h;
    haze_fixture(&h, 1, 4);
    rgb_t c = rgb_make(N(0.9), N(0.2), NUM_ZERO);
    for (double t = 0; t <= 20; t += 2.5) {
        rgb_t got = haze_apply(&h.ctx, c, N(t), NUM_ZERO, NUM_ONE);
        double w = exp(-t / 4);
        CHECK_NEAR(D(got.r), 0.6 + (0.9 - 0.6) * w, 4 * TOL);
        CHECK_NEAR(D(got.g), 0.65 + (0.2 - 0.65) * w, 4 * TOL);
        CHECK_NEAR(D(got.b), 0.7 + (0.0 - 0.7) * w, 4 * TOL);
    }
    CHECK(num_eq(haze_miss(&h.ctx).g, N(0.65)));
    CHECK(!h.ctx.pixel_lost);
    /* without haze: the colour as it is, a miss the background */
    haze_fixture(&h, 0, 4);
    rgb_t same = haze_apply(&h.ctx, c, N(7), NUM_ZERO, NUM_ONE);
    CHECK(num_eq(same.r, c.r) && num_eq(same.g, c.g) && num_eq(same.b, c.b));
    CHECK(num_eq(haze_miss(&h.ctx).b, N(0.3)));
}

static void test_haze_flags(void)
{
    struct haze_fixture h;
    rgb_t c = rgb_make(NUM_ONE, NUM_ONE, NUM_ONE);
    /* a hit whose distance is 0.1 uncertain at 1/D = 1/2: the weight
     * exp(-1/2) may move by 0.03, the pixel by 0.012 of a spread of 0.4 */
    haze_fixture(&h, 1, 2);
    haze_apply(&h.ctx, c, N(1), N(0.1), NUM_ONE);
    CHECK(h.ctx.pixel_lost);
    /* the same on a ray of weight 1/100: under 1/255 */
    haze_fixture(&h, 1, 2);
    haze_apply(&h.ctx, c, N(1), N(0.1), N(0.01));
    CHECK(!h.ctx.pixel_lost);
    /* a colour at the haze's own: no uncertainty shows */
    haze_fixture(&h, 1, 2);
    haze_apply(&h.ctx, h.scene.haze_colour, N(1), N(0.1), NUM_ONE);
    CHECK(!h.ctx.pixel_lost);
}

int main(void)
{
    printf("# num_t = %s\n", NUM_NAME);
    RUN(test_haze_exp);
    RUN(test_haze_blend);
    RUN(test_haze_flags);
    return check_exit();
}
