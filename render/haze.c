/* render/haze.c: haze, POV-Ray's constant fog (render/haze.h). */
#include "render/haze.h"

#include "render/limits.h"
#include "render/vec3.h"

#define HAZE_LN2 NUM_C(0.69314718055994530942)
#define HAZE_INV_LN2 NUM_C(1.44269504088896340736)
#define HAZE_EXP_MAX 40 /* exp(-40) < 5e-18: 0 in every arithmetic's colours */

/* Terms of the series, and the error of haze_exp_neg's result bounded
 * (ln 2's rounding times n, each term's rounding): far under the
 * RENDER_HAZE_LOST_VALUE it is judged against. */
#if defined(LINKS1_NUM_DOUBLE)
#define HAZE_EXP_TERMS 17
#define HAZE_EXP_ERR NUM_C(1e-14)
#elif defined(LINKS1_NUM_FLOAT)
#define HAZE_EXP_TERMS 9
#define HAZE_EXP_ERR NUM_C(4e-6)
#else
#define HAZE_EXP_TERMS 8
#define HAZE_EXP_ERR NUM_C(1e-4)
#endif

/* 1/k for the series' k-th step */
static const num_t haze_recip[18] = {
    NUM_C(0),        NUM_C(1.0),       NUM_C(1.0 / 2),  NUM_C(1.0 / 3),  NUM_C(1.0 / 4),
    NUM_C(1.0 / 5),  NUM_C(1.0 / 6),   NUM_C(1.0 / 7),  NUM_C(1.0 / 8),  NUM_C(1.0 / 9),
    NUM_C(1.0 / 10), NUM_C(1.0 / 11),  NUM_C(1.0 / 12), NUM_C(1.0 / 13), NUM_C(1.0 / 14),
    NUM_C(1.0 / 15), NUM_C(1.0 / 16),  NUM_C(1.0 / 17),
};
_Static_assert(HAZE_EXP_TERMS < 18, "haze_recip holds the terms");

num_t haze_exp_neg(num_t x)
{
    if (!num_gt(x, NUM_ZERO))
        return NUM_ONE;
    if (num_is_sat(x) || !num_lt(x, NUM_C(HAZE_EXP_MAX)))
        return NUM_ZERO;
    int32_t n = num_floor_int(num_mul(x, HAZE_INV_LN2));
    num_t r = num_sub(x, num_mul_int(HAZE_LN2, n)); /* 0 <= r < ln 2, near enough */
    /* exp(-r) = 1 - r (1 - r/2 (1 - r/3 (...))) */
    num_t p = NUM_ONE;
    for (int k = HAZE_EXP_TERMS; k >= 1; k--)
        p = num_sub(NUM_ONE, num_mul(num_mul(r, haze_recip[k]), p));
    return num_scale2(p, -(int)n);
}

num_t haze_weight(const render_ctx_t *ctx, num_t d)
{
    const scene_t *s = ctx->frame->scene;
    return s->haze ? haze_exp_neg(num_mul(s->haze_k, d)) : NUM_ONE;
}

/* max over the channels of |a - b| */
static num_t haze_spread(rgb_t a, rgb_t b)
{
    return num_max(num_abs(num_sub(a.r, b.r)),
                   num_max(num_abs(num_sub(a.g, b.g)), num_abs(num_sub(a.b, b.b))));
}

rgb_t haze_apply(render_ctx_t *ctx, rgb_t c, num_t t, num_t t_err, num_t weight)
{
    const scene_t *s = ctx->frame->scene;
    if (!s->haze)
        return c;
    num_t w = haze_exp_neg(num_mul(s->haze_k, t));
    rgb_t h = s->haze_colour;
    /* w moves by at most w k t_err with t (exp falls at rate w, k per
     * unit), and by the method's own error */
    num_t dw = num_add(num_mul(num_mul(w, s->haze_k), t_err), HAZE_EXP_ERR);
    if (num_is_sat(dw) ||
        !num_lt(num_mul(num_mul(dw, haze_spread(c, h)), weight), NUM_C(RENDER_HAZE_LOST_VALUE)))
        ctx->pixel_lost = 1;
    return rgb_make(num_add(h.r, num_mul(num_sub(c.r, h.r), w)),
                    num_add(h.g, num_mul(num_sub(c.g, h.g), w)),
                    num_add(h.b, num_mul(num_sub(c.b, h.b), w)));
}
