/* test_scene_parse.c: the text scene format: what it accepts, and that
 * every mistake is reported as file:line:col with what is wrong. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_import.h"
#include "host-tools/scene/scene_lex.h"
#include "tests/check.h"

#define HEAD "light point { position 0 5 0 }\nmaterial m { }\n"
#define SHADING_FLAGS (SCN_OPT_AMBIENT_SHADOWED | SCN_OPT_UNTINTED_SHADOWS)
#define LIGHTS5                                                                             \
    "light point { position 0 5 0 }\nlight parallel { direction 0 -1 0 }\n"                  \
    "light spot { position 0 4 0 at 0 0 0 cone 20 }\nlight point { position 1 5 0 }\n"       \
    "light spot { position 0 4 0 direction 0 -1 0 cone 10 falloff 2 }\n"

/* Parses text; returns 0 on success, else checks the message starts with
 * "t.scn:LINE:COL: " and contains words. */
static void expect_error(const char *text, int line, int col, const char *words,
                         const char *file, int at)
{
    struct sd_scene s;
    char err[SD_ERR_MAX], want[64];
    if (sd_parse_text("t.scn", text, &s, err, sizeof err) == 0) {
        sd_free(&s);
        check_fail(file, at, "parse succeeded, an error was expected");
        return;
    }
    snprintf(want, sizeof want, "t.scn:%d:%d: ", line, col);
    if (strncmp(err, want, strlen(want)) != 0 || strstr(err, words) == NULL) {
        char m[SD_ERR_MAX + 128];
        snprintf(m, sizeof m, "got '%s', want '%s...%s'", err, want, words);
        check_fail(file, at, m);
    }
    CHECK_EQ_INT(s.n_prims + s.n_materials + s.n_clusters + s.n_maps, 0);
}
#define EXPECT_ERROR(text, line, col, words) expect_error(text, line, col, words, __FILE__, __LINE__)

static void test_minimal_scene_and_defaults(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    int rc = sd_parse_text("t.scn", HEAD "sphere { material m radius 1 }\n", &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    CHECK_EQ_INT(s.view.width, 320);
    CHECK_EQ_INT(s.view.height, 240);
    CHECK_EQ_INT(s.view.max_depth, 5);
    CHECK_EQ_INT(s.view.density_steps, SCN_DEFAULT_DENSITY_STEPS);
    CHECK_EQ_INT(s.view.flags,
                 SCN_OPT_REFRACTIONLESS | SCN_OPT_AMBIENT_SHADOWED | SCN_OPT_UNTINTED_SHADOWS);
    CHECK_EQ_INT(s.n_prims, 1);
    CHECK_EQ_INT(s.n_clusters, 1);
    CHECK_NEAR(s.materials[0].drc, 0.9, 0);
    sd_free(&s);
}

static void test_refraction_option(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    int rc = sd_parse_text("t.scn", HEAD "options { refraction off }\nsphere { material m radius 1 }\n", &s,
                           err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    CHECK_EQ_INT(s.view.flags & ~SHADING_FLAGS, SCN_OPT_REFRACTIONLESS | SCN_OPT_NO_REFRACTION);
    sd_free(&s);
    rc = sd_parse_text("t.scn", HEAD "options { refraction on }\nsphere { material m radius 1 }\n", &s,
                       err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    CHECK_EQ_INT(s.view.flags & ~SHADING_FLAGS, SCN_OPT_REFRACTIONLESS);
    sd_free(&s);
    EXPECT_ERROR(HEAD "options { refraction maybe }\n", 3, 22, "on");
}

/* The paper's readings by default: src(th) and trc(th) on Schlick's curve
 * for a material that reflects or transmits (fresnel 1), constants for a
 * matte one, `constant`, `fresnel W` or `options { fresnel off }`;
 * ambient shadowed and untinted shadows unless the options say. */
static void test_shading_defaults_and_options(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    const char *mats = "material shiny { src 0.2 }\nmaterial clear { trc 0.5 }\n"
                       "material flat { constant src 0.3 }\nmaterial half { src 0.1 fresnel 0.25 }\n"
                       "sphere { material m radius 1 }\n";
    char text[1024];
    for (int off = 0; off < 2; off++) {
        snprintf(text, sizeof text, HEAD "%s%s", mats, off ? "options { fresnel off }\n" : "");
        int rc = sd_parse_text("t.scn", text, &s, err, sizeof err);
        CHECK_EQ_INT(rc, 0);
        if (rc)
            return;
        CHECK_NEAR(s.materials[0].fresnel, 0, 0); /* m: matte */
        CHECK_NEAR(s.materials[1].fresnel, off ? 0 : 1, 0);
        CHECK_NEAR(s.materials[2].fresnel, off ? 0 : 1, 0);
        CHECK_NEAR(s.materials[3].fresnel, 0, 0);
        CHECK_NEAR(s.materials[4].fresnel, 0.25, 0);
        sd_free(&s);
    }
    int rc = sd_parse_text("t.scn",
                           HEAD "options { ambient_shadowed off  shadow_tint on }\n"
                                "sphere { material m radius 1 }\n",
                           &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    CHECK_EQ_INT(s.view.flags & SHADING_FLAGS, 0);
    sd_free(&s);
    rc = sd_parse_text("t.scn",
                       HEAD "options { ambient_shadowed on  shadow_tint off }\n"
                            "sphere { material m radius 1 }\n",
                       &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    CHECK_EQ_INT(s.view.flags & SHADING_FLAGS, SHADING_FLAGS);
    sd_free(&s);
    EXPECT_ERROR(HEAD "options { shadow_tint 1 }\n", 3, 23, "on");
}

/* density_steps: an integer within SCN_MIN..SCN_MAX_DENSITY_STEPS. */
static void test_density_steps_option(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    int rc = sd_parse_text("t.scn", HEAD "options { density_steps 64 }\nsphere { material m radius 1 }\n",
                           &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    CHECK_EQ_INT(s.view.density_steps, 64);
    sd_free(&s);
    EXPECT_ERROR(HEAD "options { density_steps 1 }\n", 3, 25, "density_steps must be 2..256");
    EXPECT_ERROR(HEAD "options { density_steps 257 }\n", 3, 25, "density_steps must be 2..256");
    EXPECT_ERROR(HEAD "options { density_steps 2.5 }\n", 3, 25, "density_steps");
}

/* aa N (0..4) turns anti-aliasing on, aa_threshold T (0..1, default
 * 0.1) its threshold; aa with paper on is refused. */
static void test_aa_option(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    int rc = sd_parse_text("t.scn", HEAD "options { aa 2  aa_threshold 0.05 }\n"
                           "sphere { material m radius 1 }\n", &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    CHECK_EQ_INT(s.view.flags & SCN_OPT_ANTIALIAS, SCN_OPT_ANTIALIAS);
    CHECK_EQ_INT(s.view.aa_depth, 2);
    CHECK_NEAR(s.view.aa_threshold, 0.05, 1e-12);
    sd_free(&s);
    rc = sd_parse_text("t.scn", HEAD "sphere { material m radius 1 }\n", &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    CHECK_EQ_INT(s.view.flags & SCN_OPT_ANTIALIAS, 0);
    CHECK_NEAR(s.view.aa_threshold, SCN_DEFAULT_AA_THRESHOLD, 1e-12);
    sd_free(&s);
    EXPECT_ERROR(HEAD "options { aa 5 }\n", 3, 14, "aa must be 0..4");
    EXPECT_ERROR(HEAD "options { aa -1 }\n", 3, 14, "aa must be 0..4");
    EXPECT_ERROR(HEAD "options { aa_threshold 2 }\n", 3, 24, "aa_threshold");
    EXPECT_ERROR(HEAD "options { aa_threshold x }\n", 3, 24, "aa_threshold");
    rc = sd_parse_text("t.scn", HEAD "options { paper on  aa 1 }\nsphere { material m radius 1 }\n",
                       &s, err, sizeof err);
    CHECK_EQ_INT(rc, -1);
    CHECK(strstr(err, "paper mode has no anti-aliasing") != NULL);
}

static void test_transforms_compose_in_order(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    /* scale 2 then translate 1 0 0: the point (1,0,0) lands on (3,0,0);
     * rotate 0 0 90 then sends x to y. */
    int rc = sd_parse_text("t.scn",
                           HEAD "cluster a { scale 2 translate 1 0 0 rotate 0 0 90\n"
                                " box { material m min 0 0 0 max 1 1 1 } }\n",
                           &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    const double *m = s.clusters[1].m;
    double p[3];
    for (int r = 0; r < 3; r++)
        p[r] = m[r * 4 + 0] * 1 + m[r * 4 + 3];
    CHECK_NEAR(p[0], 0, 1e-12);
    CHECK_NEAR(p[1], 3, 1e-12);
    CHECK_NEAR(p[2], 0, 1e-12);
    sd_free(&s);
}

static void test_keyframe_interpolation(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    int rc = sd_parse_text("t.scn",
                           HEAD "animation { frames 5 }\n"
                                "cluster a { key 0 { translate 0 0 0 } key 4 { translate 8 0 0 "
                                "rotate 0 90 0 }\n sphere { material m radius 1 } }\n",
                           &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc)
        return;
    double k[12];
    sd_key_matrix(&s, 1, 2, k);
    CHECK_NEAR(k[3], 4, 1e-12);
    /* halfway rotation about y: 45 degrees */
    CHECK_NEAR(k[0], 0.70710678, 1e-6);
    CHECK_NEAR(k[2], 0.70710678, 1e-6);
    sd_key_matrix(&s, 1, 9, k); /* after the last key: held */
    CHECK_NEAR(k[3], 8, 1e-12);
    sd_free(&s);
}

static void test_errors_name_line_and_column(void)
{
    EXPECT_ERROR(HEAD "sphere { material m radius -1 }\n", 3, 28, "radius must be");
    EXPECT_ERROR(HEAD "sphere { material x radius 1 }\n", 3, 19, "no material named 'x'");
    EXPECT_ERROR(HEAD "sphere { radius 1 }\n", 3, 1, "sphere has no material");
    EXPECT_ERROR(HEAD "box { material m min 0 0 0 max 1 0 1 }\n", 3, 38, "axis y");
    EXPECT_ERROR(HEAD "triangle { material m v 0 0 0 v 1 1 1 v 2 2 2 }\n", 3, 47, "degenerate");
    EXPECT_ERROR(HEAD "resolution 2000 10\n", 3, 12, "width must be 1..1024");
    EXPECT_ERROR(HEAD "camera { eye 0 0 0 look_at 0 0 0 }\n", 3, 34, "same point");
    EXPECT_ERROR(HEAD "camera { up 0 0 1 }\n", 3, 19, "parallel");
    EXPECT_ERROR(HEAD "frobnicate 3\n", 3, 1, "unknown statement 'frobnicate'");
    EXPECT_ERROR(HEAD "cluster a { box { material m min 0 0 0 max 1 1 1 }\n", 4, 1,
                 "end of file inside cluster 'a'");
    EXPECT_ERROR(HEAD "sphere { material m radius 1x }\n", 3, 28, "'1x' is not a number");
    /* 16 lights of the three kinds pass, the 17th is refused naming the limit */
    EXPECT_ERROR(HEAD LIGHTS5 LIGHTS5 LIGHTS5 "light point { position 0 5 0 }\n", 18, 1,
                 "more than SCN_MAX_LIGHTS (16) lights");
    EXPECT_ERROR(HEAD "material m { }\n", 3, 10, "a second material named 'm'");
    EXPECT_ERROR(HEAD "material g { src 0.7 trc 0.5 }\n", 3, 30, "src + trc");
    EXPECT_ERROR(HEAD "map t colour { size 2 2 texels 1 1 1 }\n", 3, 38, "3 texel values, 12");
    EXPECT_ERROR(HEAD "map t bump { size 1 1 texels 0.5 }\nmaterial n { colour_map t }\n", 4,
                 25, "not a colour map");
    EXPECT_ERROR(HEAD "map t colour { image \"missing.png\" }\n", 3, 22, "missing.png");
    EXPECT_ERROR(HEAD "cluster a { key 3 { } key 2 { } }\n", 3, 27, "must rise");
    EXPECT_ERROR(HEAD "light spot { position 0 0 0 direction 0 -1 0 }\n", 3, 46,
                 "needs a cone");
    EXPECT_ERROR(HEAD "density { material m threshold 1 }\n", 3, 34, "at least one component");
    EXPECT_ERROR(HEAD "sphere { material m radius 1 } \"open\n", 3, 32, "string not closed");
    EXPECT_ERROR("material m { }\nsphere { material m radius 1 }\n", 3, 1, "no light");
    /* lengths to SCN_MAX_COORD (1e8), a cluster's matrix entries and scales
     * to SCN_MAX_SCALE (1e8), other values without a unit to SCN_MAX_FACTOR */
    EXPECT_ERROR(HEAD "sphere { material m centre 2e8 0 0 radius 1 }\n", 3, 28,
                 "centre must be -1e+08..1e+08, not 2e8");
    EXPECT_ERROR(HEAD "cluster c { translate 0 -1.5e8 0 }\n", 3, 25,
                 "translate must be -1e+08..1e+08, not -1.5e8");
    EXPECT_ERROR(HEAD "cluster c { matrix 2e9 0 0 0 0 1 0 0 0 0 1 0 }\n", 3, 20,
                 "matrix entry must be -1e+08..1e+08, not 2e9");
    EXPECT_ERROR(HEAD "cluster c { matrix 1 0 0 2e8 0 1 0 0 0 0 1 0 }\n", 3, 26,
                 "matrix translation must be -1e+08..1e+08, not 2e8");
    EXPECT_ERROR(HEAD "cluster c { scale 1e5 scale 1e4 }\n", 3, 33,
                 "the combined transform has an entry beyond 1e+08");
    EXPECT_ERROR(HEAD "triangle { material m v 0 0 0 v 1 0 0 v 0 1 0 uv 2000 0 }\n", 3, 50,
                 "u must be -1000..1000, not 2000");
}

/* cylinder and cone: their values as NFF's c (base, radius, apex,
 * radius), capped unless open, a cone's apex_radius 0 unless given; what
 * is wrong refused by name. */
static void test_cylinder_and_cone(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    int rc = sd_parse_text("t.scn",
                           HEAD "cylinder { material m base 0 0 0 apex 0 2 0 radius 0.5 }\n"
                           "cone { material m base 1 0 0 base_radius 0.4 apex 1 1 0 open }\n"
                           "cone { material m base 2 0 0 base_radius 0.2 apex 2 1 0 "
                           "apex_radius 0.3 }\n", &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc != 0) {
        check_fail(__FILE__, __LINE__, err);
        return;
    }
    static const double want[3][SCN_CONE_VALUES] = {
        {0, 0, 0, 0.5, 0, 2, 0, 0.5}, {1, 0, 0, 0.4, 1, 1, 0, 0}, {2, 0, 0, 0.2, 2, 1, 0, 0.3}};
    CHECK_EQ_INT(s.n_prims, 3);
    for (int p = 0; p < 3 && p < s.n_prims; p++) {
        CHECK_EQ_INT(s.prims[p].kind, SCN_PRIM_CONE);
        CHECK_EQ_INT(s.prims[p].capped, p == 1 ? SCN_CONE_OPEN : SCN_CONE_CAPPED);
        for (int k = 0; k < SCN_CONE_VALUES; k++)
            CHECK_NEAR(s.prims[p].v[k], want[p][k], 0);
    }
    sd_free(&s);
    EXPECT_ERROR(HEAD "cylinder { material m base 0 0 0 apex 0 1 0 }\n", 3, 45, "needs a radius");
    EXPECT_ERROR(HEAD "cone { material m base 0 0 0 apex 0 1 0 }\n", 3, 41,
                 "needs a base_radius");
    EXPECT_ERROR(HEAD "cone { material m base 0 0 0 base_radius 1 }\n", 3, 44,
                 "needs a base and an apex");
    EXPECT_ERROR(HEAD "cylinder { material m base 1 2 3 apex 1 2 3 radius 1 }\n", 3, 54,
                 "a cone of zero height");
    EXPECT_ERROR(HEAD "cone { material m base 0 0 0 base_radius 0 apex 0 1 0 }\n", 3, 55,
                 "radii are both 0");
    EXPECT_ERROR(HEAD "cone { material m base 0 0 0 base_radius -1 apex 0 1 0 }\n", 3, 42,
                 "base_radius must be 0..1e+08");
    EXPECT_ERROR(HEAD "cylinder { material m base 0 0 0 apex 0 1 0 radius 1 apex_radius 2 }\n",
                 3, 54, "unknown cylinder property 'apex_radius'");
}

/* A 2x1 binary PPM at path: texels a and b (R, G, B each). */
static int put_ppm2(const char *path, const uint8_t a[3], const uint8_t b[3])
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    fputs("P6\n2 1\n255\n", f);
    fwrite(a, 1, 3, f);
    fwrite(b, 1, 3, f);
    return fclose(f);
}

/* Normal and attribute maps: the compiled bytes (a normal normalized and
 * times 127 as signed bytes, from text -1..1 or an image's 2c/255 - 1; an
 * attribute's value times 255), the material statements, and every
 * mistake refused by name. */
static void test_normal_and_attribute_maps(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    int rc = sd_parse_text("t.scn",
                           HEAD "map n normal { size 2 1 texels 0 0 1  0.3 0 0.4 repeat 2 3 }\n"
                                "map a attribute { size 1 2 texels 0.4 1 }\n"
                                "map r normal { size 1 1 texels 0.0472440945 0 0.992125984 }\n"
                                "material k { src 0.5 trc 0.5 normal_map n dic_map a drc_map a "
                                "src_map a trc_map a }\nsphere { material k radius 1 }\n",
                           &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc) {
        printf("  %s\n", err);
        return;
    }
    CHECK_EQ_INT(s.n_maps, 3);
    CHECK_EQ_INT(s.maps[0].kind, SCN_MAP_NORMAL);
    /* bytes of unit length within their rounding are kept: 6/127 0
     * 126/127 is 6 0 126 (renormalized it would be 6 0 127) */
    static const uint8_t want_r[3] = {6, 0, 126};
    CHECK(memcmp(s.maps[2].texels, want_r, 3) == 0);
    /* (0 0 1) -> 0 0 127; (0.3 0 0.4) -> (0.6 0 0.8) * 127 = 76.2, 0, 101.6 */
    static const uint8_t want_n[6] = {0, 0, 127, 76, 0, 102};
    CHECK(memcmp(s.maps[0].texels, want_n, 6) == 0);
    CHECK_NEAR(s.maps[0].bump_depth, 0, 0);
    CHECK_EQ_INT(s.maps[1].kind, SCN_MAP_ATTRIBUTE);
    CHECK_EQ_INT(s.maps[1].texels[0], 102);
    CHECK_EQ_INT(s.maps[1].texels[1], 255);
    const struct sd_material *k = &s.materials[1];
    CHECK_EQ_INT(k->normal_map, 0);
    CHECK_EQ_INT(k->dic_map + k->drc_map + k->src_map + k->trc_map, 4);
    CHECK_EQ_INT(k->bump_map, -1);
    CHECK_EQ_INT(k->colour_map, -1);
    /* written as text (sd_write_text) and read back: the same bytes, maps */
    char *written = NULL;
    size_t wlen = 0;
    FILE *w = open_memstream(&written, &wlen);
    CHECK(w && sd_write_text(&s, NULL, w) == 0);
    if (w)
        fclose(w);
    struct sd_scene back;
    rc = written ? sd_parse_text("w.scn", written, &back, err, sizeof err) : -1;
    CHECK_EQ_INT(rc, 0);
    if (rc == 0) {
        CHECK(back.n_maps == 3 && back.maps[0].kind == SCN_MAP_NORMAL &&
              memcmp(back.maps[0].texels, want_n, 6) == 0 && back.maps[1].texels[0] == 102 &&
              memcmp(back.maps[2].texels, want_r, 3) == 0);
        CHECK(back.materials[1].normal_map == 0 && back.materials[1].trc_map == 1 &&
              back.materials[1].dic_map == 1);
        sd_free(&back);
    }
    free(written);
    sd_free(&s);

    /* from an image: the usual encoding; 128 128 255 is the flat normal */
    char dir[] = "/tmp/links1-maps-test.XXXXXX", path[128], text[512], scn[128];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/n.ppm", dir);
    snprintf(scn, sizeof scn, "%s/t.scn", dir); /* the image lies beside it */
    static const uint8_t flat[3] = {128, 128, 255}, left[3] = {0, 128, 255},
                         inward[3] = {128, 128, 100};
    CHECK_EQ_INT(put_ppm2(path, flat, left), 0);
    snprintf(text, sizeof text,
             HEAD "map n normal { image \"n.ppm\" }\nsphere { material m radius 1 }\n");
    rc = sd_parse_text(scn, text, &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc == 0) {
        /* flat: (1/255, 1/255, 1) rounds to 0 0 127; left: (-1, 1/255, 1)
         * normalized, -90 0 90 (-90 as the signed byte 166) */
        CHECK(memcmp(s.maps[0].texels, (const uint8_t[6]){0, 0, 127, 166, 0, 90}, 6) == 0);
        sd_free(&s);
    } else {
        printf("  %s\n", err);
    }
    /* a texel whose blue stands for z <= 0 points into the surface */
    CHECK_EQ_INT(put_ppm2(path, flat, inward), 0);
    rc = sd_parse_text(scn, text, &s, err, sizeof err);
    CHECK(rc != 0 && strstr(err, "normal map texel (1, 0) = RGB 128 128 100 does not point out") != NULL);
    if (rc == 0)
        sd_free(&s);
    unlink(path);
    rmdir(dir);

    EXPECT_ERROR(HEAD "map n normal { size 1 1 texels 0 0 -1 }\n", 3, 36,
                 "normal map texel 0 (0 0 -1) does not point out of the surface");
    EXPECT_ERROR(HEAD "map n normal { size 1 1 texels 0 0 0 }\n", 3, 36, "does not point out");
    EXPECT_ERROR(HEAD "map n normal { size 1 1 texels 0 0 2 }\n", 3, 36,
                 "normal map texel component must be -1..1");
    EXPECT_ERROR(HEAD "map n shiny { size 1 1 texels 1 }\n", 3, 7,
                 "map kind must be colour, bump, normal or attribute, not 'shiny'");
    EXPECT_ERROR(HEAD "map n normal { size 1 1 texels 0 0 1 depth 2 }\n", 3, 38,
                 "normal map");
    EXPECT_ERROR(HEAD "map b bump { size 1 1 texels 0.5 }\nmaterial k { normal_map b }\n", 4,
                 25, "normal_map: map 'b' is a bump map, not a normal map");
    EXPECT_ERROR(HEAD "map c colour { size 1 1 texels 1 1 1 }\nmaterial k { src_map c }\n", 4,
                 22, "src_map: map 'c' is a colour map, not an attribute map");
    EXPECT_ERROR(HEAD "map a attribute { size 1 1 texels 1 }\nmaterial k { colour_map a }\n", 4,
                 25, "colour_map: map 'a' is an attribute map, not a colour map");
    EXPECT_ERROR(HEAD "map b bump { size 1 1 texels 0.5 }\nmap n normal { size 1 1 texels 0 0 1 }\n"
                      "material k { bump_map b normal_map n }\n",
                 5, 36, "material 'k' has both a bump map and a normal map");
}

/* A scene whose lengths reach SCN_MAX_COORD parses. */
static void test_length_limit_accepted(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    CHECK_EQ_INT(sd_parse_text("t.scn",
                               "camera { eye 0 0 -1e8 look_at 0 0 0 }\n" HEAD
                               "cluster c { scale 1000 translate 1e8 0 0\n"
                               "  sphere { material m centre 0 -1e8 0 radius 1e8 } }\n",
                               &s, err, sizeof err),
                 0);
    CHECK_NEAR(s.prims[0].v[3], 1e8, 0);
    sd_free(&s);
    /* a cluster's scale and matrix to SCN_MAX_SCALE, down to 1e-6 and a
     * radius of 1e-12 (SCN_MIN_SIZE): invertible against its rows' lengths */
    CHECK_EQ_INT(sd_parse_text("t.scn",
                               HEAD "cluster c { scale 1e6 scale 100\n"
                               "  cluster d { matrix 1e-6 0 0 0  0 1e-6 0 0  0 0 1e-6 0\n"
                               "    sphere { material m radius 1e-12 } } }\n",
                               &s, err, sizeof err),
                 0);
    CHECK_NEAR(s.prims[0].v[3], 1e-12, 0);
    sd_free(&s);
}

static void test_deep_nesting_refused(void)
{
    char text[4096] = HEAD;
    for (int i = 0; i <= SCN_MAX_CLUSTER_NESTING; i++)
        strcat(text, "cluster c { ");
    struct sd_scene s;
    char err[SD_ERR_MAX];
    CHECK(sd_parse_text("t.scn", text, &s, err, sizeof err) != 0);
    CHECK(strstr(err, "nested deeper than 32") != NULL);
}

/* Keys of the camera and the lights: a value a key leaves out keeps the
 * one before it, sd_view_at interpolates as the renderer does, and bad
 * keys are refused where they stand. */
static void test_view_keys(void)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    int rc = sd_parse_text("t.scn",
                           "camera { eye 0 1 -5 look_at 0 0 0 fov 60\n"
                           "  key 0 { } key 4 { eye 4 1 -5 fov 90 } key 6 { look_at 1 0 0 } }\n"
                           "light spot { position 0 5 0 at 0 0 0 cone 20 falloff 10\n"
                           "  key 2 { position 2 5 0 } }\n"
                           "material m { } sphere { material m radius 1 }\n",
                           &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc) {
        printf("  %s\n", err);
        return;
    }
    CHECK_EQ_INT(s.n_view_keys, 4);
    if (s.n_view_keys == 4) {
        /* key 6 keeps key 4's eye and fov; the spot keeps aiming at its 'at' */
        CHECK_NEAR(s.view_keys[2].eye[0], 4, 0);
        CHECK_NEAR(s.view_keys[2].fov, 90, 0);
        CHECK_NEAR(s.view_keys[3].direction[0], -2, 0);
        CHECK_NEAR(s.view_keys[3].direction[1], -5, 0);
        CHECK_EQ_INT(s.view_keys[3].target, 0);
    }
    struct sd_view v;
    struct sd_light l[SCN_MAX_LIGHTS];
    sd_view_at(&s, 2, &v, l); /* halfway from key 0 to key 4 */
    CHECK_NEAR(v.eye[0], 2, 1e-12);
    CHECK_NEAR(tan(v.fov * 3.14159265358979323846 / 360), (tan(3.14159265358979323846 / 6) + 1) / 2,
               1e-12);
    CHECK_NEAR(l[0].position[0], 2, 1e-12); /* at its key */
    sd_view_at(&s, 9, &v, l);                /* after the last key: held */
    CHECK_NEAR(v.look_at[0], 1, 1e-12);
    sd_free(&s);

    EXPECT_ERROR(HEAD "camera { key 3 { } key 3 { } }\n", 3, 24, "key frames of the camera must rise");
    EXPECT_ERROR(HEAD "camera { key 0 { fov 200 } }\n", 3, 22, "fov (degrees) must be 0.1..170");
    EXPECT_ERROR(HEAD "camera { key 0 { } eye 0 0 -9 }\n", 3, 20,
                 "the camera's own 'eye' must come before its keys");
    EXPECT_ERROR(HEAD "camera { key 0 { look_at 0 0 -5 } }\n", 3, 33,
                 "camera key at frame 0: eye and look_at are the same point");
    /* between keys the eye passes through look_at at frame 3 */
    EXPECT_ERROR(HEAD "camera { eye 0 0 -5 look_at 0 0 5 key 0 { } key 9 { eye 0 0 15 look_at 0 0 -5 } }\n",
                 3, 79, "at frame 3 between them eye and look_at are (nearly) the same point");
    EXPECT_ERROR(HEAD "light spot { position 0 5 0 direction 0 -1 0 cone 20 key 4 { cone 80 falloff 20 } }\n",
                 3, 81, "light key at frame 4: cone + falloff is 100 degrees, more than 89");
    EXPECT_ERROR(HEAD "light spot { position 0 5 0 direction 0 -1 0 cone 20 key 4 { cone 95 } }\n",
                 3, 67, "cone (degrees) must be 0..89");
    EXPECT_ERROR(HEAD "light point { position 0 5 0 key 2 { } key 1 { } }\n", 3, 44,
                 "key frames of a light must rise");
    EXPECT_ERROR(HEAD "light parallel { direction 0 -1 0 key 0 { } key 8 { direction 0 1 0.01 } }\n",
                 3, 72, "their directions are nearly opposite");
    EXPECT_ERROR(HEAD "light point { position 0 5 0 key 0 { direction 0 1 0 } }\n", 3, 38,
                 "'direction' is not a property of a point light's key");
}

/* The lexer's fast decimal path gives strtod's double, bit for bit, on
 * every number it takes (signs, zeros, fractions, exponents, 15 digits at
 * 10^+-22), and leaves the rest to strtod. */
static void test_decimal_fast_path_is_strtod(void)
{
    static const char *take[] = {"0", "-0", "+7", "1.", ".5", "-0.000001", "3.14159265358979",
                                 "123456789012345", "0.1e-5", "9e22", "-1E+22", "2.5e-21",
                                 "0.0625", "1e0", "-8.25", "999999999999999e-22"};
    static const char *leave[] = {"1234567890123456", "1e23", "1e-23", "1e", "1e+", "-", ".",
                                  "1.2.3", "inf", "0x10", "1e00022", "12a"};
    int bad = 0, taken = 0;
    char buf[64];
    uint64_t r = 88172645463325252ull;
    for (int i = 0; i < 200000; i++) { /* random digits, point and power */
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        int nd = 1 + (int)(r % 15), dot = (int)((r >> 8) % (uint64_t)(nd + 1)), n = 0;
        if ((r >> 16) & 1)
            buf[n++] = '-';
        for (int d = 0; d < nd; d++) {
            if (d == dot && d > 0)
                buf[n++] = '.';
            buf[n++] = (char)('0' + (r >> (20 + 2 * d % 40)) % 10);
        }
        if ((r >> 60) & 1)
            n += snprintf(buf + n, sizeof buf - (size_t)n, "e%d", (int)((r >> 50) % 41) - 20);
        buf[n] = 0;
        double v;
        if (lex_decimal(buf, &v)) {
            double w = strtod(buf, NULL);
            taken++;
            bad += memcmp(&v, &w, sizeof v) != 0;
        }
    }
    CHECK(taken > 190000);
    for (size_t i = 0; i < sizeof take / sizeof take[0]; i++) {
        double v = 1, w = strtod(take[i], NULL);
        CHECK(lex_decimal(take[i], &v));
        bad += memcmp(&v, &w, sizeof v) != 0;
    }
    for (size_t i = 0; i < sizeof leave / sizeof leave[0]; i++) {
        double v;
        CHECK(!lex_decimal(leave[i], &v));
    }
    CHECK_EQ_INT(bad, 0);
}

int main(void)
{
    RUN(test_decimal_fast_path_is_strtod);
    RUN(test_minimal_scene_and_defaults);
    RUN(test_refraction_option);
    RUN(test_shading_defaults_and_options);
    RUN(test_density_steps_option);
    RUN(test_aa_option);
    RUN(test_transforms_compose_in_order);
    RUN(test_keyframe_interpolation);
    RUN(test_errors_name_line_and_column);
    RUN(test_length_limit_accepted);
    RUN(test_deep_nesting_refused);
    RUN(test_view_keys);
    RUN(test_normal_and_attribute_maps);
    RUN(test_cylinder_and_cone);
    return check_exit();
}
