/* ref_opts.h: the options of the host reference renderer, defined once.
 * links1-ref-<arith> (ref_main.c) reads ref_optdefs and the scene options
 * (scene_opts.h); `links1 ref` (scene_cmds.c) reads those and
 * ref_cmd_optdefs, takes --arith, --auto, --fpu and --target-db out and
 * runs links1-ref-<arith> with the rest.  Both print their --help from
 * the same tables. */
#ifndef LINKS1_HOST_SCENE_REF_OPTS_H
#define LINKS1_HOST_SCENE_REF_OPTS_H

#include "host-tools/opts/cli_opt.h"

enum ref_opt_code {
    REF_OPT_PPM = CLI_OWN_CODES,
    REF_OPT_FRAME,
    REF_OPT_FRAMES,
    REF_OPT_ESCALATE,
    REF_OPT_NO_ESCALATE,
    REF_OPT_VERBOSE,
    REF_OPT_SUPERSAMPLE,
    REF_OPT_ARITH, /* links1 ref only, with the three below */
    REF_OPT_FPU,
    REF_OPT_TARGET_DB,
    REF_OPT_AUTO,
};

#define REF_SHORT_OPTIONS "o:h"
#define REF_MAX_OPTIONS 48 /* getopt's table: every definition, --help, the end */

/* links1-ref-<arith>'s own options. */
extern const struct cli_optdef ref_optdefs[];
/* links1 ref's: choosing the build. */
extern const struct cli_optdef ref_cmd_optdefs[];

/* The usage line and every option's help of links1 ref (with_cmd: the
 * build-choosing options too). */
void ref_opts_usage(FILE *f, const char *prog, int with_cmd);

#endif
