/* scene_opts.c: the options that change a text scene (scene_opts.h). */
#include "host-tools/scene/scene_opts.h"

#include <stdio.h>
#include <string.h>

#include "host-tools/opts/cli_args.h"
#include "proto/scene_format.h"

const struct cli_optdef scene_optdefs[] = {
    {"size", "WxH", SCENE_OPT_SIZE, "render at this size instead of the scene's"},
    {"max-depth", "D", SCENE_OPT_MAX_DEPTH, "the scene's recursion depth instead (0..16)"},
    {"min-weight", "W", SCENE_OPT_MIN_WEIGHT,
     "adaptive depth: rays whose weight (the product of src and trc)\n"
     "falls below W are not traced (0..1; scenes default 1/512)"},
    {"density-steps", "N", SCENE_OPT_DENSITY_STEPS,
     "steps of a density sphere's root finder (2..256; scenes\n"
     "default 24): a feature thinner than a step is missed"},
    {"refractionless", "on|off", SCENE_OPT_REFRACTIONLESS,
     "transmission past the depth limit without bending"},
    {"refraction", "on|off", SCENE_OPT_REFRACTION, "off: transmitted rays never bend, at any depth"},
    {"no-auto-hierarchy", NULL, SCENE_OPT_NO_AUTO_HIERARCHY,
     "compile without the automatic hierarchy"},
    {"mark-lost", NULL, SCENE_OPT_MARK_LOST, "paint pixels that lost precision magenta"},
    {"check-lost", NULL, SCENE_OPT_CHECK_LOST,
     "trace a pixel that lost precision again in double only to check\n"
     "it: it counts as lost (and --mark-lost paints it) when double is\n"
     "more than 2/255 away; the image keeps this arithmetic's colours"},
    {"world-space", NULL, SCENE_OPT_WORLD_SPACE,
     "the DM leaves the scene in world coordinates and the NCs turn the\n"
     "camera rays: a frame whose cluster keys did not move keeps the\n"
     "frame before's primitives (no screen clipping)"},
    {"paper", NULL, SCENE_OPT_PAPER,
     "paper mode (as options { paper on }): every choice the paper made;\n"
     "an option given beside it wins; one line says what was set"},
    {"textures-from", "DIR", SCENE_OPT_TEXTURES_FROM,
     "a map's image may also come from below DIR (up to 4; not /, a\n"
     "directory just under / or your home)"},
    CLI_OPTDEF_END,
};

/* "on" or "off" into *v (1 or 0).  0, or -1 after saying what is wanted. */
static int scene_opts_on_off(const struct cli *c, int *v)
{
    if (strcmp(c->arg, "on") != 0 && strcmp(c->arg, "off") != 0)
        return cli_bad_value(c, "on or off");
    *v = strcmp(c->arg, "on") == 0;
    return 0;
}

/* The value of a scene option that has one. */
static int scene_opts_value(struct scene_file_opts *o, const struct cli *c, int code)
{
    char why[512];
    switch (code) {
    case SCENE_OPT_SIZE:
        return cli_parse_size(c->arg, &o->width, &o->height) == 0
                   ? 0 : cli_bad_value(c, cli_size_want());
    case SCENE_OPT_MAX_DEPTH: return cli_int(c, 0, SCN_MAX_DEPTH, &o->max_depth);
    case SCENE_OPT_MIN_WEIGHT: return cli_double(c, 0, 0, 1, NULL, &o->min_weight);
    case SCENE_OPT_DENSITY_STEPS:
        return cli_int(c, SCN_MIN_DENSITY_STEPS, SCN_MAX_DENSITY_STEPS, &o->density_steps);
    case SCENE_OPT_REFRACTIONLESS: return scene_opts_on_off(c, &o->refractionless);
    case SCENE_OPT_REFRACTION: return scene_opts_on_off(c, &o->refraction);
    case SCENE_OPT_TEXTURES_FROM:
        if (scene_file_textures_from(o, c->arg, why, sizeof why) == 0)
            return 0;
        return cli_usage_error(c->prog, "%s", why);
    }
    return -1;
}

int scene_opts_take(struct scene_file_opts *o, const struct cli *c, int code)
{
    switch (code) {
    case SCENE_OPT_NO_AUTO_HIERARCHY: o->no_auto_hierarchy = 1; return 1;
    case SCENE_OPT_MARK_LOST: o->mark_lost = 1; return 1;
    case SCENE_OPT_CHECK_LOST: o->check_lost = 1; return 1;
    case SCENE_OPT_WORLD_SPACE: o->world_space = 1; return 1;
    case SCENE_OPT_PAPER: o->paper = 1; return 1;
    }
    if (code < SCENE_OPT_SIZE || code > SCENE_OPT_TEXTURES_FROM)
        return 0;
    return scene_opts_value(o, c, code) == 0 ? 1 : -1;
}

/* flags with bit set (on) or cleared. */
static uint32_t scene_opts_bit(uint32_t flags, uint32_t bit, int on)
{
    return on ? flags | bit : flags & ~bit;
}

void scene_opts_apply(const struct scene_file_opts *o, struct sd_scene *s)
{
    if (o->paper && !s->paper)
        sd_paper_apply(s);
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

const char *scene_opts_given(const struct scene_file_opts *o)
{
    return o->width ? "--size" : o->max_depth >= 0 ? "--max-depth"
           : o->min_weight >= 0 ? "--min-weight"
           : o->density_steps >= 0 ? "--density-steps"
           : o->refractionless >= 0 ? "--refractionless"
           : o->refraction >= 0 ? "--refraction"
           : o->no_auto_hierarchy ? "--no-auto-hierarchy"
           : o->mark_lost ? "--mark-lost"
           : o->check_lost ? "--check-lost"
           : o->world_space ? "--world-space"
           : o->paper ? "--paper" : NULL;
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
    if (o->refraction >= 0)
        scene_opts_pair(w, &n, "--refraction", o->refraction ? "on" : "off");
    if (o->refractionless >= 0)
        scene_opts_pair(w, &n, "--refractionless", o->refractionless ? "on" : "off");
    scene_opts_switch(w, &n, o->no_auto_hierarchy, "--no-auto-hierarchy");
    scene_opts_switch(w, &n, all && o->mark_lost, "--mark-lost");
    scene_opts_switch(w, &n, all && o->check_lost, "--check-lost");
    scene_opts_switch(w, &n, all && o->world_space, "--world-space");
    scene_opts_switch(w, &n, o->paper, "--paper");
    for (int i = 0; i < SD_TEXTURES_FROM_MAX && o->textures_from[i]; i++)
        scene_opts_pair(w, &n, "--textures-from", o->textures_from[i]);
    w->w[n] = NULL;
    return n;
}
