/* scene_parse_objects.c: transform statements, keys and primitives of the
 * text scene format (docs/scene-format.md). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_parse.h"

/* ----------------------------------------------------------- transforms */

static void parse_apply(double m[12], const double t[12])
{
    double r[12];
    sd_mat_mul(t, m, r);
    memcpy(m, r, sizeof r);
}

/* translate / rotate / scale / matrix statements, applied in order. */
int parse_transform(struct parser *p, double m[12])
{
    double t[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    if (lex_is_word(&p->lx, "translate")) {
        lex_next(&p->lx);
        double v[3];
        parse_coord3(p, "translate", v);
        t[3] = v[0], t[7] = v[1], t[11] = v[2];
    } else if (lex_is_word(&p->lx, "rotate")) {
        lex_next(&p->lx);
        double deg[3], q[4];
        for (int i = 0; i < 3; i++)
            deg[i] = lex_number_in(&p->lx, "rotate (degrees)", -3600, 3600);
        sd_euler_quat(deg, q);
        sd_quat_matrix(q, t);
    } else if (lex_is_word(&p->lx, "scale")) {
        lex_next(&p->lx);
        double v[3];
        v[0] = lex_number_in(&p->lx, "scale", -SCN_MAX_SCALE, SCN_MAX_SCALE);
        if (p->lx.kind == LEX_NUMBER) {
            v[1] = lex_number_in(&p->lx, "scale", -SCN_MAX_SCALE, SCN_MAX_SCALE);
            v[2] = lex_number_in(&p->lx, "scale", -SCN_MAX_SCALE, SCN_MAX_SCALE);
        } else {
            v[1] = v[2] = v[0];
        }
        if (v[0] == 0 || v[1] == 0 || v[2] == 0)
            lex_error(&p->lx, "a scale factor is zero");
        t[0] = v[0], t[5] = v[1], t[10] = v[2];
    } else if (lex_is_word(&p->lx, "matrix")) {
        lex_next(&p->lx);
        for (int i = 0; i < 12; i++)
            t[i] = i % 4 == 3 ? lex_number_in(&p->lx, "matrix translation", -SCN_MAX_COORD,
                                              SCN_MAX_COORD)
                              : lex_number_in(&p->lx, "matrix entry", -SCN_MAX_SCALE,
                                              SCN_MAX_SCALE);
        double det = t[0] * (t[5] * t[10] - t[6] * t[9]) - t[1] * (t[4] * t[10] - t[6] * t[8]) +
                     t[2] * (t[4] * t[9] - t[5] * t[8]);
        /* against the rows' lengths: a matrix scaled by 1e-6 is invertible */
        double rows = 1;
        for (int r = 0; r < 3; r++)
            rows *= sqrt(t[4 * r] * t[4 * r] + t[4 * r + 1] * t[4 * r + 1] +
                         t[4 * r + 2] * t[4 * r + 2]);
        if (!(rows > 0) || !(fabs(det) >= 1e-12 * rows))
            lex_error(&p->lx, "matrix is not invertible (determinant %g)", det);
    } else {
        return 0;
    }
    parse_apply(m, t);
    for (int i = 0; i < 12; i++)
        if (fabs(m[i]) > (i % 4 == 3 ? SCN_MAX_COORD : SCN_MAX_SCALE))
            lex_error(&p->lx, "the combined transform has %s beyond %g", i % 4 == 3 ?
                      "a translation" : "an entry", i % 4 == 3 ? (double)SCN_MAX_COORD :
                      (double)SCN_MAX_SCALE);
    return 1;
}

void parse_key(struct parser *p, int c)
{
    struct sd_scene *s = p->s;
    struct sd_cluster *cl = &s->clusters[c];
    lex_next(&p->lx);
    struct sd_key k;
    memset(&k, 0, sizeof k);
    k.scale[0] = k.scale[1] = k.scale[2] = 1;
    if (cl->key_count > 0 && p->lx.kind == LEX_NUMBER &&
        p->lx.num <= s->keys[s->n_keys - 1].frame)
        lex_error(&p->lx, "key frames of a cluster must rise (frame %s after %d)", p->lx.tok,
                  s->keys[s->n_keys - 1].frame);
    k.frame = lex_int(&p->lx, "key frame", 0, SCN_MAX_FRAMES - 1);
    if (cl->key_count > 0 && cl->key_first + cl->key_count != s->n_keys)
        lex_error(&p->lx, "keys of a cluster must come before its child clusters");
    if (cl->key_count >= SCN_MAX_CLUSTER_KEYS)
        lex_error(&p->lx, "more than %d keys in one cluster", SCN_MAX_CLUSTER_KEYS);
    parse_open(p, "key");
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "translate")) {
            lex_next(&p->lx);
            parse_coord3(p, "translate", k.translate);
        } else if (lex_is_word(&p->lx, "rotate")) {
            lex_next(&p->lx);
            for (int i = 0; i < 3; i++)
                k.rotate[i] = lex_number_in(&p->lx, "rotate (degrees)", -3600, 3600);
        } else if (lex_is_word(&p->lx, "scale")) {
            lex_next(&p->lx);
            k.scale[0] = lex_number_in(&p->lx, "scale", -SCN_MAX_SCALE, SCN_MAX_SCALE);
            if (p->lx.kind == LEX_NUMBER) {
                k.scale[1] = lex_number_in(&p->lx, "scale", -SCN_MAX_SCALE, SCN_MAX_SCALE);
                k.scale[2] = lex_number_in(&p->lx, "scale", -SCN_MAX_SCALE, SCN_MAX_SCALE);
            } else {
                k.scale[1] = k.scale[2] = k.scale[0];
            }
            if (k.scale[0] == 0 || k.scale[1] == 0 || k.scale[2] == 0)
                lex_error(&p->lx, "a scale factor is zero");
        } else {
            parse_unknown(p, "key");
        }
    }
    s->keys = parse_grow(p, s->keys, &p->cap_keys, s->n_keys, sizeof *s->keys, SCN_MAX_KEYS,
                         "keys");
    cl = &s->clusters[c];
    if (cl->key_count == 0)
        cl->key_first = s->n_keys;
    s->keys[s->n_keys++] = k;
    cl->key_count++;
    lex_next(&p->lx);
}

/* ----------------------------------------------------------- primitives */

/* The 'material NAME' every primitive block may hold. */
static int parse_prim_material(struct parser *p, struct sd_prim *pr)
{
    if (lex_is_word(&p->lx, "material")) {
        lex_next(&p->lx);
        pr->material = parse_material_ref(p);
        return 1;
    }
    return 0;
}

/* A vertex normal of a smooth triangle, made unit length. */
static void parse_vertex_normal(struct parser *p, double n[3])
{
    parse_factor3(p, "vertex normal", n);
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 1e-6))
        lex_error(&p->lx, "a vertex normal of length %g: it has no direction", len);
    for (int i = 0; i < 3; i++)
        n[i] /= len;
}

static void parse_triangle(struct parser *p, struct sd_prim *pr)
{
    int nv = 0, nuv = 0, nn = 0;
    double *v = pr->v;
    /* default map coordinates: (0,0), (1,0), (0,1) */
    v[10] = 1;
    v[14] = 1;
    while (p->lx.kind != LEX_CLOSE) {
        if (parse_prim_material(p, pr))
            continue;
        if (lex_is_word(&p->lx, "v")) {
            if (nv == 3)
                lex_error(&p->lx, "a triangle has three vertices");
            lex_next(&p->lx);
            parse_coord3(p, "vertex", v + 3 * nv++);
        } else if (lex_is_word(&p->lx, "uv")) {
            if (nuv == 3)
                lex_error(&p->lx, "a triangle has three uv pairs");
            lex_next(&p->lx);
            v[9 + nuv] = lex_number_in(&p->lx, "u", -SCN_MAX_FACTOR, SCN_MAX_FACTOR);
            v[12 + nuv] = lex_number_in(&p->lx, "v", -SCN_MAX_FACTOR, SCN_MAX_FACTOR);
            nuv++;
        } else if (lex_is_word(&p->lx, "n")) {
            if (nn == 3)
                lex_error(&p->lx, "a triangle has three vertex normals");
            lex_next(&p->lx);
            parse_vertex_normal(p, pr->n + 3 * nn++);
        } else {
            parse_unknown(p, "triangle");
        }
    }
    if (nv != 3)
        lex_error(&p->lx, "triangle has %d vertices, needs 3", nv);
    if (nuv != 0 && nuv != 3)
        lex_error(&p->lx, "triangle has %d uv pairs, needs 0 or 3", nuv);
    if (nn != 0 && nn != 3)
        lex_error(&p->lx, "triangle has %d vertex normals, needs 0 (flat) or 3 (smooth)", nn);
    pr->smooth = nn == 3;
    if (sd_triangle_degenerate(v)) {
        double h = sd_triangle_min_height(v);
        if (h > 0)
            lex_error(&p->lx, "degenerate triangle: a sliver whose smallest height is %g, under "
                      "SCN_MIN_TRIANGLE_HEIGHT (%g)", h, SCN_MIN_TRIANGLE_HEIGHT);
        lex_error(&p->lx, "degenerate triangle (its vertices are on one line)");
    }
}

static void parse_ellipsoid(struct parser *p, struct sd_prim *pr, int sphere)
{
    int have_r = 0;
    while (p->lx.kind != LEX_CLOSE) {
        if (parse_prim_material(p, pr))
            continue;
        if (lex_is_word(&p->lx, "centre") || lex_is_word(&p->lx, "center")) {
            lex_next(&p->lx);
            parse_coord3(p, "centre", pr->v);
        } else if (sphere && lex_is_word(&p->lx, "radius")) {
            lex_next(&p->lx);
            pr->v[3] = pr->v[4] = pr->v[5] =
                lex_number_in(&p->lx, "radius", SCN_MIN_SIZE, SCN_MAX_COORD);
            have_r = 1;
        } else if (!sphere && lex_is_word(&p->lx, "radii")) {
            lex_next(&p->lx);
            for (int i = 0; i < 3; i++)
                pr->v[3 + i] = lex_number_in(&p->lx, "radius", SCN_MIN_SIZE, SCN_MAX_COORD);
            have_r = 1;
        } else {
            parse_unknown(p, sphere ? "sphere" : "ellipsoid");
        }
    }
    if (!have_r)
        lex_error(&p->lx, "%s needs %s", sphere ? "sphere" : "ellipsoid",
                  sphere ? "a radius" : "radii");
}

static void parse_box(struct parser *p, struct sd_prim *pr)
{
    double lo[3], hi[3];
    int have = 0;
    while (p->lx.kind != LEX_CLOSE) {
        if (parse_prim_material(p, pr))
            continue;
        if (lex_is_word(&p->lx, "min")) {
            lex_next(&p->lx);
            parse_coord3(p, "min", lo);
            have |= 1;
        } else if (lex_is_word(&p->lx, "max")) {
            lex_next(&p->lx);
            parse_coord3(p, "max", hi);
            have |= 2;
        } else {
            parse_unknown(p, "box");
        }
    }
    if (have != 3)
        lex_error(&p->lx, "box needs min and max corners");
    for (int i = 0; i < 3; i++) {
        if (!(hi[i] > lo[i]))
            lex_error(&p->lx, "box max must exceed min on every axis (axis %c)", "xyz"[i]);
        pr->v[i] = (lo[i] + hi[i]) / 2;
        pr->v[3 + i] = (hi[i] - lo[i]) / 2;
    }
}

/* cylinder { base X Y Z  apex X Y Z  radius R  [open] } and
 * cone { base X Y Z  base_radius R0  apex X Y Z  apex_radius R1  [open] }
 * (apex_radius 0 when not given: a pointed cone); values as NFF's c,
 * capped unless open. */
static void parse_cone(struct parser *p, struct sd_prim *pr, int cylinder)
{
    const char *kind = cylinder ? "cylinder" : "cone";
    int have = 0; /* 1 base, 2 apex, 4 a radius */
    double *v = pr->v;
    pr->capped = 1;
    while (p->lx.kind != LEX_CLOSE) {
        if (parse_prim_material(p, pr))
            continue;
        if (lex_is_word(&p->lx, "base") || lex_is_word(&p->lx, "apex")) {
            int apex = lex_is_word(&p->lx, "apex");
            lex_next(&p->lx);
            parse_coord3(p, apex ? "apex" : "base", v + 4 * apex);
            have |= apex ? 2 : 1;
        } else if (cylinder && lex_is_word(&p->lx, "radius")) {
            lex_next(&p->lx);
            v[3] = v[7] = lex_number_in(&p->lx, "radius", SCN_MIN_SIZE, SCN_MAX_COORD);
            have |= 4;
        } else if (!cylinder &&
                   (lex_is_word(&p->lx, "base_radius") || lex_is_word(&p->lx, "apex_radius"))) {
            int apex = lex_is_word(&p->lx, "apex_radius");
            lex_next(&p->lx);
            v[3 + 4 * apex] = lex_number_in(&p->lx, apex ? "apex_radius" : "base_radius", 0,
                                            SCN_MAX_COORD);
            have |= apex ? 0 : 4;
        } else if (lex_is_word(&p->lx, "open")) {
            lex_next(&p->lx);
            pr->capped = 0;
        } else {
            parse_unknown(p, kind);
        }
    }
    if ((have & 3) != 3)
        lex_error(&p->lx, "%s needs a base and an apex", kind);
    if (!(have & 4))
        lex_error(&p->lx, "%s needs a%s", kind, cylinder ? " radius" : " base_radius");
    const char *why = sd_cone_invalid(v);
    if (why)
        lex_error(&p->lx, "%s", why);
}

static void parse_density(struct parser *p, struct sd_prim *pr)
{
    struct sd_scene *s = p->s;
    int have_t = 0;
    pr->first = s->n_components;
    while (p->lx.kind != LEX_CLOSE) {
        if (parse_prim_material(p, pr))
            continue;
        if (lex_is_word(&p->lx, "threshold")) {
            lex_next(&p->lx);
            pr->v[0] = lex_number_in(&p->lx, "threshold", 1e-6, SCN_MAX_FACTOR);
            have_t = 1;
        } else if (lex_is_word(&p->lx, "component")) {
            lex_next(&p->lx);
            if (pr->count >= SCN_MAX_DENSITY_COMPONENTS)
                lex_error(&p->lx, "more than %d components", SCN_MAX_DENSITY_COMPONENTS);
            struct sd_component c;
            parse_coord3(p, "component centre", c.centre);
            c.radius = lex_number_in(&p->lx, "component radius", SCN_MIN_SIZE, SCN_MAX_COORD);
            if (p->lx.kind == LEX_NUMBER && p->lx.num == 0)
                lex_error(&p->lx, "component weight is zero");
            c.weight = lex_number_in(&p->lx, "component weight", -SCN_MAX_FACTOR, SCN_MAX_FACTOR);
            s->components = parse_grow(p, s->components, &p->cap_components, s->n_components,
                                       sizeof *s->components, SCN_MAX_COMPONENTS,
                                       "density components");
            s->components[s->n_components++] = c;
            pr->count++;
        } else {
            parse_unknown(p, "density");
        }
    }
    if (!have_t)
        lex_error(&p->lx, "density needs a threshold");
    if (pr->count == 0)
        lex_error(&p->lx, "density needs at least one component");
}

void parse_prim(struct parser *p, int cluster, int material)
{
    struct sd_scene *s = p->s;
    struct sd_prim pr;
    memset(&pr, 0, sizeof pr);
    pr.cluster = cluster;
    pr.material = material;
    char kind[LEX_TOKEN_MAX];
    strcpy(kind, p->lx.tok);
    int line = p->lx.tok_line, col = p->lx.tok_col;
    lex_next(&p->lx);
    parse_open(p, kind);
    if (strcmp(kind, "triangle") == 0) {
        pr.kind = SCN_PRIM_TRIANGLE;
        parse_triangle(p, &pr);
    } else if (strcmp(kind, "ellipsoid") == 0 || strcmp(kind, "sphere") == 0) {
        pr.kind = SCN_PRIM_ELLIPSOID;
        parse_ellipsoid(p, &pr, kind[0] == 's');
    } else if (strcmp(kind, "box") == 0) {
        pr.kind = SCN_PRIM_BOX;
        parse_box(p, &pr);
    } else if (strcmp(kind, "cylinder") == 0 || strcmp(kind, "cone") == 0) {
        pr.kind = SCN_PRIM_CONE;
        parse_cone(p, &pr, kind[1] == 'y');
    } else {
        pr.kind = SCN_PRIM_DENSITY;
        parse_density(p, &pr);
    }
    if (pr.material < 0) {
        p->lx.tok_line = line, p->lx.tok_col = col;
        lex_error(&p->lx, "%s has no material ('material NAME' inside, or 'use NAME' "
                          "before it)", kind);
    }
    s->prims = parse_grow(p, s->prims, &p->cap_prims, s->n_prims, sizeof *s->prims,
                          SCN_MAX_PRIMS, "primitives");
    s->prims[s->n_prims++] = pr;
    lex_next(&p->lx);
}
