/* scene_opts.h: the options that change a text scene before it is
 * compiled (struct scene_file_opts), each defined once here: its name,
 * value, range, help line and the field it sets.  `links1 render`,
 * `links1 ref` (and links1-ref-<arith>) read them through this table and
 * print its help; --arith auto and --auto hand them on to their
 * pre-renders from it; scene_file.c applies them and names the first one
 * given when a compiled scene cannot take it. */
#ifndef LINKS1_HOST_SCENE_OPTS_H
#define LINKS1_HOST_SCENE_OPTS_H

#include "host-tools/opts/cli_opt.h"
#include "host-tools/scene/scene_file.h"

enum scene_opt_code {
    SCENE_OPT_SIZE = CLI_SCENE_CODES,
    SCENE_OPT_MAX_DEPTH,
    SCENE_OPT_MIN_WEIGHT,
    SCENE_OPT_DENSITY_STEPS,
    SCENE_OPT_REFRACTIONLESS,
    SCENE_OPT_REFRACTION,
    SCENE_OPT_NO_AUTO_HIERARCHY,
    SCENE_OPT_MARK_LOST,
    SCENE_OPT_CHECK_LOST,
    SCENE_OPT_WORLD_SPACE,
    SCENE_OPT_PAPER,
    SCENE_OPT_TEXTURES_FROM,
};

/* The definitions, ending with CLI_OPTDEF_END. */
extern const struct cli_optdef scene_optdefs[];

/* The scene option cli_next returned as code taken into o: 1 taken, 0
 * not a scene option, -1 after saying what is wrong with its value. */
int scene_opts_take(struct scene_file_opts *o, const struct cli *c, int code);

/* o's changes made to s (paper mode first: the others win over it). */
void scene_opts_apply(const struct scene_file_opts *o, struct sd_scene *s);

/* The first option o gives that changes the scene ("--max-depth"), or
 * NULL when none does (--textures-from changes nothing). */
const char *scene_opts_given(const struct scene_file_opts *o);

/* The words that give o again on a command line: every option o gives,
 * its value after it; for a pre-render of --arith auto or --auto, only
 * those that change what is judged (not --size, which the pre-render
 * sets, nor --mark-lost, --check-lost and --world-space). */
enum scene_opts_for { SCENE_OPTS_ALL, SCENE_OPTS_PRE_RENDER };
#define SCENE_OPTS_MAX_WORDS (2 * (12 + SD_TEXTURES_FROM_MAX) + 1)
struct scene_opts_words {
    const char *w[SCENE_OPTS_MAX_WORDS]; /* NULL-ended */
    char size[32], depth[16], weight[40], steps[16];
};
/* Fills w from o; the count of words. */
int scene_opts_words(const struct scene_file_opts *o, enum scene_opts_for use,
                     struct scene_opts_words *w);

#endif
