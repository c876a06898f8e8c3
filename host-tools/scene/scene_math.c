/* scene_math.c: the host's 3x4 matrices and quaternions for scene files:
 * composing transform statements, turning Euler angles into the quaternions
 * the board interpolates (it has no trigonometry), and evaluating keyframes
 * for outputs that need a fixed frame (POV-Ray). */
#include <math.h>
#include <string.h>

#include "host-tools/scene/scene_desc.h"

#define SD_PI 3.14159265358979323846
/* sin and cos of whole right angles come out as 1e-16 or so instead of 0;
 * they are snapped to 0 so "rotate 0 90 0" maps axes onto axes exactly in
 * every arithmetic (a 1e-16 direction component is not a value the float
 * and fixed builds can carry the way double does). */
#define SD_SNAP 1e-12

static double sd_snap(double v) { return fabs(v) < SD_SNAP ? 0 : v; }

#define SD_MIN_TRIANGLE_AREA 1e-12 /* |e1 x e2|, twice the area */

int sd_triangle_degenerate(const double v[9])
{
    double e1[3], e2[3], c[3];
    for (int i = 0; i < 3; i++)
        e1[i] = v[3 + i] - v[i], e2[i] = v[6 + i] - v[i];
    c[0] = e1[1] * e2[2] - e1[2] * e2[1];
    c[1] = e1[2] * e2[0] - e1[0] * e2[2];
    c[2] = e1[0] * e2[1] - e1[1] * e2[0];
    return !(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) >= SD_MIN_TRIANGLE_AREA) ||
           !(sd_triangle_min_height(v) >= SCN_MIN_TRIANGLE_HEIGHT);
}

const char *sd_cone_invalid(const double v[SCN_CONE_VALUES])
{
    if (!(v[3] >= 0) || !(v[7] >= 0))
        return "a cone's radius is negative";
    if (!(v[3] > 0) && !(v[7] > 0))
        return "a cone whose radii are both 0 (a line)";
    double d[3] = {v[4] - v[0], v[5] - v[1], v[6] - v[2]};
    if (!(sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) >= SCN_MIN_TRIANGLE_HEIGHT))
        return "a cone of zero height (its base and apex are the same point)";
    return NULL;
}

double sd_triangle_min_height(const double v[9])
{
    /* each height is twice the area over its base: the smallest stands on
     * the longest edge */
    double e1[3], e2[3], c[3], longest = 0;
    for (int i = 0; i < 3; i++)
        e1[i] = v[3 + i] - v[i], e2[i] = v[6 + i] - v[i];
    c[0] = e1[1] * e2[2] - e1[2] * e2[1];
    c[1] = e1[2] * e2[0] - e1[0] * e2[2];
    c[2] = e1[0] * e2[1] - e1[1] * e2[0];
    for (int k = 0; k < 3; k++) {
        const double *a = v + 3 * k, *b = v + 3 * ((k + 1) % 3);
        double d = sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                        (b[2] - a[2]) * (b[2] - a[2]));
        longest = d > longest ? d : longest;
    }
    return longest > 0 ? sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / longest : 0;
}

void sd_mat_mul(const double a[12], const double b[12], double out[12])
{
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 4; c++) {
            double v = c == 3 ? a[r * 4 + 3] : 0;
            for (int k = 0; k < 3; k++)
                v += a[r * 4 + k] * b[k * 4 + c];
            out[r * 4 + c] = v;
        }
    }
}

/* q = a * b (apply b, then a) */
static void sd_quat_mul(const double a[4], const double b[4], double q[4])
{
    q[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    q[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    q[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    q[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

void sd_euler_quat(const double deg[3], double q[4])
{
    double axis[3][4];
    for (int i = 0; i < 3; i++) {
        double h = deg[i] * SD_PI / 360.0; /* half angle, radians */
        memset(axis[i], 0, sizeof axis[i]);
        axis[i][0] = sd_snap(cos(h));
        axis[i][1 + i] = sd_snap(sin(h));
    }
    double zy[4];
    sd_quat_mul(axis[2], axis[1], zy);
    sd_quat_mul(zy, axis[0], q); /* x first, then y, then z */
}

void sd_quat_matrix(const double q[4], double m[12])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double r[12] = {
        1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 0,
        2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x), 0,
        2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y), 0,
    };
    for (int i = 0; i < 12; i++)
        m[i] = sd_snap(r[i]);
}

static void sd_key_trs(const struct sd_key *k, double t[3], double q[4], double s[3])
{
    memcpy(t, k->translate, 3 * sizeof *t);
    memcpy(s, k->scale, 3 * sizeof *s);
    sd_euler_quat(k->rotate, q);
}

void sd_key_matrix(const struct sd_scene *s, int c, int frame, double k[12])
{
    const struct sd_cluster *cl = &s->clusters[c];
    double t[3], q[4], sc[3];
    memset(k, 0, 12 * sizeof *k);
    k[0] = k[5] = k[10] = 1;
    if (cl->key_count == 0)
        return;
    const struct sd_key *keys = s->keys + cl->key_first;
    int n = cl->key_count;
    if (frame <= keys[0].frame) {
        sd_key_trs(&keys[0], t, q, sc);
    } else if (frame >= keys[n - 1].frame) {
        sd_key_trs(&keys[n - 1], t, q, sc);
    } else {
        int i = 0;
        while (keys[i + 1].frame <= frame)
            i++;
        double a = (double)(frame - keys[i].frame) / (keys[i + 1].frame - keys[i].frame);
        double t1[3], q1[4], s1[3];
        sd_key_trs(&keys[i], t, q, sc);
        sd_key_trs(&keys[i + 1], t1, q1, s1);
        /* normalised linear interpolation along the shorter arc */
        double dot = q[0] * q1[0] + q[1] * q1[1] + q[2] * q1[2] + q[3] * q1[3];
        double sign = dot < 0 ? -1 : 1, len = 0;
        for (int j = 0; j < 4; j++) {
            q[j] = q[j] * (1 - a) + sign * q1[j] * a;
            len += q[j] * q[j];
        }
        for (int j = 0; j < 4; j++)
            q[j] /= sqrt(len);
        for (int j = 0; j < 3; j++) {
            t[j] = t[j] * (1 - a) + t1[j] * a;
            sc[j] = sc[j] * (1 - a) + s1[j] * a;
        }
    }
    double r[12];
    sd_quat_matrix(q, r);
    for (int row = 0; row < 3; row++) {
        for (int col = 0; col < 3; col++)
            k[row * 4 + col] = r[row * 4 + col] * sc[col];
        k[row * 4 + 3] = t[row];
    }
}
