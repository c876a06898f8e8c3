/* ref_opts.h: the options of the host reference renderer (ref_main.c).
 * `links1 ref` (scene_cmds.c) reads the same table plus --arith, takes
 * --arith out and runs links1-ref-<arith> with the rest. */
#ifndef LINKS1_HOST_SCENE_REF_OPTS_H
#define LINKS1_HOST_SCENE_REF_OPTS_H

#include "host-tools/opts/cli_opt.h"

enum ref_opt_code {
    REF_OPT_PPM = CLI_OWN_CODES,
    REF_OPT_SIZE,
    REF_OPT_FRAME,
    REF_OPT_FRAMES,
    REF_OPT_NO_AUTO_HIERARCHY,
    REF_OPT_REFRACTION,
    REF_OPT_MAX_DEPTH,
    REF_OPT_MIN_WEIGHT,
    REF_OPT_DENSITY_STEPS,
    REF_OPT_MARK_LOST,
    REF_OPT_REFRACTIONLESS,
    REF_OPT_PAPER,
    REF_OPT_ESCALATE,
    REF_OPT_CHECK_LOST,
    REF_OPT_WORLD_SPACE,
    REF_OPT_TEXTURES_FROM,
    REF_OPT_ARITH, /* links1 ref only, with the two below */
    REF_OPT_FPU,
    REF_OPT_TARGET_DB,
    REF_OPT_AUTO, /* links1 ref only: --auto */
};

#define REF_SHORT_OPTIONS "o:h"
#define REF_LONG_OPTIONS                                  \
    {"ppm", no_argument, NULL, REF_OPT_PPM},              \
    {"size", required_argument, NULL, REF_OPT_SIZE},      \
    {"frame", required_argument, NULL, REF_OPT_FRAME},    \
    {"frames", required_argument, NULL, REF_OPT_FRAMES},  \
    {"no-auto-hierarchy", no_argument, NULL, REF_OPT_NO_AUTO_HIERARCHY}, \
    {"refraction", required_argument, NULL, REF_OPT_REFRACTION}, \
    {"max-depth", required_argument, NULL, REF_OPT_MAX_DEPTH}, \
    {"min-weight", required_argument, NULL, REF_OPT_MIN_WEIGHT}, \
    {"density-steps", required_argument, NULL, REF_OPT_DENSITY_STEPS}, \
    {"mark-lost", no_argument, NULL, REF_OPT_MARK_LOST}, \
    {"refractionless", required_argument, NULL, REF_OPT_REFRACTIONLESS}, \
    {"paper", no_argument, NULL, REF_OPT_PAPER}, \
    {"escalate", no_argument, NULL, REF_OPT_ESCALATE}, \
    {"check-lost", no_argument, NULL, REF_OPT_CHECK_LOST}, \
    {"world-space", no_argument, NULL, REF_OPT_WORLD_SPACE}, \
    {"textures-from", required_argument, NULL, REF_OPT_TEXTURES_FROM}, \
    {"help", no_argument, NULL, 'h'}

#endif
