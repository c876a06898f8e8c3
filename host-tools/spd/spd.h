/* spd.h: the Standard Procedural Databases (Eric Haines, "A Proposal for
 * Standard Graphics Environments", IEEE CG&A 7(11), 1987), written here
 * from their published definitions: each generator writes its database in
 * the Neutral File Format exactly as the SPD's own programs write it with
 * `-r 1` (the same entities in the same order, every number printed with
 * %g), and links1-spd turns that text into a scene through the NFF reader
 * (host-tools/scene/nff_read.h), the same path `links1 ref FILE.nff` takes.
 */
#ifndef LINKS1_SCENES_SPD_H
#define LINKS1_SCENES_SPD_H

#include <stdio.h>

#define SPD_PI 3.141592653589793 /* the SPD's value of pi */

/* ------------------------------------------------------- the NFF writer */

struct spd_out {
    FILE *f;
    int width, height; /* the view's resolution (512 x 512 in the SPD) */
};

void spd_background(struct spd_out *o, const double rgb[3]);
/* hither is written and ignored by the reader */
void spd_view(struct spd_out *o, const double from[3], const double at[3], const double up[3],
              double angle, double hither);
void spd_light(struct spd_out *o, const double pos[3]);
/* a surface as the SPD describes it: diffuse kd, reflection ks, the
 * highlight's half angle in degrees (its "f" line gives the Phong power
 * log(0.5) / log(cos(angle)); 100000 for no highlight), transmission kt,
 * index of refraction */
void spd_surface(struct spd_out *o, const double rgb[3], double kd, double ks,
                 double half_angle, double kt, double ior);
void spd_sphere(struct spd_out *o, const double c[3], double r);
void spd_cone(struct spd_out *o, const double base[3], double r0, const double apex[3],
              double r1);
/* a polygon: neighbouring vertices closer than 1e-6 become one, as in the
 * SPD's writer (it changes v); fewer than 3 left write nothing */
void spd_polygon(struct spd_out *o, int n, double (*v)[3]);
/* a polygonal patch: vertices and their normals */
void spd_patch(struct spd_out *o, int n, const double (*v)[3], const double (*nrm)[3]);

/* ----------------------------------- the SPD's vector and matrix steps
 * Row vectors times 4x4 matrices, as the SPD computes them: the arithmetic
 * is done in the same order so the numbers come out the same. */

struct spd_mat {
    double m[4][4];
};

enum { SPD_X, SPD_Y, SPD_Z };

void spd_identity(struct spd_mat *m);
void spd_rotate(struct spd_mat *m, int axis, double angle); /* radians */
void spd_axis_rotate(struct spd_mat *m, const double axis[3], double angle);
void spd_mat_mul(struct spd_mat *out, const struct spd_mat *a, const struct spd_mat *b);
void spd_xform_vector(double out[3], const double v[3], const struct spd_mat *m);
void spd_xform_point(double out[3], const double v[3], const struct spd_mat *m);
void spd_xform4(double out[4], const double v[4], const struct spd_mat *m);
double spd_normalize(double v[3]); /* returns the length it had */

/* --------------------------------------------------------- the databases */

struct spd_db {
    const char *name;
    void (*make)(struct spd_out *o, int size);
    int max_size;     /* the largest whose scene fits the board (spd_main.c) */
    int default_size; /* the SPD's own default */
};

void spd_balls(struct spd_out *o, int size);
void spd_gears(struct spd_out *o, int size);
void spd_mount(struct spd_out *o, int size);
void spd_rings(struct spd_out *o, int size);
void spd_teapot(struct spd_out *o, int size);
void spd_tetra(struct spd_out *o, int size);
void spd_tree(struct spd_out *o, int size);

/* The databases in alphabetical order, and their count. */
extern const struct spd_db spd_dbs[];
extern const int spd_db_count;
const struct spd_db *spd_find(const char *name);

/* Database `db` at `size` as NFF text into f, width x height. */
void spd_write_nff(const struct spd_db *db, int size, int width, int height, FILE *f);

#endif
