/* image_io.c: PNG (libpng) and PPM (P6) reading and writing. */
#include "host-tools/image/image_io.h"

#include <errno.h>
#include <fcntl.h>
#include <setjmp.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define IMAGE_ERR_ROOM 200 /* libpng message kept for the error */

void image_free(struct image *img)
{
    free(img->rgb);
    img->rgb = NULL;
    img->width = img->height = 0;
}

static int image_alloc(struct image *img, int w, int h, int max_side)
{
    if (w <= 0 || h <= 0 || w > max_side || h > max_side)
        return -1;
    img->rgb = malloc((size_t)w * (size_t)h * 3);
    if (!img->rgb)
        return -1;
    img->width = w;
    img->height = h;
    return 0;
}

/* libpng's error exit: jumps back to image_read_png. */
static void image_png_error(png_structp png, png_const_charp msg)
{
    char *err = png_get_error_ptr(png);
    snprintf(err, IMAGE_ERR_ROOM, "%s", msg);
    png_longjmp(png, 1);
}

static void image_png_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* The low-level API, with no gamma handling at all: the 8-bit values are
 * taken as stored (POV-Ray's files carry a gAMA chunk that the simplified
 * API would "correct"; maps and frames here are linear values). */
static int image_read_png(FILE *f, const char *path, int max_side, struct image *img,
                          char *err, size_t errlen)
{
    char perr[IMAGE_ERR_ROOM] = "";
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, perr, image_png_error, image_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    /* volatile: it is set after setjmp and freed after the longjmp back */
    uint8_t **volatile rows = NULL;
    if (!png || !info) {
        snprintf(err, errlen, "%s: out of memory", path);
        png_destroy_read_struct(&png, &info, NULL);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        snprintf(err, errlen, "%s: not a readable PNG (%s)", path, perr);
        free(rows);
        image_free(img);
        png_destroy_read_struct(&png, &info, NULL);
        return -1;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    int colour = png_get_color_type(png, info);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_packing(png);
    if (colour == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (colour == PNG_COLOR_TYPE_GRAY || colour == PNG_COLOR_TYPE_GRAY_ALPHA) {
        png_set_expand_gray_1_2_4_to_8(png);
        png_set_gray_to_rgb(png);
    }
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != (size_t)w * 3 ||
        w > (png_uint_32)max_side || h > (png_uint_32)max_side ||
        image_alloc(img, (int)w, (int)h, max_side) != 0) {
        snprintf(err, errlen, "%s: %ux%u image is larger than %d a side or of an unusual layout",
                 path, w, h, max_side);
        png_destroy_read_struct(&png, &info, NULL);
        return -1;
    }
    rows = malloc(sizeof *rows * h);
    if (!rows)
        png_error(png, "out of memory");
    for (png_uint_32 y = 0; y < h; y++)
        rows[y] = img->rgb + (size_t)y * w * 3;
    png_read_image(png, rows);
    png_read_end(png, NULL);
    free(rows);
    png_destroy_read_struct(&png, &info, NULL);
    return 0;
}

/* Reads one header number of a PPM, skipping white space and comments. */
static int image_ppm_number(FILE *f, int *out)
{
    int c;
    for (;;) {
        c = fgetc(f);
        if (c == '#') {
            while (c != '\n' && c != EOF)
                c = fgetc(f);
        } else if (c != ' ' && c != '\t' && c != '\n' && c != '\r') {
            break;
        }
    }
    long v = 0;
    int digits = 0;
    while (c >= '0' && c <= '9' && v < IMAGE_MAX_SIDE * 16) {
        v = v * 10 + (c - '0');
        digits++;
        c = fgetc(f);
    }
    *out = (int)v;
    return digits > 0 ? 0 : -1; /* the one white space after it is consumed */
}

static int image_read_ppm(FILE *f, const char *path, int max_side, struct image *img,
                          char *err, size_t errlen)
{
    int w, h, maxval;
    if (image_ppm_number(f, &w) || image_ppm_number(f, &h) ||
        image_ppm_number(f, &maxval) || maxval != 255) {
        snprintf(err, errlen, "%s: bad P6 header (want width, height, 255)", path);
        return -1;
    }
    if (image_alloc(img, w, h, max_side) != 0) {
        snprintf(err, errlen, "%s: %dx%d image is larger than %d a side", path, w, h, max_side);
        return -1;
    }
    size_t n = (size_t)w * (size_t)h * 3;
    if (fread(img->rgb, 1, n, f) != n) {
        snprintf(err, errlen, "%s: truncated pixel data", path);
        image_free(img);
        return -1;
    }
    return 0;
}

int image_read(const char *path, struct image *img, char *err, size_t errlen)
{
    return image_read_max(path, IMAGE_MAX_SIDE, img, err, errlen);
}

int image_open(const char *path, int nofollow, int max_side, char *err, size_t errlen)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | (nofollow ? O_NOFOLLOW : 0));
    if (fd < 0) {
        snprintf(err, errlen, "%s: %s", path, errno == ELOOP && nofollow ? "a symbolic link"
                                                                         : strerror(errno));
        return -1;
    }
    struct stat st = {0};
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "%s: not a regular file (%s): not read", path,
                 S_ISDIR(st.st_mode) ? "a directory" : S_ISFIFO(st.st_mode) ? "a FIFO"
                 : S_ISSOCK(st.st_mode) ? "a socket" : "a device");
        close(fd);
        return -1;
    }
    if ((unsigned long long)st.st_size > IMAGE_FILE_MAX(max_side)) {
        snprintf(err, errlen, "%s: %lld bytes, more than an image of at most %dx%d pixels "
                 "takes (%llu)", path, (long long)st.st_size, max_side, max_side,
                 (unsigned long long)IMAGE_FILE_MAX(max_side));
        close(fd);
        return -1;
    }
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    return fd;
}

int image_read_fd(int fd, const char *path, int max_side, struct image *img, char *err,
                  size_t errlen)
{
    memset(img, 0, sizeof *img);
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        close(fd);
        return -1;
    }
    unsigned char magic[2] = {0, 0};
    size_t got = fread(magic, 1, 2, f);
    int rc;
    if (got == 2 && magic[0] == 'P' && magic[1] == '6') {
        rc = image_read_ppm(f, path, max_side, img, err, errlen);
    } else {
        rewind(f);
        rc = image_read_png(f, path, max_side, img, err, errlen);
    }
    fclose(f);
    return rc;
}

int image_read_max(const char *path, int max_side, struct image *img, char *err, size_t errlen)
{
    memset(img, 0, sizeof *img);
    int fd = image_open(path, 0, max_side, err, errlen);
    return fd < 0 ? -1 : image_read_fd(fd, path, max_side, img, err, errlen);
}

int image_write(FILE *f, const char *name, const struct image *img, int ppm, char *err,
                size_t errlen)
{
    if (!ppm) {
        png_image pi;
        memset(&pi, 0, sizeof pi);
        pi.version = PNG_IMAGE_VERSION;
        pi.width = (png_uint_32)img->width;
        pi.height = (png_uint_32)img->height;
        pi.format = PNG_FORMAT_RGB;
        if (!png_image_write_to_stdio(&pi, f, 0, img->rgb, 0, NULL)) {
            snprintf(err, errlen, "%s: cannot write PNG (%s)", name, pi.message);
            return -1;
        }
    } else {
        size_t n = (size_t)img->width * (size_t)img->height * 3;
        if (fprintf(f, "P6\n%d %d\n255\n", img->width, img->height) < 0 ||
            fwrite(img->rgb, 1, n, f) != n) {
            snprintf(err, errlen, "%s: write failed: %s", name, strerror(errno));
            return -1;
        }
    }
    if (ferror(f) || fflush(f) != 0) {
        snprintf(err, errlen, "%s: write failed: %s", name, strerror(errno));
        return -1;
    }
    return 0;
}
