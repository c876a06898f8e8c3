/* scene_parse.c: the text scene format (docs/scene-format.md) into a
 * struct sd_scene.  Every statement is checked as it is read, so the error
 * names the line and column of the offending token; on error the partly
 * built scene is freed and the caller gets an empty one.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/image_io.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_lex.h"

#define PARSE_MAX_FILE (64u * 1024u * 1024u) /* text scenes larger are refused */
#define PARSE_DEFAULT_WIDTH 320
#define PARSE_DEFAULT_HEIGHT 240
#define PARSE_DEFAULT_FOV 45.0
#define PARSE_DEFAULT_DEPTH 5
#define PARSE_DEFAULT_FALLOFF 5.0 /* degrees of a spotlight's soft edge */
#define PARSE_MIN_TRIANGLE_AREA 1e-12

struct parser {
    struct lex lx;
    struct sd_scene *s;
    char dir[1024];         /* directory of the scene file, for map images */
    int cap_materials, cap_clusters, cap_prims, cap_components, cap_keys;
    int seen_camera, seen_resolution, seen_options, seen_animation;
};

/* ------------------------------------------------------------- helpers */

static void *parse_grow(struct parser *p, void *arr, int *cap, int n, size_t elem,
                        int limit, const char *what)
{
    if (n >= limit)
        lex_error(&p->lx, "too many %s (the limit is %d)", what, limit);
    if (n < *cap)
        return arr;
    int ncap = *cap ? *cap * 2 : 16;
    void *na = realloc(arr, (size_t)ncap * elem);
    if (!na)
        lex_error(&p->lx, "out of memory reading %s", what);
    *cap = ncap;
    return na;
}

static void parse_coord3(struct parser *p, const char *what, double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = lex_number_in(&p->lx, what, -SCN_MAX_COORD, SCN_MAX_COORD);
}

static void parse_unit3(struct parser *p, const char *what, double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = lex_number_in(&p->lx, what, 0, 1);
}

static int parse_on_off(struct parser *p, const char *what)
{
    int v;
    if (lex_is_word(&p->lx, "on"))
        v = 1;
    else if (lex_is_word(&p->lx, "off"))
        v = 0;
    else
        lex_error(&p->lx, "%s takes 'on' or 'off', not '%s'", what, p->lx.tok);
    lex_next(&p->lx);
    return v;
}

static void parse_open(struct parser *p, const char *stmt)
{
    if (p->lx.kind != LEX_OPEN)
        lex_error(&p->lx, "expected '{' after %s, found '%s'", stmt, p->lx.tok);
    lex_next(&p->lx);
}

static void parse_unknown(struct parser *p, const char *block)
{
    lex_error(&p->lx, "unknown %s property '%s'", block, p->lx.tok);
}

static int parse_len3_zero(const double v[3]) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

static int parse_find_material(const struct sd_scene *s, const char *name)
{
    for (int i = 0; i < s->n_materials; i++)
        if (strcmp(s->materials[i].name, name) == 0)
            return i;
    return -1;
}

static int parse_find_map(const struct sd_scene *s, const char *name)
{
    for (int i = 0; i < s->n_maps; i++)
        if (strcmp(s->maps[i].name, name) == 0)
            return i;
    return -1;
}

static int parse_material_ref(struct parser *p)
{
    if (p->lx.kind != LEX_WORD)
        lex_error(&p->lx, "expected a material name, found '%s'", p->lx.tok);
    int m = parse_find_material(p->s, p->lx.tok);
    if (m < 0)
        lex_error(&p->lx, "no material named '%s' (define it before use)", p->lx.tok);
    lex_next(&p->lx);
    return m;
}

/* -------------------------------------------------------- global blocks */

static void parse_camera(struct parser *p)
{
    struct sd_view *v = &p->s->view;
    if (p->seen_camera++)
        lex_error(&p->lx, "a second camera (a scene has one)");
    lex_next(&p->lx);
    parse_open(p, "camera");
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "eye")) {
            lex_next(&p->lx);
            parse_coord3(p, "eye", v->eye);
        } else if (lex_is_word(&p->lx, "look_at")) {
            lex_next(&p->lx);
            parse_coord3(p, "look_at", v->look_at);
        } else if (lex_is_word(&p->lx, "up")) {
            lex_next(&p->lx);
            parse_coord3(p, "up", v->up);
        } else if (lex_is_word(&p->lx, "fov")) {
            lex_next(&p->lx);
            v->fov = lex_number_in(&p->lx, "fov (degrees)", SCN_MIN_FOV, SCN_MAX_FOV);
        } else {
            parse_unknown(p, "camera");
        }
    }
    int close_line = p->lx.tok_line;
    double d[3], c[3];
    for (int i = 0; i < 3; i++)
        d[i] = v->look_at[i] - v->eye[i];
    c[0] = d[1] * v->up[2] - d[2] * v->up[1];
    c[1] = d[2] * v->up[0] - d[0] * v->up[2];
    c[2] = d[0] * v->up[1] - d[1] * v->up[0];
    if (parse_len3_zero(d))
        lex_error(&p->lx, "camera ending on line %d: eye and look_at are the same point",
                  close_line);
    if (sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) <=
        1e-9 * sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) *
            sqrt(v->up[0] * v->up[0] + v->up[1] * v->up[1] + v->up[2] * v->up[2]))
        lex_error(&p->lx, "camera: up is parallel to the viewing direction (or zero)");
    lex_next(&p->lx);
}

static void parse_options(struct parser *p)
{
    struct sd_view *v = &p->s->view;
    if (p->seen_options++)
        lex_error(&p->lx, "a second options block");
    lex_next(&p->lx);
    parse_open(p, "options");
    while (p->lx.kind != LEX_CLOSE) {
        unsigned bit = 0;
        int inverted = 0;
        if (lex_is_word(&p->lx, "max_depth")) {
            lex_next(&p->lx);
            v->max_depth = lex_int(&p->lx, "max_depth", 0, SCN_MAX_DEPTH);
            continue;
        } else if (lex_is_word(&p->lx, "refractionless")) {
            bit = SCN_OPT_REFRACTIONLESS;
        } else if (lex_is_word(&p->lx, "bounds")) {
            bit = SCN_OPT_NO_BOUNDS, inverted = 1;
        } else if (lex_is_word(&p->lx, "hierarchy")) {
            bit = SCN_OPT_NO_HIERARCHY, inverted = 1;
        } else if (lex_is_word(&p->lx, "shadows")) {
            bit = SCN_OPT_NO_SHADOWS, inverted = 1;
        } else {
            parse_unknown(p, "options");
        }
        char name[LEX_TOKEN_MAX];
        strcpy(name, p->lx.tok);
        lex_next(&p->lx);
        int on = parse_on_off(p, name);
        if (on != inverted)
            v->flags |= bit;
        else
            v->flags &= ~bit;
    }
    lex_next(&p->lx);
}

static void parse_animation(struct parser *p)
{
    if (p->seen_animation++)
        lex_error(&p->lx, "a second animation block");
    lex_next(&p->lx);
    parse_open(p, "animation");
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "frames")) {
            lex_next(&p->lx);
            p->s->view.frames = lex_int(&p->lx, "frames", 1, SCN_MAX_FRAMES);
        } else {
            parse_unknown(p, "animation");
        }
    }
    lex_next(&p->lx);
}

static void parse_light(struct parser *p)
{
    struct sd_scene *s = p->s;
    if (s->n_lights >= SCN_MAX_LIGHTS)
        lex_error(&p->lx, "more than %d lights", SCN_MAX_LIGHTS);
    lex_next(&p->lx);
    struct sd_light l;
    memset(&l, 0, sizeof l);
    l.colour[0] = l.colour[1] = l.colour[2] = 1;
    l.falloff = PARSE_DEFAULT_FALLOFF;
    if (lex_is_word(&p->lx, "parallel"))
        l.kind = SCN_LIGHT_PARALLEL;
    else if (lex_is_word(&p->lx, "point"))
        l.kind = SCN_LIGHT_POINT;
    else if (lex_is_word(&p->lx, "spot"))
        l.kind = SCN_LIGHT_SPOT;
    else
        lex_error(&p->lx, "light kind must be parallel, point or spot, not '%s'", p->lx.tok);
    lex_next(&p->lx);
    parse_open(p, "light");
    int have_pos = 0, have_dir = 0, have_at = 0, have_cone = 0;
    double at[3] = {0, 0, 0};
    while (p->lx.kind != LEX_CLOSE) {
        int k = l.kind;
        if (lex_is_word(&p->lx, "colour") || lex_is_word(&p->lx, "color")) {
            lex_next(&p->lx);
            for (int i = 0; i < 3; i++)
                l.colour[i] = lex_number_in(&p->lx, "light colour", 0, SCN_MAX_INTENSITY);
        } else if (lex_is_word(&p->lx, "position") && k != SCN_LIGHT_PARALLEL) {
            lex_next(&p->lx);
            parse_coord3(p, "position", l.position);
            have_pos = 1;
        } else if (lex_is_word(&p->lx, "direction") && k != SCN_LIGHT_POINT) {
            lex_next(&p->lx);
            parse_coord3(p, "direction", l.direction);
            if (parse_len3_zero(l.direction))
                lex_error(&p->lx, "light direction is zero");
            have_dir = 1;
        } else if (lex_is_word(&p->lx, "at") && k == SCN_LIGHT_SPOT) {
            lex_next(&p->lx);
            parse_coord3(p, "at", at);
            have_at = 1;
        } else if (lex_is_word(&p->lx, "cone") && k == SCN_LIGHT_SPOT) {
            lex_next(&p->lx);
            l.cone = lex_number_in(&p->lx, "cone (degrees)", 0, SCN_MAX_SPOT_ANGLE);
            have_cone = 1;
        } else if (lex_is_word(&p->lx, "falloff") && k == SCN_LIGHT_SPOT) {
            lex_next(&p->lx);
            l.falloff = lex_number_in(&p->lx, "falloff (degrees)", 0.01, SCN_MAX_SPOT_ANGLE);
        } else {
            lex_error(&p->lx, "'%s' is not a property of a %s light", p->lx.tok,
                      k == SCN_LIGHT_PARALLEL ? "parallel"
                      : k == SCN_LIGHT_POINT  ? "point"
                                              : "spot");
        }
    }
    if (l.kind != SCN_LIGHT_PARALLEL && !have_pos)
        lex_error(&p->lx, "this light needs a position");
    if (l.kind == SCN_LIGHT_SPOT && have_at) {
        for (int i = 0; i < 3; i++)
            l.direction[i] = at[i] - l.position[i];
        if (parse_len3_zero(l.direction))
            lex_error(&p->lx, "spotlight 'at' is its own position");
        have_dir = 1;
    }
    if (l.kind != SCN_LIGHT_POINT && !have_dir)
        lex_error(&p->lx, "this light needs a direction%s",
                  l.kind == SCN_LIGHT_SPOT ? " (or 'at')" : "");
    if (l.kind == SCN_LIGHT_SPOT && !have_cone)
        lex_error(&p->lx, "a spotlight needs a cone angle");
    if (l.cone + l.falloff > SCN_MAX_SPOT_ANGLE)
        lex_error(&p->lx, "cone + falloff is %g degrees, more than %g", l.cone + l.falloff,
                  SCN_MAX_SPOT_ANGLE);
    s->lights[s->n_lights++] = l;
    lex_next(&p->lx);
}

static void parse_map_image(struct parser *p, struct sd_map *m)
{
    if (p->lx.kind != LEX_STRING)
        lex_error(&p->lx, "expected a file name in quotes, found '%s'", p->lx.tok);
    char path[2048];
    if (p->lx.tok[0] == '/')
        snprintf(path, sizeof path, "%s", p->lx.tok);
    else
        snprintf(path, sizeof path, "%s%s", p->dir, p->lx.tok);
    struct image img;
    char ierr[SD_ERR_MAX];
    if (image_read(path, &img, ierr, sizeof ierr) != 0)
        lex_error(&p->lx, "map image: %s", ierr);
    if (img.width > SCN_MAX_MAP_SIDE || img.height > SCN_MAX_MAP_SIDE) {
        image_free(&img);
        lex_error(&p->lx, "map image %s is %dx%d, more than %d texels a side", path,
                  img.width, img.height, SCN_MAX_MAP_SIDE);
    }
    size_t n = (size_t)img.width * (size_t)img.height;
    free(m->texels);
    m->width = img.width;
    m->height = img.height;
    if (m->kind == SCN_MAP_COLOUR) {
        m->texels = img.rgb; /* same layout: 3 bytes per texel, top row = v 0 */
        return;
    }
    /* A bump map's height is the image's luminance (Rec. 601 weights). */
    m->texels = malloc(n);
    if (!m->texels) {
        image_free(&img);
        lex_error(&p->lx, "out of memory reading %s", path);
    }
    for (size_t i = 0; i < n; i++) {
        const uint8_t *px = img.rgb + 3 * i;
        m->texels[i] = (uint8_t)((299u * px[0] + 587u * px[1] + 114u * px[2] + 500u) / 1000u);
    }
    image_free(&img);
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
    for (size_t i = 0; i < n; i++) {
        if (p->lx.kind != LEX_NUMBER)
            lex_error(&p->lx, "map has %zu texel values, %zu needed (width*height*%d)", i, n,
                      bpt);
        double v = lex_number_in(&p->lx, "texel value", 0, 1);
        m->texels[i] = (uint8_t)lround(v * 255.0);
    }
    if (p->lx.kind == LEX_NUMBER)
        lex_error(&p->lx, "more texel values than width*height*%d = %zu", bpt, n);
}

static void parse_map(struct parser *p)
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
    else
        lex_error(&p->lx, "map kind must be colour or bump, not '%s'", p->lx.tok);
    int bpt = m->kind == SCN_MAP_COLOUR ? SCN_MAP_COLOUR_BYTES : SCN_MAP_BUMP_BYTES;
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
            m->bump_depth = lex_number_in(&p->lx, "bump depth", 0, SCN_MAX_COORD);
        } else {
            parse_unknown(p, m->kind == SCN_MAP_BUMP ? "bump map" : "colour map");
        }
    }
    if (!m->texels)
        lex_error(&p->lx, "map '%s' has no texels (give 'texels' or 'image')", m->name);
    lex_next(&p->lx);
}

static void parse_material(struct parser *p)
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
    m.colour_map = m.bump_map = -1;
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
        } else if (lex_is_word(&p->lx, "colour_map") || lex_is_word(&p->lx, "color_map") ||
                   lex_is_word(&p->lx, "bump_map")) {
            int bump = lex_is_word(&p->lx, "bump_map");
            lex_next(&p->lx);
            int i = p->lx.kind == LEX_WORD ? parse_find_map(s, p->lx.tok) : -1;
            if (i < 0)
                lex_error(&p->lx, "no map named '%s' (define it before use)", p->lx.tok);
            if (s->maps[i].kind != (bump ? SCN_MAP_BUMP : SCN_MAP_COLOUR))
                lex_error(&p->lx, "map '%s' is not a %s map", p->lx.tok,
                          bump ? "bump" : "colour");
            *(bump ? &m.bump_map : &m.colour_map) = i;
            lex_next(&p->lx);
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

/* ----------------------------------------------------------- transforms */

static void parse_apply(double m[12], const double t[12])
{
    double r[12];
    sd_mat_mul(t, m, r);
    memcpy(m, r, sizeof r);
}

/* translate / rotate / scale / matrix statements, applied in order. */
static int parse_transform(struct parser *p, double m[12])
{
    double t[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    if (lex_is_word(&p->lx, "translate")) {
        lex_next(&p->lx);
        double v[3];
        parse_coord3(p, "translate", v);
        t[3] = v[0], t[7] = v[1], t[11] = v[2];
    } else if (lex_is_word(&p->lx, "rotate")) {
        lex_next(&p->lx);
        double deg[3], q[4];
        for (int i = 0; i < 3; i++)
            deg[i] = lex_number_in(&p->lx, "rotate (degrees)", -3600, 3600);
        sd_euler_quat(deg, q);
        sd_quat_matrix(q, t);
    } else if (lex_is_word(&p->lx, "scale")) {
        lex_next(&p->lx);
        double v[3];
        v[0] = lex_number_in(&p->lx, "scale", -SCN_MAX_COORD, SCN_MAX_COORD);
        if (p->lx.kind == LEX_NUMBER) {
            v[1] = lex_number_in(&p->lx, "scale", -SCN_MAX_COORD, SCN_MAX_COORD);
            v[2] = lex_number_in(&p->lx, "scale", -SCN_MAX_COORD, SCN_MAX_COORD);
        } else {
            v[1] = v[2] = v[0];
        }
        if (v[0] == 0 || v[1] == 0 || v[2] == 0)
            lex_error(&p->lx, "a scale factor is zero");
        t[0] = v[0], t[5] = v[1], t[10] = v[2];
    } else if (lex_is_word(&p->lx, "matrix")) {
        lex_next(&p->lx);
        for (int i = 0; i < 12; i++)
            t[i] = lex_number_in(&p->lx, "matrix entry", -SCN_MAX_COORD, SCN_MAX_COORD);
        double det = t[0] * (t[5] * t[10] - t[6] * t[9]) - t[1] * (t[4] * t[10] - t[6] * t[8]) +
                     t[2] * (t[4] * t[9] - t[5] * t[8]);
        if (fabs(det) < 1e-12)
            lex_error(&p->lx, "matrix is not invertible (determinant %g)", det);
    } else {
        return 0;
    }
    parse_apply(m, t);
    for (int i = 0; i < 12; i++)
        if (fabs(m[i]) > SCN_MAX_COORD)
            lex_error(&p->lx, "the combined transform has an entry beyond %g",
                      (double)SCN_MAX_COORD);
    return 1;
}

static void parse_key(struct parser *p, int c)
{
    struct sd_scene *s = p->s;
    struct sd_cluster *cl = &s->clusters[c];
    lex_next(&p->lx);
    struct sd_key k;
    memset(&k, 0, sizeof k);
    k.scale[0] = k.scale[1] = k.scale[2] = 1;
    if (cl->key_count > 0 && p->lx.kind == LEX_NUMBER &&
        p->lx.num <= s->keys[s->n_keys - 1].frame)
        lex_error(&p->lx, "key frames of a cluster must rise (frame %s after %d)", p->lx.tok,
                  s->keys[s->n_keys - 1].frame);
    k.frame = lex_int(&p->lx, "key frame", 0, SCN_MAX_FRAMES - 1);
    if (cl->key_count > 0 && cl->key_first + cl->key_count != s->n_keys)
        lex_error(&p->lx, "keys of a cluster must come before its child clusters");
    if (cl->key_count >= SCN_MAX_CLUSTER_KEYS)
        lex_error(&p->lx, "more than %d keys in one cluster", SCN_MAX_CLUSTER_KEYS);
    parse_open(p, "key");
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "translate")) {
            lex_next(&p->lx);
            parse_coord3(p, "translate", k.translate);
        } else if (lex_is_word(&p->lx, "rotate")) {
            lex_next(&p->lx);
            for (int i = 0; i < 3; i++)
                k.rotate[i] = lex_number_in(&p->lx, "rotate (degrees)", -3600, 3600);
        } else if (lex_is_word(&p->lx, "scale")) {
            lex_next(&p->lx);
            k.scale[0] = lex_number_in(&p->lx, "scale", -SCN_MAX_COORD, SCN_MAX_COORD);
            if (p->lx.kind == LEX_NUMBER) {
                k.scale[1] = lex_number_in(&p->lx, "scale", -SCN_MAX_COORD, SCN_MAX_COORD);
                k.scale[2] = lex_number_in(&p->lx, "scale", -SCN_MAX_COORD, SCN_MAX_COORD);
            } else {
                k.scale[1] = k.scale[2] = k.scale[0];
            }
            if (k.scale[0] == 0 || k.scale[1] == 0 || k.scale[2] == 0)
                lex_error(&p->lx, "a scale factor is zero");
        } else {
            parse_unknown(p, "key");
        }
    }
    s->keys = parse_grow(p, s->keys, &p->cap_keys, s->n_keys, sizeof *s->keys, SCN_MAX_KEYS,
                         "keys");
    cl = &s->clusters[c];
    if (cl->key_count == 0)
        cl->key_first = s->n_keys;
    s->keys[s->n_keys++] = k;
    cl->key_count++;
    lex_next(&p->lx);
}

/* ----------------------------------------------------------- primitives */

/* The 'material NAME' every primitive block may hold. */
static int parse_prim_material(struct parser *p, struct sd_prim *pr)
{
    if (lex_is_word(&p->lx, "material")) {
        lex_next(&p->lx);
        pr->material = parse_material_ref(p);
        return 1;
    }
    return 0;
}

static void parse_triangle(struct parser *p, struct sd_prim *pr)
{
    int nv = 0, nuv = 0;
    double *v = pr->v;
    /* default map coordinates: (0,0), (1,0), (0,1) */
    v[10] = 1;
    v[14] = 1;
    while (p->lx.kind != LEX_CLOSE) {
        if (parse_prim_material(p, pr))
            continue;
        if (lex_is_word(&p->lx, "v")) {
            if (nv == 3)
                lex_error(&p->lx, "a triangle has three vertices");
            lex_next(&p->lx);
            parse_coord3(p, "vertex", v + 3 * nv++);
        } else if (lex_is_word(&p->lx, "uv")) {
            if (nuv == 3)
                lex_error(&p->lx, "a triangle has three uv pairs");
            lex_next(&p->lx);
            v[9 + nuv] = lex_number_in(&p->lx, "u", -SCN_MAX_COORD, SCN_MAX_COORD);
            v[12 + nuv] = lex_number_in(&p->lx, "v", -SCN_MAX_COORD, SCN_MAX_COORD);
            nuv++;
        } else {
            parse_unknown(p, "triangle");
        }
    }
    if (nv != 3)
        lex_error(&p->lx, "triangle has %d vertices, needs 3", nv);
    if (nuv != 0 && nuv != 3)
        lex_error(&p->lx, "triangle has %d uv pairs, needs 0 or 3", nuv);
    double e1[3], e2[3], c[3];
    for (int i = 0; i < 3; i++)
        e1[i] = v[3 + i] - v[i], e2[i] = v[6 + i] - v[i];
    c[0] = e1[1] * e2[2] - e1[2] * e2[1];
    c[1] = e1[2] * e2[0] - e1[0] * e2[2];
    c[2] = e1[0] * e2[1] - e1[1] * e2[0];
    if (sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) < PARSE_MIN_TRIANGLE_AREA)
        lex_error(&p->lx, "degenerate triangle (its vertices are on one line)");
}

static void parse_ellipsoid(struct parser *p, struct sd_prim *pr, int sphere)
{
    int have_r = 0;
    while (p->lx.kind != LEX_CLOSE) {
        if (parse_prim_material(p, pr))
            continue;
        if (lex_is_word(&p->lx, "centre") || lex_is_word(&p->lx, "center")) {
            lex_next(&p->lx);
            parse_coord3(p, "centre", pr->v);
        } else if (sphere && lex_is_word(&p->lx, "radius")) {
            lex_next(&p->lx);
            pr->v[3] = pr->v[4] = pr->v[5] =
                lex_number_in(&p->lx, "radius", 1e-6, SCN_MAX_COORD);
            have_r = 1;
        } else if (!sphere && lex_is_word(&p->lx, "radii")) {
            lex_next(&p->lx);
            for (int i = 0; i < 3; i++)
                pr->v[3 + i] = lex_number_in(&p->lx, "radius", 1e-6, SCN_MAX_COORD);
            have_r = 1;
        } else {
            parse_unknown(p, sphere ? "sphere" : "ellipsoid");
        }
    }
    if (!have_r)
        lex_error(&p->lx, "%s needs %s", sphere ? "sphere" : "ellipsoid",
                  sphere ? "a radius" : "radii");
}

static void parse_box(struct parser *p, struct sd_prim *pr)
{
    double lo[3], hi[3];
    int have = 0;
    while (p->lx.kind != LEX_CLOSE) {
        if (parse_prim_material(p, pr))
            continue;
        if (lex_is_word(&p->lx, "min")) {
            lex_next(&p->lx);
            parse_coord3(p, "min", lo);
            have |= 1;
        } else if (lex_is_word(&p->lx, "max")) {
            lex_next(&p->lx);
            parse_coord3(p, "max", hi);
            have |= 2;
        } else {
            parse_unknown(p, "box");
        }
    }
    if (have != 3)
        lex_error(&p->lx, "box needs min and max corners");
    for (int i = 0; i < 3; i++) {
        if (!(hi[i] > lo[i]))
            lex_error(&p->lx, "box max must exceed min on every axis (axis %c)", "xyz"[i]);
        pr->v[i] = (lo[i] + hi[i]) / 2;
        pr->v[3 + i] = (hi[i] - lo[i]) / 2;
    }
}

static void parse_density(struct parser *p, struct sd_prim *pr)
{
    struct sd_scene *s = p->s;
    int have_t = 0;
    pr->first = s->n_components;
    while (p->lx.kind != LEX_CLOSE) {
        if (parse_prim_material(p, pr))
            continue;
        if (lex_is_word(&p->lx, "threshold")) {
            lex_next(&p->lx);
            pr->v[0] = lex_number_in(&p->lx, "threshold", 1e-6, SCN_MAX_COORD);
            have_t = 1;
        } else if (lex_is_word(&p->lx, "component")) {
            lex_next(&p->lx);
            if (pr->count >= SCN_MAX_DENSITY_COMPONENTS)
                lex_error(&p->lx, "more than %d components", SCN_MAX_DENSITY_COMPONENTS);
            struct sd_component c;
            parse_coord3(p, "component centre", c.centre);
            c.radius = lex_number_in(&p->lx, "component radius", 1e-6, SCN_MAX_COORD);
            if (p->lx.kind == LEX_NUMBER && p->lx.num == 0)
                lex_error(&p->lx, "component weight is zero");
            c.weight = lex_number_in(&p->lx, "component weight", -SCN_MAX_COORD, SCN_MAX_COORD);
            s->components = parse_grow(p, s->components, &p->cap_components, s->n_components,
                                       sizeof *s->components, SCN_MAX_COMPONENTS,
                                       "density components");
            s->components[s->n_components++] = c;
            pr->count++;
        } else {
            parse_unknown(p, "density");
        }
    }
    if (!have_t)
        lex_error(&p->lx, "density needs a threshold");
    if (pr->count == 0)
        lex_error(&p->lx, "density needs at least one component");
}

static void parse_prim(struct parser *p, int cluster, int material)
{
    struct sd_scene *s = p->s;
    struct sd_prim pr;
    memset(&pr, 0, sizeof pr);
    pr.cluster = cluster;
    pr.material = material;
    char kind[LEX_TOKEN_MAX];
    strcpy(kind, p->lx.tok);
    int line = p->lx.tok_line, col = p->lx.tok_col;
    lex_next(&p->lx);
    parse_open(p, kind);
    if (strcmp(kind, "triangle") == 0) {
        pr.kind = SCN_PRIM_TRIANGLE;
        parse_triangle(p, &pr);
    } else if (strcmp(kind, "ellipsoid") == 0 || strcmp(kind, "sphere") == 0) {
        pr.kind = SCN_PRIM_ELLIPSOID;
        parse_ellipsoid(p, &pr, kind[0] == 's');
    } else if (strcmp(kind, "box") == 0) {
        pr.kind = SCN_PRIM_BOX;
        parse_box(p, &pr);
    } else {
        pr.kind = SCN_PRIM_DENSITY;
        parse_density(p, &pr);
    }
    if (pr.material < 0) {
        p->lx.tok_line = line, p->lx.tok_col = col;
        lex_error(&p->lx, "%s has no material ('material NAME' inside, or 'use NAME' "
                          "before it)", kind);
    }
    s->prims = parse_grow(p, s->prims, &p->cap_prims, s->n_prims, sizeof *s->prims,
                          SCN_MAX_PRIMS, "primitives");
    s->prims[s->n_prims++] = pr;
    lex_next(&p->lx);
}

/* ------------------------------------------------------------- clusters */

static int parse_new_cluster(struct parser *p, const char *name, int parent)
{
    struct sd_scene *s = p->s;
    s->clusters = parse_grow(p, s->clusters, &p->cap_clusters, s->n_clusters,
                             sizeof *s->clusters, SCN_MAX_CLUSTERS, "clusters");
    struct sd_cluster *c = &s->clusters[s->n_clusters];
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", name);
    c->parent = parent;
    c->m[0] = c->m[5] = c->m[10] = 1;
    return s->n_clusters++;
}

static int parse_global(struct parser *p);

/* The statements of a cluster's body, up to its '}' (or the end of the file
 * for the root, where global statements are allowed too). */
static void parse_cluster_body(struct parser *p, int c, int material, int nesting)
{
    int root = c == 0;
    for (;;) {
        struct lex *lx = &p->lx;
        if (lx->kind == LEX_CLOSE && !root)
            break;
        if (lx->kind == LEX_END) {
            if (root)
                break;
            lex_error(lx, "end of file inside cluster '%s' (a '}' is missing)",
                      p->s->clusters[c].name);
        }
        if (lx->kind != LEX_WORD)
            lex_error(lx, "expected a statement, found '%s'", lx->tok);
        if (root && parse_global(p))
            continue;
        if (parse_transform(p, p->s->clusters[c].m))
            continue;
        if (lex_is_word(lx, "key")) {
            parse_key(p, c);
        } else if (lex_is_word(lx, "use")) {
            lex_next(lx);
            material = parse_material_ref(p);
        } else if (lex_is_word(lx, "triangle") || lex_is_word(lx, "ellipsoid") ||
                   lex_is_word(lx, "sphere") || lex_is_word(lx, "box") ||
                   lex_is_word(lx, "density")) {
            parse_prim(p, c, material);
        } else if (lex_is_word(lx, "cluster")) {
            lex_next(lx);
            char name[SCN_MAX_NAME];
            lex_word(lx, "a cluster name", name, sizeof name);
            if (nesting + 1 > SCN_MAX_CLUSTER_NESTING)
                lex_error(lx, "clusters nested deeper than %d", SCN_MAX_CLUSTER_NESTING);
            parse_open(p, "cluster");
            int child = parse_new_cluster(p, name, c);
            parse_cluster_body(p, child, material, nesting + 1);
            lex_next(lx);
        } else {
            lex_error(lx, "unknown statement '%s'", lx->tok);
        }
    }
}

static int parse_global(struct parser *p)
{
    struct lex *lx = &p->lx;
    struct sd_view *v = &p->s->view;
    if (lex_is_word(lx, "camera")) {
        parse_camera(p);
    } else if (lex_is_word(lx, "resolution")) {
        if (p->seen_resolution++)
            lex_error(lx, "a second resolution");
        lex_next(lx);
        v->width = lex_int(lx, "width", 1, SCN_MAX_WIDTH);
        v->height = lex_int(lx, "height", 1, SCN_MAX_HEIGHT);
    } else if (lex_is_word(lx, "background")) {
        lex_next(lx);
        parse_unit3(p, "background", v->background);
    } else if (lex_is_word(lx, "options")) {
        parse_options(p);
    } else if (lex_is_word(lx, "animation")) {
        parse_animation(p);
    } else if (lex_is_word(lx, "light")) {
        parse_light(p);
    } else if (lex_is_word(lx, "map")) {
        parse_map(p);
    } else if (lex_is_word(lx, "material")) {
        parse_material(p);
    } else {
        return 0;
    }
    return 1;
}

/* ---------------------------------------------------------------- entry */

static void parse_defaults(struct sd_view *v)
{
    v->eye[2] = -5;
    v->up[1] = 1;
    v->fov = PARSE_DEFAULT_FOV;
    v->width = PARSE_DEFAULT_WIDTH;
    v->height = PARSE_DEFAULT_HEIGHT;
    v->max_depth = PARSE_DEFAULT_DEPTH;
    v->flags = SCN_OPT_REFRACTIONLESS;
    v->frames = 1;
}

int sd_parse_text(const char *name, const char *text, struct sd_scene *s, char *err,
                  size_t errlen)
{
    memset(s, 0, sizeof *s);
    struct parser *p = calloc(1, sizeof *p);
    if (!p) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    jmp_buf fail;
    p->s = s;
    const char *slash = strrchr(name, '/');
    if (slash && (size_t)(slash - name) + 2 < sizeof p->dir)
        memcpy(p->dir, name, (size_t)(slash - name) + 1);
    lex_init(&p->lx, name, text, &fail, err, errlen);
    if (setjmp(fail)) {
        free(p);
        sd_free(s);
        return -1;
    }
    parse_defaults(&s->view);
    lex_next(&p->lx);
    parse_new_cluster(p, "root", -1);
    parse_cluster_body(p, 0, -1, 0);
    if (s->n_lights == 0)
        lex_error(&p->lx, "the scene has no light");
    if (s->n_prims == 0)
        lex_error(&p->lx, "the scene has no primitive");
    free(p);
    return 0;
}

int sd_parse_file(const char *path, struct sd_scene *s, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    char *text = malloc(PARSE_MAX_FILE + 1);
    size_t n = text ? fread(text, 1, PARSE_MAX_FILE + 1, f) : 0;
    fclose(f);
    if (!text || n > PARSE_MAX_FILE) {
        snprintf(err, errlen, "%s: %s", path,
                 text ? "larger than the 64 MiB a scene text may be" : "out of memory");
        free(text);
        return -1;
    }
    text[n] = 0;
    if (memchr(text, 0, n)) {
        snprintf(err, errlen, "%s: contains a NUL byte (not a text scene)", path);
        free(text);
        return -1;
    }
    int rc = sd_parse_text(path, text, s, err, errlen);
    free(text);
    return rc;
}

void sd_free(struct sd_scene *s)
{
    for (int i = 0; i < s->n_maps; i++)
        free(s->maps[i].texels);
    free(s->materials);
    free(s->clusters);
    free(s->prims);
    free(s->components);
    free(s->keys);
    memset(s, 0, sizeof *s);
}
