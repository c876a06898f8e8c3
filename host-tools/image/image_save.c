/* image_save.c: see image_save.h. */
#include "host-tools/image/image_save.h"

#include "host-tools/opts/out_file.h"

int image_save(const char *path, const struct image *img, int ppm, char *err, size_t cap)
{
    struct out_file of;
    if (out_file_open(&of, path, err, cap) != 0)
        return -1;
    if (image_write(of.f, path, img, ppm, err, cap) != 0) {
        out_file_abort(&of);
        return -1;
    }
    return out_file_commit(&of, err, cap);
}
