/* render/shade.c: the terms of the paper's Fig. 5 (see shade.h). */
#include "render/shade.h"

#include "render/vec3.h"

num_t shade_spot_falloff(num_t cos_angle, num_t cos_outer, num_t cos_inner)
{
    if (!num_gt(cos_angle, cos_outer))
        return NUM_ZERO;
    if (!num_lt(cos_angle, cos_inner))
        return NUM_ONE;
    num_t x = num_div(num_sub(cos_angle, cos_outer), num_sub(cos_inner, cos_outer));
    x = num_clamp01(x);
    return num_mul(num_mul(x, x), num_sub(NUM_C(3), num_mul_int(x, 2)));
}

vec3_t shade_reflect(vec3_t d, vec3_t n)
{
    return vec3_normalize(vec3_sub(d, vec3_scale(n, num_mul_int(vec3_dot(d, n), 2))));
}

int shade_refract(vec3_t d, vec3_t n, num_t eta, vec3_t *out)
{
    num_t cos_i = num_clamp01(num_neg(vec3_dot(d, n)));
    num_t sin2 = num_sub(NUM_ONE, num_mul(cos_i, cos_i));
    num_t k = num_sub(NUM_ONE, num_mul(num_mul(eta, eta), sin2));
    if (num_lt(k, NUM_ZERO))
        return 0;
    num_t along_n = num_sub(num_mul(eta, cos_i), num_sqrt(k));
    *out = vec3_normalize(vec3_add(vec3_scale(d, eta), vec3_scale(n, along_n)));
    return 1;
}
