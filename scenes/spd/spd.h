/* spd.h: the Standard Procedural Databases (Eric Haines, 1987) as links1
 * text scenes.  Each generator writes one scene through the helpers below;
 * the shapes the renderer lacks become triangles (spd_out.c):
 *   polygon   a fan of n - 2 triangles
 *   cylinder  and cone: SPD_SIDES quads (two triangles each) around the
 *             axis; open ends, as in the databases
 * The databases are written in SPD's right-handed, z-up world; the writer
 * mirrors y so the left-handed renderer shows the same picture.
 */
#ifndef LINKS1_SCENES_SPD_H
#define LINKS1_SCENES_SPD_H

#include <stdio.h>

#define SPD_SIDES 12 /* facets around a cylinder or cone */

/* SPD's background colour */
extern const double spd_sky[3];

struct spd_out {
    FILE *f;
    long spheres, triangles; /* written so far */
    long dropped;            /* degenerate triangles left out */
};

/* camera at from looking at `at`, up, full angle (degrees) */
void spd_view(struct spd_out *o, const double from[3], const double at[3], const double up[3],
              double angle, int width, int height, const double background[3]);
void spd_light(struct spd_out *o, const double pos[3], double intensity);
/* SPD's "f" line: colour, Kd, Ks, shine, T, index of refraction */
void spd_material(struct spd_out *o, const char *name, const double rgb[3], double kd, double ks,
                  double shine, double t, double ior);
void spd_sphere(struct spd_out *o, const char *mat, const double c[3], double r);
void spd_triangle(struct spd_out *o, const char *mat, const double a[3], const double b[3],
                  const double c[3]);
void spd_polygon(struct spd_out *o, const char *mat, const double (*v)[3], int n);
/* base centre and radius, apex centre and radius (0: a cone's point) */
void spd_cone(struct spd_out *o, const char *mat, const double base[3], double r0,
              const double apex[3], double r1);

/* The databases: each writes a whole scene of the given size (>= 1). */
void spd_balls(struct spd_out *o, int size, int width, int height);
void spd_tetra(struct spd_out *o, int size, int width, int height);
void spd_mount(struct spd_out *o, int size, int width, int height);
void spd_rings(struct spd_out *o, int size, int width, int height);
void spd_tree(struct spd_out *o, int size, int width, int height);
void spd_gears(struct spd_out *o, int size, int width, int height);
void spd_teapot(struct spd_out *o, int size, int width, int height);

#endif
