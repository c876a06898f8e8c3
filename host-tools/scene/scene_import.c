/* scene_import.c: a model (model.h) into scene records (scene_import.h).
 * Everything is checked before anything is added, so a refused model
 * leaves the scene as it was: nothing renders half a model. */
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_import.h"

/* Scratch of one import: the numbers worked out before the scene changes. */
struct imp {
    const struct model *m;
    const struct import_opts *o;
    struct import_result *r;
    char *err;
    size_t errlen;
    double (*world)[12];    /* node -> model root, right-handed, unscaled */
    int *kept;              /* per mesh: triangles not degenerate */
    int *mesh_uses;         /* per mesh: nodes that place it */
    struct sd_map maps[SCN_MAX_MAPS];
    int n_maps;             /* maps this import adds */
    int *mat_colour, *mat_bump; /* per model material: scene map index or -1 */
};

static int imp_fail(struct imp *im, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int imp_fail(struct imp *im, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(im->err, im->errlen, fmt, ap);
    va_end(ap);
    return -1;
}

static int imp_finite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

/* A right-handed 3x4 transform in the scene's left-handed coordinates
 * (S M S with S = diag(1, 1, -1)), its translation scaled. */
static void imp_flip_matrix(const double in[12], double scale, double out[12])
{
    memcpy(out, in, 12 * sizeof *out);
    out[2] = -out[2], out[6] = -out[6], out[8] = -out[8], out[9] = -out[9];
    out[11] = -out[11];
    out[3] *= scale, out[7] *= scale, out[11] *= scale;
}

static void imp_point(const double m[12], const double p[3], double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3];
}

/* A mesh's triangle t in the scene's coordinates: 9 values. */
static void imp_triangle(const struct model_mesh *me, int t, double scale, double v[9])
{
    for (int j = 0; j < 3; j++) {
        const double *p = me->pos + 3 * me->idx[3 * t + j];
        v[3 * j] = p[0] * scale;
        v[3 * j + 1] = p[1] * scale;
        v[3 * j + 2] = -p[2] * scale;
    }
}

/* The model's normals at triangle t's vertices in the scene's coordinates
 * (z negated), unit length; 0 when the mesh has none or one of them is
 * zero or not finite (the triangle is then flat). */
static int imp_normals(const struct model_mesh *me, int t, double n[9])
{
    if (!me->nrm)
        return 0;
    for (int j = 0; j < 3; j++) {
        const double *a = me->nrm + 3 * me->idx[3 * t + j];
        double len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        if (!isfinite(len) || !(len > 1e-6))
            return 0;
        n[3 * j] = a[0] / len;
        n[3 * j + 1] = a[1] / len;
        n[3 * j + 2] = -a[2] / len;
    }
    return 1;
}

/* A triangle with vertices 1 and 2 (and their uv and normals) swapped.
 * With z negated the file's winding (counter-clockwise seen from outside,
 * as OBJ, glTF and the other formats have it) would make the scene's face
 * normal (e1 x e2) point into the model: every triangle is turned over, so
 * that it points out, as the renderer reads it (a ray entering glass
 * meets the outward side; a normal map's z and a bump map's heights are
 * along it). */
static void imp_turn_over(struct sd_prim *pr)
{
    for (int k = 0; k < 3; k++) {
        double t = pr->v[3 + k];
        pr->v[3 + k] = pr->v[6 + k], pr->v[6 + k] = t;
        t = pr->n[3 + k];
        pr->n[3 + k] = pr->n[6 + k], pr->n[6 + k] = t;
    }
    for (int k = 9; k <= 12; k += 3) {
        double t = pr->v[k + 1];
        pr->v[k + 1] = pr->v[k + 2], pr->v[k + 2] = t;
    }
}

/* Nodes, meshes and indices hold together and every number is finite. */
static int imp_check_structure(struct imp *im)
{
    const struct model *m = im->m;
    for (int k = 0; k < m->n_nodes; k++) {
        const struct model_node *n = &m->nodes[k];
        if (!imp_finite(n->m, 12))
            return imp_fail(im, "node '%s': its transform is not finite", n->name);
        for (int i = 0; i < n->n_meshes; i++)
            if (m->node_meshes[n->first_mesh + i] < 0 ||
                m->node_meshes[n->first_mesh + i] >= m->n_meshes)
                return imp_fail(im, "node '%s': mesh index out of range", n->name);
    }
    for (int i = 0; i < m->n_meshes; i++) {
        const struct model_mesh *me = &m->meshes[i];
        if (im->o->material < 0 && (me->material < 0 || me->material >= m->n_materials))
            return imp_fail(im, "mesh '%s': material index %d out of range", me->name,
                            me->material);
        for (int v = 0; v < me->n_vertices; v++) {
            if (!imp_finite(me->pos + 3 * v, 3))
                return imp_fail(im, "mesh '%s': vertex %d is not finite (%g %g %g)", me->name,
                                v, me->pos[3 * v], me->pos[3 * v + 1], me->pos[3 * v + 2]);
            if (me->uv && !imp_finite(me->uv + 2 * v, 2))
                return imp_fail(im, "mesh '%s': vertex %d has a uv that is not finite",
                                me->name, v);
        }
        for (int t = 0; t < 3 * me->n_triangles; t++)
            if (me->idx[t] < 0 || me->idx[t] >= me->n_vertices)
                return imp_fail(im, "mesh '%s': triangle %d names vertex %d of %d", me->name,
                                t / 3, me->idx[t], me->n_vertices);
    }
    return 0;
}

/* World transforms, nesting, extent, and the --fit scale. */
static int imp_place(struct imp *im)
{
    const struct model *m = im->m;
    struct import_result *r = im->r;
    double big = 0, lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY,
                                                                      -INFINITY};
    int *depth = calloc((size_t)m->n_nodes + 1, sizeof *depth);
    if (!depth)
        return imp_fail(im, "out of memory");
    for (int k = 0; k < m->n_nodes; k++) {
        const struct model_node *n = &m->nodes[k];
        if (n->parent >= 0) {
            sd_mat_mul(im->world[n->parent], n->m, im->world[k]);
            depth[k] = depth[n->parent] + 1;
        } else {
            memcpy(im->world[k], n->m, sizeof im->world[k]);
        }
        int nest = im->o->nesting + 1 + depth[k];
        if (nest > SCN_MAX_CLUSTER_NESTING) {
            free(depth);
            return imp_fail(im, "node '%s' is nested %d deep, more than the %d clusters may "
                                "nest",
                            n->name, nest, SCN_MAX_CLUSTER_NESTING);
        }
        for (int i = 0; i < 12; i++) {
            if ((i % 4) != 3 && fabs(n->m[i]) > SCN_MAX_SCALE) {
                free(depth);
                return imp_fail(im, "node '%s': a transform entry is %g, beyond +-%g",
                                n->name, n->m[i], (double)SCN_MAX_SCALE);
            }
            if ((i % 4) == 3)
                big = fmax(big, fabs(n->m[i]));
        }
        for (int j = 0; j < n->n_meshes; j++) {
            const struct model_mesh *me = &m->meshes[m->node_meshes[n->first_mesh + j]];
            for (int v = 0; v < me->n_vertices; v++) {
                double w[3];
                imp_point(im->world[k], me->pos + 3 * v, w);
                for (int a = 0; a < 3; a++) {
                    big = fmax(big, fmax(fabs(w[a]), fabs(me->pos[3 * v + a])));
                    lo[a] = fmin(lo[a], w[a]);
                    hi[a] = fmax(hi[a], w[a]);
                }
                if (me->uv && (fabs(me->uv[2 * v]) > SCN_MAX_FACTOR ||
                               fabs(me->uv[2 * v + 1]) > SCN_MAX_FACTOR)) {
                    free(depth);
                    return imp_fail(im, "mesh '%s': vertex %d has uv %g %g, beyond +-%g",
                                    me->name, v, me->uv[2 * v], me->uv[2 * v + 1],
                                    (double)SCN_MAX_FACTOR);
                }
            }
        }
    }
    free(depth);
    if (lo[0] > hi[0])
        return imp_fail(im, "the model has no triangles");
    r->scale = 1;
    if (big > SCN_MAX_COORD) {
        if (!im->o->fit)
            return imp_fail(im, "the model spans x %g..%g, y %g..%g, z %g..%g: beyond the "
                                "+-%g a coordinate may reach (%s scales it into range)",
                            lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], (double)SCN_MAX_COORD,
                            im->o->fit_hint);
        r->scale = IMPORT_FIT_EXTENT / big;
    }
    for (int a = 0; a < 3; a++) {
        double l = lo[a] * r->scale, h = hi[a] * r->scale;
        r->lo[a] = a == 2 ? -h : l;
        r->hi[a] = a == 2 ? -l : h;
    }
    return 0;
}

/* Triangles kept per mesh, and the counts against the scene's limits. */
static int imp_count(struct imp *im, const struct sd_scene *s)
{
    const struct model *m = im->m;
    long total = 0;
    for (int i = 0; i < m->n_meshes; i++) {
        const struct model_mesh *me = &m->meshes[i];
        for (int t = 0; t < me->n_triangles; t++) {
            double v[9];
            imp_triangle(me, t, im->r->scale, v);
            im->kept[i] += !sd_triangle_degenerate(v);
        }
    }
    for (int k = 0; k < m->n_nodes; k++)
        for (int j = 0; j < m->nodes[k].n_meshes; j++) {
            int i = m->node_meshes[m->nodes[k].first_mesh + j];
            im->mesh_uses[i]++;
            total += im->kept[i];
            im->r->degenerate += m->meshes[i].n_triangles - im->kept[i];
            im->r->other += m->meshes[i].n_other;
        }
    if (total == 0)
        return imp_fail(im, "the model has no triangles%s",
                        im->r->degenerate ? " that are not degenerate" : "");
    if (total > SCN_MAX_PRIMS - s->n_prims)
        return imp_fail(im, "the model has %ld triangles, the scene room for %d more (the "
                            "limit is %d primitives)",
                        total, SCN_MAX_PRIMS - s->n_prims, SCN_MAX_PRIMS);
    if (m->n_nodes > SCN_MAX_CLUSTERS - s->n_clusters)
        return imp_fail(im, "the model has %d nodes, the scene room for %d more clusters "
                            "(the limit is %d)",
                        m->n_nodes, SCN_MAX_CLUSTERS - s->n_clusters, SCN_MAX_CLUSTERS);
    if (im->o->material < 0 && m->n_materials > SCN_MAX_MATERIALS - s->n_materials)
        return imp_fail(im, "the model has %d materials, the scene room for %d more (the "
                            "limit is %d)",
                        m->n_materials, SCN_MAX_MATERIALS - s->n_materials,
                        SCN_MAX_MATERIALS);
    im->r->triangles = (int)total;
    return 0;
}

/* A name the text form reads back as a word: [A-Za-z_][A-Za-z0-9_.-]*,
 * at most SCN_MAX_NAME - 5 characters (room for a "_NNNN" to make it
 * unique), fallback when empty. */
static void imp_word(const char *in, const char *fallback, char *out)
{
    size_t n = 0, room = SCN_MAX_NAME - 6;
    if (!((in[0] >= 'A' && in[0] <= 'Z') || (in[0] >= 'a' && in[0] <= 'z') || in[0] == '_') &&
        in[0])
        out[n++] = '_';
    for (const char *c = in; *c && n < room; c++) {
        int ok = (*c >= 'A' && *c <= 'Z') || (*c >= 'a' && *c <= 'z') ||
                 (*c >= '0' && *c <= '9') || *c == '_' || *c == '.' || *c == '-';
        out[n++] = ok ? *c : '_';
    }
    out[n] = 0;
    if (n == 0)
        snprintf(out, SCN_MAX_NAME, "%s", fallback);
}

/* word with "_k" after it, into out of SCN_MAX_NAME bytes. */
static void imp_numbered(const char *word, int k, char *out)
{
    char t[SCN_MAX_NAME + 16];
    snprintf(t, sizeof t, "%s_%d", word, k);
    size_t n = strlen(t) < SCN_MAX_NAME - 1 ? strlen(t) : SCN_MAX_NAME - 1;
    memcpy(out, t, n);
    out[n] = 0;
}

static int imp_map_named(const struct sd_scene *s, const struct imp *im, const char *name)
{
    for (int i = 0; i < s->n_maps; i++)
        if (strcmp(s->maps[i].name, name) == 0)
            return 1;
    for (int i = 0; i < im->n_maps; i++)
        if (strcmp(im->maps[i].name, name) == 0)
            return 1;
    return 0;
}

static int imp_material_named(const struct sd_scene *s, const struct sd_material *add, int n,
                              const char *name)
{
    for (int i = 0; i < s->n_materials; i++)
        if (strcmp(s->materials[i].name, name) == 0)
            return 1;
    for (int i = 0; i < n; i++)
        if (strcmp(add[i].name, name) == 0)
            return 1;
    return 0;
}

/* A texture as a map of the import (shared by the materials that use the
 * same file the same way): its scene map index, or -1 with err. */
static int imp_texture(struct imp *im, const struct sd_scene *s, const char *model_dir,
                       const struct model_material *mm, const char *tex, int kind)
{
    const char *what = kind == SCN_MAP_COLOUR   ? "diffuse texture"
                       : kind == SCN_MAP_NORMAL ? "normal texture"
                                                : "bump texture";
    if (tex[0] == '*')
        return imp_fail(im, "material '%s': %s %s is embedded in the model file; only "
                            "texture files (PNG or PPM) are read",
                        mm->name, what, tex);
    char path[IMPORT_PATH_MAX];
    snprintf(path, sizeof path, "%s%s", tex[0] == '/' ? "" : model_dir, tex);
    for (int i = 0; i < im->n_maps; i++)
        if (im->maps[i].kind == kind && strcmp(im->r->map_image[s->n_maps + i], path) == 0)
            return s->n_maps + i;
    if (s->n_maps + im->n_maps >= SCN_MAX_MAPS)
        return imp_fail(im, "material '%s': %s %s would be map %d, more than the %d a scene "
                            "may have",
                        mm->name, what, path, s->n_maps + im->n_maps + 1, SCN_MAX_MAPS);
    struct sd_map *mp = &im->maps[im->n_maps];
    memset(mp, 0, sizeof *mp);
    mp->kind = kind;
    mp->repeat_u = mp->repeat_v = 1;
    mp->bump_depth = kind == SCN_MAP_BUMP ? 1 : 0;
    char why[SD_ERR_MAX];
    int fd = sd_texture_open(tex, model_dir, im->o->textures_from, path, sizeof path, why,
                             sizeof why);
    if (fd < 0 || sd_map_read_image_fd(mp, fd, path, why, sizeof why) != 0)
        return imp_fail(im, "material '%s': %s: %s", mm->name, what, why);
    const char *base = strrchr(tex, '/');
    char word[SCN_MAX_NAME];
    imp_word(base ? base + 1 : tex, "map", word);
    snprintf(mp->name, sizeof mp->name, "%s", word);
    for (int k = 2; imp_map_named(s, im, mp->name); k++)
        imp_numbered(word, k, mp->name);
    snprintf(im->r->map_image[s->n_maps + im->n_maps], IMPORT_PATH_MAX, "%s", path);
    return s->n_maps + im->n_maps++;
}

static double imp_clamp(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

static double imp_max3(const double v[3]) { return fmax(v[0], fmax(v[1], v[2])); }

/* The paper's Fig. 5 material of a model material (docs/import.md). */
static void imp_material(const struct model_material *mm, struct sd_material *d)
{
    memset(d, 0, sizeof *d);
    d->colour[0] = d->colour[1] = d->colour[2] = 1;
    d->dic = 0.1;
    d->drc = 0.9;
    d->ior = 1;
    sd_material_no_maps(d);
    if (mm->have & MODEL_HAVE_DIFFUSE) {
        double k = imp_max3(mm->diffuse);
        d->drc = imp_clamp(k, 0, 1);
        for (int i = 0; i < 3; i++)
            d->colour[i] = k > 0 ? imp_clamp(mm->diffuse[i] / k, 0, 1) : 1;
    }
    if (mm->have & MODEL_HAVE_AMBIENT)
        d->dic = imp_clamp(imp_max3(mm->ambient), 0, 1);
    double trc = 0;
    if (mm->have & MODEL_HAVE_OPACITY)
        trc = 1 - imp_clamp(mm->opacity, 0, 1);
    if (mm->have & MODEL_HAVE_TRANSMISSION)
        trc = fmax(trc, imp_clamp(mm->transmission, 0, 1));
    d->trc = trc;
    if (mm->have & MODEL_HAVE_SPECULAR)
        d->src = imp_clamp(imp_max3(mm->specular) * mm->shininess_strength, 0, 1 - trc);
    if (mm->have & MODEL_HAVE_SHININESS)
        d->phong = (int)lround(imp_clamp(mm->shininess, 0, SCN_MAX_PHONG));
    if ((mm->have & MODEL_HAVE_IOR) && mm->ior >= 1)
        d->ior = fmin(mm->ior, SCN_MAX_IOR);
}

/* The model's materials and their maps, not yet in the scene. */
static int imp_materials(struct imp *im, const struct sd_scene *s, const char *model_dir,
                         struct sd_material *out)
{
    const struct model *m = im->m;
    size_t texel_bytes = 0;
    for (int i = 0; i < s->n_maps; i++)
        texel_bytes += (size_t)s->maps[i].width * (size_t)s->maps[i].height *
                       sd_map_texel_bytes(s->maps[i].kind);
    for (int i = 0; i < m->n_materials; i++) {
        const struct model_material *mm = &m->materials[i];
        struct sd_material *d = &out[i];
        imp_material(mm, d);
        char word[SCN_MAX_NAME];
        imp_word(mm->name, "material", word);
        snprintf(d->name, sizeof d->name, "%s", word);
        for (int k = 2; imp_material_named(s, out, i, d->name); k++)
            imp_numbered(word, k, d->name);
        int before = im->n_maps;
        if (mm->diffuse_tex[0] &&
            (d->colour_map = imp_texture(im, s, model_dir, mm, mm->diffuse_tex,
                                         SCN_MAP_COLOUR)) < 0)
            return -1;
        /* a height texture is a bump map; a normal texture a normal map in
         * the tangent frame of the triangles' texture coordinates */
        if (mm->bump_tex[0]) {
            int kind = mm->bump_is_normal ? SCN_MAP_NORMAL : SCN_MAP_BUMP;
            int k = imp_texture(im, s, model_dir, mm, mm->bump_tex, kind);
            if (k < 0)
                return -1;
            *(kind == SCN_MAP_NORMAL ? &d->normal_map : &d->bump_map) = k;
        }
        for (int k = before; k < im->n_maps; k++)
            texel_bytes += (size_t)im->maps[k].width * (size_t)im->maps[k].height *
                           sd_map_texel_bytes(im->maps[k].kind);
        if (texel_bytes > SCN_MAX_TEXEL_BYTES)
            return imp_fail(im, "material '%s': its textures bring the scene's texels to %zu "
                                "bytes, more than the limit %u",
                            mm->name, texel_bytes, SCN_MAX_TEXEL_BYTES);
    }
    return 0;
}

/* Grows *arr to hold n + add elements exactly. */
static int imp_grow(void **arr, int n, int add, size_t elem)
{
    void *na = realloc(*arr, ((size_t)n + (size_t)add + 1) * elem);
    if (!na)
        return -1;
    *arr = na;
    return 0;
}

/* Adds the checked model to s. */
static int imp_commit(struct imp *im, struct sd_scene *s, int parent, struct sd_material *mats)
{
    const struct model *m = im->m;
    int add_mats = im->o->material < 0 ? m->n_materials : 0;
    if (imp_grow((void **)&s->clusters, s->n_clusters, m->n_nodes, sizeof *s->clusters) ||
        imp_grow((void **)&s->prims, s->n_prims, im->r->triangles, sizeof *s->prims) ||
        imp_grow((void **)&s->materials, s->n_materials, add_mats, sizeof *s->materials))
        return imp_fail(im, "out of memory adding the model");
    int first_cluster = s->n_clusters, first_mat = s->n_materials;
    memcpy(s->materials + s->n_materials, mats, (size_t)add_mats * sizeof *mats);
    s->n_materials += add_mats;
    memcpy(s->maps + s->n_maps, im->maps, (size_t)im->n_maps * sizeof *im->maps);
    s->n_maps += im->n_maps;
    im->r->maps = im->n_maps;
    im->n_maps = 0; /* the scene owns their texels now */
    for (int k = 0; k < m->n_nodes; k++) {
        const struct model_node *n = &m->nodes[k];
        struct sd_cluster *c = &s->clusters[s->n_clusters++];
        memset(c, 0, sizeof *c);
        char word[SCN_MAX_NAME];
        imp_word(n->name, "node", word);
        snprintf(c->name, sizeof c->name, "%s", word);
        c->parent = n->parent < 0 ? parent : first_cluster + n->parent;
        imp_flip_matrix(n->m, im->r->scale, c->m);
        for (int j = 0; j < n->n_meshes; j++) {
            const struct model_mesh *me = &m->meshes[m->node_meshes[n->first_mesh + j]];
            for (int t = 0; t < me->n_triangles; t++) {
                struct sd_prim pr;
                memset(&pr, 0, sizeof pr);
                imp_triangle(me, t, im->r->scale, pr.v);
                if (sd_triangle_degenerate(pr.v))
                    continue;
                pr.kind = SCN_PRIM_TRIANGLE;
                pr.cluster = s->n_clusters - 1;
                pr.material = im->o->material >= 0 ? im->o->material : first_mat + me->material;
                for (int jj = 0; jj < 3; jj++) {
                    int vi = me->idx[3 * t + jj];
                    /* the model's v runs up the image, the scene's down it */
                    pr.v[9 + jj] = me->uv ? me->uv[2 * vi] : jj == 1;
                    pr.v[12 + jj] = me->uv ? 1 - me->uv[2 * vi + 1] : jj == 2;
                }
                if (im->o->smooth) {
                    pr.smooth = imp_normals(me, t, pr.n);
                    im->r->smooth += pr.smooth;
                    im->r->flat += !pr.smooth;
                }
                imp_turn_over(&pr);
                s->prims[s->n_prims++] = pr;
            }
        }
    }
    im->r->clusters = m->n_nodes;
    im->r->materials = add_mats;
    return 0;
}

int scene_import_model(struct sd_scene *s, int parent, const struct model *m,
                       const char *model_dir, const struct import_opts *o,
                       struct import_result *r, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    struct imp im;
    memset(&im, 0, sizeof im);
    im.m = m, im.o = o, im.r = r, im.err = err, im.errlen = errlen;
    if (m->n_nodes == 0)
        return imp_fail(&im, "the model has no nodes");
    im.world = calloc((size_t)m->n_nodes, sizeof *im.world);
    im.kept = calloc((size_t)m->n_meshes + 1, sizeof *im.kept);
    im.mesh_uses = calloc((size_t)m->n_meshes + 1, sizeof *im.mesh_uses);
    struct sd_material *mats = calloc((size_t)m->n_materials + 1, sizeof *mats);
    int rc = -1;
    if (!im.world || !im.kept || !im.mesh_uses || !mats)
        imp_fail(&im, "out of memory");
    else if (imp_check_structure(&im) == 0 && imp_place(&im) == 0 && imp_count(&im, s) == 0 &&
             (o->material >= 0 || imp_materials(&im, s, model_dir, mats) == 0))
        rc = imp_commit(&im, s, parent, mats);
    for (int i = 0; i < im.n_maps; i++)
        free(im.maps[i].texels);
    free(im.world);
    free(im.kept);
    free(im.mesh_uses);
    free(mats);
    return rc;
}
