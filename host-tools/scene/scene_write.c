/* scene_write.c: a scene back into the text form (scene_import.h), the
 * output of `links1 import`.  Numbers are written so they read back to the
 * same double. */
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_import.h"

/* The shortest of %.15g, %.16g, %.17g that reads back as x. */
static void wr_num(FILE *f, double x)
{
    char b[40];
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(b, sizeof b, "%.*g", prec, x);
        if (strtod(b, NULL) == x)
            break;
    }
    fprintf(f, " %s", b);
}

static void wr_vec(FILE *f, const char *word, const double *v, int n)
{
    fprintf(f, " %s", word);
    for (int i = 0; i < n; i++)
        wr_num(f, v[i]);
}

static void wr_view(FILE *f, const struct sd_scene *s)
{
    const struct sd_view *v = &s->view;
    fprintf(f, "camera {");
    wr_vec(f, "eye", v->eye, 3);
    wr_vec(f, " look_at", v->look_at, 3);
    wr_vec(f, " up", v->up, 3);
    wr_vec(f, " fov", &v->fov, 1);
    fprintf(f, " }\nresolution %d %d\n", v->width, v->height);
    wr_vec(f, "background", v->background, 3);
    fprintf(f, "\noptions { max_depth %d  min_weight %.9g  density_steps %d  refractionless %s  "
               "refraction %s  shadows %s  bounds %s  hierarchy %s  mark_lost %s\n"
               "          ambient_shadowed %s  shadow_tint %s  check_lost %s  world_space %s",
            v->max_depth, v->min_weight, v->density_steps,
            v->flags & SCN_OPT_REFRACTIONLESS ? "on" : "off",
            v->flags & SCN_OPT_NO_REFRACTION ? "off" : "on",
            v->flags & SCN_OPT_NO_SHADOWS ? "off" : "on",
            v->flags & SCN_OPT_NO_BOUNDS ? "off" : "on",
            v->flags & SCN_OPT_NO_HIERARCHY ? "off" : "on",
            v->flags & SCN_OPT_MARK_LOST ? "on" : "off",
            v->flags & SCN_OPT_AMBIENT_SHADOWED ? "on" : "off",
            v->flags & SCN_OPT_UNTINTED_SHADOWS ? "off" : "on",
            v->flags & SCN_OPT_CHECK_LOST ? "on" : "off",
            v->flags & SCN_OPT_WORLD_SPACE ? "on" : "off");
    if (v->flags & SCN_OPT_ANTIALIAS)
        fprintf(f, "\n          aa %d  aa_threshold %.9g", v->aa_depth, v->aa_threshold);
    fprintf(f, " }\n");
    if (v->frames > 1)
        fprintf(f, "animation { frames %d }\n", v->frames);
    if (v->haze) {
        fprintf(f, "haze {");
        wr_vec(f, "colour", v->haze_colour, 3);
        wr_vec(f, " distance", &v->haze_distance, 1);
        fprintf(f, " }\n");
    }
    for (int i = 0; i < s->n_lights; i++) {
        const struct sd_light *l = &s->lights[i];
        fprintf(f, "light %s {", l->kind == SCN_LIGHT_PARALLEL ? "parallel"
                                 : l->kind == SCN_LIGHT_POINT  ? "point"
                                                               : "spot");
        wr_vec(f, "colour", l->colour, 3);
        if (l->kind != SCN_LIGHT_PARALLEL)
            wr_vec(f, " position", l->position, 3);
        if (l->kind != SCN_LIGHT_POINT)
            wr_vec(f, " direction", l->direction, 3);
        if (l->kind == SCN_LIGHT_SPOT) {
            wr_vec(f, " cone", &l->cone, 1);
            wr_vec(f, " falloff", &l->falloff, 1);
        }
        fprintf(f, " }\n");
    }
}

static void wr_maps(FILE *f, const struct sd_scene *s, const char *const *map_image)
{
    for (int i = 0; i < s->n_maps; i++) {
        const struct sd_map *m = &s->maps[i];
        int bump = m->kind == SCN_MAP_BUMP;
        fprintf(f, "map %s %s {", m->name, sd_map_kind_name(m->kind));
        if (map_image && map_image[i] && map_image[i][0]) {
            fprintf(f, " image \"%s\"", map_image[i]);
        } else {
            size_t n = (size_t)m->width * (size_t)m->height * sd_map_texel_bytes(m->kind);
            fprintf(f, " size %d %d  texels", m->width, m->height);
            for (size_t k = 0; k < n; k++)
                if (m->kind == SCN_MAP_NORMAL) /* signed bytes */
                    wr_num(f, (double)(int8_t)m->texels[k] / SCN_MAP_NORMAL_ONE);
                else
                    wr_num(f, m->texels[k] / 255.0);
        }
        wr_vec(f, " repeat", &m->repeat_u, 1);
        wr_num(f, m->repeat_v);
        if (bump)
            wr_vec(f, " depth", &m->bump_depth, 1);
        fprintf(f, " }\n");
    }
}

static void wr_materials(FILE *f, const struct sd_scene *s)
{
    for (int i = 0; i < s->n_materials; i++) {
        const struct sd_material *m = &s->materials[i];
        fprintf(f, "material %s {", m->name);
        wr_vec(f, "colour", m->colour, 3);
        wr_vec(f, " dic", &m->dic, 1);
        wr_vec(f, " drc", &m->drc, 1);
        wr_vec(f, " src", &m->src, 1);
        wr_vec(f, " trc", &m->trc, 1);
        wr_vec(f, " fresnel", &m->fresnel, 1);
        wr_vec(f, " ior", &m->ior, 1);
        fprintf(f, " phong %d", m->phong);
        if (m->colour_map >= 0)
            fprintf(f, " colour_map %s", s->maps[m->colour_map].name);
        if (m->bump_map >= 0)
            fprintf(f, " bump_map %s", s->maps[m->bump_map].name);
        const int attr[5] = {m->normal_map, m->dic_map, m->drc_map, m->src_map, m->trc_map};
        static const char *const attr_word[5] = {"normal_map", "dic_map", "drc_map", "src_map",
                                                 "trc_map"};
        for (int k = 0; k < 5; k++)
            if (attr[k] >= 0)
                fprintf(f, " %s %s", attr_word[k], s->maps[attr[k]].name);
        fprintf(f, " }\n");
    }
}

static void wr_prim(FILE *f, const struct sd_scene *s, const struct sd_prim *p, int depth)
{
    const double *v = p->v;
    fprintf(f, "%*s", 2 * depth, "");
    const char *mat = s->materials[p->material].name;
    switch (p->kind) {
    case SCN_PRIM_TRIANGLE:
        fprintf(f, "triangle { material %s", mat);
        for (int j = 0; j < 3; j++)
            wr_vec(f, " v", v + 3 * j, 3);
        for (int j = 0; j < 3; j++) {
            wr_vec(f, " uv", v + 9 + j, 1);
            wr_num(f, v[12 + j]);
        }
        for (int j = 0; p->smooth && j < 3; j++)
            wr_vec(f, " n", p->n + 3 * j, 3);
        break;
    case SCN_PRIM_ELLIPSOID:
        fprintf(f, "ellipsoid { material %s", mat);
        wr_vec(f, " centre", v, 3);
        wr_vec(f, " radii", v + 3, 3);
        break;
    case SCN_PRIM_BOX: {
        double lo[3], hi[3];
        for (int i = 0; i < 3; i++)
            lo[i] = v[i] - v[3 + i], hi[i] = v[i] + v[3 + i];
        fprintf(f, "box { material %s", mat);
        wr_vec(f, " min", lo, 3);
        wr_vec(f, " max", hi, 3);
        break;
    }
    case SCN_PRIM_CONE: /* a cylinder when its radii are the same */
        fprintf(f, "%s { material %s", v[3] == v[7] ? "cylinder" : "cone", mat);
        wr_vec(f, " base", v, 3);
        if (v[3] != v[7])
            wr_vec(f, " base_radius", v + 3, 1);
        wr_vec(f, " apex", v + 4, 3);
        wr_vec(f, v[3] == v[7] ? " radius" : " apex_radius", v + 7, 1);
        if (!p->capped)
            fprintf(f, " open");
        break;
    default:
        fprintf(f, "density { material %s", mat);
        wr_vec(f, " threshold", v, 1);
        for (int k = 0; k < p->count; k++) {
            const struct sd_component *c = &s->components[p->first + k];
            wr_vec(f, " component", c->centre, 3);
            wr_num(f, c->radius);
            wr_num(f, c->weight);
        }
        break;
    }
    fprintf(f, " }\n");
}

static int wr_identity(const double m[12])
{
    static const double id[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    return memcmp(m, id, sizeof id) == 0;
}

/* Cluster c's body: its transform, keys, primitives, then its children. */
static void wr_cluster(FILE *f, const struct sd_scene *s, int c, const int *first_prim,
                       const int *next_prim, const int *first_child, const int *next_child,
                       int depth)
{
    const struct sd_cluster *cl = &s->clusters[c];
    if (!wr_identity(cl->m)) {
        fprintf(f, "%*s", 2 * depth, "");
        wr_vec(f, "matrix", cl->m, 12);
        fprintf(f, "\n");
    }
    for (int k = 0; k < cl->key_count; k++) {
        const struct sd_key *key = &s->keys[cl->key_first + k];
        fprintf(f, "%*skey %d {", 2 * depth, "", key->frame);
        wr_vec(f, "translate", key->translate, 3);
        wr_vec(f, " rotate", key->rotate, 3);
        wr_vec(f, " scale", key->scale, 3);
        fprintf(f, " }\n");
    }
    for (int p = first_prim[c]; p >= 0; p = next_prim[p])
        wr_prim(f, s, &s->prims[p], depth);
    for (int ch = first_child[c]; ch >= 0; ch = next_child[ch]) {
        fprintf(f, "%*scluster %s {\n", 2 * depth, "", s->clusters[ch].name);
        wr_cluster(f, s, ch, first_prim, next_prim, first_child, next_child, depth + 1);
        fprintf(f, "%*s}\n", 2 * depth, "");
    }
}

int sd_write_text(const struct sd_scene *s, const char *const *map_image, FILE *f)
{
    return sd_write_text_titled(s, map_image, "written by links1 import (docs/import.md)", f);
}

int sd_write_text_titled(const struct sd_scene *s, const char *const *map_image,
                         const char *title, FILE *f)
{
    size_t nc = (size_t)s->n_clusters + 1, np = (size_t)s->n_prims + 1;
    int *first_prim = malloc(nc * sizeof(int)), *first_child = malloc(nc * sizeof(int));
    int *next_child = malloc(nc * sizeof(int)), *next_prim = malloc(np * sizeof(int));
    int rc = -1;
    if (first_prim && first_child && next_child && next_prim) {
        for (int c = 0; c < s->n_clusters; c++)
            first_prim[c] = first_child[c] = next_child[c] = -1;
        for (int p = s->n_prims - 1; p >= 0; p--) { /* lists in order */
            next_prim[p] = first_prim[s->prims[p].cluster];
            first_prim[s->prims[p].cluster] = p;
        }
        for (int c = s->n_clusters - 1; c >= 1; c--) {
            next_child[c] = first_child[s->clusters[c].parent];
            first_child[s->clusters[c].parent] = c;
        }
        fprintf(f, "# %s\n", title);
        wr_view(f, s);
        wr_maps(f, s, map_image);
        wr_materials(f, s);
        if (s->n_clusters > 0)
            wr_cluster(f, s, 0, first_prim, next_prim, first_child, next_child, 0);
        rc = ferror(f) ? -1 : 0;
    }
    free(first_prim), free(first_child);
    free(next_child), free(next_prim);
    return rc;
}
