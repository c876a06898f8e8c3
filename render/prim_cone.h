/* render/prim_cone.h: the cone frustum and the cylinder (SCENE_PRIM_CONE):
 * its local frame, worked out by render_prepare and precision_detail, and
 * its ray test and surface, which prim.c's dispatch calls.  The method is
 * in docs/renderer.md ("Cones and cylinders").
 *
 * In its local frame (render_prim_t.to_local) the axis runs along y from
 * -1, the larger end of radius 1, to 1, the smaller end of radius
 * 1 - 2 cone_slope (the same as the larger for a cylinder, 0 for a pointed
 * cone): the surface x^2 + z^2 = rho(y)^2 with rho(y) = 1 - cone_slope
 * (1 + y), between the end discs, which close it when cone_capped.
 */
#ifndef LINKS1_RENDER_PRIM_CONE_H
#define LINKS1_RENDER_PRIM_CONE_H

#include "render/prim.h"

/* A cone in its cluster's coordinates. */
typedef struct {
    vec3_t centre;  /* the midpoint of its axis */
    vec3_t axis;    /* unit, from the larger end towards the smaller */
    vec3_t u, w;    /* unit, across the axis and each other */
    num_t half;     /* half the axis's length, > 0 */
    num_t radius;   /* the larger end's radius, > 0 */
    num_t slope;    /* render_prim_t.cone_slope: (1 - smaller/larger) / 2 */
} prim_cone_frame_t;

/* The frame of a scene cone (the loader has checked its radii and ends);
 * 0 when it saturates or its axis has no length in num_t. */
int prim_cone_frame(const scene_prim_t *sp, prim_cone_frame_t *f);

/* The map from its cluster's coordinates to the local frame above. */
xform_t prim_cone_shape(const prim_cone_frame_t *f);

/* prim_intersect_uncertain of a cone (prim.h). */
int prim_cone_intersect(const render_prim_t *p, const ray_t *ray, const ray_error_t *err,
                        num_t tmin, num_t tmax, num_t *t_out, int *uncertain);

/* prim_surface of a cone: its side's or its cap's normal, tangent, map
 * coordinates (the side: u round the axis as an ellipsoid's, v along it
 * from the larger end; a cap: u, v across it from -1 to 1 of x and z) and
 * the curvature at the hit. */
void prim_cone_surface(const render_prim_t *p, hit_t *hit);

#endif
