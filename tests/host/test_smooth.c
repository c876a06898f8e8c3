/* test_smooth.c: smooth triangles (`model { smooth on }`, beyond the
 * paper; docs/import.md), built once per arithmetic.
 *   - a model with vertex normals (tests/models/ball.obj): every triangle
 *     carries them, the compiled form holds one NORMALS record (40 bytes)
 *     a triangle, and the image differs from the flat one: the facets'
 *     bends of brightness
 *     inside the ball are mostly gone;
 *   - a model without normals (tests/models/cube.obj) under smooth on
 *     stays flat, counted for the warning, with no NORMALS section and an
 *     image bit for bit the flat one;
 *   - a triangle's `n` entries in the text form: written and read back
 *     (made unit length), all three or none, a zero normal refused;
 *   - the loader refuses a normal that is not unit length, a record naming
 *     a primitive that is not a triangle, and records out of order;
 *   - a smooth triangle holds its vertex normals (no pointer): the RC's
 *     relocation of a blob moves no triangle's bytes, and the copy renders
 *     the same image.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_import.h"
#include "proto/wordsum.h"
#include "proto/scene_format.h"
#include "proto/wire.h"
#include "render/blob.h"
#include "render/render.h"
#include "render/scene_load.h"
#include "render/vec3.h"
#include "tests/check.h"

#define ARENA_BYTES (16u * 1024u * 1024u)
#define W 64
#define H 64

static uint8_t *arena_mem;

static const char *scene_text(const char *model, int smooth)
{
    static char t[1024];
    snprintf(t, sizeof t,
             "camera { eye 0 0 -3.2  look_at 0 0 0  up 0 1 0  fov 45 }\n"
             "resolution %d %d\nbackground 0 0 0\n"
             /* the ball's dark side keeps its ambient, so black is the
              * background alone */
             "options { ambient_shadowed off }\n"
             "light parallel { colour 1 1 1  direction 0.4 -0.5 1 }\n"
             "material m { colour 0.9 0.8 0.7  dic 0.1 drc 0.9 }\n"
             "cluster c { rotate 0 10 0  model { file \"%s\"  material m  smooth %s } }\n",
             W, H, model, smooth ? "on" : "off");
    return t;
}

/* Parses and compiles text (named in tests/models/). */
static uint8_t *compile(const char *text, size_t *len)
{
    struct sd_scene s;
    char err[SD_ERR_MAX] = "";
    uint8_t *buf = NULL;
    if (sd_parse_text("tests/models/smooth.scn", text, &s, err, sizeof err) != 0) {
        printf("  parse: %s\n", err);
        return NULL;
    }
    if (sd_compile(&s, &buf, len, err, sizeof err) != 0)
        printf("  compile: %s\n", err);
    sd_free(&s);
    return buf;
}

/* Records of section kind in a compiled scene (0 when absent). */
static uint32_t section_count(const uint8_t *b, uint32_t kind, uint32_t *offset)
{
    uint16_t n = wire_get_u16(b + SCN_HDR_SECTIONS);
    for (uint16_t i = 0; i < n; i++) {
        const uint8_t *e = b + SCN_HEADER_SIZE + i * SCN_SECENT_SIZE;
        if (wire_get_u32(e + SCN_SECENT_KIND) == kind) {
            if (offset)
                *offset = wire_get_u32(e + SCN_SECENT_OFFSET);
            return wire_get_u32(e + SCN_SECENT_COUNT);
        }
    }
    return 0;
}

/* The image of a compiled scene, or NULL. */
static rgb8_t *render(const uint8_t *buf, size_t len)
{
    arena_t arena;
    arena_init(&arena, arena_mem, ARENA_BYTES);
    scene_t scene;
    scene_load_error_t e;
    render_frame_t *f;
    if (scene_load(buf, len, &arena, &scene, &e) != SCENE_LOAD_OK) {
        printf("  load: %s\n", e.message);
        return NULL;
    }
    if (render_prepare(&scene, 0, &arena, &f) != RENDER_OK)
        return NULL;
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    rgb8_t *img = malloc(W * H * sizeof *img);
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++)
            img[y * W + x] = render_pixel(&ctx, x, y);
    return img;
}

/* Bends of brightness well inside the ball (no background within 3
 * pixels): the sum of |second differences| along rows and columns.  The
 * facets of a flat ball give a bend at every edge; smooth shading varies
 * gently. */
static int is_bg(const rgb8_t *img, int x, int y)
{
    const rgb8_t *p = &img[y * W + x];
    return (p->r | p->g | p->b) == 0;
}

static int lum(const rgb8_t *img, int x, int y)
{
    const rgb8_t *p = &img[y * W + x];
    return p->r + p->g + p->b;
}

static long bends(const rgb8_t *img)
{
    long n = 0;
    for (int y = 4; y < H - 4; y++)
        for (int x = 4; x < W - 4; x++) {
            int inside = 1;
            for (int dy = -3; dy <= 3 && inside; dy++)
                for (int dx = -3; dx <= 3 && inside; dx++)
                    inside = !is_bg(img, x + dx, y + dy);
            if (inside)
                n += labs((long)lum(img, x - 1, y) - 2 * lum(img, x, y) + lum(img, x + 1, y)) +
                     labs((long)lum(img, x, y - 1) - 2 * lum(img, x, y) + lum(img, x, y + 1));
        }
    return n;
}

static int differing(const rgb8_t *a, const rgb8_t *b)
{
    int n = 0;
    for (int i = 0; i < W * H; i++)
        n += memcmp(&a[i], &b[i], sizeof *a) != 0;
    return n;
}

static void test_smooth_ball(void)
{
    size_t lf, ls;
    uint8_t *flat = compile(scene_text("ball.obj", 0), &lf);
    uint8_t *smooth = compile(scene_text("ball.obj", 1), &ls);
    CHECK(flat && smooth);
    if (!flat || !smooth)
        return;
    uint32_t n_prims = section_count(smooth, SCN_SEC_PRIMS, NULL);
    CHECK_EQ_INT((int)section_count(flat, SCN_SEC_NORMALS, NULL), 0);
    CHECK_EQ_INT((int)section_count(smooth, SCN_SEC_NORMALS, NULL), 12 * 8 * 2 - 2 * 12);
    CHECK_EQ_INT((int)(ls - lf), (int)(SCN_NORMALS_SIZE * (12 * 8 * 2 - 2 * 12) + SCN_SECENT_SIZE));
    CHECK(n_prims >= 12 * 8 * 2 - 2 * 12);
    rgb8_t *a = render(flat, lf), *b = render(smooth, ls);
    CHECK(a && b);
    if (a && b) {
        int diff = differing(a, b);
        long bf = bends(a), bs = bends(b);
        printf("  ball: %d of %d pixels differ; bends of brightness inside: flat %ld, "
               "smooth %ld\n", diff, W * H, bf, bs);
        CHECK(diff > W * H / 8);
        CHECK(bs * 3 < bf);
        /* the silhouette is the flat face's: background where flat has it */
        int bg = 0;
        for (int i = 0; i < W * H; i++)
            bg += (a[i].r | a[i].g | a[i].b) == 0 && (b[i].r | b[i].g | b[i].b) != 0;
        CHECK_EQ_INT(bg, 0);
    }
    free(a), free(b), free(flat), free(smooth);
}

/* Every pixel of a blob's frame. */
static rgb8_t *render_blob_image(const render_blob_t *b)
{
    render_ctx_t ctx;
    render_ctx_init(&ctx, b->frame);
    rgb8_t *img = malloc(W * H * sizeof *img);
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++)
            img[y * W + x] = render_pixel(&ctx, x, y);
    return img;
}

static void test_relocate_smooth_normals(void)
{
    size_t len, need;
    uint8_t *buf = compile(scene_text("ball.obj", 1), &len);
    render_blob_error_t err;
    CHECK(buf && render_blob_bytes(buf, len, &need, &err) == RENDER_BLOB_OK);
    if (!buf)
        return;
    size_t size = (need + RENDER_RELOCATE_ALIGN - 1) / RENDER_RELOCATE_ALIGN * RENDER_RELOCATE_ALIGN;
    uint8_t *a = aligned_alloc(RENDER_RELOCATE_ALIGN, size);
    uint8_t *b = aligned_alloc(RENDER_RELOCATE_ALIGN, size);
    render_blob_t *ab, *bb;
    CHECK_EQ_INT(render_blob_build(buf, len, 0, a, size, "test memory", &ab, &err), RENDER_BLOB_OK);
    const render_frame_t *f = ab->frame;
    uint32_t smooth = 0;
    while (smooth < f->prim_count && !f->prims[smooth].smooth)
        smooth++;
    CHECK(smooth < f->prim_count);
    if (smooth == f->prim_count)
        goto out;
    /* moved whole: the same image from the copy, and every triangle's
     * bytes as the DM wrote them (a triangle holds no pointer) */
    memcpy(b, a, ab->bytes);
    CHECK_EQ_INT(render_blob_relocate(b, size, &bb, &err), RENDER_BLOB_OK);
    rgb8_t *ia = render_blob_image(ab), *ib = render_blob_image(bb);
    CHECK(memcmp(ia, ib, W * H * sizeof *ia) == 0);
    free(ia), free(ib);
    uint32_t moved = 0;
    for (uint32_t i = 0; i < f->prim_count; i++)
        if (f->prims[i].kind == SCENE_PRIM_TRIANGLE &&
            memcmp(&f->prims[i], &bb->frame->prims[i], sizeof f->prims[i]) != 0)
            moved++;
    CHECK_EQ_INT(moved, 0);
    /* the normals held are the eye-space unit normals */
    for (int k = 0; k < 3; k++)
        CHECK(fabs(num_to_double(vec3_length(f->prims[smooth].normals.n[k])) - 1.0) < 1e-3);
out:
    free(a), free(b), free(buf);
}

static void test_no_normals_stays_flat(void)
{
    struct model m;
    char err[SD_ERR_MAX] = "";
    CHECK(model_load("tests/models/cube.obj", &m, err, sizeof err) == 0);
    struct sd_scene s;
    memset(&s, 0, sizeof s);
    sd_view_defaults(&s.view);
    s.clusters = calloc(1, sizeof *s.clusters);
    s.clusters[0].parent = -1;
    s.clusters[0].m[0] = s.clusters[0].m[5] = s.clusters[0].m[10] = 1;
    s.n_clusters = 1;
    static struct import_result r;
    struct import_opts o = {0, -1, 0, "--fit", 1, NULL};
    CHECK(scene_import_model(&s, 0, &m, "tests/models/", &o, &r, err, sizeof err) == 0);
    CHECK(r.triangles > 0);
    CHECK_EQ_INT(r.flat, r.triangles);
    CHECK_EQ_INT(r.smooth, 0);
    sd_free(&s), model_free(&m);
    size_t lf, ls;
    uint8_t *flat = compile(scene_text("cube.obj", 0), &lf);
    uint8_t *smooth = compile(scene_text("cube.obj", 1), &ls);
    CHECK(flat && smooth);
    if (!flat || !smooth)
        return;
    CHECK_EQ_INT((int)section_count(smooth, SCN_SEC_NORMALS, NULL), 0);
    CHECK(lf == ls && memcmp(flat, smooth, lf) == 0);
    rgb8_t *a = render(flat, lf), *b = render(smooth, ls);
    CHECK(a && b && differing(a, b) == 0);
    free(a), free(b), free(flat), free(smooth);
}

static void test_text_normals(void)
{
    const char *head = "light point { position 0 5 -5 }\nmaterial m { }\n";
    char text[512];
    snprintf(text, sizeof text,
             "%striangle { material m  v 0 0 0  v 1 0 0  v 0 1 0  n 0 0 -2  n 0 0.6 -0.8  "
             "n 0.6 0 -0.8 }\n", head);
    struct sd_scene s, back;
    char err[SD_ERR_MAX] = "";
    CHECK(sd_parse_text("t.scn", text, &s, err, sizeof err) == 0);
    if (err[0])
        printf("  %s\n", err);
    CHECK(s.n_prims == 1 && s.prims[0].smooth);
    CHECK_NEAR(s.prims[0].n[2], -1, 1e-12); /* made unit length */
    char *out = NULL;
    size_t olen = 0;
    FILE *f = open_memstream(&out, &olen);
    CHECK(sd_write_text(&s, NULL, f) == 0);
    fclose(f);
    CHECK(sd_parse_text("t2.scn", out, &back, err, sizeof err) == 0);
    CHECK(back.n_prims == 1 && back.prims[0].smooth);
    for (int i = 0; i < 9; i++)
        CHECK_NEAR(back.prims[0].n[i], s.prims[0].n[i], 1e-12);
    sd_free(&s), sd_free(&back), free(out);
    snprintf(text, sizeof text, "%striangle { material m  v 0 0 0  v 1 0 0  v 0 1 0  n 0 0 1 }\n",
             head);
    CHECK(sd_parse_text("t.scn", text, &s, err, sizeof err) != 0);
    CHECK(strstr(err, "1 vertex normals, needs 0 (flat) or 3") != NULL);
    snprintf(text, sizeof text,
             "%striangle { material m  v 0 0 0  v 1 0 0  v 0 1 0  n 0 0 1  n 0 0 0  n 0 0 1 }\n",
             head);
    CHECK(sd_parse_text("t.scn", text, &s, err, sizeof err) != 0);
    CHECK(strstr(err, "no direction") != NULL);
}

/* Loads buf after edit(rec) of its first NORMALS record, with the word sum
 * made good again; the loader's message. */
static const char *load_edited(const uint8_t *buf, size_t len, int what)
{
    static scene_load_error_t e;
    uint8_t *b = malloc(len);
    memcpy(b, buf, len);
    uint32_t off = 0;
    section_count(b, SCN_SEC_NORMALS, &off);
    uint8_t *rec = b + off;
    if (what == 0)
        wire_put_f32(rec + SCN_NORMALS_N + 4, 2.0f); /* n0 not unit */
    else if (what == 1) /* the last prim: the floor box */
        wire_put_u32(rec + SCN_NORMALS_PRIM, section_count(b, SCN_SEC_PRIMS, NULL) - 1);
    else
        wire_put_u32(rec + SCN_NORMALS_SIZE + SCN_NORMALS_PRIM,
                     wire_get_u32(rec + SCN_NORMALS_PRIM)); /* the next names the same */
    wire_put_u32(b + SCN_HDR_SUM, wordsum(b + SCN_SUM_START, len - SCN_SUM_START));
    arena_t arena;
    arena_init(&arena, arena_mem, ARENA_BYTES);
    scene_t scene;
    scene_load_status_t st = scene_load(b, len, &arena, &scene, &e);
    free(b);
    return st == SCENE_LOAD_OK ? "" : e.message;
}

static void test_loader_refuses_bad_normals(void)
{
    char text[2048];
    snprintf(text, sizeof text, "%sbox { material m  min -2 -2 -2  max 2 -1.5 2 }\n",
             scene_text("ball.obj", 1));
    size_t len;
    uint8_t *buf = compile(text, &len);
    CHECK(buf != NULL);
    if (!buf)
        return;
    CHECK(strstr(load_edited(buf, len, 0), "not of unit length") != NULL);
    CHECK(strstr(load_edited(buf, len, 1), "not a triangle") != NULL);
    CHECK(strstr(load_edited(buf, len, 2), "not above the previous") != NULL);
    free(buf);
}

int main(void)
{
    arena_mem = malloc(ARENA_BYTES);
    RUN(test_smooth_ball);
    RUN(test_relocate_smooth_normals);
    RUN(test_no_normals_stays_flat);
    RUN(test_text_normals);
    RUN(test_loader_refuses_bad_normals);
    free(arena_mem);
    return check_exit();
}
