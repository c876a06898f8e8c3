/* scene_parse.c: the text scene format (docs/scene-format.md) into a
 * struct sd_scene: the shared helpers, the global statements, clusters and
 * the entry points.  Every statement is checked as it is read, so the error
 * names the line and column of the offending token; on error the partly
 * built scene is freed and the caller gets an empty one.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_parse.h"
#include "host-tools/scene/scene_mem.h"

/* ------------------------------------------------------------- helpers */

void *parse_grow(struct parser *p, void *arr, int *cap, int n, size_t elem,
                        int limit, const char *what)
{
    if (n >= limit)
        lex_error(&p->lx, "too many %s (the limit is %d)", what, limit);
    if (n < *cap)
        return arr;
    int ncap = *cap ? *cap * 2 : 16;
    void *na = scene_mem_realloc(arr, (size_t)ncap * elem);
    if (!na)
        lex_error(&p->lx, "out of memory reading %s", what);
    *cap = ncap;
    return na;
}

void parse_coord3(struct parser *p, const char *what, double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = lex_number_in(&p->lx, what, -SCN_MAX_COORD, SCN_MAX_COORD);
}

void parse_factor3(struct parser *p, const char *what, double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = lex_number_in(&p->lx, what, -SCN_MAX_FACTOR, SCN_MAX_FACTOR);
}

void parse_unit3(struct parser *p, const char *what, double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = lex_number_in(&p->lx, what, 0, 1);
}

int parse_on_off(struct parser *p, const char *what)
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

void parse_open(struct parser *p, const char *stmt)
{
    if (p->lx.kind != LEX_OPEN)
        lex_error(&p->lx, "expected '{' after %s, found '%s'", stmt, p->lx.tok);
    lex_next(&p->lx);
}

void parse_unknown(struct parser *p, const char *block)
{
    lex_error(&p->lx, "unknown %s property '%s'", block, p->lx.tok);
}

int parse_len3_zero(const double v[3]) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

int parse_find_material(const struct sd_scene *s, const char *name)
{
    for (int i = 0; i < s->n_materials; i++)
        if (strcmp(s->materials[i].name, name) == 0)
            return i;
    return -1;
}

int parse_find_map(const struct sd_scene *s, const char *name)
{
    for (int i = 0; i < s->n_maps; i++)
        if (strcmp(s->maps[i].name, name) == 0)
            return i;
    return -1;
}

int parse_material_ref(struct parser *p)
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
        } else if (lex_is_word(&p->lx, "min_weight")) {
            lex_next(&p->lx);
            v->min_weight = lex_number_in(&p->lx, "min_weight", 0, 1);
            p->s->written |= SD_WROTE_MIN_WEIGHT;
            continue;
        } else if (lex_is_word(&p->lx, "density_steps")) {
            lex_next(&p->lx);
            v->density_steps = lex_int(&p->lx, "density_steps", SCN_MIN_DENSITY_STEPS,
                                       SCN_MAX_DENSITY_STEPS);
            continue;
        } else if (lex_is_word(&p->lx, "aa")) { /* present = on */
            lex_next(&p->lx);
            v->aa_depth = lex_int(&p->lx, "aa", 0, SCN_MAX_AA_DEPTH);
            v->flags |= SCN_OPT_ANTIALIAS;
            continue;
        } else if (lex_is_word(&p->lx, "aa_threshold")) {
            lex_next(&p->lx);
            v->aa_threshold = lex_number_in(&p->lx, "aa_threshold", 0, 1);
            continue;
        } else if (lex_is_word(&p->lx, "refractionless")) {
            bit = SCN_OPT_REFRACTIONLESS;
        } else if (lex_is_word(&p->lx, "bounds")) {
            bit = SCN_OPT_NO_BOUNDS, inverted = 1;
        } else if (lex_is_word(&p->lx, "hierarchy")) {
            bit = SCN_OPT_NO_HIERARCHY, inverted = 1;
        } else if (lex_is_word(&p->lx, "refraction")) {
            bit = SCN_OPT_NO_REFRACTION, inverted = 1;
        } else if (lex_is_word(&p->lx, "shadows")) {
            bit = SCN_OPT_NO_SHADOWS, inverted = 1;
        } else if (lex_is_word(&p->lx, "mark_lost")) {
            bit = SCN_OPT_MARK_LOST;
        } else if (lex_is_word(&p->lx, "check_lost")) {
            bit = SCN_OPT_CHECK_LOST;
        } else if (lex_is_word(&p->lx, "world_space")) {
            bit = SCN_OPT_WORLD_SPACE;
        } else if (lex_is_word(&p->lx, "ambient_shadowed")) {
            bit = SCN_OPT_AMBIENT_SHADOWED;
        } else if (lex_is_word(&p->lx, "shadow_tint")) {
            bit = SCN_OPT_UNTINTED_SHADOWS, inverted = 1;
        } else if (lex_is_word(&p->lx, "fresnel")) { /* compiler only */
            lex_next(&p->lx);
            p->fresnel_off = !parse_on_off(p, "fresnel");
            p->s->written |= SD_WROTE_FRESNEL;
            continue;
        } else if (lex_is_word(&p->lx, "auto_hierarchy")) { /* compiler only */
            lex_next(&p->lx);
            p->s->no_auto_hierarchy = !parse_on_off(p, "auto_hierarchy");
            p->s->written |= SD_WROTE_AUTO_HIERARCHY;
            continue;
        } else if (lex_is_word(&p->lx, "paper")) { /* sd_paper_apply at the end */
            lex_next(&p->lx);
            p->s->paper = parse_on_off(p, "paper");
            continue;
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

/* haze { colour R G B  distance D }: both, once each, in any order */
static void parse_haze(struct parser *p)
{
    struct sd_view *v = &p->s->view;
    if (p->seen_haze++)
        lex_error(&p->lx, "a second haze block");
    lex_next(&p->lx);
    parse_open(p, "haze");
    int colour = 0, distance = 0;
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "colour") || lex_is_word(&p->lx, "color")) {
            if (colour++)
                lex_error(&p->lx, "haze: a second colour");
            lex_next(&p->lx);
            parse_unit3(p, "haze colour", v->haze_colour);
        } else if (lex_is_word(&p->lx, "distance")) {
            if (distance++)
                lex_error(&p->lx, "haze: a second distance");
            lex_next(&p->lx);
            v->haze_distance = lex_number_in(&p->lx, "haze distance", 0, SCN_MAX_COORD);
            if (!(v->haze_distance > 0))
                lex_error(&p->lx, "haze distance must be over 0 (the distance at which "
                          "exp(-1) of a colour is left)");
        } else if (p->lx.kind == LEX_END) {
            lex_error(&p->lx, "end of file inside the haze block (a '}' is missing)");
        } else {
            parse_unknown(p, "haze");
        }
    }
    if (!colour || !distance)
        lex_error(&p->lx, "haze needs a colour R G B and a distance D (missing: %s)",
                  !colour && !distance ? "both" : !colour ? "colour" : "distance");
    lex_next(&p->lx);
    v->haze = 1;
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
                   lex_is_word(lx, "density") || lex_is_word(lx, "cylinder") ||
                   lex_is_word(lx, "cone")) {
            parse_prim(p, c, material);
        } else if (lex_is_word(lx, "model")) {
            parse_model(p, c, nesting);
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
    } else if (lex_is_word(lx, "haze")) {
        parse_haze(p);
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

void sd_view_defaults(struct sd_view *v)
{
    v->eye[2] = -5;
    v->up[1] = 1;
    v->fov = PARSE_DEFAULT_FOV;
    v->width = PARSE_DEFAULT_WIDTH;
    v->height = PARSE_DEFAULT_HEIGHT;
    v->max_depth = PARSE_DEFAULT_DEPTH;
    v->min_weight = SCN_DEFAULT_MIN_WEIGHT;
    v->density_steps = SCN_DEFAULT_DENSITY_STEPS;
    v->aa_threshold = SCN_DEFAULT_AA_THRESHOLD;
    v->flags = SCN_OPT_REFRACTIONLESS | SCN_OPT_AMBIENT_SHADOWED | SCN_OPT_UNTINTED_SHADOWS;
    v->frames = 1;
}

/* The default of fresnel, once the whole file (and its options) is read:
 * 1, src(th) and trc(th) on Schlick's curve (the paper's angle-dependent
 * coefficients), for a material that reflects or transmits; 0 for a
 * matte one (src = trc = 0: no mirror term whose coefficient could vary,
 * where a curve from src = 0 would make it a mirror at grazing) and
 * under options { fresnel off }. */
static void parse_resolve_fresnel(struct parser *p)
{
    for (int i = 0; i < p->s->n_materials; i++) {
        struct sd_material *m = &p->s->materials[i];
        if (m->fresnel == PARSE_FRESNEL_UNSET)
            m->fresnel = !p->fresnel_off && (m->src > 0 || m->trc > 0) ? 1 : 0;
    }
}

int sd_parse_text(const char *name, const char *text, struct sd_scene *s, char *err,
                  size_t errlen)
{
    return sd_parse_text_from(name, text, NULL, s, err, errlen);
}

int sd_parse_text_from(const char *name, const char *text, const char *const *textures_from,
                       struct sd_scene *s, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    struct parser *p = calloc(1, sizeof *p);
    if (!p) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    jmp_buf fail;
    p->s = s;
    p->textures_from = textures_from;
    const char *slash = strrchr(name, '/');
    if (slash && (size_t)(slash - name) + 2 < sizeof p->dir)
        memcpy(p->dir, name, (size_t)(slash - name) + 1);
    lex_init(&p->lx, name, text, &fail, err, errlen);
    if (setjmp(fail)) {
        free(p);
        sd_free(s);
        return -1;
    }
    sd_view_defaults(&s->view);
    lex_next(&p->lx);
    parse_new_cluster(p, "root", -1);
    parse_cluster_body(p, 0, -1, 0);
    if (s->n_lights == 0)
        lex_error(&p->lx, "the scene has no light");
    if (s->n_prims == 0)
        lex_error(&p->lx, "the scene has no primitive");
    parse_resolve_fresnel(p);
    if (s->paper && (s->view.flags & SCN_OPT_ANTIALIAS))
        lex_error(&p->lx, "options: aa with paper on: paper mode has no anti-aliasing "
                  "(--paper --aa N gives both)");
    if (s->paper)
        sd_paper_apply(s);
    free(p);
    return 0;
}

int sd_parse_file(const char *path, struct sd_scene *s, char *err, size_t errlen)
{
    return sd_parse_file_from(path, NULL, s, err, errlen);
}

int sd_parse_file_from(const char *path, const char *const *textures_from, struct sd_scene *s,
                       char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    char *text = scene_mem_alloc(PARSE_MAX_FILE + 1);
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
    int rc = sd_parse_text_from(path, text, textures_from, s, err, errlen);
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
    free(s->view_keys);
    memset(s, 0, sizeof *s);
}
