/* hostile.c: the hostile classes (see hostile.h).  Every edit goes through
 * the offsets of proto/scene_format.h; after an edit the word sum is made right
 * again (except in the class that tests it), so each class reaches the
 * check it aims at. */
#include "tests/hostile/hostile.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_board.h"
#include "host-tools/scene/scene_desc.h"
#include "proto/wordsum.h"
#include "proto/scene_format.h"
#include "proto/wire.h"

#define F32_NAN 0x7fc00000u
#define F32_INF 0x7f800000u
#define HOSTILE_NESTING 32 /* SCN_MAX_CLUSTER_NESTING: the base's chain */

/* ------------------------------------------------------------ the base */

int hostile_base(struct hostile_scene *h, char *err, size_t errlen)
{
    size_t cap = 8192, n = 0;
    char *t = malloc(cap);
    if (!t)
        return -1;
#define ADD(...) (n += (size_t)snprintf(t + n, cap - n, __VA_ARGS__))
    ADD("camera { eye 0 2 -6 look_at 0 0 0 up 0 1 0 fov 50 }\n"
        "resolution 32 24\n"
        "animation { frames 2 }\n"
        "light point { colour 0.9 0.9 0.9 position 3 6 -4 }\n"
        "map tiles colour { size 2 2 texels 1 1 1  0 0 0  0 0 0  1 1 1 repeat 4 4 }\n"
        "material plain { colour 0.8 0.7 0.6 }\n"
        "material tiled { colour_map tiles }\n"
        "use plain\n"
        "box { material tiled min -2 -1 -2 max 2 -0.8 2 }\n"
        "triangle { v -1 0 1 v 1 0 1 v 0 1.5 1 }\n"
        "density { threshold 0.5 component -0.5 0 0 1 1 component 0.5 0 0 1 1 }\n");
    for (int i = 1; i <= HOSTILE_NESTING; i++)
        ADD("cluster c%d { translate 0 0.01 0\n", i);
    ADD("sphere { centre 1.5 0 0 radius 0.3 }\n");
    for (int i = 1; i <= HOSTILE_NESTING; i++)
        ADD("}\n");
    ADD("cluster moving { key 0 { translate 0 0 0 } key 1 { translate 0 0.5 0 }\n"
        "  sphere { centre -1.5 0 0 radius 0.4 } }\n");
#undef ADD
    if (n >= cap) {
        free(t);
        snprintf(err, errlen, "hostile base: text longer than %zu bytes", cap);
        return -1;
    }
    struct sd_scene s;
    int rc = sd_parse_text("hostile-base.scn", t, &s, err, errlen);
    free(t);
    if (rc != 0)
        return -1;
    rc = sd_compile(&s, &h->buf, &h->len, err, errlen);
    sd_free(&s);
    return rc;
}

char *hostile_big_text(void)
{
    size_t cap = 32000 * 96 + 512, n = 0;
    char *t = malloc(cap);
    if (!t)
        return NULL;
    n += (size_t)snprintf(t + n, cap - n,
                          "camera { eye 0 3 -6 look_at 0 0 0 up 0 1 0 fov 50 }\n"
                          "resolution 32 24\n"
                          "light parallel { colour 0.6 0.6 0.6 direction -1 -1.5 1 }\n"
                          "material grass { colour 0.3 0.6 0.3 dic 0.25 drc 0.7 }\n");
    for (int i = 0; i < 32000; i++) {
        double x = (i % 200) * 0.05 - 5, z = (i / 200) * 0.05 - 4;
        n += (size_t)snprintf(t + n, cap - n,
                              "triangle { material grass v %.2f 0 %.2f v %.2f 0 %.2f "
                              "v %.2f 0.02 %.2f }\n",
                              x, z, x + 0.05, z, x, z + 0.05);
    }
    return t;
}

/* ----------------------------------------------------- finding records */

static uint8_t *sec_entry(struct hostile_scene *h, uint32_t kind)
{
    uint16_t nsec = wire_get_u16(h->buf + SCN_HDR_SECTIONS);
    for (uint32_t i = 0; i < nsec; i++) {
        uint8_t *e = h->buf + SCN_HEADER_SIZE + i * SCN_SECENT_SIZE;
        if (wire_get_u32(e + SCN_SECENT_KIND) == kind)
            return e;
    }
    return NULL;
}

/* Record i of a section, or NULL when there is no such record. */
static uint8_t *rec(struct hostile_scene *h, uint32_t kind, uint32_t size, uint32_t i)
{
    uint8_t *e = sec_entry(h, kind);
    if (!e || i >= wire_get_u32(e + SCN_SECENT_COUNT))
        return NULL;
    return h->buf + wire_get_u32(e + SCN_SECENT_OFFSET) + i * size;
}

/* The first primitive of a kind. */
static uint8_t *prim_of(struct hostile_scene *h, uint16_t kind)
{
    uint8_t *p;
    for (uint32_t i = 0; (p = rec(h, SCN_SEC_PRIMS, SCN_PRIM_SIZE, i)); i++)
        if (wire_get_u16(p + SCN_PRIM_KIND) == kind)
            return p;
    return NULL;
}

static int refix(struct hostile_scene *h)
{
    wire_put_u32(h->buf + SCN_HDR_SUM, wordsum(h->buf + SCN_SUM_START, h->len - SCN_SUM_START));
    return 0;
}

static void put_f32(uint8_t *p, float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    wire_put_u32(p, u);
}

/* ------------------------------------------------------------ classes */

static int nonfinite_nan(struct hostile_scene *h)
{
    uint8_t *p = prim_of(h, SCN_PRIM_ELLIPSOID);
    if (!p)
        return -1;
    wire_put_u32(p + SCN_PRIM_VALUES, F32_NAN);
    return refix(h);
}

static int nonfinite_inf(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_VIEW, SCN_VIEW_SIZE, 0);
    if (!p)
        return -1;
    wire_put_u32(p + SCN_VIEW_EYE, F32_INF);
    return refix(h);
}

/* One section's record count one over its limit. */
static int over_count(struct hostile_scene *h, uint32_t kind, uint32_t limit)
{
    uint8_t *e = sec_entry(h, kind);
    if (!e)
        return -1;
    wire_put_u32(e + SCN_SECENT_COUNT, limit + 1);
    return refix(h);
}
#define OVER(name, kind, limit) \
    static int name(struct hostile_scene *h) { return over_count(h, kind, limit); }
OVER(over_view, SCN_SEC_VIEW, 1)
OVER(over_lights, SCN_SEC_LIGHTS, SCN_MAX_LIGHTS)
OVER(over_materials, SCN_SEC_MATERIALS, SCN_MAX_MATERIALS)
OVER(over_maps, SCN_SEC_MAPS, SCN_MAX_MAPS)
OVER(over_texels, SCN_SEC_TEXELS, SCN_MAX_TEXEL_BYTES)
OVER(over_clusters, SCN_SEC_CLUSTERS, SCN_MAX_CLUSTERS)
OVER(over_prims, SCN_SEC_PRIMS, SCN_MAX_PRIMS)
OVER(over_components, SCN_SEC_COMPONENTS, SCN_MAX_COMPONENTS)
OVER(over_keys, SCN_SEC_KEYS, SCN_MAX_KEYS)

static int over_image_size(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_VIEW, SCN_VIEW_SIZE, 0);
    if (!p)
        return -1;
    wire_put_u16(p + SCN_VIEW_WIDTH, SCN_MAX_WIDTH + 1);
    return refix(h);
}

static int bad_min_weight(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_VIEW, SCN_VIEW_SIZE, 0);
    if (!p)
        return -1;
    wire_put_f32(p + SCN_VIEW_MIN_WEIGHT, 1.5f);
    return refix(h);
}

static int bad_density_steps(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_VIEW, SCN_VIEW_SIZE, 0);
    if (!p)
        return -1;
    wire_put_u32(p + SCN_VIEW_DENSITY_STEPS, SCN_MIN_DENSITY_STEPS - 1);
    return refix(h);
}

static int over_depth(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_VIEW, SCN_VIEW_SIZE, 0);
    if (!p)
        return -1;
    wire_put_u16(p + SCN_VIEW_MAX_DEPTH, SCN_MAX_DEPTH + 1);
    return refix(h);
}

static int over_frames(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_VIEW, SCN_VIEW_SIZE, 0);
    if (!p)
        return -1;
    wire_put_u32(p + SCN_VIEW_FRAMES, SCN_MAX_FRAMES + 1);
    return refix(h);
}

static int over_total_size(struct hostile_scene *h)
{
    wire_put_u32(h->buf + SCN_HDR_TOTAL, SCN_MAX_SIZE + 1);
    return refix(h);
}

static int over_density_components(struct hostile_scene *h)
{
    uint8_t *p = prim_of(h, SCN_PRIM_DENSITY);
    if (!p)
        return -1;
    wire_put_u32(p + SCN_PRIM_COUNT, SCN_MAX_DENSITY_COMPONENTS + 1);
    return refix(h);
}

static int over_phong(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_MATERIALS, SCN_MAT_SIZE, 0);
    if (!p)
        return -1;
    wire_put_u16(p + SCN_MAT_PHONG, SCN_MAX_PHONG + 1);
    return refix(h);
}

/* The last cluster (a child of the root) hung below the deepest one. */
static int nesting(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_CLUSTERS, SCN_CLUSTER_SIZE, HOSTILE_NESTING + 1);
    if (!p)
        return -1;
    wire_put_u32(p + SCN_CLUSTER_PARENT, HOSTILE_NESTING);
    return refix(h);
}

static int forward_parent(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_CLUSTERS, SCN_CLUSTER_SIZE, 1);
    if (!p)
        return -1;
    wire_put_u32(p + SCN_CLUSTER_PARENT, 2);
    return refix(h);
}

/* The primitives laid over the clusters. */
static int overlap(struct hostile_scene *h)
{
    uint8_t *prims = sec_entry(h, SCN_SEC_PRIMS), *clusters = sec_entry(h, SCN_SEC_CLUSTERS);
    if (!prims || !clusters)
        return -1;
    wire_put_u32(prims + SCN_SECENT_OFFSET, wire_get_u32(clusters + SCN_SECENT_OFFSET));
    return refix(h);
}

/* A section whose body runs past the end of the file. */
static int outside(struct hostile_scene *h)
{
    uint8_t *e = sec_entry(h, SCN_SEC_KEYS);
    if (!e)
        return -1;
    wire_put_u32(e + SCN_SECENT_OFFSET, (uint32_t)h->len - SCN_KEY_SIZE + SCN_SECTION_ALIGN);
    return refix(h);
}

/* The last 8 bytes lost on the way. */
static int truncated(struct hostile_scene *h)
{
    h->len -= 8;
    return 0;
}

static int crc_mismatch(struct hostile_scene *h)
{
    h->buf[h->len - 1] ^= 0x01; /* the word sum is not made right again */
    return 0;
}

static int wrong_version(struct hostile_scene *h)
{
    wire_put_u16(h->buf + SCN_HDR_VERSION, SCN_VERSION + 1);
    return refix(h);
}

static int zero_box(struct hostile_scene *h)
{
    uint8_t *p = prim_of(h, SCN_PRIM_BOX);
    if (!p)
        return -1;
    put_f32(p + SCN_PRIM_VALUES + 4 * 4, 0.0f); /* half edge along y */
    return refix(h);
}

/* The first triangle's vertices set to v, and the triangles' extent
 * stated again as the compiler states it (sd_extent_bits): the loader
 * meets the triangle's own fault, not one past the old extent. */
static int set_triangle(struct hostile_scene *h, const float v[9])
{
    uint8_t *p = prim_of(h, SCN_PRIM_TRIANGLE);
    uint8_t *x = rec(h, SCN_SEC_EXTENT, SCN_EXTENT_SIZE, 0);
    uint32_t bits;
    char err[SD_ERR_MAX];
    if (!p || !x)
        return -1;
    for (int k = 0; k < 9; k++)
        put_f32(p + SCN_PRIM_VALUES + 4 * k, v[k]);
    if (sd_extent_bits(h->buf, h->len, &bits, err, sizeof err) != 0)
        return -1;
    wire_put_u32(x + SCN_EXTENT_TRI_EXP, bits);
    return refix(h);
}

static int degenerate_triangle(struct hostile_scene *h)
{
    static const float v[9] = {-1, 0, 1, 1, 0, 1, 3, 0, 1}; /* on one line */
    return set_triangle(h, v);
}

static int sliver_triangle(struct hostile_scene *h)
{
    static const float v[9] = {-1, 0, 1, 1, 0, 1, 0, 1e-6f, 1}; /* 1e-6 high */
    return set_triangle(h, v);
}

/* Cluster 1's matrix with a zero row: it cannot be inverted. */
static int singular_matrix(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_CLUSTERS, SCN_CLUSTER_SIZE, 1);
    if (!p)
        return -1;
    for (int k = 0; k < 4; k++)
        put_f32(p + SCN_CLUSTER_MATRIX + 4 * k, 0.0f);
    return refix(h);
}

static int zero_key_scale(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_KEYS, SCN_KEY_SIZE, 1);
    if (!p)
        return -1;
    put_f32(p + SCN_KEY_SCALE + 4, 0.0f);
    return refix(h);
}

static int map_too_big(struct hostile_scene *h)
{
    uint8_t *p = rec(h, SCN_SEC_MAPS, SCN_MAP_SIZE, 0);
    if (!p)
        return -1;
    wire_put_u16(p + SCN_MAP_WIDTH, SCN_MAX_MAP_SIDE + 1);
    return refix(h);
}

/* The base replaced by the big scene, compiled. */
static int working_set(struct hostile_scene *h)
{
    char *t = hostile_big_text();
    if (!t)
        return -1;
    struct sd_scene s;
    char err[SD_ERR_MAX];
    int rc = sd_parse_text("hostile-big.scn", t, &s, err, sizeof err);
    free(t);
    if (rc != 0)
        return -1;
    free(h->buf);
    h->buf = NULL;
    rc = sd_compile(&s, &h->buf, &h->len, err, sizeof err);
    sd_free(&s);
    return rc;
}

const struct hostile_class hostile_classes[] = {
    {"nonfinite_nan", "prim 3: a value is not finite", nonfinite_nan},
    {"nonfinite_inf", "camera: a coordinate is not finite", nonfinite_inf},
    {"over_view", "section kind 1: record count over its limit of 1", over_view},
    {"over_lights", "section kind 2: record count over its limit of 16", over_lights},
    {"over_materials", "section kind 3: record count over its limit of 1024", over_materials},
    {"over_maps", "section kind 4: record count over its limit of 16", over_maps},
    {"over_texels", "section kind 5: record count over its limit of 4194304", over_texels},
    {"over_clusters", "section kind 6: record count over its limit of 1048576", over_clusters},
    {"over_prims", "section kind 7: record count over its limit of 1048576", over_prims},
    {"over_components", "section kind 8: record count over its limit of 65536", over_components},
    {"over_keys", "section kind 9: record count over its limit of 65536", over_keys},
    {"over_image_size", "image size 1025x24 outside 1..1024", over_image_size},
    {"over_depth", "max depth 17 over the limit of 16", over_depth},
    {"over_frames", "frame count 100001 not 1..100000", over_frames},
    {"over_total_size", "total size 67108865 is over the limit of 67108864 bytes",
     over_total_size},
    {"over_density_components", "prim 2: component count not 1..64", over_density_components},
    {"over_phong", "material 0: phong n over 1024", over_phong},
    {"nesting", "cluster 33: nested deeper than 32", nesting},
    {"forward_parent", "cluster 1: parent index not below its own", forward_parent},
    {"overlap", "overlaps another section", overlap},
    {"outside", "section kind 9: body outside the file", outside},
    {"truncated", "scene truncated: header says", truncated},
    {"crc_mismatch", "checksum mismatch", crc_mismatch},
    {"wrong_version", "format version 8 (this loader reads version 7)", wrong_version},
    {"bad_min_weight", "min_weight not within 0..1", bad_min_weight},
    {"bad_density_steps", "density_steps 1 not 2..256", bad_density_steps},
    {"zero_box", "prim 0: a semi-axis or half edge is not > 0", zero_box},
    {"degenerate_triangle", "prim 1: degenerate or sliver triangle", degenerate_triangle},
    {"sliver_triangle", "prim 1: degenerate or sliver triangle", sliver_triangle},
    {"singular_matrix", "a cluster transform cannot be inverted", singular_matrix},
    {"zero_key_scale", "key 1: scale is zero", zero_key_scale},
    {"map_too_big", "map 0: size outside 1..1024", map_too_big},
    {"working_set", "of LINKS1_IMSU_PAIR_BLOCK", working_set},
};
const int hostile_class_count = (int)(sizeof hostile_classes / sizeof hostile_classes[0]);
