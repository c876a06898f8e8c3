/* nff_read.h: Eric Haines's Neutral File Format (NFF, the output of the
 * Standard Procedural Databases) into a scene (scene_desc.h), for
 * `links1 ref/render/compile FILE.nff` (scene_file.c) and links1-spd
 * (host-tools/spd/).  The mapping, entity by entity (docs/scene-format.md,
 * "NFF files"):
 *
 *   v   from/at/up/angle/hither/resolution: the camera; angle spans the
 *       centres of the first and last pixels across the narrower side of
 *       the image (NFF's definition); hither is read and ignored
 *   b   the background colour
 *   l   a point light, colour R G B if given, else 1/sqrt(number of lights)
 *       (the SPD's rule for renderers that do not scale light intensity);
 *       more than SCN_MAX_LIGHTS are merged, the two nearest in direction
 *       from the view's `at` point first, into one of their summed colour
 *       at their intensity-weighted mean position
 *   f   a material (nff_material; identical ones are shared)
 *   s   a sphere
 *   p   a polygon: triangles, a fan when it is convex, otherwise cut by
 *       ear clipping (the gears' faces are concave)
 *   pp  the same with a vertex normal at each corner: smooth triangles
 *   c   a cone or cylinder, open-ended as NFF has it ("the surface exists
 *       without endcaps"): the renderer's cone (SCN_PRIM_CONE); paper mode
 *       makes it SD_CONE_SIDES facets round (sd_paper_facet_cones)
 *
 * NFF is right-handed (z up in the SPD); y is negated on the way in, so
 * the left-handed renderer shows the picture the file describes.  A
 * triangle the scene parser would refuse as degenerate (sd_triangle_
 * degenerate) is left out and counted.  Errors are "file:line:col: what"
 * through scene_lex's lex_error, like the text form's.
 */
#ifndef LINKS1_HOST_SCENE_NFF_READ_H
#define LINKS1_HOST_SCENE_NFF_READ_H

#include <stddef.h>

#include "host-tools/scene/scene_desc.h"

#define NFF_MAX_POLY_VERTICES 4096 /* vertices of one p or pp */
#define NFF_MAX_LIGHTS 256         /* l entities in one file (merged into 3) */
#define NFF_MAX_FILE (64u * 1024u * 1024u) /* larger files are refused */

/* What a file held and what became of it. */
struct nff_info {
    long spheres, polygons, patches, cones; /* entities read */
    long triangles;     /* triangles placed (polygons, patches) */
    long dropped;       /* degenerate triangles left out */
    int lights;         /* l entities read */
    int lights_merged;  /* merges made to keep SCN_MAX_LIGHTS */
};

/* The NFF text (NUL-terminated) into *s; name is used in messages.  On
 * failure -1 with "name:line:col: what is wrong" in err and *s empty.
 * info may be NULL. */
int nff_read_text(const char *name, const char *text, struct sd_scene *s, struct nff_info *info,
                  char *err, size_t errlen);
/* The same from a file.  With info NULL, a note on stderr says when lights
 * were merged or triangles left out. */
int nff_read_file(const char *path, struct sd_scene *s, struct nff_info *info, char *err,
                  size_t errlen);

/* The material of an NFF surface, f = {r, g, b, Kd, Ks, Shine, T, ior}
 * (each checked by the reader: colour 0..1, the rest >= 0):
 *   colour r g b   dic 0 (NFF has no ambient term)   drc min(Kd, 1)
 *   src min(Ks, 1), the reflection and the highlight's weight, as in NFF
 *   trc min(T, 1); where src + trc > 1, src = 1 - trc
 *   fresnel 0 (NFF's coefficients do not depend on the angle)
 *   ior within 1..SCN_MAX_IOR (the SPD writes 0 for opaque surfaces)
 *   phong: Shine rounded, 0..SCN_MAX_PHONG; 0 when Ks is 0
 * The name is left empty. */
void nff_material(const double f[8], struct sd_material *m);

/* The horizontal field of view (degrees) of NFF's angle at width x height;
 * -1 when the result is outside SCN_MIN_FOV..SCN_MAX_FOV. */
double nff_fov(double angle, int width, int height);

#endif
