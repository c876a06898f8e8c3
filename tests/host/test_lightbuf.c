/* test_lightbuf.c: the light buffer (render/lightbuf.h) over the scenes of
 * scenes/: its items hold every primitive once, a build decides the same
 * whatever its memory held, a shadow ray whose walk
 * would meet an item's box finds the item in its cell, a box's face it
 * skips by lies between the box and the light, and the image with it is
 * the image without it. */
#include <stdlib.h>
#include <string.h>

#include "render/lightbuf.h"
#include "render/prim.h"
#include "render/vec3.h"
#include "tests/check.h"
#include "tests/host/test_blob_util.h"

/* The frame of blob (its block, in *block), with its light buffer in
 * *mem (both freed by the caller); NULL on failure. */
static const render_frame_t *lb_frame(render_blob_t *blob, void **block, void **mem,
                                      const render_lightbuf_t **lb)
{
    *block = blob;
    *mem = NULL;
    *lb = NULL;
    if (!blob)
        return NULL;
    size_t bytes = render_lightbuf_bytes(blob->frame);
    *mem = malloc(bytes);
    *lb = render_lightbuf_build(blob->frame, *mem, bytes);
    return blob->frame;
}

/* lb_frame of scene NAME at half its resolution. */
static const render_frame_t *lb_scene(const char *name, void **block, void **mem,
                                      const render_lightbuf_t **lb)
{
    size_t size;
    return lb_frame(tb_blob_div(name, 0, 2, &size), block, mem, lb);
}

/* Primitives under item (a cluster's subtree, or one primitive), counted
 * into seen[]. */
static void lb_count(const render_frame_t *f, uint32_t item, uint32_t *seen)
{
    if (!(item & RENDER_LB_CLUSTER)) {
        seen[item]++;
        return;
    }
    const render_cluster_t *c = &f->clusters[item & ~RENDER_LB_CLUSTER];
    for (uint32_t k = 0; k < c->prim_count; k++)
        seen[f->prim_list[c->first_prim + k]]++;
    for (uint32_t k = 0; k < c->child_count; k++)
        lb_count(f, f->child_list[c->first_child + k] | RENDER_LB_CLUSTER, seen);
}

/* What f's buffer decides (its items, each light's kind, cells and items
 * in every cell) is the same built into memory of any contents: built
 * into zeroed memory at mem and into memory full of saturated values, a
 * build reads nothing it did not write (a parallel light's one grid, not
 * a cube's six, once read all six). */
static void lb_check_any_memory(const render_frame_t *f, void *mem)
{
    size_t bytes = render_lightbuf_bytes(f);
    memset(mem, 0, bytes);
    const render_lightbuf_t *a = render_lightbuf_build(f, mem, bytes);
    num_t *other = malloc(bytes);
    num_t sat = num_div(NUM_ONE, NUM_ZERO); /* a saturated value: read, it spreads */
    for (size_t k = 0; k < bytes / sizeof sat; k++)
        other[k] = sat;
    const render_lightbuf_t *b = render_lightbuf_build(f, other, bytes);
    CHECK(a != NULL && b != NULL);
    if (a && b) {
        CHECK_EQ_INT(b->item_count, a->item_count);
        CHECK(memcmp(b->item, a->item, a->item_count * sizeof a->item[0]) == 0);
        for (uint32_t i = 0; i < a->light_count; i++) {
            CHECK_EQ_INT(b->light[i].kind, a->light[i].kind);
            CHECK_EQ_INT(b->light[i].always, a->light[i].always);
            CHECK(memcmp(b->light[i].mask, a->light[i].mask, sizeof a->light[i].mask) == 0);
        }
    }
    free(other);
}

static void test_items_hold_every_prim_once(void)
{
    for (size_t s = 0; s < TB_SCENE_COUNT; s++) {
        void *block, *mem;
        const render_lightbuf_t *lb;
        const render_frame_t *f = lb_scene(tb_scenes[s], &block, &mem, &lb);
        CHECK(f && lb);
        if (!f || !lb)
            continue;
        CHECK(lb->item_count >= 1 && lb->item_count <= RENDER_LB_ITEMS);
        CHECK_EQ_INT(lb->light_count, f->light_count);
        uint32_t *seen = calloc(f->prim_count, sizeof *seen);
        for (uint32_t k = 0; k < lb->item_count; k++)
            lb_count(f, lb->item[k], seen);
        int once = 1;
        for (uint32_t p = 0; p < f->prim_count; p++)
            once &= seen[p] == 1;
        CHECK(once);
        free(seen);
        lb_check_any_memory(f, mem);
        /* too little memory: no buffer, nothing written past it */
        CHECK(render_lightbuf_build(f, mem, render_lightbuf_bytes(f) - 1) == NULL);
        CHECK(render_lightbuf_build(f, NULL, render_lightbuf_bytes(f)) == NULL);
        free(mem);
        free(block);
    }
}

/* A face a light's cells give an item (render_lb_light_t.face) is one of
 * a box's local cube that the light lies beyond (a parallel light: that
 * its direction leaves by), so a shadow ray beyond it at both ends cannot
 * reach the box; and the scenes' boxes get some. */
static void test_faces_the_light_lies_beyond(void)
{
    uint32_t faces = 0;
    for (size_t s = 0; s < TB_SCENE_COUNT; s++) {
        void *block, *mem;
        const render_lightbuf_t *lb;
        const render_frame_t *f = lb_scene(tb_scenes[s], &block, &mem, &lb);
        CHECK(f && lb);
        for (uint32_t i = 0; f && lb && i < lb->light_count; i++) {
            const render_lb_light_t *l = &lb->light[i];
            for (uint32_t k = 0; k < lb->item_count; k++) {
                if (!l->face[k])
                    continue;
                faces++;
                uint32_t item = lb->item[k];
                const render_prim_t *p = &f->prims[item & ~RENDER_LB_CLUSTER];
                CHECK(!(item & RENDER_LB_CLUSTER) && p->kind == SCENE_PRIM_BOX);
                int axis = (l->face[k] - 1) >> 1, minus = (l->face[k] - 1) & 1;
                vec3_t q = l->kind == RENDER_LB_CUBE
                               ? xform_point(&p->to_local, l->at)
                               : xform_dir(&p->to_local, f->lights[i].to_light);
                double v = num_to_double(vec3_get(q, axis)) * (minus ? -1 : 1);
                CHECK(v > (l->kind == RENDER_LB_CUBE ? 1 : 0));
            }
        }
        free(mem);
        free(block);
    }
    CHECK(faces > 0);
    printf("  %u faces over the scenes' lights and boxes\n", (unsigned)faces);
}

static uint32_t lb_rand(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u;
    return *state >> 8;
}

/* A point within box b, from 3 random draws. */
static vec3_t lb_point_in(const aabb_t *b, uint32_t *state)
{
    num_t c[3];
    for (int i = 0; i < 3; i++) {
        double t = (double)(lb_rand(state) & 0xffff) / 65535.0;
        double lo = num_to_double(vec3_get(b->lo, i)), hi = num_to_double(vec3_get(b->hi, i));
        c[i] = num_from_double(lo + (hi - lo) * t);
    }
    return vec3_make(c[0], c[1], c[2]);
}

/* Whether a shadow ray over (ray_epsilon, tmax] meets item as a walk that
 * tests each primitive's box first finds it: a box or an ellipsoid (whose
 * turned box the cells hold, not its box in eye space) its box and then
 * itself, by the primitive's test with an error on the ray of 64
 * steps of the arithmetic (at 64 for its origin, at 1 for its direction)
 * (hit, or within that of a hit); anything else, its box. */
static int lb_met(const render_frame_t *f, uint32_t item, const ray_t *ray, num_t tmax)
{
    if (item & RENDER_LB_CLUSTER)
        return prim_aabb_hit(&f->clusters[item & ~RENDER_LB_CLUSTER].bounds, ray,
                             f->ray_epsilon, tmax);
    const render_prim_t *p = &f->prims[item];
    if (p->kind != SCENE_PRIM_BOX && p->kind != SCENE_PRIM_ELLIPSOID)
        return prim_aabb_hit(&p->bounds, ray, f->ray_epsilon, tmax);
    ray_error_t err = {num_mul_int(num_ulp(NUM_C(64)), 64), num_mul_int(num_ulp(NUM_ONE), 64)};
    num_t t;
    int uncertain;
    int found = prim_intersect_uncertain(p, ray, &err, f->ray_epsilon, tmax, &t, &uncertain);
    return prim_aabb_hit(&p->bounds, ray, f->ray_epsilon, tmax) && (found || uncertain);
}

/* What lb_rays_meet counts. */
typedef struct {
    uint64_t rays, left_out, wrong;
} lb_ray_counts_t;

/* 4,000 shadow rays from random points of f's root box towards each of
 * its lights, into *n: an item left out of a ray's cell that the ray
 * meets (lb_met: the walk would find it there) is wrong. */
static void lb_rays_meet(const render_frame_t *f, const render_lightbuf_t *lb, uint32_t *state,
                         lb_ray_counts_t *n)
{
    const aabb_t *root = &f->clusters[0].bounds;
    for (uint32_t i = 0; i < f->light_count; i++)
        for (int k = 0; k < 4000; k++) {
            const render_light_t *l = &f->lights[i];
            vec3_t hit = lb_point_in(root, state);
            ray_t ray = {hit, l->to_light};
            num_t tmax = NUM_FAR;
            if (l->kind != SCENE_LIGHT_PARALLEL) {
                vec3_t to = vec3_sub(l->position, hit);
                tmax = vec3_length(to);
                if (!num_gt(tmax, NUM_ZERO))
                    continue;
                ray.dir = vec3_scale(to, num_recip(tmax));
            }
            /* as trace_lights: the origin moved off the hit by
             * ray_epsilon (here along an axis), the direction the hit's */
            int axis = (int)(lb_rand(state) % 3);
            vec3_set(&ray.origin, axis, num_add(vec3_get(hit, axis), f->ray_epsilon));
            uint32_t mask = render_lightbuf_mask(lb, i, ray.origin, ray.dir);
            n->rays++;
            for (uint32_t j = 0; j < lb->item_count; j++) {
                if (mask >> j & 1)
                    continue;
                n->left_out++;
                n->wrong += lb_met(f, lb->item[j], &ray, tmax);
            }
        }
}

/* Shadow rays over the scenes: an item left out of a ray's cell is one
 * the ray does not meet; and the cells do leave some out. */
static void test_cells_hold_what_rays_meet(void)
{
    uint32_t state = 12345;
    lb_ray_counts_t n = {0, 0, 0};
    for (size_t s = 0; s < TB_SCENE_COUNT; s++) {
        void *block, *mem;
        const render_lightbuf_t *lb;
        const render_frame_t *f = lb_scene(tb_scenes[s], &block, &mem, &lb);
        if (!f || !lb) {
            CHECK(f && lb);
            continue;
        }
        lb_rays_meet(f, lb, &state, &n);
        free(mem);
        free(block);
    }
    printf("  %llu shadow rays, %llu items left out of their cells, %llu wrongly\n",
           (unsigned long long)n.rays, (unsigned long long)n.left_out,
           (unsigned long long)n.wrong);
    CHECK(n.rays > 10000);
    CHECK(n.left_out > n.rays);
    CHECK_EQ_INT(n.wrong, 0);
}

/* A point light far off along a flat row of primitives, level with them
 * and with the camera: a face of its cube sees the scene as a thin strip,
 * its cells very fine across it.  No item lies near the light: none goes
 * in every cell, most are left out of a ray's cell, and the cells still
 * hold what the rays meet. */
static const char lb_grazing_scene[] =
    "camera { eye 0 0.005 -60  look_at 0 0.005 0  up 0 1 0  fov 40 }\n"
    "resolution 64 48\n"
    "light point { colour 1 1 1  position 60 0.005 0 }\n"
    "material m { colour 0.8 0.8 0.8  dic 0.2 drc 0.7 }\n"
    "box { material m  min -40 0 -10  max 40 0.001 10 }\n"
    "sphere { material m  centre -30 0.005 -6  radius 0.004 }\n"
    "sphere { material m  centre -10 0.005 -2  radius 0.004 }\n"
    "sphere { material m  centre 10 0.005 2  radius 0.004 }\n"
    "sphere { material m  centre 30 0.005 6  radius 0.004 }\n"
    "sphere { material m  centre -20 0.005 4  radius 0.004 }\n"
    "sphere { material m  centre 20 0.005 -4  radius 0.004 }\n";

static void test_grazing_light_lists_few(void)
{
    size_t size;
    void *block, *mem;
    const render_lightbuf_t *lb;
    const render_frame_t *f =
        lb_frame(tb_blob_text("grazing", lb_grazing_scene, &size), &block, &mem, &lb);
    CHECK(f && lb && lb->light_count == 1);
    if (f && lb && lb->light_count == 1) {
        const render_lb_light_t *l = &lb->light[0];
        CHECK_EQ_INT(l->kind, RENDER_LB_CUBE);
        CHECK_EQ_INT(l->always, 0);
        uint32_t state = 777;
        lb_ray_counts_t n = {0, 0, 0};
        lb_rays_meet(f, lb, &state, &n);
        printf("  grazing: %u items, %llu shadow rays, %llu items left out, %llu wrongly\n",
               (unsigned)lb->item_count, (unsigned long long)n.rays,
               (unsigned long long)n.left_out, (unsigned long long)n.wrong);
        CHECK(n.left_out > n.rays);
        CHECK_EQ_INT(n.wrong, 0);
    }
    free(mem);
    free(block);
}

/* The image with the light buffer is the image without it; the shadow
 * rays test fewer boxes and primitives. */
static void test_same_image(void)
{
    for (size_t s = 0; s < TB_SCENE_COUNT; s++) {
        void *block, *mem;
        const render_lightbuf_t *lb;
        const render_frame_t *f = lb_scene(tb_scenes[s], &block, &mem, &lb);
        if (!f || !lb) {
            CHECK(f && lb);
            continue;
        }
        size_t n = (size_t)f->width * f->height;
        render_stats_t plain_stats, lb_stats;
        rgb8_t *plain = tb_render_plain(f, &plain_stats);
        rgb8_t *img = calloc(n, sizeof *img);
        render_ctx_t ctx;
        render_ctx_init(&ctx, f);
        ctx.light_buffer = lb;
        for (uint32_t y = 0; y < f->height; y++)
            render_span(&ctx, y, 0, f->width, img + (size_t)y * f->width);
        lb_stats = ctx.stats;
        if (!tb_same(plain, img, n))
            printf("%s: the image differs with the light buffer\n", tb_scenes[s]);
        CHECK(tb_same(plain, img, n));
        CHECK_EQ_INT(lb_stats.shadow, plain_stats.shadow);
        CHECK(plain_stats.shadow > 0);
        CHECK(lb_stats.box_tests + lb_stats.prim_tests <
              plain_stats.box_tests + plain_stats.prim_tests);
        printf("  %s: %llu shadow rays; box and primitive tests %llu with, %llu without\n",
               tb_scenes[s], (unsigned long long)lb_stats.shadow,
               (unsigned long long)(lb_stats.box_tests + lb_stats.prim_tests),
               (unsigned long long)(plain_stats.box_tests + plain_stats.prim_tests));
        free(img);
        free(plain);
        free(mem);
        free(block);
    }
}

int main(void)
{
    RUN(test_items_hold_every_prim_once);
    RUN(test_faces_the_light_lies_beyond);
    RUN(test_cells_hold_what_rays_meet);
    RUN(test_grazing_light_lists_few);
    RUN(test_same_image);
    return check_exit();
}
