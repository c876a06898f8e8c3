/* cmd_render.c: `links1 render`: the whole LINKS-1 image generation system
 * driven from the host.  Compiles each scene in-process, boots a board of
 * DM + RC + N NCs, uploads the scene, renders the frames (progress on the
 * terminal), pulls each frame and writes it as PNG or PPM, prints a
 * one-line summary per frame.  Several SCENE -o OUT pairs render one after
 * another on the same board; a scene the board refuses is reported and the
 * next one still renders (the exit status is then 1). */
#include <errno.h>
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
#include "kernel/param.h"
#include "roles/areas.h"

#define RENDER_MAX_JOBS 16 /* SCENE -o OUT pairs in one run */

struct render_job {
    const char *scene, *out;
};

struct render_opts {
    struct board_opts board;
    struct render_job jobs[RENDER_MAX_JOBS];
    int njobs;
    struct link_render_args args;
    long first, last;   /* frames; last < 0: only frame first */
    int many;           /* --frames: one image per frame, numbered */
    int width, height;  /* --size, 0 = the scene's */
    int max_depth;      /* --max-depth, -1 = the scene's */
    int refractionless; /* --refractionless on|off: 1 / 0, -1 = the scene's */
    int ppm, count_insns;
    int no_auto_hierarchy; /* --no-auto-hierarchy (text scenes) */
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
            "  --no-yclip --no-xclip --no-bbox --no-hierarchy\n"
            "                   switch a speed-up off (the image stays the same)\n"
            "  --no-auto-hierarchy  compile without the automatic hierarchy (text scenes)\n"
            "  --view           show the frame memory live (-device ramfb, a display)\n"
            "  --ppm            write PPM (also chosen by an OUT ending in .ppm)\n"
            "  --count-insns    count guest instructions per core and print them\n"
            "  --timeout S      seconds to wait for every unit computer to report in\n"
            "  --firmware ELF   firmware to boot; --ram MB; --quiet\n",
            RENDER_DEFAULT_NCS, GIGS_DEFAULT_AREAS);
}

static int render_parse_long(const char *opt, const char *arg, long lo, long hi, long *v)
{
    char *end;
    errno = 0;
    *v = strtol(arg, &end, 10);
    if (errno || end == arg || *end || *v < lo || *v > hi) {
        fprintf(stderr, "links1 render: %s wants a number in %ld..%ld, not '%s'\n", opt, lo, hi,
                arg);
        return -1;
    }
    return 0;
}

/* Returns 0, 1 (--help shown) or -1 (bad option, printed). */
static int render_parse(struct render_opts *o, int argc, char **argv)
{
    memset(o, 0, sizeof *o);
    board_opts_init(&o->board);
    o->board.ncores = RENDER_DEFAULT_NCS + 2;
    o->args.balance = LINK_BALANCE_DECREASING;
    o->last = -1;
    o->max_depth = -1;
    o->refractionless = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        long n;
        int r = strcmp(a, "--smp") ? board_parse_opt(&o->board, argc, argv, &i) : 0;
        if (r < 0)
            return -1;
        if (r)
            continue;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            render_usage(stdout);
            return 1;
        } else if (strcmp(a, "-o") == 0 && v) {
            if (o->njobs == 0 || o->jobs[o->njobs - 1].out) {
                fprintf(stderr, "links1 render: -o %s: name the scene before its output\n", v);
                return -1;
            }
            o->jobs[o->njobs - 1].out = argv[++i];
        } else if (strcmp(a, "--ncs") == 0 && v) {
            if (render_parse_long(a, v, 1, BOARD_MAX_CORES - 2, &n) < 0)
                return -1;
            o->board.ncores = (int)n + 2;
            i++;
        } else if (strcmp(a, "--balance") == 0 && v) {
            enum areas_mode m;
            if (areas_mode_parse(v, &m) != AREAS_OK) {
                fprintf(stderr, "links1 render: --balance wants static, dynamic or decreasing, "
                        "not '%s'\n", v);
                return -1;
            }
            o->args.balance = (uint8_t)m;
            i++;
        } else if (strcmp(a, "--areas") == 0 && v) {
            if (render_parse_long(a, v, 1, 1 << 20, &n) < 0)
                return -1;
            o->args.areas = (uint32_t)n;
            i++;
        } else if ((strcmp(a, "--frame") == 0 || strcmp(a, "--frames") == 0) && v) {
            o->many = a[7] == 's';
            if (cli_parse_frames(v, &o->first, &o->last) != 0 ||
                (!o->many && o->first != o->last)) {
                fprintf(stderr, "links1 render: %s wants %s, not '%s'\n", a,
                        o->many ? "FIRST:LAST" : "a frame number", v);
                return -1;
            }
            i++;
        } else if (strcmp(a, "--size") == 0 && v) {
            if (cli_parse_size(v, &o->width, &o->height) != 0) {
                fprintf(stderr, "links1 render: --size wants WxH, each 1..1024, not '%s'\n", v);
                return -1;
            }
            i++;
        } else if (strcmp(a, "--max-depth") == 0 && v) {
            if (render_parse_long(a, v, 0, SCN_MAX_DEPTH, &n) < 0)
                return -1;
            o->max_depth = (int)n;
            i++;
        } else if (strcmp(a, "--refractionless") == 0 && v &&
                   (strcmp(v, "on") == 0 || strcmp(v, "off") == 0)) {
            o->refractionless = strcmp(v, "on") == 0;
            i++;
        } else if (strcmp(a, "--no-yclip") == 0) {
            o->args.flags |= LINK_RENDER_NO_YCLIP;
        } else if (strcmp(a, "--no-xclip") == 0) {
            o->args.flags |= LINK_RENDER_NO_XCLIP;
        } else if (strcmp(a, "--no-bbox") == 0) {
            o->args.flags |= LINK_RENDER_NO_BBOX;
        } else if (strcmp(a, "--no-hierarchy") == 0) {
            o->args.flags |= LINK_RENDER_NO_HIERARCHY;
        } else if (strcmp(a, "--no-auto-hierarchy") == 0) {
            o->no_auto_hierarchy = 1;
        } else if (strcmp(a, "--view") == 0) {
            o->board.view = 1;
        } else if (strcmp(a, "--ppm") == 0) {
            o->ppm = 1;
        } else if (strcmp(a, "--count-insns") == 0) {
            o->count_insns = 1;
        } else if (a[0] != '-' && o->njobs < RENDER_MAX_JOBS) {
            o->jobs[o->njobs++] = (struct render_job){a, NULL};
        } else {
            fprintf(stderr, "links1 render: unknown or incomplete option '%s'\n", a);
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

static int render_ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

/* The compiled scene: a .l1s file as is, a text scene compiled here (at
 * --size when given).  0, or -1 after printing why. */
static int render_scene_bytes(const struct render_opts *o, const char *path, uint8_t **buf,
                              size_t *len)
{
    char err[SD_ERR_MAX];
    if (!render_ends_with(path, ".l1s")) {
        struct sd_scene s;
        if (sd_parse_file(path, &s, err, sizeof err) != 0) {
            fprintf(stderr, "links1 render: %s\n", err);
            return -1;
        }
        if (o->width) {
            s.view.width = o->width;
            s.view.height = o->height;
        }
        if (o->max_depth >= 0)
            s.view.max_depth = o->max_depth;
        if (o->no_auto_hierarchy)
            s.no_auto_hierarchy = 1;
        if (o->refractionless >= 0)
            s.view.flags = o->refractionless ? s.view.flags | SCN_OPT_REFRACTIONLESS
                                             : s.view.flags & ~SCN_OPT_REFRACTIONLESS;
        int rc = sd_compile(&s, buf, len, err, sizeof err);
        sd_free(&s);
        if (rc != 0)
            fprintf(stderr, "links1 render: %s: %s\n", path, err);
        return rc;
    }
    if (o->width || o->max_depth >= 0 || o->refractionless >= 0 || o->no_auto_hierarchy) {
        fprintf(stderr, "links1 render: %s: --size, --max-depth, --refractionless and "
                "--no-auto-hierarchy need a text "
                "scene, not a compiled one\n", path);
        return -1;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "links1 render: %s: %s\n", path, strerror(errno));
        return -1;
    }
    *buf = malloc(SCN_MAX_SIZE + 1);
    *len = *buf ? fread(*buf, 1, SCN_MAX_SIZE + 1, f) : 0;
    fclose(f);
    if (!*buf || *len > SCN_MAX_SIZE || *len == 0) {
        fprintf(stderr, "links1 render: %s: %s\n", path,
                !*buf ? "out of memory" : *len ? "larger than a compiled scene may be" : "empty");
        free(*buf);
        return -1;
    }
    return 0;
}

/* out with the frame number before the extension: "a.png", 7 -> "a-0007.png" */
static void render_frame_path(const char *out, long frame, char *buf, size_t n)
{
    const char *dot = strrchr(out, '.');
    const char *slash = strrchr(out, '/');
    if (!dot || (slash && dot < slash))
        dot = out + strlen(out);
    snprintf(buf, n, "%.*s-%04ld%s", (int)(dot - out), out, frame, dot);
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
    uint8_t *bytes = NULL;
    size_t len = 0;
    if (render_scene_bytes(o, j->scene, &bytes, &len) != 0)
        return -1;
    struct link_scene_info info;
    int rc = render_session_load(b, bytes, len, &info);
    free(bytes);
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
    int ppm = o->ppm || render_ends_with(j->out, ".ppm");
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
            render_frame_path(j->out, f, path, sizeof path);
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
    char insn_path[] = "/tmp/links1-insns-XXXXXX";
    if (o.count_insns) {
        int fd = mkstemp(insn_path);
        if (fd < 0) {
            perror("links1: temporary file for instruction counts");
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
    return rc;
}
