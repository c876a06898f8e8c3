/* scene_parse_looks.c: the map and material statements of the text scene
 * format (docs/scene-format.md). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_import.h"
#include "host-tools/scene/scene_parse.h"

/* The map's image: below the scene's directory or --textures-from only
 * (sd_image_open_below). */
static void parse_map_image(struct parser *p, struct sd_map *m)
{
    if (p->lx.kind != LEX_STRING)
        lex_error(&p->lx, "expected a file name in quotes, found '%s'", p->lx.tok);
    char path[2048];
    char ierr[SD_ERR_MAX];
    int fd = sd_image_open_below(p->lx.tok, p->dir, p->textures_from, SD_IMAGE_OF_SCENE, path,
                                 sizeof path, ierr, sizeof ierr);
    if (fd < 0 || sd_map_read_image_fd(m, fd, path, ierr, sizeof ierr) != 0)
        lex_error(&p->lx, "map image: %s", ierr);
}

static void parse_map_texels(struct parser *p, struct sd_map *m, int bpt)
{
    if (m->width == 0)
        lex_error(&p->lx, "give 'size W H' before 'texels'");
    size_t n = (size_t)m->width * (size_t)m->height * (size_t)bpt;
    free(m->texels);
    m->texels = malloc(n);
    if (!m->texels)
        lex_error(&p->lx, "out of memory reading texels");
    int normal = m->kind == SCN_MAP_NORMAL;
    double v[3];
    for (size_t i = 0; i < n; i++) {
        if (p->lx.kind != LEX_NUMBER)
            lex_error(&p->lx, "map has %zu texel values, %zu needed (width*height*%d)", i, n,
                      bpt);
        if (!normal) {
            m->texels[i] = (uint8_t)lround(lex_number_in(&p->lx, "texel value", 0, 1) * 255.0);
            continue;
        }
        /* a normal map's texel: x y z in the tangent frame, normalized here
         * (an error names the z it reads) */
        if (p->lx.num < -1 || p->lx.num > 1)
            lex_error(&p->lx, "normal map texel component must be -1..1, not %s", p->lx.tok);
        v[i % 3] = p->lx.num;
        if (i % 3 == 2 && sd_map_normal_texel(v, m->texels + i - 2) != 0)
            lex_error(&p->lx, "normal map texel %zu (%g %g %g) does not point out of the "
                              "surface (z must be > 0)",
                      i / 3, v[0], v[1], v[2]);
        lex_next(&p->lx);
    }
    if (p->lx.kind == LEX_NUMBER)
        lex_error(&p->lx, "more texel values than width*height*%d = %zu", bpt, n);
}

void parse_map(struct parser *p)
{
    struct sd_scene *s = p->s;
    if (s->n_maps >= SCN_MAX_MAPS)
        lex_error(&p->lx, "more than %d maps", SCN_MAX_MAPS);
    lex_next(&p->lx);
    struct sd_map *m = &s->maps[s->n_maps];
    memset(m, 0, sizeof *m);
    if (p->lx.kind == LEX_WORD && parse_find_map(s, p->lx.tok) >= 0)
        lex_error(&p->lx, "a second map named '%s'", p->lx.tok);
    lex_word(&p->lx, "a map name", m->name, sizeof m->name);
    s->n_maps++; /* counted now so sd_free releases its texels on error */
    if (lex_is_word(&p->lx, "colour") || lex_is_word(&p->lx, "color"))
        m->kind = SCN_MAP_COLOUR;
    else if (lex_is_word(&p->lx, "bump"))
        m->kind = SCN_MAP_BUMP;
    else if (lex_is_word(&p->lx, "normal"))
        m->kind = SCN_MAP_NORMAL;
    else if (lex_is_word(&p->lx, "attribute"))
        m->kind = SCN_MAP_ATTRIBUTE;
    else
        lex_error(&p->lx, "map kind must be colour, bump, normal or attribute, not '%s'",
                  p->lx.tok);
    int bpt = (int)sd_map_texel_bytes(m->kind);
    lex_next(&p->lx);
    m->repeat_u = m->repeat_v = 1;
    m->bump_depth = m->kind == SCN_MAP_BUMP ? 1 : 0;
    parse_open(p, "map");
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "size")) {
            lex_next(&p->lx);
            if (m->texels)
                lex_error(&p->lx, "size after the texels");
            m->width = lex_int(&p->lx, "map width", 1, SCN_MAX_MAP_SIDE);
            m->height = lex_int(&p->lx, "map height", 1, SCN_MAX_MAP_SIDE);
        } else if (lex_is_word(&p->lx, "texels")) {
            lex_next(&p->lx);
            parse_map_texels(p, m, bpt);
        } else if (lex_is_word(&p->lx, "image")) {
            lex_next(&p->lx);
            parse_map_image(p, m);
            lex_next(&p->lx);
        } else if (lex_is_word(&p->lx, "repeat")) {
            lex_next(&p->lx);
            m->repeat_u = lex_number_in(&p->lx, "repeat u", 1e-3, SCN_MAX_REPEAT);
            m->repeat_v = lex_number_in(&p->lx, "repeat v", 1e-3, SCN_MAX_REPEAT);
        } else if (lex_is_word(&p->lx, "depth") && m->kind == SCN_MAP_BUMP) {
            lex_next(&p->lx);
            m->bump_depth = lex_number_in(&p->lx, "bump depth", 0, SCN_MAX_FACTOR);
        } else {
            char what[32];
            snprintf(what, sizeof what, "%s map", sd_map_kind_name(m->kind));
            parse_unknown(p, what);
        }
    }
    if (!m->texels)
        lex_error(&p->lx, "map '%s' has no texels (give 'texels' or 'image')", m->name);
    lex_next(&p->lx);
}

/* A material's map statement (colour_map, bump_map, normal_map, dic_map,
 * drc_map, src_map, trc_map NAME) at the current word: 1 when it was one,
 * read; 0 when the word is something else. */
static int parse_material_map(struct parser *p, struct sd_material *m)
{
    static const struct {
        const char *word;
        int kind;
    } maps[] = {
        {"colour_map", SCN_MAP_COLOUR},  {"color_map", SCN_MAP_COLOUR},
        {"bump_map", SCN_MAP_BUMP},      {"normal_map", SCN_MAP_NORMAL},
        {"dic_map", SCN_MAP_ATTRIBUTE},  {"drc_map", SCN_MAP_ATTRIBUTE},
        {"src_map", SCN_MAP_ATTRIBUTE},  {"trc_map", SCN_MAP_ATTRIBUTE},
    };
    int *slot[] = {&m->colour_map, &m->colour_map, &m->bump_map, &m->normal_map,
                   &m->dic_map,    &m->drc_map,    &m->src_map,  &m->trc_map};
    int k = 0;
    while (k < (int)(sizeof maps / sizeof maps[0]) && !lex_is_word(&p->lx, maps[k].word))
        k++;
    if (k == (int)(sizeof maps / sizeof maps[0]))
        return 0;
    lex_next(&p->lx);
    struct sd_scene *s = p->s;
    int i = p->lx.kind == LEX_WORD ? parse_find_map(s, p->lx.tok) : -1;
    if (i < 0)
        lex_error(&p->lx, "no map named '%s' (define it before use)", p->lx.tok);
    if (s->maps[i].kind != maps[k].kind)
        lex_error(&p->lx, "%s: map '%s' is a%s %s map, not a%s %s map", maps[k].word, p->lx.tok,
                  s->maps[i].kind == SCN_MAP_ATTRIBUTE ? "n" : "", sd_map_kind_name(s->maps[i].kind),
                  maps[k].kind == SCN_MAP_ATTRIBUTE ? "n" : "", sd_map_kind_name(maps[k].kind));
    *slot[k] = i;
    if (m->bump_map >= 0 && m->normal_map >= 0)
        lex_error(&p->lx, "material '%s' has both a bump map and a normal map (give one)",
                  m->name);
    lex_next(&p->lx);
    return 1;
}

void parse_material(struct parser *p)
{
    struct sd_scene *s = p->s;
    lex_next(&p->lx);
    s->materials = parse_grow(p, s->materials, &p->cap_materials, s->n_materials,
                              sizeof *s->materials, SCN_MAX_MATERIALS, "materials");
    struct sd_material m;
    memset(&m, 0, sizeof m);
    if (p->lx.kind == LEX_WORD && parse_find_material(s, p->lx.tok) >= 0)
        lex_error(&p->lx, "a second material named '%s'", p->lx.tok);
    lex_word(&p->lx, "a material name", m.name, sizeof m.name);
    m.colour[0] = m.colour[1] = m.colour[2] = 1;
    m.dic = 0.1;
    m.drc = 0.9;
    m.ior = 1;
    m.fresnel = PARSE_FRESNEL_UNSET;
    sd_material_no_maps(&m);
    parse_open(p, "material");
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "colour") || lex_is_word(&p->lx, "color")) {
            lex_next(&p->lx);
            parse_unit3(p, "colour", m.colour);
        } else if (lex_is_word(&p->lx, "dic")) {
            lex_next(&p->lx);
            m.dic = lex_number_in(&p->lx, "dic", 0, 1);
        } else if (lex_is_word(&p->lx, "drc")) {
            lex_next(&p->lx);
            m.drc = lex_number_in(&p->lx, "drc", 0, 1);
        } else if (lex_is_word(&p->lx, "src")) {
            lex_next(&p->lx);
            m.src = lex_number_in(&p->lx, "src", 0, 1);
        } else if (lex_is_word(&p->lx, "trc")) {
            lex_next(&p->lx);
            m.trc = lex_number_in(&p->lx, "trc", 0, 1);
        } else if (lex_is_word(&p->lx, "fresnel")) {
            lex_next(&p->lx);
            m.fresnel = lex_number_in(&p->lx, "fresnel", 0, 1);
        } else if (lex_is_word(&p->lx, "constant")) {
            lex_next(&p->lx);
            m.fresnel = 0;
        } else if (lex_is_word(&p->lx, "phong")) {
            lex_next(&p->lx);
            m.phong = lex_int(&p->lx, "phong", 0, SCN_MAX_PHONG);
        } else if (lex_is_word(&p->lx, "ior")) {
            lex_next(&p->lx);
            m.ior = lex_number_in(&p->lx, "ior", 1, SCN_MAX_IOR);
        } else if (parse_material_map(p, &m)) {
            continue;
        } else {
            parse_unknown(p, "material");
        }
    }
    if (m.src + m.trc > 1 + 1e-9)
        lex_error(&p->lx, "material '%s': src + trc = %g is more than 1", m.name,
                  m.src + m.trc);
    s->materials[s->n_materials++] = m;
    lex_next(&p->lx);
}
