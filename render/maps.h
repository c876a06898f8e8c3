/* render/maps.h: colour and bump maps (2-D arrays) looked up at (u, v). */
#ifndef LINKS1_RENDER_MAPS_H
#define LINKS1_RENDER_MAPS_H

#include "render/render.h"

/* Estimated error, in texels, of a lookup whose map coordinates u, v are
 * off by up to uv_error (render_prim_t.uv_error), plus 8 steps of the
 * arithmetic at 1 for the lookup's own rounding, times the repeats and the
 * map's size. */
num_t map_texel_error(const scene_map_t *m, num_t uv_error);

/* 1 when that error can move a bilinear colour lookup by more than
 * RENDER_MAP_TEXEL_TOLERANCE_VALUE texels (a colour change over 2/255):
 * a pixel that uses it counts as lost precision. */
int map_imprecise(const scene_map_t *m, num_t uv_error);

/* Bilinear colour at (u, v), repeated repeat_u x repeat_v times over [0,1). */
rgb_t map_colour(const scene_map_t *m, num_t u, num_t v);

/* Normal n tilted by the height map's slope at (u, v): with T the tangent,
 * B = n x T and slopes su, sv the central differences of neighbouring
 * texels / (2*255), the result is normalize(n - depth*(su*T + sv*B)). */
vec3_t map_bump(const scene_map_t *m, num_t u, num_t v, vec3_t n, vec3_t tangent);

/* 1 when the nearest texel map_bump picks at (u, v) could be its neighbour
 * under the lookup's error (map_texel_error): the slope, and so the
 * normal, jumps between texels by any amount, so the pixel counts as lost
 * precision. */
int map_bump_uncertain(const scene_map_t *m, num_t u, num_t v, num_t uv_error);

#endif
