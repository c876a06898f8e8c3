/* scene_opts.h: the options that change a text scene before it is
 * compiled (struct scene_file_opts), each defined once here: its name,
 * value, range, help line and the field it sets (scene_optdefs.c; read
 * by scene_opts.c).  `links1 render`, `links1 ref` (and
 * links1-ref-<arith>) read them through this table and print its help.
 * scene_file.h applies them, names them and writes them as words again
 * for a command line of a child, by these definitions' names. */
#ifndef LINKS1_HOST_SCENE_OPTS_H
#define LINKS1_HOST_SCENE_OPTS_H

#include <stdint.h>

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
    SCENE_OPT_SPD_RULES,
    SCENE_OPT_AA,
    SCENE_OPT_AA_THRESHOLD,
    SCENE_OPT_NO_AA,
};

/* The definitions, ending with CLI_OPTDEF_END. */
extern const struct cli_optdef scene_optdefs[];

/* The name (without "--") of the definition of code, or NULL. */
const char *scene_opts_name(int code);

/* The scene option cli_next returned as code taken into o: 1 taken, 0
 * not a scene option, -1 after saying what is wrong with its value. */
int scene_opts_take(struct scene_file_opts *o, const struct cli *c, int code);

/* --spd-rules: the one line of the counts of Haines's table and the
 * times apart, in seconds, on stdout:
 *   spd: eye_hit N reflect N refract N shadow N preprocess S trace S */
void scene_opts_spd_line(uint64_t eye_hit, uint64_t reflect, uint64_t refract, uint64_t shadow,
                         double preprocess, double trace);

#endif
