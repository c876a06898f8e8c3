/* render/maps.h: colour, bump, normal and attribute maps (2-D arrays)
 * looked up at (u, v). */
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

/* Bilinear value 0..1 of an ATTRIBUTE map at (u, v), as map_colour (and
 * with map_colour's precision test, map_imprecise). */
num_t map_attribute(const scene_map_t *m, num_t u, num_t v);

/* Normal of a NORMAL map at (u, v), nearest texel (x, y, z) / 127 in the
 * tangent frame normalize(x*T + y*B + z*n), B = n x T, or -(n x T) when
 * mirrored (prim_map_tangent gives T and mirrored).  A texel (0, 0, z),
 * the flat normal, gives n itself, not renormalized. */
vec3_t map_normal(const scene_map_t *m, num_t u, num_t v, vec3_t n, vec3_t tangent, int mirrored);

/* 1 when the texel map_normal picks at (u, v) could, under the lookup's
 * error (map_texel_error), be a neighbour holding another normal: the
 * normal jumps between texels by any amount, so the pixel counts as lost
 * precision.  Neighbours holding the same normal are no uncertainty (a
 * flat map never is); an error of half a texel or more always is. */
int map_normal_uncertain(const scene_map_t *m, num_t u, num_t v, num_t uv_error);

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
