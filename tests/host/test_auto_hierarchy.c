/* test_auto_hierarchy.c: the scene compiler's automatic hierarchy
 * (host-tools/scene/scene_bvh.c), built once per arithmetic.
 *   - the tree's invariants: every primitive in exactly one leaf below its
 *     own cluster, nodes are identity clusters without keys, parents before
 *     children, the nesting limit kept, every prepared box holding its
 *     children and primitives;
 *   - the image is bit for bit the same with the hierarchy on and off, on
 *     several scenes (spheres, a mesh, a moving keyframed cluster, nested
 *     author clusters), through both the full tree walk and the NC's
 *     clipped area loop;
 *   - a smaller frame (fewer rays) gets fewer clusters and larger leaves;
 *   - slivers lying along the camera's up axis, which is not the world's,
 *     get the tree built in the camera's axes, cheaper there by the cost
 *     the compiler judges it by, and the same image; in world space, and
 *     under a camera whose axes are the world's, only the clusters' own
 *     is built;
 *   - a scene that would need more clusters than the format holds, more
 *     bytes, or more of the board's memory than an IMSU block, is refused,
 *     naming the limit and the count (and one exactly at the board's
 *     limit passes).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_board.h"
#include "host-tools/scene/scene_bvh.h"
#include "host-tools/scene/scene_desc.h"
#include "render/clip.h"
#include "render/render.h"
#include "render/scene_load.h"
#include "tests/check.h"

#define ARENA_BYTES (96u * 1024u * 1024u)

/* a small repeatable generator */
static unsigned rnd_state;
static double rnd(double lo, double hi)
{
    rnd_state = rnd_state * 1103515245u + 12345u;
    return lo + (hi - lo) * ((rnd_state >> 8) & 0xffff) / 65535.0;
}

static char *text_grow(char *t, size_t *len, size_t *cap, const char *add)
{
    size_t n = strlen(add);
    if (*len + n + 1 > *cap) {
        *cap = (*len + n + 1) * 2;
        t = realloc(t, *cap);
    }
    memcpy(t + *len, add, n + 1);
    *len += n;
    return t;
}

/* 48x36 (three 16x12 areas each way, render_all's): the images are
 * compared on and off the hierarchy, which holds at any size, and whole
 * images under ASan in three arithmetics cost make test's host time. */
static const char *head =
    "camera { eye 0 5 -12  look_at 0 0.5 0  up 0 1 0  fov 55 }\n"
    "resolution 48 36\nbackground 0.1 0.1 0.2\n"
    "options { max_depth 3 }\nanimation { frames 4 }\n"
    "light point { colour 0.7 0.7 0.7  position 5 10 -6 }\n"
    "light parallel { colour 0.3 0.3 0.3  direction 0.3 -1 0.5 }\n"
    "material a { colour 0.9 0.3 0.2  dic 0.2 drc 0.7 src 0.3 phong 20 }\n"
    "material g { colour 0.5 0.8 0.9  dic 0.1 drc 0.2 src 0.1 trc 0.7 ior 1.3 }\n"
    "box { material a  min -9 -1.5 -9  max 9 -1 9 }\n";

/* The camera's up axis in head's view (up x forward, then forward x
 * right): (0, 12, 4.5) / |(0, 12, 4.5)|. */
static const double head_up[3] = {0, 0.936329, 0.351123};

/* kind 0: spheres (some glass) in the root; 1: a mesh of triangles in a
 * rotated cluster; 2: spheres in a keyframed cluster and nested clusters;
 * 3: slivers 1.2 long along the camera's up axis, 0.05 wide along x */
static char *make_scene(int kind, int n)
{
    size_t len = 0, cap = 0;
    char *t = text_grow(NULL, &len, &cap, head);
    char line[256];
    rnd_state = 7u + (unsigned)kind;
    if (kind == 1)
        t = text_grow(t, &len, &cap, "cluster mesh { rotate 10 30 0  translate 0 0.5 0\n");
    if (kind == 2)
        t = text_grow(t, &len, &cap,
                      "cluster spin { key 0 { translate 0 0 0 } key 3 { translate 1 0.5 0 "
                      "rotate 0 40 0 }\n");
    for (int i = 0; i < n; i++) {
        if (kind == 3) {
            double x = rnd(-4, 4), y = rnd(-1, 2), z = rnd(-4, 4);
            snprintf(line, sizeof line,
                     "triangle { material a  v %.4f %.4f %.4f  v %.4f %.4f %.4f  v %.4f %.4f %.4f }\n",
                     x, y, z, x + 0.05, y, z, x, y + 1.2 * head_up[1], z + 1.2 * head_up[2]);
        } else if (kind == 1) {
            double x = rnd(-4, 4), y = rnd(-1, 3), z = rnd(-4, 4);
            snprintf(line, sizeof line,
                     "triangle { material a  v %.3f %.3f %.3f  v %.3f %.3f %.3f  v %.3f %.3f %.3f }\n",
                     x, y, z, x + rnd(-0.6, 0.6), y + rnd(-0.6, 0.6), z + rnd(-0.6, 0.6),
                     x + rnd(-0.6, 0.6), y + rnd(-0.6, 0.6), z + rnd(-0.6, 0.6));
        } else {
            snprintf(line, sizeof line, "sphere { material %s  centre %.3f %.3f %.3f  radius %.3f }\n",
                     i % 4 ? "a" : "g", rnd(-6, 6), rnd(-1, 3), rnd(-6, 6), rnd(0.1, 0.5));
        }
        t = text_grow(t, &len, &cap, line);
        if (kind == 2 && i == n / 2) /* a nested author cluster of its own */
            t = text_grow(t, &len, &cap, "cluster inner { translate 0 1 0 scale 0.5 0.5 0.5\n");
    }
    if (kind == 2)
        t = text_grow(t, &len, &cap, "}\n");
    if (kind == 1 || kind == 2)
        t = text_grow(t, &len, &cap, "}\n");
    return t;
}

static int parse(const char *text, struct sd_scene *s)
{
    char err[SD_ERR_MAX];
    if (sd_parse_text("t.scn", text, s, err, sizeof err) != 0) {
        printf("# parse: %s\n", err);
        return -1;
    }
    return 0;
}

/* nesting of cluster i below the root */
static int nesting(const struct sd_cluster *c, int i)
{
    int d = 0;
    while (i > 0) {
        i = c[i].parent;
        d++;
    }
    return d;
}

static void check_tree(const struct sd_scene *s)
{
    struct sd_cluster *cl;
    int n = 0;
    int *pc = malloc((size_t)s->n_prims * sizeof *pc);
    struct bvh_build_stats st;
    char err[SD_ERR_MAX];
    CHECK_EQ_INT(sd_auto_hierarchy(s, &cl, &n, pc, &st, err, sizeof err), 0);
    CHECK(n > s->n_clusters);
    CHECK(st.nodes == n - s->n_clusters);
    CHECK(memcmp(cl, s->clusters, (size_t)s->n_clusters * sizeof *cl) == 0);
    int *prims_in = calloc((size_t)n, sizeof *prims_in);
    int *kids = calloc((size_t)n, sizeof *kids);
    int bad = 0;
    for (int i = s->n_clusters; i < n; i++) {
        bad += cl[i].parent < 0 || cl[i].parent >= i || cl[i].key_count != 0;
        static const double id[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
        bad += memcmp(cl[i].m, id, sizeof id) != 0;
        bad += nesting(cl, i) > SCN_MAX_CLUSTER_NESTING;
        kids[cl[i].parent]++;
    }
    CHECK_EQ_INT(bad, 0);
    /* every primitive in exactly one leaf (a cluster with no tree children),
     * and that leaf below the cluster the author put it in */
    int misplaced = 0;
    for (int p = 0; p < s->n_prims; p++) {
        int c = pc[p];
        if (c < 0 || c >= n) {
            misplaced++;
            continue;
        }
        prims_in[c]++;
        int a = c;
        while (a >= s->n_clusters)
            a = cl[a].parent;
        misplaced += a != s->prims[p].cluster;
        misplaced += c >= s->n_clusters && kids[c] != 0;
    }
    CHECK_EQ_INT(misplaced, 0);
    /* a node holds primitives or two children, never neither */
    int empty = 0;
    for (int i = s->n_clusters; i < n; i++)
        empty += prims_in[i] == 0 && kids[i] != 2;
    CHECK_EQ_INT(empty, 0);
    free(prims_in);
    free(kids);
    free(pc);
    free(cl);
}

static int box_holds(const aabb_t *outer, const aabb_t *inner)
{
    if (num_gt(inner->lo.x, inner->hi.x))
        return 1; /* empty */
    return !num_gt(outer->lo.x, inner->lo.x) && !num_gt(outer->lo.y, inner->lo.y) &&
           !num_gt(outer->lo.z, inner->lo.z) && !num_lt(outer->hi.x, inner->hi.x) &&
           !num_lt(outer->hi.y, inner->hi.y) && !num_lt(outer->hi.z, inner->hi.z);
}

struct loaded {
    void *mem;
    arena_t arena;
    scene_t scene;
};

static int load(const struct sd_scene *s, int auto_on, struct loaded *L)
{
    struct sd_scene t = *s;
    t.no_auto_hierarchy = !auto_on;
    uint8_t *buf;
    size_t len;
    char err[SD_ERR_MAX];
    if (sd_compile(&t, &buf, &len, err, sizeof err) != 0) {
        printf("# compile: %s\n", err);
        return -1;
    }
    L->mem = malloc(ARENA_BYTES);
    arena_init(&L->arena, L->mem, ARENA_BYTES);
    scene_load_error_t e;
    scene_load_status_t st = scene_load(buf, len, &L->arena, &L->scene, &e);
    free(buf);
    if (st != SCENE_LOAD_OK)
        printf("# load: %s\n", e.message);
    return st == SCENE_LOAD_OK ? 0 : -1;
}

/* every pixel of frame f, through render_pixel (clip 0) or render_area */
static rgb8_t *render_all(struct loaded *L, uint32_t f, int clip, int check_boxes)
{
    size_t mark = L->arena.used;
    render_frame_t *fr;
    if (render_prepare(&L->scene, f, &L->arena, &fr) != RENDER_OK)
        return NULL;
    if (check_boxes) {
        int bad = 0;
        for (uint32_t i = 0; i < fr->cluster_count; i++) {
            const render_cluster_t *c = &fr->clusters[i];
            for (uint32_t k = 0; k < c->child_count; k++)
                bad += !box_holds(&c->bounds, &fr->clusters[fr->child_list[c->first_child + k]].bounds);
            for (uint32_t k = 0; k < c->prim_count; k++)
                bad += !box_holds(&c->own_bounds, &fr->prims[fr->prim_list[c->first_prim + k]].bounds);
        }
        CHECK_EQ_INT(bad, 0);
    }
    size_t n = (size_t)fr->width * fr->height;
    rgb8_t *img = malloc(n * sizeof *img);
    render_ctx_t ctx;
    render_ctx_init(&ctx, fr);
    if (!clip) {
        for (uint32_t y = 0; y < fr->height; y++)
            render_span(&ctx, y, 0, fr->width, img + (size_t)y * fr->width);
    } else {
        void *cm = malloc(render_clip_bytes(fr));
        render_clip_t cs;
        render_clip_options_t opt = {1, 1, NULL, 0};
        CHECK_EQ_INT(render_clip_init(&cs, fr, cm, render_clip_bytes(fr)), RENDER_OK);
        /* areas of 16 x 12 as an NC gets them */
        rgb8_t *area = malloc(16 * 12 * sizeof *area);
        for (uint32_t y = 0; y < fr->height; y += 12)
            for (uint32_t x = 0; x < fr->width; x += 16) {
                render_area_t a = {x, y, 16, 12};
                CHECK_EQ_INT(render_area(&ctx, &cs, &a, &opt, area), RENDER_OK);
                for (uint32_t r = 0; r < 12; r++)
                    memcpy(img + (size_t)(y + r) * fr->width + x, area + r * 16, 16 * sizeof *area);
            }
        free(area);
        free(cm);
    }
    arena_release_to(&L->arena, mark);
    return img;
}

static void check_same_images(int kind, int n)
{
    char *text = make_scene(kind, n);
    struct sd_scene s;
    CHECK_EQ_INT(parse(text, &s), 0);
    free(text);
    check_tree(&s);
    struct loaded on, off;
    CHECK_EQ_INT(load(&s, 1, &on), 0);
    CHECK_EQ_INT(load(&s, 0, &off), 0);
    CHECK(on.scene.cluster_count > off.scene.cluster_count);
    size_t bytes = (size_t)on.scene.width * on.scene.height * sizeof(rgb8_t);
    uint32_t frames[2] = {0, 2};
    for (int k = 0; k < 2; k++) {
        rgb8_t *a = render_all(&off, frames[k], 0, 0);
        rgb8_t *b = render_all(&on, frames[k], 0, 1);
        rgb8_t *c = render_all(&on, frames[k], 1, 0);
        CHECK(a && b && c);
        if (a && b && c) {
            CHECK(memcmp(a, b, bytes) == 0);
            CHECK(memcmp(a, c, bytes) == 0);
            /* not a blank picture: the objects are in view */
            int differ = 0;
            for (size_t i = 1; i < bytes / sizeof *a; i++)
                differ += a[i].r != a[0].r || a[i].g != a[0].g || a[i].b != a[0].b;
            CHECK(differ > 100);
        }
        free(a);
        free(b);
        free(c);
    }
    free(on.mem);
    free(off.mem);
    sd_free(&s);
}

static void test_same_image_spheres(void) { check_same_images(0, 400); }
static void test_same_image_mesh(void) { check_same_images(1, 1500); }
static void test_same_image_keyframed_nested(void) { check_same_images(2, 300); }
static void test_same_image_camera_axes(void) { check_same_images(3, 600); }

/* a cluster 30 deep with 2000 primitives: the tree must fit the 2 levels
 * left (big leaves), and the loader must accept the result */
static void test_nesting_limit_kept(void)
{
    size_t len = 0, cap = 0;
    char *t = text_grow(NULL, &len, &cap, head);
    char line[160];
    for (int d = 0; d < SCN_MAX_CLUSTER_NESTING - 2; d++)
        t = text_grow(t, &len, &cap, "cluster c { translate 0 0 0\n");
    rnd_state = 99;
    for (int i = 0; i < 2000; i++) {
        snprintf(line, sizeof line, "sphere { material a  centre %.3f %.3f %.3f  radius 0.05 }\n",
                 rnd(-5, 5), rnd(-1, 3), rnd(-5, 5));
        t = text_grow(t, &len, &cap, line);
    }
    for (int d = 0; d < SCN_MAX_CLUSTER_NESTING - 2; d++)
        t = text_grow(t, &len, &cap, "}\n");
    struct sd_scene s;
    CHECK_EQ_INT(parse(t, &s), 0);
    free(t);
    check_tree(&s);
    struct loaded L;
    CHECK_EQ_INT(load(&s, 1, &L), 0);
    rgb8_t *img = render_all(&L, 0, 0, 1);
    CHECK(img != NULL);
    free(img);
    free(L.mem);
    sd_free(&s);
}

#if defined(LINKS1_NUM_DOUBLE)
/* more author clusters than leave room for the tree: refused, naming the
 * limit and the count */
static void test_cluster_limit_named(void)
{
    struct sd_scene s;
    memset(&s, 0, sizeof s);
    s.n_clusters = SCN_MAX_CLUSTERS - 10;
    s.clusters = calloc((size_t)s.n_clusters, sizeof *s.clusters);
    for (int i = 0; i < s.n_clusters; i++) {
        s.clusters[i].parent = i - 1 < 0 ? -1 : 0;
        s.clusters[i].m[0] = s.clusters[i].m[5] = s.clusters[i].m[10] = 1;
    }
    s.n_prims = 20000;
    s.prims = calloc((size_t)s.n_prims, sizeof *s.prims);
    rnd_state = 5;
    for (int i = 0; i < s.n_prims; i++) {
        s.prims[i].kind = SCN_PRIM_ELLIPSOID;
        for (int k = 0; k < 3; k++) {
            s.prims[i].v[k] = rnd(-50, 50);
            s.prims[i].v[3 + k] = 0.1;
        }
    }
    struct sd_cluster *cl = NULL;
    int n;
    int *pc = malloc((size_t)s.n_prims * sizeof *pc);
    struct bvh_build_stats st;
    char err[SD_ERR_MAX] = "";
    CHECK_EQ_INT(sd_auto_hierarchy(&s, &cl, &n, pc, &st, err, sizeof err), -1);
    CHECK(strstr(err, "SCN_MAX_CLUSTERS") != NULL && strstr(err, "1048576") != NULL &&
          strstr(err, "20000") != NULL);
    free(pc);
    free(s.prims);
    free(s.clusters);
}

/* The tree of s for a view of w x h: its clusters (0 when refused), stats
 * in *st. */
static int tree_at(struct sd_scene *s, int w, int h, struct bvh_build_stats *st)
{
    s->view.width = w;
    s->view.height = h;
    struct sd_cluster *cl = NULL;
    int n = 0;
    int *pc = malloc((size_t)s->n_prims * sizeof *pc);
    char err[SD_ERR_MAX];
    if (sd_auto_hierarchy(s, &cl, &n, pc, st, err, sizeof err) != 0)
        n = 0;
    free(pc);
    free(cl);
    return n;
}

/* A split counts the DM's work on its clusters against the rays expected
 * through the node: the same mesh gets fewer clusters and larger leaves
 * (within the cap) for a 16x12 frame than for a 1024x768 one. */
static void test_leaves_follow_rays(void)
{
    char *text = make_scene(1, 1500);
    struct sd_scene s;
    CHECK_EQ_INT(parse(text, &s), 0);
    free(text);
    struct bvh_build_stats small, big;
    int n_small = tree_at(&s, 16, 12, &small), n_big = tree_at(&s, 1024, 768, &big);
    CHECK(n_small > s.n_clusters && n_small < n_big);
    CHECK(small.largest_leaf > big.largest_leaf);
    CHECK(small.largest_leaf <= SD_AUTO_HIERARCHY_LEAF_CAP);
    printf("# 16x12: %d clusters, leaves up to %d; 1024x768: %d, up to %d\n", n_small,
           small.largest_leaf, n_big, big.largest_leaf);
    sd_free(&s);
}

/* The slivers along the camera's up axis, without the floor: built in
 * the camera's axes, whose tree costs less there (the compiler's measure)
 * by more than the margin, and as much with scene and camera turned
 * together; with the scene in world space, or a camera looking down the
 * world's z axis, the clusters' own axes alone (no second tree). */
static void test_camera_axes_kept(void)
{
    char *text = make_scene(3, 1500);
    char *floor = strstr(text, "box {"); /* the slivers alone: no floor */
    CHECK(floor != NULL);
    if (floor)
        memmove(floor, strchr(floor, '\n') + 1, strlen(strchr(floor, '\n') + 1) + 1);
    struct sd_scene s;
    CHECK_EQ_INT(parse(text, &s), 0);
    free(text);
    struct bvh_build_stats st;
    CHECK(tree_at(&s, 48, 36, &st) > s.n_clusters);
    CHECK_EQ_INT(st.camera_axes, 1);
    CHECK(st.cost_camera > 0 && st.cost_camera < 0.9 * st.cost_own);
    printf("# slivers: cost %.1f in the camera's axes, %.1f in the world's\n", st.cost_camera,
           st.cost_own);
    /* the scene and its camera turned 30 degrees about y: the camera's
     * axes turn with them, so its tree costs the same */
    struct sd_scene t = s;
    t.prims = malloc((size_t)s.n_prims * sizeof *t.prims);
    memcpy(t.prims, s.prims, (size_t)s.n_prims * sizeof *t.prims);
    const double c30 = 0.8660254037844387, s30 = 0.5;
    double *turn[3 + 3 * 1500], **end = turn;
    *end++ = t.view.eye, *end++ = t.view.look_at, *end++ = t.view.up;
    CHECK_EQ_INT(t.n_prims, 1500);
    for (int i = 0; i < t.n_prims && i < 1500; i++)
        for (int v = 0; v < 3; v++)
            *end++ = &t.prims[i].v[3 * v];
    for (double **q = turn; q < end; q++) {
        double x = (*q)[0], z = (*q)[2];
        (*q)[0] = c30 * x + s30 * z;
        (*q)[2] = -s30 * x + c30 * z;
    }
    struct bvh_build_stats turned;
    CHECK(tree_at(&t, 48, 36, &turned) > s.n_clusters);
    CHECK(turned.camera_axes == 1 && fabs(turned.cost_camera - st.cost_camera) < 1e-6 * st.cost_camera);
    printf("# turned 30 degrees: %.6f, %.1f in the world's\n", turned.cost_camera, turned.cost_own);
    free(t.prims);
    s.view.flags |= SCN_OPT_WORLD_SPACE;
    CHECK(tree_at(&s, 48, 36, &st) > s.n_clusters);
    CHECK(st.camera_axes == 0 && st.cost_camera == 0 && st.cost_own == 0);
    s.view.flags &= ~SCN_OPT_WORLD_SPACE;
    const double eye[3] = {0, 0.5, -12}, at[3] = {0, 0.5, 0};
    memcpy(s.view.eye, eye, sizeof eye);
    memcpy(s.view.look_at, at, sizeof at);
    CHECK(tree_at(&s, 48, 36, &st) > s.n_clusters);
    CHECK(st.camera_axes == 0 && st.cost_camera == 0 && st.cost_own == 0);
    sd_free(&s);
}

/* n small ellipsoids in one cluster, nothing else: a scene for the
 * compiler's limits */
static void flat_ellipsoids(struct sd_scene *s, int n, int no_tree)
{
    memset(s, 0, sizeof *s);
    s->n_clusters = 1;
    s->clusters = calloc(1, sizeof *s->clusters);
    s->clusters[0].parent = -1;
    s->clusters[0].m[0] = s->clusters[0].m[5] = s->clusters[0].m[10] = 1;
    s->n_materials = 1;
    s->materials = calloc(1, sizeof *s->materials);
    s->view.width = s->view.height = 16;
    s->view.fov = 45;
    s->view.frames = 1;
    s->no_auto_hierarchy = no_tree;
    s->n_prims = n;
    s->prims = calloc((size_t)n, sizeof *s->prims);
    rnd_state = 3;
    for (int i = 0; i < n; i++) {
        s->prims[i].kind = SCN_PRIM_ELLIPSOID;
        for (int k = 0; k < 3; k++) {
            s->prims[i].v[k] = rnd(-50, 50);
            s->prims[i].v[3 + k] = 0.1;
        }
    }
}

static void free_flat(struct sd_scene *s)
{
    free(s->prims);
    free(s->materials);
    free(s->clusters);
}

/* a scene whose compiled form passes SCN_MAX_SIZE: refused by the
 * compiler, naming the limit and the counts */
static void test_size_limit_named(void)
{
    struct sd_scene s;
    flat_ellipsoids(&s, 900000, 1); /* 68.4 MB of records */
    uint8_t *buf = NULL;
    size_t len = 0;
    char err[SD_ERR_MAX] = "";
    CHECK_EQ_INT(sd_compile(&s, &buf, &len, err, sizeof err), -1);
    CHECK(buf == NULL);
    CHECK(strstr(err, "SCN_MAX_SIZE") != NULL && strstr(err, "900000 primitives") != NULL);
    free_flat(&s);
}

/* The board's memory: a scene whose prepared frame needs exactly the
 * limit's bytes passes, one byte less refuses it naming the limit, the
 * bytes and the counts; a scene too big for the board's IMSU block is
 * refused by the compiler itself. */
static void test_board_limit_named(void)
{
    struct sd_scene s;
    flat_ellipsoids(&s, 5000, 0);
    uint8_t *buf = NULL;
    size_t len = 0;
    char err[SD_ERR_MAX] = "";
    CHECK_EQ_INT(sd_compile(&s, &buf, &len, err, sizeof err), 0);
    struct sd_board_bytes b;
    CHECK_EQ_INT(sd_board_bytes(buf, len, &b, err, sizeof err), 0);
    CHECK_EQ_INT(b.prims, 5000);
    CHECK(b.clusters > 1000 && b.blob > 5000u * (RENDER_BOARD_PRIM + RENDER_BOARD_FRAME_PRIM));
    CHECK_EQ_INT(b.nc_working, 2 * sizeof(uint32_t) * b.clusters);
    CHECK_EQ_INT(sd_board_check(buf, len, b.blob, err, sizeof err), 0);
    err[0] = 0;
    CHECK_EQ_INT(sd_board_check(buf, len, b.blob - 1, err, sizeof err), -1);
    char want[64];
    snprintf(want, sizeof want, "needs %zu bytes", b.blob);
    CHECK(strstr(err, want) != NULL && strstr(err, BOARD_IMSU_BLOCK_NAME) != NULL &&
          strstr(err, "5000 primitives") != NULL);
    free(buf);
    free_flat(&s);

    /* 760,000 primitives without a tree: 206 MB on the board, over the
     * 184 MiB of an IMSU block; the compiled form (58 MB) is within
     * SCN_MAX_SIZE */
    flat_ellipsoids(&s, 760000, 1);
    err[0] = 0;
    CHECK_EQ_INT(sd_compile(&s, &buf, &len, err, sizeof err), -1);
    CHECK(buf == NULL);
    char limit[64];
    snprintf(limit, sizeof limit, "more than the %d bytes", BOARD_IMSU_BLOCK_BYTES);
    CHECK(strstr(err, BOARD_IMSU_BLOCK_NAME) != NULL && strstr(err, "760000 primitives") != NULL &&
          strstr(err, limit) != NULL);
    free_flat(&s);
}
#endif

int main(void)
{
    printf("# arithmetic: %s\n", NUM_NAME);
    RUN(test_same_image_spheres);
    RUN(test_same_image_mesh);
    RUN(test_same_image_keyframed_nested);
    RUN(test_same_image_camera_axes);
    RUN(test_nesting_limit_kept);
#if defined(LINKS1_NUM_DOUBLE) /* the compiler alone: once is enough */
    RUN(test_cluster_limit_named);
    RUN(test_size_limit_named);
    RUN(test_board_limit_named);
    RUN(test_leaves_follow_rays);
    RUN(test_camera_axes_kept);
#endif
    return check_exit();
}
