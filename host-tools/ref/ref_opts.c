/* ref_opts.c: the options of links1 ref and links1-ref-<arith> (ref_opts.h). */
#include "host-tools/ref/ref_opts.h"

#include "host-tools/scene/scene_opts.h"

const struct cli_optdef ref_optdefs[] = {
    {"frame", "N", REF_OPT_FRAME, "render frame N (default 0)"},
    {"frames", "A:B", REF_OPT_FRAMES,
     "render frames A..B, one image each (OUT-000A.png ...); an OUT ending\n"
     "in .mp4, .webm or .apng is one film, piped to ffmpeg"},
    {"ppm", NULL, REF_OPT_PPM, "write PPM (also chosen by an OUT ending in .ppm)"},
    {"escalate", NULL, REF_OPT_ESCALATE,
     "trace a pixel that lost precision again in double, as the board\n"
     "does (float and fixed: the default, but with --paper or soft)"},
    {"no-escalate", NULL, REF_OPT_NO_ESCALATE,
     "keep a pixel that lost precision as this arithmetic traced it"},
    {"verbose", NULL, REF_OPT_VERBOSE, "say how many pixels each frame escalated to double"},
    {"supersample", "N", REF_OPT_SUPERSAMPLE,
     "each pixel the mean of N x N rays through the centres of its N x N\n"
     "sub-squares (1..16; --arith double; not with --aa, --spd-rules,\n"
     "--paper or a scene's own aa): a reference for --aa"},
    CLI_OPTDEF_END,
};

const struct cli_optdef ref_cmd_optdefs[] = {
    {"arith", "A", REF_OPT_ARITH,
     "double (default), float, soft (on the host the float build), fixed,\n"
     "or auto: the cheapest arithmetic of a unit computer that keeps\n"
     "--target-db D against double on a low-resolution pre-render"},
    {"auto", NULL, REF_OPT_AUTO,
     "the arithmetic, min_weight and density steps together: the cheapest\n"
     "that keeps --target-db D against double at the most accurate model"},
    {"fpu", "vfp|none", REF_OPT_FPU, "--arith auto and --auto: the unit computer's FPU (default vfp)"},
    {"target-db", "D", REF_OPT_TARGET_DB, "--arith auto and --auto: the PSNR to keep (default 40)"},
    CLI_OPTDEF_END,
};

void ref_opts_usage(FILE *f, const char *prog, int with_cmd)
{
    fprintf(f, "usage: %s SCENE(.scn|.l1s|.nff) -o OUT.png [options]\n", prog);
    fprintf(f,
               "Renders a scene on the host with the board's renderer; the image of an\n"
               "arithmetic equals the board's byte for byte.\n");
    if (with_cmd)
        cli_optdefs_help(f, ref_cmd_optdefs);
    cli_optdefs_help(f, ref_optdefs);
    cli_optdefs_help(f, scene_optdefs);
}
