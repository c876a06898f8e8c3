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
/* The most bytes a file of an image of at most side x side pixels is
 * taken to need (PNG may hold its pixels uncompressed, with filter bytes
 * and chunk headers): a bigger file is refused unread. */
#define IMAGE_FILE_MAX(side) (4ull * (unsigned long long)(side) * (unsigned long long)(side) + 65536u)
/* The image file at path opened to be read: O_NONBLOCK (a FIFO never
 * blocks the open), O_NOFOLLOW when nofollow; then checked a regular file
 * (not a directory, a FIFO, a device) of at most IMAGE_FILE_MAX(max_side)
 * bytes.  Its fd, or -1 with "PATH: why" in err.  image_read_max reads
 * through it. */
int image_open(const char *path, int nofollow, int max_side, char *err, size_t errlen);
/* image_read_max from fd (image_open's; closed here); path names it in
 * err. */
int image_read_fd(int fd, const char *path, int max_side, struct image *img, char *err,
                  size_t errlen);
/* img as PNG (ppm 0) or binary PPM (ppm 1) to f, which the caller makes
 * and closes (an output file is written whole through
 * host-tools/opts/out_file.h); name names it in err.  0, or -1. */
int image_write(FILE *f, const char *name, const struct image *img, int ppm, char *err,
                size_t errlen);
void image_free(struct image *img);

#endif
