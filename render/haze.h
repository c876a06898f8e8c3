/* render/haze.h: haze (the scene's `haze { colour R G B  distance D }`,
 * proto/scene_format.h SCN_SEC_HAZE), POV-Ray's fog_type 1: a ray's
 * colour c at distance t from its origin becomes h + (c - h) exp(-t/D),
 * and a ray that hits nothing takes h.  Every ray is hazed, camera,
 * reflected and transmitted alike (each from its own origin), as POV-Ray
 * fogs every ray it traces; shadow rays are not (docs/renderer.md, "Haze").
 *
 * exp has a method of its own in num_t (haze_exp_neg: +, -, * and powers
 * of two only), so each arithmetic's haze is the same on the board and the
 * host bit for bit, with no libm. */
#ifndef LINKS1_RENDER_HAZE_H
#define LINKS1_RENDER_HAZE_H

#include "render/render.h"

/* exp(-x) for x >= 0 (1 for x <= 0): x = n ln 2 + r, exp(-r) by its Taylor
 * series in Horner form (HAZE_EXP_TERMS terms: under a step of the
 * arithmetic for 0 <= r < ln 2), times 2^-n.  0 from HAZE_EXP_MAX on and
 * for a saturated x. */
num_t haze_exp_neg(num_t x);

/* The colour of a ray that hits nothing: the haze's, else the background. */
static inline rgb_t haze_miss(const render_ctx_t *ctx)
{
    const scene_t *s = ctx->frame->scene;
    return s->haze ? s->haze_colour : s->background;
}

/* c, the colour a ray found at distance t (its error bound t_err) from its
 * origin, seen through the haze (c itself without one; the callers ask
 * scene->haze first, so a scene without haze pays no call).  The pixel is
 * flagged (ctx->pixel_lost) when the haze weight's uncertainty, times how
 * far c lies from the haze colour and the ray's weight, may move it by
 * RENDER_HAZE_LOST_VALUE or more. */
rgb_t haze_apply(render_ctx_t *ctx, rgb_t c, num_t t, num_t t_err, num_t weight);

/* The haze weight exp(-k d) of a span of length d (1 without haze). */
num_t haze_weight(const render_ctx_t *ctx, num_t d);

#endif
