/* test_blob.c: a scene + frame blob built in one block (the DM's job),
 * copied to another address and relocated (the RC's broadcast), renders
 * exactly as the original even once the original is overwritten and freed;
 * no pointer into the old block survives; pointers outside the blob, blocks
 * too small and corrupt blobs are refused with a message naming why. */
#include "tests/check.h"
#include "proto/scene_format.h"
#include "proto/wire.h"
#include "render/scene_load.h"
#include "tests/host/test_blob_util.h"

#define TB_GARBAGE 0xA5 /* what the original block is overwritten with */

static uint32_t tb_frame_of(const char *name)
{
    return strcmp(name, "anim") == 0 ? 2 : 0; /* half way through its keys */
}

/* Aligned pointer-sized words of block[0..bytes) whose value lies in
 * [lo, lo + span): pointers into that range (or, very unlikely, a number
 * that looks like one). */
static size_t tb_words_into(const void *block, size_t bytes, uintptr_t lo, size_t span)
{
    const uint8_t *b = block;
    size_t n = 0;
    for (size_t at = 0; at + sizeof(uintptr_t) <= bytes; at += sizeof(uintptr_t)) {
        uintptr_t v;
        memcpy(&v, b + at, sizeof v);
        n += v >= lo && v - lo < span;
    }
    return n;
}

/* The forgotten-field test: build in A, copy to B, relocate B, wreck and
 * free A, render every pixel from B.  A pointer render_relocate missed
 * still names A: ASan stops on the read, and without ASan the 0xA5 bytes
 * change the image. */
static void test_relocated_copy_renders_same(void)
{
    for (size_t s = 0; s < TB_SCENE_COUNT; s++) {
        size_t size;
        /* at half resolution (the same objects in view, so the same
         * fields read; full-size renders under ASan cost make test time) */
        render_blob_t *a = tb_blob_div(tb_scenes[s], tb_frame_of(tb_scenes[s]), 2, &size);
        CHECK(a != NULL);
        if (!a)
            continue;
        const render_frame_t *fa = a->frame;
        size_t n = (size_t)fa->width * fa->height;
        rgb8_t *before = tb_render_plain(fa, NULL);

        void *b = tb_block(size);
        memcpy(b, a, a->bytes);
        render_blob_t *rb;
        render_blob_error_t err;
        CHECK_EQ_INT(render_blob_relocate(b, size, &rb, &err), RENDER_BLOB_OK);
        memset(a, TB_GARBAGE, size);
        free(a);
        if (rb) {
            CHECK(rb == b && rb->home == (uintptr_t)b);
            CHECK((const void *)rb->frame->scene == (const void *)&rb->scene);
            rgb8_t *after = tb_render_plain(rb->frame, NULL);
            if (!tb_same(before, after, n))
                printf("%s: the relocated copy renders differently\n", tb_scenes[s]);
            CHECK(tb_same(before, after, n));
            free(after);
        }
        free(before);
        free(b);
    }
}

/* Also catches pointers rendering never reads: after relocation no word
 * of the copy points into the original, and exactly as many point into
 * the copy as pointed into the original before. */
static void test_relocate_no_stale_pointer(void)
{
    for (size_t s = 0; s < TB_SCENE_COUNT; s++) {
        size_t size;
        render_blob_t *a = tb_blob(tb_scenes[s], tb_frame_of(tb_scenes[s]), &size);
        CHECK(a != NULL);
        if (!a)
            continue;
        size_t inside_a = tb_words_into(a, a->bytes, (uintptr_t)a, a->bytes);
        /* scene: 7 arrays; frame: scene and 5 arrays; header: home, frame */
        CHECK(inside_a >= 7 + 6 + 2);
        void *b = tb_block(size);
        memcpy(b, a, a->bytes);
        render_blob_t *rb;
        render_blob_error_t err;
        CHECK_EQ_INT(render_blob_relocate(b, size, &rb, &err), RENDER_BLOB_OK);
        CHECK_EQ_INT(tb_words_into(b, a->bytes, (uintptr_t)a, a->bytes), 0);
        CHECK_EQ_INT(tb_words_into(b, a->bytes, (uintptr_t)b, a->bytes), inside_a);
        /* relocating where it already is changes nothing */
        uint8_t *again = malloc(a->bytes);
        memcpy(again, b, a->bytes);
        CHECK_EQ_INT(render_blob_relocate(b, size, &rb, &err), RENDER_BLOB_OK);
        CHECK(memcmp(again, b, a->bytes) == 0);
        free(again);
        free(a);
        free(b);
    }
}

/* A frame prepared in the block from a scene loaded elsewhere is not
 * self-contained: refused, naming the field, the copy untouched. */
static void test_relocate_refuses_outside_pointers(void)
{
    size_t len;
    uint8_t *buf = tb_compile("demo", &len);
    CHECK(buf != NULL);
    if (!buf)
        return;
    static _Alignas(RENDER_RELOCATE_ALIGN) uint8_t scene_mem[1 << 20];
    arena_t scene_arena;
    arena_init(&scene_arena, scene_mem, sizeof scene_mem);
    scene_t scene;
    scene_load_error_t lerr;
    CHECK_EQ_INT(scene_load(buf, len, &scene_arena, &scene, &lerr), SCENE_LOAD_OK);
    size_t size = render_prepare_bytes(&scene);
    uint8_t *a = tb_block(size), *b = tb_block(size);
    arena_t arena;
    arena_init(&arena, a, size);
    render_frame_t *frame;
    CHECK_EQ_INT(render_prepare(&scene, 0, &arena, &frame), RENDER_OK);
    memcpy(b, a, arena.used);
    uint8_t *saved = malloc(arena.used);
    memcpy(saved, b, arena.used);
    const char *bad = NULL;
    render_frame_t *moved = frame;
    CHECK_EQ_INT(render_relocate(b, arena.used, (uintptr_t)a, NULL, &moved, &bad), RENDER_ERR_RELOCATE);
    CHECK(bad && strcmp(bad, "frame.scene") == 0);
    CHECK(moved == frame);
    CHECK(memcmp(saved, b, arena.used) == 0);

    /* a scene_t outside the range (here on the stack) is refused */
    const scene_t *sp = &scene;
    CHECK_EQ_INT(render_relocate(scene_mem, sizeof scene_mem, (uintptr_t)scene_mem, &sp, NULL, &bad),
                 RENDER_ERR_RELOCATE); /* scene_t itself is on the stack */
    CHECK(bad && strcmp(bad, "scene") == 0);

    /* a base not aligned to RENDER_RELOCATE_ALIGN */
    CHECK_EQ_INT(render_relocate(b + 8, arena.used - 8, (uintptr_t)a, NULL, &moved, &bad),
                 RENDER_ERR_RELOCATE);
    CHECK(bad && strstr(bad, "RENDER_RELOCATE_ALIGN") != NULL);
    free(saved);
    free(a);
    free(b);
    free(buf);
}

/* Fields bent outside a complete blob, one at a time: each is refused with
 * its own name and the copy left as it was. */
static void test_relocate_names_each_bad_field(void)
{
    size_t size;
    render_blob_t *a = tb_blob("demo", 0, &size);
    CHECK(a != NULL);
    if (!a)
        return;
    uint8_t *b = tb_block(size);
    render_blob_t *bb = (render_blob_t *)b;
    uintptr_t outside = (uintptr_t)a + a->bytes + 64; /* just past the blob */
    struct {
        const char *field;
        size_t offset; /* of the pointer field, from the blob's start */
    } cases[9];
    int n = 0;
    const render_frame_t *f = a->frame;
    uint32_t dens = 0;
    while (dens < f->prim_count && f->prims[dens].kind != SCENE_PRIM_DENSITY)
        dens++;
    CHECK(dens < f->prim_count && a->scene.map_count > 0);
#define TB_CASE(name, ptr_lvalue) \
    (cases[n].field = (name), cases[n++].offset = (size_t)((const uint8_t *)&(ptr_lvalue) - (const uint8_t *)a))
    TB_CASE("scene.prims", a->scene.prims);
    TB_CASE("scene.maps[].texels", a->scene.maps[0].texels);
    TB_CASE("frame.clusters", f->clusters);
    TB_CASE("frame.density_inv_radius2", f->density_inv_radius2);
    if (dens < f->prim_count) {
        TB_CASE("frame.prims[].components", f->prims[dens].components);
        TB_CASE("frame.prims[].inv_radius2", f->prims[dens].inv_radius2);
    }
    TB_CASE("frame", a->frame);
#undef TB_CASE
    for (int i = 0; i < n; i++) {
        memcpy(b, a, a->bytes);
        memcpy(b + cases[i].offset, &outside, sizeof outside);
        uint8_t *saved = malloc(a->bytes);
        memcpy(saved, b, a->bytes);
        render_blob_t *rb;
        render_blob_error_t err;
        CHECK_EQ_INT(render_blob_relocate(b, size, &rb, &err), RENDER_BLOB_ERR_RELOCATE);
        if (!strstr(err.message, cases[i].field))
            printf("bent %s, message: %s\n", cases[i].field, err.message);
        CHECK(strstr(err.message, cases[i].field) != NULL);
        CHECK(memcmp(saved, b, a->bytes) == 0);
        CHECK(rb == NULL);
        free(saved);
    }
    /* a frame given with a scene that is not its own */
    memcpy(b, a, a->bytes);
    const scene_t *other = (const scene_t *)(uintptr_t)a->frame;
    render_frame_t *frame = a->frame;
    const char *bad;
    CHECK_EQ_INT(render_relocate(b, a->bytes, (uintptr_t)a, &other, &frame, &bad), RENDER_ERR_RELOCATE);
    CHECK(bad && strstr(bad, "not the scene given") != NULL);
    /* the blob's own scene and frame given directly: fine */
    const scene_t *own = &a->scene;
    CHECK_EQ_INT(render_relocate(b, a->bytes, (uintptr_t)a, &own, &frame, &bad), RENDER_OK);
    CHECK((const uint8_t *)own == b + offsetof(render_blob_t, scene) && frame->scene == own);
    /* a count that would take an array past the blob's end */
    memcpy(b, a, a->bytes);
    bb->scene.prim_count = 0x7fffffffu;
    render_blob_t *rb;
    render_blob_error_t err;
    CHECK_EQ_INT(render_blob_relocate(b, size, &rb, &err), RENDER_BLOB_ERR_RELOCATE);
    CHECK(strstr(err.message, "scene.prims") != NULL);
    free(a);
    free(b);
}

/* The DM's size check: the bound fits every frame, one byte less is
 * refused before anything is written, with the numbers and the limit's
 * name. */
static void test_blob_size_bound(void)
{
    size_t len, need;
    render_blob_error_t err;
    const char *names[] = {"demo", "city", "anim"};
    for (int s = 0; s < 3; s++) {
        uint8_t *buf = tb_compile(names[s], &len);
        CHECK(buf != NULL);
        if (!buf)
            continue;
        CHECK_EQ_INT(render_blob_bytes(buf, len, &need, &err), RENDER_BLOB_OK);
        uint8_t *block = tb_block(need + RENDER_RELOCATE_ALIGN);
        render_blob_t *blob;
        /* the DM's load, its sum checked: the bound counts the parent maps
         * of the clusters that may have them, not two a cluster (most of
         * city's 150 are the automatic hierarchy's plain ones) */
        scene_load_known_t sum = {.body_sum = wire_get_u32(buf + SCN_HDR_SUM)};
        CHECK_EQ_INT(render_blob_load_summed(buf, len, &sum, block, need, "IMSU_BLOCK_BYTES", &blob,
                                             &err),
                     RENDER_BLOB_OK);
        for (uint32_t frame = 0; frame < 4; frame++) {
            CHECK_EQ_INT(render_blob_build(buf, len, frame, block, need, "NC_MEMORY", &blob, &err),
                         RENDER_BLOB_OK);
            CHECK(blob && blob->bytes <= blob->peak && blob->peak <= need && blob->frame_index == frame);
        }
        memset(block, 0x5a, need);
        CHECK_EQ_INT(render_blob_build(buf, len, 0, block, need - 1, "IMSU_BLOCK_BYTES", &blob, &err),
                     RENDER_BLOB_ERR_TOO_BIG);
        char want[80];
        snprintf(want, sizeof want, "needs %zu bytes, more than the %zu bytes of IMSU_BLOCK_BYTES", need,
                 need - 1);
        if (!strstr(err.message, want))
            printf("message: %s\n", err.message);
        CHECK(strstr(err.message, want) != NULL);
        CHECK(blob == NULL && block[0] == 0x5a && block[need - 1] == 0x5a);
        /* the DM's load into a block too small for the root's maps alone:
         * refused as such, before the clusters' maps are counted */
        const size_t tiny = 1024;
        CHECK_EQ_INT(render_blob_load_summed(buf, len, &sum, block, tiny, "IMSU_BLOCK_BYTES", &blob,
                                             &err),
                     RENDER_BLOB_ERR_TOO_BIG);
        const char *at = strstr(err.message, "needs at least ");
        size_t least = 0;
        CHECK(at && sscanf(at, "needs at least %zu", &least) == 1 && least > tiny && least <= need);
        CHECK(blob == NULL && block[0] == 0x5a);
        free(block);
        free(buf);
    }
}

/* Builds that fail for other reasons name them. */
static void test_blob_errors(void)
{
    size_t len, need;
    render_blob_error_t err;
    render_blob_t *blob;
    const render_blob_t *cblob;
    uint8_t *buf = tb_compile("glass", &len);
    CHECK(buf != NULL);
    if (!buf)
        return;
    CHECK_EQ_INT(render_blob_bytes(buf, len, &need, &err), RENDER_BLOB_OK);
    uint8_t *block = tb_block(need + RENDER_RELOCATE_ALIGN);
    /* misaligned block */
    CHECK_EQ_INT(render_blob_build(buf, len, 0, block + 4, need, NULL, &blob, &err), RENDER_BLOB_ERR_BLOCK);
    /* corrupt scene: the loader's own message comes through */
    buf[len - 1] ^= 1;
    CHECK_EQ_INT(render_blob_build(buf, len, 0, block, need, NULL, &blob, &err), RENDER_BLOB_ERR_LOAD);
    CHECK(strstr(err.message, "checksum") != NULL);
    CHECK_EQ_INT(render_blob_bytes(buf, len, &need, &err), RENDER_BLOB_ERR_LOAD);
    buf[len - 1] ^= 1;
    CHECK_EQ_INT(render_blob_bytes(buf, len, &need, &err), RENDER_BLOB_OK);
    /* open: at home fine; a copy not relocated, garbage, a short block refused */
    CHECK_EQ_INT(render_blob_build(buf, len, 0, block, need, NULL, &blob, &err), RENDER_BLOB_OK);
    CHECK_EQ_INT(render_blob_open(block, need, &cblob, &err), RENDER_BLOB_OK);
    CHECK(cblob == (const render_blob_t *)block);
    uint8_t *copy = tb_block(need);
    memcpy(copy, block, blob->bytes);
    CHECK_EQ_INT(render_blob_open(copy, need, &cblob, &err), RENDER_BLOB_ERR_NOT_BLOB);
    CHECK(strstr(err.message, "not relocated") != NULL);
    CHECK_EQ_INT(render_blob_open(block, blob->bytes - 1, &cblob, &err), RENDER_BLOB_ERR_NOT_BLOB);
    memset(copy, 0, need);
    CHECK_EQ_INT(render_blob_open(copy, need, &cblob, &err), RENDER_BLOB_ERR_NOT_BLOB);
    CHECK(strstr(err.message, "magic") != NULL);
    render_blob_t *rb;
    CHECK_EQ_INT(render_blob_relocate(copy, need, &rb, &err), RENDER_BLOB_ERR_NOT_BLOB);
    free(copy);
    free(block);
    free(buf);
}

/* The blob of a text scene: RENDER_BLOB_OK, or its status with the
 * message in why. */
static render_blob_status_t tb_text_blob(const char *text, char *why, size_t cap)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    uint8_t *buf = NULL;
    size_t len, need;
    render_blob_error_t berr = {RENDER_BLOB_OK, ""};
    render_blob_t *blob;
    snprintf(why, cap, "cannot compile");
    if (sd_parse_text("detail.scn", text, &s, err, sizeof err) != 0) {
        printf("# %s\n", err);
        return RENDER_BLOB_ERR_LOAD;
    }
    int compiled = sd_compile(&s, &buf, &len, err, sizeof err) == 0;
    sd_free(&s);
    if (!compiled || render_blob_bytes(buf, len, &need, &berr) != RENDER_BLOB_OK) {
        free(buf);
        return RENDER_BLOB_ERR_LOAD;
    }
    void *block = tb_block(need);
    render_blob_status_t st =
        render_blob_build(buf, len, 0, block, need, "the test block", &blob, &berr);
    snprintf(why, cap, "%s", st == RENDER_BLOB_OK ? "ok" : berr.message);
    printf("# %s\n", why);
    free(block);
    free(buf);
    return st;
}

/* Issue 11: a sphere of radius 1e-6 in a scene spanning 12 is one fixed
 * step (2^-19): refused in fixed point, rendered in float and double; of
 * radius 1e-5 it renders in every arithmetic.  Far from the origin (x =
 * 100) float resolves 1.19e-5 and refuses a radius of 1e-5. */
static void test_blob_detail(void)
{
    static const char scene[] =
        "camera { eye %s 1 -0.00001  look_at %s 1 0  up 0 1 0  fov 40 }  resolution 64 48\n"
        "light point { colour 1 1 1  position -4 9 -5 }\n"
        "material m { colour 1 1 1 dic 0.3 drc 0.7 }\n"
        "box { material m  min -6 -0.5 -4  max %s 0 8 }\n"
        "sphere { material m centre %s 1 0 radius %s }\n";
    char text[600], why[RENDER_BLOB_MSG_MAX];
    snprintf(text, sizeof text, scene, "0", "0", "6", "0", "0.000001");
    render_blob_status_t st = tb_text_blob(text, why, sizeof why);
#if defined(LINKS1_NUM_FIXED)
    CHECK_EQ_INT(st, RENDER_BLOB_ERR_PREPARE);
    CHECK(strcmp(why, "frame 0: ellipsoid 1 has a radius of 1.91e-6; fixed Q12.19 resolves "
                      "1.91e-6 there, in a scene spanning 12 (lengths scaled by 2^0): enlarge "
                      "it or use float") == 0);
#else
    CHECK_EQ_INT(st, RENDER_BLOB_OK);
#endif
    snprintf(text, sizeof text, scene, "0", "0", "6", "0", "0.00001");
    CHECK_EQ_INT(tb_text_blob(text, why, sizeof why), RENDER_BLOB_OK);
    snprintf(text, sizeof text, scene, "100", "100", "106", "100", "0.00001");
    st = tb_text_blob(text, why, sizeof why);
#if defined(LINKS1_NUM_DOUBLE)
    CHECK_EQ_INT(st, RENDER_BLOB_OK);
#elif defined(LINKS1_NUM_FLOAT)
    CHECK_EQ_INT(st, RENDER_BLOB_ERR_PREPARE);
    CHECK(strcmp(why, "frame 0: ellipsoid 1 has a radius of 0.00001; float resolves 1.19e-5 "
                      "there, in a scene spanning 112 (lengths scaled by 2^-3): enlarge it") == 0);
#else
    CHECK_EQ_INT(st, RENDER_BLOB_ERR_PREPARE);
    CHECK(strstr(why, "ellipsoid 1 has a radius of 1.53e-5; fixed Q12.19 resolves 1.53e-5") != NULL);
#endif
}

/* The DM's way (docs/gigs.md): the scene loaded into a block once, then
 * frames prepared one after another in it, each the same bytes as a build
 * of that frame alone; and the RC's render_blob_copy gives a copy that
 * opens where it lies, every pointer inside it. */
static void test_blob_load_then_prepare(void)
{
    size_t len, need;
    render_blob_error_t err;
    uint8_t *buf = tb_compile("anim", &len);
    CHECK(buf != NULL);
    if (!buf)
        return;
    CHECK_EQ_INT(render_blob_bytes(buf, len, &need, &err), RENDER_BLOB_OK);
    uint8_t *block = tb_block(need), *fresh = tb_block(need), *copy = tb_block(need);
    render_blob_t *blob, *alone, *moved;
    CHECK_EQ_INT(render_blob_load(buf, len, block, need, NULL, &blob, &err), RENDER_BLOB_OK);
    CHECK(blob && blob->frame == NULL && blob->bound == need && blob->bytes == blob->scene_bytes);
    int same = blob != NULL;
    for (uint32_t frame = 0; blob && frame < blob->scene.frame_count && frame < 3; frame++) {
        CHECK_EQ_INT(render_blob_prepare(blob, frame, need, &err), RENDER_BLOB_OK);
        /* the lone build at the same address: the same bytes, pointers too */
        memcpy(fresh, block, need);
        memset(block, 0, need);
        CHECK_EQ_INT(render_blob_build(buf, len, frame, block, need, NULL, &alone, &err),
                     RENDER_BLOB_OK);
        same = same && memcmp(fresh, block, alone->bytes) == 0 && alone->bytes == blob->bytes;
        memcpy(block, fresh, need); /* the DM's block again, frame after frame */
    }
    CHECK(same);
    if (blob && render_blob_copy(copy, need, blob, &moved, &err) == RENDER_BLOB_OK) {
        const render_blob_t *opened;
        CHECK_EQ_INT(render_blob_open(copy, need, &opened, &err), RENDER_BLOB_OK);
        CHECK((const uint8_t *)moved->frame > copy && (const uint8_t *)moved->frame < copy + need);
    } else {
        CHECK(0);
    }
    free(block);
    free(fresh);
    free(copy);
    free(buf);
}

/* Frame f's clusters all cover the whole screen (screen and tree
 * rectangles), as RENDER_PREP_NO_SCREEN leaves them. */
static int tb_whole_screen(const render_frame_t *f)
{
    int32_t w = (int32_t)f->width - 1, h = (int32_t)f->height - 1;
    for (uint32_t i = 0; i < f->cluster_count; i++) {
        const render_cluster_t *c = &f->clusters[i];
        if (c->screen_x0 != 0 || c->screen_y0 != 0 || c->screen_x1 != w || c->screen_y1 != h ||
            c->tree_x0 != 0 || c->tree_y0 != 0 || c->tree_x1 != w || c->tree_y1 != h)
            return 0;
    }
    return f->screenless;
}

/* RENDER_PREP_NO_SCREEN (the wide frame's): frame after frame of name in
 * one block, every rectangle the whole screen, the primitives byte for
 * byte the whole frame's and every pixel (render_pixel's tree walk) the
 * same; the frames it prepared, or -1 at the first that differs. */
static int tb_no_screen_frames(const char *name)
{
    size_t len, need;
    render_blob_error_t err;
    uint8_t *buf = tb_compile_div(name, 4, &len);
    int ok = buf && render_blob_bytes(buf, len, &need, &err) == RENDER_BLOB_OK;
    uint8_t *a = ok ? tb_block(need) : NULL, *b = ok ? tb_block(need) : NULL;
    render_blob_t *none = NULL, *whole = NULL;
    ok = a && b && render_blob_load(buf, len, a, need, NULL, &none, &err) == RENDER_BLOB_OK &&
         render_blob_load(buf, len, b, need, NULL, &whole, &err) == RENDER_BLOB_OK;
    int frames = 0;
    for (uint32_t k = 0; ok && k < none->scene.frame_count && k < 4; k++, frames++) {
        ok = render_blob_prepare_parts(none, k, need, RENDER_PREP_NO_SCREEN, &err) ==
                 RENDER_BLOB_OK &&
             render_blob_prepare(whole, k, need, &err) == RENDER_BLOB_OK;
        const render_frame_t *fn = ok ? none->frame : NULL, *fw = ok ? whole->frame : NULL;
        ok = ok && tb_whole_screen(fn) && !fw->screenless &&
             memcmp(fn->prims, fw->prims, sizeof *fn->prims * fn->prim_count) == 0;
        rgb8_t *in = ok ? tb_render_plain(fn, NULL) : NULL;
        rgb8_t *iw = ok ? tb_render_plain(fw, NULL) : NULL;
        ok = in && iw && memcmp(in, iw, sizeof *in * fn->width * fn->height) == 0;
        free(in);
        free(iw);
    }
    if (!ok)
        printf("  %s: frame %d of RENDER_PREP_NO_SCREEN differs\n", name, frames);
    free(a);
    free(b);
    free(buf);
    return ok ? frames : -1;
}

/* The same on anim (most clusters moving: each frame prepared whole) and
 * pendulum (a few: only those prepared again). */
static void test_blob_no_screen(void)
{
    CHECK(tb_no_screen_frames("anim") >= 3);
    CHECK(tb_no_screen_frames("pendulum") >= 3);
}

/* The RC's frame-only forwarding: the DM's two blocks A and B hold one
 * load of anim (scene_id 7), frames 0 and 1; A is copied whole into the
 * broadcast block C, then B's frame into C alone (render_blob_copy_frame):
 * C is then byte for byte what a whole copy of B into C gives.  A blob of
 * another load (scene_id 8), or of none (0), is copied whole. */
static void test_blob_copy_frame_only(void)
{
    size_t len, need;
    render_blob_error_t err;
    uint8_t *buf = tb_compile("anim", &len);
    CHECK(buf != NULL);
    if (!buf)
        return;
    CHECK_EQ_INT(render_blob_bytes(buf, len, &need, &err), RENDER_BLOB_OK);
    uint8_t *a = tb_block(need), *b = tb_block(need), *c = tb_block(need), *whole = tb_block(need);
    render_blob_t *ba = NULL, *bb = NULL, *bc = NULL;
    int partial = -1;
    CHECK_EQ_INT(render_blob_load(buf, len, a, need, NULL, &ba, &err), RENDER_BLOB_OK);
    CHECK_EQ_INT(render_blob_load(buf, len, b, need, NULL, &bb, &err), RENDER_BLOB_OK);
    if (ba && bb) {
        ba->scene_id = bb->scene_id = 7;
        CHECK_EQ_INT(render_blob_prepare(ba, 0, need, &err), RENDER_BLOB_OK);
        CHECK_EQ_INT(render_blob_prepare(bb, 1, need, &err), RENDER_BLOB_OK);
        CHECK_EQ_INT(render_blob_copy_frame(c, need, ba, &bc, &partial, &err), RENDER_BLOB_OK);
        CHECK_EQ_INT(partial, 0); /* C held nothing: whole */
        CHECK_EQ_INT(render_blob_copy_frame(c, need, bb, &bc, &partial, &err), RENDER_BLOB_OK);
        CHECK_EQ_INT(partial, 1);
        memcpy(whole, c, need);
        render_blob_t *bw;
        CHECK_EQ_INT(render_blob_copy(c, need, bb, &bw, &err), RENDER_BLOB_OK);
        CHECK(bc && bc->frame_index == 1 && bc->bytes == bb->bytes);
        CHECK(memcmp(whole, c, bb->bytes) == 0);
        bb->scene_id = 8; /* another load: whole */
        CHECK_EQ_INT(render_blob_copy_frame(c, need, bb, &bc, &partial, &err), RENDER_BLOB_OK);
        CHECK_EQ_INT(partial, 0);
        bb->scene_id = 0; /* unnumbered: whole */
        CHECK_EQ_INT(render_blob_copy_frame(c, need, bb, &bc, &partial, &err), RENDER_BLOB_OK);
        CHECK_EQ_INT(partial, 0);
    }
    free(a);
    free(b);
    free(c);
    free(whole);
    free(buf);
}

/* A case of frames prepared over the ones before: a scene (compiled at a
 * quarter of its size, in world space or not) whose frames are prepared
 * in turn, and what each step should report. */
typedef struct {
    const char *name;
    uint32_t frames[4];
    int want[4];
    int world;
} world_case_t;

/* Runs check(case, compiled form, its length, the bytes its blob needs)
 * over each case whose scene compiles (a failed check otherwise). */
static void tb_world_cases(const world_case_t *cases, size_t n,
                           void (*check)(const world_case_t *, const uint8_t *, size_t, size_t))
{
    for (size_t c = 0; c < n; c++) {
        size_t len, need;
        render_blob_error_t err;
        uint8_t *buf = tb_compile_flags(cases[c].name, 4,
                                        cases[c].world ? SCN_OPT_WORLD_SPACE : 0, &len);
        CHECK(buf != NULL);
        if (buf) {
            render_blob_status_t st = render_blob_bytes(buf, len, &need, &err);
            CHECK_EQ_INT(st, RENDER_BLOB_OK);
            if (st == RENDER_BLOB_OK)
                check(&cases[c], buf, len, need);
        }
        free(buf);
    }
}

/* A step's report against the case's: printed when they differ. */
static void tb_world_step(const world_case_t *wc, int k, const char *what, int got)
{
    if (got != wc->want[k])
        printf("%s frame %u (step %d): %s %d, expected %d\n", wc->name, (unsigned)wc->frames[k], k,
               what, got, wc->want[k]);
    CHECK_EQ_INT(got, wc->want[k]);
}

/* One block, as the DM's: each frame prepared over the one before. */
static void world_keeps(const world_case_t *wc, const uint8_t *buf, size_t len, size_t need)
{
    render_blob_error_t err;
    uint8_t *block = tb_block(need), *saved = tb_block(need);
    render_blob_t *blob, *alone;
    CHECK_EQ_INT(render_blob_load(buf, len, block, need, NULL, &blob, &err), RENDER_BLOB_OK);
    for (int k = 0; blob && k < 4; k++) {
        CHECK_EQ_INT(render_blob_prepare(blob, wc->frames[k], need, &err), RENDER_BLOB_OK);
        if (!blob->frame)
            break;
        CHECK(blob->frame->world == wc->world);
        tb_world_step(wc, k, "kept", blob->frame->kept);
        blob->frame->kept = 0;
        memcpy(saved, block, need);
        memset(block, 0, need);
        CHECK_EQ_INT(render_blob_build(buf, len, wc->frames[k], block, need, NULL, &alone, &err),
                     RENDER_BLOB_OK);
        CHECK(alone && alone->bytes == ((render_blob_t *)saved)->bytes);
        CHECK(alone && memcmp(saved, block, alone->bytes) == 0);
        memcpy(block, saved, need); /* the DM's block again */
    }
    free(block);
    free(saved);
}

/* A world-space scene prepared frame after frame in one block, as the
 * DM does: a frame whose keyed cluster maps are those of the block's
 * frame before keeps its world part (kept 1; fly: only the camera and
 * lights move; the still demo prepared twice), one where a few clusters
 * moved prepares only them again (2; pendulum: the pendulum and its bob,
 * and the lamp until it stops), one where most moved is prepared whole
 * (0; anim: five of six primitives); either way the block holds the bytes
 * a fresh build there writes (but the frame's kept), and renders the
 * same. */
static void test_blob_world_space_keeps(void)
{
    static const world_case_t cases[] = {
        {"fly", {0, 1, 2, 3}, {0, 1, 1, 1}, 1},
        {"demo", {0, 0, 0, 0}, {0, 1, 1, 1}, 1},
        {"anim", {0, 1, 2, 2}, {0, 0, 0, 1}, 1},
        {"pendulum", {0, 1, 2, 3}, {0, 2, 2, 2}, 1},
        {"pendulum", {3, 0, 0, 2}, {0, 2, 1, 2}, 1},
    };
    tb_world_cases(cases, sizeof cases / sizeof cases[0], world_keeps);
}

/* The same in eye space, the paper's: a frame seen from the camera of the
 * block's frame before keeps its primitives and boxes when no keyed
 * cluster map differs (kept 1; the still demo prepared again), prepares
 * only the clusters that moved again where few did (2; pendulum, its
 * camera still), and the whole frame when the camera moved (0; fly) or
 * most clusters did (anim); the block holds the bytes a fresh build
 * there writes, screen rectangles and clip coverage included. */
static void test_blob_eye_space_keeps(void)
{
    static const world_case_t cases[] = {
        {"fly", {0, 1, 2, 2}, {0, 0, 0, 1}, 0},
        {"demo", {0, 0, 0, 0}, {0, 1, 1, 1}, 0},
        {"anim", {0, 1, 2, 2}, {0, 0, 0, 1}, 0},
        {"pendulum", {0, 1, 2, 3}, {0, 2, 2, 2}, 0},
        {"pendulum", {3, 0, 0, 2}, {0, 2, 1, 2}, 0},
    };
    tb_world_cases(cases, sizeof cases / sizeof cases[0], world_keeps);
}

/* The index's range of keyed clusters holds every cluster with keys and
 * begins and ends with one (none: 0, 0); a world-space frame compares
 * the maps of those alone (render_world_same). */
static void test_blob_keyed_range(void)
{
    const char *names[] = {"anim", "pendulum", "fly", "demo"};
    for (int n = 0; n < 4; n++) {
        size_t len, need;
        render_blob_error_t err;
        uint8_t *buf = tb_compile(names[n], &len);
        CHECK(buf != NULL);
        if (!buf)
            continue;
        CHECK_EQ_INT(render_blob_bytes(buf, len, &need, &err), RENDER_BLOB_OK);
        uint8_t *block = tb_block(need);
        render_blob_t *blob = NULL;
        CHECK_EQ_INT(render_blob_load(buf, len, block, need, NULL, &blob, &err), RENDER_BLOB_OK);
        const scene_t *sc = blob ? &blob->scene : NULL;
        uint32_t keyed = 0, lo = sc ? sc->index.keyed_lo : 0, hi = sc ? sc->index.keyed_hi : 0;
        for (uint32_t i = 0; sc && i < sc->cluster_count; i++) {
            keyed += sc->clusters[i].key_count != 0;
            CHECK(sc->clusters[i].key_count == 0 || (i >= lo && i < hi));
        }
        CHECK(keyed ? sc->clusters[lo].key_count && sc->clusters[hi - 1].key_count : lo == 0 && hi == 0);
        CHECK(n >= 2 || keyed > 1); /* anim and pendulum move clusters */
        free(block);
        free(buf);
    }
}

/* The DM's two blocks taking the frames in turn, each forwarded into the
 * RC's broadcast block. */
static void world_forwards(const world_case_t *wc, const uint8_t *buf, size_t len, size_t need)
{
    render_blob_error_t err;
    uint8_t *dm[2] = {tb_block(need), tb_block(need)}, *bc = tb_block(need), *saved = tb_block(need);
    render_blob_t *blob[2] = {NULL, NULL}, *out;
    for (int k = 0; k < 2; k++) {
        CHECK_EQ_INT(render_blob_load(buf, len, dm[k], need, NULL, &blob[k], &err), RENDER_BLOB_OK);
        if (blob[k])
            blob[k]->scene_id = 7;
    }
    for (int k = 0; blob[0] && blob[1] && k < 4; k++) {
        render_blob_t *src = blob[k & 1];
        int partial = -1;
        CHECK_EQ_INT(render_blob_prepare(src, wc->frames[k], need, &err), RENDER_BLOB_OK);
        CHECK_EQ_INT(render_blob_copy_frame(bc, need, src, &out, &partial, &err), RENDER_BLOB_OK);
        tb_world_step(wc, k, "partial", partial);
        CHECK(out && out->frame_index == wc->frames[k] && out->bytes == src->bytes);
        memcpy(saved, bc, need);
        CHECK_EQ_INT(render_blob_copy(bc, need, src, &out, &err), RENDER_BLOB_OK);
        CHECK(memcmp(saved, bc, src->bytes) == 0);
        memcpy(bc, saved, need); /* the RC's block again */
    }
    free(dm[0]);
    free(dm[1]);
    free(bc);
    free(saved);
}

/* The RC's forwarding of world-space frames: the DM's two blocks A and B
 * take the frames of one load in turn (each keeping its own frame before),
 * and each is forwarded into the broadcast block C: a frame whose world
 * part C holds (fly: the camera and lights move; demo prepared again) gets
 * its header alone (partial 2), one whose clusters moved (pendulum) its
 * frame part (1); either way C is then byte for byte what a whole copy of
 * that frame into C gives. */
static void test_blob_copy_world_header(void)
{
    static const world_case_t cases[] = {
        {"fly", {0, 1, 2, 3}, {0, 2, 2, 2}, 1},
        {"demo", {0, 0, 0, 0}, {0, 2, 2, 2}, 1},
        {"pendulum", {0, 1, 2, 3}, {0, 1, 1, 1}, 1},
    };
    tb_world_cases(cases, sizeof cases / sizeof cases[0], world_forwards);
}

int main(void)
{
    RUN(test_relocated_copy_renders_same);
    RUN(test_relocate_no_stale_pointer);
    RUN(test_relocate_refuses_outside_pointers);
    RUN(test_relocate_names_each_bad_field);
    RUN(test_blob_size_bound);
    RUN(test_blob_errors);
    RUN(test_blob_detail);
    RUN(test_blob_load_then_prepare);
    RUN(test_blob_copy_frame_only);
    RUN(test_blob_no_screen);
    RUN(test_blob_world_space_keeps);
    RUN(test_blob_eye_space_keeps);
    RUN(test_blob_copy_world_header);
    RUN(test_blob_keyed_range);
    return check_exit();
}
