/* scene_file.c: see scene_file.h. */
#include "host-tools/scene/scene_file.h"

#include <errno.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/nff_read.h"
#include "host-tools/scene/scene_board.h"
#include "host-tools/scene/scene_import.h"
#include "host-tools/scene/scene_opts.h"
#include "proto/machines.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_mem.h"

void scene_file_opts_init(struct scene_file_opts *o)
{
    o->width = o->height = 0;
    o->max_depth = -1;
    o->min_weight = -1;
    o->density_steps = -1;
    o->aa_depth = -1;
    o->aa_threshold = -1;
    o->no_aa = 0;
    o->refractionless = -1;
    o->refraction = -1;
    o->no_auto_hierarchy = 0;
    o->mark_lost = 0;
    o->check_lost = 0;
    o->world_space = 0;
    o->paper = 0;
    o->spd_rules = 0;
    o->machine = MACHINE_VIRT;
    memset(o->textures_from, 0, sizeof o->textures_from);
}

int scene_file_textures_from(struct scene_file_opts *o, const char *dir, char *err,
                             size_t errlen)
{
    int n = 0;
    while (o->textures_from[n])
        n++;
    if (n == SD_TEXTURES_FROM_MAX) {
        snprintf(err, errlen, "--textures-from %s: at most %d directories", dir,
                 SD_TEXTURES_FROM_MAX);
        return -1;
    }
    if (sd_textures_from_ok(dir, "--textures-from", err, errlen) != 0)
        return -1;
    o->textures_from[n] = dir;
    return 0;
}

int scene_file_ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

int scene_file_parse(const char *path, struct sd_scene *s, char *err, size_t errlen)
{
    return scene_file_parse_from(path, NULL, s, err, errlen);
}

int scene_file_parse_from(const char *path, const char *const *textures_from,
                          struct sd_scene *s, char *err, size_t errlen)
{
    if (scene_file_ends_with(path, ".nff"))
        return nff_read_file(path, s, NULL, err, errlen);
    return sd_parse_file_from(path, textures_from, s, err, errlen);
}

static int scene_file_compile(const char *path, const struct scene_file_opts *o, uint8_t **buf,
                              size_t *len, struct scene_file_info *info, char *err,
                              size_t errlen)
{
    struct sd_scene s;
    if (scene_file_parse_from(path, o->textures_from, &s, err, errlen) != 0)
        return -1;
    scene_opts_apply(o, &s);
    info->auto_hierarchy = !s.no_auto_hierarchy;
    info->own_clusters = s.n_clusters;
    char why[SD_ERR_MAX];
    int rc = sd_compile(&s, buf, len, why, sizeof why);
    sd_free(&s);
    if (rc != 0)
        snprintf(err, errlen, "%s: %s", path, why);
    return rc;
}

static int scene_file_read(const char *path, uint8_t **buf, size_t *len, char *err,
                           size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    *buf = scene_mem_alloc(SCN_MAX_SIZE + 1);
    *len = *buf ? fread(*buf, 1, SCN_MAX_SIZE + 1, f) : 0;
    fclose(f);
    const char *why = !*buf ? "out of memory"
                      : *len > SCN_MAX_SIZE ? "larger than a compiled scene may be"
                      : *len == 0 ? "empty file, not a compiled scene"
                      : NULL;
    if (why) {
        snprintf(err, errlen, "%s: %s", path, why);
        free(*buf);
        *buf = NULL;
        return -1;
    }
    return 0;
}

int scene_file_bytes(const char *path, const struct scene_file_opts *o, uint8_t **buf,
                     size_t *len, char *err, size_t errlen)
{
    struct scene_file_info info;
    return scene_file_bytes_info(path, o, buf, len, &info, err, errlen);
}

static int scene_file_bytes_any(const char *path, const struct scene_file_opts *o,
                                uint8_t **buf, size_t *len, struct scene_file_info *info,
                                char *err, size_t errlen);

int scene_file_bytes_info(const char *path, const struct scene_file_opts *o, uint8_t **buf,
                          size_t *len, struct scene_file_info *info, char *err, size_t errlen)
{
    if (scene_file_bytes_any(path, o, buf, len, info, err, errlen) != 0)
        return -1;
    char why[SD_ERR_MAX];
    if (sd_machine_check(*buf, *len, o->machine, why, sizeof why) == 0)
        return 0;
    snprintf(err, errlen, "%s: %s", path, why);
    free(*buf);
    *buf = NULL;
    *len = 0;
    return -1;
}

/* The bytes, compiled or read, checked against the virt board's limits
 * (the largest). */
static int scene_file_bytes_any(const char *path, const struct scene_file_opts *o,
                                uint8_t **buf, size_t *len, struct scene_file_info *info,
                                char *err, size_t errlen)
{
    *buf = NULL;
    *len = 0;
    info->auto_hierarchy = -1;
    info->own_clusters = -1;
    if (!scene_file_ends_with(path, ".l1s"))
        return scene_file_compile(path, o, buf, len, info, err, errlen);
    const char *change = scene_opts_given(o);
    if (change) {
        snprintf(err, errlen, "%s: --%s needs a text scene, not a compiled one%s", path, change,
                 strcmp(change, "paper") == 0
                     ? " (give the text scene, or compile it with options { paper on })" : "");
        return -1;
    }
    if (scene_file_read(path, buf, len, err, errlen) != 0)
        return -1;
    char why[SD_ERR_MAX];
    if (sd_board_check(*buf, *len, SD_BOARD_BLOB_LIMIT, why, sizeof why) == 0)
        return 0;
    snprintf(err, errlen, "%s: %s", path, why);
    free(*buf);
    *buf = NULL;
    *len = 0;
    return -1;
}

void scene_file_frame_path(const char *out, long frame, char *buf, size_t n)
{
    const char *dot = strrchr(out, '.');
    const char *slash = strrchr(out, '/');
    if (!dot || (slash && dot < slash))
        dot = out + strlen(out);
    snprintf(buf, n, "%.*s-%04ld%s", (int)(dot - out), out, frame, dot);
}

/* flags with bit set (on) or cleared. */
static uint32_t scene_opts_bit(uint32_t flags, uint32_t bit, int on)
{
    return on ? flags | bit : flags & ~bit;
}

/* Haines's rules for timing the SPD (docs/results/spd.md): 512x512, depth
 * 5 with the camera ray's (max_depth 4 here), every ray spawned
 * (min_weight 0), transmitted rays bent by Snell's law and none past the
 * depth limit, shadow rays; the corner rays and the reflected rays of
 * transmitters are the renderer's (SCN_OPT_SPD_RULES). */
static void scene_opts_spd_rules(struct sd_scene *s)
{
    s->view.width = s->view.height = 512;
    s->view.max_depth = 4;
    s->view.min_weight = 0;
    s->view.flags |= SCN_OPT_SPD_RULES;
    s->view.flags &= ~(SCN_OPT_REFRACTIONLESS | SCN_OPT_NO_REFRACTION | SCN_OPT_NO_SHADOWS);
}

/* --aa, --aa-threshold, --no-aa. */
static void scene_opts_apply_aa(const struct scene_file_opts *o, struct sd_view *v)
{
    if (o->aa_depth >= 0) {
        v->flags |= SCN_OPT_ANTIALIAS;
        v->aa_depth = o->aa_depth;
    }
    if (o->aa_threshold >= 0)
        v->aa_threshold = o->aa_threshold;
    if (o->no_aa)
        v->flags &= ~SCN_OPT_ANTIALIAS;
}

void scene_opts_apply(const struct scene_file_opts *o, struct sd_scene *s)
{
    if (o->paper && !s->paper)
        sd_paper_apply(s);
    if (s->paper_faceted > 0) /* once: the parser's paper mode or this one's */
        fprintf(stderr, "%s: %d cones/cylinders faceted (%d sides round: the paper's four "
                "primitives)\n", o->paper ? "--paper" : "paper mode", s->paper_faceted,
                SD_CONE_SIDES);
    if (o->spd_rules)
        scene_opts_spd_rules(s);
    if (o->width) {
        s->view.width = o->width;
        s->view.height = o->height;
    }
    if (o->max_depth >= 0)
        s->view.max_depth = o->max_depth;
    if (o->min_weight >= 0)
        s->view.min_weight = o->min_weight;
    if (o->density_steps >= 0)
        s->view.density_steps = o->density_steps;
    scene_opts_apply_aa(o, &s->view);
    if (o->no_auto_hierarchy)
        s->no_auto_hierarchy = 1;
    s->view.flags |= (o->mark_lost ? SCN_OPT_MARK_LOST : 0) |
                     (o->check_lost ? SCN_OPT_CHECK_LOST : 0) |
                     (o->world_space ? SCN_OPT_WORLD_SPACE : 0);
    if (o->refractionless >= 0)
        s->view.flags = scene_opts_bit(s->view.flags, SCN_OPT_REFRACTIONLESS, o->refractionless);
    if (o->refraction >= 0)
        s->view.flags = scene_opts_bit(s->view.flags, SCN_OPT_NO_REFRACTION, !o->refraction);
}

/* A scene option's field and value: a switch (given when not 0), a
 * number or on|off (given when not below 0), or the size (given when
 * width is not 0). */
enum scene_opt_value {
    SCENE_VALUE_NONE,   /* an int, no value */
    SCENE_VALUE_INT,    /* an int, written "%d" */
    SCENE_VALUE_DOUBLE, /* a double, written "%.17g" */
    SCENE_VALUE_ON_OFF, /* an int, written on (1) or off (0) */
    SCENE_VALUE_WXH,    /* width and height, written "WxH" */
};

/* Which commands an option goes to again (scene_opts_words), and whether
 * --auto chooses it itself (scene_opts_model_given). */
enum scene_opt_use {
    SCENE_USE_JUDGED, /* changes what a pre-render judges: in every use */
    SCENE_USE_MODEL,  /* judged, and one --auto chooses */
    SCENE_USE_OWN,    /* only in SCENE_OPTS_ALL: not in a pre-render */
};

/* An option of scene_optdefs (its name) as a field of struct
 * scene_file_opts. */
struct scene_opt_field {
    int code;
    enum scene_opt_value kind;
    size_t offset;
    enum scene_opt_use use;
};

#define SCENE_OPT_FIELD(code, kind, field, use) \
    {code, kind, offsetof(struct scene_file_opts, field), use}

/* In the order scene_opts_given looks and scene_opts_words writes. */
static const struct scene_opt_field scene_opt_fields[] = {
    SCENE_OPT_FIELD(SCENE_OPT_SIZE, SCENE_VALUE_WXH, width, SCENE_USE_OWN),
    SCENE_OPT_FIELD(SCENE_OPT_MAX_DEPTH, SCENE_VALUE_INT, max_depth, SCENE_USE_JUDGED),
    SCENE_OPT_FIELD(SCENE_OPT_MIN_WEIGHT, SCENE_VALUE_DOUBLE, min_weight, SCENE_USE_MODEL),
    SCENE_OPT_FIELD(SCENE_OPT_DENSITY_STEPS, SCENE_VALUE_INT, density_steps, SCENE_USE_MODEL),
    SCENE_OPT_FIELD(SCENE_OPT_AA, SCENE_VALUE_INT, aa_depth, SCENE_USE_JUDGED),
    SCENE_OPT_FIELD(SCENE_OPT_AA_THRESHOLD, SCENE_VALUE_DOUBLE, aa_threshold, SCENE_USE_JUDGED),
    SCENE_OPT_FIELD(SCENE_OPT_NO_AA, SCENE_VALUE_NONE, no_aa, SCENE_USE_JUDGED),
    SCENE_OPT_FIELD(SCENE_OPT_REFRACTIONLESS, SCENE_VALUE_ON_OFF, refractionless,
                    SCENE_USE_JUDGED),
    SCENE_OPT_FIELD(SCENE_OPT_REFRACTION, SCENE_VALUE_ON_OFF, refraction, SCENE_USE_JUDGED),
    SCENE_OPT_FIELD(SCENE_OPT_NO_AUTO_HIERARCHY, SCENE_VALUE_NONE, no_auto_hierarchy,
                    SCENE_USE_JUDGED),
    SCENE_OPT_FIELD(SCENE_OPT_MARK_LOST, SCENE_VALUE_NONE, mark_lost, SCENE_USE_OWN),
    SCENE_OPT_FIELD(SCENE_OPT_CHECK_LOST, SCENE_VALUE_NONE, check_lost, SCENE_USE_OWN),
    SCENE_OPT_FIELD(SCENE_OPT_WORLD_SPACE, SCENE_VALUE_NONE, world_space, SCENE_USE_OWN),
    SCENE_OPT_FIELD(SCENE_OPT_PAPER, SCENE_VALUE_NONE, paper, SCENE_USE_MODEL),
    SCENE_OPT_FIELD(SCENE_OPT_SPD_RULES, SCENE_VALUE_NONE, spd_rules, SCENE_USE_MODEL),
};
#define SCENE_OPT_FIELDS (sizeof scene_opt_fields / sizeof scene_opt_fields[0])
_Static_assert(SCENE_OPT_FIELDS + 1 <= SCENE_OPTS_MAX_FLAGS, "a flag buffer for each option");

/* 1 when o gives the option of f. */
static int scene_opt_is_given(const struct scene_file_opts *o, const struct scene_opt_field *f)
{
    const char *p = (const char *)o + f->offset;
    if (f->kind == SCENE_VALUE_DOUBLE)
        return *(const double *)p >= 0;
    if (f->kind == SCENE_VALUE_NONE || f->kind == SCENE_VALUE_WXH)
        return *(const int *)p != 0;
    return *(const int *)p >= 0;
}

/* The value o gives the option of f as a word (in buf when a number), or
 * NULL for a switch. */
static const char *scene_opt_value(const struct scene_file_opts *o,
                                   const struct scene_opt_field *f, char *buf, size_t n)
{
    const char *p = (const char *)o + f->offset;
    switch (f->kind) {
    case SCENE_VALUE_NONE: return NULL;
    case SCENE_VALUE_ON_OFF: return *(const int *)p ? "on" : "off";
    case SCENE_VALUE_INT: snprintf(buf, n, "%d", *(const int *)p); break;
    case SCENE_VALUE_DOUBLE: snprintf(buf, n, "%.17g", *(const double *)p); break;
    case SCENE_VALUE_WXH: snprintf(buf, n, "%dx%d", o->width, o->height); break;
    }
    return buf;
}

/* The name of the first option of scene_opt_fields o gives, of those
 * --auto chooses when model, or NULL. */
static const char *scene_opts_first(const struct scene_file_opts *o, int model)
{
    for (size_t i = 0; i < SCENE_OPT_FIELDS; i++) {
        const struct scene_opt_field *f = &scene_opt_fields[i];
        if ((!model || f->use == SCENE_USE_MODEL) && scene_opt_is_given(o, f))
            return scene_opts_name(f->code);
    }
    return NULL;
}

const char *scene_opts_model_given(const struct scene_file_opts *o)
{
    return scene_opts_first(o, 1);
}

const char *scene_opts_given(const struct scene_file_opts *o)
{
    return scene_opts_first(o, 0);
}

/* The word "--NAME" of option code, in w's next flag buffer. */
static const char *scene_opts_flag(struct scene_opts_words *w, int *flags, int code)
{
    char *buf = w->flag[(*flags)++];
    snprintf(buf, sizeof w->flag[0], "--%s", scene_opts_name(code));
    return buf;
}

int scene_opts_words(const struct scene_file_opts *o, enum scene_opts_for use,
                     struct scene_opts_words *w)
{
    int n = 0, flags = 0;
    for (size_t i = 0; i < SCENE_OPT_FIELDS; i++) {
        const struct scene_opt_field *f = &scene_opt_fields[i];
        if ((use != SCENE_OPTS_ALL && f->use == SCENE_USE_OWN) || !scene_opt_is_given(o, f))
            continue;
        const char *value = scene_opt_value(o, f, w->value[flags], sizeof w->value[0]);
        w->w[n++] = scene_opts_flag(w, &flags, f->code);
        if (value)
            w->w[n++] = value;
    }
    const char *from = o->textures_from[0] ? scene_opts_flag(w, &flags, SCENE_OPT_TEXTURES_FROM)
                                           : NULL;
    for (int i = 0; i < SD_TEXTURES_FROM_MAX && o->textures_from[i]; i++) {
        w->w[n++] = from;
        w->w[n++] = o->textures_from[i];
    }
    w->w[n] = NULL;
    return n;
}
