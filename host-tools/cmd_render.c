/* cmd_render.c: `links1 render`: the whole LINKS-1 image generation system
 * driven from the host.  Compiles each scene in-process, boots a board of
 * DM + RC + N NCs, uploads the scene, renders the frames (progress on the
 * terminal), pulls each frame and writes it as PNG or PPM, prints a
 * one-line summary per frame.  Several SCENE -o OUT pairs render one after
 * another on the same board; a scene the board refuses is reported and the
 * next one still renders (the exit status is then 1). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/board.h"
#include "host-tools/insn_report.h"
#include "host-tools/links1_cmds.h"
#include "host-tools/render_session.h"
#include "host-tools/scene/image_io.h"
#include "host-tools/scene/cli_args.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_file.h"
#include "proto/areas.h"

#define RENDER_MAX_JOBS 16 /* SCENE -o OUT pairs in one run */

struct render_job {
    const char *scene, *out;
    uint8_t *bytes; /* the compiled scene, read before the board boots */
    size_t len;
};

struct render_opts {
    struct board_opts board;
    struct render_job jobs[RENDER_MAX_JOBS];
    int njobs;
    struct link_render_args args;
    long first, last;   /* frames; last < 0: only frame first */
    int many;           /* --frames: one image per frame, numbered */
    struct scene_file_opts scene; /* --size, --max-depth, --refractionless */
    int ppm, count_insns;
};

static void render_usage(FILE *out)
{
    fprintf(out,
            "usage: links1 render SCENE(.scn|.l1s) -o OUT.png [SCENE2 -o OUT2 ...] [options]\n"
            "Renders on the emulated LINKS-1 (DM, RC and N NCs); several scenes render one\n"
            "after another on the same board.\n"
            "options:\n"
            "  --ncs N          node computers (1..254, default %d)\n"
            "  --arith A        float, soft or fixed (default float)\n"
            "  --balance M      static, dynamic or decreasing (default decreasing)\n"
            "  --areas K        areas of the dynamic grid, smallest-area bound of decreasing\n"
            "                   (default %d)\n"
            "  --frame N        render frame N (default 0)\n"
            "  --frames A:B     render frames A..B, writing OUT-000A.png ... (the DM prepares\n"
            "                   frame k+1 while frame k renders)\n"
            "  --size WxH       render at this size instead of the scene's (text scenes)\n"
            "  --max-depth D    --refractionless on|off\n"
"                   override the scene's recursion depth / transmission past it\n"
            "  --min-weight W   adaptive depth: rays whose weight (product of src and trc)\n"
            "                   falls below W are not traced (0..1; scenes default 1/512)\n"
            "  --mark-lost      paint pixels that lost precision magenta (text scenes)\n"
            "  --no-yclip --no-xclip --no-bbox --no-hierarchy\n"
            "                   switch a speed-up off (the image stays the same)\n"
            "  --no-auto-hierarchy  compile without the automatic hierarchy (text scenes)\n"
            "  --view           show the frame memory live (-device ramfb, a display)\n"
            "  --ppm            write PPM (also chosen by an OUT ending in .ppm)\n"
            "  --count-insns    count guest instructions per core and print them\n"
            "  --timeout S      seconds to wait for every unit computer to report in\n"
            "  --firmware ELF   firmware to boot; --ram MB; --quiet\n",
            RENDER_DEFAULT_NCS, AREAS_DEFAULT_K);
}

enum render_opt_code {
    RENDER_OPT_NCS = CLI_OWN_CODES,
    RENDER_OPT_BALANCE,
    RENDER_OPT_AREAS,
    RENDER_OPT_FRAME,
    RENDER_OPT_FRAMES,
    RENDER_OPT_SIZE,
    RENDER_OPT_MAX_DEPTH,
    RENDER_OPT_MIN_WEIGHT,
    RENDER_OPT_MARK_LOST,
    RENDER_OPT_REFRACTIONLESS,
    RENDER_OPT_NO_YCLIP,
    RENDER_OPT_NO_XCLIP,
    RENDER_OPT_NO_BBOX,
    RENDER_OPT_NO_HIERARCHY,
    RENDER_OPT_NO_AUTO_HIERARCHY,
    RENDER_OPT_VIEW,
    RENDER_OPT_PPM,
    RENDER_OPT_COUNT_INSNS,
};

static const struct option render_options[] = {
    BOARD_LONG_OPTIONS,
    {"ncs", required_argument, NULL, RENDER_OPT_NCS},
    {"balance", required_argument, NULL, RENDER_OPT_BALANCE},
    {"areas", required_argument, NULL, RENDER_OPT_AREAS},
    {"frame", required_argument, NULL, RENDER_OPT_FRAME},
    {"frames", required_argument, NULL, RENDER_OPT_FRAMES},
    {"size", required_argument, NULL, RENDER_OPT_SIZE},
    {"max-depth", required_argument, NULL, RENDER_OPT_MAX_DEPTH},
    {"min-weight", required_argument, NULL, RENDER_OPT_MIN_WEIGHT},
    {"mark-lost", no_argument, NULL, RENDER_OPT_MARK_LOST},
    {"refractionless", required_argument, NULL, RENDER_OPT_REFRACTIONLESS},
    {"no-yclip", no_argument, NULL, RENDER_OPT_NO_YCLIP},
    {"no-xclip", no_argument, NULL, RENDER_OPT_NO_XCLIP},
    {"no-bbox", no_argument, NULL, RENDER_OPT_NO_BBOX},
    {"no-hierarchy", no_argument, NULL, RENDER_OPT_NO_HIERARCHY},
    {"no-auto-hierarchy", no_argument, NULL, RENDER_OPT_NO_AUTO_HIERARCHY},
    {"view", no_argument, NULL, RENDER_OPT_VIEW},
    {"ppm", no_argument, NULL, RENDER_OPT_PPM},
    {"count-insns", no_argument, NULL, RENDER_OPT_COUNT_INSNS},
    {"help", no_argument, NULL, 'h'},
    {NULL, 0, NULL, 0},
};

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
    o->jobs[o->njobs++] = (struct render_job){arg, NULL, NULL, 0};
    return 0;
}

/* One option of render's own (not a board option, not a scene or -o). */
static int render_take(struct render_opts *o, const struct cli *c, int code)
{
    long n;
    enum areas_mode m;
    switch (code) {
    case BOARD_OPT_SMP:
        fprintf(stderr, "links1 render: --smp: give the node computers with --ncs N instead "
                "(the board has N + 2 cores)\n");
        return -1;
    case RENDER_OPT_NCS:
        if (cli_long(c, 10, 1, UNITS_MAX_CORES - 2, &n) < 0)
            return -1;
        o->board.ncores = (int)n + 2;
        return 0;
    case RENDER_OPT_BALANCE:
        if (areas_mode_parse(c->arg, &m) != AREAS_OK)
            return cli_bad_value(c, "static, dynamic or decreasing");
        o->args.balance = (uint8_t)m;
        return 0;
    case RENDER_OPT_AREAS:
        if (cli_long(c, 10, 1, 1 << 20, &n) < 0)
            return -1;
        o->args.areas = (uint32_t)n;
        return 0;
    case RENDER_OPT_FRAME:
    case RENDER_OPT_FRAMES:
        o->many = code == RENDER_OPT_FRAMES;
        if (cli_parse_frames(c->arg, &o->first, &o->last) != 0 ||
            (!o->many && o->first != o->last))
            return cli_bad_value(c, o->many ? "FIRST:LAST" : "a frame number");
        return 0;
    case RENDER_OPT_SIZE:
        if (cli_parse_size(c->arg, &o->scene.width, &o->scene.height) != 0)
            return cli_bad_value(c, cli_size_want());
        return 0;
    case RENDER_OPT_MAX_DEPTH:
        return cli_int(c, 0, SCN_MAX_DEPTH, &o->scene.max_depth);
    case RENDER_OPT_MIN_WEIGHT:
        return cli_double(c, 0, 0, 1, NULL, &o->scene.min_weight);
    case RENDER_OPT_MARK_LOST:
        o->scene.mark_lost = 1;
        return 0;
    case RENDER_OPT_REFRACTIONLESS:
        if (strcmp(c->arg, "on") != 0 && strcmp(c->arg, "off") != 0)
            return cli_bad_value(c, "on or off");
        o->scene.refractionless = strcmp(c->arg, "on") == 0;
        return 0;
    case RENDER_OPT_NO_YCLIP:
        o->args.flags |= LINK_RENDER_NO_YCLIP;
        return 0;
    case RENDER_OPT_NO_XCLIP:
        o->args.flags |= LINK_RENDER_NO_XCLIP;
        return 0;
    case RENDER_OPT_NO_BBOX:
        o->args.flags |= LINK_RENDER_NO_BBOX;
        return 0;
    case RENDER_OPT_NO_HIERARCHY:
        o->args.flags |= LINK_RENDER_NO_HIERARCHY;
        return 0;
    case RENDER_OPT_NO_AUTO_HIERARCHY:
        o->scene.no_auto_hierarchy = 1;
        return 0;
    case RENDER_OPT_VIEW:
        o->board.view = 1;
        return 0;
    case RENDER_OPT_PPM:
        o->ppm = 1;
        return 0;
    case RENDER_OPT_COUNT_INSNS:
        o->count_insns = 1;
        return 0;
    }
    return -1; /* CLI_BAD: reported already */
}

/* Returns 0, 1 (--help shown) or -1 (bad option, printed). */
static int render_parse(struct render_opts *o, int argc, char **argv)
{
    memset(o, 0, sizeof *o);
    board_opts_init(&o->board);
    o->board.ncores = RENDER_DEFAULT_NCS + 2;
    o->args.balance = LINK_BALANCE_DECREASING;
    o->last = -1;
    scene_file_opts_init(&o->scene);
    struct cli c;
    cli_init(&c, "links1 render", argc, argv, "o:h", render_options);
    for (int code; (code = cli_next(&c)) != -1;) {
        int r = code == BOARD_OPT_SMP ? 0 : board_opt(&o->board, &c, code);
        if (r == 0 && code == 'h') {
            render_usage(stdout);
            return 1;
        }
        if (r == 0)
            r = code == 'o' || code == CLI_OPERAND ? render_add_job(o, code, c.arg)
                                                   : render_take(o, &c, code);
        if (r < 0) {
            if (code == CLI_BAD)
                render_usage(stderr);
            return -1;
        }
    }
    if (o->njobs == 0) {
        render_usage(stderr);
        return -1;
    }
    for (int j = 0; j < o->njobs; j++) {
        if (!o->jobs[j].out) {
            fprintf(stderr, "links1 render: %s has no -o OUT\n", o->jobs[j].scene);
            return -1;
        }
    }
    return 0;
}

/* Every scene's compiled bytes, before the board boots.  0, or -1 after
 * printing why a scene cannot be read or compiled. */
static void render_free_scenes(struct render_opts *o)
{
    for (int j = 0; j < o->njobs; j++)
        free(o->jobs[j].bytes);
}

static int render_read_scenes(struct render_opts *o)
{
    for (int j = 0; j < o->njobs; j++) {
        char err[SD_ERR_MAX];
        struct render_job *job = &o->jobs[j];
        if (scene_file_bytes(job->scene, &o->scene, &job->bytes, &job->len, err,
                             sizeof err) != 0) {
            fprintf(stderr, "links1 render: %s\n", err);
            return -1;
        }
    }
    return 0;
}

static void render_summary(const char *path, const struct link_render_stats *s,
                           const struct image *img, uint8_t balance, double seconds)
{
    printf("links1 render: frame %u %dx%d -> %s: %u NCs, %u areas (%s), %.1f s "
           "(board: prepare %u ms, render %u ms); rays %llu primary, %llu shadow, "
           "%llu reflection, %llu refraction, %llu transmission; tests %llu box, %llu primitive "
           "(%llu by primary rays); %u pixels lost precision; memory high-water DM %u, RC %u, NC %u of %u bytes\n",
           s->frame, img->width, img->height, path, s->ncs, s->areas,
           areas_mode_name((enum areas_mode)balance), seconds, s->prepare_ms, s->render_ms,
           (unsigned long long)s->primary, (unsigned long long)s->shadow,
           (unsigned long long)s->reflection, (unsigned long long)s->refraction,
           (unsigned long long)s->transmission, (unsigned long long)s->box_tests,
           (unsigned long long)s->prim_tests, (unsigned long long)s->primary_prim_tests,
           s->precision_lost_pixels, s->dm_high,
           s->rc_high, s->nc_high_max, s->nc_private);
    fflush(stdout);
}

/* One scene on the running board: upload, every frame asked for. */
static int render_job(struct board *b, const struct render_opts *o, const struct render_job *j)
{
    struct link_scene_info info;
    int rc = render_session_load(b, j->bytes, j->len, &info);
    if (rc != 0) {
        fprintf(stderr, "links1 render: %s was not loaded\n", j->scene);
        return -1;
    }
    printf("links1 render: %s loaded: %ux%u, %u frame(s), %u bytes compiled, a prepared frame "
           "needs at most %u of the DM's %u-byte IMSU block\n",
           j->scene, info.width, info.height, info.frames, info.compiled_bytes, info.blob_bytes,
           info.blob_limit);
    long first = o->first, last = o->last < 0 ? o->first : o->last;
    if ((uint32_t)last >= info.frames) {
        fprintf(stderr, "links1 render: %s: frame %ld, the scene has %u frames (0..%u)\n",
                j->scene, last, info.frames, info.frames - 1);
        return -1;
    }
    int ppm = o->ppm || scene_file_ends_with(j->out, ".ppm");
    for (long f = first; f <= last; f++) {
        struct link_render_args a = o->args;
        a.frame = (uint32_t)f;
        if (f < last)
            a.flags |= LINK_RENDER_PREPARE_NEXT;
        long long t0 = board_now_ms();
        struct link_render_stats s;
        struct image img = {0, 0, NULL};
        if (render_session_frame(b, &a, isatty(2), &s) != 0 || render_session_pull(b, &img) != 0)
            return -1;
        char path[4096], err[SD_ERR_MAX];
        if (o->many)
            scene_file_frame_path(j->out, f, path, sizeof path);
        else
            snprintf(path, sizeof path, "%s", j->out);
        rc = ppm ? image_write_ppm(path, &img, err, sizeof err)
                 : image_write_png(path, &img, err, sizeof err);
        if (rc != 0) {
            fprintf(stderr, "links1 render: %s\n", err);
            image_free(&img);
            return -1;
        }
        render_summary(path, &s, &img, a.balance, (double)(board_now_ms() - t0) / 1000.0);
        image_free(&img);
    }
    return 0;
}

int cmd_render(int argc, char **argv)
{
    struct render_opts o;
    int r = render_parse(&o, argc, argv);
    if (r != 0)
        return r > 0 ? 0 : 2;
    if (render_read_scenes(&o) != 0) {
        render_free_scenes(&o);
        return 1;
    }
    char insn_path[] = "/tmp/links1-insns-XXXXXX";
    if (o.count_insns) {
        int fd = mkstemp(insn_path);
        if (fd < 0) {
            perror("links1: temporary file for instruction counts");
            render_free_scenes(&o);
            return 1;
        }
        close(fd);
        o.board.insn_count_out = insn_path;
    }
    struct board b;
    int rc = 1;
    if (board_start(&b, &o.board) == 0 &&
        board_wait_reported(&b, o.board.timeout_s * 1000) == 0) {
        rc = 0;
        for (int j = 0; j < o.njobs; j++)
            if (render_job(&b, &o, &o.jobs[j]) != 0)
                rc = 1;
    }
    if (board_stop(&b) < 0)
        rc = 1;
    if (board_report_link_errors(&b))
        rc = 1;
    if (b.nfaults) {
        fprintf(stderr, "links1 render: %d unit computer(s) faulted\n", b.nfaults);
        rc = 1;
    }
    if (o.count_insns) {
        if (insn_report_print(insn_path, o.board.ncores) < 0)
            rc = 1;
        unlink(insn_path);
    }
    render_free_scenes(&o);
    return rc;
}
