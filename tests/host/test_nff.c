/* test_nff.c: NFF files (host-tools/scene/nff_read.c) and links1-spd
 * (host-tools/spd/) against the SPD's own output (tests/spd/official/):
 *   - each generator's NFF equals the official program's, entity for
 *     entity and number for number (within 1e-6), at sizes 1 and 2, and
 *     the numbers the SPD issue (23) names: the sphereflake's directions,
 *     the views, the lights, the counts;
 *   - links1-spd's text scene compiles to the bytes the official NFF does;
 *   - every entity (v b l f s p pp c) and the mapping of surfaces, lights
 *     (merged beyond SCN_MAX_LIGHTS) and the view;
 *   - hostile files (truncated, huge counts, a cone of zero height,
 *     unknown entities, ...) refused by file:line:col, never a crash;
 *     every prefix of an official file read without one;
 *   - a .nff path read as NFF by scene_file.c.
 * Run from the repository's root (tests/run.sh does). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/scene/nff_read.h"
#include "host-tools/scene/scene_import.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_file.h"
#include "host-tools/spd/spd.h"
#include "tests/check.h"

#define OFFICIAL "tests/spd/official/"
#define PI 3.14159265358979323846

static const char *const dbs[] = {"balls", "gears", "mount", "rings", "teapot", "tetra", "tree"};
#define N_DBS ((int)(sizeof dbs / sizeof dbs[0]))

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *t = malloc((size_t)n + 1);
    if (t && fread(t, 1, (size_t)n, f) != (size_t)n) {
        free(t);
        t = NULL;
    }
    if (t)
        t[n] = 0;
    fclose(f);
    return t;
}

/* links1-spd's NFF of db at size, 512 x 512 */
static char *generate(const char *db, int size)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&buf, &len);
    const struct spd_db *d = spd_find(db);
    if (!m || !d) {
        if (m)
            fclose(m);
        free(buf);
        return NULL;
    }
    spd_write_nff(d, size, 512, 512, m);
    fclose(m);
    return buf;
}

/* Compares two NFF texts token by token: the same words, numbers within
 * tol.  Returns the count of differing tokens (0: equal); *textual counts
 * the numbers written differently though within tol, *tokens all tokens. */
static long compare_nff(const char *a, const char *b, double tol, long *textual, long *tokens,
                        char *why, size_t whylen)
{
    long bad = 0;
    *textual = *tokens = 0;
    why[0] = 0;
    for (;;) {
        a += strspn(a, " \t\r\n");
        b += strspn(b, " \t\r\n");
        size_t la = strcspn(a, " \t\r\n"), lb = strcspn(b, " \t\r\n");
        if (la == 0 || lb == 0) {
            if (la != lb) {
                bad++;
                if (!why[0])
                    snprintf(why, whylen, "token %ld: one text ends before the other", *tokens);
            }
            return bad;
        }
        char ta[64], tb[64];
        snprintf(ta, sizeof ta, "%.*s", (int)la, a);
        snprintf(tb, sizeof tb, "%.*s", (int)lb, b);
        char *ea, *eb;
        double x = strtod(ta, &ea), y = strtod(tb, &eb);
        int numbers = *ea == 0 && *eb == 0 && ea != ta && eb != tb;
        if (numbers ? !(fabs(x - y) <= tol) : strcmp(ta, tb) != 0) {
            if (!bad)
                snprintf(why, whylen, "token %ld: '%s' against '%s'", *tokens, ta, tb);
            bad++;
        } else if (numbers && strcmp(ta, tb) != 0) {
            (*textual)++;
        }
        (*tokens)++;
        a += la;
        b += lb;
    }
}

/* ---------------------------------------------- against the official SPD */

static void test_generators_equal_official(void)
{
    for (int i = 0; i < N_DBS; i++)
        for (int size = 1; size <= 2; size++) {
            char path[128], why[200], msg[400];
            snprintf(path, sizeof path, OFFICIAL "%s%d.nff", dbs[i], size);
            char *official = read_text(path), *mine = generate(dbs[i], size);
            CHECK(official && mine);
            if (!official || !mine) {
                free(official);
                free(mine);
                continue;
            }
            long textual, tokens;
            long bad = compare_nff(mine, official, 1e-6, &textual, &tokens, why, sizeof why);
            snprintf(msg, sizeof msg, "%s: %ld of %ld tokens differ (%s)", path, bad, tokens, why);
            if (bad)
                check_fail(__FILE__, __LINE__, msg);
            CHECK(tokens > 30);
            /* stronger than asked: printed alike, byte for byte */
            CHECK_EQ_INT(textual, 0);
            CHECK(strcmp(mine, official) == 0);
            free(official);
            free(mine);
        }
}

/* entity counts of the official files, as the SPD's comments give them */
static void test_official_counts(void)
{
    static const struct {
        const char *file;
        long spheres, polygons, patches, cones;
        int lights;
    } want[] = {
        {"balls1", 10, 1, 0, 0, 3},     {"balls2", 91, 1, 0, 0, 3},
        {"gears1", 0, 147, 0, 0, 5},    {"gears2", 0, 1169, 0, 0, 5},
        {"mount1", 4, 8, 0, 0, 1},      {"mount2", 4, 32, 0, 0, 1},
        {"rings1", 30, 1, 0, 30, 3},    {"rings2", 150, 1, 0, 150, 3},
        {"teapot1", 0, 1, 56, 0, 2},    {"teapot2", 0, 4, 240, 0, 2},
        {"tetra1", 0, 4, 0, 0, 1},      {"tetra2", 0, 16, 0, 0, 1},
        {"tree1", 3, 1, 0, 3, 7},       {"tree2", 7, 1, 0, 7, 7},
    };
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        char path[128], err[SD_ERR_MAX];
        snprintf(path, sizeof path, OFFICIAL "%s.nff", want[i].file);
        struct sd_scene s;
        struct nff_info info;
        int rc = nff_read_file(path, &s, &info, err, sizeof err);
        CHECK_EQ_INT(rc, 0);
        if (rc != 0) {
            check_fail(__FILE__, __LINE__, err);
            continue;
        }
        CHECK_EQ_INT(info.spheres, want[i].spheres);
        CHECK_EQ_INT(info.polygons, want[i].polygons);
        CHECK_EQ_INT(info.patches, want[i].patches);
        CHECK_EQ_INT(info.cones, want[i].cones);
        CHECK_EQ_INT(info.lights, want[i].lights);
        /* every SPD database has at most 7 lights: none merged */
        CHECK_EQ_INT(s.n_lights, want[i].lights);
        CHECK_EQ_INT(info.lights_merged, 0);
        /* spheres stay spheres and cones open cones, polygons and
         * patches became triangles */
        long tri = 0, sph = 0, cone = 0;
        for (int p = 0; p < s.n_prims; p++) {
            sph += s.prims[p].kind == SCN_PRIM_ELLIPSOID;
            tri += s.prims[p].kind == SCN_PRIM_TRIANGLE;
            cone += s.prims[p].kind == SCN_PRIM_CONE && s.prims[p].capped == SCN_CONE_OPEN;
        }
        CHECK_EQ_INT(sph, want[i].spheres);
        CHECK_EQ_INT(cone, want[i].cones);
        CHECK_EQ_INT(tri, info.triangles);
        CHECK_EQ_INT(sph + tri + cone, s.n_prims);
        sd_free(&s);
    }
}

static void scene_of(const char *db, int size, struct sd_scene *s)
{
    char *nff = generate(db, size), err[SD_ERR_MAX];
    CHECK(nff && nff_read_text("gen", nff, s, NULL, err, sizeof err) == 0);
    free(nff);
}

/* the numbers the issue names, from links1-spd's own output */
static void test_issue_numbers(void)
{
    struct sd_scene s;
    /* balls 1: the first level's children, six round the equator at
     * azimuths 15, 75, ..., 315 and three 54.7 degrees up at 45, 165, 285
     * (y is negated on the way in: the azimuths are taken in NFF's terms) */
    scene_of("balls", 1, &s);
    CHECK_EQ_INT(s.n_prims, 2 + 10);
    int equator = 0, up = 0;
    for (int p = 3; p < s.n_prims; p++) {
        const double *c = s.prims[p].v;
        double az = atan2(-c[1], c[0]) * 180 / PI, el = atan2(c[2], hypot(c[0], c[1])) * 180 / PI;
        CHECK_NEAR(s.prims[p].v[3], 1.0 / 6.0, 1e-6);
        if (fabs(el) < 1e-6) {
            CHECK_NEAR(remainder(az - 15, 60), 0, 1e-4);
            equator++;
        } else {
            CHECK_NEAR(el, atan(1 / sqrt(0.5)) * 180 / PI, 1e-4); /* 54.7356 */
            CHECK_NEAR(remainder(az - 45, 120), 0, 1e-4);
            up++;
        }
    }
    CHECK_EQ_INT(equator, 6);
    CHECK_EQ_INT(up, 3);
    sd_free(&s);
    /* tetra: one light, Kay and Kajiya's eye; 4 and 16 triangles */
    scene_of("tetra", 1, &s);
    CHECK_EQ_INT(s.n_lights, 1);
    CHECK_EQ_INT(s.n_prims, 4);
    CHECK_NEAR(s.view.eye[0], 1.02285, 1e-6);
    CHECK_NEAR(s.view.eye[1], 3.17715, 1e-6);
    CHECK_NEAR(s.view.eye[2], -2.17451, 1e-6);
    sd_free(&s);
    scene_of("tetra", 2, &s);
    CHECK_EQ_INT(s.n_prims, 16);
    sd_free(&s);
    /* gears: 1 gear of 2 concave faces (142 triangles each), 144 quads;
     * the ground's quad; eye (-1.1, -2.1, 2.6) */
    scene_of("gears", 1, &s);
    CHECK_EQ_INT(s.n_prims, 2 * 142 + 144 * 2 + 2);
    CHECK_NEAR(s.view.eye[0], -1.1, 1e-12);
    CHECK_NEAR(s.view.eye[1], 2.1, 1e-12);
    CHECK_NEAR(s.view.eye[2], 2.6, 1e-12);
    sd_free(&s);
    /* mount 1: 4 spheres, 8 triangles, one light at (-100, -100, 100) */
    scene_of("mount", 1, &s);
    CHECK_EQ_INT(s.n_prims, 12);
    CHECK_EQ_INT(s.n_lights, 1);
    CHECK_NEAR(s.lights[0].position[0], -100, 0);
    CHECK_NEAR(s.lights[0].position[1], 100, 0);
    CHECK_NEAR(s.lights[0].position[2], 100, 0);
    CHECK_NEAR(s.view.eye[0], -1.6, 1e-12);
    CHECK_NEAR(s.view.eye[1], -1.6, 1e-12);
    CHECK_NEAR(s.view.eye[2], 1.7, 1e-12);
    sd_free(&s);
    /* rings 1: 30 spheres, 30 open cylinders */
    scene_of("rings", 1, &s);
    CHECK_EQ_INT(s.n_prims, 2 + 30 + 30);
    sd_free(&s);
    /* tree 2: 7 spheres, 7 cones */
    scene_of("tree", 2, &s);
    CHECK_EQ_INT(s.n_prims, 2 + 7 + 7);
    CHECK_EQ_INT(s.n_lights, 7);
    sd_free(&s);
}

/* links1-spd's text scene and the official NFF compile to the same bytes */
static void test_scene_compiles_as_official(void)
{
    for (int i = 0; i < N_DBS; i++)
        for (int size = 1; size <= 2; size++) {
            char path[128], err[SD_ERR_MAX];
            snprintf(path, sizeof path, OFFICIAL "%s%d.nff", dbs[i], size);
            char *nff = generate(dbs[i], size), *scn = NULL;
            size_t scn_len = 0;
            struct sd_scene gen, text, off;
            CHECK(nff_read_text("gen", nff, &gen, NULL, err, sizeof err) == 0);
            FILE *m = open_memstream(&scn, &scn_len);
            CHECK(m && sd_write_text_titled(&gen, NULL, "test", m) == 0);
            if (m)
                fclose(m);
            int rc = sd_parse_text("gen.scn", scn, &text, err, sizeof err);
            CHECK_EQ_INT(rc, 0);
            if (rc)
                check_fail(__FILE__, __LINE__, err);
            CHECK(nff_read_file(path, &off, NULL, err, sizeof err) == 0);
            uint8_t *a = NULL, *b = NULL;
            size_t la = 0, lb = 0;
            CHECK(rc == 0 && sd_compile(&text, &a, &la, err, sizeof err) == 0);
            CHECK(sd_compile(&off, &b, &lb, err, sizeof err) == 0);
            CHECK(la > 0 && la == lb && memcmp(a, b, la) == 0);
            free(a);
            free(b);
            free(nff);
            free(scn);
            sd_free(&gen);
            sd_free(&text);
            sd_free(&off);
        }
}

/* -------------------------------------------------------------- entities */

static const char *head = "# a comment\n"
                          "b 0.1 0.2 0.3\n"
                          "v\nfrom 0 -10 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\n"
                          "resolution 64 32\n"
                          "l 0 -10 10\n";

static int read_nff(const char *body, struct sd_scene *s, struct nff_info *info, char *err,
                    size_t errlen)
{
    size_t n = strlen(head) + strlen(body) + 1;
    char *t = malloc(n);
    snprintf(t, n, "%s%s", head, body);
    int rc = nff_read_text("t.nff", t, s, info, err, errlen);
    free(t);
    return rc;
}

static void test_view_and_looks(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    CHECK(read_nff("f 1 0.5 0.25 0.7 0.3 3.4 0 1.5\ns 1 2 3 0.5\n", &s, NULL, err,
                   sizeof err) == 0);
    /* y negated: NFF is right-handed */
    CHECK_NEAR(s.view.eye[1], 10, 0);
    CHECK_NEAR(s.view.up[2], 1, 0);
    CHECK_NEAR(s.prims[0].v[1], -2, 0);
    CHECK_NEAR(s.prims[0].v[3], 0.5, 0);
    CHECK_NEAR(s.prims[0].v[5], 0.5, 0);
    CHECK_EQ_INT(s.view.width, 64);
    CHECK_EQ_INT(s.view.height, 32);
    /* angle 45 between the centres of the top and bottom pixel rows (the
     * narrower side, 32): the horizontal field of view over 64 pixels */
    double want = 2 * atan(tan(22.5 * PI / 180) * 64 / 31) * 180 / PI;
    CHECK_NEAR(s.view.fov, want, 1e-9);
    CHECK_NEAR(nff_fov(45, 512, 512), 2 * atan(tan(22.5 * PI / 180) * 512 / 511) * 180 / PI,
               1e-12);
    CHECK_NEAR(s.view.background[2], 0.3, 0);
    CHECK_EQ_INT(s.n_lights, 1);
    CHECK_NEAR(s.lights[0].colour[0], 1, 0);
    const struct sd_material *m = &s.materials[0];
    CHECK_NEAR(m->colour[1], 0.5, 0);
    CHECK_NEAR(m->dic, 0, 0);
    CHECK_NEAR(m->drc, 0.7, 0);
    CHECK_NEAR(m->src, 0.3, 0);
    CHECK_NEAR(m->trc, 0, 0);
    CHECK_NEAR(m->ior, 1.5, 0);
    CHECK_NEAR(m->fresnel, 0, 0);
    CHECK_EQ_INT(m->phong, 3);
    sd_free(&s);
    /* nff_material's limits */
    struct sd_material mm;
    nff_material((const double[8]){1, 1, 1, 2, 0.5, 100000, 0.9, 0}, &mm);
    CHECK_NEAR(mm.drc, 1, 0);
    CHECK_NEAR(mm.trc, 0.9, 0);
    CHECK_NEAR(mm.src, 1 - 0.9, 1e-15);
    CHECK_NEAR(mm.ior, 1, 0);
    CHECK_EQ_INT(mm.phong, SCN_MAX_PHONG);
    nff_material((const double[8]){1, 1, 1, 0.5, 0, 100000, 0, 30}, &mm);
    CHECK_EQ_INT(mm.phong, 0); /* no specular: no highlight */
    CHECK_NEAR(mm.ior, SCN_MAX_IOR, 0);
    /* identical surfaces share one material */
    CHECK(read_nff("f 1 0 0 1 0 0 0 0\ns 0 0 0 1\nf 0 1 0 1 0 0 0 0\ns 0 0 2 1\n"
                   "f 1 0 0 1 0 0 0 0\ns 0 0 4 1\n", &s, NULL, err, sizeof err) == 0);
    CHECK_EQ_INT(s.n_materials, 2);
    CHECK_EQ_INT(s.prims[2].material, s.prims[0].material);
    CHECK(strcmp(s.materials[1].name, "nff2") == 0);
    sd_free(&s);
}

static void test_lights(void)
{
    struct sd_scene s;
    struct nff_info info;
    char err[SD_ERR_MAX];
    /* two lights: each 1/sqrt(2); a coloured one keeps its colour */
    CHECK(read_nff("l 5 5 5 0.25 0.5 1\nf 1 1 1 1 0 0 0 0\ns 0 0 0 1\n", &s, NULL, err,
                   sizeof err) == 0);
    CHECK_EQ_INT(s.n_lights, 2);
    CHECK_NEAR(s.lights[0].colour[2], 1 / sqrt(2.0), 1e-15);
    CHECK_NEAR(s.lights[1].colour[1], 0.5, 0);
    sd_free(&s);
    /* SCN_MAX_LIGHTS (16; the head's and 15 more) are kept as they are */
    char text[2048];
    size_t len = 0;
    for (int i = 0; i < SCN_MAX_LIGHTS - 1; i++)
        len += (size_t)snprintf(text + len, sizeof text - len, "l %d 5 %d\n", 3 * i, -i);
    snprintf(text + len, sizeof text - len, "f 1 1 1 1 0 0 0 0\ns 0 0 0 1\n");
    CHECK(read_nff(text, &s, &info, err, sizeof err) == 0);
    CHECK_EQ_INT(info.lights, 16);
    CHECK_EQ_INT(info.lights_merged, 0);
    CHECK_EQ_INT(s.n_lights, 16);
    CHECK_NEAR(s.lights[15].position[0], 42, 0);
    CHECK_NEAR(s.lights[15].position[2], -14, 0);
    sd_free(&s);
    /* eighteen (the head's, 4 and 13): merged into sixteen, the nearest in
     * direction first; the total intensity kept (18 / sqrt(18)) */
    len = 0;
    const char *merged = "l 0 -10 10.1\nl 10 0 0\nl -10 0 0\nl 10 0.1 0\n";
    len += (size_t)snprintf(text + len, sizeof text - len, "%s", merged);
    for (int i = 0; i < 13; i++) /* far apart in direction: a circle above at */
        len += (size_t)snprintf(text + len, sizeof text - len, "l %.17g %.17g 30\n",
                                10 * cos(0.45 * (i + 1)), 10 * sin(0.45 * (i + 1)));
    snprintf(text + len, sizeof text - len, "f 1 1 1 1 0 0 0 0\ns 0 0 0 1\n");
    CHECK(read_nff(text, &s, &info, err, sizeof err) == 0);
    CHECK_EQ_INT(info.lights, 18);
    CHECK_EQ_INT(info.lights_merged, 2);
    CHECK_EQ_INT(s.n_lights, 16);
    double sum = 0;
    for (int i = 0; i < s.n_lights; i++)
        sum += s.lights[i].colour[0];
    CHECK_NEAR(sum, 18 / sqrt(18.0), 1e-12);
    /* (0,-10,10) and (0,-10,10.1) became one, half way; so did the two at
     * x = 10 */
    CHECK_NEAR(s.lights[0].position[2], 10.05, 1e-12);
    CHECK_NEAR(s.lights[0].colour[0], 2 / sqrt(18.0), 1e-12);
    CHECK_NEAR(s.lights[1].position[1], -0.05, 1e-12);
    CHECK_NEAR(s.lights[2].position[0], -10, 0);
    sd_free(&s);
}

/* the centroid of each triangle of a concave polygon lies inside it */
static int inside_l(double x, double y)
{
    return x > 0 && y > 0 && x < 2 && y < 2 && !(x > 1 && y > 1);
}

static void test_polygons_patches_cones(void)
{
    struct sd_scene s;
    struct nff_info info;
    char err[SD_ERR_MAX];
    /* an L-shaped hexagon (concave) in the plane z = 0, wound either way */
    for (int rev = 0; rev < 2; rev++) {
        const char *ccw = "f 1 1 1 1 0 0 0 0\np 6\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n";
        const char *cw = "f 1 1 1 1 0 0 0 0\np 6\n0 2 0\n1 2 0\n1 1 0\n2 1 0\n2 0 0\n0 0 0\n";
        CHECK(read_nff(rev ? cw : ccw, &s, &info, err, sizeof err) == 0);
        CHECK_EQ_INT(s.n_prims, 4);
        double area = 0;
        for (int p = 0; p < s.n_prims; p++) {
            const double *v = s.prims[p].v;
            double cx = (v[0] + v[3] + v[6]) / 3, cy = -(v[1] + v[4] + v[7]) / 3;
            CHECK(inside_l(cx, cy));
            area += fabs((v[3] - v[0]) * (v[7] - v[1]) - (v[4] - v[1]) * (v[6] - v[0])) / 2;
        }
        CHECK_NEAR(area, 3, 1e-12);
        sd_free(&s);
    }
    /* a convex one: a fan of n - 2 */
    CHECK(read_nff("f 1 1 1 1 0 0 0 0\np 5\n0 0 0\n2 0 0\n3 1 0\n1 3 0\n-1 1 0\n", &s, NULL,
                   err, sizeof err) == 0);
    CHECK_EQ_INT(s.n_prims, 3);
    CHECK_NEAR(s.prims[2].v[0], 0, 0);
    sd_free(&s);
    /* a patch: smooth triangles, unit normals, y negated */
    CHECK(read_nff("f 1 1 1 1 0 0 0 0\npp 4\n0 0 0 0 0 2\n1 0 0 0 0.6 0.8\n1 1 0 0 0 1\n"
                   "0 1 0 0 -3 4\n", &s, &info, err, sizeof err) == 0);
    CHECK_EQ_INT(info.patches, 1);
    CHECK_EQ_INT(s.n_prims, 2);
    CHECK(s.prims[0].smooth && s.prims[1].smooth);
    CHECK_NEAR(s.prims[0].n[2], 1, 0);
    CHECK_NEAR(s.prims[0].n[4], -0.6, 1e-15);
    CHECK_NEAR(s.prims[1].n[7], 0.6, 1e-15);
    sd_free(&s);
    /* a cylinder and a cone to a point: the renderer's cones, open ("the
     * surface exists without endcaps"), y negated; both radii negative
     * (seen from inside) the same cone */
    CHECK(read_nff("f 1 1 1 1 0 0 0 0\nc 1 2 3 0.5 1 2 5 0.5\nc 0 0 0 1 2 0 0 0\n"
                   "c 0 0 0 -1 2 0 0 -0.5\n", &s, &info, err, sizeof err) == 0);
    CHECK_EQ_INT(info.cones, 3);
    CHECK_EQ_INT(info.triangles, 0);
    CHECK_EQ_INT(s.n_prims, 3);
    static const double want[3][SCN_CONE_VALUES] = {
        {1, -2, 3, 0.5, 1, -2, 5, 0.5}, {0, 0, 0, 1, 2, 0, 0, 0}, {0, 0, 0, 1, 2, 0, 0, 0.5}};
    for (int p = 0; p < 3 && p < s.n_prims; p++) {
        CHECK_EQ_INT(s.prims[p].kind, SCN_PRIM_CONE);
        CHECK_EQ_INT(s.prims[p].capped, SCN_CONE_OPEN);
        for (int k = 0; k < SCN_CONE_VALUES; k++)
            CHECK_NEAR(s.prims[p].v[k], want[p][k], 0);
    }
    sd_free(&s);
    /* paper mode keeps the paper's four primitives: 16 quads round the
     * cylinder, 16 triangles round the cone (one end a point), no caps
     * (open), each corner at its radius from the axis */
    CHECK(read_nff("f 1 1 1 1 0 0 0 0\nc 1 2 3 0.5 1 2 5 0.5\nc 0 0 0 1 2 0 0 0\n", &s, &info,
                   err, sizeof err) == 0);
    sd_paper_apply(&s);
    CHECK_EQ_INT(s.paper_faceted, 2);
    CHECK_EQ_INT(s.n_prims, 3 * SD_CONE_SIDES);
    for (int p = 0; p < 2 * SD_CONE_SIDES && p < s.n_prims; p++)
        for (int k = 0; k < 3; k++) {
            const double *v = s.prims[p].v + 3 * k;
            CHECK_EQ_INT(s.prims[p].kind, SCN_PRIM_TRIANGLE);
            CHECK_NEAR(hypot(v[0] - 1, v[1] + 2), 0.5, 1e-12);
            CHECK(v[2] == 3 || v[2] == 5);
        }
    sd_free(&s);
    /* degenerate triangles are left out and counted */
    CHECK(read_nff("f 1 1 1 1 0 0 0 0\np 4\n0 0 0\n1 0 0\n2 0 0\n2 1 0\ns 0 0 0 1\n", &s, &info,
                   err, sizeof err) == 0);
    CHECK_EQ_INT(info.dropped, 1);
    CHECK_EQ_INT(info.triangles, 1);
    sd_free(&s);
}

/* ---------------------------------------------------------------- hostile */

static void test_hostile_refused(void)
{
    static const struct {
        const char *body;  /* after head (10 lines) */
        const char *where; /* "t.nff:LINE:COL: " */
        const char *what;
    } bad[] = {
        {"f 1 1 1 1 0 0 0 0\np 4\n0 0 0\n1 0 0\n", "t.nff:15:1: ",
         "the polygon begun on line 12 has 4 vertices, and 2 of them were read"},
        {"f 1 1 1 1 0 0 0 0\np 4\n0 0 0\n1 0 0\ns 0 0 0 1\n", "t.nff:15:1: ",
         "expected a number, found 's'"},
        {"f 1 1 1 1 0 0 0 0\np 1000000000\n", "t.nff:12:3: ",
         "the polygon's vertex count must be 3..4096, not 1000000000"},
        {"f 1 1 1 1 0 0 0 0\npp 2\n", "t.nff:12:4: ", "must be 3..4096, not 2"},
        {"f 1 1 1 1 0 0 0 0\np 3.5\n", "t.nff:12:3: ", "must be a whole number"},
        {"f 1 1 1 1 0 0 0 0\nc 0 0 0 1 0 0 0 1\n", "t.nff:12:1: ", "a cone of zero height"},
        {"f 1 1 1 1 0 0 0 0\nc 0 0 0 0 0 0 1 0\n", "t.nff:12:1: ", "radii are both 0"},
        {"f 1 1 1 1 0 0 0 0\nc 0 0 0 -1 0 0 1 1\n", "t.nff:12:1: ", "must have one sign"},
        {"f 1 1 1 1 0 0 0 0\nc 0 0 0 1 0 0 1\n", "t.nff:13:1: ",
         "expected a number (cone apex radius), found 'end of file'"},
        {"cone 1 2 3\n", "t.nff:11:1: ", "unknown NFF entity 'cone'"},
        {"f 1 1 1 1 0 0 0 0\n3 4 5\n", "t.nff:12:1: ", "expected an NFF entity"},
        {"s 0 0 0 1\n", "t.nff:11:1: ", "a sphere before any surface ('f')"},
        {"f 1 1 1 1 0 0 0 0\ns 0 0 0 -1\n", "t.nff:12:9: ", "negative radius"},
        {"f 1 1 1 1 0 0 0 0\ns 0 0 0 0\n", "t.nff:12:9: ", "sphere radius must be 1e-06..1e+08"},
        {"f 1 1 1 1 0 0 0 0\ns 0 0 1e999 1\n", "t.nff:12:7: ", "not a finite number"},
        {"f 1 1 1 1 0 0 0 0\ns 0 0 nan 1\n", "t.nff:12:7: ", "expected a number"},
        {"f 1 1 1 1 0 0 0 0\ns 0 0 2e8 1\n", "t.nff:12:7: ", "must be -1e+08..1e+08"},
        {"f 1.5 1 1 1 0 0 0 0\n", "t.nff:11:3: ", "red must be 0..1"},
        {"f 1 1 1 -1 0 0 0 0\n", "t.nff:11:9: ", "Kd must not be negative"},
        {"f 1 1 1 1 0 0 0 0\npp 3\n0 0 0 0 0 0\n1 0 0 0 0 1\n0 1 0 0 0 1\n", "t.nff:13:7: ",
         "a vertex normal of length 0"},
        {"v\nfrom 0 0 0\nat 0 0 1\nup 0 0 1\nangle 45\nresolution 8 8\n", "t.nff:11:1: ",
         "a second view"},
        {"l 0 0 0 -1 1 1\n", "t.nff:11:9: ", "light colour must be 0..100"},
        {"b 0 0\n", "t.nff:12:1: ", "expected a number (background colour)"},
        {"f 1 1 1 1 0 0 0 0\np 7\n0 2 0\n0 1 0\n2 2 0\n2 0 0\n1 3 0\n2 3 0\n1 1 0\n",
         "t.nff:12:1: ", "cannot be cut into triangles"}, /* it crosses itself */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        struct sd_scene s;
        char err[SD_ERR_MAX], msg[SD_ERR_MAX + 200];
        int rc = read_nff(bad[i].body, &s, NULL, err, sizeof err);
        int ok = rc == -1 && strncmp(err, bad[i].where, strlen(bad[i].where)) == 0 &&
                 strstr(err, bad[i].what) != NULL && s.n_prims == 0 && s.prims == NULL &&
                 s.materials == NULL && s.clusters == NULL;
        snprintf(msg, sizeof msg, "case %zu: rc %d, '%s'; want '%s...%s'", i, rc,
                 rc ? err : "(read)", bad[i].where, bad[i].what);
        if (!ok)
            check_fail(__FILE__, __LINE__, msg);
        if (rc == 0)
            sd_free(&s);
    }
    /* whole-file problems, at the end of the text */
    static const struct {
        const char *text, *what;
    } whole[] = {
        {"l 0 0 1\nf 1 1 1 1 0 0 0 0\ns 0 0 0 1\n", "t.nff:4:1: the file has no view"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 45\nresolution 8 8\nf 1 1 1 1 0 0 0 0\n"
         "s 0 0 0 1\n", "t.nff:9:1: the file has no light"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 45\nresolution 8 8\nl 0 0 1\n",
         "t.nff:8:1: the file has no object"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nresolution 8 8\nl 0 0 1\n",
         "t.nff:6:1: the view begun on line 1 has no 'angle' (found 'l')"},
        {"v\nfrom 0 -1 0\nat 0 -1 0\nup 0 0 1\nangle 45\nresolution 8 8\nl 0 0 1\n",
         "t.nff:1:1: view: from and at are the same point"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 2 0\nangle 45\nresolution 8 8\nl 0 0 1\n",
         "t.nff:1:1: view: up is parallel"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 180\nresolution 8 8\nl 0 0 1\n",
         "t.nff:5:7: angle must be above 0 and below 180"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 179\nresolution 8 8\nl 0 0 1\n",
         "t.nff:1:1: view: angle 179 at 8x8 is a horizontal field of view beyond"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 45\nresolution 0 8\nl 0 0 1\n",
         "t.nff:6:12: resolution width must be 1..1024, not 0"},
        {"v\nfrom 0 -1 0\nat 0 0 0\nup 0 0 1\nangle 45\nresolution 8 8\nl 0 0 1\n"
         "f 1 1 1 1 0 0 0 0\np 3\n0 0 0\n1 0 0\n2 0 0\n",
         "t.nff:13:1: the file has no object that is not degenerate"},
        {"v { }\n", "t.nff:1:3: the view begun on line 1 has no 'from'"},
        {"v\nfrom 0 -1 0 \"at\n", "t.nff:2:13: string not closed"},
    };
    for (size_t i = 0; i < sizeof whole / sizeof whole[0]; i++) {
        struct sd_scene s;
        char err[SD_ERR_MAX], msg[SD_ERR_MAX + 200];
        int rc = nff_read_text("t.nff", whole[i].text, &s, NULL, err, sizeof err);
        snprintf(msg, sizeof msg, "whole %zu: rc %d, '%s'; want '%s'", i, rc, rc ? err : "",
                 whole[i].what);
        if (rc != -1 || strncmp(err, whole[i].what, strlen(whole[i].what)) != 0)
            check_fail(__FILE__, __LINE__, msg);
        if (rc == 0)
            sd_free(&s);
    }
    /* more lights than NFF_MAX_LIGHTS, more surfaces than materials */
    size_t cap = 64 * 1024;
    char *t = malloc(cap);
    size_t n = (size_t)snprintf(t, cap, "%s", head);
    for (int i = 0; i < NFF_MAX_LIGHTS; i++)
        n += (size_t)snprintf(t + n, cap - n, "l %d 0 0\n", i);
    struct sd_scene s;
    char err[SD_ERR_MAX];
    CHECK(nff_read_text("t.nff", t, &s, NULL, err, sizeof err) == -1);
    CHECK(strstr(err, "t.nff:266:1: too many lights (the limit is 256)") == err);
    n = (size_t)snprintf(t, cap, "%s", head);
    for (int i = 0; i <= SCN_MAX_MATERIALS; i++)
        n += (size_t)snprintf(t + n, cap - n, "f 1 1 1 %g 0 0 0 0\n", i / 2048.0);
    CHECK(nff_read_text("t.nff", t, &s, NULL, err, sizeof err) == -1);
    CHECK(strstr(err, "too many different surfaces (the limit is 1024)") != NULL);
    free(t);
}

/* every prefix of official files (and each with a byte changed) is read or
 * refused, never a crash, leak or sanitizer report */
static void test_prefixes_never_crash(void)
{
    static const char *const files[] = {"teapot1", "rings1", "gears1", "tree1"};
    long ok = 0, refused = 0;
    for (size_t f = 0; f < sizeof files / sizeof files[0]; f++) {
        char path[128];
        snprintf(path, sizeof path, OFFICIAL "%s.nff", files[f]);
        char *t = read_text(path);
        CHECK(t != NULL);
        if (!t)
            continue;
        size_t len = strlen(t);
        for (size_t cut = 0; cut <= len; cut += 1 + cut / 64) {
            for (int flip = 0; flip < 2; flip++) {
                char *p = malloc(cut + 1);
                memcpy(p, t, cut);
                p[cut] = 0;
                if (flip && cut > 0)
                    p[cut / 2] = "x9-.\n{#e"[cut % 8];
                struct sd_scene s;
                char err[SD_ERR_MAX];
                if (nff_read_text("cut.nff", p, &s, NULL, err, sizeof err) == 0) {
                    ok++;
                    CHECK(s.n_prims > 0 && s.n_lights > 0);
                    sd_free(&s);
                } else {
                    refused++;
                    CHECK(strncmp(err, "cut.nff:", 8) == 0 && s.prims == NULL);
                }
                free(p);
            }
        }
        free(t);
    }
    CHECK(ok > 0 && refused > 0);
}

/* ---------------------------------------------------------- scene files */

static void test_scene_file_reads_nff(void)
{
    char dir[] = "/tmp/links1-test-nff-XXXXXX", path[128], err[SD_ERR_MAX];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/balls1.nff", dir);
    char *t = read_text(OFFICIAL "balls1.nff");
    FILE *f = fopen(path, "w");
    CHECK(t && f);
    if (f && t)
        fputs(t, f);
    if (f)
        fclose(f);
    free(t);
    struct sd_scene s, direct;
    CHECK(scene_file_parse(path, &s, err, sizeof err) == 0);
    CHECK(nff_read_file(OFFICIAL "balls1.nff", &direct, NULL, err, sizeof err) == 0);
    CHECK_EQ_INT(s.n_prims, 12); /* 10 spheres, the floor's 2 triangles */
    CHECK(s.n_prims == direct.n_prims &&
          memcmp(s.prims, direct.prims, (size_t)s.n_prims * sizeof *s.prims) == 0);
    sd_free(&s);
    sd_free(&direct);
    struct scene_file_opts o;
    scene_file_opts_init(&o);
    o.width = o.height = 16;
    uint8_t *buf = NULL;
    size_t len = 0;
    CHECK(scene_file_bytes(path, &o, &buf, &len, err, sizeof err) == 0 && len > 0);
    free(buf);
    /* an error names the file, line and column */
    f = fopen(path, "w");
    if (f) {
        fputs("v\nfrom 0 0 0\nbogus\n", f);
        fclose(f);
    }
    CHECK(scene_file_parse(path, &s, err, sizeof err) == -1);
    char want[200];
    snprintf(want, sizeof want, "%s:3:1: the view begun on line 1 has no 'at'", path);
    CHECK(strncmp(err, want, strlen(want)) == 0);
    /* the text form is still the text form */
    snprintf(path, sizeof path, "%s/x.scn", dir);
    f = fopen(path, "w");
    if (f) {
        fputs("b 0 0 0\n", f);
        fclose(f);
    }
    CHECK(scene_file_parse(path, &s, err, sizeof err) == -1 && strstr(err, "unknown statement"));
    remove(path);
    snprintf(path, sizeof path, "%s/balls1.nff", dir);
    remove(path);
    rmdir(dir);
}

int main(void)
{
    RUN(test_generators_equal_official);
    RUN(test_official_counts);
    RUN(test_issue_numbers);
    RUN(test_scene_compiles_as_official);
    RUN(test_view_and_looks);
    RUN(test_lights);
    RUN(test_polygons_patches_cones);
    RUN(test_hostile_refused);
    RUN(test_prefixes_never_crash);
    RUN(test_scene_file_reads_nff);
    return check_exit();
}
