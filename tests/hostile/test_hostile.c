/* test_hostile.c: every hostile class refused on the host with an error
 * naming the problem: the compiled ones (hostile.c) by the loader or the
 * DM's frame build (render_blob_build, the code the board runs), the text
 * ones by the parser and compiler. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/image/image_io.h"
#include "host-tools/scene/scene_desc.h"
#include "render/blob.h"
#include "render/scene_load.h"
#include "tests/hostile/hostile.h"

/* The block the host test builds frames in: room for every edit of the
 * base, not for the big scene.  Its refusal names the board's block, as
 * the DM's does. */
#define TEST_LIMIT_NAME "LINKS1_IMSU_PAIR_BLOCK"

static int failures;

/* One "PASS name" or "FAIL name: why" line (tests/run.sh counts them). */
static void verdict(int ok, const char *name, const char *fmt, ...)
{
    if (ok) {
        printf("PASS %s\n", name);
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    printf("FAIL %s: ", name);
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
    failures++;
}

static uint8_t *block;
static size_t block_size;

static void check_base(const struct hostile_scene *base)
{
    arena_t arena;
    arena_init(&arena, block, block_size);
    scene_t s;
    scene_load_error_t err;
    int ok = scene_load(base->buf, base->len, &arena, &s, &err) == SCENE_LOAD_OK;
    verdict(ok, "hostile_base_loads", "%s", err.message);
    if (!ok)
        return;
    /* the records the classes edit are where they expect them */
    verdict(s.cluster_count == 34 && s.clusters[32].parent == 31 && s.clusters[33].parent == 0 &&
              s.key_count == 2 && s.map_count == 1 && s.prim_count == 5 &&
              s.prims[0].kind == SCENE_PRIM_BOX && s.prims[1].kind == SCENE_PRIM_TRIANGLE &&
              s.prims[3].kind == SCENE_PRIM_ELLIPSOID,
          "hostile_base_shape", "%u clusters, %u keys, %u maps, %u prims",
          (unsigned)s.cluster_count, (unsigned)s.key_count, (unsigned)s.map_count,
          (unsigned)s.prim_count);
    render_blob_t *blob;
    render_blob_error_t berr;
    verdict(render_blob_build(base->buf, base->len, 1, block, block_size, TEST_LIMIT_NAME, &blob,
                            &berr) == RENDER_BLOB_OK,
          "hostile_base_builds", "%s", berr.message);
}

static void check_class(const struct hostile_scene *base, const struct hostile_class *c)
{
    char name[64];
    snprintf(name, sizeof name, "hostile_%s", c->name);
    struct hostile_scene h = {malloc(base->len), base->len};
    if (!h.buf)
        abort();
    memcpy(h.buf, base->buf, base->len);
    if (c->make(&h) != 0) {
        verdict(0, name, "the base scene lacks the record this class edits");
        free(h.buf);
        return;
    }
    render_blob_t *blob;
    render_blob_error_t err;
    render_blob_status_t st =
        render_blob_build(h.buf, h.len, 0, block, block_size, TEST_LIMIT_NAME, &blob, &err);
    verdict(st != RENDER_BLOB_OK && strstr(err.message, c->expect), name,
          "status %d, message \"%s\", want it to contain \"%s\"", (int)st, err.message,
          c->expect);
    free(h.buf);
}

#define HEAD                                                                                \
    "camera { eye 0 2 -6 look_at 0 0 0 up 0 1 0 fov 50 }\n"                                 \
    "light point { position 3 6 -4 }\n"                                                     \
    "material m { colour 1 1 1 }\nuse m\n"
#define BALL "sphere { radius 1 }\n"
#define LIGHTS4                                                                             \
    "light point { position 1 1 1 }\nlight parallel { direction 0 -1 0 }\n"                  \
    "light spot { position 0 4 0 at 0 0 0 cone 20 }\nlight point { position -1 1 1 }\n"

struct text_case {
    const char *name, *text, *expect;
};

static const struct text_case text_cases[] = {
    {"text_nonfinite", HEAD "sphere { radius 1e999 }\n", "'1e999' is not a finite number"},
    {"text_nan", HEAD "sphere { radius nan }\n", "expected a number (radius), found 'nan'"},
    {"text_over_lights", /* HEAD's light and 16 more: 17 */
     HEAD LIGHTS4 LIGHTS4 LIGHTS4 LIGHTS4 BALL, "more than SCN_MAX_LIGHTS (16) lights"},
    {"text_over_size", HEAD "resolution 2000 10\n" BALL, "width must be 1..1024, not 2000"},
    {"text_over_depth", HEAD "options { max_depth 17 }\n" BALL, "max_depth must be 0..16"},
    {"text_over_frames", HEAD "animation { frames 100001 }\n" BALL,
     "frames must be 1..100000, not 100001"},
    {"text_zero_box", HEAD "box { min 0 0 0 max 1 0 1 }\n", "box max must exceed min"},
    {"text_degenerate_triangle", HEAD "triangle { v 0 0 0 v 1 0 0 v 2 0 0 }\n",
     "degenerate triangle"},
    {"text_sliver_triangle", HEAD "triangle { v 0 0 0 v 1 0 0 v 0.5 0.00001 0 }\n",
     "a sliver whose smallest height is 1e-05, under SCN_MIN_TRIANGLE_HEIGHT"},
    {"text_singular_matrix",
     HEAD "cluster a { matrix 1 0 0 0  0 0 0 0  0 0 1 0 " BALL "}\n",
     "matrix is not invertible"},
    {"text_zero_scale", HEAD "cluster a { scale 0 " BALL "}\n", "a scale factor is zero"},
    {"text_zero_key_scale", HEAD "cluster a { key 0 { scale 0 } " BALL "}\n",
     "a scale factor is zero"},
    {"text_map_too_big", HEAD "map t colour { size 1025 1 }\n" BALL,
     "map width must be 1..1024, not 1025"},
};

static void check_nesting_text(void)
{
    char text[4096];
    size_t n = (size_t)snprintf(text, sizeof text, "%s", HEAD);
    for (int i = 0; i < 33; i++)
        n += (size_t)snprintf(text + n, sizeof text - n, "cluster c%d {\n", i);
    n += (size_t)snprintf(text + n, sizeof text - n, BALL);
    for (int i = 0; i < 33; i++)
        n += (size_t)snprintf(text + n, sizeof text - n, "}\n");
    struct sd_scene s;
    char err[SD_ERR_MAX] = "";
    int rc = sd_parse_text("nest.scn", text, &s, err, sizeof err);
    if (rc == 0)
        sd_free(&s);
    verdict(rc != 0 && strstr(err, "clusters nested deeper than 32"), "hostile_text_nesting",
          "rc %d, \"%s\"", rc, err);
}

/* A map image one texel wider than SCN_MAX_MAP_SIDE, refused from its
 * header. */
static void check_map_image_text(void)
{
    char dir[] = "/tmp/links1-hostile.XXXXXX", path[64], scene[64], text[512];
    struct image img = {1025, 2, calloc(1025 * 2, 3)};
    char err[SD_ERR_MAX] = "";
    int rc = -1;
    if (img.rgb && mkdtemp(dir)) {
        snprintf(path, sizeof path, "%s/wide.png", dir);
        snprintf(scene, sizeof scene, "%s/wide.scn", dir);
        snprintf(text, sizeof text, HEAD "map w colour { image \"wide.png\" }\n" BALL);
        struct sd_scene s;
        FILE *png = fopen(path, "wb");
        int written = png && image_write(png, path, &img, 0, err, sizeof err) == 0;
        if (png && fclose(png) != 0)
            written = 0;
        if (written) {
            rc = sd_parse_text(scene, text, &s, err, sizeof err);
            if (rc == 0)
                sd_free(&s);
        }
        remove(path);
        rmdir(dir);
    }
    free(img.rgb);
    verdict(rc != 0 && strstr(err, "1025x2 image is larger than 1024 a side"),
            "hostile_text_map_image_too_big", "rc %d, \"%s\"", rc, err);
}

int main(void)
{
    struct hostile_scene base;
    char err[SD_ERR_MAX];
    if (hostile_base(&base, err, sizeof err) != 0) {
        verdict(0, "hostile_base", "%s", err);
        return 1;
    }
    render_blob_error_t berr;
    if (render_blob_bytes(base.buf, base.len, &block_size, &berr) != RENDER_BLOB_OK) {
        verdict(0, "hostile_base", "%s", berr.message);
        return 1;
    }
    block_size *= 4;
    block = aligned_alloc(RENDER_RELOCATE_ALIGN, (block_size + 63) & ~(size_t)63);
    if (!block)
        abort();
    check_base(&base);
    for (int i = 0; i < hostile_class_count; i++)
        check_class(&base, &hostile_classes[i]);
    for (size_t i = 0; i < sizeof text_cases / sizeof text_cases[0]; i++) {
        const struct text_case *t = &text_cases[i];
        struct sd_scene s;
        char name[64];
        snprintf(name, sizeof name, "hostile_%s", t->name);
        err[0] = 0;
        int rc = sd_parse_text("hostile.scn", t->text, &s, err, sizeof err);
        if (rc == 0) {
            uint8_t *buf = NULL;
            size_t len;
            rc = sd_compile(&s, &buf, &len, err, sizeof err) == 0 ? 0 : -1;
            free(buf);
            sd_free(&s);
        }
        verdict(rc != 0 && strstr(err, t->expect), name, "rc %d, \"%s\", want \"%s\"", rc, err,
              t->expect);
    }
    check_nesting_text();
    check_map_image_text();
    free(block);
    free(base.buf);
    return failures ? 1 : 0;
}
