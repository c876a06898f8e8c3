/* render/maps.h: colour and bump maps (2-D arrays) looked up at (u, v). */
#ifndef LINKS1_RENDER_MAPS_H
#define LINKS1_RENDER_MAPS_H

#include "render/render.h"

/* 1 when rounding of a map coordinate (about 8 steps of the arithmetic at
 * 1), times the repeats and the map's size, can move a lookup by more than
 * RENDER_MAP_TEXEL_TOLERANCE_VALUE texels: a pixel that uses it counts as
 * lost precision. */
int map_imprecise(const scene_map_t *m);

/* Bilinear colour at (u, v), repeated repeat_u x repeat_v times over [0,1). */
rgb_t map_colour(const scene_map_t *m, num_t u, num_t v);

/* Normal n tilted by the height map's slope at (u, v): with T the tangent,
 * B = n x T and slopes su, sv the central differences of neighbouring
 * texels / (2*255), the result is normalize(n - depth*(su*T + sv*B)). */
vec3_t map_bump(const scene_map_t *m, num_t u, num_t v, vec3_t n, vec3_t tangent);

#endif
