/* scene_texture.c: a model's texture file opened only where it may be
 * (scene_import.h, sd_texture_open). */
#define _GNU_SOURCE
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "host-tools/image/image_io.h"
#include "host-tools/scene/scene_import.h"

/* real (a resolved path) lies below the directory dir (resolved here). */
static int sd_texture_below(const char *dir, const char *real)
{
    char r[PATH_MAX];
    if (!dir || !realpath(dir[0] ? dir : ".", r))
        return 0;
    size_t n = strlen(r);
    if (n == 1 && r[0] == '/')
        return 1; /* the user allowed everything */
    return strncmp(real, r, n) == 0 && real[n] == '/';
}

int sd_texture_open(const char *tex, const char *model_dir, const char *allow, char *path,
                    size_t cap, char *err, size_t errlen)
{
    snprintf(path, cap, "%s%s", tex[0] == '/' ? "" : model_dir, tex);
    char real[PATH_MAX];
    if (!realpath(path, real)) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    if (!sd_texture_below(model_dir, real) && !sd_texture_below(allow, real)) {
        snprintf(err, errlen, "%s: outside the model's directory %s%s%s; not read "
                 "(`textures_from \"DIR\"` in the model statement, or `links1 import "
                 "--textures-from DIR`, allows another)", path, model_dir[0] ? model_dir : ".",
                 allow ? " and " : "", allow ? allow : "");
        return -1;
    }
    /* What the path resolved to is opened, no link followed; it must
     * still be that file once open (nothing swapped in between). */
    int fd = image_open(real, 1, SCN_MAX_MAP_SIDE, err, errlen);
    if (fd < 0)
        return -1;
    char proc[64], now[PATH_MAX];
    snprintf(proc, sizeof proc, "/proc/self/fd/%d", fd);
    ssize_t n = readlink(proc, now, sizeof now - 1);
    if (n < 0 || (size_t)n != strlen(real) || memcmp(now, real, (size_t)n) != 0) {
        snprintf(err, errlen, "%s: changed while it was opened; not read", path);
        close(fd);
        return -1;
    }
    return fd;
}
