/* cmd_render.c: `links1 render`: the whole LINKS-1 image generation system
 * driven from the host.  Compiles each scene in-process, boots a board of
 * DM + RC + N NCs, uploads the scene, renders the frames (progress on the
 * terminal), pulls each frame and writes it as PNG or PPM, prints a
 * one-line summary per frame.  Several SCENE -o OUT pairs render one after
 * another on the same board; a scene the board refuses is reported and the
 * next one still renders (the exit status is then 1). */
#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/launcher/launcher.h"
#include "host-tools/insn/insn_report.h"
#include "host-tools/cli/links1_cmds.h"
#include "host-tools/gigs/render_faults.h"
#include "host-tools/gigs/render_session.h"
#include "host-tools/trace/trace_file.h"
#include "host-tools/ref/arith_auto.h"
#include "host-tools/image/film.h"
#include "host-tools/image/image_io.h"
#include "host-tools/image/image_save.h"
#include "host-tools/opts/cli_args.h"
#include "host-tools/opts/out_file.h"
#include "host-tools/opts/tmp_dir.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_file.h"
#include "host-tools/scene/scene_opts.h"
#include "host-tools/scene/scene_paper.h"
#include "proto/areas.h"
#include "render/render.h"

#define RENDER_MAX_JOBS 16 /* SCENE -o OUT pairs in one run */
#define RENDER_MAX_OPTIONS 80 /* getopt's table: every option's definition, --help, the end */

struct render_job {
    const char *scene, *out;
    uint8_t *bytes; /* the compiled scene, read before the board boots */
    size_t len;
    struct scene_file_info info; /* how it was compiled */
    uint32_t frames, height;     /* its compiled header's (render_check_job); 0: not
                                    readable, the board's loader judges it */
};

/* Where a render command's wall time goes, ms, and QEMU's host CPU time
 * while the board rendered (for the host cores' use). */
struct render_wall {
    long long compile; /* the scenes', the board booting beside it (render_boots_early) */
    long long boot;    /* the rest of the boot, after the compile */
    long long upload, load, frame, pull, write, shutdown, total;
    long long board_prepare, board_render;
    long long render_cpu; /* the QEMUs' user + system ms during the frames (every
                             an521 board's) */
};

/* Escalation as asked (render_escalation_settle decides the default). */
enum render_escalation { RENDER_ESC_DEFAULT, RENDER_ESC_ON, RENDER_ESC_OFF };

struct render_opts {
    struct board_opts board;
    struct render_job jobs[RENDER_MAX_JOBS];
    int njobs;
    struct link_render_args args;
    long first, last;   /* frames; last < 0: only frame first */
    long row_first, row_last; /* --rows A:B: a band of the frame (row_first < 0: all) */
    long band, bands;         /* --band I/N: band I of N equal bands (bands 0: none) */
    int many;           /* --frames: one image per frame, numbered */
    struct scene_file_opts scene; /* --size, --max-depth, --refractionless */
    int ppm, count_insns;
    const char *board_name; /* --board NAME: a running named board */
    unsigned inject, inject_seed; /* --inject-faults K[:SEED] */
    uint8_t inject_kind;          /* --inject-kind */
    unsigned inject_every;        /* --inject-every F: K more every F frames */
    int unit_fault_core;          /* --inject-unit-fault: DM or RC core, -1: none */
    long unit_fault_frame;
    int resume;                   /* --resume: frames already written are kept */
    int fps;                      /* --fps N: a film's frames a second */
    const char *trace;  /* --trace FILE */
    int arith_auto, fpu; /* --arith auto (or --auto), --fpu vfp|none (-1: not given) */
    int model_auto, arith_named; /* --auto; --arith given */
    double target_db;    /* --target-db D (-1: not given) */
    unsigned gave;      /* SCENE_PAPER_GAVE_*: render options given, which paper mode keeps */
    enum render_escalation escalation; /* --escalate, --no-escalate or neither */
};

/* What a render command keeps as it runs (its options are render_opts'). */
struct render_run {
    struct render_wall wall; /* where the command's wall time went */
    uint8_t inject_taken[LINK_CORE_MAP_SIZE]; /* NCs already planned to fail */
    long frames_done;        /* frames rendered in this run */
    uint32_t traced_w, traced_h, traced_bytes; /* the traced frame's size, broadcast */
    struct link_render_args traced_args;       /* what the traced frame ran with */
    uint32_t prims;          /* the first scene's primitives (the DM's spans a primitive) */
};

enum render_opt_code {
    RENDER_OPT_BALANCE = CLI_OWN_CODES,
    RENDER_OPT_AREAS,
    RENDER_OPT_GUIDED,
    RENDER_OPT_ASK,
    RENDER_OPT_FRAME,
    RENDER_OPT_FRAMES,
    RENDER_OPT_ROWS,
    RENDER_OPT_BAND,
    RENDER_OPT_NO_YCLIP,
    RENDER_OPT_NO_XCLIP,
    RENDER_OPT_CLIP,
    RENDER_OPT_NO_BBOX,
    RENDER_OPT_NO_HIERARCHY,
    RENDER_OPT_PPM,
    RENDER_OPT_COUNT_INSNS,
    RENDER_OPT_INSN_PROFILE,
    RENDER_OPT_INSN_PROFILE_CORE,
    RENDER_OPT_BOARD,
    RENDER_OPT_INJECT_FAULTS,
    RENDER_OPT_INJECT_KIND,
    RENDER_OPT_INJECT_UNIT_FAULT,
    RENDER_OPT_INJECT_EVERY,
    RENDER_OPT_RESUME,
    RENDER_OPT_TRACE,
    RENDER_OPT_FPU,
    RENDER_OPT_TARGET_DB,
    RENDER_OPT_FPS,
    RENDER_OPT_ESCALATE,
    RENDER_OPT_NO_ESCALATE,
    RENDER_OPT_AUTO,
};

/* render's own options (the board's and the scene's are theirs). */
static const struct cli_optdef render_optdefs[] = {
    {"auto", NULL, RENDER_OPT_AUTO,
     "the arithmetic, min_weight and density steps together: the\n"
     "cheapest that keeps --target-db D against double (--arith auto:\n"
     "the arithmetic alone)"},
    {"fpu", "vfp|none", RENDER_OPT_FPU, "--arith auto and --auto: the NCs' FPU (default vfp)"},
    {"target-db", "D", RENDER_OPT_TARGET_DB, "--arith auto and --auto: the PSNR to keep (default 40)"},
    {"escalate", NULL, RENDER_OPT_ESCALATE,
     "trace a pixel that lost precision again in double on the same\n"
     "NC (float or fixed: links1-<arith>-esc.elf, or a named board\n"
     "started in float or fixed); the default there, but with --paper\n"
     "or --firmware"},
    {"no-escalate", NULL, RENDER_OPT_NO_ESCALATE,
     "keep a pixel that lost precision as the NC's arithmetic traced it"},
    {"balance", "M", RENDER_OPT_BALANCE,
     "static, dynamic, decreasing (default) or lines (simple dynamic\n"
     "on scanlines, the paper's job unit)"},
    {"areas", "K", RENDER_OPT_AREAS,
     "areas of the dynamic or lines grid; the smallest-area bound of\n"
     "decreasing (default: by NC count, docs/areas.md)"},
    {"guided", "F", RENDER_OPT_GUIDED,
     "decreasing: each area takes 1/(F * NCs) of what is left (1..64)"},
    {"ask", "ahead|finished", RENDER_OPT_ASK,
     "when an NC asks for its next area: a round trip before it\n"
     "expects to finish (default), or once it has (the paper's rule)"},
    {"clip", "auto|lists|tree", RENDER_OPT_CLIP,
     "how the NCs clip the screen: the paper's lists where few\n"
     "clusters cover a pixel, the hierarchy where many (auto)"},
    {"no-yclip", NULL, RENDER_OPT_NO_YCLIP, "switch Y clipping off (the image stays the same)"},
    {"no-xclip", NULL, RENDER_OPT_NO_XCLIP, "switch X clipping off (the same image)"},
    {"no-bbox", NULL, RENDER_OPT_NO_BBOX, "switch the bounding boxes off (the same image)"},
    {"no-hierarchy", NULL, RENDER_OPT_NO_HIERARCHY, "switch the hierarchy off (the same image)"},
    {"frame", "N", RENDER_OPT_FRAME, "render frame N (default 0)"},
    {"frames", "A:B", RENDER_OPT_FRAMES,
     "render frames A..B into OUT-000A.png ...; an OUT ending in .mp4,\n"
     ".webm or .apng is one film, the frames piped to ffmpeg"},
    {"fps", "N", RENDER_OPT_FPS, "a film's frames a second (1..240, default 12)"},
    {"resume", NULL, RENDER_OPT_RESUME,
     "with --frames: keep the frames already written, render the rest"},
    {"rows", "A:B", RENDER_OPT_ROWS, "render scanlines A..B only: OUT is that band"},
    {"band", "I/N", RENDER_OPT_BAND, "render band I of N equal bands of scanlines"},
    {"ppm", NULL, RENDER_OPT_PPM, "write PPM (also chosen by an OUT ending in .ppm)"},
    {"board", "NAME", RENDER_OPT_BOARD,
     "render on the running board NAME (links1 board start)"},
    {"count-insns", NULL, RENDER_OPT_COUNT_INSNS, "count guest instructions per core, print them"},
    {"trace", "FILE", RENDER_OPT_TRACE,
     "write one frame's per-area and per-pixel instruction costs (the\n"
     "input of links1 replay)"},
    {"insn-profile", "FILE", RENDER_OPT_INSN_PROFILE,
     "the NCs' guest instructions per translated block into FILE"},
    {"insn-profile-core", "K", RENDER_OPT_INSN_PROFILE_CORE, "profile core K alone instead"},
    {"inject-faults", "K[:SEED]", RENDER_OPT_INJECT_FAULTS,
     "test hook: K random NCs fail during the first frame, which\n"
     "still completes"},
    {"inject-kind", "KIND", RENDER_OPT_INJECT_KIND,
     "undef, abort, hang, silent or mixed (default)"},
    {"inject-every", "F", RENDER_OPT_INJECT_EVERY, "K more NCs fail every F frames"},
    {"inject-unit-fault", "dm|rc:FRAME", RENDER_OPT_INJECT_UNIT_FAULT,
     "test hook: the DM or the RC faults while FRAME renders"},
    CLI_OPTDEF_END,
};

static void render_usage(FILE *out)
{
    fprintf(out, "usage: links1 render SCENE(.scn|.l1s|.nff) -o OUT.png [SCENE2 -o OUT2 ...] "
                 "[options]\n"
                 "Renders on the emulated LINKS-1 (DM, RC and N NCs); several scenes render one\n"
                 "after another on the same board.  --arith auto: the cheapest arithmetic that\n"
                 "keeps --target-db D against double on a low-resolution pre-render.\n"
                 "board options:\n");
    cli_optdefs_help(out, board_optdefs);
    fprintf(out, "scene options (text scenes):\n");
    cli_optdefs_help(out, scene_optdefs);
    fprintf(out, "render options:\n");
    cli_optdefs_help(out, render_optdefs);
}

/* A line of what happened, on stdout unless --quiet: with --quiet a
 * render that works prints nothing (what it was asked to count or trace
 * is still printed). */
__attribute__((format(printf, 2, 3))) static void render_say(const struct render_opts *o,
                                                             const char *fmt, ...)
{
    if (o->board.quiet)
        return;
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

/* A scene named on the command line, or the -o OUT of the last one. */
static int render_add_job(struct render_opts *o, int code, const char *arg)
{
    if (code == 'o') {
        if (o->njobs == 0 || o->jobs[o->njobs - 1].out) {
            fprintf(stderr, "links1 render: -o %s: name the scene before its output\n", arg);
            return -1;
        }
        o->jobs[o->njobs - 1].out = arg;
        return 0;
    }
    if (o->njobs == RENDER_MAX_JOBS) {
        fprintf(stderr, "links1 render: %s: at most %d scenes in one run\n", arg,
                RENDER_MAX_JOBS);
        return -1;
    }
    o->jobs[o->njobs++] = (struct render_job){arg, NULL, NULL, 0, {-1, -1}, 0, 0};
    return 0;
}

/* One of render's options of the area schedule and the NCs' clipping: 1
 * taken, 0 not one of them, -1 said what is wrong. */
static int render_take_schedule(struct render_opts *o, const struct cli *c, int code)
{
    long n;
    enum areas_mode m;
    static const struct { const char *word; uint8_t clip; } clips[] = {
        {"auto", LINK_CLIP_AUTO}, {"lists", LINK_CLIP_LISTS}, {"tree", LINK_CLIP_TREE}};
    static const struct { int code; uint8_t flag; } offs[] = {
        {RENDER_OPT_NO_YCLIP, LINK_RENDER_NO_YCLIP}, {RENDER_OPT_NO_XCLIP, LINK_RENDER_NO_XCLIP},
        {RENDER_OPT_NO_BBOX, LINK_RENDER_NO_BBOX}, {RENDER_OPT_NO_HIERARCHY, LINK_RENDER_NO_HIERARCHY}};
    for (size_t i = 0; i < sizeof offs / sizeof offs[0]; i++)
        if (code == offs[i].code) {
            o->args.flags |= offs[i].flag;
            return 1;
        }
    switch (code) {
    case RENDER_OPT_BALANCE:
        if (areas_mode_parse(c->arg, &m) != AREAS_OK)
            return cli_bad_value(c, "static, dynamic, decreasing or lines");
        o->args.balance = (uint8_t)m;
        o->gave |= SCENE_PAPER_GAVE_BALANCE;
        return 1;
    case RENDER_OPT_AREAS:
        if (cli_long(c, 10, 1, 1 << 20, &n) < 0)
            return -1;
        o->args.areas = (uint32_t)n;
        o->gave |= SCENE_PAPER_GAVE_AREAS;
        return 1;
    case RENDER_OPT_GUIDED:
        if (cli_long(c, 10, 1, AREAS_MAX_GUIDED_FACTOR, &n) < 0)
            return -1;
        o->args.guided = (uint8_t)n;
        return 1;
    case RENDER_OPT_ASK:
        if (strcmp(c->arg, "ahead") != 0 && strcmp(c->arg, "finished") != 0)
            return cli_bad_value(c, "ahead or finished");
        o->args.flags = strcmp(c->arg, "finished") == 0
                            ? o->args.flags | LINK_RENDER_ASK_WHEN_DONE
                            : o->args.flags & (uint8_t)~LINK_RENDER_ASK_WHEN_DONE;
        o->gave |= SCENE_PAPER_GAVE_ASK;
        return 1;
    case RENDER_OPT_CLIP:
        for (size_t i = 0; i < sizeof clips / sizeof clips[0]; i++)
            if (strcmp(c->arg, clips[i].word) == 0) {
                o->args.clip = clips[i].clip;
                o->gave |= SCENE_PAPER_GAVE_CLIP;
                return 1;
            }
        return cli_bad_value(c, "auto, lists or tree");
    }
    return 0;
}

/* One of render's options of which frames, rows and files: 1, 0 or -1. */
static int render_take_frames(struct render_opts *o, const struct cli *c, int code)
{
    long n;
    switch (code) {
    case RENDER_OPT_FRAME:
    case RENDER_OPT_FRAMES:
        o->many = code == RENDER_OPT_FRAMES;
        if (cli_parse_frames(c->arg, &o->first, &o->last) != 0 ||
            (!o->many && o->first != o->last))
            return cli_bad_value(c, o->many ? "FIRST:LAST" : "a frame number");
        return 1;
    case RENDER_OPT_ROWS:
        if (cli_parse_frames(c->arg, &o->row_first, &o->row_last) != 0 ||
            o->row_last >= UINT16_MAX)
            return cli_bad_value(c, "scanlines A:B, 0 <= A <= B");
        return 1;
    case RENDER_OPT_BAND:
        if (cli_parse_band(c->arg, &o->band, &o->bands) != 0) {
            o->bands = 0;
            return cli_bad_value(c, "band I/N, 0 <= I < N <= 65535");
        }
        return 1;
    case RENDER_OPT_FPS:
        if (cli_long(c, 10, 1, FILM_MAX_FPS, &n) < 0)
            return -1;
        o->fps = (int)n;
        return 1;
    case RENDER_OPT_RESUME: o->resume = 1; return 1;
    case RENDER_OPT_PPM: o->ppm = 1; return 1;
    case RENDER_OPT_BOARD: o->board_name = c->arg; return 1;
    }
    return 0;
}

/* One of render's test hooks and counters: 1, 0 or -1. */
static int render_take_hooks(struct render_opts *o, const struct cli *c, int code)
{
    long n;
    switch (code) {
    case RENDER_OPT_COUNT_INSNS: o->count_insns = 1; return 1;
    case RENDER_OPT_INSN_PROFILE: o->board.insn_profile_out = c->arg; return 1;
    case RENDER_OPT_INSN_PROFILE_CORE:
        if (cli_long(c, 10, 0, UNITS_MAX_CORES - 1, &n) < 0)
            return -1;
        o->board.insn_profile_core = (int)n;
        return 1;
    case RENDER_OPT_TRACE:
        o->trace = c->arg;
        o->args.flags |= LINK_RENDER_TRACE;
        return 1;
    case RENDER_OPT_INJECT_FAULTS:
        if (render_faults_parse(c->arg, &o->inject, &o->inject_seed) != 0)
            return cli_bad_value(c, "K[:SEED], K at most LINK_INJECT_MAX (128)");
        return 1;
    case RENDER_OPT_INJECT_KIND:
        if (render_faults_kind_parse(c->arg, &o->inject_kind) != 0)
            return cli_bad_value(c, "undef, abort, hang, silent or mixed");
        return 1;
    case RENDER_OPT_INJECT_EVERY:
        if (cli_long(c, 10, 1, 1 << 20, &n) < 0)
            return -1;
        o->inject_every = (unsigned)n;
        return 1;
    case RENDER_OPT_INJECT_UNIT_FAULT: {
        char *end = NULL;
        int dm = strncmp(c->arg, "dm:", 3) == 0, rc = strncmp(c->arg, "rc:", 3) == 0;
        long f = (dm || rc) ? strtol(c->arg + 3, &end, 10) : -1;
        if ((!dm && !rc) || end == c->arg + 3 || *end || f < 0)
            return cli_bad_value(c, "dm:FRAME or rc:FRAME");
        o->unit_fault_core = dm ? UNITS_DM_CORE : UNITS_RC_CORE;
        o->unit_fault_frame = f;
        return 1;
    }
    }
    return 0;
}

/* One of render's own options (not a board or scene option, not a scene
 * or -o): 0, or -1 after saying what is wrong. */
static int render_take(struct render_opts *o, const struct cli *c, int code)
{
    int r = render_take_schedule(o, c, code);
    if (r == 0)
        r = render_take_frames(o, c, code);
    if (r == 0)
        r = render_take_hooks(o, c, code);
    if (r != 0)
        return r < 0 ? -1 : 0;
    switch (code) {
    case RENDER_OPT_FPU:
        if ((o->fpu = arith_auto_fpu(c->arg)) < 0)
            return cli_bad_value(c, "vfp or none");
        return 0;
    case RENDER_OPT_TARGET_DB: return cli_double(c, 0, 1, 99, NULL, &o->target_db);
    case RENDER_OPT_ESCALATE:
    case RENDER_OPT_NO_ESCALATE: {
        enum render_escalation e = code == RENDER_OPT_ESCALATE ? RENDER_ESC_ON : RENDER_ESC_OFF;
        if (o->escalation != RENDER_ESC_DEFAULT && o->escalation != e)
            return cli_usage_error("links1 render", "--escalate or --no-escalate, not both");
        o->escalation = e;
        return 0;
    }
    case RENDER_OPT_AUTO: o->model_auto = o->arith_auto = 1; return 0;
    }
    return -1; /* CLI_BAD: reported already */
}

/* An option, a scene or -o OUT, whoever's it is: 0, 1 (--help shown) or
 * -1 (a usage error, said). */
static int render_take_any(struct render_opts *o, const struct cli *c, int code)
{
    if (code == CLI_BAD)
        return -1;
    if (code == 'h') {
        render_usage(stdout);
        return 1;
    }
    if (code == BOARD_OPT_ARITH) { /* auto chooses the board's arithmetic */
        o->arith_named = 1;
        o->arith_auto |= strcmp(c->arg, "auto") == 0;
        if (o->arith_auto)
            return 0;
    }
    int r = board_opt(&o->board, c, code);
    if (r == 0)
        r = scene_opts_take(&o->scene, c, code);
    if (r > 0 && code == SCENE_OPT_CHECK_LOST)
        o->board.escalate = 1; /* the firmware that carries double, to check with */
    if (r != 0)
        return r < 0 ? -1 : 0;
    if (code == 'o' || code == CLI_OPERAND)
        return render_add_job(o, code, c->arg);
    return render_take(o, c, code);
}

/* Escalation settled: --escalate's; by default where a firmware that
 * escalates runs: the one this command picks for float and fixed (not
 * --firmware's, nor with --arith auto, which decides it itself), or a named
 * board's whose record says so (links1 board start boots it for float and
 * fixed); never by default with --paper (a scene's own paper mode clears
 * it: scene_paper_args). */
static void render_escalation_settle(struct render_opts *o, int named_wide)
{
    const char *a = o->board.arith;
    int wide = o->board_name ? named_wide
                             : (strcmp(a, "float") == 0 || strcmp(a, "fixed") == 0) &&
                                   !o->board.firmware && !o->arith_auto;
    if (o->escalation == RENDER_ESC_ON)
        o->gave |= SCENE_PAPER_GAVE_ESCALATE;
    if (o->escalation == RENDER_ESC_ON ||
        (o->escalation == RENDER_ESC_DEFAULT && wide && !o->scene.paper)) {
        o->args.flags |= LINK_RENDER_ESCALATE;
        o->board.escalate = 1;
    }
}

/* --escalate: the firmware that carries the wide arithmetic (float or
 * fixed; links1-A-esc.elf, an521/links1-A-esc.elf on the an521 boards,
 * whose M33s compute its double in software), unless a named board's or --firmware's
 * (whose DM refuses escalation when it carries none). */
static int render_escalate_check(const struct render_opts *o)
{
    if (!o->board.escalate)
        return 0;
    const char *a = o->board.arith;
    const char *why =
        o->arith_auto ? "an arithmetic given, float or fixed (not --arith auto, which escalates "
                        "by itself where that is the cheapest way to its target, or --auto)"
        : strcmp(a, "double") == 0 ? "--arith float or fixed: double is the wide arithmetic itself"
        : strcmp(a, "soft") == 0 ? "--arith float or fixed: the soft build models a unit without "
                                   "an FPU, which has no double to escalate to"
                                 : NULL;
    if (why)
        fprintf(stderr, "links1 render: --escalate and --check-lost need %s\n", why);
    return why ? -1 : 0;
}

/* --arith auto chooses the firmware for one scene of a board of its own. */
static int render_auto_check(const struct render_opts *o)
{
    if (!o->arith_auto) {
        if (o->fpu >= 0 || o->target_db >= 0) {
            fprintf(stderr,
                    "links1 render: --fpu and --target-db go with --arith auto (or --auto)\n");
            return -1;
        }
        return 0;
    }
    const char *chosen = o->arith_named ? "arith" : scene_opts_model_given(&o->scene);
    if (o->model_auto && chosen) {
        fprintf(stderr, "links1 render: --auto chooses the arithmetic, min_weight and density "
                "steps, so it takes no --%s (--arith auto chooses the arithmetic alone)\n", chosen);
        return -1;
    }
    const char *what = o->model_auto ? "--auto" : "--arith auto";
    const char *why = o->njobs > 1 ? "one SCENE (it chooses per scene)"
                      : o->board_name ? "a board of its own, not --board"
                      : o->board.firmware ? "no --firmware (it chooses the firmware)"
                      : NULL;
    if (why)
        fprintf(stderr, "links1 render: %s takes %s\n", what, why);
    return why ? -1 : 0;
}

/* --arith auto: the pre-render and the pick, into o->board.arith. */
static int render_auto_pick(struct render_opts *o)
{
    static struct arith_auto_choice pick;
    struct arith_auto_words w;
    arith_auto_scene_words(&o->scene, o->first, &w);
    struct arith_auto_opts ao = {
        .fpu = o->fpu < 0 ? 1 : o->fpu,
        .target_db = o->target_db < 0 ? ARITH_AUTO_TARGET_DB : o->target_db,
        .target = ARITH_AUTO_BOARD,
        .machine = o->board.machine,
        .width = o->scene.width,
        .height = o->scene.height,
        .words = w.words,
        .model = o->model_auto,
    };
    if (arith_auto_pick("links1 render", o->jobs[0].scene, &ao, &pick) != 0)
        return -1;
    o->board.arith = pick.arith;
    if (pick.escalate) { /* as --escalate: the firmware that carries double */
        o->args.flags |= LINK_RENDER_ESCALATE;
        o->board.escalate = 1;
    }
    /* --auto: the model picked (render_main compiles the scene again) */
    if (pick.density_steps >= 0)
        o->scene.density_steps = pick.density_steps;
    if (pick.min_weight >= 0)
        o->scene.min_weight = pick.min_weight;
    return 0;
}

/* -o OUT (with --frames A:B, its first frame's file) checked before the
 * board boots.  0, or -1 after saying why. */
static int render_out_check(const struct render_opts *o, const char *out)
{
    char path[PATH_MAX + 16], err[PATH_MAX + 256];
    if (o->many && film_kind_of(out) == FILM_NONE)
        scene_file_frame_path(out, o->first, path, sizeof path);
    else
        snprintf(path, sizeof path, "%s", out);
    if (out_file_check(path, err, sizeof err) == 0)
        return 0;
    fprintf(stderr, "links1 render: -o %s\n", err);
    return -1;
}

/* Returns 0, 1 (--help shown) or -1 (bad option, printed). */
/* Every job's -o OUT checked before the board boots, and a film's ffmpeg
 * there.  0, or -1 after saying why. */
static int render_outs_check(const struct render_opts *o)
{
    int films = 0;
    for (int j = 0; j < o->njobs; j++) {
        if (!o->jobs[j].out) {
            fprintf(stderr, "links1 render: %s has no -o OUT\n", o->jobs[j].scene);
            return -1;
        }
        if (render_out_check(o, o->jobs[j].out) != 0)
            return -1;
        films += film_kind_of(o->jobs[j].out) != FILM_NONE;
    }
    if (!films)
        return 0;
    char err[512];
    if (o->resume) {
        fprintf(stderr, "links1 render: --resume keeps numbered frames; a film (.mp4, "
                ".webm, .apng) is made whole in one run\n");
        return -1;
    }
    if (film_program_check(err, sizeof err) != 0) {
        fprintf(stderr, "links1 render: %s\n", err);
        return -1;
    }
    return 0;
}

/* The machine the scene is checked against: --machine's, or the named
 * board's; then escalation (render_escalation_settle).  0, or -1 after
 * saying why. */
static int render_machine_settle(struct render_opts *o)
{
    o->scene.machine = o->board.machine;
    int wide = 0;
    if (!o->board_name) {
        render_escalation_settle(o, 0);
        return 0;
    }
    int m = board_named_machine(o->board_name, &wide);
    if (m < 0)
        return -1;
    render_escalation_settle(o, wide);
    if (o->board.machine != MACHINE_VIRT && o->board.machine != m) {
        fprintf(stderr, "links1 render: --machine %s, but board %s is a %s board\n",
                machine_limits(o->board.machine)->name, o->board_name,
                machine_limits(m)->name);
        return -1;
    }
    o->board.machine = o->scene.machine = m;
    return 0;
}

static int render_parse(struct render_opts *o, int argc, char **argv)
{
    memset(o, 0, sizeof *o);
    board_opts_init(&o->board);
    o->board.ncores = RENDER_DEFAULT_NCS + 2;
    o->args.balance = LINK_BALANCE_DECREASING;
    o->last = -1;
    o->row_first = o->row_last = -1;
    o->unit_fault_core = -1;
    o->fpu = -1;
    o->target_db = -1;
    scene_file_opts_init(&o->scene);
    static const struct cli_optdef *const lists[] = {board_optdefs, scene_optdefs,
                                                     render_optdefs, NULL};
    struct option longs[RENDER_MAX_OPTIONS];
    if (cli_optdefs_table(lists, longs, RENDER_MAX_OPTIONS) != 0)
        return -1;
    struct cli c;
    cli_init(&c, "links1 render", argc, argv, "o:h", longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        int r = render_take_any(o, &c, code);
        if (r != 0)
            return r;
    }
    if (o->njobs == 0)
        return cli_usage_error("links1 render", "no SCENE given");
    if (o->board_name && (o->count_insns || o->board.insn_profile_out || o->board.view ||
                          o->board.link_noise_on)) {
        fprintf(stderr, "links1 render: --count-insns, --insn-profile, --view and --link-noise "
                "need a board of this command's own, not --board %s\n", o->board_name);
        return -1;
    }
    if (render_outs_check(o) != 0 || render_auto_check(o) != 0 ||
        render_machine_settle(o) != 0 || render_escalate_check(o) != 0)
        return -1;
    if (o->resume && !o->many) {
        fprintf(stderr, "links1 render: --resume goes with --frames A:B\n");
        return -1;
    }
    unsigned ncs = (unsigned)o->board.ncores - UNITS_FIRST_NC;
    if (o->inject >= ncs && o->inject) {
        fprintf(stderr, "links1 render: --inject-faults %u: at most %u of the %u NCs may fail "
                "(one must be left)\n", o->inject, ncs - 1, ncs);
        return -1;
    }
    if (o->trace && (o->njobs > 1 || o->many)) {
        fprintf(stderr, "links1 render: --trace records one frame of one scene: give one SCENE "
                "and no --frames\n");
        return -1;
    }
    if (o->board.insn_profile_core >= 0 &&
        (!o->board.insn_profile_out || o->board.insn_profile_core >= o->board.ncores)) {
        fprintf(stderr, "links1 render: --insn-profile-core %d goes with --insn-profile, and the "
                "board has cores 0..%d\n", o->board.insn_profile_core, o->board.ncores - 1);
        return -1;
    }
    if (o->row_first >= 0 && o->bands) {
        fprintf(stderr, "links1 render: --rows or --band, not both\n");
        return -1;
    }
    if (o->trace && (o->row_first >= 0 || o->bands)) {
        fprintf(stderr, "links1 render: --trace records a whole frame (the replay hands out the "
                "whole screen); --rows renders a band of it\n");
        return -1;
    }
    return 0;
}

/* Every scene's compiled bytes, before the board boots.  0, or -1 after
 * printing why a scene cannot be read or compiled. */
static void render_free_scenes(struct render_opts *o)
{
    for (int j = 0; j < o->njobs; j++) {
        free(o->jobs[j].bytes);
        o->jobs[j].bytes = NULL;
    }
}

/* The frames and the band asked for, against a scene of frames frames
 * (at least 1) of height scanlines (at least 1).  0, or -1 after saying
 * why. */
static int render_fits(const struct render_opts *o, const char *scene, uint32_t frames,
                       uint32_t height)
{
    long last = o->last < 0 ? o->first : o->last;
    if ((uint64_t)last >= frames) {
        fprintf(stderr, "links1 render: %s: frame %ld, the scene has %u frames (0..%u)\n",
                scene, last, frames, frames - 1);
        return -1;
    }
    if (o->bands && (uint64_t)o->bands > height) {
        fprintf(stderr, "links1 render: %s: --band %ld/%ld: %ld bands of a frame of %u "
                "scanlines (at most one band a scanline)\n", scene, o->band, o->bands,
                o->bands, height);
        return -1;
    }
    if (o->row_first >= 0 && (uint64_t)o->row_last >= height) {
        fprintf(stderr, "links1 render: %s: --rows %ld:%ld, the frame has %u scanlines "
                "(0..%u)\n", scene, o->row_first, o->row_last, height, height - 1);
        return -1;
    }
    return 0;
}

/* render_fits against the compiled scene's own header, before a board
 * boots.  A compiled file whose view cannot be read is left to the board's
 * loader, which names what is wrong with it (and the next scene still
 * renders). */
static int render_check_job(const struct render_opts *o, struct render_job *j)
{
    struct scene_paper v;
    char why[SD_ERR_MAX];
    j->frames = j->height = 0;
    if (scene_paper_read(j->bytes, j->len, &v, why, sizeof why) != 0 || v.frames == 0 ||
        v.height <= 0)
        return 0;
    j->frames = v.frames;
    j->height = (uint32_t)v.height;
    return render_fits(o, j->scene, j->frames, j->height);
}

static int render_read_scenes(struct render_opts *o)
{
    for (int j = 0; j < o->njobs; j++) {
        char err[SD_ERR_MAX];
        struct render_job *job = &o->jobs[j];
        if (scene_file_bytes_info(job->scene, &o->scene, &job->bytes, &job->len, &job->info,
                                  err, sizeof err) != 0) {
            fprintf(stderr, "links1 render: %s\n", err);
            return -1;
        }
        if (render_check_job(o, job) != 0)
            return -1;
    }
    return 0;
}

/* "decreasing, K 32768, factor 2, asking ahead, clipping auto": the
 * schedule the RC ran and how the NCs were told to clip. */
static void render_schedule_name(const struct link_render_args *a, uint32_t ncs, char *out,
                                 size_t cap)
{
    static const char *const clips[LINK_CLIP_MODES] = {"auto", "lists", "tree"};
    char ask[64];
    snprintf(ask, sizeof ask, "%s, clipping %s",
             a->flags & LINK_RENDER_ASK_WHEN_DONE ? "asking when finished" : "asking ahead",
             a->clip < LINK_CLIP_MODES ? clips[a->clip] : "?");
    enum areas_mode m = (enum areas_mode)a->balance;
    uint32_t k, factor;
    areas_settings(m, ncs, a->areas, a->guided, &k, &factor);
    if (m == AREAS_DECREASING) {
        snprintf(out, cap, "%s, K %u, factor %u, %s", areas_mode_name(m), (unsigned)k,
                 (unsigned)factor, ask);
    } else if (m == AREAS_DYNAMIC || m == AREAS_LINES) {
        snprintf(out, cap, "%s, K %u, %s", areas_mode_name(m), (unsigned)k, ask);
    } else {
        snprintf(out, cap, "%s, %s", areas_mode_name(m), ask);
    }
}

static void render_summary(const char *path, const struct link_render_stats *s,
                           const struct image *img, const struct link_render_args *a,
                           double seconds, long long upload_ms, long long pull_ms)
{
    char sched[160];
    render_schedule_name(a, s->ncs, sched, sizeof sched);
    printf("links1 render: frame %u %dx%d -> %s: %u NCs, %u areas (%s), %.1f s "
           "(board: prepare %u ms, render %u ms; upload %lld ms, pull %lld ms); rays %llu primary, %llu shadow, "
           "%llu reflection, %llu refraction, %llu transmission; tests %llu box, %llu primitive "
           "(%llu by primary rays); %u pixels in doubt; memory high-water DM %u, RC %u, NC %u of %u bytes\n",
           s->frame, img->width, img->height, path, s->ncs, s->areas, sched, seconds, s->prepare_ms, s->render_ms,
           upload_ms, pull_ms,
           (unsigned long long)s->primary, (unsigned long long)s->shadow,
           (unsigned long long)s->reflection, (unsigned long long)s->refraction,
           (unsigned long long)s->transmission, (unsigned long long)s->box_tests,
           (unsigned long long)s->prim_tests, (unsigned long long)s->primary_prim_tests,
           s->precision_lost_pixels, s->dm_high,
           s->rc_high, s->nc_high_max, s->nc_private);
    fflush(stdout);
}

/* The fault plan of frame f into plan (the test hooks): the NCs' on the
 * first frame rendered (and every --inject-every frames), the DM's or RC's
 * on its frame.  Returns its bytes
 * (0: none). */
static uint32_t render_frame_plan(const struct render_opts *o, struct render_run *run, long f,
                                  uint8_t plan[LINK_INJECT_SIZE(LINK_INJECT_MAX + 1)])
{
    uint32_t n = 0;
    long k = run->frames_done++;
    if (o->inject && (o->inject_every ? k % o->inject_every == 0 : k == 0)) {
        unsigned ncs = (unsigned)o->board.ncores - UNITS_FIRST_NC;
        render_faults_plan(o->inject, o->inject_seed + (unsigned)k, o->inject_kind, ncs,
                           run->inject_taken, plan);
        render_faults_print_plan(stdout, plan);
        n = plan[0];
    }
    if (o->unit_fault_core >= 0 && f == o->unit_fault_frame) {
        struct link_inject e = {(uint16_t)o->unit_fault_core, LINK_INJECT_UNDEF, 0, 1};
        link_inject_put(plan + LINK_INJECT_SIZE(n), &e);
        n++;
        render_say(o, "links1 render: fault plan: the %s faults during frame %ld\n",
               unit_role_name(unit_role_of_core((uint32_t)o->unit_fault_core)), f);
    }
    plan[0] = (uint8_t)n;
    plan[1] = 0;
    return n ? LINK_INJECT_SIZE(n) : 0;
}

/* QEMU's user + system CPU time so far, ms (/proc/PID/stat), or -1. */
static long long render_qemu_cpu_ms(pid_t pid)
{
    char path[64], buf[1024];
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    const char *p = strrchr(buf, ')'); /* the command name may hold spaces */
    unsigned long long ut = 0, st = 0;
    if (!p || sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu", &ut,
                     &st) != 2)
        return -1;
    long hz = sysconf(_SC_CLK_TCK);
    return hz > 0 ? (long long)((ut + st) * 1000ull / (unsigned long long)hz) : -1;
}

/* Each QEMU's CPU time now (ms; -1 where unreadable): board 0's (the virt
 * board's) in cpu[0], the an521 NC boards' in cpu[k]. */
static void render_board_cpu(const struct board *b, long long cpu[AN521_MAX_BOARDS])
{
    cpu[0] = render_qemu_cpu_ms(b->qemu_pid);
    for (int k = 1; k < AN521_MAX_BOARDS; k++)
        cpu[k] = b->nc_board_pid[k] ? render_qemu_cpu_ms(b->nc_board_pid[k]) : -1;
}

/* The CPU time the board's QEMUs took between two readings (those read
 * both times: a board whose process ended in between is left out). */
static long long render_board_cpu_spent(const long long c0[AN521_MAX_BOARDS],
                                        const long long c1[AN521_MAX_BOARDS])
{
    long long sum = 0;
    for (int k = 0; k < AN521_MAX_BOARDS; k++)
        if (c0[k] >= 0 && c1[k] >= c0[k])
            sum += c1[k] - c0[k];
    return sum;
}

/* One scene on the running board: upload, every frame asked for. */
/* The scene j uploaded and loaded, what the board says of it checked.
 * 0, or -1 after saying why. */
static int render_job_load(struct board *b, const struct render_opts *o, struct render_run *run,
                           const struct render_job *j, struct link_scene_info *info,
                           long long *upload_ms)
{
    long long load_ms = 0;
    int rc = render_session_load(b, j->bytes, j->len, info, upload_ms, &load_ms);
    run->wall.upload += *upload_ms;
    run->wall.load += load_ms;
    if (rc != 0) {
        fprintf(stderr, "links1 render: %s was not loaded\n", j->scene);
        return -1;
    }
    render_say(o, "links1 render: %s loaded: %ux%u, %u frame(s), %u bytes compiled, a prepared "
               "frame needs at most %u of the DM's %u-byte IMSU block; the DM's check %u ms, "
               "load %u ms (the index included), frame 0's preparation %u ms\n", j->scene,
               info->width, info->height, info->frames, info->compiled_bytes, info->blob_bytes,
               info->blob_limit, info->check_ms, info->load_ms, info->prepare_ms);
    if (!run->prims)
        run->prims = info->prims;
    if (j->frames && (info->frames != j->frames || info->height != j->height)) {
        /* render_check_job checked what the compiled header says */
        fprintf(stderr, "links1 render: %s: the board loaded %u frames of %u scanlines, the "
                "compiled scene says %u of %u\n", j->scene, info->frames, info->height,
                j->frames, j->height);
        return -1;
    }
    /* what the board says, range-checked before use (the header's, when it
     * could be read before the boot) */
    if (info->frames == 0 || info->height == 0) {
        fprintf(stderr, "links1 render: %s: the board loaded %u frames of %u scanlines\n",
                j->scene, info->frames, info->height);
        return -1;
    }
    return render_fits(o, j->scene, info->frames, info->height);
}

/* The frame's render arguments for job j: the band's scanlines and what
 * paper mode sets.  0, or -1 after saying why. */
static int render_job_args(const struct render_opts *o, struct render_run *run,
                           const struct render_job *j, const struct link_scene_info *info,
                           struct link_render_args *job_args)
{
    *job_args = o->args;
    if (o->bands) { /* band I of N: its scanlines (render_check_job: N <= height) */
        job_args->row0 = (uint16_t)((uint64_t)info->height * (uint64_t)o->band /
                                    (uint64_t)o->bands);
        job_args->rows = (uint16_t)((uint64_t)info->height * (uint64_t)(o->band + 1) /
                                    (uint64_t)o->bands - job_args->row0);
    }
    if (o->row_first >= 0) { /* a band (render_check_job: within the height) */
        job_args->row0 = (uint16_t)o->row_first;
        job_args->rows = (uint16_t)(o->row_last - o->row_first + 1);
    }
    struct scene_paper paper;
    char why[SD_ERR_MAX];
    if (scene_paper_read(j->bytes, j->len, &paper, why, sizeof why) != 0) {
        fprintf(stderr, "links1 render: %s: %s\n", j->scene, why);
        return -1;
    }
    if (paper.paper) {
        char line[512];
        scene_paper_args(&paper, o->gave, job_args);
        scene_paper_line(&paper, job_args, j->info.auto_hierarchy, j->info.own_clusters, line,
                         sizeof line);
        render_say(o, "links1 render: %s: %s\n", j->scene, line);
    }
    run->traced_args = *job_args;
    return 0;
}

/* One frame of a job: its arguments, number, the job's last frame, and
 * the scene's upload time (told with its first frame). */
struct render_frame_run {
    const struct link_render_args *args;
    long frame, last;
    long long upload_ms;
};

/* Where a job's frames go: numbered (or one) image files, or one film. */
struct render_sink {
    const char *out;
    int filming, ppm;
    struct film film;
};

/* A film started for OUT (frames width x height), or image files.  0, or
 * -1 after saying why. */
static int render_sink_open(const struct render_opts *o, const struct render_job *j,
                            uint32_t width, uint32_t height, struct render_sink *k)
{
    memset(k, 0, sizeof *k);
    k->out = j->out;
    k->ppm = o->ppm || scene_file_ends_with(j->out, ".ppm");
    k->filming = film_kind_of(j->out) != FILM_NONE;
    if (!k->filming)
        return 0;
    char err[512];
    if (film_open(&k->film, j->out, (int)width, (int)height, o->fps ? o->fps : FILM_DEFAULT_FPS,
                  err, sizeof err) != 0) {
        fprintf(stderr, "links1 render: %s\n", err);
        return -1;
    }
    if (film_padded(k->film.kind, (int)width, (int)height))
        render_say(o, "links1 render: %s: %ux%u padded to %ux%u (the film's yuv420p needs even "
                   "sides)\n", j->out, width, height, (width + 1) & ~1u, (height + 1) & ~1u);
    return 0;
}

/* Frame f's image into the sink: written whole or not at all
 * (image_save.h), so a run that dies leaves no half frame for --resume.
 * 0, or -1 after saying why. */
static int render_sink_put(struct render_sink *k, const char *path, const struct image *img)
{
    char err[SD_ERR_MAX];
    int rc = k->filming ? film_frame(&k->film, img, err, sizeof err)
                        : image_save(path, img, k->ppm, err, sizeof err);
    if (rc != 0)
        fprintf(stderr, "links1 render: %s\n", err);
    return rc;
}

/* Frame f rendered, pulled and put into the sink.  0, or -1 after saying why. */
static int render_one_frame(struct board *b, const struct render_opts *o, struct render_run *run,
                            const struct link_scene_info *info, const struct render_frame_run *r,
                            struct render_sink *k, const char *path)
{
    struct link_render_args a = *r->args;
    a.frame = (uint32_t)r->frame;
    if (r->frame < r->last)
        a.flags |= LINK_RENDER_PREPARE_NEXT;
    long long t0 = board_now_ms(), pull_ms = 0;
    long long cpu0[AN521_MAX_BOARDS], cpu1[AN521_MAX_BOARDS];
    render_board_cpu(b, cpu0);
    struct link_render_stats s;
    struct link_render_fails fails;
    struct image img = {0, 0, NULL};
    uint8_t plan[LINK_INJECT_SIZE(LINK_INJECT_MAX + 1)];
    uint32_t plan_len = render_frame_plan(o, run, r->frame, plan);
    if (render_session_frame(b, &a, isatty(2), plan, plan_len, &s, &fails) != 0)
        return -1;
    long long t1 = board_now_ms();
    render_board_cpu(b, cpu1);
    run->wall.frame += t1 - t0;
    run->wall.board_prepare += s.prepare_ms;
    run->wall.board_render += s.render_ms;
    run->wall.render_cpu += render_board_cpu_spent(cpu0, cpu1);
    if (render_session_pull(b, (int)info->width, (int)info->height, &img, &pull_ms) != 0)
        return -1;
    if (a.rows) { /* the band's scanlines only */
        memmove(img.rgb, img.rgb + (size_t)a.row0 * (size_t)img.width * 3,
                (size_t)a.rows * (size_t)img.width * 3);
        img.height = a.rows;
    }
    long long t2 = board_now_ms();
    run->wall.pull += t2 - t1;
    render_faults_print(stdout, a.frame, &fails);
    int rc = render_sink_put(k, path, &img);
    run->wall.write += board_now_ms() - t2;
    /* The scene's upload time is told with its first frame. */
    if (rc == 0 && !o->board.quiet && (a.flags & ~s.flags & LINK_RENDER_ESCALATE))
        fprintf(stderr, "links1 render: frame %u: escalation off: the scene's double copy does "
                "not fit beside it in the DM's %u-byte IMSU block; its pixels in doubt stay "
                "as traced, as with --no-escalate\n", s.frame, (unsigned)info->blob_limit);
    if (rc == 0 && o->board.verbose && (s.flags & LINK_RENDER_ESCALATE))
        printf("links1 render: frame %u: %u pixels escalated to double\n", s.frame,
               s.escalated_pixels);
    if (rc == 0 && !o->board.quiet)
        render_summary(path, &s, &img, &a, (double)(board_now_ms() - t0) / 1000.0, r->upload_ms, pull_ms);
    if (rc == 0 && o->scene.spd_rules)
        /* preprocessing: the upload with the DM's load (told with the
         * first frame) and the DM's preparation; tracing: the RC's render */
        scene_opts_spd_line(s.primary_hit, s.reflection, s.refraction, s.shadow,
                            (double)(r->upload_ms + (long long)s.prepare_ms) / 1000.0,
                            (double)s.render_ms / 1000.0);
    run->traced_w = (uint32_t)img.width;
    run->traced_h = (uint32_t)img.height;
    run->traced_bytes = s.blob_bytes;
    image_free(&img);
    return rc;
}

static int render_job(struct board *b, const struct render_opts *o, struct render_run *run,
                      const struct render_job *j)
{
    struct link_scene_info info;
    long long upload_ms = 0;
    struct link_render_args job_args;
    if (render_job_load(b, o, run, j, &info, &upload_ms) != 0 ||
        render_job_args(o, run, j, &info, &job_args) != 0)
        return -1;
    long first = o->first, last = o->last < 0 ? o->first : o->last;
    struct render_sink k;
    if (render_sink_open(o, j, info.width, job_args.rows ? job_args.rows : info.height, &k) != 0)
        return -1;
    for (long f = first; f <= last; f++) {
        char path[4096];
        if (k.filming)
            snprintf(path, sizeof path, "%s (frame %ld of the film)", j->out, f);
        else if (o->many)
            scene_file_frame_path(j->out, f, path, sizeof path);
        else
            snprintf(path, sizeof path, "%s", j->out);
        if (o->resume && !k.filming && access(path, F_OK) == 0) {
            render_say(o, "links1 render: frame %ld: %s is there already (--resume): kept\n", f,
                       path);
            continue;
        }
        struct render_frame_run r = {&job_args, f, last, f == first ? upload_ms : 0};
        if (render_one_frame(b, o, run, &info, &r, &k, path) != 0) {
            film_abort(&k.film);
            return -1;
        }
    }
    if (!k.filming)
        return 0;
    char err[512];
    long frames = k.film.frames;
    if (film_close(&k.film, err, sizeof err) != 0) {
        fprintf(stderr, "links1 render: %s\n", err);
        return -1;
    }
    render_say(o, "links1 render: %s: a film of %ld frame(s) at %d a second (ffmpeg)\n", j->out,
               frames, o->fps ? o->fps : FILM_DEFAULT_FPS);
    return 0;
}

/* One line accounting for the command's wall time (bench_wallclock.sh). */
static void render_print_wall(const struct render_wall *w)
{
    long long other = w->total - w->compile - w->boot - w->upload - w->load - w->frame - w->pull -
                      w->write - w->shutdown;
    /* load: the DM checks the scene, loads it and prepares its first frame
     * before it answers; the board's prepare counts every frame's
     * preparation, the first one's inside load, each later one's inside
     * the frame before (pipelined) or its own. */
    printf("links1 render: wall %lld ms: compile %lld, boot %lld, upload %lld, load %lld, frames "
           "%lld (board: prepare %lld, render %lld), pull %lld, write %lld, shutdown %lld, other "
           "%lld; QEMU CPU while rendering %lld ms (%.2f host cores)\n",
           w->total, w->compile, w->boot, w->upload, w->load, w->frame, w->board_prepare,
           w->board_render, w->pull, w->write, w->shutdown, other, w->render_cpu,
           w->frame > 0 ? (double)w->render_cpu / (double)w->frame : 0.0);
}

/* The trace of the one frame rendered, from the plugin's marks. */
static int render_write_trace(const struct render_opts *o, const struct render_run *run,
                              const char *marks_path)
{
    struct trace t;
    char err[TRACE_ERR_MAX];
    uint32_t ncs = (uint32_t)o->board.ncores - 2;
    if (trace_decode_marks(marks_path, run->traced_w, run->traced_h, ncs, &t, err, sizeof err) != 0) {
        fprintf(stderr, "links1 render: --trace %s: %s\n", o->trace, err);
        return -1;
    }
    t.balance = run->traced_args.balance;
    t.k = run->traced_args.areas;
    t.guided = run->traced_args.guided;
    t.flags = run->traced_args.flags & ~(uint32_t)LINK_RENDER_TRACE;
    t.broadcast_bytes = run->traced_bytes;
    struct out_file of;
    int rc = out_file_open(&of, o->trace, err, sizeof err);
    if (rc == 0 && trace_write(of.f, o->trace, &t, err, sizeof err) != 0) {
        out_file_abort(&of);
        rc = -1;
    } else if (rc == 0) {
        rc = out_file_commit(&of, err, sizeof err);
    }
    if (rc != 0)
        fprintf(stderr, "links1 render: --trace: %s\n", err);
    else
        render_say(o, "links1 render: trace of %u areas written to %s\n", (unsigned)t.nareas, o->trace);
    trace_free(&t);
    return rc;
}

/* What the counting plugin writes for --count-insns, --trace and
 * --insn-profile: files in one private directory made for the run
 * (tmp_dir_make: mode 0700, a name no one can predict), counts, marks and
 * profile, each an521 NC board's beside them (.bK); the plugin makes each
 * new (O_EXCL | O_NOFOLLOW). */
struct render_counting {
    char dir[PATH_MAX];
    char counts[PATH_MAX + 16], marks[PATH_MAX + 16], profile[PATH_MAX + 16];
    const char *profile_out; /* --insn-profile FILE: the profile copied there */
};

/* The directory made and the board options pointed into it (nothing made
 * when nothing counts).  0, or -1 after saying why. */
static int render_counting_open(struct render_opts *o, struct render_counting *k)
{
    memset(k, 0, sizeof *k);
    k->profile_out = o->board.insn_profile_out;
    if (!o->trace && !o->count_insns && !k->profile_out)
        return 0;
    if (tmp_dir_make("insns", k->dir, sizeof k->dir) != 0) {
        fprintf(stderr, "links1 render: a private directory for the instruction counts: %s\n",
                strerror(errno));
        k->dir[0] = 0;
        return -1;
    }
    snprintf(k->counts, sizeof k->counts, "%s/counts", k->dir);
    snprintf(k->marks, sizeof k->marks, "%s/marks", k->dir);
    snprintf(k->profile, sizeof k->profile, "%s/profile", k->dir);
    o->board.insn_count_out = o->count_insns ? k->counts : NULL;
    /* the marks for --count-insns too: the DM's spans (render_dm_spans) */
    o->board.insn_trace_out = o->trace || o->count_insns ? k->marks : NULL;
    o->board.insn_profile_out = k->profile_out ? k->profile : NULL;
    return 0;
}

/* The DM's first spans (docs/trace.md): the upload's check (on the serial
 * path the upload itself, its frames checked), the load and frame 0's
 * preparation, printed with their sum a primitive of prims.  0, or -1
 * after saying why. */
static int render_dm_spans(const char *marks, uint32_t prims)
{
    uint64_t span[3];
    size_t n = 0;
    char err[PATH_MAX + 128];
    if (trace_dm_spans(marks, span, 3, &n, err, sizeof err) != 0) {
        fprintf(stderr, "links1 render: the DM's spans: %s\n", err);
        return -1;
    }
    if (n < 3)
        return 0; /* no scene loaded */
    uint64_t check = span[0], load = span[1], prep = span[2];
    uint64_t all = check + load + prep;
    double per = prims ? (double)all / prims : 0;
    printf("  DM's scene load: check %" PRIu64 ", load and index %" PRIu64 ", frame 0's "
           "preparation %" PRIu64 "; %" PRIu64 " in all, %.0f a primitive (%" PRIu32 ")\n",
           check, load, prep, all, per, prims);
    return 0;
}

/* The counting's private directory removed, nothing read from it (the
 * run ended before its board reported in). */
static void render_counting_drop(struct render_counting *k)
{
    if (k->dir[0] && tmp_dir_remove(k->dir) != 0)
        fprintf(stderr, "links1 render: could not remove %s: %s\n", k->dir, strerror(errno));
}

/* The counts printed, the trace and the profile written (rc: the run's
 * status so far), the directory removed.  0, or -1 after saying why. */
static int render_counting_close(struct render_opts *o, const struct render_run *run,
                                 struct render_counting *k, int rc)
{
    if (!k->dir[0])
        return 0;
    int r = 0;
    if (o->count_insns && (insn_report_print(k->counts, o->board.ncores) < 0 ||
                           render_dm_spans(k->marks, run->prims) < 0))
        r = -1;
    if (o->trace && rc == 0 && render_write_trace(o, run, k->marks) != 0)
        r = -1;
    char err[PATH_MAX + 256];
    if (k->profile_out && out_file_copy(k->profile, k->profile_out, err, sizeof err) != 0) {
        fprintf(stderr, "links1 render: --insn-profile: %s\n", err);
        r = -1;
    }
    o->board.insn_profile_out = k->profile_out;
    if (tmp_dir_remove(k->dir) != 0)
        fprintf(stderr, "links1 render: could not remove %s: %s\n", k->dir, strerror(errno));
    return r;
}

int cmd_render_check_args(int n, const char *const *args)
{
    static const int farms[] = {'o', RENDER_OPT_FRAME, RENDER_OPT_FRAMES, RENDER_OPT_BAND,
                                RENDER_OPT_ROWS};
    char **argv = calloc((size_t)n + 2, sizeof *argv);
    if (!argv)
        return -1;
    argv[0] = "render";
    for (int i = 0; i < n; i++)
        argv[i + 1] = (char *)args[i];
    static const struct cli_optdef *const lists[] = {board_optdefs, scene_optdefs,
                                                     render_optdefs, NULL};
    struct option longs[RENDER_MAX_OPTIONS];
    struct render_opts o;
    memset(&o, 0, sizeof o);
    board_opts_init(&o.board);
    scene_file_opts_init(&o.scene);
    struct cli c;
    int rc = cli_optdefs_table(lists, longs, RENDER_MAX_OPTIONS);
    cli_init(&c, "links1 farm", n + 1, argv, "o:h", longs);
    for (int code; rc == 0 && (code = cli_next(&c)) != -1;) {
        for (size_t i = 0; i < sizeof farms / sizeof farms[0]; i++)
            if (code == farms[i])
                rc = cli_usage_error("links1 farm", "render argument %s: the farm sets it",
                                     c.name);
        if (rc == 0 && (code == CLI_OPERAND || code == 'h'))
            rc = cli_usage_error("links1 farm", "render argument '%s': the farm names the "
                                 "scene and its output itself", argv[optind - 1]);
        if (rc == 0)
            rc = render_take_any(&o, &c, code) < 0 ? -1 : 0;
    }
    free(argv);
    return rc;
}

/* Whether the board boots while the scenes compile (a large model's
 * compile takes as long as a board's boot): not with --arith auto or
 * --model auto (the compiled scene picks the firmware), --gdb (a board
 * halted for a debugger) or on a named board (none boots). */
static int render_boots_early(const struct render_opts *o)
{
    return !o->board_name && !o->arith_auto && !o->model_auto && !o->board.gdb;
}

/* Every scene compiled and checked, --arith auto's and --model auto's
 * picks made.  0, or -1 after saying why. */
static int render_take_scenes(struct render_opts *o)
{
    if (render_read_scenes(o) == 0 && (!o->arith_auto || render_auto_pick(o) == 0) &&
        (!o->model_auto || (render_free_scenes(o), render_read_scenes(o) == 0)))
        return 0;
    render_free_scenes(o);
    return -1;
}

/* The board up, every unit computer reported in: the one started beside
 * the compile (started: board_start_unannounced's result), else one
 * started, or the named board reached, now.  0, or -1 after saying why. */
static int render_board_up(struct board *b, struct render_opts *o, int early, int started)
{
    if (o->board_name)
        return board_connect(b, &o->board, o->board_name);
    if (!early)
        started = board_start_unannounced(b, &o->board);
    if (started != 0)
        return -1;
    board_say_booting(b);
    return board_wait_reported(b, o->board.timeout_s * 1000);
}

int cmd_render(int argc, char **argv)
{
    struct render_opts o;
    int r = render_parse(&o, argc, argv);
    if (r != 0)
        return r > 0 ? 0 : 2;
    struct render_counting k;
    if (render_counting_open(&o, &k) != 0)
        return 1;
    struct board b;
    struct render_run run;
    memset(&run, 0, sizeof run);
    long long t_start = board_now_ms();
    int early = render_boots_early(&o);
    int started = early ? board_start_unannounced(&b, &o.board) : 0;
    if (render_take_scenes(&o) != 0) { /* refused before the board reported in */
        if (early)
            board_abandon(&b);
        render_counting_drop(&k);
        return 1;
    }
    run.wall.compile = board_now_ms() - t_start;
    int rc = 1;
    if (render_board_up(&b, &o, early, started) == 0) {
        run.wall.boot = board_now_ms() - t_start - run.wall.compile;
        rc = 0;
        for (int j = 0; j < o.njobs; j++) {
            if (render_job(&b, &o, &run, &o.jobs[j]) == 0)
                continue;
            rc = 1;
            if (render_faults_unit_down(b.faults, b.nfaults < BOARD_MAX_FAULTS
                                                      ? b.nfaults : BOARD_MAX_FAULTS) >= 0)
                break; /* no scene renders on a board without its DM or RC */
        }
    }
    long long t_stop = board_now_ms();
    if (board_stop(&b) < 0)
        rc = 1;
    run.wall.shutdown = board_now_ms() - t_stop;
    run.wall.total = board_now_ms() - t_start;
    if (rc == 0)
        if (!o.board.quiet)
            render_print_wall(&run.wall);
    /* Damage the retransmission repaired fails the run only on a link
     * without --link-noise, where there should be none. */
    if (board_report_link_errors(&b) && (!o.board.link_noise_on || board_arq_failed(&b)))
        rc = 1;
    /* An NC that faulted is left out and its areas drawn by others (the
     * frames above say so); a DM or RC fault ends the run. */
    int unit_faults = 0;
    for (int i = 0; i < b.nfaults && i < BOARD_MAX_FAULTS; i++)
        unit_faults += b.faults[i].role != ROLE_NC;
    if (b.nfaults > BOARD_MAX_FAULTS || unit_faults) {
        int down = render_faults_unit_down(b.faults, b.nfaults < BOARD_MAX_FAULTS
                                                         ? b.nfaults : BOARD_MAX_FAULTS);
        fprintf(stderr, "links1 render: %d unit computer(s) faulted, %d of them DM or RC", b.nfaults,
                unit_faults);
        if (down >= 0)
            fprintf(stderr, ": the %s (core %u) failed, the board could not go on; the frames "
                    "written are whole, and --resume renders the rest on a new board",
                    unit_role_name(b.faults[down].role), b.faults[down].core);
        fprintf(stderr, "\n");
        rc = 1;
    } else if (b.nfaults) {
        printf("links1 render: %d NC(s) faulted; the frames were finished without them\n",
               b.nfaults);
    }
    if (render_counting_close(&o, &run, &k, rc) != 0)
        rc = 1;
    render_free_scenes(&o);
    return rc;
}
