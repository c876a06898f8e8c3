/* cmd_compare.c: `links1 compare A B`: how far two renderings of a scene
 * are apart, per channel, and whether enough pixels agree (the measures:
 * host-tools/image/image_compare.h).  Every run prints the PSNR over the
 * compared pixels. */
#include <stdio.h>
#include <stdlib.h>

#include "host-tools/cli/scene_cmds.h"
#include "host-tools/image/image_compare.h"
#include "host-tools/image/image_io.h"
#include "host-tools/opts/cli_opt.h"

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

static void compare_print(const char *pa, const char *pb, const struct image *a,
                          const struct image_compare_opts *o,
                          const struct image_compare_result *r, double min_fraction)
{
    double fraction = r->compared ? (double)r->good / (double)r->compared : 0;
    printf("compare %s %s: %dx%d, %ld pixels compared, %ld masked (silhouette)", pa, pb,
           a->width, a->height, r->compared, r->masked);
    if (o->moved)
        printf(", %ld moved", r->moved);
    printf("\n");
    printf("  |difference|/255:");
    for (int d = 0; d < IMAGE_HIST_BUCKETS; d++)
        printf(d < IMAGE_HIST_BUCKETS - 1 ? "%8d" : "%7d+", d);
    printf("\n");
    for (int k = 0; k < 3; k++) {
        printf("  %-17s", k == 0 ? "red" : k == 1 ? "green" : "blue");
        for (int d = 0; d < IMAGE_HIST_BUCKETS; d++)
            printf("%8ld", r->hist[k][d]);
        printf("\n");
    }
    printf("  within %d/255 on every channel: %.4f%% (need %.4f%%), largest difference %d\n",
           o->within, 100.0 * fraction, 100.0 * min_fraction, r->worst);
    printf("  PSNR %.2f dB (99 = identical)%s", r->psnr, o->flagged ? "" : "\n");
    if (o->flagged)
        printf("; %ld pixels flagged (the --mark-lost colour in B), left out\n", r->flagged);
}

int scene_cmd_compare(int argc, char **argv)
{
    const char *pa = NULL, *pb = NULL;
    struct image_compare_opts o = {.within = 1};
    double min_fraction = 0.99, max_masked = 1.0;
    struct cli c;
    cli_init(&c, "links1 compare", argc, argv, "h", compare_options);
    for (int code; (code = cli_next(&c)) != -1;) {
        int bad = 0;
        if (code == 'h') {
            compare_usage(stdout);
            return 0;
        } else if (code == COMPARE_OPT_WITHIN) {
            bad = cli_int(&c, 0, 255, &o.within);
        } else if (code == COMPARE_OPT_MIN_FRACTION) {
            bad = cli_double(&c, 0, 0, 1, NULL, &min_fraction);
        } else if (code == COMPARE_OPT_MAX_MASKED) {
            bad = cli_double(&c, 0, 0, 1, NULL, &max_masked);
        } else if (code == COMPARE_OPT_SILHOUETTE) {
            o.silhouette = 1;
        } else if (code == COMPARE_OPT_FLAGGED) {
            o.flagged = 1;
        } else if (code == COMPARE_OPT_MOVED) {
            o.moved = 1;
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
    struct image_compare_result r;
    image_compare(&a, &b, &o, &r);
    compare_print(pa, pb, &a, &o, &r, min_fraction);
    double fraction = r.compared ? (double)r.good / (double)r.compared : 0;
    double masked_fraction = (double)r.masked / ((double)a.width * (double)a.height);
    if (masked_fraction > max_masked)
        printf("  too many pixels masked: %.2f%% (at most %.2f%% allowed)\n",
               100.0 * masked_fraction, 100.0 * max_masked);
    image_free(&a);
    image_free(&b);
    return fraction >= min_fraction && r.compared > 0 && masked_fraction <= max_masked ? 0 : 1;
}
