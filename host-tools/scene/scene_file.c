/* scene_file.c: see scene_file.h. */
#include "host-tools/scene/scene_file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/nff_read.h"
#include "host-tools/scene/scene_board.h"
#include "host-tools/scene/scene_import.h"
#include "proto/machines.h"
#include "host-tools/scene/scene_desc.h"

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
    *buf = malloc(SCN_MAX_SIZE + 1);
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
        snprintf(err, errlen, "%s: %s needs a text scene, not a compiled one%s", path, change,
                 strcmp(change, "--paper") == 0
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

const char *scene_opts_model_given(const struct scene_file_opts *o)
{
    return o->min_weight >= 0 ? "--min-weight" : o->density_steps >= 0 ? "--density-steps"
           : o->paper ? "--paper" : o->spd_rules ? "--spd-rules" : NULL;
}

const char *scene_opts_given(const struct scene_file_opts *o)
{
    return o->width ? "--size" : o->max_depth >= 0 ? "--max-depth"
           : o->min_weight >= 0 ? "--min-weight"
           : o->density_steps >= 0 ? "--density-steps"
           : o->aa_depth >= 0 ? "--aa" : o->aa_threshold >= 0 ? "--aa-threshold"
           : o->no_aa ? "--no-aa"
           : o->refractionless >= 0 ? "--refractionless"
           : o->refraction >= 0 ? "--refraction"
           : o->no_auto_hierarchy ? "--no-auto-hierarchy"
           : o->mark_lost ? "--mark-lost"
           : o->check_lost ? "--check-lost"
           : o->world_space ? "--world-space"
           : o->paper ? "--paper" : o->spd_rules ? "--spd-rules" : NULL;
}

/* A word for a switch that is given. */
static void scene_opts_switch(struct scene_opts_words *w, int *n, int on, const char *word)
{
    if (on)
        w->w[(*n)++] = word;
}

/* A word and its value. */
static void scene_opts_pair(struct scene_opts_words *w, int *n, const char *word,
                            const char *value)
{
    w->w[(*n)++] = word;
    w->w[(*n)++] = value;
}

int scene_opts_words(const struct scene_file_opts *o, enum scene_opts_for use,
                     struct scene_opts_words *w)
{
    int n = 0, all = use == SCENE_OPTS_ALL;
    if (all && o->width) {
        snprintf(w->size, sizeof w->size, "%dx%d", o->width, o->height);
        scene_opts_pair(w, &n, "--size", w->size);
    }
    if (o->max_depth >= 0) {
        snprintf(w->depth, sizeof w->depth, "%d", o->max_depth);
        scene_opts_pair(w, &n, "--max-depth", w->depth);
    }
    if (o->min_weight >= 0) {
        snprintf(w->weight, sizeof w->weight, "%.17g", o->min_weight);
        scene_opts_pair(w, &n, "--min-weight", w->weight);
    }
    if (o->density_steps >= 0) {
        snprintf(w->steps, sizeof w->steps, "%d", o->density_steps);
        scene_opts_pair(w, &n, "--density-steps", w->steps);
    }
    if (o->aa_depth >= 0) {
        snprintf(w->aa, sizeof w->aa, "%d", o->aa_depth);
        scene_opts_pair(w, &n, "--aa", w->aa);
    }
    if (o->aa_threshold >= 0) {
        snprintf(w->aa_threshold, sizeof w->aa_threshold, "%.17g", o->aa_threshold);
        scene_opts_pair(w, &n, "--aa-threshold", w->aa_threshold);
    }
    scene_opts_switch(w, &n, o->no_aa, "--no-aa");
    if (o->refraction >= 0)
        scene_opts_pair(w, &n, "--refraction", o->refraction ? "on" : "off");
    if (o->refractionless >= 0)
        scene_opts_pair(w, &n, "--refractionless", o->refractionless ? "on" : "off");
    scene_opts_switch(w, &n, o->no_auto_hierarchy, "--no-auto-hierarchy");
    scene_opts_switch(w, &n, all && o->mark_lost, "--mark-lost");
    scene_opts_switch(w, &n, all && o->check_lost, "--check-lost");
    scene_opts_switch(w, &n, all && o->world_space, "--world-space");
    scene_opts_switch(w, &n, o->paper, "--paper");
    scene_opts_switch(w, &n, o->spd_rules, "--spd-rules");
    for (int i = 0; i < SD_TEXTURES_FROM_MAX && o->textures_from[i]; i++)
        scene_opts_pair(w, &n, "--textures-from", o->textures_from[i]);
    w->w[n] = NULL;
    return n;
}
