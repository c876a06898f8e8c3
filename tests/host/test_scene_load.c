/* test_scene_load.c: the compiled scene format and its loader: a round trip
 * through text -> compiled form -> scene_t, and every kind of corruption
 * (truncation at every length, each header field, flipped bits, bad
 * indices) refused with the right error. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_desc.h"
#include "proto/wordsum.h"
#include "proto/wire.h"
#include "render/scene_load.h"
#include "tests/check.h"

#define ARENA_BYTES (4u * 1024u * 1024u)
#define TEST_PI 3.14159265358979323846

/* Built once per arithmetic: a value that is not a multiple of the fixed
 * build's step (1/65536) comes out within one step, IEEE ones within float
 * rounding. */
#if defined(LINKS1_NUM_FIXED)
#define VAL_TOL 2e-5
#else
#define VAL_TOL 1e-6
#endif

static const char *scene_text =
    "camera { eye 0 1 -5 look_at 0 0 0 up 0 1 0 fov 60 }\n"
    "resolution 64 48\n"
    "background 0.1 0.2 0.3\n"
    "options { max_depth 4 shadows off }\n"
    "animation { frames 3 }\n"
    "light point { colour 1 0.5 0.25 position 1 2 3 }\n"
    "light spot { position 0 5 0 at 0 0 0 cone 20 falloff 10 }\n"
    "map tiles colour { size 2 1 texels 1 0 0  0 0 1 repeat 4 2 }\n"
    "map bumps bump { size 1 2 texels 0 1 depth 0.5 }\n"
    "map nrm normal { size 1 1 texels 0 0.6 0.8 }\n"
    "map att attribute { size 2 1 texels 0.2 1 repeat 3 1 }\n"
    "material a { colour 0.5 0.6 0.7 dic 0.1 drc 0.8 src 0.2 trc 0.3 fresnel 0.5 ior 1.5 "
    "phong 20 colour_map tiles bump_map bumps }\n"
    "material b { colour 1 1 1 normal_map nrm dic_map att drc_map att src_map att trc_map att }\n"
    "use b\n"
    "box { min -1 -1 -1 max 1 0 3 }\n"
    "cluster c1 { translate 1 2 3\n"
    "  key 0 { translate 0 0 0 }\n"
    "  key 2 { rotate 0 90 0 scale 2 }\n"
    "  sphere { material a centre 0 0 0 radius 0.5 }\n"
    "  cluster c2 { scale 2\n"
    "    triangle { v 0 0 0 v 1 0 0 v 0 1 0 uv 0 0 uv 1 0 uv 0 1 }\n"
    "    density { threshold 0.5 component 0 0 0 1 1 component 1 0 0 1 -0.5 }\n"
    "    ellipsoid { centre 1 1 1 radii 1 2 3 }\n"
    "  }\n"
    "}\n";

static uint8_t *compiled(size_t *len)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    uint8_t *buf = NULL;
    if (sd_parse_text("t.scn", scene_text, &s, err, sizeof err) != 0) {
        printf("parse failed: %s\n", err);
        return NULL;
    }
    if (sd_compile(&s, &buf, len, err, sizeof err) != 0)
        printf("compile failed: %s\n", err);
    sd_free(&s);
    return buf;
}

static scene_load_status_t try_load(const uint8_t *buf, size_t len, scene_load_error_t *e)
{
    static uint8_t mem[ARENA_BYTES];
    arena_t arena;
    scene_t s;
    arena_init(&arena, mem, sizeof mem);
    scene_load_status_t st = scene_load(buf, len, &arena, &s, e);
    if (st != SCENE_LOAD_OK && arena.used != 0)
        printf("arena not released after a failed load\n");
    return st;
}

/* Recomputes the word sum so a deliberate field change reaches the field checks. */
static void fix_crc(uint8_t *b, size_t len)
{
    wire_put_u32(b + SCN_HDR_SUM, wordsum(b + SCN_SUM_START, len - SCN_SUM_START));
}

/* Offset of the section of a kind, via the table. */
static uint32_t section_offset(const uint8_t *b, int kind)
{
    int n = wire_get_u16(b + SCN_HDR_SECTIONS);
    for (int i = 0; i < n; i++) {
        const uint8_t *e = b + SCN_HEADER_SIZE + i * SCN_SECENT_SIZE;
        if ((int)wire_get_u32(e + SCN_SECENT_KIND) == kind)
            return wire_get_u32(e + SCN_SECENT_OFFSET);
    }
    return 0;
}

/* A length of the scene in the scene text's units (scene_t.unit_exp). */
#define LEN(s, v) ldexp(num_to_double(v), -(s)->unit_exp)

static void test_round_trip(void)
{
    size_t len;
    uint8_t *b = compiled(&len);
    CHECK(b != NULL);
    if (!b)
        return;
    static uint8_t mem[ARENA_BYTES];
    arena_t arena;
    arena_init(&arena, mem, sizeof mem);
    scene_t s;
    scene_load_error_t e;
    CHECK_EQ_INT(scene_load(b, len, &arena, &s, &e), SCENE_LOAD_OK);
    CHECK_EQ_INT(s.width, 64);
    CHECK_EQ_INT(s.height, 48);
    CHECK_EQ_INT(s.frame_count, 3);
    CHECK_EQ_INT(s.options.max_depth, 4);
    /* lengths scaled to the scene in world units: the largest, c2's
     * ellipsoid's semi-axis 3 times c2's scale 2 times c1's key scale 2,
     * 12, is stored as 12, in [2^RENDER_NORM_EXP, 2^(RENDER_NORM_EXP+1)) */
    CHECK_EQ_INT(s.unit_exp, RENDER_NORM_EXP - 3);
    CHECK_NEAR(num_to_double(s.camera.eye.z), -5.0 * (1 << s.unit_exp), 0);
    CHECK_EQ_INT(s.options.shadows, 0);
    CHECK_EQ_INT(s.options.refractionless, 1);
    CHECK_EQ_INT(s.options.refraction, 1);
    CHECK_EQ_INT(s.options.use_bounds, 1);
    CHECK_NEAR(num_to_double(s.background.b), 0.3, VAL_TOL);
    /* fov 60 horizontal, 64x48: tan(30 deg) * 48/64 */
    CHECK_NEAR(num_to_double(s.camera.tan_half_fov_y), 0.57735026919 * 0.75, VAL_TOL);
    CHECK_EQ_INT(s.light_count, 2);
    CHECK_EQ_INT(s.lights[0].kind, SCENE_LIGHT_POINT);
    CHECK_NEAR(num_to_double(s.lights[0].intensity.g), 0.5, VAL_TOL);
    CHECK_NEAR(LEN(&s, s.lights[0].position.z), 3, VAL_TOL);
    CHECK_EQ_INT(s.lights[1].kind, SCENE_LIGHT_SPOT);
    CHECK_NEAR(num_to_double(s.lights[1].direction.y), -5, VAL_TOL);
    CHECK_NEAR(num_to_double(s.lights[1].cos_inner), 0.93969262, VAL_TOL);
    CHECK_NEAR(num_to_double(s.lights[1].cos_outer), 0.86602540, VAL_TOL);
    CHECK_EQ_INT(s.map_count, 4);
    CHECK_EQ_INT(s.maps[0].kind, SCENE_MAP_COLOUR);
    CHECK_EQ_INT(s.maps[0].width, 2);
    CHECK_EQ_INT(s.maps[0].texels[0], 255);
    CHECK_EQ_INT(s.maps[0].texels[5], 255);
    CHECK_EQ_INT(s.maps[0].texels[3], 0);
    CHECK_NEAR(num_to_double(s.maps[0].repeat_u), 4, 0);
    CHECK_EQ_INT(s.maps[1].kind, SCENE_MAP_BUMP);
    CHECK_EQ_INT(s.maps[1].texels[1], 255);
    CHECK_NEAR(num_to_double(s.maps[1].bump_depth), 0.5, 0);
    /* a normal map: (0, 0.6, 0.8) * 127 as signed bytes; an attribute map */
    CHECK_EQ_INT(s.maps[2].kind, SCENE_MAP_NORMAL);
    CHECK(s.maps[2].texels[0] == 0 && s.maps[2].texels[1] == 76 && s.maps[2].texels[2] == 102);
    CHECK_EQ_INT(s.maps[3].kind, SCENE_MAP_ATTRIBUTE);
    CHECK(s.maps[3].texels[0] == 51 && s.maps[3].texels[1] == 255);
    CHECK_NEAR(num_to_double(s.maps[3].repeat_u), 3, 0);
    CHECK_EQ_INT(s.material_count, 2);
    CHECK_NEAR(num_to_double(s.materials[0].ior), 1.5, 0);
    CHECK_NEAR(num_to_double(s.materials[0].fresnel), 0.5, 0);
    CHECK_EQ_INT(s.materials[0].phong_n, 20);
    CHECK_EQ_INT(s.materials[0].colour_map, 0);
    CHECK_EQ_INT(s.materials[0].bump_map, 1);
    CHECK_EQ_INT(s.materials[1].colour_map, SCENE_NONE);
    CHECK_EQ_INT(s.materials[0].normal_map, SCENE_NONE);
    CHECK_EQ_INT(s.materials[0].src_map, SCENE_NONE);
    CHECK_EQ_INT(s.materials[1].normal_map, 2);
    CHECK_EQ_INT(s.materials[1].bump_map, SCENE_NONE);
    CHECK(s.materials[1].dic_map == 3 && s.materials[1].drc_map == 3 &&
          s.materials[1].src_map == 3 && s.materials[1].trc_map == 3);
    CHECK_EQ_INT(s.cluster_count, 3);
    CHECK(s.clusters[0].parent == SCENE_NO_CLUSTER);
    CHECK_EQ_INT(s.clusters[1].parent, 0);
    CHECK_EQ_INT(s.clusters[2].parent, 1);
    /* each cluster's power of two leaves its matrix and key scales for the
     * lengths it holds: c1's keys scale by up to 2 (its matrix's
     * translation, between the keys and the matrix, times 2), c2 by 2 more
     * (its contents times 4) */
    CHECK_NEAR(LEN(&s, s.clusters[1].local.m[1][3]), 2 * 2, 0);
    CHECK_NEAR(num_to_double(s.clusters[2].local.m[2][2]), 1, 0);
    CHECK_EQ_INT(s.clusters[1].key_count, 2);
    CHECK_EQ_INT(s.key_count, 2);
    CHECK_EQ_INT(s.keys[1].frame, 2);
    /* rotate 0 90 0: quaternion (cos 45, 0, sin 45, 0) */
    CHECK_NEAR(num_to_double(s.keys[1].rot_w), 0.70710678, VAL_TOL);
    CHECK_NEAR(num_to_double(s.keys[1].rot_y), 0.70710678, VAL_TOL);
    CHECK_NEAR(num_to_double(s.keys[1].scale.z), 1, 0);
    CHECK_NEAR(num_to_double(s.keys[0].scale.z), 0.5, 0);
    CHECK_EQ_INT(s.prim_count, 5);
    CHECK_EQ_INT(s.prims[0].kind, SCENE_PRIM_BOX);
    CHECK_NEAR(LEN(&s, s.prims[0].shape.box.centre.z), 1, 0);
    CHECK_NEAR(LEN(&s, s.prims[0].shape.box.half.z), 2, 0);
    CHECK_EQ_INT(s.prims[0].material, 1);
    CHECK_EQ_INT(s.prims[1].kind, SCENE_PRIM_ELLIPSOID);
    CHECK_EQ_INT(s.prims[1].material, 0);
    CHECK_EQ_INT(s.prims[1].cluster, 1);
    CHECK_EQ_INT(s.prims[2].kind, SCENE_PRIM_TRIANGLE);
    CHECK_EQ_INT(s.prims[2].cluster, 2);
    CHECK_NEAR(LEN(&s, s.prims[1].shape.ellipsoid.radius.x), 0.5 * 2, 0);
    CHECK_NEAR(LEN(&s, s.prims[2].shape.triangle.v[1].x), 1 * 4, 0);
    CHECK_NEAR(num_to_double(s.prims[2].shape.triangle.tex_v[2]), 1, 0);
    CHECK_EQ_INT(s.prims[3].kind, SCENE_PRIM_DENSITY);
    CHECK_EQ_INT(s.prims[3].shape.density.count, 2);
    CHECK_NEAR(num_to_double(s.prims[3].shape.density.threshold), 0.5, 0);
    CHECK_EQ_INT(s.density_component_count, 2);
    CHECK_NEAR(num_to_double(s.density_components[1].weight), -0.5, 0);
    CHECK_NEAR(LEN(&s, s.density_components[1].centre.x), 1 * 4, 0);
    CHECK_NEAR(LEN(&s, s.prims[4].shape.ellipsoid.radius.z), 3 * 4, 0);
    free(b);
}

/* Cut the file at every length: each is refused (truncated, or a size
 * mismatch for the cut that leaves the header), never read out of bounds. */
static void test_truncation_every_length(void)
{
    size_t len;
    uint8_t *b = compiled(&len);
    if (!b)
        return;
    int bad = 0;
    for (size_t n = 0; n < len; n++) {
        uint8_t *cut = malloc(n ? n : 1); /* exact size: ASan catches overreads */
        memcpy(cut, b, n);
        scene_load_error_t e;
        scene_load_status_t st = try_load(n ? cut : NULL, n, &e);
        if (st != SCENE_LOAD_ERR_TRUNCATED && !bad++)
            printf("length %zu: status %d (%s)\n", n, st, e.message);
        free(cut);
    }
    CHECK_EQ_INT(bad, 0);
    free(b);
}

static void test_header_fields(void)
{
    size_t len;
    uint8_t *b = compiled(&len);
    if (!b)
        return;
    uint8_t *c = malloc(len);
    scene_load_error_t e;

    memcpy(c, b, len);
    c[1] = 'X';
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_MAGIC);

    memcpy(c, b, len);
    wire_put_u16(c + SCN_HDR_VERSION, SCN_VERSION + 1);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_VERSION);
    char want[48];
    snprintf(want, sizeof want, "reads version %d", SCN_VERSION);
    CHECK(strstr(e.message, want) != NULL);

    memcpy(c, b, len);
    wire_put_u32(c + SCN_HDR_TOTAL, (uint32_t)len - 4);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SIZE);

    memcpy(c, b, len);
    wire_put_u32(c + SCN_HDR_TOTAL, SCN_MAX_SIZE + 1);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SIZE);

    memcpy(c, b, len);
    wire_put_u32(c + SCN_HDR_SUM, wire_get_u32(c + SCN_HDR_SUM) ^ 1);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_CRC);

    memcpy(c, b, len);
    wire_put_u16(c + SCN_HDR_SECTIONS, 0);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION);

    memcpy(c, b, len);
    wire_put_u16(c + SCN_HDR_SECTIONS, SCN_SEC_COUNT + 1);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION);
    free(c);
    free(b);
}

/* Every single-bit flip anywhere in the file is refused. */
static void test_every_bit_flip(void)
{
    size_t len;
    uint8_t *b = compiled(&len);
    if (!b)
        return;
    int accepted = 0;
    for (size_t i = 0; i < len * 8; i++) {
        b[i / 8] ^= (uint8_t)(1u << (i % 8));
        scene_load_error_t e;
        if (try_load(b, len, &e) == SCENE_LOAD_OK && !accepted++)
            printf("flip of bit %zu accepted\n", i);
        b[i / 8] ^= (uint8_t)(1u << (i % 8));
    }
    CHECK_EQ_INT(accepted, 0);
    free(b);
}

/* Section table damage, with the word sum fixed so the table checks are reached. */
static void test_section_table(void)
{
    size_t len;
    uint8_t *b = compiled(&len);
    if (!b)
        return;
    uint8_t *c = malloc(len);
    uint8_t *e0 = c + SCN_HEADER_SIZE; /* first entry: the VIEW section */
    scene_load_error_t e;

    memcpy(c, b, len);
    wire_put_u32(e0 + SCN_SECENT_KIND, 99);
    fix_crc(c, len);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION);

    memcpy(c, b, len);
    wire_put_u32(e0 + SCN_SECENT_KIND, SCN_SEC_CLUSTERS); /* duplicate kind */
    fix_crc(c, len);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION);

    memcpy(c, b, len);
    wire_put_u32(e0 + SCN_SECENT_OFFSET, (uint32_t)len - 8); /* runs past the end */
    fix_crc(c, len);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION);

    memcpy(c, b, len);
    wire_put_u32(e0 + SCN_SECENT_OFFSET, 0xfffffff0u); /* offset + size wraps */
    fix_crc(c, len);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION);

    memcpy(c, b, len);
    wire_put_u32(e0 + SCN_SECENT_OFFSET, wire_get_u32(e0 + SCN_SECENT_OFFSET) + 2);
    fix_crc(c, len);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION); /* misaligned */

    memcpy(c, b, len);
    wire_put_u32(e0 + SCN_SECENT_COUNT, 2); /* a second view: over its limit of 1 */
    fix_crc(c, len);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_LIMIT);

    memcpy(c, b, len);
    wire_put_u32(e0 + SCN_SECENT_BYTES, SCN_VIEW_SIZE - 4); /* size not count * record */
    fix_crc(c, len);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION);

    memcpy(c, b, len);
    wire_put_u32(e0 + SCN_SECENT_OFFSET, wire_get_u32(e0 + SCN_SECENT_OFFSET + SCN_SECENT_SIZE));
    fix_crc(c, len);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION); /* overlap */

    memcpy(c, b, len);
    wire_put_u32(e0 + SCN_SECENT_OFFSET, 0); /* inside the header */
    fix_crc(c, len);
    CHECK_EQ_INT(try_load(c, len, &e), SCENE_LOAD_ERR_SECTION);
    free(c);
    free(b);
}

/* A field of one record changed (CRC fixed): the right error, naming it. */
static void expect_field(const uint8_t *b, size_t len, int kind, uint32_t rec_off,
                         uint32_t value, int bytes, scene_load_status_t want, const char *words)
{
    uint8_t *c = malloc(len);
    memcpy(c, b, len);
    uint8_t *p = c + section_offset(c, kind) + rec_off;
    if (bytes == 1)
        *p = (uint8_t)value;
    else if (bytes == 2)
        wire_put_u16(p, (uint16_t)value);
    else
        wire_put_u32(p, value);
    fix_crc(c, len);
    scene_load_error_t e;
    scene_load_status_t st = try_load(c, len, &e);
    if (st != want || strstr(e.message, words) == NULL) {
        char m[256];
        snprintf(m, sizeof m, "kind %d offset %u: status %d '%s', want %d with '%s'", kind,
                 rec_off, st, e.message, want, words);
        check_fail(__FILE__, __LINE__, m);
    }
    free(c);
}

static uint32_t f32_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static void test_bad_indices_and_values(void)
{
    size_t len;
    uint8_t *b = compiled(&len);
    if (!b)
        return;
    const uint32_t P = SCN_PRIM_SIZE, C = SCN_CLUSTER_SIZE;
    expect_field(b, len, SCN_SEC_PRIMS, SCN_PRIM_MATERIAL, 2, 2, SCENE_LOAD_ERR_INDEX,
                 "prim 0: material");
    expect_field(b, len, SCN_SEC_PRIMS, P + SCN_PRIM_CLUSTER, 3, 4, SCENE_LOAD_ERR_INDEX,
                 "prim 1: cluster");
    expect_field(b, len, SCN_SEC_PRIMS, P + SCN_PRIM_KIND, 9, 2, SCENE_LOAD_ERR_VALUE,
                 "prim 1: unknown kind");
    /* a triangle (prim 2) has no component range (checked apart from its values) */
    expect_field(b, len, SCN_SEC_PRIMS, 2 * P + SCN_PRIM_FIRST, 1, 4, SCENE_LOAD_ERR_VALUE,
                 "prim 2: component range on a primitive that is not a density sphere");
    expect_field(b, len, SCN_SEC_PRIMS, 2 * P + SCN_PRIM_COUNT, 1, 4, SCENE_LOAD_ERR_VALUE,
                 "prim 2: component range on a primitive that is not a density sphere");
    expect_field(b, len, SCN_SEC_PRIMS, 3 * P + SCN_PRIM_COUNT, 3, 4, SCENE_LOAD_ERR_INDEX,
                 "prim 3: components outside");
    expect_field(b, len, SCN_SEC_PRIMS, 3 * P + SCN_PRIM_COUNT, 0, 4, SCENE_LOAD_ERR_LIMIT,
                 "prim 3: component count");
    expect_field(b, len, SCN_SEC_PRIMS, 4 * P + SCN_PRIM_VALUES + 20, f32_bits(-1.0f), 4,
                 SCENE_LOAD_ERR_VALUE, "prim 4: a semi-axis");
    expect_field(b, len, SCN_SEC_PRIMS, 2 * P + SCN_PRIM_VALUES, 0x7fc00000u, 4,
                 SCENE_LOAD_ERR_VALUE, "prim 2: a value is not finite");
    /* lengths to SCN_MAX_COORD, values without a unit to SCN_MAX_FACTOR,
     * and the message names both */
    expect_field(b, len, SCN_SEC_PRIMS, 2 * P + SCN_PRIM_VALUES, f32_bits(2e8f), 4,
                 SCENE_LOAD_ERR_VALUE, "prim 2: a value is not finite or beyond "
                 "+-100000000 (a length) or +-1000 (no unit)");
    expect_field(b, len, SCN_SEC_PRIMS, 2 * P + SCN_PRIM_VALUES + 4 * 9, f32_bits(2000.0f), 4,
                 SCENE_LOAD_ERR_VALUE, "prim 2: a value is not finite or beyond +-");
    expect_field(b, len, SCN_SEC_PRIMS, 3 * P + SCN_PRIM_VALUES, f32_bits(2000.0f), 4,
                 SCENE_LOAD_ERR_VALUE, "prim 3: a value is not finite or beyond +-");
    expect_field(b, len, SCN_SEC_VIEW, SCN_VIEW_EYE + 4, f32_bits(-2e8f), 4,
                 SCENE_LOAD_ERR_VALUE, "camera: a coordinate is not finite or beyond "
                 "+-100000000 (a length)");
    expect_field(b, len, SCN_SEC_VIEW, SCN_VIEW_UP, f32_bits(2000.0f), 4,
                 SCENE_LOAD_ERR_VALUE, "camera: a coordinate is not finite or beyond +-");
    expect_field(b, len, SCN_SEC_LIGHTS, SCN_LIGHT_POSITION, f32_bits(2e8f), 4,
                 SCENE_LOAD_ERR_VALUE, "light 0: position or direction not finite or beyond");
    expect_field(b, len, SCN_SEC_CLUSTERS, C + SCN_CLUSTER_MATRIX + 4 * 3, f32_bits(2e8f), 4,
                 SCENE_LOAD_ERR_VALUE, "cluster 1: a matrix entry not finite or beyond");
    expect_field(b, len, SCN_SEC_CLUSTERS, C + SCN_CLUSTER_MATRIX, f32_bits(2e9f), 4,
                 SCENE_LOAD_ERR_VALUE, "cluster 1: a matrix entry not finite or beyond");
    expect_field(b, len, SCN_SEC_KEYS, SCN_KEY_SCALE, f32_bits(2e9f), 4,
                 SCENE_LOAD_ERR_VALUE, "key 0: translation or scale not finite or beyond");
    expect_field(b, len, SCN_SEC_COMPONENTS, SCN_COMPONENT_WEIGHT, f32_bits(2000.0f), 4,
                 SCENE_LOAD_ERR_VALUE, "density component 0");
    expect_field(b, len, SCN_SEC_PRIMS, 0 * P + SCN_PRIM_VALUES + 4 * 10, f32_bits(1.0f), 4,
                 SCENE_LOAD_ERR_VALUE, "unused value");
    /* the tree: a cycle (parent not below), the root with a parent */
    expect_field(b, len, SCN_SEC_CLUSTERS, C + SCN_CLUSTER_PARENT, 2, 4, SCENE_LOAD_ERR_TREE,
                 "cluster 1: parent");
    expect_field(b, len, SCN_SEC_CLUSTERS, 2 * C + SCN_CLUSTER_PARENT, 2, 4,
                 SCENE_LOAD_ERR_TREE, "cluster 2: parent");
    expect_field(b, len, SCN_SEC_CLUSTERS, SCN_CLUSTER_PARENT, 0, 4, SCENE_LOAD_ERR_TREE,
                 "cluster 0: the root");
    expect_field(b, len, SCN_SEC_CLUSTERS, C + SCN_CLUSTER_KEY_COUNT, 3, 4,
                 SCENE_LOAD_ERR_INDEX, "cluster 1: key range");
    expect_field(b, len, SCN_SEC_CLUSTERS, C + SCN_CLUSTER_MATRIX, 0xff800000u, 4,
                 SCENE_LOAD_ERR_VALUE, "cluster 1: a matrix entry");
    expect_field(b, len, SCN_SEC_KEYS, SCN_KEY_SIZE + SCN_KEY_FRAME, 0, 4,
                 SCENE_LOAD_ERR_TREE, "key frames do not rise");
    expect_field(b, len, SCN_SEC_KEYS, SCN_KEY_ROTATION, f32_bits(0.5f), 4,
                 SCENE_LOAD_ERR_VALUE, "unit quaternion");
    expect_field(b, len, SCN_SEC_MATERIALS, SCN_MAT_COLOUR_MAP, 1, 2, SCENE_LOAD_ERR_INDEX,
                 "material 0: colour map");
    expect_field(b, len, SCN_SEC_MATERIALS, SCN_MAT_BUMP_MAP, 7, 2, SCENE_LOAD_ERR_INDEX,
                 "material 0: bump map");
    /* normal and attribute maps: the kind each index names, not both a
     * bump and a normal map, a normal texel out of the surface (texels:
     * tiles' 6 bytes, bumps' 2, then nrm's x y z) */
    const uint32_t M = SCN_MAT_SIZE;
    expect_field(b, len, SCN_SEC_MATERIALS, M + SCN_MAT_NORMAL_MAP, 1, 2, SCENE_LOAD_ERR_INDEX,
                 "material 1: normal map index out of range or not a normal map");
    expect_field(b, len, SCN_SEC_MATERIALS, M + SCN_MAT_NORMAL_MAP, 4, 2, SCENE_LOAD_ERR_INDEX,
                 "material 1: normal map index");
    expect_field(b, len, SCN_SEC_MATERIALS, SCN_MAT_NORMAL_MAP, 2, 2, SCENE_LOAD_ERR_VALUE,
                 "material 0: both a bump map and a normal map");
    expect_field(b, len, SCN_SEC_MATERIALS, M + SCN_MAT_SRC_MAP, 0, 2, SCENE_LOAD_ERR_INDEX,
                 "material 1: dic, drc, src or trc map index out of range or not an attribute");
    expect_field(b, len, SCN_SEC_MATERIALS, M + SCN_MAT_TRC_MAP, 2, 2, SCENE_LOAD_ERR_INDEX,
                 "not an attribute map");
    expect_field(b, len, SCN_SEC_MATERIALS, SCN_MAT_DIC_MAP, 9, 2, SCENE_LOAD_ERR_INDEX,
                 "material 0: dic, drc, src or trc map");
    expect_field(b, len, SCN_SEC_TEXELS, 6 + 2 + 2, 0x80, 1, SCENE_LOAD_ERR_VALUE,
                 "map 2: normal map texel with z < 1");
    expect_field(b, len, SCN_SEC_TEXELS, 6 + 2 + 2, 0, 1, SCENE_LOAD_ERR_VALUE,
                 "map 2: normal map texel with z < 1");
    expect_field(b, len, SCN_SEC_MAPS, 2 * SCN_MAP_SIZE + SCN_MAP_KIND, SCN_MAP_ATTRIBUTE, 2,
                 SCENE_LOAD_ERR_INDEX, "material 1: normal map index");
    expect_field(b, len, SCN_SEC_MATERIALS, SCN_MAT_DRC, f32_bits(1.5f), 4,
                 SCENE_LOAD_ERR_VALUE, "material 0: colour, dic, drc");
    expect_field(b, len, SCN_SEC_MATERIALS, SCN_MAT_TRC, f32_bits(0.9f), 4,
                 SCENE_LOAD_ERR_VALUE, "src + trc");
    expect_field(b, len, SCN_SEC_MATERIALS, SCN_MAT_IOR, f32_bits(0.5f), 4,
                 SCENE_LOAD_ERR_VALUE, "ior");
    expect_field(b, len, SCN_SEC_MATERIALS, SCN_MAT_PHONG, 5000, 2, SCENE_LOAD_ERR_LIMIT,
                 "phong");
    expect_field(b, len, SCN_SEC_MAPS, SCN_MAP_WIDTH, 100, 2, SCENE_LOAD_ERR_INDEX,
                 "map 0: texels outside");
    expect_field(b, len, SCN_SEC_MAPS, SCN_MAP_WIDTH, 0, 2, SCENE_LOAD_ERR_LIMIT, "map 0: size");
    expect_field(b, len, SCN_SEC_MAPS, SCN_MAP_KIND, 7, 2, SCENE_LOAD_ERR_VALUE,
                 "map 0: unknown kind");
    expect_field(b, len, SCN_SEC_MAPS, SCN_MAP_REPEAT_U, 0, 4, SCENE_LOAD_ERR_VALUE,
                 "map 0: repeat");
    expect_field(b, len, SCN_SEC_LIGHTS, SCN_LIGHT_KIND, 0, 4, SCENE_LOAD_ERR_VALUE,
                 "light 0: unknown kind");
    expect_field(b, len, SCN_SEC_LIGHTS, SCN_LIGHT_COLOUR, f32_bits(-1.0f), 4,
                 SCENE_LOAD_ERR_VALUE, "light 0: colour");
    expect_field(b, len, SCN_SEC_LIGHTS, SCN_LIGHT_SIZE + SCN_LIGHT_COS_OUTER,
                 f32_bits(0.99f), 4, SCENE_LOAD_ERR_VALUE, "light 1: cone");
    expect_field(b, len, SCN_SEC_VIEW, SCN_VIEW_WIDTH, 1025, 2, SCENE_LOAD_ERR_LIMIT,
                 "image size 1025x48");
    expect_field(b, len, SCN_SEC_VIEW, SCN_VIEW_MAX_DEPTH, 17, 2, SCENE_LOAD_ERR_LIMIT,
                 "max depth 17");
    expect_field(b, len, SCN_SEC_VIEW, SCN_VIEW_FLAGS, SCN_OPT_KNOWN + 1, 2, SCENE_LOAD_ERR_VALUE,
                 "option flags");
    expect_field(b, len, SCN_SEC_VIEW, SCN_VIEW_FRAMES, 0, 4, SCENE_LOAD_ERR_LIMIT,
                 "frame count 0");
    expect_field(b, len, SCN_SEC_VIEW, SCN_VIEW_DENSITY_STEPS, SCN_MAX_DENSITY_STEPS + 1, 4,
                 SCENE_LOAD_ERR_LIMIT, "density_steps 257 not 2..256");
    expect_field(b, len, SCN_SEC_VIEW, SCN_VIEW_TAN_HALF_FOV_Y, f32_bits(-0.5f), 4,
                 SCENE_LOAD_ERR_VALUE, "field of view");
    expect_field(b, len, SCN_SEC_COMPONENTS, SCN_COMPONENT_RADIUS, 0, 4, SCENE_LOAD_ERR_VALUE,
                 "density component 0");
    free(b);
}

/* A scene text compiled (checked to parse and compile): the buffer for
 * the caller to free, or NULL. */
static uint8_t *compile_text(const char *text, size_t *len)
{
    struct sd_scene sd;
    char err[SD_ERR_MAX];
    uint8_t *b = NULL;
    CHECK_EQ_INT(sd_parse_text("t.scn", text, &sd, err, sizeof err), 0);
    CHECK_EQ_INT(sd_compile(&sd, &b, len, err, sizeof err), 0);
    sd_free(&sd);
    return b;
}

/* A scene text compiled and loaded into *s (its arena static, as each
 * test's); the compiled buffer, which *s points into, for the caller to
 * free. */
static uint8_t *load_text(const char *text, scene_t *s)
{
    struct sd_scene sd;
    char err[SD_ERR_MAX];
    uint8_t *buf = NULL;
    size_t len = 0;
    CHECK_EQ_INT(sd_parse_text("t.scn", text, &sd, err, sizeof err), 0);
    CHECK_EQ_INT(sd_compile(&sd, &buf, &len, err, sizeof err), 0);
    sd_free(&sd);
    static uint8_t mem[ARENA_BYTES];
    arena_t arena;
    arena_init(&arena, mem, sizeof mem);
    scene_load_error_t e;
    CHECK_EQ_INT(scene_load(buf, len, &arena, s, &e), SCENE_LOAD_OK);
    return buf;
}

/* A cylinder and an open cone: their ends, radii (times 2^unit_exp) and
 * caps loaded; caps not 0 or 1, a negative radius and ends that meet
 * refused by name. */
static void test_cone(void)
{
    static const char *text =
        "camera { eye 0 1 -5 look_at 0 0 0 up 0 1 0 fov 60 }\n"
        "light point { position 1 2 3 }\n"
        "material m { }\n"
        "cylinder { material m base 0 -1 0 apex 0 1 0 radius 0.5 }\n"
        "cone { material m base 1 0 0 base_radius 0.25 apex 2 0 0 apex_radius 0.75 open }\n";
    scene_t s;
    uint8_t *buf = load_text(text, &s);
    if (!buf)
        return;
    CHECK_EQ_INT(s.prim_count, 2);
    double k = ldexp(1.0, s.unit_exp);
    const scene_prim_t *c = &s.prims[0], *d = &s.prims[1];
    CHECK_EQ_INT(c->kind, SCENE_PRIM_CONE);
    CHECK_EQ_INT(c->shape.cone.capped, 1);
    CHECK_NEAR(num_to_double(c->shape.cone.end[0].y), -k, 0);
    CHECK_NEAR(num_to_double(c->shape.cone.radius[1]), 0.5 * k, 0);
    CHECK_EQ_INT(d->kind, SCENE_PRIM_CONE);
    CHECK_EQ_INT(d->shape.cone.capped, 0);
    CHECK_NEAR(num_to_double(d->shape.cone.end[1].x), 2 * k, 0);
    CHECK_NEAR(num_to_double(d->shape.cone.radius[0]), 0.25 * k, 0);
    size_t len = 0;
    struct sd_scene sd;
    char err[SD_ERR_MAX];
    uint8_t *b = NULL;
    CHECK_EQ_INT(sd_parse_text("t.scn", text, &sd, err, sizeof err), 0);
    CHECK_EQ_INT(sd_compile(&sd, &b, &len, err, sizeof err), 0);
    sd_free(&sd);
    const uint32_t V = SCN_PRIM_VALUES;
    expect_field(b, len, SCN_SEC_PRIMS, SCN_PRIM_CAPS, 2, 4, SCENE_LOAD_ERR_VALUE,
                 "prim 0: a cone's caps");
    expect_field(b, len, SCN_SEC_PRIMS, V + 12, f32_bits(-0.5f), 4, SCENE_LOAD_ERR_VALUE,
                 "prim 0: a cone's radius is negative");
    expect_field(b, len, SCN_SEC_PRIMS, V + 20, f32_bits(-1.0f), 4, SCENE_LOAD_ERR_VALUE,
                 "or its ends meet");
    free(b);
    free(buf);
}

/* The tolerances do not follow a far light or eye beyond 8 times the
 * geometry (scene_t.tol_exp): a light at 200 beside spheres reaching 2.5
 * ([2, 4)) scales the lengths by 2^-4 (200 to 12.5) and the tolerances by
 * 2^-6+3 more; a light at 20 leaves them (0); times 64, the same; a light
 * at 1e5, 2^-6 (RENDER_TOL_EXP_MIN). */
static void tol_case(const char *text, int unit_exp, int tol_exp)
{
    scene_t s;
    uint8_t *buf = load_text(text, &s);
    CHECK_EQ_INT(s.unit_exp, unit_exp);
    CHECK_EQ_INT(s.tol_exp, tol_exp);
    free(buf);
}

static void test_tolerance_follows_geometry(void)
{
    tol_case("camera { eye -1 8.8 3.5 look_at 0 0 0.4 }\n"
             "light point { position -100 100 200 }\nmaterial m { }\n"
             "sphere { material m centre 0.9 0.5 2.1 radius 0.4 }\n",
             RENDER_NORM_EXP - 7, -6 + RENDER_TOL_SLACK_EXP);
    tol_case("camera { eye -1 8.8 3.5 look_at 0 0 0.4 }\n"
             "light point { position -10 10 20 }\nmaterial m { }\n"
             "sphere { material m centre 0.9 0.5 2.1 radius 0.4 }\n",
             RENDER_NORM_EXP - 4, 0);
    tol_case("camera { eye -64 563.2 224 look_at 0 0 25.6 }\n"
             "light point { position -640 640 1280 }\nmaterial m { }\n"
             "sphere { material m centre 57.6 32 134.4 radius 25.6 }\n",
             RENDER_NORM_EXP - 10, 0);
    tol_case("camera { eye -1 8.8 3.5 look_at 0 0 0.4 }\n"
             "light point { position -1e5 0 0 }\nmaterial m { }\n"
             "sphere { material m centre 0.9 0.5 2.1 radius 0.4 }\n",
             RENDER_NORM_EXP - 16, RENDER_TOL_EXP_MIN);
    /* the geometry the largest: the tolerances as the lengths */
    tol_case("camera { eye 0 1 -5 look_at 0 0 0 }\n"
             "light point { position 0 5 0 }\nmaterial m { }\n"
             "sphere { material m centre 0 0 0 radius 9 }\n",
             RENDER_NORM_EXP - 3, 0);
}

/* The lengths and tolerances follow the geometry in world units, its
 * clusters' scales included: a sphere of radius 1 at 5 in a cluster scaled
 * by 2^k (the eye and the light scaled by hand) is stored as the same
 * sphere at scale 1, with the same unit_exp and tol_exp, for k from -20
 * to 20 (about 1e-6 to 1e6), whether the scale is the cluster's matrix or
 * its key; the cluster's matrix or key scale is stored as 1.  Before,
 * the lengths followed the coordinates alone, and the matrix kept 2^k. */
static void test_cluster_scale_follows(void)
{
    scene_t one;
    uint8_t *b1 = load_text("camera { eye 0 1 -8 look_at 0 0 5 }\n"
                            "light point { position 4 8 -5 }\nmaterial m { }\n"
                            "cluster c { sphere { material m centre 0 0 5 radius 1 } }\n", &one);
    /* load_text's arena is reused: what is compared, kept */
    int32_t unit1 = one.unit_exp, tol1 = one.tol_exp;
    num_t r1 = one.prims[0].shape.ellipsoid.radius.x, c1 = one.prims[0].shape.ellipsoid.centre.z;
    num_t eye1 = one.camera.eye.z;
    for (int k = -20; k <= 20; k += 5)
        for (int key = 0; key < 2; key++) {
            double f = ldexp(1, k);
            char text[512];
            snprintf(text, sizeof text,
                     "camera { eye 0 %.17g %.17g look_at 0 0 %.17g }\n"
                     "light point { position %.17g %.17g %.17g }\nmaterial m { }\n"
                     "cluster c { %s%.17g%s sphere { material m centre 0 0 5 radius 1 } }\n",
                     f, -8 * f, 5 * f, 4 * f, 8 * f, -5 * f, key ? "key 0 { scale " : "scale ",
                     f, key ? " }" : "");
            scene_t s;
            uint8_t *b = load_text(text, &s);
            CHECK_EQ_INT(s.unit_exp, unit1 - k);
            CHECK_EQ_INT(s.tol_exp, tol1);
            CHECK(num_eq(s.prims[0].shape.ellipsoid.radius.x, r1));
            CHECK(num_eq(s.prims[0].shape.ellipsoid.centre.z, c1));
            CHECK(num_eq(s.camera.eye.z, eye1));
            CHECK(num_eq(key ? s.keys[0].scale.y : s.clusters[1].local.m[1][1], NUM_ONE));
            free(b);
        }
    free(b1);
}

/* A scene at the length limit (SCN_MAX_COORD) loads in every arithmetic,
 * its lengths scaled to 8..16; one beyond it is refused by the compiler,
 * naming the limit. */
static void test_length_limit(void)
{
    const char *text = "camera { eye 0 3e7 -1e8 look_at 0 0 0 }\n"
                       "light point { position 1e8 1e8 -1e8 }\nmaterial m { }\n"
                       "sphere { material m centre 0 0 0 radius 5e7 }\n";
    scene_t s;
    uint8_t *buf = load_text(text, &s);
    CHECK_EQ_INT(s.unit_exp, RENDER_NORM_EXP - 26); /* 1e8 is in [2^26, 2^27) */
    CHECK_NEAR(num_to_double(s.camera.eye.z), -1e8 * ldexp(1, s.unit_exp), VAL_TOL * 16);
    CHECK_NEAR(LEN(&s, s.prims[0].shape.ellipsoid.radius.x), 5e7, 5e7 * VAL_TOL);
    free(buf);
    struct sd_scene sd;
    char err[SD_ERR_MAX];
    const char *beyond = "camera { eye 0 3e7 -2e8 look_at 0 0 0 }\n"
                         "light point { position 0 5 0 }\nmaterial m { }\n"
                         "sphere { material m radius 1 }\n";
    CHECK(sd_parse_text("t.scn", beyond, &sd, err, sizeof err) != 0);
    CHECK(strstr(err, "eye must be -1e+08..1e+08, not -2e8") != NULL);
    const char *scale = "light point { position 0 5 0 }\nmaterial m { }\n"
                        "cluster c { scale 2e9 sphere { material m radius 1 } }\n";
    CHECK(sd_parse_text("t.scn", scale, &sd, err, sizeof err) != 0);
    CHECK(strstr(err, "scale must be -1e+08..1e+08, not 2e9") != NULL);
}

static void test_small_arena(void)
{
    size_t len;
    uint8_t *b = compiled(&len);
    if (!b)
        return;
    static uint8_t mem[256];
    arena_t arena;
    arena_init(&arena, mem, sizeof mem);
    scene_t s;
    scene_load_error_t e;
    CHECK_EQ_INT(scene_load(b, len, &arena, &s, &e), SCENE_LOAD_ERR_ARENA);
    CHECK(strstr(e.message, "arena too small") != NULL);
    CHECK_EQ_INT(arena.used, 0);
    free(b);
}

/* Keys of the camera and the lights: loaded in order (the camera's, then
 * each light's), the angles as their tangent and cosines, and every
 * field a loader must check refused when damaged. */
static void test_view_keys(void)
{
    static const char *text =
        "camera { eye 0 1 -5 look_at 0 0 0 fov 60 key 0 { } key 2 { eye 1 1 -5 fov 40 } }\n"
        "resolution 64 48\n"
        "light point { position 1 2 3 key 1 { colour 0.5 0.5 0.5 } }\n"
        "light spot { position 0 5 0 at 0 0 0 cone 20 falloff 10 key 0 { } key 2 { cone 30 } }\n"
        "material b { }\n"
        "box { material b min -1 -1 -1 max 1 0 3 }\n";
    size_t len = 0;
    uint8_t *b = compile_text(text, &len);
    if (!b)
        return;
    static uint8_t mem[ARENA_BYTES];
    arena_t arena;
    scene_t s;
    scene_load_error_t e;
    arena_init(&arena, mem, sizeof mem);
    CHECK_EQ_INT(scene_load(b, len, &arena, &s, &e), SCENE_LOAD_OK);
    CHECK_EQ_INT(s.view_key_count, 5);
    if (s.view_key_count == 5) {
        static const uint16_t target[5] = {SCENE_VIEW_KEY_CAMERA, SCENE_VIEW_KEY_CAMERA, 0, 1, 1};
        static const uint32_t frame[5] = {0, 2, 1, 0, 2};
        for (int i = 0; i < 5; i++) {
            CHECK_EQ_INT(s.view_keys[i].target, target[i]);
            CHECK_EQ_INT(s.view_keys[i].frame, frame[i]);
        }
        CHECK_NEAR(num_to_double(s.view_keys[1].v.camera.tan_half_fov_y),
                   tan(20 * TEST_PI / 180) * 48 / 64, VAL_TOL);
        CHECK_NEAR(num_to_double(s.view_keys[0].v.camera.tan_half_fov_y),
                   num_to_double(s.camera.tan_half_fov_y), 0);
        CHECK_NEAR(num_to_double(s.view_keys[2].v.light.intensity.g), 0.5, VAL_TOL);
        CHECK_NEAR(num_to_double(s.view_keys[4].v.light.cos_inner), cos(30 * TEST_PI / 180), VAL_TOL);
        CHECK_NEAR(num_to_double(s.view_keys[4].v.light.cos_outer), cos(40 * TEST_PI / 180), VAL_TOL);
        CHECK_EQ_INT(s.view_keys[4].v.light.kind, SCENE_LIGHT_SPOT);
    }
    expect_field(b, len, SCN_SEC_VIEW_KEYS, SCN_VKEY_SIZE + SCN_VKEY_FRAME, 0, 4,
                 SCENE_LOAD_ERR_TREE, "view key 1: out of order");
    expect_field(b, len, SCN_SEC_VIEW_KEYS, 2 * SCN_VKEY_SIZE + SCN_VKEY_TARGET, SCN_VKEY_CAMERA,
                 4, SCENE_LOAD_ERR_TREE, "view key 2: out of order");
    expect_field(b, len, SCN_SEC_VIEW_KEYS, 2 * SCN_VKEY_SIZE + SCN_VKEY_TARGET, 2, 4,
                 SCENE_LOAD_ERR_INDEX, "view key 2: names neither");
    expect_field(b, len, SCN_SEC_VIEW_KEYS, SCN_VKEY_SIZE + SCN_VKEY_TAN_HALF_FOV_Y,
                 f32_bits(-0.5f), 4, SCENE_LOAD_ERR_VALUE, "camera key: field of view");
    expect_field(b, len, SCN_SEC_VIEW_KEYS, SCN_VKEY_RESERVED, 1, 4, SCENE_LOAD_ERR_VALUE,
                 "view key 0: reserved");
    expect_field(b, len, SCN_SEC_VIEW_KEYS, 4 * SCN_VKEY_SIZE + SCN_VKEY_COS_OUTER,
                 f32_bits(0.99f), 4, SCENE_LOAD_ERR_VALUE, "light key 4: cone cosines");
    expect_field(b, len, SCN_SEC_VIEW_KEYS, 2 * SCN_VKEY_SIZE + SCN_VKEY_COLOUR,
                 f32_bits(-1.0f), 4, SCENE_LOAD_ERR_VALUE, "light key 2: colour");
    expect_field(b, len, SCN_SEC_VIEW_KEYS, SCN_VKEY_FRAME, SCN_MAX_FRAMES, 4,
                 SCENE_LOAD_ERR_LIMIT, "view key 0: frame");
    free(b);
}

/* A haze block: its colour and 1/D (scaled with the scene's lengths)
 * loaded, no haze without one, and a bad record refused by name. */
static void test_haze(void)
{
    static const char *text =
        "resolution 8 8\nlight point { colour 1 1 1  position 0 5 -5 }\n"
        "haze { colour 0.25 0.5 0.75  distance 8 }\n"
        "material m { colour 1 1 1  dic 0.2 drc 0.8 }\n"
        "sphere { material m  centre 0 0 0  radius 4 }\n";
    size_t len = 0;
    uint8_t *b = compile_text(text, &len);
    if (!b)
        return;
    static uint8_t mem[ARENA_BYTES];
    arena_t arena;
    scene_t s;
    scene_load_error_t e;
    arena_init(&arena, mem, sizeof mem);
    CHECK_EQ_INT(scene_load(b, len, &arena, &s, &e), SCENE_LOAD_OK);
    CHECK_EQ_INT(s.haze, 1);
    CHECK_NEAR(num_to_double(s.haze_colour.b), 0.75, VAL_TOL);
    /* 1/D per stored unit: lengths are the text's times 2^unit_exp */
    CHECK_NEAR(num_to_double(s.haze_k), ldexp(1.0 / 8, -s.unit_exp), VAL_TOL);
    expect_field(b, len, SCN_SEC_HAZE, SCN_HAZE_COLOUR + 4, f32_bits(1.5f), 4,
                 SCENE_LOAD_ERR_VALUE, "haze colour");
    expect_field(b, len, SCN_SEC_HAZE, SCN_HAZE_INV_DISTANCE, f32_bits(0.0f), 4,
                 SCENE_LOAD_ERR_VALUE, "haze 1/distance");
    expect_field(b, len, SCN_SEC_HAZE, SCN_HAZE_INV_DISTANCE, f32_bits(1.0e6f), 4,
                 SCENE_LOAD_ERR_VALUE, "haze distance under");
    free(b);
    b = compile_text("light point { colour 1 1 1  position 0 5 -5 }\n"
                     "material m { colour 1 1 1 }\nsphere { material m  radius 1 }\n",
                     &len);
    if (!b)
        return;
    arena_init(&arena, mem, sizeof mem);
    CHECK_EQ_INT(scene_load(b, len, &arena, &s, &e), SCENE_LOAD_OK);
    CHECK_EQ_INT(s.haze, 0);
    free(b);
}

/* The triangles' extent (SCN_SEC_EXTENT): the compiler states the
 * loader's own (scene_load_triangle_exp); a load given it makes the scene
 * a load without it makes, bit for bit; one stated below a triangle's
 * coordinate, or beyond the limit, is refused by name; one stated above
 * loads. */
static void test_extent(void)
{
    static const char *text =
        "resolution 8 8\nlight point { colour 1 1 1  position 0 5 -5 }\n"
        "material m { colour 1 1 1 }\n"
        "triangle { material m  v -3 0 0  v 3 0 0  v 0 2.5 1 }\n"
        "cluster c { scale 4\n triangle { material m  v 0 0 0  v 1 0 0  v 0 1 0 } }\n";
    size_t len = 0;
    uint8_t *b = compile_text(text, &len);
    if (!b)
        return;
    static uint8_t mem[ARENA_BYTES], mem2[ARENA_BYTES];
    arena_t arena, arena2;
    uint32_t bits = 0;
    scene_load_error_t e;
    arena_init(&arena, mem, sizeof mem);
    CHECK_EQ_INT(scene_load_triangle_exp(b, len, &arena, &bits, &e), SCENE_LOAD_OK);
    uint32_t at = section_offset(b, SCN_SEC_EXTENT);
    CHECK(at != 0 && wire_get_u32(b + at + SCN_EXTENT_TRI_EXP) == bits);
    CHECK_EQ_INT((int32_t)bits, 2); /* 3 in the root (2^1), 1 in c of scale 4 (2^0 + 2) */
    /* without it: the section's count 0 */
    uint8_t *c = malloc(len);
    memcpy(c, b, len);
    for (int i = 0; i < wire_get_u16(c + SCN_HDR_SECTIONS); i++) {
        uint8_t *ent = c + SCN_HEADER_SIZE + i * SCN_SECENT_SIZE;
        if (wire_get_u32(ent + SCN_SECENT_KIND) == SCN_SEC_EXTENT) {
            wire_put_u32(ent + SCN_SECENT_BYTES, 0);
            wire_put_u32(ent + SCN_SECENT_COUNT, 0);
        }
    }
    fix_crc(c, len);
    scene_t with, without;
    arena_init(&arena, mem, sizeof mem);
    arena_init(&arena2, mem2, sizeof mem2);
    CHECK_EQ_INT(scene_load(b, len, &arena, &with, &e), SCENE_LOAD_OK);
    CHECK_EQ_INT(scene_load(c, len, &arena2, &without, &e), SCENE_LOAD_OK);
    CHECK_EQ_INT(with.unit_exp, without.unit_exp);
    CHECK_EQ_INT(with.tol_exp, without.tol_exp);
    CHECK(with.prim_count == 2 && without.prim_count == 2 &&
          memcmp(with.prims, without.prims, 2 * sizeof *with.prims) == 0);
    free(c);
    expect_field(b, len, SCN_SEC_EXTENT, SCN_EXTENT_TRI_EXP, 0, 4, SCENE_LOAD_ERR_VALUE,
                 "beyond the triangles' extent the scene states");
    expect_field(b, len, SCN_SEC_EXTENT, SCN_EXTENT_TRI_EXP, SCN_EXTENT_NO_TRIANGLE, 4,
                 SCENE_LOAD_ERR_VALUE, "prim 0: a coordinate beyond the triangles' extent");
    expect_field(b, len, SCN_SEC_EXTENT, SCN_EXTENT_TRI_EXP, SCN_EXTENT_EXP_LIMIT + 1, 4,
                 SCENE_LOAD_ERR_VALUE, "the EXTENT section's exponent");
    expect_field(b, len, SCN_SEC_EXTENT, SCN_EXTENT_TRI_EXP, 3, 4, SCENE_LOAD_OK, "");
    /* a coordinate not a number, under a stated extent: refused as a value */
    expect_field(b, len, SCN_SEC_PRIMS, SCN_PRIM_VALUES, 0x7fc00000u, 4, SCENE_LOAD_ERR_VALUE,
                 "prim 0: a value is");
    free(b);
}

/* Anti-aliasing: options { aa N  aa_threshold T } reach render_options_t;
 * a depth over SCN_MAX_AA_DEPTH, a reserved word not 0, a threshold not
 * within 0..1 or not a number are refused, naming the field. */
static void test_antialias(void)
{
    scene_t s;
    uint8_t *b = load_text("light point { colour 1 1 1  position 0 5 -5 }\n"
                           "material m { colour 1 1 1 }\noptions { aa 3  aa_threshold 0.25 }\n"
                           "sphere { material m  radius 1 }\n", &s);
    if (!b)
        return;
    CHECK_EQ_INT(s.options.antialias, 1);
    CHECK_EQ_INT(s.options.aa_depth, 3);
    CHECK_NEAR(num_to_double(s.options.aa_threshold), 0.25, VAL_TOL);
    uint32_t total = wire_get_u32(b + SCN_HDR_TOTAL);
    expect_field(b, total, SCN_SEC_VIEW, SCN_VIEW_AA_DEPTH, SCN_MAX_AA_DEPTH + 1, 2,
                 SCENE_LOAD_ERR_LIMIT, "aa depth 5 not 0..4");
    expect_field(b, total, SCN_SEC_VIEW, SCN_VIEW_AA_ZERO, 1, 2, SCENE_LOAD_ERR_VALUE,
                 "reserved word after aa depth");
    expect_field(b, total, SCN_SEC_VIEW, SCN_VIEW_AA_THRESHOLD, f32_bits(1.5f), 4,
                 SCENE_LOAD_ERR_VALUE, "aa_threshold not within 0..1");
    expect_field(b, total, SCN_SEC_VIEW, SCN_VIEW_AA_THRESHOLD, f32_bits(-0.25f), 4,
                 SCENE_LOAD_ERR_VALUE, "aa_threshold not within 0..1");
    expect_field(b, total, SCN_SEC_VIEW, SCN_VIEW_AA_THRESHOLD, 0x7fc00000u, 4,
                 SCENE_LOAD_ERR_VALUE, "aa_threshold not within 0..1");
    free(b);
    b = load_text("light point { colour 1 1 1  position 0 5 -5 }\n"
                  "material m { colour 1 1 1 }\nsphere { material m  radius 1 }\n", &s);
    if (b)
        CHECK_EQ_INT(s.options.antialias, 0);
    free(b);
}

int main(void)
{
    RUN(test_round_trip);
    RUN(test_truncation_every_length);
    RUN(test_header_fields);
    RUN(test_every_bit_flip);
    RUN(test_section_table);
    RUN(test_bad_indices_and_values);
    RUN(test_length_limit);
    RUN(test_tolerance_follows_geometry);
    RUN(test_cluster_scale_follows);
    RUN(test_small_arena);
    RUN(test_view_keys);
    RUN(test_cone);
    RUN(test_haze);
    RUN(test_antialias);
    RUN(test_extent);
    return check_exit();
}
