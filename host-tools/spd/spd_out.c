/* spd_out.c: the NFF writer and the vector and matrix steps of the
 * generators (see spd.h).  Kept apart from the generators so the math
 * library computes every sine and cosine at run time, as the SPD's own
 * library does. */
#include <math.h>
#include <string.h>

#include "host-tools/spd/spd.h"

/* ------------------------------------------------------------------ NFF */

void spd_background(struct spd_out *o, const double c[3])
{
    fprintf(o->f, "b %g %g %g\n", c[0], c[1], c[2]);
}

void spd_view(struct spd_out *o, const double from[3], const double at[3], const double up[3],
              double angle, double hither)
{
    fprintf(o->f, "v\nfrom %g %g %g\nat %g %g %g\nup %g %g %g\nangle %g\nhither %g\n"
                  "resolution %d %d\n",
            from[0], from[1], from[2], at[0], at[1], at[2], up[0], up[1], up[2], angle, hither,
            o->width, o->height);
}

void spd_light(struct spd_out *o, const double p[3])
{
    fprintf(o->f, "l %g %g %g\n", p[0], p[1], p[2]);
}

void spd_surface(struct spd_out *o, const double rgb[3], double kd, double ks,
                 double half_angle, double kt, double ior)
{
    /* the Phong power whose highlight falls to half at half_angle */
    double rad = SPD_PI * half_angle / 180.0, shine;
    if (rad <= 0.0)
        shine = 100000.0; /* no highlight */
    else if (rad >= SPD_PI / 2.0)
        shine = 1.0;
    else
        shine = log(0.5) / log(cos(rad));
    fprintf(o->f, "f %g %g %g %g %g %g %g %g\n", rgb[0], rgb[1], rgb[2], kd, ks, shine, kt, ior);
}

void spd_sphere(struct spd_out *o, const double c[3], double r)
{
    fprintf(o->f, "s %g %g %g %g\n", c[0], c[1], c[2], r);
}

void spd_cone(struct spd_out *o, const double base[3], double r0, const double apex[3],
              double r1)
{
    fprintf(o->f, "c %g %g %g %g %g %g %g %g\n", base[0], base[1], base[2], r0, apex[0],
            apex[1], apex[2], r1);
}

void spd_polygon(struct spd_out *o, int n, double (*v)[3])
{
    for (int i = 0; i < n;) {
        double d[3] = {v[i][0] - v[(i + 1) % n][0], v[i][1] - v[(i + 1) % n][1],
                       v[i][2] - v[(i + 1) % n][2]};
        if (spd_normalize(d) < 1.0e-6) {
            memmove(v + i, v + i + 1, (size_t)(n - i - 1) * sizeof *v);
            n--;
        } else {
            i++;
        }
    }
    if (n < 3)
        return;
    fprintf(o->f, "p %d\n", n);
    for (int i = 0; i < n; i++)
        fprintf(o->f, "%g %g %g\n", v[i][0], v[i][1], v[i][2]);
}

void spd_patch(struct spd_out *o, int n, const double (*v)[3], const double (*nrm)[3])
{
    fprintf(o->f, "pp %d\n", n);
    for (int i = 0; i < n; i++)
        fprintf(o->f, "%g %g %g %g %g %g\n", v[i][0], v[i][1], v[i][2], nrm[i][0], nrm[i][1],
                nrm[i][2]);
}

/* ------------------------------------------------- vectors and matrices */

void spd_identity(struct spd_mat *m)
{
    memset(m, 0, sizeof *m);
    for (int i = 0; i < 4; i++)
        m->m[i][i] = 1.0;
}

void spd_rotate(struct spd_mat *m, int axis, double angle)
{
    double c = cos(angle), s = sin(angle);
    int a = (axis + 1) % 3, b = (axis + 2) % 3; /* the plane turned: x->y, y->z, z->x */
    memset(m, 0, sizeof *m);
    m->m[axis][axis] = 1.0;
    m->m[a][a] = c;
    m->m[b][b] = c;
    m->m[a][b] = s;
    m->m[b][a] = -s;
    m->m[3][3] = 1.0;
}

/* the rotation by angle about the unit axis u (Rodrigues' formula), in
 * the row-vector convention: p' = p m */
void spd_axis_rotate(struct spd_mat *m, const double u[3], double angle)
{
    double c = cos(angle), s = sin(angle), t = 1.0 - c;
    memset(m, 0, sizeof *m);
    m->m[0][0] = u[0] * u[0] + (1.0 - u[0] * u[0]) * c;
    m->m[0][1] = u[0] * u[1] * t + u[2] * s;
    m->m[0][2] = u[0] * u[2] * t - u[1] * s;
    m->m[1][0] = u[0] * u[1] * t - u[2] * s;
    m->m[1][1] = u[1] * u[1] + (1.0 - u[1] * u[1]) * c;
    m->m[1][2] = u[1] * u[2] * t + u[0] * s;
    m->m[2][0] = u[0] * u[2] * t + u[1] * s;
    m->m[2][1] = u[1] * u[2] * t - u[0] * s;
    m->m[2][2] = u[2] * u[2] + (1.0 - u[2] * u[2]) * c;
    m->m[3][3] = 1.0;
}

void spd_mat_mul(struct spd_mat *out, const struct spd_mat *a, const struct spd_mat *b)
{
    struct spd_mat r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            r.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] +
                        a->m[i][2] * b->m[2][j] + a->m[i][3] * b->m[3][j];
    *out = r;
}

void spd_xform_vector(double out[3], const double v[3], const struct spd_mat *m)
{
    double r[3];
    for (int j = 0; j < 3; j++)
        r[j] = v[0] * m->m[0][j] + v[1] * m->m[1][j] + v[2] * m->m[2][j];
    memcpy(out, r, sizeof r);
}

void spd_xform_point(double out[3], const double v[3], const struct spd_mat *m)
{
    double r[3];
    for (int j = 0; j < 3; j++)
        r[j] = v[0] * m->m[0][j] + v[1] * m->m[1][j] + v[2] * m->m[2][j] + m->m[3][j];
    memcpy(out, r, sizeof r);
}

void spd_xform4(double out[4], const double v[4], const struct spd_mat *m)
{
    double r[4];
    for (int j = 0; j < 4; j++)
        r[j] = v[0] * m->m[0][j] + v[1] * m->m[1][j] + v[2] * m->m[2][j] + v[3] * m->m[3][j];
    memcpy(out, r, sizeof r);
}

double spd_normalize(double v[3])
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0.0)
        for (int k = 0; k < 3; k++)
            v[k] /= len;
    return len;
}
