/* scene_map_image.c: a map from an image file (scene_import.h); the
 * `image` of a map statement and the textures of imported models. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "host-tools/image/image_io.h"
#include "host-tools/scene/scene_import.h"

/* The image read (rc 0) into map m, or its error passed on. */
static int sd_map_take(struct sd_map *m, int rc, struct image *img, const char *path,
                       char *err, size_t errlen)
{
    if (rc != 0)
        return -1;
    size_t n = (size_t)img->width * (size_t)img->height;
    free(m->texels);
    m->texels = NULL;
    m->width = img->width;
    m->height = img->height;
    if (m->kind == SCN_MAP_COLOUR) {
        m->texels = img->rgb; /* same layout: 3 bytes per texel, top row = v 0 */
        return 0;
    }
    if (m->kind == SCN_MAP_NORMAL) {
        /* the usual encoding: channel c stands for 2c/255 - 1 */
        for (size_t i = 0; i < n; i++) {
            uint8_t *px = img->rgb + 3 * i;
            double v[3] = {2.0 * px[0] / 255 - 1, 2.0 * px[1] / 255 - 1, 2.0 * px[2] / 255 - 1};
            if (sd_map_normal_texel(v, px) != 0) {
                snprintf(err, errlen,
                         "%s: normal map texel (%zu, %zu) = RGB %u %u %u does not point out of "
                         "the surface (blue must stand for z > 0)",
                         path, i % (size_t)img->width, i / (size_t)img->width, px[0], px[1],
                         px[2]);
                image_free(img);
                return -1;
            }
        }
        m->texels = img->rgb; /* 3 signed bytes per texel now */
        return 0;
    }
    /* A bump map's height, an attribute map's value, is the image's
     * luminance (Rec. 601 weights). */
    m->texels = malloc(n);
    if (!m->texels) {
        image_free(img);
        snprintf(err, errlen, "out of memory reading %s", path);
        return -1;
    }
    for (size_t i = 0; i < n; i++) {
        const uint8_t *px = img->rgb + 3 * i;
        m->texels[i] = (uint8_t)((299u * px[0] + 587u * px[1] + 114u * px[2] + 500u) / 1000u);
    }
    image_free(img);
    return 0;
}

int sd_map_normal_texel(const double v[3], uint8_t out[3])
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!isfinite(len) || !(len > 0))
        return -1;
    long q[3];
    for (int k = 0; k < 3; k++)
        q[k] = lround(v[k] * SCN_MAP_NORMAL_ONE);
    /* already of unit length within the bytes' rounding (|q| within
     * sqrt(3)/2 of 127): kept as rounded, so a texel written as q/127
     * (sd_write_text) reads back as q; otherwise normalized first */
    double qlen = sqrt((double)(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]));
    if (fabs(qlen - SCN_MAP_NORMAL_ONE) > 0.8660254037844386)
        for (int k = 0; k < 3; k++)
            q[k] = lround(v[k] / len * SCN_MAP_NORMAL_ONE);
    if (q[2] < 1)
        return -1;
    for (int k = 0; k < 3; k++)
        out[k] = (uint8_t)(q[k] < 0 ? q[k] + 256 : q[k]);
    return 0;
}

int sd_map_read_image_fd(struct sd_map *m, int fd, const char *path, char *err, size_t errlen)
{
    struct image img;
    int rc = image_read_fd(fd, path, SCN_MAX_MAP_SIDE, &img, err, errlen);
    return sd_map_take(m, rc, &img, path, err, errlen);
}
