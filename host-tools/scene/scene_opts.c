/* scene_opts.c: the options that change a text scene (scene_opts.h). */
#include "host-tools/scene/scene_opts.h"

#include <stdio.h>
#include <string.h>

#include "host-tools/opts/cli_args.h"
#include "proto/scene_format.h"

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

/* --aa N, --aa-threshold T, --no-aa (not with --aa). */
static int scene_opts_aa(struct scene_file_opts *o, const struct cli *c, int code)
{
    if (code == SCENE_OPT_AA_THRESHOLD)
        return cli_double(c, 0, 0, 1, NULL, &o->aa_threshold);
    if (code == SCENE_OPT_NO_AA)
        o->no_aa = 1;
    else if (cli_int(c, 0, SCN_MAX_AA_DEPTH, &o->aa_depth) != 0)
        return -1;
    if (o->no_aa && o->aa_depth >= 0)
        return cli_usage_error(c->prog, "--aa and --no-aa together");
    return 0;
}

int scene_opts_take(struct scene_file_opts *o, const struct cli *c, int code)
{
    switch (code) {
    case SCENE_OPT_NO_AUTO_HIERARCHY: o->no_auto_hierarchy = 1; return 1;
    case SCENE_OPT_MARK_LOST: o->mark_lost = 1; return 1;
    case SCENE_OPT_CHECK_LOST: o->check_lost = 1; return 1;
    case SCENE_OPT_WORLD_SPACE: o->world_space = 1; return 1;
    case SCENE_OPT_PAPER: o->paper = 1; return 1;
    case SCENE_OPT_SPD_RULES: o->spd_rules = 1; return 1;
    case SCENE_OPT_AA: case SCENE_OPT_AA_THRESHOLD: case SCENE_OPT_NO_AA:
        return scene_opts_aa(o, c, code) == 0 ? 1 : -1;
    }
    if (code < SCENE_OPT_SIZE || code > SCENE_OPT_TEXTURES_FROM)
        return 0;
    return scene_opts_value(o, c, code) == 0 ? 1 : -1;
}


void scene_opts_spd_line(uint64_t eye_hit, uint64_t reflect, uint64_t refract, uint64_t shadow,
                         double preprocess, double trace)
{
    printf("spd: eye_hit %llu reflect %llu refract %llu shadow %llu preprocess %.3f trace %.3f\n",
           (unsigned long long)eye_hit, (unsigned long long)reflect,
           (unsigned long long)refract, (unsigned long long)shadow, preprocess, trace);
    fflush(stdout);
}
