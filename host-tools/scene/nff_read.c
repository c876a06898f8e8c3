/* nff_read.c: NFF into a scene (see nff_read.h).  The text is read with the
 * scene format's tokenizer (scene_lex.c: NFF's entities are words, its values
 * numbers, '#' starts a comment) and every error leaves through its
 * lex_error, "file:line:col: what", with the partly built scene freed. */
#include "host-tools/scene/nff_read.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_lex.h"
#include "host-tools/scene/scene_mem.h"

#define NFF_PI 3.14159265358979323846

struct nff_light {
    double pos[3];    /* NFF coordinates */
    double colour[3];
    int coloured;     /* 1: R G B given */
};

struct nff {
    struct lex lx;
    struct sd_scene *s;
    struct nff_info info;
    int cap_prims, cap_materials, cap_lights;
    int material;     /* of the objects that follow; -1 before the first f */
    int seen_view;
    double at[3];     /* the view's at, NFF coordinates (merging lights) */
    struct nff_light *lights;
    int n_lights;
    /* the polygon being read (NFF_MAX_POLY_VERTICES each, allocated at the
     * first p or pp) and its ear clipping's work */
    double (*vert)[3], (*norm)[3], (*flat)[2];
    int *idx;
};

/* ------------------------------------------------------------- helpers */

static void *nff_grow(struct nff *r, void *arr, int *cap, int n, size_t elem, int limit,
                      const char *what)
{
    if (n >= limit)
        lex_error(&r->lx, "too many %s (the limit is %d)", what, limit);
    if (n < *cap)
        return arr;
    int ncap = *cap ? *cap * 2 : 64;
    if (ncap > limit)
        ncap = limit;
    void *na = scene_mem_realloc(arr, (size_t)ncap * elem);
    if (!na)
        lex_error(&r->lx, "out of memory reading %s", what);
    *cap = ncap;
    return na;
}

/* an error at a remembered token position */
#define nff_error_at(r, line, col, ...)                                      \
    do {                                                                     \
        (r)->lx.tok_line = (line);                                           \
        (r)->lx.tok_col = (col);                                             \
        lex_error(&(r)->lx, __VA_ARGS__);                                    \
    } while (0)

static void nff_point(struct nff *r, const char *what, double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = lex_number_in(&r->lx, what, -SCN_MAX_COORD, SCN_MAX_COORD);
}

static double nff_nonneg(struct nff *r, const char *what)
{
    if (r->lx.kind == LEX_NUMBER && r->lx.num < 0)
        lex_error(&r->lx, "%s must not be negative, not %s", what, r->lx.tok);
    return lex_number(&r->lx, what);
}

/* NFF's right-handed coordinates into the renderer's left-handed ones
 * (0 - y: a y of 0 stays +0, not -0) */
static void nff_mirror(const double in[3], double out[3])
{
    out[0] = in[0];
    out[1] = 0.0 - in[1];
    out[2] = in[2];
}

static double nff_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void nff_cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static void nff_need_surface(struct nff *r, int line, int col, const char *what)
{
    if (r->material < 0)
        nff_error_at(r, line, col, "%s before any surface ('f'): it has no material", what);
}

/* ------------------------------------------------------- view and looks */

double nff_fov(double angle, int width, int height)
{
    /* angle spans the centres of the first and last pixels across the
     * narrower side: (m - 1) pixels; the renderer's horizontal field of
     * view spans the whole width, edge to edge (m = 1: edge to edge too) */
    int m = width < height ? width : height;
    double t = tan(angle * NFF_PI / 360.0) * width / (m > 1 ? m - 1 : 1);
    double fov = 2.0 * atan(t) * 180.0 / NFF_PI;
    return fov >= SCN_MIN_FOV && fov <= SCN_MAX_FOV ? fov : -1;
}

static void nff_view(struct nff *r)
{
    static const char *const key[6] = {"from", "at", "up", "angle", "hither", "resolution"};
    int line = r->lx.tok_line, col = r->lx.tok_col;
    if (r->seen_view++)
        lex_error(&r->lx, "a second view ('v'): a file has one");
    lex_next(&r->lx);
    double from[3] = {0, 0, 0}, at[3] = {0, 0, 0}, up[3] = {0, 0, 0}, angle = 0;
    int width = 0, height = 0, have = 0;
    for (;;) {
        int k = 0;
        while (k < 6 && !lex_is_word(&r->lx, key[k]))
            k++;
        if (k == 6)
            break;
        if (have & (1 << k))
            lex_error(&r->lx, "a second '%s' in the view", key[k]);
        have |= 1 << k;
        lex_next(&r->lx);
        if (k == 0) {
            nff_point(r, "from", from);
        } else if (k == 1) {
            nff_point(r, "at", at);
        } else if (k == 2) {
            for (int i = 0; i < 3; i++)
                up[i] = lex_number_in(&r->lx, "up", -SCN_MAX_FACTOR, SCN_MAX_FACTOR);
        } else if (k == 3) {
            if (r->lx.kind == LEX_NUMBER && !(r->lx.num > 0 && r->lx.num < 180))
                lex_error(&r->lx, "angle must be above 0 and below 180 degrees, not %s",
                          r->lx.tok);
            angle = lex_number(&r->lx, "angle");
        } else if (k == 4) {
            lex_number(&r->lx, "hither"); /* no near plane in a ray tracer */
        } else {
            width = lex_int(&r->lx, "resolution width", 1, SCN_MAX_WIDTH);
            height = lex_int(&r->lx, "resolution height", 1, SCN_MAX_HEIGHT);
        }
    }
    for (int k = 0; k < 6; k++)
        if (k != 4 && !(have & (1 << k)))
            lex_error(&r->lx, "the view begun on line %d has no '%s' (found '%s')", line, key[k],
                      r->lx.tok);
    double d[3] = {at[0] - from[0], at[1] - from[1], at[2] - from[2]}, c[3];
    nff_cross(d, up, c);
    if (d[0] == 0 && d[1] == 0 && d[2] == 0)
        nff_error_at(r, line, col, "view: from and at are the same point");
    if (sqrt(nff_dot(c, c)) <= 1e-9 * sqrt(nff_dot(d, d)) * sqrt(nff_dot(up, up)))
        nff_error_at(r, line, col, "view: up is parallel to the viewing direction (or zero)");
    double fov = nff_fov(angle, width, height);
    if (fov < 0)
        nff_error_at(r, line, col,
                     "view: angle %g at %dx%d is a horizontal field of view beyond %g..%g degrees",
                     angle, width, height, SCN_MIN_FOV, SCN_MAX_FOV);
    struct sd_view *v = &r->s->view;
    nff_mirror(from, v->eye);
    nff_mirror(at, v->look_at);
    nff_mirror(up, v->up);
    v->fov = fov;
    v->width = width;
    v->height = height;
    memcpy(r->at, at, sizeof r->at);
}

static void nff_background(struct nff *r)
{
    lex_next(&r->lx);
    for (int i = 0; i < 3; i++)
        r->s->view.background[i] = lex_number_in(&r->lx, "background colour", 0, 1);
}

static void nff_light(struct nff *r)
{
    r->lights = nff_grow(r, r->lights, &r->cap_lights, r->n_lights, sizeof *r->lights,
                         NFF_MAX_LIGHTS, "lights");
    lex_next(&r->lx);
    struct nff_light l;
    memset(&l, 0, sizeof l);
    nff_point(r, "light position", l.pos);
    if (r->lx.kind == LEX_NUMBER) {
        for (int i = 0; i < 3; i++)
            l.colour[i] = lex_number_in(&r->lx, "light colour", 0, SCN_MAX_INTENSITY);
        l.coloured = 1;
    }
    r->lights[r->n_lights++] = l;
}

void nff_material(const double f[8], struct sd_material *m)
{
    memset(m, 0, sizeof *m);
    for (int i = 0; i < 3; i++)
        m->colour[i] = f[i];
    m->dic = 0;
    m->drc = f[3] < 1 ? f[3] : 1;
    m->src = f[4] < 1 ? f[4] : 1;
    m->trc = f[6] < 1 ? f[6] : 1;
    if (m->src + m->trc > 1)
        m->src = 1 - m->trc;
    m->fresnel = 0;
    m->ior = f[7] < 1 ? 1 : f[7] > SCN_MAX_IOR ? SCN_MAX_IOR : f[7];
    m->phong = m->src <= 0              ? 0
               : f[5] >= SCN_MAX_PHONG ? SCN_MAX_PHONG
                                        : (int)floor(f[5] + 0.5);
    sd_material_no_maps(m);
}

static int nff_same_material(const struct sd_material *a, const struct sd_material *b)
{
    return a->colour[0] == b->colour[0] && a->colour[1] == b->colour[1] &&
           a->colour[2] == b->colour[2] && a->dic == b->dic && a->drc == b->drc &&
           a->src == b->src && a->trc == b->trc && a->fresnel == b->fresnel &&
           a->ior == b->ior && a->phong == b->phong;
}

static void nff_surface(struct nff *r)
{
    static const char *const what[8] = {"red", "green", "blue", "Kd", "Ks", "Shine", "T",
                                        "index of refraction"};
    lex_next(&r->lx);
    double f[8];
    for (int i = 0; i < 8; i++)
        f[i] = i < 3 ? lex_number_in(&r->lx, what[i], 0, 1) : nff_nonneg(r, what[i]);
    struct sd_material m;
    nff_material(f, &m);
    struct sd_scene *s = r->s;
    for (int i = 0; i < s->n_materials; i++)
        if (nff_same_material(&s->materials[i], &m)) {
            r->material = i;
            return;
        }
    s->materials = nff_grow(r, s->materials, &r->cap_materials, s->n_materials,
                            sizeof *s->materials, SCN_MAX_MATERIALS, "different surfaces");
    snprintf(m.name, sizeof m.name, "nff%d", s->n_materials + 1);
    r->material = s->n_materials;
    s->materials[s->n_materials++] = m;
}

/* ------------------------------------------------------------- objects */

static struct sd_prim *nff_new_prim(struct nff *r, int kind)
{
    struct sd_scene *s = r->s;
    s->prims = nff_grow(r, s->prims, &r->cap_prims, s->n_prims, sizeof *s->prims,
                        SCN_MAX_PRIMS, "primitives");
    struct sd_prim *p = &s->prims[s->n_prims];
    memset(p, 0, sizeof *p);
    p->kind = kind;
    p->material = r->material;
    p->cluster = 0;
    return p;
}

static void nff_sphere(struct nff *r)
{
    int line = r->lx.tok_line, col = r->lx.tok_col;
    nff_need_surface(r, line, col, "a sphere");
    lex_next(&r->lx);
    double c[3];
    nff_point(r, "sphere centre", c);
    if (r->lx.kind == LEX_NUMBER && r->lx.num < 0)
        lex_error(&r->lx, "a negative radius (a sphere seen only from inside) is not supported");
    double radius = lex_number_in(&r->lx, "sphere radius", 1e-6, SCN_MAX_COORD);
    struct sd_prim *p = nff_new_prim(r, SCN_PRIM_ELLIPSOID);
    nff_mirror(c, p->v);
    p->v[3] = p->v[4] = p->v[5] = radius;
    r->s->n_prims++;
    r->info.spheres++;
}

/* One triangle a b c (NFF coordinates; na nb nc its unit vertex normals,
 * or NULL), left out and counted when degenerate. */
static void nff_triangle(struct nff *r, const double *a, const double *b, const double *c,
                         const double *na, const double *nb, const double *nc, int line,
                         int col)
{
    double v[15] = {0};
    nff_mirror(a, v);
    nff_mirror(b, v + 3);
    nff_mirror(c, v + 6);
    for (int i = 0; i < 9; i++)
        if (!(fabs(v[i]) <= SCN_MAX_COORD))
            nff_error_at(r, line, col, "this object reaches %g, beyond the +-%g of a coordinate",
                         v[i], SCN_MAX_COORD);
    if (sd_triangle_degenerate(v)) {
        r->info.dropped++;
        return;
    }
    struct sd_prim *p = nff_new_prim(r, SCN_PRIM_TRIANGLE);
    memcpy(p->v, v, sizeof v);
    p->v[10] = 1; /* map coordinates (0,0), (1,0), (0,1), as the text form's */
    p->v[14] = 1;
    if (na) {
        p->smooth = 1;
        nff_mirror(na, p->n);
        nff_mirror(nb, p->n + 3);
        nff_mirror(nc, p->n + 6);
    }
    r->s->n_prims++;
    r->info.triangles++;
}

static double nff_turn(const double (*q)[2], int a, int b, int c)
{
    return (q[b][0] - q[a][0]) * (q[c][1] - q[b][1]) - (q[b][1] - q[a][1]) * (q[c][0] - q[b][0]);
}

/* p inside or on the triangle a b c of orientation o (+1 or -1) */
static int nff_in_triangle(const double (*q)[2], int p, int a, int b, int c, double o)
{
    return o * nff_turn(q, a, b, p) >= 0 && o * nff_turn(q, b, c, p) >= 0 &&
           o * nff_turn(q, c, a, p) >= 0;
}

static void nff_emit(struct nff *r, int smooth, int a, int b, int c, int line, int col)
{
    nff_triangle(r, r->vert[a], r->vert[b], r->vert[c], smooth ? r->norm[a] : NULL,
                 smooth ? r->norm[b] : NULL, smooth ? r->norm[c] : NULL, line, col);
}

/* The polygon in r->vert (and r->norm), n vertices, into triangles: a fan
 * from the first vertex when it is convex, otherwise ear clipping, both
 * decided on its shadow in the coordinate plane it is most nearly parallel
 * to (the one across its normal's largest component). */
static void nff_cut_polygon(struct nff *r, int n, int smooth, int line, int col)
{
    double (*v)[3] = r->vert, nrm[3] = {0, 0, 0};
    for (int i = 0; i < n; i++) { /* Newell's normal */
        const double *p = v[i], *q = v[(i + 1) % n];
        nrm[0] += (p[1] - q[1]) * (p[2] + q[2]);
        nrm[1] += (p[2] - q[2]) * (p[0] + q[0]);
        nrm[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    int drop = fabs(nrm[0]) > fabs(nrm[1]) ? (fabs(nrm[0]) > fabs(nrm[2]) ? 0 : 2)
                                           : (fabs(nrm[1]) > fabs(nrm[2]) ? 1 : 2);
    int ax = drop == 0 ? 1 : 0, ay = drop == 2 ? 1 : 2;
    double (*q)[2] = r->flat, area = 0;
    for (int i = 0; i < n; i++) {
        q[i][0] = v[i][ax];
        q[i][1] = v[i][ay];
    }
    for (int i = 0; i < n; i++)
        area += q[i][0] * q[(i + 1) % n][1] - q[(i + 1) % n][0] * q[i][1];
    double o = area < 0 ? -1 : 1;
    int convex = 1;
    for (int i = 0; i < n && convex; i++)
        convex = o * nff_turn(q, i, (i + 1) % n, (i + 2) % n) >= 0;
    if (convex || area == 0) {
        for (int i = 1; i + 1 < n; i++)
            nff_emit(r, smooth, 0, i, i + 1, line, col);
        return;
    }
    int *idx = r->idx, m = n, k = 0, tried = 0;
    for (int i = 0; i < n; i++)
        idx[i] = i;
    while (m > 3) {
        if (tried == m)
            nff_error_at(r, line, col, "this polygon cannot be cut into triangles (its edges "
                                       "cross, or it folds over itself)");
        int a = idx[(k + m - 1) % m], b = idx[k], c = idx[(k + 1) % m];
        int ear = o * nff_turn(q, a, b, c) >= 0;
        for (int j = 0; ear && j < m; j++) {
            int p = idx[j];
            if (p == a || p == b || p == c || o * nff_turn(q, idx[(j + m - 1) % m], p,
                                                           idx[(j + 1) % m]) > 0)
                continue; /* only reflex (or straight) corners can lie in an ear */
            if ((q[p][0] == q[a][0] && q[p][1] == q[a][1]) ||
                (q[p][0] == q[b][0] && q[p][1] == q[b][1]) ||
                (q[p][0] == q[c][0] && q[p][1] == q[c][1]))
                continue; /* a repeated vertex */
            ear = !nff_in_triangle(q, p, a, b, c, o);
        }
        if (!ear) {
            k = (k + 1) % m;
            tried++;
            continue;
        }
        nff_emit(r, smooth, a, b, c, line, col);
        memmove(idx + k, idx + k + 1, (size_t)(m - k - 1) * sizeof *idx);
        m--;
        k = k % m;
        tried = 0;
    }
    nff_emit(r, smooth, idx[0], idx[1], idx[2], line, col);
}

static void nff_polygon(struct nff *r, int smooth)
{
    const char *what = smooth ? "patch" : "polygon";
    int line = r->lx.tok_line, col = r->lx.tok_col;
    nff_need_surface(r, line, col, smooth ? "a patch ('pp')" : "a polygon ('p')");
    lex_next(&r->lx);
    int n = lex_int(&r->lx, smooth ? "the patch's vertex count" : "the polygon's vertex count",
                    3, NFF_MAX_POLY_VERTICES);
    if (!r->vert) {
        r->vert = malloc(NFF_MAX_POLY_VERTICES * sizeof *r->vert);
        r->norm = malloc(NFF_MAX_POLY_VERTICES * sizeof *r->norm);
        r->flat = malloc(NFF_MAX_POLY_VERTICES * sizeof *r->flat);
        r->idx = malloc(NFF_MAX_POLY_VERTICES * sizeof *r->idx);
        if (!r->vert || !r->norm || !r->flat || !r->idx)
            lex_error(&r->lx, "out of memory reading a %s", what);
    }
    for (int i = 0; i < n; i++) {
        if (r->lx.kind != LEX_NUMBER)
            lex_error(&r->lx, "the %s begun on line %d has %d vertices, and %d of them %s: "
                      "expected a number, found '%s'", what, line, n, i,
                      i == 1 ? "was read" : "were read", r->lx.tok);
        nff_point(r, smooth ? "patch vertex" : "polygon vertex", r->vert[i]);
        if (!smooth)
            continue;
        int nline = r->lx.tok_line, ncol = r->lx.tok_col;
        double *nv = r->norm[i];
        for (int k = 0; k < 3; k++)
            nv[k] = lex_number_in(&r->lx, "vertex normal", -SCN_MAX_FACTOR, SCN_MAX_FACTOR);
        double len = sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        if (!(len > 1e-6))
            nff_error_at(r, nline, ncol, "a vertex normal of length %g: it has no direction",
                         len);
        for (int k = 0; k < 3; k++)
            nv[k] /= len;
    }
    if (smooth)
        r->info.patches++;
    else
        r->info.polygons++;
    nff_cut_polygon(r, n, smooth, line, col);
}

/* NFF's cone or cylinder: "the surface exists without endcaps", so an
 * open cone (SCN_CONE_OPEN); both radii negative mean that only its inside
 * is seen, which a renderer of two-sided surfaces shows anyway. */
static void nff_cone(struct nff *r)
{
    int line = r->lx.tok_line, col = r->lx.tok_col;
    nff_need_surface(r, line, col, "a cone or cylinder ('c')");
    lex_next(&r->lx);
    double base[3], apex[3], r0, r1;
    nff_point(r, "cone base", base);
    r0 = lex_number_in(&r->lx, "cone base radius", -SCN_MAX_COORD, SCN_MAX_COORD);
    nff_point(r, "cone apex", apex);
    r1 = lex_number_in(&r->lx, "cone apex radius", -SCN_MAX_COORD, SCN_MAX_COORD);
    if ((r0 < 0 && r1 > 0) || (r0 > 0 && r1 < 0))
        nff_error_at(r, line, col, "a cone's radii must have one sign (both negative: seen "
                                   "from inside), not %g and %g", r0, r1);
    double v[SCN_CONE_VALUES];
    nff_mirror(base, v);
    v[3] = fabs(r0);
    nff_mirror(apex, v + 4);
    v[7] = fabs(r1);
    const char *why = sd_cone_invalid(v);
    if (why)
        nff_error_at(r, line, col, "%s", why);
    for (int e = 0; e < 2; e++)
        for (int k = 0; k < 3; k++)
            if (!(fabs(v[4 * e + k]) + v[4 * e + 3] <= SCN_MAX_COORD))
                nff_error_at(r, line, col, "this cone reaches beyond the +-%g of a coordinate",
                             SCN_MAX_COORD);
    struct sd_prim *p = nff_new_prim(r, SCN_PRIM_CONE);
    memcpy(p->v, v, sizeof v);
    p->capped = SCN_CONE_OPEN;
    r->s->n_prims++;
    r->info.cones++;
}

/* ---------------------------------------------------------------- entry */

/* The lights into the scene: each 1/sqrt(n) unless coloured.  While more
 * than SCN_MAX_LIGHTS remain, the two whose directions from the view's at
 * point are nearest (the first such pair) become one: the sum of their
 * colours at the mean of their positions weighted by intensity. */
static void nff_place_lights(struct nff *r)
{
    struct sd_scene *s = r->s;
    struct nff_light *l = r->lights;
    int n = r->n_lights;
    double plain = 1.0 / sqrt((double)n);
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3 && !l[i].coloured; k++)
            l[i].colour[k] = plain;
    while (n > SCN_MAX_LIGHTS) {
        int ba = 0, bb = 1;
        double best = -2;
        for (int a = 0; a < n; a++)
            for (int b = a + 1; b < n; b++) {
                double da[3], db[3];
                for (int k = 0; k < 3; k++) {
                    da[k] = l[a].pos[k] - r->at[k];
                    db[k] = l[b].pos[k] - r->at[k];
                }
                double la = sqrt(nff_dot(da, da)), lb = sqrt(nff_dot(db, db));
                double c = la > 0 && lb > 0 ? nff_dot(da, db) / (la * lb) : 1;
                if (c > best)
                    best = c, ba = a, bb = b;
            }
        double wa = l[ba].colour[0] + l[ba].colour[1] + l[ba].colour[2];
        double wb = l[bb].colour[0] + l[bb].colour[1] + l[bb].colour[2];
        if (!(wa + wb > 0))
            wa = wb = 1;
        for (int k = 0; k < 3; k++) {
            l[ba].pos[k] = (wa * l[ba].pos[k] + wb * l[bb].pos[k]) / (wa + wb);
            double sum = l[ba].colour[k] + l[bb].colour[k];
            l[ba].colour[k] = sum < SCN_MAX_INTENSITY ? sum : SCN_MAX_INTENSITY;
        }
        memmove(l + bb, l + bb + 1, (size_t)(n - bb - 1) * sizeof *l);
        n--;
        r->info.lights_merged++;
    }
    for (int i = 0; i < n; i++) {
        struct sd_light *sl = &s->lights[s->n_lights++];
        memset(sl, 0, sizeof *sl);
        sl->kind = SCN_LIGHT_POINT;
        nff_mirror(l[i].pos, sl->position);
        memcpy(sl->colour, l[i].colour, sizeof sl->colour);
    }
    r->info.lights = r->n_lights;
}

static void nff_free_work(struct nff *r)
{
    free(r->lights);
    free(r->vert);
    free(r->norm);
    free(r->flat);
    free(r->idx);
    free(r);
}

int nff_read_text(const char *name, const char *text, struct sd_scene *s, struct nff_info *info,
                  char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (info)
        memset(info, 0, sizeof *info);
    struct nff *r = calloc(1, sizeof *r);
    if (!r) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    jmp_buf fail;
    r->s = s;
    r->material = -1;
    lex_init(&r->lx, name, text, &fail, err, errlen);
    if (setjmp(fail)) {
        nff_free_work(r);
        sd_free(s);
        return -1;
    }
    sd_view_defaults(&s->view);
    s->clusters = calloc(1, sizeof *s->clusters);
    if (!s->clusters)
        lex_error(&r->lx, "out of memory");
    s->n_clusters = 1;
    snprintf(s->clusters[0].name, sizeof s->clusters[0].name, "root");
    s->clusters[0].parent = -1;
    s->clusters[0].m[0] = s->clusters[0].m[5] = s->clusters[0].m[10] = 1;
    lex_next(&r->lx);
    while (r->lx.kind != LEX_END) {
        struct lex *lx = &r->lx;
        if (lx->kind != LEX_WORD)
            lex_error(lx, "expected an NFF entity (v, b, l, f, c, s, p or pp), found '%s'",
                      lx->tok);
        if (lex_is_word(lx, "v"))
            nff_view(r);
        else if (lex_is_word(lx, "b"))
            nff_background(r);
        else if (lex_is_word(lx, "l"))
            nff_light(r);
        else if (lex_is_word(lx, "f"))
            nff_surface(r);
        else if (lex_is_word(lx, "s"))
            nff_sphere(r);
        else if (lex_is_word(lx, "p"))
            nff_polygon(r, 0);
        else if (lex_is_word(lx, "pp"))
            nff_polygon(r, 1);
        else if (lex_is_word(lx, "c"))
            nff_cone(r);
        else
            lex_error(lx, "unknown NFF entity '%s' (v, b, l, f, c, s, p and pp are known)",
                      lx->tok);
    }
    if (!r->seen_view)
        lex_error(&r->lx, "the file has no view ('v')");
    if (r->n_lights == 0)
        lex_error(&r->lx, "the file has no light ('l')");
    if (s->n_prims == 0)
        lex_error(&r->lx, "the file has no object%s", r->info.dropped ? " that is not degenerate"
                                                                      : "");
    nff_place_lights(r);
    if (info)
        *info = r->info;
    nff_free_work(r);
    return 0;
}

int nff_read_file(const char *path, struct sd_scene *s, struct nff_info *info, char *err,
                  size_t errlen)
{
    memset(s, 0, sizeof *s);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    char *text = scene_mem_alloc(NFF_MAX_FILE + 1);
    size_t n = text ? fread(text, 1, NFF_MAX_FILE + 1, f) : 0;
    fclose(f);
    if (!text || n > NFF_MAX_FILE) {
        snprintf(err, errlen, "%s: %s", path,
                 text ? "larger than the 64 MiB an NFF file may be" : "out of memory");
        free(text);
        return -1;
    }
    text[n] = 0;
    if (memchr(text, 0, n)) {
        snprintf(err, errlen, "%s: contains a NUL byte (not an NFF file)", path);
        free(text);
        return -1;
    }
    struct nff_info mine;
    int rc = nff_read_text(path, text, s, info ? info : &mine, err, errlen);
    free(text);
    if (rc == 0 && !info) {
        if (mine.lights_merged)
            fprintf(stderr, "%s: %d lights, merged into the renderer's %d (docs/scene-format.md, "
                            "\"NFF files\")\n", path, mine.lights, mine.lights - mine.lights_merged);
        if (mine.dropped)
            fprintf(stderr, "%s: %ld degenerate triangles left out\n", path, mine.dropped);
    }
    return rc;
}
