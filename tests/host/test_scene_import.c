/* test_scene_import.c: models made elsewhere into scenes (scene_import.h,
 * docs/import.md): each format of tests/models/, the material mapping field
 * by field, camera and lights, the `model` statement, and every kind of bad
 * model.  Runs from the repository's top directory. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/scene/scene_import.h"
#include "tests/check.h"
#include "tests/host/empty_scene.h"

#define MODELS "tests/models/"


/* Imports path into a fresh scene s: 0, or -1 with err. */
static int import(const char *path, int fit, struct sd_scene *s, struct import_result *r,
                  struct model *m, char *err, size_t errlen)
{
    empty_scene(s);
    memset(m, 0, sizeof *m);
    if (model_load(path, m, err, errlen) != 0)
        return -1;
    struct import_opts o = {fit, -1, 0, "--fit", 0, NULL};
    return scene_import_model(s, 0, m, MODELS, &o, r, err, errlen);
}

static const struct sd_material *material(const struct sd_scene *s, const char *name)
{
    for (int i = 0; i < s->n_materials; i++)
        if (strcmp(s->materials[i].name, name) == 0)
            return &s->materials[i];
    return NULL;
}

static struct import_result res; /* large: the texture paths */

static void test_obj_mtl_material_mapping(void)
{
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "cube.obj", 0, &s, &res, &m, err, sizeof err) == 0);
    if (err[0])
        printf("  %s\n", err);
    CHECK_EQ_INT(res.triangles, 12);
    CHECK_EQ_INT(s.n_prims, 12);
    const struct sd_material *red = material(&s, "red"), *glass = material(&s, "glass");
    CHECK(red && glass);
    if (red) {
        /* Kd 0.8 0.2 0.4: drc the largest channel, F the colour over it */
        CHECK_NEAR(red->drc, 0.8, 1e-6);
        CHECK_NEAR(red->colour[0], 1, 1e-6);
        CHECK_NEAR(red->colour[1], 0.25, 1e-6);
        CHECK_NEAR(red->colour[2], 0.5, 1e-6);
        CHECK_NEAR(red->dic, 0.3, 1e-6);   /* Ka 0.3 0.1 0.2 */
        CHECK_NEAR(red->src, 0.5, 1e-6);   /* Ks 0.5 0.4 0.2 */
        CHECK_EQ_INT(red->phong, 32);      /* Ns 32 */
        CHECK_NEAR(red->trc, 0.25, 1e-6);  /* d 0.75 */
        CHECK_NEAR(red->ior, 1.5, 1e-6);   /* Ni 1.5 */
        CHECK_NEAR(red->fresnel, 0, 0);
        CHECK(red->colour_map >= 0 && red->bump_map >= 0);
        if (red->colour_map >= 0 && red->bump_map >= 0) {
            const struct sd_map *c = &s.maps[red->colour_map], *b = &s.maps[red->bump_map];
            CHECK_EQ_INT(c->kind, SCN_MAP_COLOUR);
            CHECK_EQ_INT(c->width, 2);
            CHECK(c->texels[0] == 255 && c->texels[1] == 0 && c->texels[5] == 0 &&
                  c->texels[4] == 255); /* red, green: the file's first row */
            CHECK_EQ_INT(b->kind, SCN_MAP_BUMP);
            CHECK(b->texels[0] == 0 && b->texels[1] == 100 && b->texels[3] == 255);
        }
    }
    if (glass) {
        CHECK_NEAR(glass->trc, 0.8, 1e-6);    /* d 0.2 */
        CHECK_NEAR(glass->src, 0.2, 1e-6);    /* Ks 0.9, cut to 1 - trc */
        CHECK_EQ_INT(glass->phong, SCN_MAX_PHONG); /* Ns 2000, clamped */
        CHECK_NEAR(glass->ior, SCN_MAX_IOR, 1e-6); /* Ni 20, clamped */
        CHECK_EQ_INT(glass->colour_map, -1);
    }
    /* uv: the model's v runs up the image, the scene's down it */
    const struct sd_prim *p = &s.prims[0];
    CHECK_NEAR(p->v[12], 1, 1e-9);
    /* z negated: the cube's face at model z = -1 is at scene z = +1 */
    CHECK_NEAR(p->v[2], 1, 1e-9);
    sd_free(&s);
    model_free(&m);
}

static void test_gltf_camera_lights_transmission(void)
{
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "plate.gltf", 0, &s, &res, &m, err, sizeof err) == 0);
    CHECK_EQ_INT(res.triangles, 2);
    const struct sd_material *g = material(&s, "tinted_glass");
    CHECK(g != NULL);
    if (g) {
        CHECK_NEAR(g->trc, 0.6, 1e-6); /* KHR_materials_transmission */
        CHECK_NEAR(g->ior, 1.4, 1e-6); /* KHR_materials_ior */
        CHECK_NEAR(g->drc, 0.6, 1e-6);
        CHECK_NEAR(g->colour[0], 0.2 / 0.6, 1e-6);
    }
    /* nodes: stand (translate y 0.5) > plate (scale 2): world point of
     * the quad's corner (1, 1, 0) lies at y 0.5 + 2 */
    CHECK_NEAR(res.hi[1], 2.5, 1e-5);
    char wpath[] = "/tmp/links1-test-import-XXXXXX";
    int fd = mkstemp(wpath);
    FILE *warn = fdopen(fd, "w+");
    CHECK(scene_import_view(&s, &m, &res, 0, warn, err, sizeof err) == 0);
    CHECK_EQ_INT(s.n_lights, 4); /* 4 in the file, within SCN_MAX_LIGHTS: all kept */
    for (int i = 0; i < 3; i++)
        CHECK(s.lights[i].colour[0] > 0.2);
    CHECK_NEAR(s.lights[3].colour[0], 0.1, 1e-6); /* lamp_d: the weakest, last */
    CHECK_EQ_INT(s.lights[0].kind, SCN_LIGHT_POINT); /* lamp_a: strongest */
    CHECK_NEAR(s.lights[0].position[2], -5, 1e-6);   /* z negated */
    CHECK_EQ_INT(s.lights[1].kind, SCN_LIGHT_SPOT);
    CHECK_NEAR(s.lights[1].cone, 0.1 * 180 / M_PI, 1e-3); /* inner angle 0.2 rad, full */
    CHECK_EQ_INT(s.lights[2].kind, SCN_LIGHT_PARALLEL);
    CHECK_NEAR(s.lights[2].direction[2], 1, 1e-6); /* -z in the model */
    CHECK_NEAR(s.view.eye[2], -6, 1e-6);
    CHECK_NEAR(s.view.eye[1], 1, 1e-6);
    CHECK_EQ_INT(s.view.height, 213); /* 320 / aspect 1.5 */
    rewind(warn);
    char line[512] = "";
    while (fgets(line, sizeof line, warn))
        CHECK(strstr(line, "strongest") == NULL); /* no light left out */
    fclose(warn);
    unlink(wpath);
    sd_free(&s);
    model_free(&m);
}

static void test_ply_stl_collada(void)
{
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "tetra.ply", 0, &s, &res, &m, err, sizeof err) == 0);
    CHECK_EQ_INT(res.triangles, 4);
    /* no material in the file: the scene's defaults */
    CHECK(s.n_materials == 1 && s.materials[0].drc == 0.9 && s.materials[0].src == 0);
    sd_free(&s), model_free(&m);
    CHECK(import(MODELS "pyramid.stl", 0, &s, &res, &m, err, sizeof err) == 0);
    CHECK_EQ_INT(res.triangles, 6);
    sd_free(&s), model_free(&m);
    CHECK(import(MODELS "tower.dae", 0, &s, &res, &m, err, sizeof err) == 0);
    CHECK_EQ_INT(res.triangles, 12); /* one tetrahedron in each of 3 nested nodes */
    int deepest = 0;
    for (int c = 0; c < s.n_clusters; c++) {
        int d = 0;
        for (int k = c; s.clusters[k].parent >= 0; k = s.clusters[k].parent)
            d++;
        deepest = d > deepest ? d : deepest;
    }
    CHECK_EQ_INT(deepest, 4); /* root > scene > base > middle > top */
    const struct sd_material *st = material(&s, "stone");
    CHECK(st && fabs(st->dic - 0.2) < 1e-6 && fabs(st->src - 0.25) < 1e-6 &&
          st->phong == 12 && fabs(st->ior - 1.3) < 1e-6 && fabs(st->drc - 0.9) < 1e-6);
    CHECK(scene_import_view(&s, &m, &res, 0, stderr, err, sizeof err) == 0);
    CHECK_EQ_INT(s.n_lights, 2);
    CHECK_NEAR(s.view.fov, 50, 1e-3);
    sd_free(&s), model_free(&m);
}

/* A 3DS file (binary chunks): one object, a tetrahedron, in a material
 * with a diffuse colour. */
static void put16(FILE *f, unsigned v) { fputc(v & 255, f), fputc(v >> 8, f); }
static void put32(FILE *f, unsigned long v) { put16(f, v & 0xffff), put16(f, v >> 16); }
static void putf(FILE *f, float x)
{
    unsigned long u;
    unsigned int b;
    memcpy(&b, &x, 4);
    u = b;
    put32(f, u);
}
static void write_3ds(const char *path)
{
    static const float v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    static const unsigned faces[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    unsigned mat_name = 4, colour = 6 + 3, diffuse = 6 + colour, mat_name_chunk = 6 + mat_name;
    unsigned material = 6 + mat_name_chunk + diffuse;
    unsigned facemat = 6 + mat_name + 2 + 4 * 2;
    unsigned facelist = 6 + 2 + 4 * 8 + facemat, vertlist = 6 + 2 + 12 * 4;
    unsigned trimesh = 6 + vertlist + facelist, object = 6 + 4 + trimesh;
    unsigned editor = 6 + material + object, main_len = 6 + editor;
    FILE *f = fopen(path, "wb");
    put16(f, 0x4d4d), put32(f, main_len);
    put16(f, 0x3d3d), put32(f, editor);
    put16(f, 0xafff), put32(f, material);
    put16(f, 0xa000), put32(f, mat_name_chunk), fwrite("red", 1, 4, f);
    put16(f, 0xa020), put32(f, diffuse);
    put16(f, 0x0011), put32(f, colour), fputc(204, f), fputc(51, f), fputc(0, f);
    put16(f, 0x4000), put32(f, object), fwrite("tet", 1, 4, f);
    put16(f, 0x4100), put32(f, trimesh);
    put16(f, 0x4110), put32(f, vertlist), put16(f, 4);
    for (int i = 0; i < 12; i++)
        putf(f, v[i]);
    put16(f, 0x4120), put32(f, facelist), put16(f, 4);
    for (int i = 0; i < 4; i++)
        put16(f, faces[3 * i]), put16(f, faces[3 * i + 1]), put16(f, faces[3 * i + 2]),
            put16(f, 7);
    put16(f, 0x4130), put32(f, facemat), fwrite("red", 1, 4, f), put16(f, 4);
    for (int i = 0; i < 4; i++)
        put16(f, (unsigned)i);
    fclose(f);
}

/* tests/models/tetra.3ds is what write_3ds writes (3DS has no text form). */
static void test_3ds(void)
{
    char path[] = "/tmp/links1-test-import-XXXXXX.3ds";
    close(mkstemps(path, 4));
    write_3ds(path);
    char a[512], b[512];
    FILE *fa = fopen(path, "rb"), *fb = fopen(MODELS "tetra.3ds", "rb");
    size_t na = fa ? fread(a, 1, sizeof a, fa) : 0, nb = fb ? fread(b, 1, sizeof b, fb) : 1;
    CHECK(na > 0 && na == nb && memcmp(a, b, na) == 0);
    if (fa)
        fclose(fa);
    if (fb)
        fclose(fb);
    unlink(path);
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "tetra.3ds", 0, &s, &res, &m, err, sizeof err) == 0);
    if (err[0])
        printf("  %s\n", err);
    CHECK_EQ_INT(res.triangles, 4);
    const struct sd_material *red = material(&s, "red");
    CHECK(red && fabs(red->drc - 0.8) < 1e-6 && fabs(red->colour[1] - 0.25) < 1e-6);
    sd_free(&s), model_free(&m);
}

/* The import written as text reads back to the same scene. */
static void test_written_text_reads_back(void)
{
    struct sd_scene s, back;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "tower.dae", 0, &s, &res, &m, err, sizeof err) == 0);
    CHECK(scene_import_view(&s, &m, &res, 0, stderr, err, sizeof err) == 0);
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    CHECK(sd_write_text(&s, NULL, f) == 0);
    fclose(f);
    CHECK(sd_parse_text("written.scn", text, &back, err, sizeof err) == 0);
    if (err[0])
        printf("  %s\n", err);
    CHECK_EQ_INT(back.n_prims, s.n_prims);
    CHECK_EQ_INT(back.n_clusters, s.n_clusters);
    CHECK_EQ_INT(back.n_lights, s.n_lights);
    int same = back.n_prims == s.n_prims;
    for (int i = 0; same && i < s.n_prims; i++)
        same = memcmp(back.prims[i].v, s.prims[i].v, sizeof s.prims[i].v) == 0;
    CHECK(same);
    int same_m = back.n_clusters == s.n_clusters;
    for (int i = 0; same_m && i < s.n_clusters; i++)
        for (int k = 0; k < 12; k++)
            same_m &= back.clusters[i].m[k] == s.clusters[i].m[k];
    CHECK(same_m);
    free(text);
    sd_free(&back), sd_free(&s), model_free(&m);
}

/* ------------------------------------------------------------- bad models */

static void test_bad_library_failure(void)
{
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "bad_syntax.gltf", 0, &s, &res, &m, err, sizeof err) != 0);
    CHECK(strstr(err, "bad_syntax.gltf") && strstr(err, "cannot read it: "));
    sd_free(&s);
    CHECK(import(MODELS "no_such_model.obj", 0, &s, &res, &m, err, sizeof err) != 0);
    CHECK(strstr(err, "no_such_model.obj") != NULL);
    sd_free(&s);
}

static void test_bad_nonfinite(void)
{
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "nonfinite.obj", 0, &s, &res, &m, err, sizeof err) != 0);
    CHECK(strstr(err, "vertex 2 is not finite") != NULL);
    if (!strstr(err, "not finite"))
        printf("  %s\n", err);
    CHECK_EQ_INT(s.n_prims, 0); /* nothing of it added */
    CHECK_EQ_INT(s.n_clusters, 1);
    sd_free(&s), model_free(&m);
}

static void test_bad_degenerate_dropped(void)
{
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "degenerate.obj", 0, &s, &res, &m, err, sizeof err) == 0);
    CHECK_EQ_INT(res.triangles, 2);
    CHECK_EQ_INT(res.degenerate, 2);
    CHECK_EQ_INT(s.n_prims, 2);
    sd_free(&s), model_free(&m);
}

static void test_bad_missing_texture(void)
{
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "missing_tex.obj", 0, &s, &res, &m, err, sizeof err) != 0);
    CHECK(strstr(err, "material 'painted'") && strstr(err, "no_such_texture.png"));
    CHECK_EQ_INT(s.n_prims, 0);
    CHECK_EQ_INT(s.n_materials, 0);
    CHECK_EQ_INT(s.n_maps, 0);
    sd_free(&s), model_free(&m);
}

static void test_bad_over_the_triangle_limit(void)
{
    char path[] = "/tmp/links1-test-import-XXXXXX.obj";
    FILE *f = fdopen(mkstemps(path, 4), "w");
    fprintf(f, "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for (int i = 0; i <= SCN_MAX_PRIMS; i++)
        fputs("f 1 2 3\n", f);
    fclose(f);
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(path, 0, &s, &res, &m, err, sizeof err) != 0);
    char want[2][48];
    snprintf(want[0], sizeof want[0], "%d triangles", SCN_MAX_PRIMS + 1);
    snprintf(want[1], sizeof want[1], "limit is %d", SCN_MAX_PRIMS);
    CHECK(strstr(err, want[0]) && strstr(err, want[1]));
    CHECK_EQ_INT(s.n_prims, 0);
    sd_free(&s), model_free(&m);
    unlink(path);
}

static void test_bad_out_of_range_and_fit(void)
{
    struct sd_scene s;
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(import(MODELS "huge.obj", 0, &s, &res, &m, err, sizeof err) != 0);
    CHECK(strstr(err, "x -2.5e+08..2.5e+08") && strstr(err, "+-1e+08") && strstr(err, "--fit"));
    sd_free(&s), model_free(&m);
    CHECK(import(MODELS "huge.obj", 1, &s, &res, &m, err, sizeof err) == 0);
    CHECK_NEAR(res.scale, IMPORT_FIT_EXTENT / 3e8, 1e-18);
    CHECK_NEAR(res.hi[1], IMPORT_FIT_EXTENT, 1e-9);
    /* the file's second vertex, third in the scene (triangles turned over) */
    CHECK_NEAR(s.prims[0].v[6], 2.5e8 * IMPORT_FIT_EXTENT / 3e8, 1e-9);
    sd_free(&s), model_free(&m);
}

/* A PLY header line libassimp 5.2 loops without end on is refused before
 * the library sees it (file and memory); a good PLY still reads. */
static void test_bad_ply_header(void)
{
    const char *ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x outer loop\n"
                      "property float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
    const char *path = "build/test-logs/bad_header.ply";
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f)
        return;
    fputs(ply, f);
    fclose(f);
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(model_load(path, &m, err, sizeof err) != 0);
    CHECK(strstr(err, "bad_header.ply: a PLY header line the model library cannot take") &&
          strstr(err, "'property float x outer loop'"));
    CHECK(model_load_memory(ply, strlen(ply), "ply", &m, err, sizeof err) != 0);
    CHECK(strstr(err, "'property float x outer loop'") != NULL);
    CHECK(model_load("tests/models/tetra.ply", &m, err, sizeof err) == 0);
    model_free(&m);
    remove(path);
}

/* ------------------------------------------------------ the model statement */

static void test_model_statement(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX] = "";
    const char *text = "light point { position 0 5 -5 }\n"
                       "material m { colour 1 0 0 }\n"
                       "cluster a { rotate 0 25 0  model { file \"cube.obj\" } }\n"
                       "cluster b { translate 3 0 0  model { file \"tower.dae\"  material m } }\n";
    CHECK(sd_parse_text(MODELS "scene.scn", text, &s, err, sizeof err) == 0);
    if (err[0])
        printf("  %s\n", err);
    CHECK_EQ_INT(s.n_prims, 12 + 12);
    CHECK(material(&s, "red") != NULL); /* the cube keeps its own */
    CHECK(material(&s, "stone") == NULL); /* the tower takes m */
    int in_b = 0;
    for (int i = 0; i < s.n_prims; i++)
        in_b += s.prims[i].material == 0;
    CHECK_EQ_INT(in_b, 12);
    sd_free(&s);
    /* a bad model stops the scene with the statement's position */
    const char *bad = "light point { position 0 5 -5 }\n"
                      "cluster a {\n  model { file \"missing_tex.obj\" } }\n";
    CHECK(sd_parse_text(MODELS "bad.scn", bad, &s, err, sizeof err) != 0);
    CHECK(strstr(err, "bad.scn:3:3: model ") && strstr(err, "no_such_texture.png"));
    const char *range = "light point { position 0 5 -5 }\n"
                        "model { file \"huge.obj\" }\n";
    CHECK(sd_parse_text(MODELS "r.scn", range, &s, err, sizeof err) != 0);
    CHECK(strstr(err, "r.scn:2:1:") && strstr(err, "'fit on'"));
    const char *fit = "light point { position 0 5 -5 }\n"
                      "model { file \"huge.obj\"  fit on }\n";
    CHECK(sd_parse_text(MODELS "r.scn", fit, &s, err, sizeof err) == 0);
    sd_free(&s);
    const char *none = "light point { position 0 5 -5 }\nmodel { file \"nothing.obj\" }\n";
    CHECK(sd_parse_text(MODELS "n.scn", none, &s, err, sizeof err) != 0);
    CHECK(strstr(err, "n.scn:2:1: model: tests/models/nothing.obj") != NULL);
}

int main(void)
{
    RUN(test_obj_mtl_material_mapping);
    RUN(test_gltf_camera_lights_transmission);
    RUN(test_ply_stl_collada);
    RUN(test_3ds);
    RUN(test_written_text_reads_back);
    RUN(test_bad_library_failure);
    RUN(test_bad_nonfinite);
    RUN(test_bad_degenerate_dropped);
    RUN(test_bad_missing_texture);
    RUN(test_bad_over_the_triangle_limit);
    RUN(test_bad_out_of_range_and_fit);
    RUN(test_bad_ply_header);
    RUN(test_model_statement);
    return check_exit();
}
