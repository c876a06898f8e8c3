/* test_wide.c: escalation (render/wide.h) in one program that carries the
 * renderer twice, its own arithmetic and the wide copy (double) under
 * wide_* names.  A pixel that loses precision takes the wide copy's colour,
 * every other keeps its own, and a lost one stops its own rays; the
 * counts say so; an NC's area walk escalates the same pixels; the wide
 * blob survives the RC's copy (relocated, frame part only for the next
 * frame); the wide load given what the narrow load found (the DM's) makes
 * the same scene; bad blocks and contexts are refused with a message. */
#include "tests/check.h"
#include "proto/scene_format.h"
#include "proto/wire.h"
#include "render/wide.h"
#include "tests/host/test_blob_util.h"

#define TW_DIV 2 /* demo.scn at 160x120 */

/* The wide blob of scenes/NAME.scn, frame frame_index, in a new block;
 * known: what its load is told (wide_blob_load's), or NULL. */
static void *tw_wide_blob_known(const char *name, uint32_t frame_index,
                                const scene_load_known_t *known, size_t *size)
{
    size_t len;
    char why[RENDER_BLOB_MSG_MAX];
    uint8_t *buf = tb_compile_div(name, TW_DIV, &len);
    void *block = NULL;
    if (buf && RENDER_WIDE(wide_blob_bytes)(buf, len, size, why, sizeof why) == 0) {
        block = tb_block(*size);
        if (RENDER_WIDE(wide_blob_load)(buf, len, known, block, *size, "the test block", 7, why,
                                        sizeof why) != 0 ||
            RENDER_WIDE(wide_blob_prepare)(block, frame_index, *size, why, sizeof why) != 0) {
            printf("%s: %s\n", name, why);
            free(block);
            block = NULL;
        }
    }
    free(buf);
    return block;
}

static void *tw_wide_blob(const char *name, uint32_t frame_index, size_t *size)
{
    return tw_wide_blob_known(name, frame_index, NULL, size);
}

static void *tw_wide_ctx(const void *block, size_t size)
{
    char why[RENDER_BLOB_MSG_MAX];
    void *mem = aligned_alloc(RENDER_WIDE_CTX_ALIGN, (RENDER_WIDE(wide_ctx_bytes)() + 7) & ~7u);
    if (mem && RENDER_WIDE(wide_ctx_open)(mem, block, size, 1, 1, 0, why, sizeof why) != 0) {
        printf("wide context: %s\n", why);
        free(mem);
        mem = NULL;
    }
    return mem;
}

/* demo.scn's narrow blob (f its frame), its wide blob and a wide context
 * on it. */
struct tw_demo {
    render_blob_t *blob;
    const render_frame_t *f;
    void *wblock, *wctx;
    size_t wsize;
};

/* d made; 0 (a failed check, each part freed) when one cannot be. */
static int tw_demo_open(struct tw_demo *d)
{
    size_t size;
    d->blob = tb_blob_div("demo", 0, TW_DIV, &size);
    d->wblock = tw_wide_blob("demo", 0, &d->wsize);
    d->wctx = d->wblock ? tw_wide_ctx(d->wblock, d->wsize) : NULL;
    d->f = d->blob ? d->blob->frame : NULL;
    CHECK(d->blob && d->wctx);
    if (d->blob && d->wctx)
        return 1;
    free(d->blob);
    free(d->wblock);
    free(d->wctx);
    return 0;
}

static void tw_demo_close(struct tw_demo *d)
{
    free(d->wctx);
    free(d->wblock);
    free(d->blob);
}

/* Every pixel of the frame with ctx, into a new image; lost[i] = whether
 * pixel i lost precision (when lost is not NULL). */
static rgb8_t *tw_render(render_ctx_t *ctx, uint8_t *lost)
{
    const render_frame_t *f = ctx->frame;
    rgb8_t *img = malloc(sizeof *img * f->width * f->height);
    for (uint32_t y = 0; img && y < f->height; y++)
        for (uint32_t x = 0; x < f->width; x++) {
            img[y * f->width + x] = render_pixel(ctx, x, y);
            if (lost)
                lost[y * f->width + x] = ctx->pixel_lost;
        }
    return img;
}

/* The same with the wide copy (wide_pixel on its context), w x h. */
static rgb8_t *tw_render_wide(void *wctx, uint32_t w, uint32_t h, uint8_t *lost)
{
    rgb8_t *img = malloc(sizeof *img * w * h);
    for (uint32_t y = 0; img && y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            uint8_t l;
            img[y * w + x] = RENDER_WIDE(wide_pixel)(wctx, x, y, &l);
            if (lost)
                lost[y * w + x] = l;
        }
    return img;
}

static int tw_same(rgb8_t a, rgb8_t b)
{
    return a.r == b.r && a.g == b.g && a.b == b.b;
}

/* demo.scn rendered both ways, for comparing pixel by pixel: own, this
 * arithmetic with escalation's net (RENDER_ESCALATE_MARGIN) and lost[] its
 * doubts; wide, the wide copy's, and wide_lost[] what it lost. */
struct tw_both {
    size_t n;
    rgb8_t *own, *wide;
    uint8_t *lost, *wide_lost;
    render_stats_t own_stats; /* own's rays */
};

static void tw_both_render(const render_frame_t *f, void *wctx, struct tw_both *b)
{
    b->n = (size_t)f->width * f->height;
    b->lost = calloc(b->n, 1);
    b->wide_lost = calloc(b->n, 1);
    render_ctx_t plain;
    render_ctx_init(&plain, f);
    plain.error_margin = RENDER_ESCALATE_MARGIN; /* the net escalation casts */
    b->own = tw_render(&plain, b->lost);
    b->own_stats = plain.stats;
    b->wide = tw_render_wide(wctx, f->width, f->height, b->wide_lost);
}

static void tw_both_free(struct tw_both *b)
{
    free(b->lost);
    free(b->wide_lost);
    free(b->own);
    free(b->wide);
}

/* A lost pixel takes the wide colour, the others keep theirs; escalated
 * counts the lost ones, precision_lost_pixels those the wide one lost.
 * Its own rays stop once it is lost: fewer are traced than without
 * escalation. */
static void test_wide_escalates_lost_pixels(void)
{
    struct tw_demo d;
    if (!tw_demo_open(&d))
        return;
    const render_frame_t *f = d.f;
    struct tw_both b;
    tw_both_render(f, d.wctx, &b);
    size_t n = b.n;
    const uint8_t *lost = b.lost, *wide_lost = b.wide_lost;
    const rgb8_t *own = b.own, *wide = b.wide;
    render_ctx_t esc;
    void *wctx2 = tw_wide_ctx(d.wblock, d.wsize);
    render_ctx_init(&esc, f);
    render_wide_escalate(&esc, wctx2);
    rgb8_t *got = tw_render(&esc, NULL);
    uint32_t nlost = 0, nboth = 0, wrong = 0;
    for (size_t i = 0; i < n; i++) {
        nlost += lost[i];
        nboth += lost[i] && wide_lost[i];
        wrong += !tw_same(got[i], lost[i] ? wide[i] : own[i]);
    }
    printf("demo %ux%u: %u of %zu pixels escalated, %u lost in double too\n", (unsigned)f->width,
           (unsigned)f->height, (unsigned)nlost, n, (unsigned)nboth);
    CHECK(nlost > 0 && nlost < n);
    CHECK_EQ_INT(wrong, 0);
    CHECK_EQ_INT(esc.stats.escalated_pixels, nlost);
    CHECK_EQ_INT(esc.stats.precision_lost_pixels, nboth);
    /* the wide copy's rays are counted apart, and add up */
    render_stats_t sum = esc.stats;
    RENDER_WIDE(wide_stats_add)(wctx2, &sum);
    CHECK(sum.primary == esc.stats.primary + nlost);
    uint64_t all = b.own_stats.shadow + b.own_stats.reflection + b.own_stats.refraction;
    uint64_t stopped = esc.stats.shadow + esc.stats.reflection + esc.stats.refraction;
    printf("demo: secondary rays %llu, %llu with the lost pixels stopped\n",
           (unsigned long long)all, (unsigned long long)stopped);
    CHECK(stopped < all);
    tw_both_free(&b);
    free(got);
    free(wctx2);
    tw_demo_close(&d);
}

/* 1 when a and b differ by more than RENDER_CHECK_LOST_STEPS in a channel. */
static int tw_apart(rgb8_t a, rgb8_t b)
{
    return abs(a.r - b.r) > RENDER_CHECK_LOST_STEPS || abs(a.g - b.g) > RENDER_CHECK_LOST_STEPS ||
           abs(a.b - b.b) > RENDER_CHECK_LOST_STEPS;
}

/* Checking (options.check_lost): every pixel keeps its own colour; a lost
 * one stays lost, and with mark_lost is painted, exactly when the wide
 * copy's colour is apart from it (or the wide copy lost it too). */
static void test_wide_check_keeps_colours(void)
{
    struct tw_demo d;
    if (!tw_demo_open(&d))
        return;
    const render_frame_t *f = d.f;
    struct tw_both b;
    tw_both_render(f, d.wctx, &b);
    size_t n = b.n;
    const uint8_t *lost = b.lost, *wide_lost = b.wide_lost;
    const rgb8_t *own = b.own, *wide = b.wide;
    render_ctx_t check;
    uint32_t off = 0, doubted = 0, wrong = 0, painted = 0;
    for (size_t i = 0; i < n; i++) {
        doubted += lost[i];
        off += lost[i] && (wide_lost[i] || tw_apart(own[i], wide[i]));
    }
    for (int mark = 0; mark <= 1; mark++) {
        void *w2 = tw_wide_ctx(d.wblock, d.wsize);
        render_ctx_init(&check, f);
        check.options.check_lost = 1;
        check.options.mark_lost = (uint8_t)mark;
        render_wide_escalate(&check, w2);
        rgb8_t *got = tw_render(&check, NULL);
        for (size_t i = 0; i < n; i++) {
            int is_off = lost[i] && (wide_lost[i] || tw_apart(own[i], wide[i]));
            rgb8_t want = mark && is_off ? RENDER_LOST_COLOUR : own[i];
            wrong += !tw_same(got[i], want);
            painted += mark && is_off;
        }
        CHECK_EQ_INT(check.stats.precision_lost_pixels, off);
        CHECK_EQ_INT(check.stats.escalated_pixels, doubted);
        /* checking keeps every pixel's own colour: no ray is stopped */
        CHECK(check.stats.shadow == b.own_stats.shadow &&
              check.stats.reflection == b.own_stats.reflection &&
              check.stats.refraction == b.own_stats.refraction);
        free(got);
        free(w2);
    }
    printf("demo: %u pixels doubted, %u of them more than %d/255 off double\n", (unsigned)doubted,
           (unsigned)off, RENDER_CHECK_LOST_STEPS);
    CHECK(doubted > 0 && off < doubted && painted == off);
    CHECK_EQ_INT(wrong, 0);
    tw_both_free(&b);
    tw_demo_close(&d);
}

/* render_area (the paper's lists, and clipping in the tree) escalates the
 * pixels render_pixel escalates, to the same colours. */
static void test_wide_area_same_as_pixels(void)
{
    struct tw_demo d;
    if (!tw_demo_open(&d))
        return;
    const render_frame_t *f = d.f;
    void *wctx = d.wctx;
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    render_wide_escalate(&ctx, wctx);
    rgb8_t *want = tw_render(&ctx, NULL);
    uint32_t want_escalated = ctx.stats.escalated_pixels;
    size_t clip_bytes = render_clip_bytes(f);
    void *clip_mem = malloc(clip_bytes ? clip_bytes : 1);
    for (int lists = 0; lists <= 1; lists++) {
        render_clip_t clip;
        render_clip_init(&clip, f, clip_mem, clip_bytes);
        render_ctx_init(&ctx, f);
        render_wide_escalate(&ctx, wctx);
        render_clip_options_t opt = {.y_clip = 1, .x_clip = 1, .lists = (uint8_t)lists};
        rgb8_t *area = malloc(sizeof *area * 16 * 16);
        uint32_t wrong = 0;
        for (uint32_t y = 0; y < f->height; y += 16)
            for (uint32_t x = 0; x < f->width; x += 16) {
                render_area_t a = {x, y, f->width - x < 16 ? f->width - x : 16,
                                   f->height - y < 16 ? f->height - y : 16};
                CHECK_EQ_INT(render_area(&ctx, &clip, &a, &opt, area), RENDER_OK);
                for (uint32_t r = 0; r < a.h; r++)
                    for (uint32_t c = 0; c < a.w; c++)
                        wrong += !tw_same(area[r * a.w + c], want[(y + r) * f->width + x + c]);
            }
        CHECK_EQ_INT(wrong, 0);
        CHECK_EQ_INT(ctx.stats.escalated_pixels, want_escalated);
        free(area);
    }
    free(clip_mem);
    free(want);
    tw_demo_close(&d);
}

/* The RC's copy of the wide blob: relocated to its new block (the old one
 * wrecked and freed), it renders as the original; the next frame of the
 * same load copies its frame part only and renders as a lone build. */
static void test_wide_copy_frame(void)
{
    size_t size, size2;
    void *a = tw_wide_blob("anim", 1, &size);
    void *a2 = tw_wide_blob("anim", 2, &size2);
    size_t nsize;
    render_blob_t *narrow = tb_blob_div("anim", 1, TW_DIV, &nsize); /* for the sizes */
    CHECK(a && a2 && narrow);
    if (!a || !a2 || !narrow)
        return;
    uint32_t w = narrow->frame->width, h = narrow->frame->height;
    size_t n = (size_t)w * h;
    void *ca = tw_wide_ctx(a, size);
    rgb8_t *before = tw_render_wide(ca, w, h, NULL);
    void *b = tb_block(size);
    char why[RENDER_BLOB_MSG_MAX];
    CHECK_EQ_INT(RENDER_WIDE(wide_blob_copy_frame)(b, size, a, why, sizeof why), 0);
    memset(a, 0xA5, size);
    free(a);
    void *cb = tw_wide_ctx(b, size);
    rgb8_t *after = cb ? tw_render_wide(cb, w, h, NULL) : NULL;
    CHECK(after && memcmp(before, after, n * sizeof *after) == 0);
    /* frame 2 over it: a2 is the same load (both numbered 7) */
    void *c2 = tw_wide_ctx(a2, size2);
    rgb8_t *lone = tw_render_wide(c2, w, h, NULL);
    CHECK_EQ_INT(RENDER_WIDE(wide_blob_copy_frame)(b, size, a2, why, sizeof why), 0);
    void *cb2 = tw_wide_ctx(b, size);
    rgb8_t *next = cb2 ? tw_render_wide(cb2, w, h, NULL) : NULL;
    CHECK(next && memcmp(lone, next, n * sizeof *next) == 0);
    free(before);
    free(after);
    free(lone);
    free(next);
    free(ca);
    free(cb);
    free(c2);
    free(cb2);
    free(a2);
    free(b);
    free(narrow);
}

/* The DM's wide load: told the narrow load's word sum and scaling
 * (scene_load_known_of), it makes the scene it makes on its own: every
 * pixel the same, on demo and on anim's frame 1 (clusters scaled and
 * moved); its index handed over from a float load, not from a fixed one. */
static void test_wide_known_same(void)
{
    const char *names[] = {"demo", "anim"};
    for (int i = 0; i < 2; i++) {
        size_t nsize, size, ksize, len;
        render_blob_t *narrow = tb_blob_div(names[i], 1, TW_DIV, &nsize);
        uint8_t *buf = tb_compile_div(names[i], TW_DIV, &len);
        CHECK(narrow && buf);
        if (!narrow || !buf) {
            free(narrow);
            free(buf);
            continue;
        }
        scene_load_known_t known =
            scene_load_known_of(&narrow->scene, wire_get_u32(buf + SCN_HDR_SUM));
        CHECK(known.passed && known.unit_exp == narrow->scene.unit_exp);
#if defined(LINKS1_NUM_FIXED)
        CHECK(known.index.groups == NULL); /* rounded values: decisions of their own */
#else
        CHECK(known.index.groups == narrow->scene.index.groups);
#endif
        void *alone = tw_wide_blob(names[i], 1, &size);
        void *told = tw_wide_blob_known(names[i], 1, &known, &ksize);
        void *ca = alone ? tw_wide_ctx(alone, size) : NULL;
        void *ct = told ? tw_wide_ctx(told, ksize) : NULL;
        uint32_t w = narrow->frame->width, h = narrow->frame->height;
        rgb8_t *a = ca ? tw_render_wide(ca, w, h, NULL) : NULL;
        rgb8_t *t = ct ? tw_render_wide(ct, w, h, NULL) : NULL;
        CHECK(a && t && memcmp(a, t, sizeof *a * w * h) == 0);
        free(a);
        free(t);
        free(ca);
        free(ct);
        free(alone);
        free(told);
        free(buf);
        free(narrow);
    }
}

/* Refusals name their problem: a block with no blob, a context not
 * aligned, a block too small for the wide scene. */
static void test_wide_errors(void)
{
    char why[RENDER_BLOB_MSG_MAX];
    void *empty = tb_block(4096);
    void *mem = aligned_alloc(RENDER_WIDE_CTX_ALIGN, (RENDER_WIDE(wide_ctx_bytes)() + 15) & ~7u);
    CHECK_EQ_INT(RENDER_WIDE(wide_ctx_open)(mem, empty, 4096, 1, 1, 0, why, sizeof why), -1);
    CHECK(strstr(why, "no blob") != NULL);
    CHECK_EQ_INT(RENDER_WIDE(wide_ctx_open)((uint8_t *)mem + 1, empty, 4096, 1, 1, 0, why,
                                            sizeof why),
                 -1);
    CHECK(strstr(why, "aligned") != NULL);
    size_t len;
    uint8_t *buf = tb_compile_div("demo", TW_DIV, &len);
    CHECK_EQ_INT(RENDER_WIDE(wide_blob_load)(buf, len, NULL, empty, 4096, "the small block", 1, why,
                                             sizeof why),
                 -1);
    CHECK(strstr(why, "the small block") != NULL && strstr(why, "double") != NULL);
    CHECK(render_wide_linked());
    free(buf);
    free(mem);
    free(empty);
}

int main(void)
{
    RUN(test_wide_escalates_lost_pixels);
    RUN(test_wide_check_keeps_colours);
    RUN(test_wide_area_same_as_pixels);
    RUN(test_wide_copy_frame);
    RUN(test_wide_known_same);
    RUN(test_wide_errors);
    return check_exit();
}
