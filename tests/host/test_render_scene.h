/* test_render_scene.h: scenes built in C for the renderer's tests, so they
 * need neither the scene compiler nor the loader.
 *
 * The default camera sits at the origin looking along +z with y up, so
 * world and eye coordinates coincide and expected values can be worked out
 * by hand in one frame.
 */
#ifndef LINKS1_TEST_RENDER_SCENE_H
#define LINKS1_TEST_RENDER_SCENE_H

#include <string.h>

#include "proto/scene_format.h"
#include "render/render.h"
#include "render/vec3.h"

#define TS_MAX 64

typedef struct {
    scene_t scene;
    scene_light_t lights[RENDER_MAX_LIGHTS];
    scene_material_t materials[TS_MAX];
    scene_map_t maps[4];
    scene_cluster_t clusters[TS_MAX];
    scene_key_t keys[TS_MAX];
    scene_prim_t prims[TS_MAX];
    scene_density_component_t comps[TS_MAX];
    scene_normals_t normals[TS_MAX];
    uint8_t arena_memory[1 << 20];
    arena_t arena;
} test_scene_t;

static inline vec3_t ts_v(double x, double y, double z)
{
    return vec3_make(num_from_double(x), num_from_double(y), num_from_double(z));
}

static inline rgb_t ts_rgb(double r, double g, double b)
{
    return rgb_make(num_from_double(r), num_from_double(g), num_from_double(b));
}

/* Empty scene: root cluster, one grey diffuse material (index 0). */
static inline void ts_init(test_scene_t *t, uint16_t width, uint16_t height)
{
    memset(t, 0, sizeof *t);
    scene_t *s = &t->scene;
    s->width = width;
    s->height = height;
    s->frame_count = 1;
    s->camera.eye = ts_v(0, 0, 0);
    s->camera.look_at = ts_v(0, 0, 1);
    s->camera.up = ts_v(0, 1, 0);
    s->camera.tan_half_fov_y = num_from_double(0.5);
    s->background = ts_rgb(0, 0, 0);
    s->options.max_depth = 4;
    s->options.density_steps = SCN_DEFAULT_DENSITY_STEPS;
    s->options.refractionless = 1;
    s->options.use_bounds = 1;
    s->options.use_hierarchy = 1;
    s->options.shadows = 1;
    s->options.refraction = 1;
    s->options.ambient_shadowed = 1; /* the text form's defaults */
    s->options.shadow_tint = 0;
    s->lights = t->lights;
    s->materials = t->materials;
    s->maps = t->maps;
    s->clusters = t->clusters;
    s->keys = t->keys;
    s->prims = t->prims;
    s->density_components = t->comps;
    s->normals = t->normals;
    t->clusters[0].parent = SCENE_NO_CLUSTER;
    t->clusters[0].local = xform_identity();
    s->cluster_count = 1;
    scene_material_t *m = &t->materials[0];
    m->colour = ts_rgb(1, 1, 1);
    m->drc = num_from_double(1);
    m->ior = NUM_ONE;
    scene_material_no_maps(m);
    s->material_count = 1;
    arena_init(&t->arena, t->arena_memory, sizeof t->arena_memory);
}

static inline uint16_t ts_material(test_scene_t *t, scene_material_t m)
{
    if (!m.ior)
        m.ior = NUM_ONE;
    t->materials[t->scene.material_count] = m;
    return t->scene.material_count++;
}

static inline uint16_t ts_cluster(test_scene_t *t, uint16_t parent, xform_t local)
{
    scene_cluster_t *c = &t->clusters[t->scene.cluster_count];
    c->parent = parent;
    c->local = local;
    return t->scene.cluster_count++;
}

static inline xform_t ts_translate(double x, double y, double z)
{
    xform_t m = xform_identity();
    m.m[0][3] = num_from_double(x);
    m.m[1][3] = num_from_double(y);
    m.m[2][3] = num_from_double(z);
    return m;
}

/* Rotation by deg degrees about z (cos/sin given, computed on the host). */
static inline xform_t ts_rotate_z(double c, double s, double tx, double ty, double tz)
{
    xform_t m = ts_translate(tx, ty, tz);
    m.m[0][0] = num_from_double(c);
    m.m[0][1] = num_from_double(-s);
    m.m[1][0] = num_from_double(s);
    m.m[1][1] = num_from_double(c);
    return m;
}

static inline scene_prim_t *ts_prim(test_scene_t *t, uint8_t kind, uint16_t cluster, uint16_t material)
{
    scene_prim_t *p = &t->prims[t->scene.prim_count++];
    p->kind = kind;
    p->cluster = cluster;
    p->material = material;
    return p;
}

static inline void ts_triangle(test_scene_t *t, uint16_t cluster, uint16_t material, vec3_t a, vec3_t b,
                               vec3_t c)
{
    scene_prim_t *p = ts_prim(t, SCENE_PRIM_TRIANGLE, cluster, material);
    p->shape.triangle.v[0] = a;
    p->shape.triangle.v[1] = b;
    p->shape.triangle.v[2] = c;
    p->shape.triangle.tex_u[1] = NUM_ONE;
    p->shape.triangle.tex_v[2] = NUM_ONE;
}

/* Triangle prim made smooth: vertex normals a, b, c (unit length), a
 * record of its own. */
static inline void ts_smooth(test_scene_t *t, uint32_t prim, vec3_t a, vec3_t b, vec3_t c)
{
    scene_normals_t *n = &t->normals[t->scene.normals_count++];
    n->n[0] = a;
    n->n[1] = b;
    n->n[2] = c;
    t->prims[prim].shape.triangle.smooth = t->scene.normals_count;
}

static inline void ts_ellipsoid(test_scene_t *t, uint16_t cluster, uint16_t material, vec3_t c, vec3_t r)
{
    scene_prim_t *p = ts_prim(t, SCENE_PRIM_ELLIPSOID, cluster, material);
    p->shape.ellipsoid.centre = c;
    p->shape.ellipsoid.radius = r;
}

static inline void ts_box(test_scene_t *t, uint16_t cluster, uint16_t material, vec3_t c, vec3_t half)
{
    scene_prim_t *p = ts_prim(t, SCENE_PRIM_BOX, cluster, material);
    p->shape.box.centre = c;
    p->shape.box.half = half;
}

/* A cone from base (radius r0) to apex (radius r1), capped or open. */
static inline void ts_cone(test_scene_t *t, uint16_t cluster, uint16_t material, vec3_t base,
                           double r0, vec3_t apex, double r1, int capped)
{
    scene_prim_t *p = ts_prim(t, SCENE_PRIM_CONE, cluster, material);
    p->shape.cone.end[0] = base;
    p->shape.cone.end[1] = apex;
    p->shape.cone.radius[0] = num_from_double(r0);
    p->shape.cone.radius[1] = num_from_double(r1);
    p->shape.cone.capped = (uint8_t)capped;
}

/* Density sphere of n components (centres, radii d, weights b). */
static inline void ts_density(test_scene_t *t, uint16_t cluster, uint16_t material, double threshold,
                              int n, const double (*comp)[5])
{
    scene_prim_t *p = ts_prim(t, SCENE_PRIM_DENSITY, cluster, material);
    p->shape.density.first = t->scene.density_component_count;
    p->shape.density.count = (uint16_t)n;
    p->shape.density.threshold = num_from_double(threshold);
    for (int i = 0; i < n; i++) {
        scene_density_component_t *c = &t->comps[t->scene.density_component_count++];
        c->centre = ts_v(comp[i][0], comp[i][1], comp[i][2]);
        c->radius = num_from_double(comp[i][3]);
        c->weight = num_from_double(comp[i][4]);
    }
}

static inline scene_light_t *ts_light(test_scene_t *t, uint8_t kind, rgb_t intensity)
{
    scene_light_t *l = &t->lights[t->scene.light_count++];
    l->kind = kind;
    l->intensity = intensity;
    return l;
}

/* Prepare frame 0; NULL (and a message) on failure. */
static inline render_frame_t *ts_prepare(test_scene_t *t)
{
    render_frame_t *f = NULL;
    arena_reset(&t->arena);
    render_status_t st = render_prepare(&t->scene, 0, &t->arena, &f);
    if (st != RENDER_OK)
        printf("# render_prepare: %s\n", render_status_name(st));
    return f;
}

#endif
