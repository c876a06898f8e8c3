/* test_scene_index.c: the scene's static structure worked out once a load
 * (render_scene_index, render/render.h), built once per arithmetic.
 *   - a frame prepared from a loaded scene (its index the loader's) equals
 *     byte for byte the frame prepared from the same scene without an index
 *     (render_prepare then works the structure out itself, as it once did
 *     every frame): primitives, clusters, vertex normals, lists; on the
 *     scenes of scenes/ and a smooth model, first and later frames;
 *   - the index itself: children and primitives grouped by owner in rising
 *     index, the primitives that are not triangles within [pointer_lo,
 *     pointer_hi), each cluster's maps its own or (a plain cluster) its parent's,
 *     what of a cluster's maps to its parent and back stays from frame to
 *     frame (parent_maps, in cluster order) the bits a frame would work
 *     out, each shared vertex normal naming the first one with the same
 *     bits and maps, itself first (and the smooth model does share);
 *     and render_scene_index_same, given the integer part of the index,
 *     makes it again: every array and count the same;
 *   - a scene the index refuses: a normals record named by two triangles
 *     (RENDER_ERR_PRIM), a cluster whose parent follows it
 *     (RENDER_ERR_CLUSTER).
 */
#include "render/scene_load.h"
#include "render/vec3.h"
#include "tests/check.h"
#include "tests/host/test_blob_util.h"

#define TI_ARENA (64u * 1024u * 1024u)

/* A ball of smooth triangles (tests/models/ball.obj) in a rotated cluster,
 * beside the scenes of scenes/. */
static uint8_t *ti_compile_smooth(size_t *len)
{
    const char *text = "camera { eye 0 0 -3.2  look_at 0 0 0  up 0 1 0  fov 45 }\n"
                       "resolution 32 32\nbackground 0 0 0\n"
                       "light parallel { colour 1 1 1  direction 0.4 -0.5 1 }\n"
                       "material m { colour 0.9 0.8 0.7  dic 0.1 drc 0.9 }\n"
                       "cluster c { rotate 0 10 0  model { file \"ball.obj\"  material m  smooth on } }\n";
    struct sd_scene s;
    char err[SD_ERR_MAX] = "";
    uint8_t *buf = NULL;
    if (sd_parse_text("tests/models/index.scn", text, &s, err, sizeof err) != 0) {
        printf("  parse: %s\n", err);
        return NULL;
    }
    if (sd_compile(&s, &buf, len, err, sizeof err) != 0)
        printf("  compile: %s\n", err);
    sd_free(&s);
    return buf;
}

/* Scene i: 0..TB_SCENE_COUNT-1 those of scenes/, TB_SCENE_COUNT the ball. */
#define TI_SCENES (TB_SCENE_COUNT + 1)
static const char *ti_name(size_t i) { return i < TB_SCENE_COUNT ? tb_scenes[i] : "smooth ball"; }

static uint8_t *ti_compile(size_t i, size_t *len)
{
    return i < TB_SCENE_COUNT ? tb_compile_div(tb_scenes[i], 4, len) : ti_compile_smooth(len);
}

/* Frames a and b hold the same values: every array byte for byte, a
 * primitive's pointer into its frame's array (inv_radius2) as the
 * element it names (a smooth triangle's normals are in it). */
static int ti_same_frame(const render_frame_t *a, const render_frame_t *b)
{
    if (a->cluster_count != b->cluster_count || a->prim_count != b->prim_count ||
        memcmp(a->clusters, b->clusters, sizeof *a->clusters * a->cluster_count) != 0 ||
        memcmp(a->child_list, b->child_list, sizeof *a->child_list * a->cluster_count) != 0 ||
        memcmp(a->prim_list, b->prim_list, sizeof *a->prim_list * a->prim_count) != 0 ||
        memcmp(a->lights, b->lights, sizeof a->lights) != 0 || a->span != b->span ||
        a->clip_coverage != b->clip_coverage || a->clip_rows != b->clip_rows ||
        a->precision_lost != b->precision_lost || a->detail_prim != b->detail_prim)
        return 0;
    for (uint32_t i = 0; i < a->prim_count; i++) {
        render_prim_t pa = a->prims[i], pb = b->prims[i];
        if ((pa.inv_radius2 ? pa.inv_radius2 - a->density_inv_radius2 + 1 : 0) !=
            (pb.inv_radius2 ? pb.inv_radius2 - b->density_inv_radius2 + 1 : 0))
            return 0;
        pa.inv_radius2 = pb.inv_radius2 = NULL;
        if (memcmp(&pa, &pb, sizeof pa) != 0)
            return 0;
    }
    return 1;
}

static void test_index_gives_the_same_frames(void)
{
    uint8_t *mem = malloc(TI_ARENA);
    CHECK(mem != NULL);
    for (size_t i = 0; mem && i < TI_SCENES; i++) {
        size_t len;
        uint8_t *buf = ti_compile(i, &len);
        CHECK(buf != NULL);
        if (!buf)
            continue;
        arena_t arena;
        arena_init(&arena, mem, TI_ARENA);
        scene_t scene;
        scene_load_error_t lerr;
        CHECK_EQ_INT(scene_load(buf, len, &arena, &scene, &lerr), SCENE_LOAD_OK);
        CHECK(scene.index.groups != NULL);
        scene_t bare = scene; /* the same arrays, no index */
        memset(&bare.index, 0, sizeof bare.index);
        CHECK(render_prepare_bytes(&bare) > render_prepare_bytes(&scene));
        uint32_t frames = scene.frame_count < 3 ? scene.frame_count : 3;
        for (uint32_t fi = 0; fi < frames; fi++) {
            render_frame_t *with, *without;
            CHECK_EQ_INT(render_prepare(&scene, fi, &arena, &with), RENDER_OK);
            CHECK_EQ_INT(render_prepare(&bare, fi, &arena, &without), RENDER_OK);
            if (with && without) {
                with->scene = without->scene; /* compared apart from that */
                int same = ti_same_frame(with, without);
                if (!same)
                    printf("  %s frame %u: the frames differ\n", ti_name(i), (unsigned)fi);
                CHECK(same);
            }
        }
        free(buf);
    }
    free(mem);
}

/* code names vertex normal k' of record j' before j << 2 | k, equal in
 * bits and maps, and first itself */
static int ti_first_equal(const scene_t *s, const uint32_t *src, uint32_t code, uint32_t self,
                          const vec3_t *(*at)(const scene_t *, uint32_t),
                          uint32_t (*maps)(const scene_t *, uint32_t))
{
    if (code == self)
        return 1;
    return code < self && src[3 * (code >> 2) + (code & 3)] == code &&
           memcmp(at(s, code), at(s, self), sizeof(vec3_t)) == 0 && maps(s, code) == maps(s, self);
}

static const vec3_t *ti_normal(const scene_t *s, uint32_t c) { return &s->normals[c >> 2].n[c & 3]; }
static uint32_t ti_normal_maps(const scene_t *s, uint32_t c)
{
    for (uint32_t i = 0; i < s->prim_count; i++) /* the triangle naming record c >> 2 */
        if (s->prims[i].kind == SCENE_PRIM_TRIANGLE && s->prims[i].shape.triangle.smooth == (c >> 2) + 1)
            return s->index.groups[s->prims[i].cluster].maps_of;
    return UINT32_MAX;
}

/* Cluster c's pair in the index's parent_maps (the at-th), as its
 * preparation would work it out each frame: without keys its key (the
 * identity) composed with its local map, and back; with keys its local
 * map's inverse.  1 when it is not. */
static uint32_t ti_parent_maps_bad(const scene_t *s, uint32_t c, uint32_t at)
{
    const scene_index_t *ix = &s->index;
    const scene_cluster_t *cl = &s->clusters[c];
    xform_t id = xform_identity(), id_inv, local_inv;
    if (at + 2 > ix->parent_map_count ||
        !xform_invert(&id, &id_inv) || !xform_invert(&cl->local, &local_inv))
        return 1;
    const xform_t *m = &ix->parent_maps[at];
    if (cl->key_count)
        return memcmp(&m[1], &local_inv, sizeof local_inv) != 0;
    xform_t to = xform_compose(&id, &cl->local), from = xform_compose(&local_inv, &id_inv);
    return memcmp(&m[0], &to, sizeof to) != 0 || memcmp(&m[1], &from, sizeof from) != 0;
}

/* ix's arrays and counts as render_scene_index_same makes them again from
 * its integer part (what another arithmetic's load hands over). */
static int ti_same_again(const scene_t *s, const scene_index_t *ix, arena_t *arena)
{
    scene_index_ints_t ints = render_scene_index_ints(s);
    scene_index_t again;
    size_t nc = s->cluster_count, np = s->prim_count, nn = s->normals_count;
    return render_scene_index_same(s, arena, &ints, &again) == RENDER_OK &&
           memcmp(again.groups, ix->groups, sizeof *ix->groups * nc) == 0 &&
           memcmp(again.child_list, ix->child_list, sizeof(uint32_t) * nc) == 0 &&
           memcmp(again.prim_list, ix->prim_list, sizeof(uint32_t) * np) == 0 &&
           memcmp(again.normal_src, ix->normal_src, sizeof(uint32_t) * 3 * nn) == 0 &&
           memcmp(again.uv_spread, ix->uv_spread, sizeof(num_t) * np) == 0 &&
           again.parent_map_count == ix->parent_map_count &&
           memcmp(again.parent_maps, ix->parent_maps, sizeof(xform_t) * ix->parent_map_count) == 0 &&
           again.own_count == ix->own_count &&
           memcmp(again.own_list, ix->own_list, sizeof(uint32_t) * ix->own_count) == 0 &&
           again.pointer_lo == ix->pointer_lo && again.pointer_hi == ix->pointer_hi &&
           again.keyed_lo == ix->keyed_lo && again.keyed_hi == ix->keyed_hi;
}

static void test_index_structure(void)
{
    uint8_t *mem = malloc(TI_ARENA);
    CHECK(mem != NULL);
    for (size_t i = 0; mem && i < TI_SCENES; i++) {
        size_t len;
        uint8_t *buf = ti_compile(i, &len);
        CHECK(buf != NULL);
        if (!buf)
            continue;
        arena_t arena;
        arena_init(&arena, mem, TI_ARENA);
        scene_t s;
        scene_load_error_t lerr;
        CHECK_EQ_INT(scene_load(buf, len, &arena, &s, &lerr), SCENE_LOAD_OK);
        const scene_index_t *ix = &s.index;
        uint32_t bad = 0, kids = 0, prims = 0, shared_n = 0, own = 0;
        for (uint32_t c = 0; c < s.cluster_count; c++) {
            const scene_group_t *g = &ix->groups[c];
            bad += g->first_child != kids || g->first_prim != prims;
            for (uint32_t k = 0; k < g->child_count; k++) {
                uint32_t ch = ix->child_list[g->first_child + k];
                bad += ch >= s.cluster_count || s.clusters[ch].parent != c ||
                       (k > 0 && ch <= ix->child_list[g->first_child + k - 1]);
            }
            for (uint32_t k = 0; k < g->prim_count; k++) {
                uint32_t p = ix->prim_list[g->first_prim + k];
                bad += p >= s.prim_count || s.prims[p].cluster != c ||
                       (k > 0 && p <= ix->prim_list[g->first_prim + k - 1]);
            }
            kids += g->child_count;
            prims += g->prim_count;
            const scene_cluster_t *cl = &s.clusters[c];
            int plain = c > 0 && cl->key_count == 0; /* and the identity, as numbers */
            for (int r = 0; r < 3; r++)
                for (int k = 0; k < 4; k++)
                    plain = plain && num_eq(cl->local.m[r][k], r == k ? NUM_ONE : NUM_ZERO);
            bad += g->maps_of != (plain ? ix->groups[cl->parent].maps_of : c);
            if (g->maps_of == c)
                bad += ti_parent_maps_bad(&s, c, 2 * own++);
        }
        bad += kids != s.cluster_count - 1 || prims != s.prim_count;
        /* the primitives relocation looks into: every one that is not a
         * triangle, the range's ends among them */
        uint32_t others = 0;
        for (uint32_t p = 0; p < s.prim_count; p++)
            if (s.prims[p].kind != SCENE_PRIM_TRIANGLE) {
                others++;
                bad += p < ix->pointer_lo || p >= ix->pointer_hi;
            }
        bad += others ? s.prims[ix->pointer_lo].kind == SCENE_PRIM_TRIANGLE ||
                            s.prims[ix->pointer_hi - 1].kind == SCENE_PRIM_TRIANGLE
                      : ix->pointer_lo != 0 || ix->pointer_hi != 0;
        for (uint32_t p = 0; p < s.prim_count; p++) {
            const scene_prim_t *sp = &s.prims[p];
            if (sp->kind != SCENE_PRIM_TRIANGLE || !sp->shape.triangle.smooth)
                continue;
            for (uint32_t k = 0; k < 3; k++) {
                uint32_t j = sp->shape.triangle.smooth - 1, nself = j << 2 | k;
                uint32_t code = ix->normal_src[3 * j + k];
                shared_n += code != nself;
                bad += !ti_first_equal(&s, ix->normal_src, code, nself, ti_normal, ti_normal_maps);
            }
        }
        int again = ti_same_again(&s, ix, &arena);
        if (!again)
            printf("  %s: render_scene_index_same made another index\n", ti_name(i));
        bad += !again;
        if (bad)
            printf("  %s: %u entries of the index wrong\n", ti_name(i), (unsigned)bad);
        CHECK_EQ_INT(bad, 0);
        if (i == TB_SCENE_COUNT) { /* the ball: a mesh shares its vertices */
            printf("  %s: %u triangles, %u of their vertex normals shared\n", ti_name(i),
                   (unsigned)s.prim_count, (unsigned)shared_n);
            CHECK(shared_n > s.prim_count);
        }
        free(buf);
    }
    free(mem);
}

static void test_index_refusals(void)
{
    uint8_t *mem = malloc(TI_ARENA);
    size_t len;
    uint8_t *buf = ti_compile_smooth(&len);
    CHECK(mem != NULL && buf != NULL);
    if (!mem || !buf) {
        free(mem);
        free(buf);
        return;
    }
    arena_t arena;
    arena_init(&arena, mem, TI_ARENA);
    scene_t s;
    scene_load_error_t lerr;
    CHECK_EQ_INT(scene_load(buf, len, &arena, &s, &lerr), SCENE_LOAD_OK);
    scene_index_t ix;
    /* a copy of the primitives with one normals record named twice */
    scene_prim_t *prims = malloc(sizeof *prims * s.prim_count);
    CHECK(prims != NULL && s.prim_count >= 2);
    if (prims && s.prim_count >= 2) {
        memcpy(prims, s.prims, sizeof *prims * s.prim_count);
        prims[1].shape.triangle.smooth = prims[0].shape.triangle.smooth;
        scene_t twice = s;
        twice.prims = prims;
        memset(&twice.index, 0, sizeof twice.index);
        CHECK_EQ_INT(render_scene_index(&twice, &arena, &ix), RENDER_ERR_PRIM);
        render_frame_t *f;
        CHECK_EQ_INT(render_prepare(&twice, 0, &arena, &f), RENDER_ERR_PRIM);
    }
    free(prims);
    /* a cluster whose parent is not before it */
    scene_cluster_t *clusters = malloc(sizeof *clusters * s.cluster_count);
    CHECK(clusters != NULL && s.cluster_count >= 2);
    if (clusters && s.cluster_count >= 2) {
        memcpy(clusters, s.clusters, sizeof *clusters * s.cluster_count);
        clusters[1].parent = 1;
        scene_t loop = s;
        loop.clusters = clusters;
        CHECK_EQ_INT(render_scene_index(&loop, &arena, &ix), RENDER_ERR_CLUSTER);
    }
    free(clusters);
    /* an arena too small: refused, not overrun */
    uint8_t small_mem[256];
    arena_t small;
    arena_init(&small, small_mem, sizeof small_mem);
    CHECK_EQ_INT(render_scene_index(&s, &small, &ix), RENDER_ERR_ARENA);
    free(buf);
    free(mem);
}

int main(void)
{
    RUN(test_index_gives_the_same_frames);
    RUN(test_index_structure);
    RUN(test_index_refusals);
    return check_exit();
}
