/* spd_dbs.c: six of the seven databases (the teapot is spd_teapot.c), from
 * the definitions published with the Standard Procedural Databases (Eric
 * Haines, 1987; version 3.14 of the package).  Each writes what the SPD's
 * program of the same name writes with `-r 1`: the same view (angle 45,
 * 512 x 512 unless --size), the same lights and surfaces, the same
 * primitives in the same order.  Size s gives:
 *   balls   sphereflake: a sphere with nine children a third its size,
 *           s levels deep: (9^(s+1) - 1) / 8 spheres (10, 91, 820, 7,381)
 *           and the floor polygon
 *   gears   s^3 gears, each two 144-sided concave faces and 144 side
 *           quadrilaterals, and the ground polygon
 *   mount   a fractal mountain, midpoint displacement s times: 2 * 4^s
 *           triangles (8, 32, 128, ... 8,192 at 6), and 4 glass spheres
 *   rings   s layers of dodecahedral ring sets, 1, 4, 9, ... of them: 30
 *           spheres and 30 cylinders each (30, 150, 420, ... 4,200 at 7)
 *   tetra   a Sierpinski tetrahedron of s levels: 4^s triangles
 *   tree    a branching tree of 2^(s+1) - 1 cones, a sphere at each tip
 */
#include <math.h>
#include <string.h>

#include "host-tools/spd/spd.h"

/* every database's background: "UNC sky blue" */
static const double spd_sky[3] = {0.078, 0.361, 0.753};

static void spd_head(struct spd_out *o, const double from[3], const double at[3],
                     const double up[3], double hither)
{
    spd_background(o, spd_sky);
    spd_view(o, from, at, up, 45.0, hither);
}

/* --------------------------------------------------------------- balls */

/* The nine directions of a sphere's children, unit vectors (w 0): three
 * trios 120 degrees apart about z, each trio three corners of a cube
 * turned so that its diagonal is z. */
static void balls_directions(double dirs[9][4])
{
    double d = 1.0 / sqrt((double)2.0);
    double trio[3][4] = {{d, d, 0.0, 0.0}, {d, 0.0, -d, 0.0}, {0.0, d, -d, 0.0}};
    double axis[3] = {1.0, -1.0, 0.0};
    spd_normalize(axis);
    struct spd_mat m;
    spd_axis_rotate(&m, axis, asin((double)(2.0 / sqrt((double)6.0))));
    for (int i = 0; i < 3; i++)
        spd_xform4(trio[i], trio[i], &m);
    for (int set = 0; set < 3; set++) {
        spd_rotate(&m, SPD_Z, (double)set * 2.0 * SPD_PI / 3.0);
        for (int i = 0; i < 3; i++)
            spd_xform4(dirs[set * 3 + i], trio[i], &m);
    }
}

/* A sphere (c: centre and radius) and, levels deep, its children along
 * the directions turned from z to dir (dir[3]: a child's radius ratio). */
static void balls_flake(struct spd_out *o, const double dirs[9][4], int levels,
                        const double c[4], const double dir[4])
{
    spd_sphere(o, c, c[3]);
    if (levels-- == 0)
        return;
    struct spd_mat m;
    if (dir[2] >= 0.9999) {
        spd_identity(&m);
    } else if (dir[2] <= -0.9999) {
        spd_rotate(&m, SPD_Y, SPD_PI);
    } else {
        /* the axis z x dir, the angle between them */
        const double z[3] = {0.0, 0.0, 1.0};
        double axis[3] = {z[1] * dir[2] - z[2] * dir[1], z[2] * dir[0] - z[0] * dir[2],
                          z[0] * dir[1] - z[1] * dir[0]};
        spd_normalize(axis);
        spd_axis_rotate(&m, axis, acos((double)(z[0] * dir[0] + z[1] * dir[1] + z[2] * dir[2])));
    }
    double reach = c[3] * (1.0 + dir[3]); /* centre to a child's centre */
    for (int i = 0; i < 9; i++) {
        double child[4], child_dir[4];
        spd_xform4(child, dirs[i], &m);
        for (int k = 0; k < 3; k++)
            child[k] = child[k] * reach + c[k];
        child[3] = c[3] * dir[3];
        for (int k = 0; k < 3; k++)
            child_dir[k] = (child[k] - c[k]) / reach;
        child_dir[3] = dir[3];
        balls_flake(o, dirs, levels, child, child_dir);
    }
}

void spd_balls(struct spd_out *o, int size)
{
    spd_head(o, (const double[3]){2.1, 1.3, 1.7}, (const double[3]){0.0, 0.0, 0.0},
             (const double[3]){0.0, 0.0, 1.0}, 0.01);
    spd_light(o, (const double[3]){4.0, 3.0, 2.0});
    spd_light(o, (const double[3]){1.0, -4.0, 4.0});
    spd_light(o, (const double[3]){-3.0, 1.0, 5.0});
    /* the floor: beige, matte, a square 24 wide half a radius below */
    spd_surface(o, (const double[3]){1.0, 0.75, 0.33}, 0.8, 0.0, 0.0, 0.0, 1.0);
    double floor[4][3] = {{12.0, 12.0, -0.5}, {-12.0, 12.0, -0.5}, {-12.0, -12.0, -0.5},
                          {12.0, -12.0, -0.5}};
    spd_polygon(o, 4, floor);
    /* the spheres: mirrored */
    spd_surface(o, (const double[3]){1.0, 0.9, 0.7}, 0.5, 0.5, 37.0, 0.0, 1.0);
    double dirs[9][4];
    balls_directions(dirs);
    balls_flake(o, (const double(*)[4])dirs, size, (const double[4]){0.0, 0.0, 0.0, 0.5},
                (const double[4]){0.0, 0.0, 1.0, 1.0 / 3.0});
}

/* --------------------------------------------------------------- tetra */

/* the corners (x, y, z) = centre + half * (+-1, +-1, +-1) with x y z = +1 */
static void tetra_corners(const double c[4], double scale, double out[4][3])
{
    int n = 0;
    for (int x = -1; x <= 1; x += 2)
        for (int y = -1; y <= 1; y += 2)
            for (int z = -1; z <= 1; z += 2)
                if (x * y * z == 1) {
                    out[n][0] = c[0] + (double)x * c[3] / scale;
                    out[n][1] = c[1] + (double)y * c[3] / scale;
                    out[n][2] = c[2] + (double)z * c[3] / scale;
                    n++;
                }
}

/* c: the centre of the tetrahedron's cube and half its side */
static void tetra(struct spd_out *o, int depth, const double c[4])
{
    double p[4][3];
    if (depth <= 1) {
        tetra_corners(c, 1.0, p);
        for (int face = 0; face < 4; face++) {
            /* corners face, face+1, face+2 (mod 4); odd faces reversed */
            int a = face, b = (face + 1) % 4, d = (face + 2) % 4;
            if (face % 2 == 1) {
                int t = a;
                a = d;
                d = t;
            }
            double tri[3][3];
            memcpy(tri[0], p[a], sizeof tri[0]);
            memcpy(tri[1], p[b], sizeof tri[1]);
            memcpy(tri[2], p[d], sizeof tri[2]);
            spd_polygon(o, 3, tri);
        }
        return;
    }
    tetra_corners(c, 2.0, p);
    for (int i = 0; i < 4; i++) {
        double sub[4] = {p[i][0], p[i][1], p[i][2], c[3] / 2.0};
        tetra(o, depth - 1, sub);
    }
}

void spd_tetra(struct spd_out *o, int size)
{
    /* Kay and Kajiya's view and light */
    spd_head(o, (const double[3]){1.022846, -3.177154, -2.174512},
             (const double[3]){-0.004103, -0.004103, 0.216539},
             (const double[3]){-0.816497, -0.816497, 0.816497}, 1.0);
    spd_light(o, (const double[3]){2.0, -18.0, -5.0});
    spd_surface(o, (const double[3]){1.0, 0.2, 0.2}, 1.0, 0.0, 0.0, 0.0, 0.0);
    tetra(o, size, (const double[4]){0.0, 0.0, 0.0, 1.0});
}

/* --------------------------------------------------------------- mount */

/* The SPD's own pseudo-random numbers: a seed from the grid position (the
 * original, repetitive hash, as in the 1987 pictures), then the gaussian
 * deviate of Numerical Recipes' GASDEV on a small linear congruential
 * generator.  At size 8 the hash's last shift is by -1, which C leaves
 * undefined; that term is taken as 0, as the SPD's program compiled with
 * gcc for x86-64 computes it. */
static long mount_hash(long a, long b, int size)
{
    unsigned long h = ((unsigned long)a << (23 - size)) + ((unsigned long)b << (15 - size));
    if (size <= 7)
        h += (unsigned long)a << (7 - size);
    return (long)(h & 0xffff);
}

static double mount_gauss(long seed)
{
    long a, b = seed;
    double v1, v2, r;
    do {
        a = (28411 + b * 8121) % 134456;
        b = (28411 + a * 8121) % 134456;
        v1 = (double)a * 2.0 / 134456 - 1.0;
        v2 = (double)b * 2.0 / 134456 - 1.0;
        r = v1 * v1 + v2 * v2;
    } while (r >= 1.0);
    return v1 * sqrt((double)(-2.0 * log(r) / r));
}

struct mount {
    struct spd_out *o;
    int size;
    double cells;     /* 2^size, the grid's cells along a side */
    double roughness;
};

/* The square of `width` cells at (x, y) with heights z at its corners
 * (lower left, lower right, upper right, upper left): split in four with
 * displaced midpoints, or at width 1 written as two triangles. */
static void mount_grow(const struct mount *m, int width, int x, int y, const double z[4])
{
    if (width == 1) {
        double x0 = -1.0 + (double)x * 2.0 / m->cells, x1 = -1.0 + (double)(x + 1) * 2.0 / m->cells;
        double y0 = -1.0 + (double)y * 2.0 / m->cells, y1 = -1.0 + (double)(y + 1) * 2.0 / m->cells;
        double corner[4][3] = {{x0, y0, z[0]}, {x1, y0, z[1]}, {x1, y1, z[2]}, {x0, y1, z[3]}};
        for (int t = 0; t < 2; t++) {
            double tri[3][3];
            for (int v = 0; v < 3; v++)
                memcpy(tri[v], corner[(v + t * 2) % 4], sizeof tri[v]);
            spd_polygon(m->o, 3, tri);
        }
        return;
    }
    int half = width >> 1;
    double rise = (double)half * 2.0 / m->cells * m->roughness;
#define MOUNT_RAND(px, py) mount_gauss(21 + mount_hash((px), (py), m->size))
    double lower = (z[0] + z[1]) / 2.0 + rise * MOUNT_RAND(x + half, y);
    double right = (z[1] + z[2]) / 2.0 + rise * MOUNT_RAND(x + width, y + half);
    double upper = (z[2] + z[3]) / 2.0 + rise * MOUNT_RAND(x + half, y + width);
    double left = (z[3] + z[0]) / 2.0 + rise * MOUNT_RAND(x, y + half);
    double middle = (z[0] + z[1] + z[2] + z[3]) / 4.0 + 1.4142136 * rise * MOUNT_RAND(x + half,
                                                                                    y + half);
#undef MOUNT_RAND
    mount_grow(m, half, x, y, (const double[4]){z[0], lower, middle, left});
    mount_grow(m, half, x + half, y, (const double[4]){lower, z[1], right, middle});
    mount_grow(m, half, x + half, y + half, (const double[4]){middle, right, z[2], upper});
    mount_grow(m, half, x, y + half, (const double[4]){left, middle, upper, z[3]});
}

void spd_mount(struct spd_out *o, int size)
{
    spd_head(o, (const double[3]){-1.6, 1.6, 1.7}, (const double[3]){0.0, 0.0, 0.0},
             (const double[3]){0.0, 0.0, 1.0}, 0.01);
    spd_light(o, (const double[3]){-100.0, -100.0, 100.0});
    /* four crystal spheres in a pyramid above the mountain */
    spd_surface(o, (const double[3]){1.0, 1.0, 1.0}, 0.1, 0.1, 6.7, 0.9, 1.5);
    const double base[4] = {-0.8, 0.8, 1.00, 0.17};
    double top[3] = {0.0, 0.0, base[3] * sqrt((double)(3.0 / 2.0))}, s[3], turned[3];
    for (int k = 0; k < 3; k++)
        s[k] = base[k] + top[k];
    spd_sphere(o, s, base[3]);
    double axis[3] = {1.0, 1.0, 0.0};
    spd_normalize(axis);
    struct spd_mat rot;
    spd_axis_rotate(&rot, axis, acos((double)(-1.0 / 3.0)));
    spd_xform_vector(turned, top, &rot);
    for (int i = 0; i < 3; i++) {
        spd_rotate(&rot, SPD_Z, (double)i * 2.0 * SPD_PI / 3.0);
        spd_xform_vector(s, turned, &rot);
        for (int k = 0; k < 3; k++)
            s[k] += base[k];
        spd_sphere(o, s, base[3]);
    }
    /* the mountain: grey, fractal dimension 2.2 */
    spd_surface(o, (const double[3]){0.5, 0.45, 0.35}, 1.0, 0.0, 0.0, 0.0, 0.0);
    struct mount m = {o, size, (double)(1 << size), 0};
    double ratio = 2.0 / exp((double)(log((double)2.0) / (2.2 - 1.0)));
    m.roughness = sqrt((double)(ratio * ratio - 1.0));
    mount_grow(&m, 1 << size, 0, 0, (const double[4]){0.0, 0.0, 0.0, 0.0});
}

/* --------------------------------------------------------------- rings */

/* The 30 edge midpoints of a dodecahedron as six pentagonal rings, scaled
 * so that the rings (cylinders of radius r round them) fit a unit sphere. */
static void rings_points(double r, double p[30][3])
{
    double scale = 1.0 / (1.0 + r);
    for (int i = 0; i < 5; i++) {
        p[i][0] = scale * cos((double)i * 2.0 * SPD_PI / 5.0);
        p[i][1] = scale * sin((double)i * 2.0 * SPD_PI / 5.0);
        p[i][2] = 0.0;
    }
    /* the other five: turned about x by the angle between two faces, then
     * about z by 1/10 + k/5 of a turn */
    struct spd_mat tilt, spin;
    spd_rotate(&tilt, SPD_X, 2.0 * acos(cos((double)(SPD_PI / 3.0)) / sin((double)(SPD_PI / 5.0))));
    for (int ring = 1; ring < 6; ring++) {
        spd_rotate(&spin, SPD_Z, SPD_PI * (2.0 * (double)(ring - 1) + 1.0) / 5.0);
        for (int i = 0; i < 5; i++) {
            double t[3];
            spd_xform_point(t, p[i], &tilt);
            spd_xform_point(p[5 * ring + i], t, &spin);
        }
    }
}

void spd_rings(struct spd_out *o, int size)
{
    const double radius = 0.07412; /* of the cylinders and spheres */
    double gap = 1 / sin((double)(SPD_PI / 8.0)); /* between layers, along y */
    double from[3] = {-1.0, -gap, 0.5}, at[3] = {from[0], from[1] + 1.0, from[2]};
    spd_head(o, from, at, (const double[3]){0.0, 0.0, 1.0}, 1.0);
    spd_light(o, (const double[3]){3.0, -gap, 3.0});
    spd_light(o, (const double[3]){-4.0, -gap, 1.0});
    spd_light(o, (const double[3]){2.0, -gap, -4.0});
    /* a white wall behind, just filling the 45 degree view (+1%) */
    spd_surface(o, (const double[3]){1.0, 1.0, 1.0}, 1.0, 0.0, 0.0, 0.0, 0.0);
    double wy = gap * (size + 1), wxz = 1.01 * (wy - from[1]) * tan(SPD_PI / 8.0);
    double wall[4][3] = {{wxz + from[0], wy, wxz + from[2]},
                         {-wxz + from[0], wy, wxz + from[2]},
                         {-wxz + from[0], wy, -wxz + from[2]},
                         {wxz + from[0], wy, -wxz + from[2]}};
    spd_polygon(o, 4, wall);
    static const double colour[6][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0},
                                        {0.0, 1.0, 1.0}, {1.0, 0.0, 1.0}, {1.0, 1.0, 0.0}};
    double p[30][3];
    rings_points(radius, p);
    /* layer d holds (d+1)^2 sets, y = gap (d+1), spread 2 apart in x and z */
    for (int d = 0; d < size; d++)
        for (int iz = 0; iz <= d; iz++)
            for (int ix = 0; ix <= d; ix++) {
                double off[3] = {1.0 * (double)(2 * ix - d), gap * (double)(d + 1),
                                 1.0 * (double)(2 * iz - d)};
                for (int e = 0; e < 30; e++) {
                    int prev = e % 5 == 0 ? e + 4 : e - 1;
                    if (e % 5 == 0)
                        spd_surface(o, colour[e / 5], 0.5, 0.2, 37.0, 0.0, 0.0);
                    double b[3], a[3];
                    for (int k = 0; k < 3; k++) {
                        b[k] = p[e][k] + off[k];
                        a[k] = p[prev][k] + off[k];
                    }
                    spd_cone(o, b, radius, a, radius);
                    spd_sphere(o, b, radius);
                }
            }
}

/* ---------------------------------------------------------------- tree */

/* Each branch: a cone from (0,0,0) to (0,0,1) of its frame, radius 0.15
 * of its scale at the base and 0.67 of that at the tip, a sphere at the
 * tip, and two children in the frames step[0] and step[1] of it. */
static void tree_grow(struct spd_out *o, const struct spd_mat step[2], const struct spd_mat *frame,
                      double scale, int depth)
{
    double base[3], tip[3];
    spd_xform_point(base, (const double[3]){0.0, 0.0, 0.0}, frame);
    spd_xform_point(tip, (const double[3]){0.0, 0.0, 1.0}, frame);
    double r0 = scale * 0.15, r1 = r0 * 0.67;
    spd_cone(o, base, r0, tip, r1);
    spd_sphere(o, tip, r1);
    if (depth-- <= 0)
        return;
    for (int i = 0; i < 2; i++) {
        struct spd_mat child;
        spd_mat_mul(&child, &step[i], frame);
        tree_grow(o, step, &child, scale * 0.67, depth);
    }
}

void spd_tree(struct spd_out *o, int size)
{
    spd_head(o, (const double[3]){4.5, 0.4, 2.0}, (const double[3]){0.0, 0.0, 1.5},
             (const double[3]){0.0, 0.0, 1.0}, 1.0);
    static const double lights[7][3] = {{-5.0, 5.0, 50.0},   {30.0, -30.0, 30.0},
                                        {-40.0, -30.0, 20.0}, {10.0, 30.0, 40.0},
                                        {-30.0, 40.0, 10.0},  {50.0, 25.0, 20.0},
                                        {-10.0, -60.0, 30.0}};
    for (int i = 0; i < 7; i++)
        spd_light(o, lights[i]);
    spd_surface(o, (const double[3]){0.2, 0.7, 0.2}, 1.0, 0.0, 0.0, 0.0, 0.0);
    double field[4][3] = {{50.0, 50.0, 0.0}, {-50.0, 50.0, 0.0}, {-50.0, -50.0, 0.0},
                          {50.0, -50.0, 0.0}};
    spd_polygon(o, 4, field);
    spd_surface(o, (const double[3]){0.55, 0.4, 0.2}, 1.0, 0.0, 0.0, 0.0, 0.0);
    /* Aono and Kunii's branching: the two children tilt 40 and 25 degrees,
     * turn 90 and 230 degrees about their parent, and shrink to 0.65 and
     * 0.70, placed at the parent's tip */
    static const double tilt[2] = {40.0, 25.0}, turn[2] = {90.0, 140.0 + 90.0},
                        shrink[2] = {0.65, 0.70};
    struct spd_mat step[2];
    for (int i = 0; i < 2; i++) {
        struct spd_mat rx, rz, r, st;
        spd_rotate(&rx, SPD_X, tilt[i] * SPD_PI / 180.0);
        spd_rotate(&rz, SPD_Z, turn[i] * SPD_PI / 180.0);
        spd_mat_mul(&r, &rx, &rz);
        spd_identity(&st);
        st.m[0][0] = st.m[1][1] = st.m[2][2] = shrink[i];
        st.m[3][2] = 1.0;
        spd_mat_mul(&step[i], &r, &st);
    }
    struct spd_mat root;
    spd_identity(&root);
    tree_grow(o, step, &root, 1.0, size);
}

/* --------------------------------------------------------------- gears */

#define GEAR_TEETH 36
#define GEAR_INNER 0.9   /* root radius / outer radius */
#define GEAR_OUTER 0.995 /* a gap between meshing teeth */

/* A tooth's four outline points about the gear's centre: two on the tip
 * radius, two on the root radius. */
static void gear_tooth(double gear_angle, double tooth_angle, const double c[3],
                       const double outer[3], const double inner[3], double out[4][3])
{
    static const double at[4] = {-0.19, 0.19, 0.3, 0.7};
    for (int i = 0; i < 4; i++) {
        struct spd_mat m;
        spd_rotate(&m, SPD_Z, gear_angle + at[i] * tooth_angle);
        spd_xform_vector(out[i], i < 2 ? outer : inner, &m);
        for (int k = 0; k < 3; k++)
            out[i][k] += c[k];
    }
}

static void gear(struct spd_out *o, const double c[3], double phase, double outer_r,
                 double inner_r, double thickness)
{
    double outer[3] = {outer_r, 0.0, 0.0}, inner[3] = {inner_r, 0.0, 0.0};
    double tooth = 2.0 * SPD_PI / (double)GEAR_TEETH;
    double face[4 * GEAR_TEETH][3], side[4][3];
    for (int t = 0; t < GEAR_TEETH; t++)
        gear_tooth(phase + 2.0 * SPD_PI * (double)t / (double)GEAR_TEETH, tooth, c, outer, inner,
                   face + 4 * t);
    spd_polygon(o, 4 * GEAR_TEETH, face);
    for (int i = 0; i < 4 * GEAR_TEETH; i++) {
        int j = (i + 1) % (4 * GEAR_TEETH);
        memcpy(side[0], face[i], sizeof side[0]);
        memcpy(side[1], face[i], sizeof side[1]);
        side[1][2] -= thickness;
        memcpy(side[2], face[j], sizeof side[2]);
        side[2][2] -= thickness;
        memcpy(side[3], face[j], sizeof side[3]);
        spd_polygon(o, 4, side);
    }
    /* the bottom face, wound the other way */
    outer[2] = inner[2] = -thickness;
    for (int t = 0; t < GEAR_TEETH; t++)
        gear_tooth(phase - 2.0 * SPD_PI * (double)t / (double)GEAR_TEETH, -tooth, c, outer, inner,
                   face + 4 * t);
    spd_polygon(o, 4 * GEAR_TEETH, face);
}

static double frac(double a) { return a - (int)a; }

void spd_gears(struct spd_out *o, int size)
{
    spd_head(o, (const double[3]){-1.1, -2.1, 2.6}, (const double[3]){0.0, 0.0, 0.0},
             (const double[3]){0.0, 0.0, 1.0}, 1.0);
    static const double lights[5][3] = {{2.0, 4.0, 4.0}, {-2.0, 4.0, 3.0}, {2.0, -2.5, 2.5},
                                        {-1.0, -4.0, 2.0}, {-1.111, -2.121, 2.626}};
    for (int i = 0; i < 5; i++)
        spd_light(o, lights[i]);
    /* the ground: off white, reflective */
    spd_surface(o, (const double[3]){1.0, 0.85, 0.7}, 0.3, 0.6, 37.0, 0.0, 0.0);
    double ground[4][3] = {{2.0, 2.0, 0.0}, {-2.0, 2.0, 0.0}, {-2.0, -2.0, 0.0},
                           {2.0, -2.0, 0.0}};
    spd_polygon(o, 4, ground);
    /* size^3 gears in a cube of side 2 resting on the ground; neighbours
     * mesh (turned half a tooth apart) */
    const double edge = 1.0 - GEAR_INNER;
    double r = 1.0 / ((double)size - (double)(size - 1) * edge / 2.0);
    double first[3] = {-1.0 + r, -1.0 + r, 1.0};
    double step[3] = {r * (2.0 - edge), r * (2.0 - edge), -1.0 / (double)size};
    double thickness = 1.0 / (2.0 * (double)size) < 0.1 ? 1.0 / (2.0 * (double)size) : 0.1;
    for (int iz = 0; iz < size; iz++)
        for (int iy = 0; iy < size; iy++)
            for (int ix = 0; ix < size; ix++) {
                double c[3] = {first[0] + (double)ix * step[0], first[1] + (double)iy * step[1],
                               first[2] + (double)iz * step[2]};
                /* a colour from the position, its largest channel 1 */
                double rgb[3] = {0.01 + frac((double)(ix * 3 + iy * 2 + iz + 1) * 5.0 / 7.0),
                                 0.01 + frac((double)(iy * 3 + iz * 2 + ix + 1) * 3.0 / 7.0),
                                 0.01 + frac((double)(iz * 3 + ix * 2 + iy + 1) * 2.0 / 7.0)};
                double top = rgb[0] > rgb[1] ? rgb[0] : rgb[1];
                top = top > rgb[2] ? top : rgb[2];
                for (int k = 0; k < 3; k++)
                    rgb[k] /= top;
                if ((ix * 4 + iy * 2 + iz) % 5 == 0) /* every fifth is glass */
                    spd_surface(o, rgb, 0.2, 0.0, 0.0, 0.8, 1.1);
                else
                    spd_surface(o, rgb, 1.0, 0.0, 0.0, 0.0, 0.0);
                gear(o, c, SPD_PI * (double)((ix + iy + iz) % 2) / (double)GEAR_TEETH,
                     GEAR_OUTER * r, (1.0 - edge) * r, thickness);
            }
}

/* ----------------------------------------------------------- the table */

const struct spd_db spd_dbs[] = {
    {"balls", spd_balls, 5, 4},  {"gears", spd_gears, 8, 4}, {"mount", spd_mount, 8, 6},
    {"rings", spd_rings, 10, 7}, {"teapot", spd_teapot, 65, 6}, {"tetra", spd_tetra, 9, 6},
    {"tree", spd_tree, 12, 11},
};
const int spd_db_count = (int)(sizeof spd_dbs / sizeof spd_dbs[0]);

const struct spd_db *spd_find(const char *name)
{
    for (int i = 0; i < spd_db_count; i++)
        if (strcmp(spd_dbs[i].name, name) == 0)
            return &spd_dbs[i];
    return NULL;
}

void spd_write_nff(const struct spd_db *db, int size, int width, int height, FILE *f)
{
    struct spd_out o = {f, width, height};
    db->make(&o, size);
}
