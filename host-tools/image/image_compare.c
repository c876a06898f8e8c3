/* image_compare.c: how far two renderings are apart (see image_compare.h). */
#include "host-tools/image/image_compare.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render/render.h"

static const uint8_t *image_px(const struct image *a, int x, int y)
{
    return a->rgb + 3 * ((size_t)y * (size_t)a->width + (size_t)x);
}

static int image_is_edge(const struct image *a, int x, int y)
{
    const uint8_t *c = image_px(a, x, y);
    for (int dy = -1; dy <= 1; dy++) {
        for (int dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= a->width || ny >= a->height)
                continue;
            const uint8_t *n = image_px(a, nx, ny);
            for (int k = 0; k < 3; k++)
                if (abs((int)n[k] - (int)c[k]) > IMAGE_EDGE_STEP)
                    return 1;
        }
    }
    return 0;
}

/* B's pixel b at (x, y) is within k of some pixel of A's 3x3 neighbourhood. */
static int image_is_moved(const struct image *a, const uint8_t *b, int x, int y, int k)
{
    for (int dy = -1; dy <= 1; dy++) {
        for (int dx = -1; dx <= 1; dx++) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= a->width || ny >= a->height)
                continue;
            const uint8_t *n = image_px(a, nx, ny);
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

int image_pixel_flagged(const struct image *img, long i)
{
    const rgb8_t lost = RENDER_LOST_COLOUR;
    const uint8_t *p = img->rgb + 3 * (size_t)i;
    return p[0] == lost.r && p[1] == lost.g && p[2] == lost.b;
}

double image_psnr(double sq, long pixels)
{
    if (pixels <= 0 || sq <= 0)
        return IMAGE_PSNR_SAME;
    return 10.0 * log10(255.0 * 255.0 * 3.0 * (double)pixels / sq);
}

void image_compare(const struct image *a, const struct image *b,
                   const struct image_compare_opts *o, struct image_compare_result *r)
{
    memset(r, 0, sizeof *r);
    double sq = 0;
    for (int y = 0; y < a->height; y++) {
        for (int x = 0; x < a->width; x++) {
            if (o->silhouette && image_is_edge(a, x, y)) {
                r->masked++;
                continue;
            }
            long i = (long)y * a->width + x;
            const uint8_t *pa = image_px(a, x, y), *pb = image_px(b, x, y);
            if (o->flagged && image_pixel_flagged(b, i)) {
                r->flagged++;
                continue;
            }
            if (o->moved) {
                int off = 0;
                for (int k = 0; k < 3; k++)
                    if (abs((int)pa[k] - (int)pb[k]) > o->within)
                        off = 1;
                if (off && image_is_moved(a, pb, x, y, o->within)) {
                    r->moved++;
                    continue;
                }
            }
            int ok = 1;
            for (int k = 0; k < 3; k++) {
                int d = abs((int)pa[k] - (int)pb[k]);
                sq += (double)d * d;
                r->hist[k][d < IMAGE_HIST_BUCKETS - 1 ? d : IMAGE_HIST_BUCKETS - 1]++;
                if (d > o->within)
                    ok = 0;
                if (d > r->worst)
                    r->worst = d;
            }
            r->compared++;
            r->good += ok;
        }
    }
    r->psnr = image_psnr(sq, r->compared);
}

void image_error_flagged(const struct image *ref, const struct image *img,
                         const struct image *marked, double *all, double *flagged_psnr,
                         long *flagged)
{
    double sq = 0, sq_flagged = 0;
    long n = (long)ref->width * ref->height, nf = 0;
    for (long i = 0; i < n; i++) {
        const uint8_t *a = ref->rgb + 3 * (size_t)i, *b = img->rgb + 3 * (size_t)i;
        double d = 0;
        for (int k = 0; k < 3; k++)
            d += ((double)a[k] - b[k]) * ((double)a[k] - b[k]);
        sq += d;
        if (image_pixel_flagged(marked, i)) {
            sq_flagged += d;
            nf++;
        }
    }
    *all = image_psnr(sq, n);
    *flagged_psnr = image_psnr(sq_flagged, nf);
    *flagged = nf;
}

void image_flag_score(const struct image *ref, const struct image *img,
                      const struct image *marked, int within, struct image_flag_score *s)
{
    memset(s, 0, sizeof *s);
    for (int y = 0; y < ref->height; y++) {
        for (int x = 0; x < ref->width; x++) {
            long i = (long)y * ref->width + x;
            const uint8_t *pa = image_px(ref, x, y), *pb = image_px(img, x, y);
            int beyond = 0;
            for (int k = 0; k < 3; k++)
                if (abs((int)pa[k] - (int)pb[k]) > within)
                    beyond = 1;
            int flagged = image_pixel_flagged(marked, i);
            s->pixels++;
            s->flagged += flagged;
            s->beyond += beyond;
            s->flagged_beyond += flagged && beyond;
            if (beyond && !flagged) {
                s->missed++;
                if (image_is_edge(ref, x, y) || image_is_moved(ref, pb, x, y, within))
                    s->missed_explained++;
            }
        }
    }
}

double image_flag_precision(const struct image_flag_score *s)
{
    return s->flagged ? (double)s->flagged_beyond / (double)s->flagged : 1.0;
}

double image_flag_recall(const struct image_flag_score *s)
{
    long want = s->flagged_beyond + s->missed - s->missed_explained;
    return want ? (double)s->flagged_beyond / (double)want : 1.0;
}
