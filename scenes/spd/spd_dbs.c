/* spd_dbs.c: the databases, from the descriptions published with the
 * Standard Procedural Databases (Eric Haines, 1987).  Counts, for size s:
 *   balls   sphereflake: a sphere and nine children a third its size,
 *           recursively, s levels below the root: (9^(s+1) - 1) / 8
 *           spheres (10, 91, 820, 7,381 at s = 1..4; with the ground,
 *           SPD's 7,382 objects at its default size 4) on a ground square
 *   tetra   Sierpinski tetrahedron, s levels: 4^s tetrahedra, 4^(s+1)
 *           triangles (16,384 at s = 6)
 *   mount   fractal mountain, midpoint displacement s times: 2 * 4^s
 *           triangles (8,192 at s = 6), four spheres floating above it
 *   rings   s x s rings in a square, each a ring of 8 spheres joined by
 *           cylinders, stacked s/2 + 1 layers high, on a ground square
 *   tree    a branching tree: every branch a cone with two children,
 *           s levels (2^s - 1 branches), a leaf sphere at each tip
 *   gears   s x s gears in a plane: a toothed disk (polygons) with
 *           its rim, meshing with their neighbours
 * Sizes grow the object count about 4x (balls 9x) per step, as in SPD.
 * Each database is seeded identically every run: the same size gives the
 * same file.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "scenes/spd/spd.h"

#define PI 3.14159265358979323846


static void ground(struct spd_out *o, const char *mat, double half, double z)
{
    double v[4][3] = {{half, half, z}, {-half, half, z}, {-half, -half, z}, {half, -half, z}};
    spd_polygon(o, mat, (const double (*)[3])v, 4);
}

/* --------------------------------------------------------------- balls */

/* a frame whose w axis is the direction d */
static void frame_of(const double d[3], double u[3], double v[3])
{
    double any[3] = {0, 0, 1};
    if (fabs(d[2]) > 0.9)
        any[0] = 1, any[2] = 0;
    u[0] = d[1] * any[2] - d[2] * any[1];
    u[1] = d[2] * any[0] - d[0] * any[2];
    u[2] = d[0] * any[1] - d[1] * any[0];
    double l = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int k = 0; k < 3; k++)
        u[k] /= l;
    v[0] = d[1] * u[2] - d[2] * u[1];
    v[1] = d[2] * u[0] - d[0] * u[2];
    v[2] = d[0] * u[1] - d[1] * u[0];
}

static void flake(struct spd_out *o, const double c[3], double r, const double dir[3], int levels)
{
    spd_sphere(o, "ball", c, r);
    if (levels == 0)
        return;
    double u[3], v[3];
    frame_of(dir, u, v);
    /* six children round the equator, three above between them */
    for (int i = 0; i < 9; i++) {
        double az = i < 6 ? i * PI / 3 : (i - 6) * 2 * PI / 3 + PI / 6;
        double el = i < 6 ? 0 : PI / 3;
        double d[3], cc[3];
        for (int k = 0; k < 3; k++) {
            d[k] = cos(el) * (cos(az) * u[k] + sin(az) * v[k]) + sin(el) * dir[k];
            cc[k] = c[k] + d[k] * (r + r / 3);
        }
        flake(o, cc, r / 3, d, levels - 1);
    }
}

void spd_balls(struct spd_out *o, int size, int width, int height)
{
    const double from[3] = {2.1, 1.3, 1.7}, at[3] = {0, 0, 0}, up[3] = {0, 0, 1};
    spd_view(o, from, at, up, 45, width, height, spd_sky);
    const double l[3][3] = {{4, 3, 2}, {1, -4, 4}, {-3, 1, 5}};
    for (int i = 0; i < 3; i++)
        spd_light(o, l[i], 1 / sqrt(3.0));
    spd_material(o, "floor", (const double[3]){1, 0.75, 0.33}, 0.8, 0, 0, 0, 1);
    spd_material(o, "ball", (const double[3]){1, 0.9, 0.7}, 0.5, 0.5, 3, 0, 1);
    ground(o, "floor", 12, -0.5);
    flake(o, (const double[3]){0, 0, 0}, 0.5, (const double[3]){0, 0, 1}, size);
}

/* --------------------------------------------------------------- tetra */

static void tetra(struct spd_out *o, const double (*v)[3], int level)
{
    if (level == 0) {
        static const int face[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
        for (int f = 0; f < 4; f++)
            spd_triangle(o, "tetra", v[face[f][0]], v[face[f][1]], v[face[f][2]]);
        return;
    }
    for (int corner = 0; corner < 4; corner++) {
        double w[4][3];
        for (int i = 0; i < 4; i++)
            for (int k = 0; k < 3; k++)
                w[i][k] = 0.5 * (v[corner][k] + v[i][k]);
        tetra(o, (const double (*)[3])w, level - 1);
    }
}

void spd_tetra(struct spd_out *o, int size, int width, int height)
{
    const double from[3] = {1.2, -2.2, 1.1}, at[3] = {0, 0, -0.05}, up[3] = {0, 0, 1};
    spd_view(o, from, at, up, 45, width, height, spd_sky);
    spd_light(o, (const double[3]){1.85, -2.0, 3.35}, 0.8);
    spd_light(o, (const double[3]){-2.5, -3.0, 0.5}, 0.5);
    spd_material(o, "tetra", (const double[3]){1, 0.2, 0.2}, 0.8, 0, 0, 0, 1);
    const double s = 1 / sqrt(2.0);
    double v[4][3] = {{0, -s, -0.5}, {0, s, -0.5}, {-s, 0, 0.5}, {s, 0, 0.5}};
    /* a regular tetrahedron: its edges at z = -0.5 and 0.5 cross at right angles */
    tetra(o, (const double (*)[3])v, size);
}

/* --------------------------------------------------------------- mount */

/* a repeatable pseudo-random number in [-1, 1] for a grid point */
static double hash_unit(uint32_t a, uint32_t b, uint32_t seed)
{
    uint32_t h = a * 0x9e3779b1u ^ (b + 0x7f4a7c15u) * 0x85ebca6bu ^ seed * 0xc2b2ae35u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return (double)h / 2147483647.5 - 1;
}

void spd_mount(struct spd_out *o, int size, int width, int height)
{
    const double from[3] = {-1.0, -8.8, 3.5}, at[3] = {0, 0, 0.4}, up[3] = {0, 0, 1};
    spd_view(o, from, at, up, 25, width, height, spd_sky);
    spd_light(o, (const double[3]){-100, -100, 200}, 1);
    spd_material(o, "rock", (const double[3]){1, 0.5, 0.2}, 0.9, 0, 0, 0, 1);
    spd_material(o, "glass", (const double[3]){1, 1, 1}, 0.1, 0.2, 30, 0.75, 1.5);
    spd_material(o, "mirror", (const double[3]){0.9, 0.9, 0.9}, 0.3, 0.7, 60, 0, 1);
    /* a (2^size + 1)^2 grid of heights over [-2, 2]^2, refined by
     * midpoint displacement halving the amplitude each level */
    int n = 1 << size, m = n + 1;
    static double hgt[(1 << 8) + 1][(1 << 8) + 1];
    memset(hgt, 0, sizeof hgt);
    double amp = 1.0;
    for (int step = n; step > 1; step /= 2, amp *= 0.5) {
        int h = step / 2;
        for (int i = 0; i < n; i += step)
            for (int j = 0; j <= n; j += step) {
                /* edge midpoints along both directions, then the centre */
                hgt[i + h][j] = 0.5 * (hgt[i][j] + hgt[i + step][j]) + amp * 0.5 * hash_unit((uint32_t)(i + h), (uint32_t)j, 1);
                hgt[j][i + h] = 0.5 * (hgt[j][i] + hgt[j][i + step]) + amp * 0.5 * hash_unit((uint32_t)j, (uint32_t)(i + h), 2);
            }
        for (int i = 0; i < n; i += step)
            for (int j = 0; j < n; j += step)
                hgt[i + h][j + h] = 0.25 * (hgt[i][j] + hgt[i + step][j] + hgt[i][j + step] +
                                            hgt[i + step][j + step]) +
                                    amp * 0.5 * hash_unit((uint32_t)(i + h), (uint32_t)(j + h), 3);
    }
    /* a peak: raise the middle */
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++) {
            double x = 4.0 * i / n - 2, y = 4.0 * j / n - 2;
            hgt[i][j] += 1.2 * exp(-(x * x + y * y));
        }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double p[4][3];
            for (int c = 0; c < 4; c++) {
                int a = i + (c == 1 || c == 2), b = j + (c >= 2);
                p[c][0] = 4.0 * a / n - 2;
                p[c][1] = 4.0 * b / n - 2;
                p[c][2] = hgt[a][b];
            }
            spd_triangle(o, "rock", p[0], p[1], p[2]);
            spd_triangle(o, "rock", p[0], p[2], p[3]);
        }
    spd_sphere(o, "glass", (const double[3]){-0.8, -0.8, 1.9}, 0.45);
    spd_sphere(o, "mirror", (const double[3]){0.9, -0.5, 2.1}, 0.4);
    spd_sphere(o, "glass", (const double[3]){0.2, -1.3, 2.5}, 0.3);
    spd_sphere(o, "mirror", (const double[3]){-0.3, 0.6, 2.8}, 0.35);
}

/* --------------------------------------------------------------- rings */

static void ring(struct spd_out *o, const double c[3], double r, double t)
{
    double p[9][3];
    for (int i = 0; i <= 8; i++) {
        double a = 2 * PI * (i % 8) / 8;
        p[i][0] = c[0] + r * cos(a);
        p[i][1] = c[1] + r * sin(a);
        p[i][2] = c[2];
    }
    for (int i = 0; i < 8; i++) {
        spd_sphere(o, "ring", p[i], t);
        spd_cone(o, "ring", p[i], t, p[i + 1], t);
    }
}

void spd_rings(struct spd_out *o, int size, int width, int height)
{
    double span = 2.5 * size;
    const double from[3] = {-span * 0.55, -span * 1.0, span * 0.75};
    const double at[3] = {0, 0, 0.5}, up[3] = {0, 0, 1};
    spd_view(o, from, at, up, 40, width, height, spd_sky);
    spd_light(o, (const double[3]){-3 * span, -2 * span, 4 * span}, 0.6);
    spd_light(o, (const double[3]){2 * span, -3 * span, 3 * span}, 0.5);
    spd_material(o, "floor", (const double[3]){0.9, 0.9, 0.9}, 0.8, 0, 0, 0, 1);
    spd_material(o, "ring", (const double[3]){0.9, 0.6, 0.2}, 0.6, 0.4, 20, 0, 1);
    ground(o, "floor", 3 * span, -0.3);
    int layers = size / 2 + 1;
    for (int l = 0; l < layers; l++)
        for (int i = 0; i < size; i++)
            for (int j = 0; j < size; j++) {
                double c[3] = {(i - (size - 1) / 2.0) * 2.5 + (l % 2) * 1.25,
                               (j - (size - 1) / 2.0) * 2.5 + (l % 2) * 1.25, l * 0.8};
                ring(o, c, 1.0, 0.12);
            }
}

/* ---------------------------------------------------------------- tree */

static void branch(struct spd_out *o, const double base[3], const double dir[3], double len,
                   double r, int level, uint32_t id)
{
    double tip[3];
    for (int k = 0; k < 3; k++)
        tip[k] = base[k] + dir[k] * len;
    spd_cone(o, "bark", base, r, tip, r * 0.7);
    if (level == 1) {
        spd_sphere(o, "leaf", tip, len * 0.5);
        return;
    }
    double u[3], v[3];
    frame_of(dir, u, v);
    for (int c = 0; c < 2; c++) {
        double turn = 0.45 + 0.1 * hash_unit(id, (uint32_t)c, 7);
        double az = c * PI + 1.3 * level + 0.3 * hash_unit(id, (uint32_t)c, 8);
        double d[3];
        for (int k = 0; k < 3; k++)
            d[k] = cos(turn) * dir[k] + sin(turn) * (cos(az) * u[k] + sin(az) * v[k]);
        branch(o, tip, d, len * 0.75, r * 0.7, level - 1, id * 2 + (uint32_t)c);
    }
}

void spd_tree(struct spd_out *o, int size, int width, int height)
{
    const double from[3] = {4.5, -7.5, 2.6}, at[3] = {0, 0, 2.0}, up[3] = {0, 0, 1};
    spd_view(o, from, at, up, 45, width, height, spd_sky);
    spd_light(o, (const double[3]){-5, -6, 10}, 0.8);
    spd_light(o, (const double[3]){6, -2, 4}, 0.4);
    spd_material(o, "floor", (const double[3]){0.4, 0.6, 0.3}, 0.8, 0, 0, 0, 1);
    spd_material(o, "bark", (const double[3]){0.55, 0.4, 0.25}, 0.8, 0, 0, 0, 1);
    spd_material(o, "leaf", (const double[3]){0.2, 0.7, 0.2}, 0.7, 0.2, 10, 0, 1);
    ground(o, "floor", 20, 0);
    branch(o, (const double[3]){0, 0, 0}, (const double[3]){0, 0, 1}, 1.6, 0.2, size, 1);
}

/* --------------------------------------------------------------- gears */

static void gear(struct spd_out *o, const double c[3], double r, int teeth, double phase,
                 const char *mat)
{
    /* outline: each tooth is 4 points, tip radius r, root radius 0.85 r */
    int n = teeth * 4;
    double top[4 * 64][3], bot[4 * 64][3];
    for (int i = 0; i < n; i++) {
        double a = phase + 2 * PI * i / n;
        double rr = (i % 4 == 1 || i % 4 == 2) ? r : 0.85 * r;
        top[i][0] = bot[i][0] = c[0] + rr * cos(a);
        top[i][1] = bot[i][1] = c[1] + rr * sin(a);
        top[i][2] = c[2] + 0.1 * r;
        bot[i][2] = c[2] - 0.1 * r;
    }
    /* the faces as fans from the centre (the outline is not convex) */
    double ct[3] = {c[0], c[1], c[2] + 0.1 * r}, cb[3] = {c[0], c[1], c[2] - 0.1 * r};
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        spd_triangle(o, mat, ct, top[i], top[j]);
        spd_triangle(o, mat, cb, bot[j], bot[i]);
        spd_triangle(o, mat, bot[i], bot[j], top[j]);
        spd_triangle(o, mat, bot[i], top[j], top[i]);
    }
}

void spd_gears(struct spd_out *o, int size, int width, int height)
{
    double span = 2.0 * size;
    const double from[3] = {-span * 0.6, -span * 1.5, span * 1.3};
    const double at[3] = {0, 0, 0}, up[3] = {0, 0, 1};
    spd_view(o, from, at, up, 40, width, height, spd_sky);
    spd_light(o, (const double[3]){-2 * span, -3 * span, 5 * span}, 0.7);
    spd_light(o, (const double[3]){3 * span, -span, 2 * span}, 0.4);
    spd_material(o, "floor", (const double[3]){0.8, 0.8, 0.8}, 0.5, 0.5, 40, 0, 1);
    spd_material(o, "brass", (const double[3]){0.9, 0.7, 0.3}, 0.6, 0.4, 30, 0, 1);
    spd_material(o, "steel", (const double[3]){0.6, 0.65, 0.7}, 0.5, 0.5, 50, 0, 1);
    ground(o, "floor", 2 * span, -0.3);
    for (int i = 0; i < size; i++)
        for (int j = 0; j < size; j++) {
            double c[3] = {(i - (size - 1) / 2.0) * 2.0, (j - (size - 1) / 2.0) * 2.0, 0};
            /* neighbours turn half a tooth apart so the teeth mesh */
            gear(o, c, 1.07, 16, ((i + j) % 2) * PI / 16, (i + j) % 2 ? "steel" : "brass");
        }
}
