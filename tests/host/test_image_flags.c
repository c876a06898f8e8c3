/* Host tests of image_flag_score (links1 compare --flags): the precision
 * and recall of a --mark-lost render's flags against a reference. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/image/image_compare.h"
#include "render/render.h"
#include "tests/check.h"

#define W 16
#define H 16

static struct image image_flat(uint8_t v)
{
    struct image img = {W, H, malloc(W * H * 3)};
    memset(img.rgb, v, W * H * 3);
    return img;
}

static void image_set(struct image *img, int x, int y, uint8_t r, uint8_t g, uint8_t b)
{
    uint8_t *p = img->rgb + ((size_t)y * W + (size_t)x) * 3;
    p[0] = r;
    p[1] = g;
    p[2] = b;
}

static void image_flag(struct image *img, int x, int y)
{
    image_set(img, x, y, RENDER_LOST_COLOUR.r, RENDER_LOST_COLOUR.g, RENDER_LOST_COLOUR.b);
}

/* A flat reference: 4 pixels beyond 2/255 (one channel off by 10), one of
 * them flagged, two flagged pixels that are fine: precision 1/3, recall 1/4;
 * a pixel off by exactly 2 is not beyond. */
static void flags_score_flat(void)
{
    struct image ref = image_flat(100), plain = image_flat(100);
    int bx[4] = {1, 5, 9, 13}, by[4] = {2, 6, 10, 14};
    for (int i = 0; i < 4; i++)
        image_set(&plain, bx[i], by[i], 100, 110, 100);
    image_set(&plain, 3, 3, 102, 98, 100); /* within 2 */
    struct image marked = image_flat(100);
    memcpy(marked.rgb, plain.rgb, W * H * 3);
    image_flag(&marked, 1, 2);
    image_flag(&marked, 0, 0);
    image_flag(&marked, 15, 15);
    struct image_flag_score s;
    image_flag_score(&ref, &plain, &marked, 2, &s);
    CHECK_EQ_INT(s.pixels, W * H);
    CHECK_EQ_INT(s.flagged, 3);
    CHECK_EQ_INT(s.beyond, 4);
    CHECK_EQ_INT(s.flagged_beyond, 1);
    CHECK_EQ_INT(s.missed, 3);
    CHECK_EQ_INT(s.missed_explained, 0);
    CHECK_NEAR(image_flag_precision(&s), 1.0 / 3.0, 1e-12);
    CHECK_NEAR(image_flag_recall(&s), 0.25, 1e-12);
    free(ref.rgb);
    free(plain.rgb);
    free(marked.rgb);
}

/* A reference with an edge (columns 0..7 dark, 8..15 bright): a pixel beyond
 * on the edge and not flagged is explained (an edge moved by under a pixel),
 * so it does not lower the recall; one beyond in the flat middle does. */
static void flags_score_edge_explained(void)
{
    struct image ref = image_flat(20), plain = image_flat(20);
    for (int y = 0; y < H; y++)
        for (int x = 8; x < W; x++) {
            image_set(&ref, x, y, 200, 200, 200);
            image_set(&plain, x, y, 200, 200, 200);
        }
    image_set(&plain, 8, 5, 20, 20, 20); /* the edge moved one pixel right */
    image_set(&plain, 3, 9, 60, 20, 20); /* wrong in the flat dark part */
    struct image marked = image_flat(0);
    memcpy(marked.rgb, plain.rgb, W * H * 3);
    struct image_flag_score s;
    image_flag_score(&ref, &plain, &marked, 2, &s);
    CHECK_EQ_INT(s.beyond, 2);
    CHECK_EQ_INT(s.missed, 2);
    CHECK_EQ_INT(s.missed_explained, 1);
    CHECK_NEAR(image_flag_recall(&s), 0.0, 1e-12);
    CHECK_NEAR(image_flag_precision(&s), 1.0, 1e-12); /* nothing flagged */
    image_flag(&marked, 3, 9);
    image_flag_score(&ref, &plain, &marked, 2, &s);
    CHECK_NEAR(image_flag_recall(&s), 1.0, 1e-12);
    CHECK_NEAR(image_flag_precision(&s), 1.0, 1e-12);
    free(ref.rgb);
    free(plain.rgb);
    free(marked.rgb);
}

int main(void)
{
    RUN(flags_score_flat);
    RUN(flags_score_edge_explained);
    return check_exit();
}
