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
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "host-tools/scene/image_io.h"
#include "host-tools/scene/cli_args.h"
#include "host-tools/scene/scene_desc.h"
#include "render/render.h"
#include "render/scene_load.h"

#define REF_ARENA_START (64u * 1024u * 1024u)  /* first arena tried */
#define REF_ARENA_MAX (1024u * 1024u * 1024u)  /* largest arena tried */

static int ref_usage(void)
{
    fprintf(stderr, "usage: links1 ref SCENE(.scn|.l1s) -o OUT.png [--arith double|float|soft|"
                    "fixed] [--ppm] [--size WxH] [--frame N | --frames FIRST:LAST]\n"
                    "  [--no-auto-hierarchy]\n"
                    "  (this is the %s build)\n",
            NUM_NAME);
    return 2;
}

static int ref_ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

/* The compiled bytes of a scene file: read as is (.l1s) or compiled from
 * text.  0, or -1 with err. */
static int ref_scene_bytes(const char *path, uint8_t **buf, size_t *len, char *err,
                           size_t errlen, int width, int height, int no_auto_hierarchy)
{
    if (!ref_ends_with(path, ".l1s")) {
        struct sd_scene s;
        if (sd_parse_file(path, &s, err, errlen) != 0)
            return -1;
        if (no_auto_hierarchy)
            s.no_auto_hierarchy = 1;
        if (width) { /* --size: the same scene at another resolution */
            s.view.width = width;
            s.view.height = height;
        }
        int rc = sd_compile(&s, buf, len, err, errlen);
        sd_free(&s);
        return rc;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    *buf = malloc(SCN_MAX_SIZE + 1);
    *len = *buf ? fread(*buf, 1, SCN_MAX_SIZE + 1, f) : 0;
    fclose(f);
    if (!*buf || *len > SCN_MAX_SIZE) {
        snprintf(err, errlen, "%s: %s", path,
                 *buf ? "larger than a compiled scene may be" : "out of memory");
        free(*buf);
        *buf = NULL;
        return -1;
    }
    return 0;
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
            fprintf(stderr, "links1 ref: %s: %s\n", in, render_status_name(rs));
            return -1;
        }
        arena_release_to(arena, *mark);
        return 0;
    }
    fprintf(stderr, "links1 ref: %s: no arena up to %u bytes holds the scene\n", in,
            REF_ARENA_MAX);
    return -1;
}

/* out with the frame number before the extension: "a.png", 7 -> "a-0007.png" */
static void ref_frame_path(const char *out, long frame, char *buf, size_t n)
{
    const char *dot = strrchr(out, '.');
    const char *slash = strrchr(out, '/');
    if (!dot || (slash && dot < slash))
        dot = out + strlen(out);
    snprintf(buf, n, "%.*s-%04ld%s", (int)(dot - out), out, frame, dot);
}

static int ref_render_frame(const char *in, const scene_t *scene, arena_t *arena,
                            size_t mark, long frame, const char *out, int ppm)
{
    arena_release_to(arena, mark);
    render_frame_t *frame_data;
    render_status_t rs = render_prepare(scene, (uint32_t)frame, arena, &frame_data);
    if (rs != RENDER_OK) {
        fprintf(stderr, "links1 ref: %s frame %ld: %s\n", in, frame, render_status_name(rs));
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
    struct timespec t0, t1; /* tracing only: make bench's ns per ray */
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (uint32_t y = 0; y < scene->height; y++) {
        render_span(&ctx, y, 0, scene->width, row);
        for (int x = 0; x < img.width; x++) {
            uint8_t *px = img.rgb + 3 * ((size_t)y * (size_t)img.width + (size_t)x);
            px[0] = row[x].r;
            px[1] = row[x].g;
            px[2] = row[x].b;
        }
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    char err[SD_ERR_MAX];
    int rc = ppm ? image_write_ppm(out, &img, err, sizeof err)
                 : image_write_png(out, &img, err, sizeof err);
    if (rc != 0)
        fprintf(stderr, "links1 ref: %s\n", err);
    else
        fprintf(stderr,
                "links1 ref (%s): %s frame %ld, %dx%d -> %s; rays: %llu primary, %llu "
                "shadow, %llu reflection, %llu refraction, %llu transmission; "
                "%u pixels lost precision; %llu box tests, %llu primitive tests; traced in "
                "%.3f s\n",
                NUM_NAME, in, frame, img.width, img.height, out,
                (unsigned long long)ctx.stats.primary, (unsigned long long)ctx.stats.shadow,
                (unsigned long long)ctx.stats.reflection,
                (unsigned long long)ctx.stats.refraction,
                (unsigned long long)ctx.stats.transmission,
                (unsigned)ctx.stats.precision_lost_pixels,
                (unsigned long long)ctx.stats.box_tests, (unsigned long long)ctx.stats.prim_tests,
                secs);
    free(row);
    image_free(&img);
    return rc;
}

int main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    int ppm = 0, many = 0, width = 0, height = 0, no_auto_hierarchy = 0;
    long first = 0, last = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) {
            out = argv[++i];
        } else if (strcmp(argv[i], "--ppm") == 0) {
            ppm = 1;
        } else if (strcmp(argv[i], "--no-auto-hierarchy") == 0) {
            no_auto_hierarchy = 1;
        } else if (strcmp(argv[i], "--size") == 0 && i + 1 < argc) {
            if (cli_parse_size(argv[++i], &width, &height) != 0) {
                fprintf(stderr, "links1 ref: --size wants WxH within %dx%d, not '%s'\n",
                        RENDER_MAX_WIDTH, RENDER_MAX_HEIGHT, argv[i]);
                return 2;
            }
        } else if ((strcmp(argv[i], "--frame") == 0 || strcmp(argv[i], "--frames") == 0) &&
                   i + 1 < argc) {
            many = argv[i][7] == 's';
            if (cli_parse_frames(argv[++i], &first, &last) != 0 || (!many && first != last)) {
                fprintf(stderr, "links1 ref: %s wants %s, not '%s'\n", argv[i - 1],
                        many ? "FIRST:LAST" : "a frame number", argv[i]);
                return 2;
            }
        } else if (argv[i][0] != '-' && !in) {
            in = argv[i];
        } else {
            fprintf(stderr, "links1 ref: unknown argument '%s'\n", argv[i]);
            return ref_usage();
        }
    }
    if (!in || !out)
        return ref_usage();
    if (!ppm && ref_ends_with(out, ".ppm"))
        ppm = 1;

    char err[SD_ERR_MAX];
    uint8_t *bytes = NULL;
    size_t len = 0;
    if (ref_scene_bytes(in, &bytes, &len, err, sizeof err, width, height, no_auto_hierarchy) != 0) {
        fprintf(stderr, "links1 ref: %s\n", err);
        return 1;
    }
    void *mem = NULL;
    arena_t arena;
    size_t mark;
    scene_t scene;
    int rc = ref_load(in, bytes, len, &mem, &arena, &mark, &scene);
    if (rc == 0 && (uint32_t)last >= scene.frame_count) {
        fprintf(stderr, "links1 ref: %s: frame %ld, the scene has %u frames (0..%u)\n", in,
                last, (unsigned)scene.frame_count, (unsigned)scene.frame_count - 1);
        rc = -1;
    }
    for (long f = first; rc == 0 && f <= last; f++) {
        char path[4096];
        if (many)
            ref_frame_path(out, f, path, sizeof path);
        else
            snprintf(path, sizeof path, "%s", out);
        rc = ref_render_frame(in, &scene, &arena, mark, f, path, ppm);
    }
    free(mem);
    free(bytes);
    return rc != 0;
}
