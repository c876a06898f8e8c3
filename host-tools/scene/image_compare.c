/* image_compare.c: `links1 compare A B`: how far two renderings of a scene
 * are apart, per channel, and whether enough pixels agree.
 *
 * Silhouette mask (--silhouette): a pixel is left out when its 3x3
 * neighbourhood in A (the reference) crosses an edge, i.e. some neighbour
 * differs from it by more than COMPARE_EDGE_STEP in some channel.  Object
 * outlines (and hard shadow outlines) are where two renderers that sample
 * one ray per pixel disagree by a whole pixel's worth of coverage, so the
 * accuracy of the shading is judged away from them.
 *
 * Moved pixels (--moved): a pixel of B beyond K of A's that lies within K,
 * on every channel, of one pixel of A's 3x3 neighbourhood is left out: the
 * value a surface, a shadow or texel edge or an object thinner than a
 * pixel moved by less than a pixel gives, whatever the contrast.
 *
 * Flagged pixels (--flagged): B was rendered with --mark-lost; its pixels
 * painted RENDER_LOST_COLOUR are counted apart and left out, so "every
 * other pixel within K" checks that no wrong pixel went unflagged.
 * Every run prints the PSNR over the compared pixels.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/cli_opt.h"
#include "host-tools/scene/image_io.h"
#include "host-tools/scene/scene_cmds.h"
#include "render/render.h"

#define COMPARE_EDGE_STEP 24     /* /255: a jump this large between neighbours is an edge */
#define COMPARE_HIST_BUCKETS 8   /* differences 0..6 one by one, then "7 or more" */

static int compare_is_edge(const struct image *a, int x, int y)
{
    const uint8_t *c = a->rgb + 3 * ((size_t)y * (size_t)a->width + (size_t)x);
    for (int dy = -1; dy <= 1; dy++) {
        for (int dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= a->width || ny >= a->height)
                continue;
            const uint8_t *n = a->rgb + 3 * ((size_t)ny * (size_t)a->width + (size_t)nx);
            for (int k = 0; k < 3; k++)
                if (abs((int)n[k] - (int)c[k]) > COMPARE_EDGE_STEP)
                    return 1;
        }
    }
    return 0;
}

/* B's pixel at (x, y) is within k of some pixel of A's 3x3 neighbourhood. */
static int compare_is_moved(const struct image *a, const uint8_t *b, int x, int y, int k)
{
    for (int dy = -1; dy <= 1; dy++) {
        for (int dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= a->width || ny >= a->height)
                continue;
            const uint8_t *n = a->rgb + 3 * ((size_t)ny * (size_t)a->width + (size_t)nx);
            int near = 1;
            for (int c = 0; c < 3; c++)
                if (abs((int)n[c] - (int)b[c]) > k)
                    near = 0;
            if (near)
                return 1;
        }
    }
    return 0;
}

static int compare_usage(FILE *out)
{
    fprintf(out, "usage: links1 compare A.png B.png [--within K] [--min-fraction F] "
                    "[--silhouette [--max-masked F]] [--moved] [--flagged]\n"
                    "  exit 0 when at least F (default 0.99) of the compared pixels have every\n"
                    "  channel within K/255 (default 1); --silhouette leaves out the pixels\n"
                    "  next to an edge of A, and fails if more than F of all pixels are left out;\n"
                    "  --moved leaves out the pixels of B within K of a pixel next to them in A\n"
                    "  (an edge or a thin object moved by less than a pixel);\n"
                    "  --flagged leaves out the pixels of B painted the --mark-lost colour\n");
    return out == stdout ? 0 : 2;
}

enum { COMPARE_OPT_WITHIN = CLI_OWN_CODES, COMPARE_OPT_MIN_FRACTION, COMPARE_OPT_MAX_MASKED,
       COMPARE_OPT_SILHOUETTE, COMPARE_OPT_FLAGGED, COMPARE_OPT_MOVED };

static const struct option compare_options[] = {
    {"within", required_argument, NULL, COMPARE_OPT_WITHIN},
    {"min-fraction", required_argument, NULL, COMPARE_OPT_MIN_FRACTION},
    {"max-masked", required_argument, NULL, COMPARE_OPT_MAX_MASKED},
    {"silhouette", no_argument, NULL, COMPARE_OPT_SILHOUETTE},
    {"flagged", no_argument, NULL, COMPARE_OPT_FLAGGED},
    {"moved", no_argument, NULL, COMPARE_OPT_MOVED},
    {"help", no_argument, NULL, 'h'},
    {NULL, 0, NULL, 0},
};

int scene_cmd_compare(int argc, char **argv)
{
    const char *pa = NULL, *pb = NULL;
    int within = 1, silhouette = 0, flagged_out = 0, moved_out = 0;
    double min_fraction = 0.99, max_masked = 1.0;
    struct cli c;
    cli_init(&c, "links1 compare", argc, argv, "h", compare_options);
    for (int code; (code = cli_next(&c)) != -1;) {
        int bad = 0;
        if (code == 'h') {
            compare_usage(stdout);
            return 0;
        } else if (code == COMPARE_OPT_WITHIN) {
            bad = cli_int(&c, 0, 255, &within);
        } else if (code == COMPARE_OPT_MIN_FRACTION) {
            bad = cli_double(&c, 0, 0, 1, NULL, &min_fraction);
        } else if (code == COMPARE_OPT_MAX_MASKED) {
            bad = cli_double(&c, 0, 0, 1, NULL, &max_masked);
        } else if (code == COMPARE_OPT_SILHOUETTE) {
            silhouette = 1;
        } else if (code == COMPARE_OPT_FLAGGED) {
            flagged_out = 1;
        } else if (code == COMPARE_OPT_MOVED) {
            moved_out = 1;
        } else if (code == CLI_OPERAND && (!pa || !pb)) {
            *(pa ? &pb : &pa) = c.arg;
        } else {
            if (code == CLI_OPERAND)
                fprintf(stderr, "links1 compare: two images, not also '%s'\n", c.arg);
            bad = -1;
        }
        if (bad)
            return compare_usage(stderr);
    }
    if (!pa || !pb) {
        fprintf(stderr, "links1 compare: name two images\n");
        return compare_usage(stderr);
    }
    struct image a, b;
    char err[512];
    if (image_read(pa, &a, err, sizeof err) != 0) {
        fprintf(stderr, "links1 compare: %s\n", err);
        return 2;
    }
    if (image_read(pb, &b, err, sizeof err) != 0) {
        fprintf(stderr, "links1 compare: %s\n", err);
        image_free(&a);
        return 2;
    }
    if (a.width != b.width || a.height != b.height) {
        fprintf(stderr, "links1 compare: %s is %dx%d but %s is %dx%d\n", pa, a.width, a.height,
                pb, b.width, b.height);
        image_free(&a);
        image_free(&b);
        return 2;
    }
    long hist[3][COMPARE_HIST_BUCKETS];
    memset(hist, 0, sizeof hist);
    long compared = 0, masked = 0, good = 0, flagged = 0, moved = 0;
    double sq = 0;
    int worst = 0;
    const rgb8_t lost = RENDER_LOST_COLOUR;
    for (int y = 0; y < a.height; y++) {
        for (int x = 0; x < a.width; x++) {
            if (silhouette && compare_is_edge(&a, x, y)) {
                masked++;
                continue;
            }
            size_t o = 3 * ((size_t)y * (size_t)a.width + (size_t)x);
            if (flagged_out && b.rgb[o] == lost.r && b.rgb[o + 1] == lost.g &&
                b.rgb[o + 2] == lost.b) {
                flagged++;
                continue;
            }
            if (moved_out) {
                int off = 0;
                for (int k = 0; k < 3; k++)
                    if (abs((int)a.rgb[o + k] - (int)b.rgb[o + k]) > within)
                        off = 1;
                if (off && compare_is_moved(&a, b.rgb + o, x, y, within)) {
                    moved++;
                    continue;
                }
            }
            int ok = 1;
            for (int k = 0; k < 3; k++) {
                int d = abs((int)a.rgb[o + k] - (int)b.rgb[o + k]);
                sq += (double)d * d;
                hist[k][d < COMPARE_HIST_BUCKETS - 1 ? d : COMPARE_HIST_BUCKETS - 1]++;
                if (d > within)
                    ok = 0;
                if (d > worst)
                    worst = d;
            }
            compared++;
            good += ok;
        }
    }
    double fraction = compared ? (double)good / (double)compared : 0;
    printf("compare %s %s: %dx%d, %ld pixels compared, %ld masked (silhouette)", pa, pb,
           a.width, a.height, compared, masked);
    if (moved_out)
        printf(", %ld moved", moved);
    printf("\n");
    printf("  |difference|/255:");
    for (int d = 0; d < COMPARE_HIST_BUCKETS; d++)
        printf(d < COMPARE_HIST_BUCKETS - 1 ? "%8d" : "%7d+", d);
    printf("\n");
    for (int k = 0; k < 3; k++) {
        printf("  %-17s", k == 0 ? "red" : k == 1 ? "green" : "blue");
        for (int d = 0; d < COMPARE_HIST_BUCKETS; d++)
            printf("%8ld", hist[k][d]);
        printf("\n");
    }
    printf("  within %d/255 on every channel: %.4f%% (need %.4f%%), largest difference %d\n",
           within, 100.0 * fraction, 100.0 * min_fraction, worst);
    double mse = compared ? sq / (3.0 * (double)compared) : 0;
    printf("  PSNR %.2f dB (99 = identical)%s", mse > 0 ? 10.0 * log10(255.0 * 255.0 / mse) : 99.0,
           flagged_out ? "" : "\n");
    if (flagged_out)
        printf("; %ld pixels flagged (the --mark-lost colour in B), left out\n", flagged);
    double masked_fraction = (double)masked / ((double)a.width * (double)a.height);
    if (masked_fraction > max_masked)
        printf("  too many pixels masked: %.2f%% (at most %.2f%% allowed)\n",
               100.0 * masked_fraction, 100.0 * max_masked);
    image_free(&a);
    image_free(&b);
    return fraction >= min_fraction && compared > 0 && masked_fraction <= max_masked ? 0 : 1;
}
