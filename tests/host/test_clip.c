/* test_clip.c: the NC's screen clipping.  The Y list is exactly the
 * clusters whose rectangle meets the area, sorted by (screen_x0, index);
 * the X list at each pixel exactly those of the Y list holding its x;
 * rendering areas with clipping gives the image of the plain full walk bit
 * for bit, with fewer primary-ray tests; each speed-up switched off gives
 * the same image.  The Y list's walk down the tree (pruned by each
 * cluster's tree rectangle) equals the old walk over every cluster on
 * random areas, also on a scene of thousands of clusters. */
#include "tests/check.h"
#include "tests/host/render_fixture.h"
#include "tests/host/test_blob_util.h"

#define TC_TILE 16 /* side of the square areas the whole-image tests use */
/* The scenes of scenes/ at half their resolution (160x120, anim 80x60):
 * every check here compares two walks or two images of the same frame,
 * which hold at any size, and the whole-image renders (under ASan, three
 * arithmetics) were most of make test's host time at full size. */
#define TC_SIZE_DIV 2

static int tc_open(rf_scene_t *t, const char *name)
{
    return rf_open(t, name, strcmp(name, "anim") == 0 ? 2 : 0, TC_SIZE_DIV);
}

static int tc_meets(const render_cluster_t *c, const render_area_t *a)
{
    return c->screen_x0 <= c->screen_x1 && c->screen_y0 <= c->screen_y1 &&
           c->screen_x1 >= (int32_t)a->x && c->screen_x0 <= (int32_t)(a->x + a->w - 1) &&
           c->screen_y1 >= (int32_t)a->y && c->screen_y0 <= (int32_t)(a->y + a->h - 1);
}

/* Brute force: every cluster tested, then an insertion sort. */
static uint32_t tc_brute_y(const render_frame_t *f, const render_area_t *a, uint32_t *out)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < f->cluster_count; i++) {
        if (!tc_meets(&f->clusters[i], a))
            continue;
        uint32_t j = n++;
        while (j > 0 && f->clusters[out[j - 1]].screen_x0 > f->clusters[i].screen_x0) {
            out[j] = out[j - 1];
            j--;
        }
        out[j] = i;
    }
    return n;
}

/* Areas the way the RC cuts screens: the whole screen, single scanlines,
 * pieces of one scanline, square tiles. */
static uint32_t tc_areas(const render_frame_t *f, render_area_t *out, uint32_t max)
{
    uint32_t n = 0, W = f->width, H = f->height;
    out[n++] = (render_area_t){0, 0, W, H};
    for (uint32_t y = 0; y < H && n < max; y += 7)
        out[n++] = (render_area_t){0, y, W, 1};
    for (uint32_t x = 0; x < W && n < max; x += 40)
        out[n++] = (render_area_t){x, H / 2, W - x < 40 ? W - x : 40, 1};
    for (uint32_t y = 0; y < H; y += 32)
        for (uint32_t x = 0; x < W && n < max; x += 32)
            out[n++] = (render_area_t){x, y, W - x < 32 ? W - x : 32, H - y < 32 ? H - y : 32};
    return n;
}

#define TC_MAX_AREAS 256

static void test_clip_y_matches_brute_force(void)
{
    for (size_t s = 0; s < TB_SCENE_COUNT; s++) {
        rf_scene_t t;
        CHECK(tc_open(&t, tb_scenes[s]));
        if (!t.blob)
            continue;
        render_area_t areas[TC_MAX_AREAS];
        uint32_t na = tc_areas(t.f, areas, TC_MAX_AREAS);
        uint32_t *want = malloc(sizeof *want * t.f->cluster_count);
        int exact = 1, sorted = 1, some_cut = 0;
        for (uint32_t i = 0; i < na; i++) {
            uint32_t n = render_clip_y(&t.clip, &areas[i], 0);
            uint32_t m = tc_brute_y(t.f, &areas[i], want);
            exact &= n == m && memcmp(t.clip.ylist, want, n * sizeof *want) == 0;
            for (uint32_t k = 1; k < n; k++) {
                const render_cluster_t *p = &t.f->clusters[t.clip.ylist[k - 1]];
                const render_cluster_t *q = &t.f->clusters[t.clip.ylist[k]];
                sorted &= p->screen_x0 < q->screen_x0 ||
                          (p->screen_x0 == q->screen_x0 && t.clip.ylist[k - 1] < t.clip.ylist[k]);
            }
            some_cut |= n < render_clip_y(&t.clip, &areas[i], 1);
        }
        if (!exact || !sorted)
            printf("%s: Y list differs from brute force\n", tb_scenes[s]);
        CHECK(exact);
        CHECK(sorted);
        CHECK(some_cut); /* Y clipping leaves clusters out somewhere */
        free(want);
        rf_close(&t);
    }
}

/* A scene of n small triangles scattered in front of the eye, a few
 * straddling the eye plane and a few behind it, in one author cluster the
 * compiler splits into a deep automatic hierarchy (thousands of clusters). */
static char *tc_scatter_text(uint32_t n, uint32_t seed)
{
    size_t cap = 256 + (size_t)n * 160, len = 0;
    char *t = malloc(cap);
    len += (size_t)snprintf(t + len, cap - len,
                            "camera { eye 0 0 -10  look_at 0 0 0  up 0 1 0  fov 60 }\n"
                            "resolution 96 72\nbackground 0 0 0\n"
                            "light point { colour 1 1 1  position 5 10 -10 }\n"
                            "material a { colour 0.8 0.6 0.4  dic 0.2 drc 0.8 }\n"
                            "cluster cloud { rotate 10 20 0\n");
    uint32_t r = seed;
    for (uint32_t i = 0; i < n; i++) {
        double v[9];
        for (int k = 0; k < 9; k++) {
            r = r * 1103515245u + 12345u;
            double u = ((r >> 8) & 0xffff) / 65535.0;
            v[k] = k < 3 ? (k == 2 ? -14 + 30 * u : -8 + 16 * u) : v[k % 3] + 0.6 * (u - 0.5);
        }
        len += (size_t)snprintf(t + len, cap - len,
                                "triangle { material a  v %.3f %.3f %.3f  v %.3f %.3f %.3f  v %.3f %.3f %.3f }\n",
                                v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
    }
    snprintf(t + len, cap - len, "}\n");
    return t;
}

/* The scattered scene compiled as a blob, in t (as tc_open). */
static int tc_open_scatter(rf_scene_t *t, uint32_t n, uint32_t seed)
{
    char err[SD_ERR_MAX];
    struct sd_scene s;
    uint8_t *buf = NULL;
    size_t len, need;
    render_blob_error_t be;
    memset(t, 0, sizeof *t);
    char *text = tc_scatter_text(n, seed);
    int ok = sd_parse_text("scatter.scn", text, &s, err, sizeof err) == 0;
    free(text);
    if (!ok) {
        printf("scatter: %s\n", err);
        return 0;
    }
    ok = sd_compile(&s, &buf, &len, err, sizeof err) == 0;
    sd_free(&s);
    if (ok && render_blob_bytes(buf, len, &need, &be) == RENDER_BLOB_OK) {
        void *block = tb_block(need);
        if (render_blob_build(buf, len, 0, block, need, "the test block", &t->blob, &be) != RENDER_BLOB_OK)
            free(block);
    }
    free(buf);
    if (!t->blob)
        return 0;
    t->f = t->blob->frame;
    return rf_clip(t);
}

/* Each cluster's tree rectangle is exactly the union of the screen
 * rectangles of it and every cluster below it (empty when they all are). */
static int tc_tree_rects_exact(const render_frame_t *f)
{
    uint32_t n = f->cluster_count;
    int32_t *u = malloc(4 * sizeof *u * n);
    uint32_t *parent = malloc(sizeof *parent * n);
    for (uint32_t i = 0; i < n; i++) {
        u[4 * i] = u[4 * i + 1] = 1;
        u[4 * i + 2] = u[4 * i + 3] = 0;
        parent[i] = UINT32_MAX;
    }
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t k = 0; k < f->clusters[i].child_count; k++)
            parent[f->child_list[f->clusters[i].first_child + k]] = i;
    for (uint32_t i = 0; i < n; i++) {
        const render_cluster_t *c = &f->clusters[i];
        if (c->screen_x0 > c->screen_x1 || c->screen_y0 > c->screen_y1)
            continue;
        for (uint32_t a = i; a != UINT32_MAX; a = parent[a]) {
            int32_t *r = &u[4 * a];
            int empty = r[0] > r[2];
            r[0] = empty || c->screen_x0 < r[0] ? c->screen_x0 : r[0];
            r[1] = empty || c->screen_y0 < r[1] ? c->screen_y0 : r[1];
            r[2] = empty || c->screen_x1 > r[2] ? c->screen_x1 : r[2];
            r[3] = empty || c->screen_y1 > r[3] ? c->screen_y1 : r[3];
        }
    }
    int same = 1;
    for (uint32_t i = 0; i < n; i++) {
        const render_cluster_t *c = &f->clusters[i];
        int want_empty = u[4 * i] > u[4 * i + 2];
        int got_empty = c->tree_x0 > c->tree_x1 || c->tree_y0 > c->tree_y1;
        same &= want_empty == got_empty;
        if (!want_empty)
            same &= c->tree_x0 == u[4 * i] && c->tree_y0 == u[4 * i + 1] &&
                    c->tree_x1 == u[4 * i + 2] && c->tree_y1 == u[4 * i + 3];
    }
    free(u);
    free(parent);
    return same;
}

/* The tree walk of Y clipping (pruned by tree rectangles) gives exactly
 * the list of the old walk over every cluster (tc_brute_y) on random
 * areas of every shape, on the scenes of scenes/ and on scattered
 * triangles with thousands of clusters; and the deep scene's hierarchy
 * has clusters whose tree rectangle misses some areas, so the walk does
 * prune there. */
static void test_clip_y_tree_walk_random_areas(void)
{
    uint32_t rs = 12345u;
    for (size_t s = 0; s < TB_SCENE_COUNT + 2; s++) {
        rf_scene_t t;
        const char *name = s < TB_SCENE_COUNT ? tb_scenes[s] : s == TB_SCENE_COUNT ? "scatter 3000" : "scatter 200";
        int ok = s < TB_SCENE_COUNT ? tc_open(&t, name) : tc_open_scatter(&t, s == TB_SCENE_COUNT ? 3000 : 200, 7u + (uint32_t)s);
        CHECK(ok);
        if (!t.blob)
            continue;
        const render_frame_t *f = t.f;
        if (s == TB_SCENE_COUNT)
            CHECK(f->cluster_count > 1000);
        CHECK(tc_tree_rects_exact(f));
        uint32_t *want = malloc(sizeof *want * f->cluster_count);
        int exact = 1, pruned = 0;
        for (uint32_t i = 0; i < 2000; i++) {
            uint32_t v[4];
            for (int k = 0; k < 4; k++) {
                rs = rs * 1664525u + 1013904223u;
                v[k] = rs >> 8;
            }
            render_area_t a;
            /* small areas mostly, like the RC's finest grids; some big */
            uint32_t maxw = i % 8 == 0 ? f->width : 1 + f->width / 16;
            uint32_t maxh = i % 8 == 0 ? f->height : 1 + f->height / 16;
            a.w = 1 + v[0] % maxw;
            a.h = 1 + v[1] % maxh;
            a.x = v[2] % (f->width - a.w + 1);
            a.y = v[3] % (f->height - a.h + 1);
            uint32_t n = render_clip_y(&t.clip, &a, 0);
            uint32_t m = tc_brute_y(f, &a, want);
            int same = n == m && memcmp(t.clip.ylist, want, n * sizeof *want) == 0;
            if (!same && exact)
                printf("%s: area %ux%u at (%u,%u): tree walk %u clusters, old walk %u\n", name, a.w, a.h,
                       a.x, a.y, n, m);
            exact &= same;
            for (uint32_t c = 1; c < f->cluster_count && !pruned; c++) {
                const render_cluster_t *k = &f->clusters[c];
                pruned |= k->child_count > 0 && k->tree_x0 <= k->tree_x1 &&
                          (k->tree_x1 < (int32_t)a.x || k->tree_x0 > (int32_t)(a.x + a.w - 1) ||
                           k->tree_y1 < (int32_t)a.y || k->tree_y0 > (int32_t)(a.y + a.h - 1));
            }
        }
        CHECK(exact);
        if (s == TB_SCENE_COUNT)
            CHECK(pruned); /* whole subtrees off the area: the walk skips them */
        free(want);
        rf_close(&t);
    }
}

/* At every pixel of every area, raster order: the X list holds exactly the
 * Y-list clusters whose X range holds x, each once, nearest own box first. */
static void test_clip_x_matches_brute_force(void)
{
    for (size_t s = 0; s < TB_SCENE_COUNT; s++) {
        rf_scene_t t;
        CHECK(tc_open(&t, tb_scenes[s]));
        if (!t.blob)
            continue;
        const render_cluster_t *cl = t.f->clusters;
        uint8_t *mark = calloc(t.f->cluster_count, 1);
        render_area_t areas[TC_MAX_AREAS];
        uint32_t na = tc_areas(t.f, areas, TC_MAX_AREAS);
        int exact = 1, z_sorted = 1;
        uint64_t checked = 0;
        for (uint32_t i = 0; i < na; i++) {
            const render_area_t *a = &areas[i];
            render_clip_y(&t.clip, a, 0);
            for (uint32_t y = a->y; y < a->y + a->h; y++)
                for (uint32_t x = a->x; x < a->x + a->w; x++) {
                    uint32_t n = render_clip_x(&t.clip, (int32_t)x);
                    uint32_t want = 0;
                    for (uint32_t k = 0; k < t.clip.ycount; k++) {
                        uint32_t c = t.clip.ylist[k];
                        want += cl[c].screen_x0 <= (int32_t)x && cl[c].screen_x1 >= (int32_t)x;
                    }
                    uint32_t good = 0;
                    for (uint32_t k = 0; k < n; k++) {
                        uint32_t c = t.clip.xlist[k];
                        good += !mark[c] && cl[c].screen_x0 <= (int32_t)x && cl[c].screen_x1 >= (int32_t)x;
                        mark[c] = 1;
                    }
                    for (uint32_t k = 0; k < n; k++)
                        mark[t.clip.xlist[k]] = 0;
                    /* nearest own box first */
                    for (uint32_t k = 1; k < n; k++)
                        z_sorted &= !num_lt(cl[t.clip.xlist[k]].own_bounds.lo.z,
                                            cl[t.clip.xlist[k - 1]].own_bounds.lo.z);
                    exact &= n == want && good == n;
                    checked++;
                }
        }
        /* going backwards restarts the window and still answers right */
        render_area_t whole = {0, 0, t.f->width, t.f->height};
        render_clip_y(&t.clip, &whole, 0);
        for (int32_t x = t.f->width - 1; x >= 0; x -= 13) {
            uint32_t n = render_clip_x(&t.clip, x), want = 0;
            for (uint32_t k = 0; k < t.clip.ycount; k++)
                want += cl[t.clip.ylist[k]].screen_x0 <= x && cl[t.clip.ylist[k]].screen_x1 >= x;
            exact &= n == want;
        }
        if (!exact)
            printf("%s: X list differs from brute force\n", tb_scenes[s]);
        CHECK(exact);
        CHECK(z_sorted);
        CHECK(checked > (uint64_t)t.f->width * t.f->height);
        free(mark);
        rf_close(&t);
    }
}

/* Clipping, by the paper's lists and in the tree, gives render_pixel's
 * image with the same rays; the lists cut the camera rays' tests, the tree
 * skips subtrees by their rectangles before any box test. */
static void test_clipped_render_same_image(void)
{
    for (size_t s = 0; s < TB_SCENE_COUNT; s++) {
        rf_scene_t t;
        CHECK(tc_open(&t, tb_scenes[s]));
        if (!t.blob)
            continue;
        size_t n = (size_t)t.f->width * t.f->height;
        render_stats_t plain_stats, clip_stats;
        rgb8_t *plain = tb_render_plain(t.f, &plain_stats);
        for (int lists = 1; lists >= 0; lists--) {
            render_clip_options_t both = {1, 1, NULL, (uint8_t)lists};
            rgb8_t *clipped = rf_areas(&t, TC_TILE, TC_TILE, NULL, &both, &clip_stats);
            if (!tb_same(plain, clipped, n))
                printf("%s: clipped image differs (%s)\n", tb_scenes[s], lists ? "lists" : "tree");
            CHECK(tb_same(plain, clipped, n));
            /* the same rays; fewer tests on the camera rays, none elsewhere */
            CHECK_EQ_INT(clip_stats.primary, plain_stats.primary);
            CHECK_EQ_INT(clip_stats.shadow, plain_stats.shadow);
            CHECK_EQ_INT(clip_stats.prim_tests - clip_stats.primary_prim_tests,
                         plain_stats.prim_tests - plain_stats.primary_prim_tests);
            if (lists) { /* fewer tests in all: the plain walk tests a
                            primitive's own box too, and may meet as few */
                CHECK(clip_stats.primary_prim_tests + clip_stats.primary_box_tests <
                      plain_stats.primary_prim_tests + plain_stats.primary_box_tests);
                CHECK(clip_stats.primary_box_tests < plain_stats.primary_box_tests);
                CHECK_EQ_INT(clip_stats.screen_tests, 0);
            } else {
                CHECK(clip_stats.primary_prim_tests <= plain_stats.primary_prim_tests);
                CHECK(clip_stats.screen_tests > 0);
            }
            printf("%s (%s): primary prim tests %llu clipped, %llu plain; primary box tests "
                   "%llu, %llu; rectangles %llu\n", tb_scenes[s], lists ? "lists" : "tree",
                   (unsigned long long)clip_stats.primary_prim_tests,
                   (unsigned long long)plain_stats.primary_prim_tests,
                   (unsigned long long)clip_stats.primary_box_tests,
                   (unsigned long long)plain_stats.primary_box_tests,
                   (unsigned long long)clip_stats.screen_tests);
            free(clipped);
        }
        free(plain);
        rf_close(&t);
    }
}

/* Y clipping, X clipping, bounding boxes, hierarchy: each off alone, and
 * all off, give the image of all on. */
static void test_area_switches_same_image(void)
{
    const char *names[] = {"demo", "city"};
    for (int s = 0; s < 2; s++) {
        rf_scene_t t;
        CHECK(tc_open(&t, names[s]));
        if (!t.blob)
            continue;
        size_t n = (size_t)t.f->width * t.f->height;
        render_options_t on = t.f->options;
        on.use_bounds = on.use_hierarchy = 1;
        render_clip_options_t both = {1, 1, NULL, 1};
        render_stats_t ref_stats, st;
        rgb8_t *ref = rf_areas(&t, TC_TILE, TC_TILE, &on, &both, &ref_stats);
        for (int off = 0; off < 6; off++) {
            render_options_t o = on;
            render_clip_options_t c = both;
            if (off == 0 || off == 4)
                c.y_clip = 0;
            if (off == 1 || off == 4)
                c.x_clip = 0;
            if (off == 2 || off == 4)
                o.use_bounds = 0;
            if (off == 3 || off == 4)
                o.use_hierarchy = 0;
            if (off == 5)
                c.lists = 0; /* clipping in the tree */
            uint64_t y_kept = t.clip.y_kept, x_kept = t.clip.x_kept;
            rgb8_t *img = rf_areas(&t, TC_TILE, TC_TILE, &o, &c, &st);
            if (!tb_same(ref, img, n))
                printf("%s: switch set %d changes the image\n", names[s], off);
            CHECK(tb_same(ref, img, n));
            /* each switch does something measurable */
            if (off == 0)
                CHECK(t.clip.y_kept - y_kept > ref_stats.primary / n); /* all kept */
            if (off == 0 || off == 1) /* more candidates: their boxes reject them */
                CHECK(st.primary_box_tests + st.primary_prim_tests >
                      ref_stats.primary_box_tests + ref_stats.primary_prim_tests);
            if (off == 1)
                CHECK_EQ_INT(t.clip.x_kept, x_kept); /* no X clipping done */
            if (off == 2)
                CHECK(st.box_tests == 0 && st.prim_tests > ref_stats.prim_tests);
            if (off == 4)
                CHECK(st.primary_prim_tests > ref_stats.primary_prim_tests);
            if (off == 5) /* no lists: rectangles in the tree instead */
                CHECK(t.clip.y_kept == y_kept && t.clip.x_kept == x_kept && st.screen_tests > 0);
            free(img);
        }
        free(ref);
        rf_close(&t);
    }
}

/* Memory is what render_clip_bytes says; bad areas are refused. */
static void test_clip_memory_and_errors(void)
{
    rf_scene_t t;
    CHECK(tc_open(&t, "molecule"));
    if (!t.blob)
        return;
    size_t bytes = render_clip_bytes(t.f);
    CHECK_EQ_INT(bytes, 2 * sizeof(uint32_t) * t.f->cluster_count);
    render_clip_t c;
    uint32_t *mem = malloc(bytes + 4);
    CHECK_EQ_INT(render_clip_init(&c, t.f, mem, bytes - 1), RENDER_ERR_ARENA);
    CHECK_EQ_INT(render_clip_init(&c, t.f, (uint8_t *)mem + 1, bytes), RENDER_ERR_ARENA);
    CHECK_EQ_INT(render_clip_init(&c, t.f, mem, bytes), RENDER_OK);
    render_ctx_t ctx;
    render_ctx_init(&ctx, t.f);
    render_clip_options_t both = {1, 1, NULL, 0};
    rgb8_t px[4];
    uint32_t W = t.f->width, H = t.f->height;
    render_area_t bad[] = {{0, 0, 0, 1}, {0, 0, 1, 0}, {W, 0, 1, 1}, {W - 1, 0, 2, 1}, {0, H - 1, 1, 2}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        CHECK_EQ_INT(render_area(&ctx, &c, &bad[i], &both, px), RENDER_ERR_AREA);
    render_area_t corner = {W - 2, H - 2, 2, 2};
    CHECK_EQ_INT(render_area(&ctx, &c, &corner, &both, px), RENDER_OK);
    CHECK(render_status_name(RENDER_ERR_AREA)[0] != 0);
    free(mem);
    rf_close(&t);
}

/* options.spd_rules: one area over the whole screen traces (w+1) x (h+1)
 * corner rays; areas of TC_TILE, clipped by lists, in the tree or not at
 * all, give its image and count its rays exactly (each corner once over
 * the frame), and render_pixel (four corners of its own a pixel) its
 * image with four camera rays a pixel. */
static void test_spd_rules_corners(void)
{
    const char *names[] = {"demo", "glass"};
    for (int s = 0; s < 2; s++) {
        rf_scene_t t;
        CHECK(tc_open(&t, names[s]));
        if (!t.blob)
            continue;
        t.f->options.spd_rules = 1; /* the test's own copy */
        size_t n = (size_t)t.f->width * t.f->height;
        CHECK(rf_clip(&t));
        render_clip_options_t tree = {1, 1, NULL, 0}, lists = {1, 1, NULL, 1}, none = {0, 0, NULL, 0};
        render_stats_t whole_st, st;
        rgb8_t *whole = rf_areas(&t, t.f->width, t.f->height, NULL, &tree, &whole_st);
        CHECK_EQ_INT(whole_st.primary, (uint64_t)(t.f->width + 1) * (t.f->height + 1));
        CHECK(whole_st.primary_hit > 0 && whole_st.primary_hit < whole_st.primary);
        const render_clip_options_t *modes[3] = {&tree, &lists, &none};
        for (int m = 0; m < 3; m++) {
            rgb8_t *tiled = rf_areas(&t, TC_TILE, TC_TILE, NULL, modes[m], &st);
            if (!tb_same(whole, tiled, n) || !rf_same_rays(&whole_st, &st))
                printf("%s: areas (mode %d) differ from the whole screen's\n", names[s], m);
            CHECK(tb_same(whole, tiled, n));
            CHECK(rf_same_rays(&whole_st, &st));
            free(tiled);
        }
        rgb8_t *plain = tb_render_plain(t.f, &st);
        CHECK(tb_same(whole, plain, n));
        CHECK_EQ_INT(st.primary, 4 * (uint64_t)n);
        printf("%s: %llu corner rays, %llu hit; %llu reflected, %llu refracted, %llu shadow\n",
               names[s], (unsigned long long)whole_st.primary,
               (unsigned long long)whole_st.primary_hit, (unsigned long long)whole_st.reflection,
               (unsigned long long)whole_st.refraction, (unsigned long long)whole_st.shadow);
        free(plain);
        free(whole);
        rf_close(&t);
    }
}

int main(void)
{
    RUN(test_clip_y_matches_brute_force);
    RUN(test_clip_y_tree_walk_random_areas);
    RUN(test_clip_x_matches_brute_force);
    RUN(test_clipped_render_same_image);
    RUN(test_area_switches_same_image);
    RUN(test_clip_memory_and_errors);
    RUN(test_spd_rules_corners);
    return check_exit();
}
