/* scene_compile.c: struct sd_scene into the compiled form of
 * proto/scene_format.h.  Angles become the cosines, tangent and quaternions
 * the board needs; everything else is copied field by field through
 * proto/wire.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_board.h"
#include "host-tools/scene/scene_bvh.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_mem.h"
#include "proto/board_map.h"
#include "proto/wordsum.h"
#include "proto/wire.h"

#define COMPILE_PI 3.14159265358979323846

struct compile_section {
    int kind;
    uint32_t count, record;  /* records, bytes per record */
    uint32_t offset;         /* filled in by the layout */
};

static void compile_vec3(uint8_t *p, const double v[3])
{
    for (int i = 0; i < 3; i++)
        wire_put_f32(p + 4 * i, (float)v[i]);
}

/* fov is horizontal (as POV-Ray's angle); the renderer wants the
 * vertical half-angle's tangent. */
static double compile_tan_half_fov_y(double fov, const struct sd_view *v)
{
    return tan(fov * COMPILE_PI / 360.0) * v->height / v->width;
}

static void compile_view(const struct sd_scene *s, uint8_t *p)
{
    const struct sd_view *v = &s->view;
    compile_vec3(p + SCN_VIEW_EYE, v->eye);
    compile_vec3(p + SCN_VIEW_LOOK_AT, v->look_at);
    compile_vec3(p + SCN_VIEW_UP, v->up);
    wire_put_f32(p + SCN_VIEW_TAN_HALF_FOV_Y, (float)compile_tan_half_fov_y(v->fov, v));
    wire_put_u16(p + SCN_VIEW_WIDTH, (uint16_t)v->width);
    wire_put_u16(p + SCN_VIEW_HEIGHT, (uint16_t)v->height);
    compile_vec3(p + SCN_VIEW_BACKGROUND, v->background);
    wire_put_u16(p + SCN_VIEW_MAX_DEPTH, (uint16_t)v->max_depth);
    wire_put_u16(p + SCN_VIEW_FLAGS, (uint16_t)v->flags);
    wire_put_u32(p + SCN_VIEW_FRAMES, (uint32_t)v->frames);
    wire_put_f32(p + SCN_VIEW_MIN_WEIGHT, (float)v->min_weight);
    wire_put_u32(p + SCN_VIEW_DENSITY_STEPS, (uint32_t)v->density_steps);
    wire_put_u16(p + SCN_VIEW_AA_DEPTH, (uint16_t)v->aa_depth);
    wire_put_u16(p + SCN_VIEW_AA_ZERO, 0);
    wire_put_f32(p + SCN_VIEW_AA_THRESHOLD, (float)v->aa_threshold);
}

/* A light's values from colour to cos_outer, at p (its record's colour
 * field or its key's: the same order, scene_format.h). */
#define COMPILE_LIGHT_AT(field) (p + (SCN_LIGHT_##field - SCN_LIGHT_COLOUR))
static void compile_light_values(int kind, const double colour[3], const double position[3],
                                 const double direction[3], double cone, double falloff,
                                 uint8_t *p)
{
    compile_vec3(COMPILE_LIGHT_AT(COLOUR), colour);
    compile_vec3(COMPILE_LIGHT_AT(POSITION), position);
    compile_vec3(COMPILE_LIGHT_AT(DIRECTION), direction);
    double inner = 1, outer = 0;
    if (kind == SCN_LIGHT_SPOT) {
        inner = cos(cone * COMPILE_PI / 180.0);
        outer = cos((cone + falloff) * COMPILE_PI / 180.0);
    }
    wire_put_f32(COMPILE_LIGHT_AT(COS_INNER), (float)inner);
    wire_put_f32(COMPILE_LIGHT_AT(COS_OUTER), (float)outer);
}
#undef COMPILE_LIGHT_AT

static void compile_light(const struct sd_light *l, uint8_t *p)
{
    wire_put_u32(p + SCN_LIGHT_KIND, (uint32_t)l->kind);
    compile_light_values(l->kind, l->colour, l->position, l->direction, l->cone, l->falloff,
                         p + SCN_LIGHT_COLOUR);
}

/* The keys of the camera and the lights, the camera's first, then each
 * light's in light order (each target's keys lie together in s, frames
 * rising). */
static void compile_view_keys(const struct sd_scene *s, uint8_t *p)
{
    for (int target = -1; target < s->n_lights; target++)
        for (int i = 0; i < s->n_view_keys; i++) {
            const struct sd_view_key *k = &s->view_keys[i];
            if (k->target != target)
                continue;
            wire_put_u32(p + SCN_VKEY_FRAME, (uint32_t)k->frame);
            if (target < 0) {
                wire_put_u32(p + SCN_VKEY_TARGET, SCN_VKEY_CAMERA);
                compile_vec3(p + SCN_VKEY_EYE, k->eye);
                compile_vec3(p + SCN_VKEY_LOOK_AT, k->look_at);
                compile_vec3(p + SCN_VKEY_UP, k->up);
                wire_put_f32(p + SCN_VKEY_TAN_HALF_FOV_Y,
                             (float)compile_tan_half_fov_y(k->fov, &s->view));
            } else {
                wire_put_u32(p + SCN_VKEY_TARGET, (uint32_t)target);
                compile_light_values(s->lights[target].kind, k->colour, k->position,
                                     k->direction, k->cone, k->falloff, p + SCN_VKEY_COLOUR);
            }
            p += SCN_VKEY_SIZE;
        }
}

static uint16_t compile_index(int i) { return i < 0 ? SCN_NO_INDEX : (uint16_t)i; }

static void compile_material(const struct sd_material *m, uint8_t *p)
{
    compile_vec3(p + SCN_MAT_COLOUR, m->colour);
    wire_put_f32(p + SCN_MAT_DIC, (float)m->dic);
    wire_put_f32(p + SCN_MAT_DRC, (float)m->drc);
    wire_put_f32(p + SCN_MAT_SRC, (float)m->src);
    wire_put_f32(p + SCN_MAT_TRC, (float)m->trc);
    wire_put_f32(p + SCN_MAT_FRESNEL, (float)m->fresnel);
    wire_put_f32(p + SCN_MAT_IOR, (float)m->ior);
    wire_put_u16(p + SCN_MAT_PHONG, (uint16_t)m->phong);
    wire_put_u16(p + SCN_MAT_COLOUR_MAP, compile_index(m->colour_map));
    wire_put_u16(p + SCN_MAT_BUMP_MAP, compile_index(m->bump_map));
    wire_put_u16(p + SCN_MAT_NORMAL_MAP, compile_index(m->normal_map));
    wire_put_u16(p + SCN_MAT_DIC_MAP, compile_index(m->dic_map));
    wire_put_u16(p + SCN_MAT_DRC_MAP, compile_index(m->drc_map));
    wire_put_u16(p + SCN_MAT_SRC_MAP, compile_index(m->src_map));
    wire_put_u16(p + SCN_MAT_TRC_MAP, compile_index(m->trc_map));
}

static size_t compile_map_bytes(const struct sd_map *m)
{
    return (size_t)m->width * (size_t)m->height * sd_map_texel_bytes(m->kind);
}

static void compile_cluster(const struct sd_cluster *c, uint8_t *p)
{
    wire_put_u32(p + SCN_CLUSTER_PARENT, c->parent < 0 ? SCN_NO_CLUSTER : (uint32_t)c->parent);
    wire_put_u32(p + SCN_CLUSTER_KEY_COUNT, (uint32_t)c->key_count);
    wire_put_u32(p + SCN_CLUSTER_KEY_FIRST, (uint32_t)(c->key_count ? c->key_first : 0));
    for (int i = 0; i < 12; i++)
        wire_put_f32(p + SCN_CLUSTER_MATRIX + 4 * i, (float)c->m[i]);
}

/* Primitive pr in cluster cluster (its own, or the automatic tree's). */
static void compile_prim(const struct sd_prim *pr, int cluster, uint8_t *p)
{
    wire_put_u16(p + SCN_PRIM_KIND, (uint16_t)pr->kind);
    wire_put_u16(p + SCN_PRIM_MATERIAL, (uint16_t)pr->material);
    wire_put_u32(p + SCN_PRIM_CLUSTER, (uint32_t)cluster);
    if (pr->kind == SCN_PRIM_CONE)
        wire_put_u32(p + SCN_PRIM_CAPS, pr->capped ? SCN_CONE_CAPPED : SCN_CONE_OPEN);
    if (pr->kind == SCN_PRIM_DENSITY) {
        wire_put_u32(p + SCN_PRIM_FIRST, (uint32_t)pr->first);
        wire_put_u32(p + SCN_PRIM_COUNT, (uint32_t)pr->count);
    }
    for (int i = 0; i < SCN_PRIM_MAX_VALUES; i++)
        wire_put_f32(p + SCN_PRIM_VALUES + 4 * i, (float)pr->v[i]);
}

static void compile_key(const struct sd_key *k, uint8_t *p)
{
    double q[4];
    sd_euler_quat(k->rotate, q);
    wire_put_u32(p + SCN_KEY_FRAME, (uint32_t)k->frame);
    compile_vec3(p + SCN_KEY_TRANSLATE, k->translate);
    for (int i = 0; i < 4; i++)
        wire_put_f32(p + SCN_KEY_ROTATION + 4 * i, (float)q[i]);
    compile_vec3(p + SCN_KEY_SCALE, k->scale);
}

static void compile_maps(const struct sd_scene *s, uint8_t *p)
{
    uint32_t first = 0;
    for (int k = 0; k < s->n_maps; k++) {
        const struct sd_map *m = &s->maps[k];
        uint8_t *r = p + k * SCN_MAP_SIZE;
        wire_put_u16(r + SCN_MAP_KIND, (uint16_t)m->kind);
        wire_put_u16(r + SCN_MAP_WIDTH, (uint16_t)m->width);
        wire_put_u16(r + SCN_MAP_HEIGHT, (uint16_t)m->height);
        wire_put_u32(r + SCN_MAP_FIRST, first);
        wire_put_f32(r + SCN_MAP_REPEAT_U, (float)m->repeat_u);
        wire_put_f32(r + SCN_MAP_REPEAT_V, (float)m->repeat_v);
        wire_put_f32(r + SCN_MAP_BUMP_DEPTH, (float)m->bump_depth);
        first += (uint32_t)compile_map_bytes(m);
    }
}

static void compile_texels(const struct sd_scene *s, uint8_t *p)
{
    for (int k = 0; k < s->n_maps; k++) {
        size_t mb = compile_map_bytes(&s->maps[k]);
        memcpy(p, s->maps[k].texels, mb);
        p += mb;
    }
}

static void compile_components(const struct sd_scene *s, uint8_t *p)
{
    for (int k = 0; k < s->n_components; k++) {
        const struct sd_component *c = &s->components[k];
        uint8_t *r = p + (size_t)k * SCN_COMPONENT_SIZE;
        compile_vec3(r + SCN_COMPONENT_CENTRE, c->centre);
        wire_put_f32(r + SCN_COMPONENT_RADIUS, (float)c->radius);
        wire_put_f32(r + SCN_COMPONENT_WEIGHT, (float)c->weight);
    }
}

static void compile_normals(const struct sd_scene *s, uint8_t *p)
{
    for (int k = 0; k < s->n_prims; k++) {
        const struct sd_prim *pr = &s->prims[k];
        if (pr->kind != SCN_PRIM_TRIANGLE || !pr->smooth)
            continue;
        wire_put_u32(p + SCN_NORMALS_PRIM, (uint32_t)k);
        for (int j = 0; j < 9; j++)
            wire_put_f32(p + SCN_NORMALS_N + 4 * j, (float)pr->n[j]);
        p += SCN_NORMALS_SIZE;
    }
}

/* Section kind's records written at p; prim_cluster: each primitive's
 * cluster in the automatic tree, or NULL (its own). */
static void compile_section_body(const struct sd_scene *s, const int *prim_cluster, int kind,
                                 uint8_t *p)
{
    switch (kind) {
    case SCN_SEC_VIEW: compile_view(s, p); break;
    case SCN_SEC_LIGHTS:
        for (int k = 0; k < s->n_lights; k++)
            compile_light(&s->lights[k], p + k * SCN_LIGHT_SIZE);
        break;
    case SCN_SEC_MATERIALS:
        for (int k = 0; k < s->n_materials; k++)
            compile_material(&s->materials[k], p + k * SCN_MAT_SIZE);
        break;
    case SCN_SEC_MAPS: compile_maps(s, p); break;
    case SCN_SEC_TEXELS: compile_texels(s, p); break;
    case SCN_SEC_CLUSTERS:
        for (int k = 0; k < s->n_clusters; k++)
            compile_cluster(&s->clusters[k], p + k * SCN_CLUSTER_SIZE);
        break;
    case SCN_SEC_PRIMS:
        for (int k = 0; k < s->n_prims; k++)
            compile_prim(&s->prims[k], prim_cluster ? prim_cluster[k] : s->prims[k].cluster,
                         p + (size_t)k * SCN_PRIM_SIZE);
        break;
    case SCN_SEC_COMPONENTS: compile_components(s, p); break;
    case SCN_SEC_KEYS:
        for (int k = 0; k < s->n_keys; k++)
            compile_key(&s->keys[k], p + (size_t)k * SCN_KEY_SIZE);
        break;
    case SCN_SEC_NORMALS: compile_normals(s, p); break;
    case SCN_SEC_VIEW_KEYS: compile_view_keys(s, p); break;
    case SCN_SEC_HAZE:
        compile_vec3(p + SCN_HAZE_COLOUR, s->view.haze_colour);
        wire_put_f32(p + SCN_HAZE_INV_DISTANCE, (float)(1.0 / s->view.haze_distance));
        break;
    case SCN_SEC_EXTENT: /* compile_extent states it once the rest is written */
        wire_put_u32(p + SCN_EXTENT_TRI_EXP, SCN_EXTENT_NO_TRIANGLE);
        break;
    }
}

/* The non-empty sections of s into used[] with their offsets: header,
 * table of the sections, then their bodies, each aligned.  Their count;
 * *total the form's bytes. */
static int compile_layout(const struct sd_scene *s, size_t texel_bytes,
                          struct compile_section used[SCN_SEC_COUNT], size_t *total)
{
    uint32_t n_smooth = 0;
    for (int i = 0; i < s->n_prims; i++)
        n_smooth += s->prims[i].kind == SCN_PRIM_TRIANGLE && s->prims[i].smooth;
    const struct compile_section all[SCN_SEC_COUNT] = {
        {SCN_SEC_VIEW, 1, SCN_VIEW_SIZE, 0},
        {SCN_SEC_LIGHTS, (uint32_t)s->n_lights, SCN_LIGHT_SIZE, 0},
        {SCN_SEC_MATERIALS, (uint32_t)s->n_materials, SCN_MAT_SIZE, 0},
        {SCN_SEC_MAPS, (uint32_t)s->n_maps, SCN_MAP_SIZE, 0},
        {SCN_SEC_TEXELS, (uint32_t)texel_bytes, 1, 0},
        {SCN_SEC_CLUSTERS, (uint32_t)s->n_clusters, SCN_CLUSTER_SIZE, 0},
        {SCN_SEC_PRIMS, (uint32_t)s->n_prims, SCN_PRIM_SIZE, 0},
        {SCN_SEC_COMPONENTS, (uint32_t)s->n_components, SCN_COMPONENT_SIZE, 0},
        {SCN_SEC_KEYS, (uint32_t)s->n_keys, SCN_KEY_SIZE, 0},
        {SCN_SEC_NORMALS, n_smooth, SCN_NORMALS_SIZE, 0},
        {SCN_SEC_VIEW_KEYS, (uint32_t)s->n_view_keys, SCN_VKEY_SIZE, 0},
        {SCN_SEC_HAZE, s->view.haze ? 1u : 0u, SCN_HAZE_SIZE, 0},
        {SCN_SEC_EXTENT, 1, SCN_EXTENT_SIZE, 0}, /* compile_extent's */
    };
    int n = 0;
    for (int i = 0; i < SCN_SEC_COUNT; i++)
        if (all[i].count > 0)
            used[n++] = all[i];
    size_t pos = SCN_HEADER_SIZE + (size_t)n * SCN_SECENT_SIZE;
    for (int i = 0; i < n; i++) {
        pos = (pos + SCN_SECTION_ALIGN - 1) & ~(size_t)(SCN_SECTION_ALIGN - 1);
        used[i].offset = (uint32_t)pos;
        pos += (size_t)used[i].count * used[i].record;
    }
    *total = (pos + SCN_SECTION_ALIGN - 1) & ~(size_t)(SCN_SECTION_ALIGN - 1);
    return n;
}

/* The header: magic, version, section count and size (the word sum:
 * compile_sum, once the body is whole). */
static void compile_header(uint8_t *b, int n, size_t total)
{
    b[SCN_HDR_MAGIC + 0] = SCN_MAGIC_0;
    b[SCN_HDR_MAGIC + 1] = SCN_MAGIC_1;
    b[SCN_HDR_MAGIC + 2] = SCN_MAGIC_2;
    b[SCN_HDR_MAGIC + 3] = SCN_MAGIC_3;
    wire_put_u16(b + SCN_HDR_VERSION, SCN_VERSION);
    wire_put_u16(b + SCN_HDR_SECTIONS, (uint16_t)n);
    wire_put_u32(b + SCN_HDR_TOTAL, (uint32_t)total);
}

static void compile_sum(uint8_t *b, size_t total)
{
    wire_put_u32(b + SCN_HDR_SUM, wordsum(b + SCN_SUM_START, total - SCN_SUM_START));
}

/* The EXTENT section's value of the form b[0..total) (section entry at):
 * the triangles' exponent as the loader works it out (sd_extent_bits), so
 * that its loads need not. */
static int compile_extent(uint8_t *b, size_t total, const struct compile_section *at, char *err,
                          size_t errlen)
{
    uint32_t bits;
    if (sd_extent_bits(b, total, &bits, err, errlen) != 0)
        return -1;
    wire_put_u32(b + at->offset + SCN_EXTENT_TRI_EXP, bits);
    return 0;
}

static int compile_form(const struct sd_scene *s, const int *prim_cluster, uint8_t **out,
                        size_t *len, char *err, size_t errlen)
{
    *out = NULL;
    *len = 0;
    size_t texel_bytes = 0;
    for (int i = 0; i < s->n_maps; i++)
        texel_bytes += compile_map_bytes(&s->maps[i]);
    if (texel_bytes > SCN_MAX_TEXEL_BYTES) {
        snprintf(err, errlen, "maps hold %zu texel bytes, more than the %u allowed",
                 texel_bytes, SCN_MAX_TEXEL_BYTES);
        return -1;
    }
    struct compile_section used[SCN_SEC_COUNT];
    size_t total;
    int n = compile_layout(s, texel_bytes, used, &total);
    if (total > SCN_MAX_SIZE) {
        snprintf(err, errlen,
                 "compiled scene is %zu bytes (%d clusters, %d primitives), more than "
                 "SCN_MAX_SIZE (%u bytes)",
                 total, s->n_clusters, s->n_prims, SCN_MAX_SIZE);
        return -1;
    }
    uint8_t *b = scene_mem_zalloc(total);
    if (!b) {
        snprintf(err, errlen, "out of memory compiling the scene");
        return -1;
    }
    for (int i = 0; i < n; i++) {
        uint8_t *e = b + SCN_HEADER_SIZE + i * SCN_SECENT_SIZE;
        wire_put_u32(e + SCN_SECENT_KIND, (uint32_t)used[i].kind);
        wire_put_u32(e + SCN_SECENT_OFFSET, used[i].offset);
        wire_put_u32(e + SCN_SECENT_BYTES, used[i].count * used[i].record);
        wire_put_u32(e + SCN_SECENT_COUNT, used[i].count);
        compile_section_body(s, prim_cluster, used[i].kind, b + used[i].offset);
    }
    compile_header(b, n, total);
    int x = 0;
    while (used[x].kind != SCN_SEC_EXTENT) /* always among them */
        x++;
    if (compile_extent(b, total, &used[x], err, errlen) != 0) { /* reads no sum */
        free(b);
        return -1;
    }
    compile_sum(b, total);
    *out = b;
    *len = total;
    return 0;
}

/* The compiled form, refused when the board could not hold it. */
static int compile_checked(const struct sd_scene *s, const int *prim_cluster, uint8_t **out,
                           size_t *len, char *err, size_t errlen)
{
    if (compile_form(s, prim_cluster, out, len, err, errlen) != 0)
        return -1;
    if (sd_board_check(*out, *len, SD_BOARD_BLOB_LIMIT, err, errlen) == 0)
        return 0;
    free(*out);
    *out = NULL;
    *len = 0;
    return -1;
}

int sd_compile(const struct sd_scene *s, uint8_t **out, size_t *len, char *err, size_t errlen)
{
    for (int i = 0; s->paper && i < s->n_prims; i++)
        if (s->prims[i].kind == SCN_PRIM_CONE) {
            snprintf(err, errlen, "paper mode keeps the paper's four primitives, but its cones "
                                  "and cylinders could not be faceted (%d sides round would "
                                  "pass SCN_MAX_PRIMS primitives, or memory)", SD_CONE_SIDES);
            return -1;
        }
    *out = NULL;
    *len = 0;
    if (s->no_auto_hierarchy || s->n_prims == 0)
        return compile_checked(s, NULL, out, len, err, errlen);
    /* the same scene with the tree's clusters, the primitives moved into
     * its leaves (prim_cluster); everything else shared */
    struct sd_scene t = *s;
    int *prim_cluster = scene_mem_alloc((size_t)s->n_prims * sizeof *prim_cluster);
    struct bvh_build_stats stats;
    int rc = -1;
    if (!prim_cluster)
        snprintf(err, errlen, "out of memory compiling the scene");
    else if (sd_auto_hierarchy(s, &t.clusters, &t.n_clusters, prim_cluster, &stats, err, errlen) == 0) {
        rc = compile_checked(&t, prim_cluster, out, len, err, errlen);
        free(t.clusters);
    }
    free(prim_cluster);
    return rc;
}
