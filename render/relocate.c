/* render/relocate.c: every pointer field of a scene and a prepared frame,
 * moved by the distance between two copies of a blob (see relocate.h).
 *
 * This file is the one list of the renderer's pointer fields.  A pointer
 * field added to scene_t, scene_map_t, render_frame_t or render_prim_t must
 * be added here, or a broadcast copy keeps reading the old block:
 * test_relocate_no_stale_pointer (tests/host/test_blob.c) fails then.
 */
#include "render/relocate.h"

typedef struct {
    uintptr_t old_lo, old_hi; /* the original blob [old_lo, old_hi) */
    uintptr_t new_lo;         /* where its copy starts */
    int write;                /* 0: check every pointer; 1: rewrite them */
    int frame_only;           /* 1: the scene is relocated already; 2: and
                                 the frame's arrays (its header's pointers
                                 alone are moved) */
    const char *bad;          /* first field outside the blob, or NULL */
} reloc_t;

/* The copy's address of the array of count elements (elem bytes each,
 * aligned to align) that the old pointer p names; NULL, with r->bad set to
 * field, when that array is not wholly inside the old blob.  A NULL p is
 * an empty array or an error. */
static void *reloc_addr(reloc_t *r, const void *p, size_t count, size_t elem, size_t align,
                        const char *field)
{
    uintptr_t a = (uintptr_t)p;
    if (r->write) /* every field was checked by the first pass */
        return p ? (void *)(a - r->old_lo + r->new_lo) : NULL;
    if (r->bad)
        return NULL;
    if (!p) {
        if (count != 0)
            r->bad = field;
        return NULL;
    }
    /* count is compared by division so a garbage count cannot wrap */
    if (a < r->old_lo || a > r->old_hi || (a & (align - 1)) != 0 || count > (r->old_hi - a) / elem) {
        r->bad = field;
        return NULL;
    }
    return (void *)(a - r->old_lo + r->new_lo);
}

#define RELOC(r, ptr, count, field) \
    reloc_addr((r), (ptr), (size_t)(count), sizeof *(ptr), _Alignof(__typeof__(*(ptr))), (field))

static void reloc_scene(reloc_t *r, scene_t *s)
{
    scene_light_t *lights = RELOC(r, s->lights, s->light_count, "scene.lights");
    scene_material_t *materials = RELOC(r, s->materials, s->material_count, "scene.materials");
    scene_map_t *maps = RELOC(r, s->maps, s->map_count, "scene.maps");
    scene_cluster_t *clusters = RELOC(r, s->clusters, s->cluster_count, "scene.clusters");
    scene_key_t *keys = RELOC(r, s->keys, s->key_count, "scene.keys");
    scene_prim_t *prims = RELOC(r, s->prims, s->prim_count, "scene.prims");
    scene_density_component_t *comps =
        RELOC(r, s->density_components, s->density_component_count, "scene.density_components");
    scene_normals_t *normals = RELOC(r, s->normals, s->normals_count, "scene.normals");
    scene_view_key_t *view_keys = RELOC(r, s->view_keys, s->view_key_count, "scene.view_keys");
    /* the index (render_scene_index): all its arrays or none */
    scene_index_t ix = {.parent_map_count = s->index.parent_map_count,
                        .own_count = s->index.own_count,
                        .pointer_lo = s->index.pointer_lo,
                        .pointer_hi = s->index.pointer_hi,
                        .keyed_lo = s->index.keyed_lo,
                        .keyed_hi = s->index.keyed_hi};
    if (s->index.groups || s->index.child_list || s->index.prim_list || s->index.normal_src ||
        s->index.uv_spread || s->index.parent_maps || s->index.own_list) {
        ix.groups = RELOC(r, s->index.groups, s->cluster_count, "scene.index.groups");
        ix.child_list = RELOC(r, s->index.child_list, s->cluster_count, "scene.index.child_list");
        ix.prim_list = RELOC(r, s->index.prim_list, s->prim_count, "scene.index.prim_list");
        ix.normal_src = RELOC(r, s->index.normal_src, 3 * (size_t)s->normals_count,
                              "scene.index.normal_src");
        ix.uv_spread = RELOC(r, s->index.uv_spread, s->prim_count, "scene.index.uv_spread");
        ix.parent_maps = RELOC(r, s->index.parent_maps, s->index.parent_map_count,
                               "scene.index.parent_maps");
        ix.own_list = RELOC(r, s->index.own_list, s->index.own_count ? s->index.own_count : 1,
                            "scene.index.own_list");
        /* an empty array is still an allocation: none may be NULL */
        if (!r->bad && (!ix.groups || !ix.child_list || !ix.prim_list || !ix.normal_src ||
                        !ix.uv_spread || !ix.parent_maps || !ix.own_list))
            r->bad = "scene.index (part of it NULL)";
    }
    if (r->bad)
        return;
    for (uint32_t i = 0; i < s->map_count; i++) {
        scene_map_t *m = &maps[i];
        size_t bytes = (size_t)m->width * m->height * scene_map_texel_bytes(m->kind);
        const uint8_t *texels = RELOC(r, m->texels, bytes, "scene.maps[].texels");
        if (r->write)
            m->texels = texels;
    }
    if (!r->write || r->bad)
        return;
    s->lights = lights;
    s->materials = materials;
    s->maps = maps;
    s->clusters = clusters;
    s->keys = keys;
    s->prims = prims;
    s->density_components = comps;
    s->normals = normals;
    s->view_keys = view_keys;
    s->index = ix;
}

/* f and s are the copy's frame and scene; f->scene is rewritten by the
 * caller. */
static void reloc_frame(reloc_t *r, render_frame_t *f, const scene_t *s)
{
    render_cluster_t *clusters = RELOC(r, f->clusters, f->cluster_count, "frame.clusters");
    uint32_t *child_list = RELOC(r, f->child_list, f->cluster_count, "frame.child_list");
    render_prim_t *prims = RELOC(r, f->prims, f->prim_count, "frame.prims");
    uint32_t *prim_list = RELOC(r, f->prim_list, f->prim_count, "frame.prim_list");
    num_t *inv_radius2 =
        RELOC(r, f->density_inv_radius2, s->density_component_count, "frame.density_inv_radius2");
    if (r->bad)
        return;
    /* a triangle holds no pointer (its vertex normals are in it): only
     * [pointer_lo, pointer_hi) is looked into (the RC relocates every
     * frame), and there any other kind's density pointers are checked and
     * moved (NULL with no components: an ellipsoid's, a box's) */
    uint32_t hi = f->pointer_hi < f->prim_count ? f->pointer_hi : f->prim_count;
    for (uint32_t i = f->pointer_lo; r->frame_only < 2 && i < hi; i++) {
        render_prim_t *p = &prims[i];
        if (p->kind == SCENE_PRIM_TRIANGLE)
            continue;
        const scene_density_component_t *comps =
            RELOC(r, p->components, p->component_count, "frame.prims[].components");
        const num_t *inv = RELOC(r, p->inv_radius2, p->component_count, "frame.prims[].inv_radius2");
        if (r->write && !r->bad) {
            p->components = comps;
            p->inv_radius2 = inv;
        }
    }
    if (!r->write || r->bad)
        return;
    f->clusters = clusters;
    f->child_list = child_list;
    f->prims = prims;
    f->prim_list = prim_list;
    f->density_inv_radius2 = inv_radius2;
}

/* One pass over everything reachable from scene and frame (old
 * addresses); *new_scene and *new_frame get their copies. */
static void reloc_pass(reloc_t *r, const scene_t *scene, render_frame_t *frame, scene_t **new_scene,
                       render_frame_t **new_frame)
{
    *new_frame = frame ? RELOC(r, frame, 1, "frame") : NULL;
    *new_scene = scene ? RELOC(r, scene, 1, "scene") : NULL;
    if (r->bad)
        return;
    if (*new_frame) {
        scene_t *fs = RELOC(r, (*new_frame)->scene, 1, "frame.scene");
        if (r->bad)
            return;
        if (*new_scene && fs != *new_scene) {
            r->bad = "frame.scene (not the scene given)";
            return;
        }
        *new_scene = fs;
        reloc_frame(r, *new_frame, fs);
        if (r->write && !r->bad)
            (*new_frame)->scene = fs;
    }
    if (*new_scene && !r->bad && !r->frame_only)
        reloc_scene(r, *new_scene);
}

static render_status_t reloc_run(void *new_base, size_t size, uintptr_t old_base,
                                 const scene_t **scene, render_frame_t **frame,
                                 const char **bad_field, int frame_only)
{
    uintptr_t new_lo = (uintptr_t)new_base;
    reloc_t r = {old_base, old_base + size, new_lo, 0, frame_only, NULL};
    if (bad_field)
        *bad_field = NULL;
    if (!new_base || old_base % RENDER_RELOCATE_ALIGN != 0 || new_lo % RENDER_RELOCATE_ALIGN != 0 ||
        size > UINTPTR_MAX - old_base || size > UINTPTR_MAX - new_lo) {
        if (bad_field)
            *bad_field = "base (NULL, not aligned to RENDER_RELOCATE_ALIGN, or the range wraps)";
        return RENDER_ERR_RELOCATE;
    }
    scene_t *new_scene = NULL;
    render_frame_t *new_frame = NULL;
    /* check everything first so a failure leaves the copy as it was */
    for (r.write = 0; r.write < 2; r.write++) {
        reloc_pass(&r, scene ? *scene : NULL, frame ? *frame : NULL, &new_scene, &new_frame);
        if (r.bad) {
            if (bad_field)
                *bad_field = r.bad;
            return RENDER_ERR_RELOCATE;
        }
    }
    if (scene)
        *scene = new_scene;
    if (frame)
        *frame = new_frame;
    return RENDER_OK;
}

render_status_t render_relocate(void *new_base, size_t size, uintptr_t old_base,
                                const scene_t **scene, render_frame_t **frame,
                                const char **bad_field)
{
    return reloc_run(new_base, size, old_base, scene, frame, bad_field, 0);
}

render_status_t render_relocate_frame(void *new_base, size_t size, uintptr_t old_base,
                                      render_frame_t **frame, const char **bad_field)
{
    return reloc_run(new_base, size, old_base, NULL, frame, bad_field, 1);
}

render_status_t render_relocate_frame_header(void *new_base, size_t size, uintptr_t old_base,
                                             render_frame_t **frame, const char **bad_field)
{
    return reloc_run(new_base, size, old_base, NULL, frame, bad_field, 2);
}
