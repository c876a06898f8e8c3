/* out_file.c: an output file written whole through a temporary file
 * beside it (out_file.h). */
#define _GNU_SOURCE
#include "host-tools/opts/out_file.h"
#include "host-tools/opts/exit_clean.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The most characters of OUT's name kept in the temporary file's name
 * (".NAME.XXXXXX" must stay within a file name's 255). */
#define OUT_FILE_NAME_KEEP 200

/* OUT missing or a regular file: 0; else -1 with why in err. */
static int out_file_target_ok(const char *path, char *err, size_t cap)
{
    struct stat st;
    if (lstat(path, &st) != 0) {
        if (errno == ENOENT)
            return 0;
        snprintf(err, cap, "%s: %s", path, strerror(errno));
        return -1;
    }
    if (S_ISREG(st.st_mode))
        return 0;
    const char *what = S_ISLNK(st.st_mode)  ? "a symbolic link"
                       : S_ISDIR(st.st_mode) ? "a directory"
                       : S_ISFIFO(st.st_mode) ? "a FIFO"
                       : S_ISSOCK(st.st_mode) ? "a socket"
                                              : "a device";
    snprintf(err, cap, "%s is %s, not a regular file: not written through or replaced "
             "(remove it, or write elsewhere)", path, what);
    return -1;
}

/* The temporary file removed (or renamed away) and unregistered. */
static void out_file_forget(struct out_file *o)
{
    if (o->tmp[0]) {
        unlink(o->tmp);
        exit_clean_drop(o->tmp);
    }
    o->tmp[0] = 0;
}

int out_file_check(const char *path, char *err, size_t cap)
{
    if (strlen(path) >= PATH_MAX || !*path) {
        snprintf(err, cap, "%.200s...: not a usable output path", path);
        return -1;
    }
    if (out_file_target_ok(path, err, cap) < 0)
        return -1;
    /* Its directory: where the temporary file is made. */
    char dir[PATH_MAX];
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else
        snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
    struct stat st;
    const char *why = stat(dir, &st) != 0            ? strerror(errno)
                      : !S_ISDIR(st.st_mode)          ? "not a directory"
                      : access(dir, W_OK | X_OK) != 0 ? "you cannot make a file in it"
                                                      : NULL;
    if (why) {
        snprintf(err, cap, "%s: its directory %s: %s", path, dir, why);
        return -1;
    }
    return 0;
}

int out_file_open(struct out_file *o, const char *path, char *err, size_t cap)
{
    memset(o, 0, sizeof *o);
    if (out_file_check(path, err, cap) < 0)
        return -1;
    memcpy(o->path, path, strlen(path) + 1);
    const char *slash = strrchr(path, '/');
    const char *name = slash ? slash + 1 : path;
    int dirlen = slash ? (int)(slash - path) + 1 : 0;
    if (snprintf(o->tmp, sizeof o->tmp, "%.*s.%.*s.XXXXXX", dirlen, path, OUT_FILE_NAME_KEEP,
                 name) >= (int)sizeof o->tmp) {
        snprintf(err, cap, "%s: path too long", path);
        return -1;
    }
    sigset_t held;
    exit_clean_hold(&held); /* made and registered before a signal can end us */
    int fd = mkostemp(o->tmp, O_CLOEXEC);
    if (fd >= 0)
        exit_clean_add(o->tmp, EXIT_CLEAN_FILE);
    exit_clean_release(&held);
    if (fd < 0) {
        snprintf(err, cap, "%s: cannot make a temporary file beside it: %s", path,
                 strerror(errno));
        o->tmp[0] = 0;
        return -1;
    }
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0 || !(o->f = fdopen(fd, "wb"))) {
        snprintf(err, cap, "%s: %s", o->tmp, strerror(errno));
        close(fd);
        out_file_forget(o);
        return -1;
    }
    return 0;
}

int out_file_commit(struct out_file *o, char *err, size_t cap)
{
    if (!o->f) {
        snprintf(err, cap, "%s: not open", o->path);
        return -1;
    }
    int ok = fflush(o->f) == 0 && !ferror(o->f) && fsync(fileno(o->f)) == 0;
    int saved = errno;
    if (fclose(o->f) != 0 && ok) {
        ok = 0;
        saved = errno;
    }
    o->f = NULL;
    if (ok && out_file_target_ok(o->path, err, cap) < 0) { /* changed meanwhile */
        out_file_forget(o);
        return -1;
    }
    if (ok && rename(o->tmp, o->path) != 0) {
        ok = 0;
        saved = errno;
    }
    if (!ok) {
        snprintf(err, cap, "%s: writing it failed: %s", o->path, strerror(saved));
        unlink(o->tmp);
    }
    exit_clean_drop(o->tmp); /* removed, or renamed: OUT now */
    o->tmp[0] = 0;
    return ok ? 0 : -1;
}

void out_file_abort(struct out_file *o)
{
    if (o->f)
        fclose(o->f);
    o->f = NULL;
    out_file_forget(o);
}

int out_file_copy(const char *from, const char *path, char *err, size_t cap)
{
    int in = open(from, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st;
    if (in < 0 || fstat(in, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, cap, "%s: %s", from, in < 0 ? strerror(errno) : "not a regular file");
        if (in >= 0)
            close(in);
        return -1;
    }
    struct out_file o;
    if (out_file_open(&o, path, err, cap) != 0) {
        close(in);
        return -1;
    }
    char buf[65536];
    ssize_t n;
    while ((n = read(in, buf, sizeof buf)) > 0)
        if (fwrite(buf, 1, (size_t)n, o.f) != (size_t)n)
            break;
    int failed = n != 0 || ferror(o.f);
    int saved = errno;
    close(in);
    if (failed) {
        snprintf(err, cap, "%s: copying %s: %s", path, from, strerror(saved));
        out_file_abort(&o);
        return -1;
    }
    return out_file_commit(&o, err, cap);
}

int out_file_write(const char *path, const void *data, size_t len, char *err, size_t cap)
{
    struct out_file o;
    if (out_file_open(&o, path, err, cap) != 0)
        return -1;
    if (fwrite(data, 1, len, o.f) != len) {
        snprintf(err, cap, "%s: write failed: %s", path, strerror(errno));
        out_file_abort(&o);
        return -1;
    }
    return out_file_commit(&o, err, cap);
}
