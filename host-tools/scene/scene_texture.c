/* scene_texture.c: an image file a scene or a model names (a model's
 * texture, a map statement's image) opened only where it may be, and the
 * rule for a directory the user allows more images from
 * (scene_import.h: sd_image_open_below, sd_texture_open,
 * sd_textures_from_ok). */
#define _GNU_SOURCE
#include <errno.h>
#include <limits.h>
#include <pwd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "host-tools/image/image_io.h"
#include "host-tools/scene/scene_import.h"

int sd_image_below(const char *dir, const char *real)
{
    char r[PATH_MAX];
    if (!dir || !realpath(dir[0] ? dir : ".", r))
        return 0;
    size_t n = strlen(r);
    if (n == 1 && r[0] == '/')
        return 1; /* a file in / itself names everything below */
    return strncmp(real, r, n) == 0 && real[n] == '/';
}

/* real lies below one of the directories of the NULL-ended list allow. */
static int sd_image_below_any(const char *const *allow, const char *real)
{
    for (int i = 0; allow && allow[i]; i++)
        if (sd_image_below(allow[i], real))
            return 1;
    return 0;
}

/* The allowed directories as a message lists them: " and A, B". */
static void sd_image_allowed(const char *const *allow, char *out, size_t cap)
{
    out[0] = 0;
    for (int i = 0; allow && allow[i]; i++) {
        size_t n = strlen(out);
        snprintf(out + n, cap - n, "%s%s", i ? ", " : " and ", allow[i]);
    }
}

/* Why name (resolved to real) is not read: outside dir and allow. */
static void sd_image_outside(const char *path, const char *dir, const char *const *allow,
                             enum sd_image_owner owner, char *err, size_t errlen)
{
    char also[1024];
    sd_image_allowed(allow, also, sizeof also);
    if (owner == SD_IMAGE_OF_MODEL)
        snprintf(err, errlen, "%s: outside the model's directory %s%s; not read "
                 "(`textures_from \"DIR\"` in the model statement, or `links1 import "
                 "--textures-from DIR`, allows another)", path, dir[0] ? dir : ".", also);
    else
        snprintf(err, errlen, "%s: outside the scene's directory %s%s; not read (a map's "
                 "image lies below the scene file's directory, or below a directory given "
                 "with --textures-from DIR)", path, dir[0] ? dir : ".", also);
}

int sd_image_open_below(const char *name, const char *dir, const char *const *allow,
                        enum sd_image_owner owner, char *path, size_t cap, char *err,
                        size_t errlen)
{
    snprintf(path, cap, "%s%s", name[0] == '/' ? "" : dir, name);
    char real[PATH_MAX];
    if (!realpath(path, real)) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    if (!sd_image_below(dir, real) && !sd_image_below_any(allow, real)) {
        sd_image_outside(path, dir, allow, owner, err, errlen);
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

int sd_texture_open(const char *tex, const char *model_dir, const char *allow, char *path,
                    size_t cap, char *err, size_t errlen)
{
    const char *list[2] = {allow, NULL};
    return sd_image_open_below(tex, model_dir, list, SD_IMAGE_OF_MODEL, path, cap, err,
                               errlen);
}

/* real is the invoking user's home directory. */
static int sd_is_home(const char *real)
{
    struct passwd *pw = getpwuid(getuid());
    char home[PATH_MAX];
    return pw && pw->pw_dir && realpath(pw->pw_dir, home) && strcmp(home, real) == 0;
}

int sd_textures_from_ok(const char *dir, const char *what, char *err, size_t errlen)
{
    char real[PATH_MAX];
    struct stat st;
    if (!realpath(dir[0] ? dir : ".", real) || stat(real, &st) != 0) {
        snprintf(err, errlen, "%s \"%s\": %s", what, dir, strerror(errno));
        return -1;
    }
    if (!S_ISDIR(st.st_mode)) {
        snprintf(err, errlen, "%s \"%s\": not a directory", what, dir);
        return -1;
    }
    const char *why = strcmp(real, "/") == 0 ? "the root of the file system"
                      : strchr(real + 1, '/') == NULL ? "a directory directly under / "
                                                        "(a system root such as /etc, /home, "
                                                        "/tmp, /usr)"
                      : sd_is_home(real) ? "your home directory"
                      : NULL;
    if (!why)
        return 0;
    snprintf(err, errlen, "%s \"%s\": %s is %s, which would allow images from too much of "
             "the system; refused: name the directory that holds the images",
             what, dir, real, why);
    return -1;
}
