/* clip_stats_main.c: the host program `build/render-clip-stats`:
 * how much each speed-up of section 4 cuts the work of a frame, counted
 * (not timed) by the renderer's statistics, in the spirit of the paper's
 * Table 2.  Host only (stdio, malloc); not part of the shared renderer.
 *
 *   build/render-clip-stats SCENE.scn [--area WxH]
 *
 * The screen is cut into areas of W x H pixels (default 32x4: about the
 * paper's 100 pixels per area) and each area rendered the NC's way
 * (render_area) under six settings: nothing, boxes on a flat list, boxes
 * with the hierarchy, + Y clipping, + X clipping (the paper's lists), and
 * both clippings done in the hierarchy per pixel (the NCs' default).  Every setting must give
 * the same image; the program fails if one does not. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/opts/cli_opt.h"
#include "host-tools/opts/cli_args.h"
#include "host-tools/scene/scene_desc.h"
#include "render/blob.h"
#include "render/clip.h"

#define STATS_SETTINGS 6

static const char *const stats_names[STATS_SETTINGS] = {
    "no speed-up", "boxes, flat list", "boxes + hierarchy", "+ Y clipping", "+ X clipping",
    "clipping in the tree",
};

static int stats_fail(const char *what, const char *why)
{
    fprintf(stderr, "render-clip-stats: %s: %s\n", what, why);
    return 1;
}

enum stats_opt_code { STATS_OPT_AREA = CLI_OWN_CODES };

static const struct cli_optdef stats_optdefs[] = {
    {"area", "WxH", STATS_OPT_AREA,
     "the areas the screen is cut into, rendered the NC's way\n"
     "(default 32x4: about the paper's 100 pixels an area)"},
    CLI_OPTDEF_END,
};

static int stats_usage(FILE *out, int status)
{
    fprintf(out, "usage: render-clip-stats SCENE.scn [options]\n"
                 "Counts the work of a frame (boxes and primitives tested, clusters the\n"
                 "screen clipping keeps) under six settings, from no speed-up to clipping\n"
                 "in the hierarchy; fails if one setting changes the image.\n");
    cli_optdefs_help(out, stats_optdefs);
    return status;
}

/* The command line: the scene and the area size.  0, 1 (--help shown) or
 * 2 (a usage error, said). */
static int stats_parse(int argc, char **argv, const char **in, int *area_w, int *area_h)
{
    static const struct cli_optdef *const lists[] = {stats_optdefs, NULL};
    struct option longs[4];
    struct cli c;
    if (cli_optdefs_table(lists, longs, 4) != 0)
        return 2;
    cli_init(&c, "render-clip-stats", argc, argv, "h", longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        if (code == 'h')
            return stats_usage(stdout, 1);
        if (code == STATS_OPT_AREA && cli_parse_size(c.arg, area_w, area_h) != 0) {
            cli_bad_value(&c, cli_size_want());
            return 2;
        }
        if (code == CLI_OPERAND && *in) {
            cli_usage_error("render-clip-stats", "one scene at a time, not also '%s'", c.arg);
            return 2;
        }
        if (code == CLI_OPERAND)
            *in = c.arg;
        else if (code != STATS_OPT_AREA)
            return 2;
    }
    if (!*in) {
        cli_usage_error("render-clip-stats", "no SCENE given");
        return 2;
    }
    return 0;
}

int main(int argc, char **argv)
{
    int area_w = 32, area_h = 4;
    const char *in = NULL;
    int r = stats_parse(argc, argv, &in, &area_w, &area_h);
    if (r != 0)
        return r == 1 ? 0 : 2;
    unsigned aw = (unsigned)area_w, ah = (unsigned)area_h;
    char err[SD_ERR_MAX];
    struct sd_scene sd;
    uint8_t *buf;
    size_t len, need;
    if (sd_parse_file(in, &sd, err, sizeof err) != 0)
        return stats_fail(in, err);
    if (sd_compile(&sd, &buf, &len, err, sizeof err) != 0)
        return stats_fail(in, err);
    sd_free(&sd);
    render_blob_error_t berr;
    render_blob_t *blob;
    if (render_blob_bytes(buf, len, &need, &berr) != RENDER_BLOB_OK)
        return stats_fail(in, berr.message);
    void *block = aligned_alloc(RENDER_RELOCATE_ALIGN, (need + 63) / 64 * 64);
    if (!block || render_blob_build(buf, len, 0, block, need, "host memory", &blob, &berr) != RENDER_BLOB_OK)
        return stats_fail(in, block ? berr.message : "out of memory");
    const render_frame_t *f = blob->frame;
    size_t pixels = (size_t)f->width * f->height, clip_bytes = render_clip_bytes(f);
    void *clip_mem = malloc(clip_bytes);
    rgb8_t *img[STATS_SETTINGS], *tile = malloc(sizeof *tile * aw * ah);
    render_clip_t clip;
    if (!clip_mem || !tile || render_clip_init(&clip, f, clip_mem, clip_bytes) != RENDER_OK)
        return stats_fail(in, "out of memory");
    unsigned areas = ((f->width + aw - 1) / aw) * ((f->height + ah - 1) / ah);
    printf("%s: %ux%u, %u clusters, %u primitives, %u areas of %ux%u, blob %zu bytes (peak %zu, bound %zu), NC working set %zu bytes\n",
           in, f->width, f->height, f->cluster_count, f->prim_count, areas, aw, ah, blob->bytes,
           blob->peak, need, clip_bytes);
    printf("%-20s %14s %14s %14s %14s %10s %10s %12s\n", "setting", "primary boxes",
           "primary prims", "all boxes", "all prims", "Y kept/area", "X kept/px", "rects/px");
    int same = 1;
    for (int s = 0; s < STATS_SETTINGS; s++) {
        render_ctx_t ctx;
        render_ctx_init(&ctx, f);
        ctx.options.use_bounds = s >= 1;
        ctx.options.use_hierarchy = s >= 2;
        render_clip_options_t opt = {s >= 3, s >= 4, NULL, s < 5};
        uint64_t y0 = clip.y_kept, x0 = clip.x_kept;
        img[s] = malloc(sizeof *img[s] * pixels);
        for (uint32_t y = 0; y < f->height; y += ah)
            for (uint32_t x = 0; x < f->width; x += aw) {
                render_area_t a = {x, y, f->width - x < aw ? f->width - x : aw, f->height - y < ah ? f->height - y : ah};
                if (render_area(&ctx, &clip, &a, &opt, tile) != RENDER_OK)
                    return stats_fail(in, "render_area refused an area");
                for (uint32_t r = 0; r < a.h; r++)
                    memcpy(img[s] + (size_t)(y + r) * f->width + x, tile + r * a.w, a.w * sizeof *tile);
            }
        same &= memcmp(img[s], img[0], pixels * sizeof *img[0]) == 0;
        const render_stats_t *st = &ctx.stats;
        char ykept[16] = "-", xkept[16] = "-";
        if (opt.y_clip)
            snprintf(ykept, sizeof ykept, "%.1f", (double)(clip.y_kept - y0) / areas);
        if (opt.x_clip)
            snprintf(xkept, sizeof xkept, "%.2f", (double)(clip.x_kept - x0) / pixels);
        if (!opt.lists) /* clipping in the tree: no lists, tree rectangles per pixel */
            ykept[0] = '-', ykept[1] = 0, xkept[0] = '-', xkept[1] = 0;
        printf("%-20s %14llu %14llu %14llu %14llu %10s %10s %12.2f\n", stats_names[s],
               (unsigned long long)st->primary_box_tests, (unsigned long long)st->primary_prim_tests,
               (unsigned long long)st->box_tests, (unsigned long long)st->prim_tests, ykept, xkept,
               (double)st->screen_tests / pixels);
    }
    for (int s = 0; s < STATS_SETTINGS; s++)
        free(img[s]);
    free(tile);
    free(clip_mem);
    free(block);
    free(buf);
    if (!same)
        return stats_fail(in, "a speed-up changed the image");
    return 0;
}
