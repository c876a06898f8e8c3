/* ref_main.c: links1-ref-<arith>, the host reference renderer, built once per
 * arithmetic of the shared renderer (double, float, fixed).  `links1 ref`
 * runs the one asked for; it can also be run alone:
 *
 *   links1-ref-double SCENE(.scn|.l1s) -o OUT.png [--ppm] [--frame N | --frames A:B]
 *
 * --frames writes one image per frame, the number before the extension
 * (out-0000.png, out-0001.png, ...).
 *
 * A text scene is compiled in memory first, so the host goes through the
 * same compiled form and the same loader (render/scene_load.c) as the board.
 */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "host-tools/image/film.h"
#include "host-tools/image/image_io.h"
#include "host-tools/opts/cli_args.h"
#include "host-tools/opts/exit_clean.h"
#include "host-tools/opts/out_file.h"
#include "host-tools/image/image_save.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_file.h"
#include "host-tools/scene/scene_opts.h"
#include "host-tools/scene/scene_paper.h"
#include "host-tools/ref/ref_opts.h"
#include "proto/scene_format.h"
#include "proto/wire.h"
#include "render/blob.h"
#include "render/clip.h"
#include "render/lightbuf.h"
#include "render/precision.h"
#include "render/render.h"
#include "render/scene_load.h"
#include "render/wide.h"

#define REF_ARENA_START (64u * 1024u * 1024u)  /* first arena tried */
#define REF_ARENA_MAX (1024u * 1024u * 1024u)  /* largest arena tried */

/* This build's --help, under the name it was started by (links1-ref-float). */
static int ref_usage(FILE *out, const char *argv0, int status)
{
    const char *slash = strrchr(argv0, '/');
    ref_opts_usage(out, slash ? slash + 1 : argv0, 0);
    return status;
}

/* After RENDER_ERR_DETAIL on a text scene: "; it is in cluster NAME" when
 * the primitive is in a cluster of its own (the compiled scene, and so
 * the board's message, keeps no names).  Empty otherwise. */
static void ref_cluster_note(const char *in, render_status_t rs, const render_frame_t *f,
                             char *out, size_t cap)
{
    out[0] = 0;
    if (rs != RENDER_ERR_DETAIL || !f || !scene_file_ends_with(in, ".scn"))
        return;
    struct sd_scene s;
    char err[SD_ERR_MAX];
    if (sd_parse_file(in, &s, err, sizeof err) != 0)
        return;
    if (f->detail_prim < (uint32_t)s.n_prims) {
        int c = s.prims[f->detail_prim].cluster;
        if (c > 0 && c < s.n_clusters && s.clusters[c].name[0])
            snprintf(out, cap, "; it is in cluster %s", s.clusters[c].name);
    }
    sd_free(&s);
}

/* The arena with the loaded scene in it: grown until the scene and one
 * prepared frame fit.  *mark is where the frame's memory starts. */
static int ref_load(const char *in, const uint8_t *bytes, size_t len, void **mem,
                    arena_t *arena, size_t *mark, scene_t *scene)
{
    for (size_t size = REF_ARENA_START; size <= REF_ARENA_MAX; size *= 2) {
        free(*mem);
        *mem = malloc(size);
        if (!*mem)
            break;
        arena_init(arena, *mem, size);
        scene_load_error_t lerr;
        scene_load_status_t ls = scene_load(bytes, len, arena, scene, &lerr);
        if (ls == SCENE_LOAD_ERR_ARENA)
            continue;
        if (ls != SCENE_LOAD_OK) {
            fprintf(stderr, "links1 ref: %s: %s: %s\n", in, scene_load_status_name(ls),
                    lerr.message);
            return -1;
        }
        *mark = arena->used;
        render_frame_t *frame;
        render_status_t rs = render_prepare(scene, 0, arena, &frame);
        if (rs == RENDER_ERR_ARENA)
            continue;
        if (rs != RENDER_OK) {
            char why[256], note[64];
            precision_status_message(frame, rs, why, sizeof why);
            ref_cluster_note(in, rs, frame, note, sizeof note);
            fprintf(stderr, "links1 ref: %s: %s%s\n", in, why, note);
            return -1;
        }
        arena_release_to(arena, *mark);
        return 0;
    }
    fprintf(stderr, "links1 ref: %s: no arena up to %u bytes holds the scene\n", in,
            REF_ARENA_MAX);
    return -1;
}

/* --escalate: the scene in the wide arithmetic (render/wide.h), as the
 * board's DM prepares it beside the narrow one, and a context on it. */
struct ref_wide {
    void *block;     /* the wide blob, aligned to RENDER_RELOCATE_ALIGN */
    size_t size;
    void *ctx;       /* the wide context */
};

static void ref_wide_free(struct ref_wide *w)
{
    free(w->block);
    free(w->ctx);
    memset(w, 0, sizeof *w);
}

/* Loads the wide blob of the compiled scene, told what the narrow load
 * found (scene, loaded from the same bytes), as the DM does; 0, or -1
 * after saying why. */
static int ref_wide_load(const char *in, const uint8_t *bytes, size_t len, const scene_t *scene,
                         struct ref_wide *w)
{
    char why[RENDER_BLOB_MSG_MAX];
    memset(w, 0, sizeof *w);
    if (!render_wide_linked()) {
        fprintf(stderr, "links1 ref: --escalate: the %s build carries no wide arithmetic (%s)\n",
                NUM_NAME, strcmp(NUM_NAME, "double") == 0 ? "double is the wide one itself"
                                                          : "links1 ref --arith float or fixed");
        return -1;
    }
    if (RENDER_WIDE(wide_blob_bytes)(bytes, len, &w->size, why, sizeof why) != 0) {
        fprintf(stderr, "links1 ref: %s: --escalate: %s\n", in, why);
        return -1;
    }
    w->block = aligned_alloc(RENDER_RELOCATE_ALIGN,
                             (w->size + RENDER_RELOCATE_ALIGN - 1) & ~(size_t)(RENDER_RELOCATE_ALIGN - 1));
    w->ctx = aligned_alloc(RENDER_WIDE_CTX_ALIGN,
                           (RENDER_WIDE(wide_ctx_bytes)() + RENDER_WIDE_CTX_ALIGN - 1) &
                               ~(size_t)(RENDER_WIDE_CTX_ALIGN - 1));
    if (!w->block || !w->ctx) {
        fprintf(stderr, "links1 ref: --escalate: out of memory for the wide scene\n");
        ref_wide_free(w);
        return -1;
    }
    scene_load_known_t known = scene_load_known_of(scene, wire_get_u32(bytes + SCN_HDR_SUM));
    if (RENDER_WIDE(wide_blob_load)(bytes, len, &known, w->block, w->size, "the wide blob", 0,
                                    why, sizeof why) != 0) {
        fprintf(stderr, "links1 ref: %s: --escalate: %s\n", in, why);
        ref_wide_free(w);
        return -1;
    }
    return 0;
}

/* The wide frame and its context, ctx escalating into it; 0 or -1. */
static int ref_wide_frame(const char *in, struct ref_wide *w, long frame, render_ctx_t *ctx)
{
    char why[RENDER_BLOB_MSG_MAX];
    const render_options_t *o = &ctx->options;
    if (RENDER_WIDE(wide_blob_prepare)(w->block, (uint32_t)frame, w->size, why, sizeof why) != 0 ||
        RENDER_WIDE(wide_ctx_open)(w->ctx, w->block, w->size, o->use_bounds, o->use_hierarchy,
                                   o->mark_lost && !o->check_lost, why, sizeof why) != 0) {
        fprintf(stderr, "links1 ref: %s frame %ld: --escalate: %s\n", in, frame, why);
        return -1;
    }
    render_wide_escalate(ctx, w->ctx);
    return 0;
}

/* The frame's light buffer (render/lightbuf.h) for ctx, in memory the
 * caller frees; without memory shadow rays walk the whole tree. */
static void *ref_light_buffer(render_ctx_t *ctx, const render_frame_t *f)
{
    size_t bytes = render_lightbuf_bytes(f);
    void *mem = malloc(bytes);
    ctx->light_buffer = render_lightbuf_build(f, mem, bytes);
    return mem;
}

/* Every row of the image through render_span, or with supersample > 0
 * render_pixel_supersampled. */
static void ref_trace_rows(render_ctx_t *ctx, struct image *img, rgb8_t *row, int supersample)
{
    for (uint32_t y = 0; y < (uint32_t)img->height; y++) {
        if (supersample == 0)
            render_span(ctx, y, 0, (uint32_t)img->width, row);
        for (uint32_t x = 0; supersample > 0 && x < (uint32_t)img->width; x++)
            row[x] = render_pixel_supersampled(ctx, x, y, (uint32_t)supersample);
        for (int x = 0; x < img->width; x++) {
            uint8_t *px = img->rgb + 3 * ((size_t)y * (size_t)img->width + (size_t)x);
            px[0] = row[x].r;
            px[1] = row[x].g;
            px[2] = row[x].b;
        }
    }
}

_Static_assert(sizeof(rgb8_t) == 3, "an image's rows are packed r,g,b bytes");

/* Corner mode (--spd-rules, --aa; render_corner_mode): the whole image as
 * one area (render_area), whose corner rays are each traced and counted
 * once, searched by screen as an NC's are by default.  0, or -1 after
 * saying why. */
static int ref_trace_corners(render_ctx_t *ctx, const render_frame_t *f, struct image *img)
{
    size_t bytes = render_clip_bytes(f);
    void *mem = malloc(bytes ? bytes : 1);
    render_clip_t clip;
    if (!mem || render_clip_init(&clip, f, mem, bytes) != RENDER_OK) {
        fprintf(stderr, "links1 ref: out of memory for the corner rays\n");
        free(mem);
        return -1;
    }
    render_area_t all = {0, 0, f->width, f->height};
    render_clip_options_t opt = {.y_clip = 1, .x_clip = 1, .lists = 0};
    render_status_t rs = render_area(ctx, &clip, &all, &opt, (rgb8_t *)img->rgb);
    free(mem);
    if (rs != RENDER_OK) {
        fprintf(stderr, "links1 ref: the corner rays: %s\n", render_status_name(rs));
        return -1;
    }
    return 0;
}

/* One frame to out (an image file), or to film when it is not NULL; wide
 * (when not NULL): escalating into it. */
static int ref_render_frame(const char *in, const scene_t *scene, arena_t *arena,
                            size_t mark, long frame, const char *out, int ppm, struct film *film,
                            struct ref_wide *wide, int verbose, int supersample)
{
    arena_release_to(arena, mark);
    render_frame_t *frame_data;
    render_status_t rs = render_prepare(scene, (uint32_t)frame, arena, &frame_data);
    if (rs != RENDER_OK) {
        char why[256], note[64];
        precision_status_message(frame_data, rs, why, sizeof why);
        ref_cluster_note(in, rs, frame_data, note, sizeof note);
        fprintf(stderr, "links1 ref: %s frame %ld: %s%s\n", in, frame, why, note);
        return -1;
    }
    struct image img = {scene->width, scene->height, NULL};
    img.rgb = malloc((size_t)img.width * (size_t)img.height * 3);
    rgb8_t *row = malloc(sizeof *row * (size_t)img.width);
    if (!img.rgb || !row) {
        fprintf(stderr, "links1 ref: out of memory for the image\n");
        free(row);
        image_free(&img);
        return -1;
    }
    render_ctx_t ctx;
    render_ctx_init(&ctx, frame_data);
    void *lights = ref_light_buffer(&ctx, frame_data);
    if (wide && ref_wide_frame(in, wide, frame, &ctx) != 0) {
        free(lights);
        free(row);
        image_free(&img);
        return -1;
    }
    /* tracing only: make bench's ns per ray; the process's CPU time too,
     * which other programs on a busy machine inflate far less */
    struct timespec t0, t1, c0, c1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
    if (render_corner_mode(&ctx.options)) {
        if (ref_trace_corners(&ctx, frame_data, &img) != 0) {
            free(lights);
            free(row);
            image_free(&img);
            return -1;
        }
    } else {
        ref_trace_rows(&ctx, &img, row, supersample);
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
    free(lights);
    if (wide)
        RENDER_WIDE(wide_stats_add)(wide->ctx, &ctx.stats); /* the escalations' rays */
    if (wide && verbose)
        fprintf(stderr, "links1 ref: frame %ld: %u pixels escalated to double\n", frame,
                (unsigned)ctx.stats.escalated_pixels);
    double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    double cpu = (double)(c1.tv_sec - c0.tv_sec) + 1e-9 * (double)(c1.tv_nsec - c0.tv_nsec);
    char err[SD_ERR_MAX];
    int rc = film ? film_frame(film, &img, err, sizeof err)
                  : image_save(out, &img, ppm, err, sizeof err);
    if (rc != 0)
        fprintf(stderr, "links1 ref: %s\n", err);
    else
        fprintf(stderr,
                "links1 ref (%s): %s frame %ld, %dx%d -> %s; rays: %llu primary, %llu "
                "shadow, %llu reflection, %llu refraction, %llu transmission, %llu cut by "
                "weight, %llu blocked by their surface; "
                "%u pixels in doubt; %llu box tests, %llu primitive tests; traced in "
                "%.6f s (%.6f s CPU)\n",
                NUM_NAME, in, frame, img.width, img.height, out,
                (unsigned long long)ctx.stats.primary, (unsigned long long)ctx.stats.shadow,
                (unsigned long long)ctx.stats.reflection,
                (unsigned long long)ctx.stats.refraction,
                (unsigned long long)ctx.stats.transmission,
                (unsigned long long)ctx.stats.weight_cut,
                (unsigned long long)ctx.stats.self_blocked,
                (unsigned)ctx.stats.precision_lost_pixels,
                (unsigned long long)ctx.stats.box_tests, (unsigned long long)ctx.stats.prim_tests,
                secs, cpu);
    if (rc == 0 && ctx.options.spd_rules) /* preprocessing: the CPU time before tracing */
        scene_opts_spd_line(ctx.stats.primary_hit, ctx.stats.reflection, ctx.stats.refraction,
                            ctx.stats.shadow, (double)c0.tv_sec + 1e-9 * (double)c0.tv_nsec, cpu);
    free(row);
    image_free(&img);
    return rc;
}

/* Escalation as asked: by default wherever the build carries the wide
 * arithmetic (float and fixed) and the scene is not in paper mode. */
enum ref_escalation { REF_ESC_DEFAULT, REF_ESC_ON, REF_ESC_OFF };

struct ref_args {
    const char *in, *out;
    int ppm, many, verbose, escalate; /* escalate: settled (ref_escalation_settle) */
    int supersample; /* --supersample N: N, else 0 */
    enum ref_escalation escalation;
    long first, last;
    struct scene_file_opts scene;
};

/* One option of links1-ref's own (not a scene option): 0, or -1 (said). */
static int ref_take(struct ref_args *a, const struct cli *c, int code)
{
    switch (code) {
    case 'o': a->out = c->arg; return 0;
    case REF_OPT_PPM: a->ppm = 1; return 0;
    case REF_OPT_VERBOSE: a->verbose = 1; return 0;
    case REF_OPT_SUPERSAMPLE: return cli_int(c, 1, RENDER_MAX_SUPERSAMPLE, &a->supersample);
    case REF_OPT_ESCALATE:
    case REF_OPT_NO_ESCALATE: {
        enum ref_escalation e = code == REF_OPT_ESCALATE ? REF_ESC_ON : REF_ESC_OFF;
        if (a->escalation != REF_ESC_DEFAULT && a->escalation != e)
            return cli_usage_error(c->prog, "--escalate or --no-escalate, not both");
        a->escalation = e;
        return 0;
    }
    case REF_OPT_FRAME:
    case REF_OPT_FRAMES:
        a->many = code == REF_OPT_FRAMES;
        if (cli_parse_frames(c->arg, &a->first, &a->last) != 0 ||
            (!a->many && a->first != a->last))
            return cli_bad_value(c, a->many ? "FIRST:LAST" : "a frame number");
        return 0;
    case CLI_OPERAND:
        if (!a->in) {
            a->in = c->arg;
            return 0;
        }
        return cli_usage_error(c->prog, "one scene at a time, not also '%s'", c->arg);
    }
    return -1;
}

/* --supersample: the double build, without --aa, --spd-rules, --paper (a
 * scene's own anti-aliasing or SPD rules are refused when it is loaded).
 * 0, or -1 (said). */
static int ref_supersample_check(const struct ref_args *a)
{
    const struct scene_file_opts *o = &a->scene;
    const char *with = o->aa_depth >= 0 ? "--aa" : o->spd_rules ? "--spd-rules"
                       : o->paper ? "--paper" : NULL;
    if (!a->supersample)
        return 0;
    if (with)
        return cli_usage_error("links1 ref", "--supersample and %s: one sampling at a time",
                               with);
    if (strcmp(NUM_NAME, "double") != 0)
        return cli_usage_error("links1 ref", "--supersample is for --arith double (a "
                               "reference), not %s", NUM_NAME);
    return 0;
}

/* 0, 1 (--help shown) or -1 (bad arguments, reported). */
static int ref_parse(int argc, char **argv, struct ref_args *a)
{
    memset(a, 0, sizeof *a);
    scene_file_opts_init(&a->scene);
    static const struct cli_optdef *const lists[] = {ref_optdefs, scene_optdefs, NULL};
    struct option longs[REF_MAX_OPTIONS];
    if (cli_optdefs_table(lists, longs, REF_MAX_OPTIONS) != 0)
        return -1;
    struct cli c;
    cli_init(&c, "links1 ref", argc, argv, REF_SHORT_OPTIONS, longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        if (code == 'h')
            return 1;
        int taken = code == CLI_BAD ? -1 : scene_opts_take(&a->scene, &c, code);
        if (taken == 0)
            taken = ref_take(a, &c, code) == 0 ? 1 : -1;
        if (taken < 0)
            return -1;
    }
    if (!a->in || !a->out)
        return cli_usage_error("links1 ref", "%s", !a->in ? "no SCENE given" : "no -o OUT given");
    if (!a->ppm && scene_file_ends_with(a->out, ".ppm"))
        a->ppm = 1;
    return ref_supersample_check(a);
}

/* Whether to escalate: --escalate, --check-lost (the wide copy, to check
 * with), or by default where the build carries the wide arithmetic and
 * neither --paper, the scene's paper mode nor --no-escalate says no. */
static void ref_escalation_settle(struct ref_args *a, const uint8_t *bytes, size_t len)
{
    struct scene_paper p;
    char why[SD_ERR_MAX];
    int paper = a->scene.paper ||
                (scene_paper_read(bytes, len, &p, why, sizeof why) == 0 && p.paper);
    a->escalate = a->escalation == REF_ESC_ON || a->scene.check_lost ||
                  (a->escalation == REF_ESC_DEFAULT && render_wide_linked() && !paper);
}

/* -o OUT (with --frames, its first frame's file) checked before any
 * rendering.  0, or -1 after saying why. */
static int ref_out_check(const struct ref_args *a)
{
    char path[PATH_MAX + 16], err[PATH_MAX + 256];
    if (a->many && film_kind_of(a->out) == FILM_NONE)
        scene_file_frame_path(a->out, a->first, path, sizeof path);
    else
        snprintf(path, sizeof path, "%s", a->out);
    if (out_file_check(path, err, sizeof err) == 0)
        return 0;
    fprintf(stderr, "links1 ref: -o %s\n", err);
    return -1;
}

int main(int argc, char **argv)
{
    exit_clean_install(); /* a signal leaves no temporary file and no child of ours */
    struct ref_args a;
    int r = ref_parse(argc, argv, &a);
    if (r != 0)
        return r > 0 ? ref_usage(stdout, argv[0], 0) : 2;
    if (ref_out_check(&a) != 0)
        return 1;
    const char *in = a.in, *out = a.out;
    long first = a.first, last = a.last;

    char err[SD_ERR_MAX];
    uint8_t *bytes = NULL;
    size_t len = 0;
    if (scene_file_bytes(in, &a.scene, &bytes, &len, err, sizeof err) != 0) {
        fprintf(stderr, "links1 ref: %s\n", err);
        return 1;
    }
    ref_escalation_settle(&a, bytes, len);
    void *mem = NULL;
    arena_t arena;
    size_t mark;
    scene_t scene;
    int rc = ref_load(in, bytes, len, &mem, &arena, &mark, &scene);
    struct ref_wide wide;
    memset(&wide, 0, sizeof wide);
    if (rc == 0 && a.escalate)
        rc = ref_wide_load(in, bytes, len, &scene, &wide);
    if (rc == 0 && a.supersample && render_corner_mode(&scene.options)) {
        fprintf(stderr, "links1 ref: %s: --supersample: the scene has %s on\n", in,
                scene.options.antialias ? "anti-aliasing (aa; --no-aa turns it off)"
                                        : "the SPD rules");
        rc = -1;
    }
    if (rc == 0 && (uint32_t)last >= scene.frame_count) {
        fprintf(stderr, "links1 ref: %s: frame %ld, the scene has %u frames (0..%u)\n", in,
                last, (unsigned)scene.frame_count, (unsigned)scene.frame_count - 1);
        rc = -1;
    }
    /* an OUT ending in .mp4, .webm or .apng: one film through ffmpeg */
    struct film film;
    memset(&film, 0, sizeof film);
    int filming = film_kind_of(out) != FILM_NONE;
    if (rc == 0 && filming &&
        (film_program_check(err, sizeof err) != 0 ||
         film_open(&film, out, scene.width, scene.height, FILM_DEFAULT_FPS, err, sizeof err) != 0)) {
        fprintf(stderr, "links1 ref: %s\n", err);
        rc = -1;
        filming = 0;
    }
    for (long f = first; rc == 0 && f <= last; f++) {
        char path[4096];
        if (filming)
            snprintf(path, sizeof path, "%s (frame %ld of the film)", out, f);
        else if (a.many)
            scene_file_frame_path(out, f, path, sizeof path);
        else
            snprintf(path, sizeof path, "%s", out);
        rc = ref_render_frame(in, &scene, &arena, mark, f, path, a.ppm, filming ? &film : NULL,
                              a.escalate ? &wide : NULL, a.verbose, a.supersample);
    }
    if (filming && rc == 0 && film_close(&film, err, sizeof err) != 0) {
        fprintf(stderr, "links1 ref: %s\n", err);
        rc = -1;
    }
    if (filming)
        film_abort(&film); /* nothing after a close; a failed film removed */
    ref_wide_free(&wide);
    free(mem);
    free(bytes);
    return rc != 0;
}
