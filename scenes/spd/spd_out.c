/* spd_out.c: writing SPD's shapes as a links1 text scene (see spd.h). */
#include <math.h>
#include <stdlib.h>

#include "host-tools/scene/scene_desc.h"
#include "scenes/spd/spd.h"

#define SPD_PI 3.14159265358979323846

const double spd_sky[3] = {0.078, 0.361, 0.753};

/* SPD's right-handed world into the renderer's left-handed one */
static void spd_p(struct spd_out *o, const char *what, const double v[3])
{
    fprintf(o->f, " %s %.6g %.6g %.6g", what, v[0], -v[1], v[2]);
}

void spd_view(struct spd_out *o, const double from[3], const double at[3], const double up[3],
              double angle, int width, int height, const double background[3])
{
    /* SPD's angle spans the image's height (square in the originals);
     * the renderer's fov spans its width */
    double fov = 2 * atan(tan(angle * SPD_PI / 360) * width / height) * 180 / SPD_PI;
    fprintf(o->f, "camera {");
    spd_p(o, "eye", from);
    spd_p(o, "look_at", at);
    spd_p(o, "up", up);
    fprintf(o->f, "  fov %.6g }\nresolution %d %d\nbackground %.4g %.4g %.4g\n", fov, width,
            height, background[0], background[1], background[2]);
    fprintf(o->f, "options { max_depth 5 }\n");
}

void spd_light(struct spd_out *o, const double pos[3], double intensity)
{
    fprintf(o->f, "light point { colour %.4g %.4g %.4g ", intensity, intensity, intensity);
    spd_p(o, "position", pos);
    fprintf(o->f, " }\n");
}

void spd_material(struct spd_out *o, const char *name, const double rgb[3], double kd, double ks,
                  double shine, double t, double ior)
{
    if (ks + t > 1) /* the renderer keeps src + trc <= 1 */
        ks = 1 - t;
    int phong = shine > 1024 ? 1024 : (int)(shine + 0.5);
    fprintf(o->f,
            "material %s { colour %.4g %.4g %.4g  dic 0.1  drc %.4g  src %.4g  trc %.4g  "
            "ior %.4g  phong %d }\n",
            name, rgb[0], rgb[1], rgb[2], kd, ks, t, ior < 1 ? 1.0 : ior, phong);
}

void spd_sphere(struct spd_out *o, const char *mat, const double c[3], double r)
{
    fprintf(o->f, "sphere { material %s", mat);
    spd_p(o, "centre", c);
    fprintf(o->f, " radius %.6g }\n", r);
    o->spheres++;
}

/* v as the scene file will hold it (spd_p's digits) */
static void spd_as_written(const double v[3], double out[3])
{
    char t[32];
    for (int k = 0; k < 3; k++) {
        snprintf(t, sizeof t, "%.6g", v[k]);
        out[k] = strtod(t, NULL);
    }
}

void spd_triangle(struct spd_out *o, const char *mat, const double a[3], const double b[3],
                  const double c[3])
{
    /* a triangle the scene parser would refuse as degenerate (a fine
     * tessellation's slivers near a pole) is left out */
    double w[9];
    spd_as_written(a, w);
    spd_as_written(b, w + 3);
    spd_as_written(c, w + 6);
    if (sd_triangle_degenerate(w)) {
        o->dropped++;
        return;
    }
    fprintf(o->f, "triangle { material %s", mat);
    spd_p(o, "v", a);
    spd_p(o, "v", b);
    spd_p(o, "v", c);
    fprintf(o->f, " }\n");
    o->triangles++;
}

void spd_polygon(struct spd_out *o, const char *mat, const double (*v)[3], int n)
{
    for (int i = 1; i + 1 < n; i++)
        spd_triangle(o, mat, v[0], v[i], v[i + 1]);
}

static void spd_unit(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++)
        v[k] /= l;
}

static void spd_cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void spd_cone(struct spd_out *o, const char *mat, const double base[3], double r0,
              const double apex[3], double r1)
{
    double axis[3] = {apex[0] - base[0], apex[1] - base[1], apex[2] - base[2]};
    spd_unit(axis);
    double any[3] = {1, 0, 0};
    if (fabs(axis[0]) > 0.9)
        any[0] = 0, any[1] = 1;
    double u[3], v[3];
    spd_cross(axis, any, u);
    spd_unit(u);
    spd_cross(axis, u, v);
    double ring0[SPD_SIDES + 1][3], ring1[SPD_SIDES + 1][3];
    for (int i = 0; i <= SPD_SIDES; i++) {
        double a = 2 * SPD_PI * (i % SPD_SIDES) / SPD_SIDES;
        for (int k = 0; k < 3; k++) {
            double d = cos(a) * u[k] + sin(a) * v[k];
            ring0[i][k] = base[k] + r0 * d;
            ring1[i][k] = apex[k] + r1 * d;
        }
    }
    for (int i = 0; i < SPD_SIDES; i++) {
        spd_triangle(o, mat, ring0[i], ring0[i + 1], ring1[i + 1]);
        if (r1 > 0)
            spd_triangle(o, mat, ring0[i], ring1[i + 1], ring1[i]);
    }
}
