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

enum compare_opt_code {
    COMPARE_OPT_WITHIN = CLI_OWN_CODES,
    COMPARE_OPT_MIN_FRACTION,
    COMPARE_OPT_MAX_MASKED,
    COMPARE_OPT_SILHOUETTE,
    COMPARE_OPT_FLAGGED,
    COMPARE_OPT_MOVED,
    COMPARE_OPT_FLAGS,
    COMPARE_OPT_MIN_PRECISION,
    COMPARE_OPT_MIN_RECALL
};

static const struct cli_optdef compare_optdefs[] = {
    {"within", "K", COMPARE_OPT_WITHIN,
     "a pixel agrees when every channel is within K/255 (0..255,\n"
     "default 1; 2 with --flags)"},
    {"min-fraction", "F", COMPARE_OPT_MIN_FRACTION,
     "exit 0 when at least F of the compared pixels agree (0..1,\n"
     "default 0.99)"},
    {"silhouette", NULL, COMPARE_OPT_SILHOUETTE, "leave out the pixels next to an edge of A"},
    {"max-masked", "F", COMPARE_OPT_MAX_MASKED,
     "fail if --silhouette leaves out more than F of all pixels (0..1,\n"
     "default 1)"},
    {"moved", NULL, COMPARE_OPT_MOVED,
     "leave out the pixels of B within K of a pixel next to them in A\n"
     "(an edge or a thin object moved by less than a pixel)"},
    {"flagged", NULL, COMPARE_OPT_FLAGGED,
     "leave out the pixels of B painted the --mark-lost colour"},
    CLI_OPTDEF_END,
};

/* The second form: how well --mark-lost's flags pick out the pixels that
 * lost precision. */
static const struct cli_optdef compare_flags_optdefs[] = {
    {"flags", "MARKED", COMPARE_OPT_FLAGS,
     "score the flags of MARKED (PLAIN rendered with --mark-lost)\n"
     "against the pixels of PLAIN beyond K/255 of REF"},
    {"min-precision", "P", COMPARE_OPT_MIN_PRECISION,
     "exit 0 only when precision, the share of flagged pixels that are\n"
     "beyond, is at least P (0..1, default 0)"},
    {"min-recall", "R", COMPARE_OPT_MIN_RECALL,
     "and recall, the share of pixels beyond that were flagged (those\n"
     "next to an edge of REF or moved left out), at least R (0..1,\n"
     "default 1)"},
    CLI_OPTDEF_END,
};

static void compare_usage(FILE *out)
{
    fprintf(out, "usage: links1 compare A.png B.png [options]\n"
                 "       links1 compare REF.png PLAIN.png --flags MARKED.png [--within K] "
                 "[options of --flags]\n"
                 "Compares two images pixel by pixel: the differences per channel, the PSNR;\n"
                 "exit 0 when enough pixels agree.\n"
                 "options:\n");
    cli_optdefs_help(out, compare_optdefs);
    fprintf(out, "options of --flags:\n");
    cli_optdefs_help(out, compare_flags_optdefs);
}

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

/* Reads path into img; 0, or 1 after saying why. */
static int compare_read(const char *path, struct image *img)
{
    char err[512];
    if (image_read(path, img, err, sizeof err) == 0)
        return 0;
    fprintf(stderr, "links1 compare: %s\n", err);
    return 1;
}

/* --flags: how well MARKED's flags pick out PLAIN's pixels beyond K of REF. */
static int compare_flags(const char *pref, const char *pplain, const char *pmarked, int within,
                         double min_precision, double min_recall)
{
    struct image img[3];
    const char *path[3] = {pref, pplain, pmarked};
    int n = 0, rc = 0;
    for (; n < 3; n++) {
        if (compare_read(path[n], &img[n]) != 0) {
            rc = 1;
            break;
        }
        if (n > 0 && (img[n].width != img[0].width || img[n].height != img[0].height)) {
            fprintf(stderr, "links1 compare: %s is %dx%d but %s is %dx%d\n", path[0],
                    img[0].width, img[0].height, path[n], img[n].width, img[n].height);
            n++;
            rc = 1;
            break;
        }
    }
    if (rc == 0) {
        struct image_flag_score s;
        image_flag_score(&img[0], &img[1], &img[2], within, &s);
        double p = image_flag_precision(&s), r = image_flag_recall(&s);
        printf("flags %s: %ld of %ld pixels flagged, %ld beyond %d/255 of %s; "
               "%ld flagged and beyond (precision %.2f%%); %ld beyond and not flagged, "
               "%ld of them next to an edge or moved (recall %.2f%%)\n",
               pmarked, s.flagged, s.pixels, s.beyond, within, pref, s.flagged_beyond,
               100.0 * p, s.missed, s.missed_explained, 100.0 * r);
        rc = p >= min_precision && r >= min_recall ? 0 : 1;
    }
    while (n-- > 0)
        image_free(&img[n]);
    return rc;
}

int scene_cmd_compare(int argc, char **argv)
{
    const char *pmarked = NULL;
    double min_precision = 0, min_recall = 1;
    int within_given = 0;
    const char *pa = NULL, *pb = NULL;
    struct image_compare_opts o = {.within = 1};
    double min_fraction = 0.99, max_masked = 1.0;
    static const struct cli_optdef *const lists[] = {compare_optdefs, compare_flags_optdefs,
                                                     NULL};
    struct option longs[16];
    struct cli c;
    if (cli_optdefs_table(lists, longs, 16) != 0)
        return 2;
    cli_init(&c, "links1 compare", argc, argv, "h", longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        int bad = 0;
        if (code == 'h') {
            compare_usage(stdout);
            return 0;
        } else if (code == COMPARE_OPT_WITHIN) {
            bad = cli_int(&c, 0, 255, &o.within);
            within_given = 1;
        } else if (code == COMPARE_OPT_FLAGS) {
            pmarked = c.arg;
        } else if (code == COMPARE_OPT_MIN_PRECISION) {
            bad = cli_double(&c, 0, 0, 1, NULL, &min_precision);
        } else if (code == COMPARE_OPT_MIN_RECALL) {
            bad = cli_double(&c, 0, 0, 1, NULL, &min_recall);
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
                cli_usage_error("links1 compare", "two images, not also '%s'", c.arg);
            bad = -1;
        }
        if (bad)
            return 2;
    }
    if (!pa || !pb) {
        cli_usage_error("links1 compare", "name two images");
        return 2;
    }
    if (pmarked)
        return compare_flags(pa, pb, pmarked, within_given ? o.within : 2, min_precision,
                             min_recall);
    struct image a, b;
    char err[512];
    if (image_read(pa, &a, err, sizeof err) != 0) {
        fprintf(stderr, "links1 compare: %s\n", err);
        return 1;
    }
    if (image_read(pb, &b, err, sizeof err) != 0) {
        fprintf(stderr, "links1 compare: %s\n", err);
        image_free(&a);
        return 1;
    }
    if (a.width != b.width || a.height != b.height) {
        fprintf(stderr, "links1 compare: %s is %dx%d but %s is %dx%d\n", pa, a.width, a.height,
                pb, b.width, b.height);
        image_free(&a);
        image_free(&b);
        return 1;
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
