/* scene_map_image.c: a colour or bump map from an image file (scene_import.h);
 * the `image` of a map statement and the textures of imported models. */
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
    /* A bump map's height is the image's luminance (Rec. 601 weights). */
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

int sd_map_read_image(struct sd_map *m, const char *path, char *err, size_t errlen)
{
    struct image img;
    /* The side limit is checked on the file's header: a small file
     * claiming a huge image costs nothing. */
    int rc = image_read_max(path, SCN_MAX_MAP_SIDE, &img, err, errlen);
    return sd_map_take(m, rc, &img, path, err, errlen);
}

int sd_map_read_image_fd(struct sd_map *m, int fd, const char *path, char *err, size_t errlen)
{
    struct image img;
    int rc = image_read_fd(fd, path, SCN_MAX_MAP_SIDE, &img, err, errlen);
    return sd_map_take(m, rc, &img, path, err, errlen);
}
