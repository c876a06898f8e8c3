/* image_save.h: an image file written whole or not at all: image_write
 * (image_io.h) through an out_file (opts/out_file.h: a temporary file
 * beside it, renamed over it once complete), so a run that dies leaves no
 * half image under the name. */
#ifndef LINKS1_HOST_IMAGE_SAVE_H
#define LINKS1_HOST_IMAGE_SAVE_H

#include <stddef.h>

#include "host-tools/image/image_io.h"

/* img as PNG (ppm 0) or binary PPM (ppm 1) at path.  0, or -1 with
 * "PATH: why" in err and nothing new named path. */
int image_save(const char *path, const struct image *img, int ppm, char *err, size_t cap);

#endif
