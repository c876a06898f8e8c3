/* image_io.h: 8-bit RGB images on the host: PNG through libpng, binary PPM
 * (P6) by hand.  Pixels are row-major, top row first, 3 bytes per pixel. */
#ifndef LINKS1_HOST_IMAGE_IO_H
#define LINKS1_HOST_IMAGE_IO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define IMAGE_MAX_SIDE 16384 /* refuse larger files rather than allocate blindly */

struct image {
    int width, height;
    uint8_t *rgb;           /* width * height * 3 bytes, malloc'ed */
};

/* Each returns 0, or -1 with a message naming the file and the problem. */
int image_read(const char *path, struct image *img, char *err, size_t errlen);
/* Same, refusing an image wider or taller than max_side (<= IMAGE_MAX_SIDE)
 * from its header, before any pixel is allocated or read. */
int image_read_max(const char *path, int max_side, struct image *img, char *err,
                   size_t errlen);
/* img as PNG (ppm 0) or binary PPM (ppm 1) to f, which the caller makes
 * and closes (an output file is written whole through
 * host-tools/opts/out_file.h); name names it in err.  0, or -1. */
int image_write(FILE *f, const char *name, const struct image *img, int ppm, char *err,
                size_t errlen);
void image_free(struct image *img);

#endif
