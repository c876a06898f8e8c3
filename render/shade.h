/* render/shade.h: the paper's Fig. 5 shading model, term by term.
 *
 *   I = sum_i [ (dic + drc cos th_i) F + cos^n(th_ri) src(th) ] S_i
 *       + src(th) I_r + trc(th) F I_t
 *
 * with S_i light i's intensity times the transmissivity of everything
 * between the point and the light (the paper's shadow rule).  The ambient
 * term dic F takes S_i (options.ambient_shadowed, the default) or the
 * unshadowed L_i.  docs/renderer.md has the details and the readings;
 * these functions are separate so the tests can check each term.
 */
#ifndef LINKS1_RENDER_SHADE_H
#define LINKS1_RENDER_SHADE_H

#include "render/render.h"
#include "render/vec3.h"

/* src(th) and trc(th), the paper's reflection coefficient and
 * transmissivity as functions of the angle of incidence "approximating
 * Fresnel's law", at incidence cosine cos_theta (in [0,1]):
 *   s = fresnel * (1 - cos_theta)^5            (Schlick's curve, weighted)
 *   src(th) = src + (1 - src) * s              (src at normal incidence,
 *                                               1 at grazing when fresnel 1)
 *   trc(th) = trc * (1 - s)                    (trc at normal incidence,
 *                                               0 at grazing when fresnel 1)
 * fresnel = 0 gives the constants src and trc (Whitted's). */
static inline void shade_src_trc(const scene_material_t *m, num_t cos_theta, num_t *src,
                                 num_t *trc)
{
    num_t c = num_clamp01(cos_theta);
    num_t s = num_mul(m->fresnel, num_pow_int(num_sub(NUM_ONE, c), 5));
    *src = num_add(m->src, num_mul(num_sub(NUM_ONE, m->src), s));
    *trc = num_mul(m->trc, num_sub(NUM_ONE, s));
}

/* Smooth spotlight edge: 0 at cos_outer, 1 at cos_inner, smoothstep between. */
num_t shade_spot_falloff(num_t cos_angle, num_t cos_outer, num_t cos_inner);

/* Parallel lights are "infinitely" far: shadow rays stop here instead. */
#define SHADE_PARALLEL_DISTANCE NUM_FAR

/* Light i as seen from point: unit direction towards the light, distance
 * (a large constant for parallel light) and the unshadowed intensity
 * (spotlight cone applied).  0 if the point gets nothing from it. */
static inline int shade_light_at(const render_light_t *l, vec3_t point, vec3_t *to_light,
                                  num_t *distance, rgb_t *intensity)
{
    *intensity = l->intensity;
    if (l->kind == SCENE_LIGHT_PARALLEL) {
        *to_light = l->to_light;
        *distance = SHADE_PARALLEL_DISTANCE;
        return 1;
    }
    vec3_t v = vec3_sub(l->position, point);
    num_t dist = vec3_length(v);
    if (!num_gt(dist, NUM_ZERO) || num_is_sat(dist))
        return 0;
    *to_light = vec3_scale(v, num_recip(dist));
    *distance = dist;
    if (l->kind == SCENE_LIGHT_SPOT) {
        num_t k = shade_spot_falloff(num_neg(vec3_dot(*to_light, l->axis)), l->cos_outer,
                                     l->cos_inner);
        if (!num_gt(k, NUM_ZERO))
            return 0;
        *intensity = rgb_scale(l->intensity, k);
    }
    return 1;
}

/* One light's term of the sum: normal n faces the viewer, view is the unit
 * ray direction arriving at the point, to_light unit; shadowed the light
 * the diffuse and highlight terms take, ambient the light the ambient
 * term takes where it is another (not shadowed), NULL where it is the
 * same: the product of colour and light is then made once.  Inline:
 * called once a light at every hit, where its eight arguments' passing
 * cost more than its body. */
static inline rgb_t shade_light_term(const scene_material_t *m, rgb_t colour, vec3_t n,
                                     vec3_t view, vec3_t to_light, const rgb_t *ambient,
                                     rgb_t shadowed, num_t src_theta)
{
    /* ambient: dic F times the light given (S_i, or L_i whatever lies
     * between point and light) */
    rgb_t lit = rgb_mul(colour, ambient ? *ambient : shadowed);
    num_t cos_i = vec3_dot(n, to_light);
    if (!num_gt(cos_i, NUM_ZERO))
        return rgb_scale(lit, m->dic);
    /* diffuse: drc cos(th_i) F S_i; of the same light as the ambient
     * term, both in one product: (dic + drc cos) F S_i */
    rgb_t out;
    if (ambient)
        out = rgb_add(rgb_scale(lit, m->dic),
                      rgb_scale(rgb_mul(colour, shadowed), num_mul(m->drc, cos_i)));
    else
        out = rgb_scale(lit, num_add(m->dic, num_mul(m->drc, cos_i)));
    if (m->phong_n == 0)
        return out;
    /* highlight: cos^n of the angle between the mirrored light and the
     * direction back to the viewer, times src(th) */
    vec3_t mirrored = vec3_sub(vec3_scale(n, num_mul_int(cos_i, 2)), to_light);
    num_t cos_r = num_neg(vec3_dot(mirrored, view));
    if (!num_gt(cos_r, NUM_ZERO))
        return out;
    num_t k = num_mul(num_pow_int(num_min(cos_r, NUM_ONE), m->phong_n), src_theta);
    return rgb_add(out, rgb_scale(shadowed, k));
}

/* Mirror direction of d about unit normal n. */
vec3_t shade_reflect(vec3_t d, vec3_t n);

/* Refracted direction of unit d entering through unit normal n (facing
 * against d) with eta = n1/n2; 0 on total internal reflection. */
int shade_refract(vec3_t d, vec3_t n, num_t eta, vec3_t *out);

#endif
