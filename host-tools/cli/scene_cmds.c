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

/* compile takes every scene option (scene_opts.h) */
static int compile_take(struct cli *c, int code, void *ctx)
{
    return scene_opts_take(ctx, c, code) > 0 ? 0 : -1;
}

/* Reads "SCENE -o OUT" and the options of a scene command: each option of
 * longs other than -o and --help goes to take (when given).  0, 1 (--help
 * shown: the caller adds its options), -1 (bad arguments, said) or -2 (OUT cannot be
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
            bad = cli_usage_error(c->prog, "one scene at a time, not also '%s'", c->arg);
        } else {
            bad = code == CLI_BAD || !take || take(c, code, ctx) < 0;
        }
        if (bad)
            return -1;
    }
    if (!*in || !*out) {
        return cli_usage_error(c->prog, "%s", !*in ? "no SCENE given" : "no -o OUT given");
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
    int rc = out_file_write(path, data, len, err, sizeof err);
    if (rc != 0)
        fprintf(stderr, "links1: %s\n", err);
    return rc;
}


int scene_cmd_compile(int argc, char **argv)
{
    const char *in, *out;
    struct scene_file_opts so;
    scene_file_opts_init(&so);
    static const struct cli_optdef *const lists[] = {scene_optdefs, NULL};
    struct option longs[32];
    if (cli_optdefs_table(lists, longs, 32) != 0)
        return 2;
    struct cli c;
    cli_init(&c, "links1 compile", argc, argv, "o:h", longs);
    int r = scene_cmd_args(&c, "links1 compile SCENE.scn -o OUT.l1s [scene options]\n"
                           "Compiles a text scene into the form uploaded to the board; links1\n"
                           "render and links1 ref take either form.", &in, &out,
                           compile_take, &so);
    if (r == 1)
        cli_optdefs_help(stdout, scene_optdefs);
    if (r != 0)
        return r > 0 ? 0 : r == -2 ? 1 : 2;
    struct sd_scene s;
    char err[SD_ERR_MAX];
    if (scene_file_parse_from(in, so.textures_from, &s, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    scene_opts_apply(&so, &s);
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

static const struct cli_optdef export_pov_optdefs[] = {
    {"frame", "N", EXPORT_OPT_FRAME, "write frame N of a keyed scene (default 0)"},
    {"strict", NULL, EXPORT_OPT_STRICT,
     "refuse a scene POV-Ray cannot carry the same way, naming the first\n"
     "part, instead of writing it approximately (listed in a comment)"},
    CLI_OPTDEF_END,
};

/* export-pov's help: its own options and the scene option it shares. */
static void export_pov_usage(const struct cli_optdef *scene_defs)
{
    printf("Writes a scene for POV-Ray 3.7 (docs/pov-mapping.md).\n");
    cli_optdefs_help(stdout, export_pov_optdefs);
    cli_optdefs_help(stdout, scene_defs);
}

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
        return scene_opts_take(&a->scene, c, code) > 0 ? 0 : -1;
    return code == EXPORT_OPT_FRAME ? cli_int(c, 0, SCN_MAX_FRAMES - 1, &a->frame) : -1;
}

int scene_cmd_export_pov(int argc, char **argv)
{
    const char *in, *out;
    struct export_pov_args a = {0, 0, {0}};
    scene_file_opts_init(&a.scene);
    static const int shared[] = {SCENE_OPT_TEXTURES_FROM};
    struct cli_optdef scene_defs[2];
    const struct cli_optdef *const lists[] = {export_pov_optdefs, scene_defs, NULL};
    struct option longs[8];
    if (cli_optdefs_pick(scene_optdefs, shared, 1, scene_defs, 2) != 0 ||
        cli_optdefs_table(lists, longs, 8) != 0)
        return 2;
    struct cli c;
    cli_init(&c, "links1 export-pov", argc, argv, "o:h", longs);
    int r = scene_cmd_args(&c, "links1 export-pov SCENE.scn -o OUT.pov [options]", &in, &out,
                           export_pov_take, &a);
    if (r == 1)
        export_pov_usage(scene_defs);
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

/* What links1 ref's command line asks for. */
struct ref_cmd {
    const char *arith;        /* --arith (default double) */
    int arith_given, model;   /* --arith given; --auto */
    int fpu;                  /* --fpu: 1 vfp, 0 none, -1 not given */
    double target;            /* --target-db, -1 not given */
    const char *scene;        /* the first operand */
    int picked;               /* arith is the build --arith auto or --auto picked */
    int escalation_given;     /* --escalate or --no-escalate given */
    long first;               /* --frame or --frames' first: the pre-render's frame */
    struct scene_file_opts so; /* the scene options, for the pre-render */
    char **args;              /* links1-ref-<build>'s arguments, args[0] left for it */
    int nargs;
};

/* One option of links1 ref's own: 0, or -1 after saying why.  *pass is
 * set when the option goes on to links1-ref-<build>. */
static int ref_cmd_take(struct ref_cmd *r, struct cli *c, int code, int *pass)
{
    long last;
    *pass = 0;
    switch (code) {
    case REF_OPT_ARITH: r->arith = c->arg; r->arith_given = 1; return 0;
    case REF_OPT_AUTO: r->model = 1; return 0;
    case REF_OPT_FPU:
        return (r->fpu = arith_auto_fpu(c->arg)) < 0 ? cli_bad_value(c, "vfp or none") : 0;
    case REF_OPT_TARGET_DB: return cli_double(c, 0, 1, 99, NULL, &r->target);
    case REF_OPT_FRAME:
    case REF_OPT_FRAMES:
        cli_parse_frames(c->arg, &r->first, &last); /* links1-ref checks the value */
        break;
    case CLI_OPERAND:
        r->scene = r->scene ? r->scene : c->arg;
        break;
    case REF_OPT_ESCALATE:
    case REF_OPT_NO_ESCALATE:
        r->escalation_given = 1;
        break;
    }
    *pass = 1;
    int scene = scene_opts_take(&r->so, c, code);
    return scene < 0 ? -1 : 0;
}

/* The command line read into r.  0, 1 (--help shown) or -1 (said). */
static int ref_cmd_parse(struct ref_cmd *r, int argc, char **argv)
{
    static const struct cli_optdef *const lists[] = {ref_optdefs, scene_optdefs,
                                                     ref_cmd_optdefs, NULL};
    struct option longs[REF_MAX_OPTIONS];
    if (cli_optdefs_table(lists, longs, REF_MAX_OPTIONS) != 0)
        return -1;
    struct cli c;
    cli_init(&c, "links1 ref", argc, argv, REF_SHORT_OPTIONS, longs);
    for (int from = 1, code; (code = cli_next(&c)) != -1; from = optind) {
        int pass;
        if (code == 'h') {
            ref_opts_usage(stdout, "links1 ref", 1);
            return 1;
        }
        if (code == CLI_BAD || ref_cmd_take(r, &c, code, &pass) != 0)
            return -1;
        /* the words of this option, as written (a "--" before an operand too) */
        for (int k = from; pass && k < optind; k++)
            r->args[r->nargs++] = argv[k];
    }
    const char *model_word = scene_opts_model_given(&r->so);
    if (r->model && (r->arith_given || model_word))
        return cli_usage_error("links1 ref", "--auto chooses the arithmetic, min_weight and "
                               "density steps, so it takes no --%s (--arith auto chooses the "
                               "arithmetic alone)", r->arith_given ? "arith" : model_word);
    if (r->model)
        r->arith = "auto";
    if (strcmp(r->arith, "auto") != 0 && (r->fpu >= 0 || r->target >= 0))
        return cli_usage_error("links1 ref", "--fpu and --target-db go with --arith auto (or "
                               "--auto)");
    return 0;
}

/* --arith auto or --auto: the build chosen, and what it adds to the
 * arguments.  0, or -1 after saying why. */
static int ref_cmd_auto(struct ref_cmd *r, struct arith_auto_choice *pick,
                        struct scene_opts_words *model)
{
    struct arith_auto_words w;
    arith_auto_scene_words(&r->so, r->first, &w);
    struct arith_auto_opts ao = {.fpu = r->fpu < 0 ? 1 : r->fpu,
                                 .target_db = r->target < 0 ? ARITH_AUTO_TARGET_DB : r->target,
                                 .target = ARITH_AUTO_HOST, .width = r->so.width,
                                 .height = r->so.height, .words = w.words, .model = r->model};
    if (arith_auto_pick("links1 ref", r->scene, &ao, pick) != 0)
        return -1;
    r->arith = pick->build;
    r->picked = 1;
    r->args[r->nargs++] = pick->escalate ? "--escalate" : "--no-escalate";
    struct scene_file_opts picked; /* --auto's model, after the words given */
    scene_file_opts_init(&picked);
    picked.density_steps = pick->density_steps;
    picked.min_weight = pick->min_weight;
    int n = scene_opts_words(&picked, SCENE_OPTS_ALL, model);
    for (int i = 0; i < n; i++)
        r->args[r->nargs++] = (char *)model->w[i];
    return 0;
}

/* The build links1-ref-<build> that runs r's arithmetic: 0, 1 (failed,
 * said) or 2 (a usage error, said). */
static int ref_cmd_build(struct ref_cmd *r, const char **build)
{
    int is_auto = strcmp(r->arith, "auto") == 0;
    int code = is_auto || r->picked ? ARITH_FIXED : arith_from_name(r->arith); /* by name */
    *build = r->arith;
    if (r->picked) {
        return 0; /* a host build's own name: fixed18 is Q13.18 */
    } else if (is_auto) {
        *build = "double"; /* no scene: it says what is missing */
    } else if (code == ARITH_SOFT) {
        /* Software float differs from hardware float only in who executes
         * the IEEE operations; on the host both are the float build. */
        fprintf(stderr, "links1 ref: --arith soft on the host is the float build\n");
        *build = "float";
        if (!r->escalation_given) /* as the board's soft, which has no double to escalate to */
            r->args[r->nargs++] = "--no-escalate";
    } else if (code < 0) {
        cli_usage_error("links1 ref", "--arith '%s': want double, float, soft, fixed or auto",
                        r->arith);
        return 2;
    }
    return 0;
}

/* links1 ref: runs links1-ref-<arith> from the directory of this program
 * with every argument but the build-choosing ones (ref_main.c reads them
 * again); --arith auto and --auto first choose the build (arith_auto.c). */
int scene_cmd_ref(int argc, char **argv)
{
    struct ref_cmd r = {.arith = "double", .fpu = -1, .target = -1};
    scene_file_opts_init(&r.so);
    r.args = calloc((size_t)argc + 8, sizeof *r.args);
    if (!r.args) {
        fprintf(stderr, "links1 ref: out of memory\n");
        return 1;
    }
    r.nargs = 1;
    int rc = ref_cmd_parse(&r, argc, argv);
    struct arith_auto_choice pick;
    struct scene_opts_words model;
    char prog[PATH_MAX + 32];
    const char *build = NULL;
    if (rc == 0 && strcmp(r.arith, "auto") == 0 && r.scene)
        rc = ref_cmd_auto(&r, &pick, &model) == 0 ? 0 : 3;
    if (rc == 0)
        rc = ref_cmd_build(&r, &build) == 0 ? 0 : 2;
    if (rc == 0 && ref_program_path(build, prog, sizeof prog) != 0)
        rc = 3;
    if (rc == 0) {
        r.args[0] = prog;
        r.args[r.nargs] = NULL;
        execv(prog, r.args);
        fprintf(stderr, "links1 ref: cannot run %s: %s (build it with make)\n", prog,
                strerror(errno));
        rc = 3;
    }
    free(r.args);
    return rc == 1 ? 0 : rc < 0 ? 2 : rc == 3 ? 1 : rc;
}
