/* image_compare.h: how far two renderings of a scene are apart.
 *
 * Silhouette mask: a pixel is left out when its 3x3 neighbourhood in A (the
 * reference) crosses an edge, i.e. some neighbour differs from it by more
 * than IMAGE_EDGE_STEP in some channel.  Object outlines (and hard shadow
 * outlines) are where two renderers that sample one ray per pixel disagree
 * by a whole pixel's worth of coverage, so the accuracy of the shading is
 * judged away from them.
 *
 * Moved pixels: a pixel of B beyond K of A's that lies within K, on every
 * channel, of one pixel of A's 3x3 neighbourhood is left out: the value a
 * surface, a shadow or texel edge or an object thinner than a pixel moved
 * by less than a pixel gives, whatever the contrast.
 *
 * Flagged pixels: B was rendered with --mark-lost; its pixels painted
 * RENDER_LOST_COLOUR are counted apart and left out. */
#ifndef LINKS1_HOST_IMAGE_COMPARE_H
#define LINKS1_HOST_IMAGE_COMPARE_H

#include "host-tools/image/image_io.h"

#define IMAGE_EDGE_STEP 24      /* /255: a jump this large between neighbours is an edge */
#define IMAGE_HIST_BUCKETS 8    /* differences 0..6 one by one, then "7 or more" */
#define IMAGE_PSNR_SAME 99.0    /* the PSNR reported for identical images */

struct image_compare_opts {
    int within;      /* K: a pixel is good when every channel is within K/255 */
    int silhouette;  /* 1: leave out pixels next to an edge of A */
    int moved;       /* 1: leave out pixels of B moved by under a pixel */
    int flagged;     /* 1: leave out pixels of B painted the --mark-lost colour */
};

struct image_compare_result {
    long compared;   /* pixels compared */
    long good;       /* ... with every channel within K */
    long masked, moved, flagged; /* pixels left out, by reason */
    long hist[3][IMAGE_HIST_BUCKETS]; /* per channel, |difference| counts */
    int worst;       /* the largest channel difference compared */
    double psnr;     /* over the compared pixels */
};

/* 1 when pixel i of img is painted the --mark-lost colour. */
int image_pixel_flagged(const struct image *img, long i);

/* PSNR of sq, the sum of squared channel differences over pixels pixels;
 * IMAGE_PSNR_SAME when there is no difference (or no pixel). */
double image_psnr(double sq, long pixels);

/* Compares b with the reference a (the same size: the caller checks). */
void image_compare(const struct image *a, const struct image *b,
                   const struct image_compare_opts *o, struct image_compare_result *r);

/* PSNR of img against ref over every pixel (*all) and over the pixels that
 * marked (a --mark-lost render of the same) paints as lost (*flagged_psnr,
 * their number in *flagged).  The three images are the same size. */
void image_error_flagged(const struct image *ref, const struct image *img,
                         const struct image *marked, double *all, double *flagged_psnr,
                         long *flagged);

/* How well the flags of a --mark-lost render (marked) pick out the pixels
 * of img (the same render, plain) beyond `within` of ref (the double
 * build), on some channel.  A pixel beyond and not flagged is `explained`
 * when it lies next to an edge of ref or is within `within` of a pixel
 * next to it there (image_compare's --silhouette and --moved: an edge
 * moved by under a pixel).  Precision: flagged_beyond / flagged; recall:
 * the pixels beyond, less those explained, that were flagged. */
struct image_flag_score {
    long pixels, flagged, beyond, flagged_beyond;
    long missed;           /* beyond, not flagged */
    long missed_explained; /* ... of which next to an edge or moved */
};

void image_flag_score(const struct image *ref, const struct image *img,
                      const struct image *marked, int within, struct image_flag_score *s);

/* flagged_beyond / flagged (1 when nothing is flagged) and
 * flagged_beyond / (flagged_beyond + unexplained misses) (1 when there is
 * nothing to find). */
double image_flag_precision(const struct image_flag_score *s);
double image_flag_recall(const struct image_flag_score *s);

#endif
