/* scene_cmds.c: `links1 compile`, `links1 ref` and `links1 export-pov`
 * (`links1 compare` is in image_compare.c). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/opts/cli_opt.h"
#include "host-tools/ref/arith_auto.h"
#include "host-tools/opts/cli_args.h"
#include "host-tools/opts/out_file.h"
#include "host-tools/ref/ref_opts.h"
#include "host-tools/cli/scene_cmds.h"
#include "host-tools/ref/ref_program.h"
#include "host-tools/scene/scene_board.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_file.h"
#include "host-tools/scene/scene_opts.h"
#include "proto/arith.h"

enum { EXPORT_OPT_FRAME = CLI_OWN_CODES, EXPORT_OPT_STRICT };

/* --textures-from DIR into the scene options o (scene_file_textures_from);
 * -1 after saying why. */
static int scene_cmd_textures_from(struct cli *c, struct scene_file_opts *o)
{
    char why[SD_ERR_MAX];
    if (scene_file_textures_from(o, c->arg, why, sizeof why) == 0)
        return 0;
    fprintf(stderr, "%s: %s\n", c->prog, why);
    return -1;
}

static int compile_take(struct cli *c, int code, void *ctx)
{
    return code == SCENE_OPT_TEXTURES_FROM ? scene_cmd_textures_from(c, ctx) : -1;
}

/* Reads "SCENE -o OUT" and the options of a scene command: each option of
 * longs other than -o and --help goes to take (when given).  0, 1 (--help
 * shown), -1 (bad arguments, reported with the usage) or -2 (OUT cannot be
 * written, out_file_check: said why). */
static int scene_cmd_args(struct cli *c, const char *usage, const char **in, const char **out,
                          int (*take)(struct cli *c, int code, void *ctx), void *ctx)
{
    *in = *out = NULL;
    for (int code; (code = cli_next(c)) != -1;) {
        int bad = 0;
        if (code == 'h') {
            printf("usage: %s\n", usage);
            return 1;
        } else if (code == 'o') {
            *out = c->arg;
        } else if (code == CLI_OPERAND && !*in) {
            *in = c->arg;
        } else if (code == CLI_OPERAND) {
            fprintf(stderr, "%s: one scene at a time, not also '%s'\n", c->prog, c->arg);
            bad = 1;
        } else {
            bad = code == CLI_BAD || !take || take(c, code, ctx) < 0;
        }
        if (bad) {
            fprintf(stderr, "usage: %s\n", usage);
            return -1;
        }
    }
    if (!*in || !*out) {
        fprintf(stderr, "%s: %s\nusage: %s\n", c->prog, !*in ? "no SCENE given" : "no -o OUT given",
                usage);
        return -1;
    }
    char err[PATH_MAX + 256];
    if (out_file_check(*out, err, sizeof err) != 0) { /* before the scene is read */
        fprintf(stderr, "%s: -o %s\n", c->prog, err);
        return -2;
    }
    return 0;
}

/* Writes len bytes to path whole or not at all (opts/out_file.h). */
static int cmd_write_file(const char *path, const void *data, size_t len)
{
    char err[PATH_MAX + 256];
    struct out_file of;
    int rc = out_file_open(&of, path, err, sizeof err);
    if (rc == 0 && fwrite(data, 1, len, of.f) != len) {
        snprintf(err, sizeof err, "%s: write failed: %s", path, strerror(errno));
        out_file_abort(&of);
        rc = -1;
    } else if (rc == 0) {
        rc = out_file_commit(&of, err, sizeof err);
    }
    if (rc != 0)
        fprintf(stderr, "links1: %s\n", err);
    return rc;
}

static const struct option compile_options[] = {
    {"textures-from", required_argument, NULL, SCENE_OPT_TEXTURES_FROM},
    {"help", no_argument, NULL, 'h'},
    {NULL, 0, NULL, 0},
};

int scene_cmd_compile(int argc, char **argv)
{
    const char *in, *out;
    struct scene_file_opts so;
    scene_file_opts_init(&so);
    struct cli c;
    cli_init(&c, "links1 compile", argc, argv, "o:h", compile_options);
    int r = scene_cmd_args(&c, "links1 compile SCENE.scn -o OUT.l1s [--textures-from DIR]", &in,
                           &out, compile_take, &so);
    if (r != 0)
        return r > 0 ? 0 : r == -2 ? 1 : 2;
    struct sd_scene s;
    char err[SD_ERR_MAX];
    if (scene_file_parse_from(in, so.textures_from, &s, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    uint8_t *buf;
    size_t len;
    int rc = sd_compile(&s, &buf, &len, err, sizeof err);
    sd_free(&s);
    if (rc != 0) {
        fprintf(stderr, "%s: %s\n", in, err);
        return 1;
    }
    rc = cmd_write_file(out, buf, len);
    struct sd_board_bytes b;
    if (rc == 0 && sd_board_bytes(buf, len, &b, err, sizeof err) == 0)
        printf("%s: %zu bytes (%u primitives, %u clusters); on the board: blob %zu bytes of "
               "%zu, NC clip lists %zu bytes\n",
               out, len, b.prims, b.clusters, b.blob, SD_BOARD_BLOB_LIMIT, b.nc_working);
    free(buf);
    return rc ? 1 : 0;
}

static const struct option export_pov_options[] = {
    {"frame", required_argument, NULL, EXPORT_OPT_FRAME},
    {"strict", no_argument, NULL, EXPORT_OPT_STRICT},
    {"textures-from", required_argument, NULL, SCENE_OPT_TEXTURES_FROM},
    {"help", no_argument, NULL, 'h'},
    {NULL, 0, NULL, 0},
};

struct export_pov_args {
    int strict, frame;
    struct scene_file_opts scene; /* its textures_from */
};

static int export_pov_take(struct cli *c, int code, void *ctx)
{
    struct export_pov_args *a = ctx;
    if (code == EXPORT_OPT_STRICT) {
        a->strict = 1;
        return 0;
    }
    if (code == SCENE_OPT_TEXTURES_FROM)
        return scene_cmd_textures_from(c, &a->scene);
    return code == EXPORT_OPT_FRAME ? cli_int(c, 0, SCN_MAX_FRAMES - 1, &a->frame) : -1;
}

int scene_cmd_export_pov(int argc, char **argv)
{
    const char *in, *out;
    struct export_pov_args a = {0, 0, {0}};
    scene_file_opts_init(&a.scene);
    struct cli c;
    cli_init(&c, "links1 export-pov", argc, argv, "o:h", export_pov_options);
    int r = scene_cmd_args(&c, "links1 export-pov SCENE.scn -o OUT.pov [--frame N] [--strict] "
                           "[--textures-from DIR]", &in, &out, export_pov_take, &a);
    if (r != 0)
        return r > 0 ? 0 : r == -2 ? 1 : 2;
    int strict = a.strict, frame = a.frame;
    struct sd_scene s;
    char err[SD_ERR_MAX];
    if (scene_file_parse_from(in, a.scene.textures_from, &s, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    struct out_file of;
    int rc = out_file_open(&of, out, err, sizeof err);
    if (rc != 0) {
        sd_free(&s);
        fprintf(stderr, "links1: %s\n", err);
        return 1;
    }
    rc = sd_export_pov(&s, frame, strict, of.f, out, err, sizeof err);
    sd_free(&s);
    if (rc != 0) {
        out_file_abort(&of);
        fprintf(stderr, "%s: %s\n", in, err);
        return 1;
    }
    if (out_file_commit(&of, err, sizeof err) != 0) {
        fprintf(stderr, "links1: %s\n", err);
        return 1;
    }
    return 0;
}

static const struct option ref_cmd_options[] = {
    REF_LONG_OPTIONS,
    {"arith", required_argument, NULL, REF_OPT_ARITH},
    {"fpu", required_argument, NULL, REF_OPT_FPU},
    {"target-db", required_argument, NULL, REF_OPT_TARGET_DB},
    {"auto", no_argument, NULL, REF_OPT_AUTO},
    {NULL, 0, NULL, 0},
};

/* links1 ref: runs links1-ref-<arith> from the directory of this program
 * with every argument but --arith A (ref_main.c checks their values);
 * --arith auto first chooses the build (arith_auto.c). */
int scene_cmd_ref(int argc, char **argv)
{
    const char *arith = "double", *model_word = NULL; /* an option --auto chooses */
    int model = 0, arith_given = 0;
    char **args = calloc((size_t)argc + 8, sizeof *args);
    const char **words = calloc((size_t)argc + 4, sizeof *words); /* the pre-render's */
    if (!args || !words) {
        fprintf(stderr, "links1 ref: out of memory\n");
        free(args);
        free(words);
        return 1;
    }
    int n = 1, nw = 0, fpu = -1, bad = 0;
    double target = -1;
    struct arith_auto_opts ao = {.fpu = 1, .target_db = ARITH_AUTO_TARGET_DB,
                                 .target = ARITH_AUTO_HOST};
    const char *scene = NULL;
    char first[24];
    struct cli c;
    cli_init(&c, "links1 ref", argc, argv, REF_SHORT_OPTIONS, ref_cmd_options);
    for (int from = 1, code; !bad && (code = cli_next(&c)) != -1; from = optind) {
        long f0, f1;
        switch (code) {
        case CLI_BAD:
            bad = 1;
            continue;
        case REF_OPT_ARITH:
            arith = c.arg;
            arith_given = 1;
            continue;
        case REF_OPT_AUTO:
            model = 1;
            continue;
        case REF_OPT_FPU:
            if ((fpu = arith_auto_fpu(c.arg)) < 0)
                bad = cli_bad_value(&c, "vfp or none") < 0;
            continue;
        case REF_OPT_TARGET_DB:
            bad = cli_double(&c, 0, 1, 99, NULL, &target) < 0;
            continue;
        case CLI_OPERAND:
            scene = scene ? scene : c.arg;
            break;
        case REF_OPT_SIZE:
            cli_parse_size(c.arg, &ao.width, &ao.height); /* ref_main.c reports bad ones */
            break;
        case REF_OPT_FRAMES: /* the pre-render: the first frame */
            if (cli_parse_frames(c.arg, &f0, &f1) == 0) {
                snprintf(first, sizeof first, "%ld", f0);
                words[nw++] = "--frame";
                words[nw++] = first;
            }
            break;
        case REF_OPT_MIN_WEIGHT:
        case REF_OPT_DENSITY_STEPS:
        case REF_OPT_PAPER:
            model_word = argv[from];
            /* fall through */
        case REF_OPT_MAX_DEPTH:
        case REF_OPT_REFRACTION:
        case REF_OPT_REFRACTIONLESS:
        case REF_OPT_NO_AUTO_HIERARCHY:
        case REF_OPT_TEXTURES_FROM:
        case REF_OPT_FRAME:
            for (int k = from; k < optind; k++)
                words[nw++] = argv[k];
            break;
        }
        /* the words of this option, as written (a "--" before an operand too) */
        for (int k = from; k < optind; k++)
            args[n++] = argv[k];
    }
    args[n] = NULL;
    words[nw] = NULL;
    if (!bad && model && (arith_given || model_word)) {
        fprintf(stderr, "links1 ref: --auto chooses the arithmetic, min_weight and density "
                "steps, so it takes no %s (--arith auto chooses the arithmetic alone)\n",
                arith_given ? "--arith" : model_word);
        bad = 1;
    }
    if (model)
        arith = "auto";
    int is_auto = strcmp(arith, "auto") == 0;
    if (!bad && !is_auto && (fpu >= 0 || target >= 0)) {
        fprintf(stderr, "links1 ref: --fpu and --target-db go with --arith auto (or --auto)\n");
        bad = 1;
    }
    if (bad) {
        fprintf(stderr, "usage: links1 ref SCENE(.scn|.l1s) -o OUT.png [options] "
                        "(links1 ref --help)\n");
        free(args);
        free(words);
        return 2;
    }
    struct arith_auto_choice pick;
    if (is_auto && scene) {
        ao.fpu = fpu < 0 ? 1 : fpu;
        ao.target_db = target < 0 ? ARITH_AUTO_TARGET_DB : target;
        ao.words = words;
        ao.model = model;
        if (arith_auto_pick("links1 ref", scene, &ao, &pick) != 0) {
            free(args);
            free(words);
            return 1;
        }
        arith = pick.build;
        if (pick.escalate)
            args[n++] = "--escalate";
    }
    char steps[16], weight[40]; /* --auto's model, after the words given */
    if (is_auto && scene && pick.density_steps >= 0) {
        snprintf(steps, sizeof steps, "%d", pick.density_steps);
        args[n++] = "--density-steps";
        args[n++] = steps;
    }
    if (is_auto && scene && pick.min_weight >= 0) {
        snprintf(weight, sizeof weight, "%.17g", pick.min_weight);
        args[n++] = "--min-weight";
        args[n++] = weight;
    }
    args[n] = NULL;
    free(words);
    const char *build = arith;
    int arith_code = is_auto ? ARITH_FIXED : arith_from_name(arith); /* a build, by name */
    if (is_auto && !scene) {
        build = "double"; /* it says what is missing */
    } else if (arith_code == ARITH_SOFT) {
        /* Software float differs from hardware float only in who executes
         * the IEEE operations; on the host both are the float build. */
        fprintf(stderr, "links1 ref: --arith soft on the host is the float build\n");
        build = "float";
    } else if (arith_code < 0) {
        fprintf(stderr, "links1 ref: --arith '%s': want double, float, soft, fixed or auto\n",
                arith);
        free(args);
        return 2;
    }
    char prog[PATH_MAX + 32];
    if (ref_program_path(build, prog, sizeof prog) != 0) {
        free(args);
        return 1;
    }
    args[0] = prog;
    execv(prog, args);
    fprintf(stderr, "links1 ref: cannot run %s: %s (build it with make)\n", prog,
            strerror(errno));
    free(args);
    return 1;
}
