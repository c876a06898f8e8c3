/* private_path.c: a file or directory only you (or root) can change (see
 * private_path.h). */
#include "host-tools/opts/private_path.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define PP_GO_WRITE (S_IWGRP | S_IWOTH)

/* Whether uid may own what a command trusts: you, or root. */
static int pp_trusted(uid_t uid)
{
    return uid == geteuid() || uid == 0;
}

static const char *pp_noun(enum private_path_kind kind)
{
    return kind == PRIVATE_PATH_DIR ? "directory" : "file";
}

/* What path names, looked at without following a link: of the kind
 * wanted.  0, or -1 with why in err. */
static int pp_lstat(const char *path, enum private_path_kind kind, struct stat *st, char *err,
                    size_t cap)
{
    if (lstat(path, st) != 0) {
        snprintf(err, cap, "%s: cannot read it: %s", path, strerror(errno));
        return -1;
    }
    if (S_ISLNK(st->st_mode)) {
        snprintf(err, cap, "%s: a symbolic link: refused, not followed (name the %s itself, "
                 "one of yours)", path, pp_noun(kind));
        return -1;
    }
    if (kind == PRIVATE_PATH_FILE ? !S_ISREG(st->st_mode) : !S_ISDIR(st->st_mode)) {
        snprintf(err, cap, "%s: not a %s", path,
                 kind == PRIVATE_PATH_FILE ? "regular file" : "directory");
        return -1;
    }
    return 0;
}

/* The path's own owner and mode.  0, or -1 with why in err. */
static int pp_own(const char *path, enum private_path_kind kind, const struct stat *st,
                  char *err, size_t cap)
{
    uid_t me = geteuid();
    if (st->st_uid != me && (kind == PRIVATE_PATH_DIR || st->st_uid != 0)) {
        snprintf(err, cap, "%s: the %s belongs to uid %u, not to you (uid %u)%s: refused (use "
                 "a %s of your own)", path, pp_noun(kind), (unsigned)st->st_uid, (unsigned)me,
                 kind == PRIVATE_PATH_FILE ? " or root" : "", pp_noun(kind));
        return -1;
    }
    if (st->st_mode & PP_GO_WRITE) {
        snprintf(err, cap, "%s: mode %04o, its group or others may write it: refused (chmod "
                 "go-w %s)", path, (unsigned)(st->st_mode & 07777), path);
        return -1;
    }
    return 0;
}

/* Every directory above real (resolved, absolute), up to /: owned by you
 * or root, and writable by no one else unless sticky with the entry below
 * it on the way yours or root's (child_uid, the path's own owner first).
 * 0, or -1 with why in err. */
static int pp_above(const char *path, const char *real, uid_t child_uid, char *err, size_t cap)
{
    char dir[PATH_MAX];
    snprintf(dir, sizeof dir, "%s", real);
    for (;;) {
        char *slash = strrchr(dir, '/');
        if (!slash || (slash == dir && dir[1] == 0))
            return 0; /* above / there is nothing */
        slash[slash == dir ? 1 : 0] = 0;
        struct stat st;
        if (lstat(dir, &st) != 0) {
            snprintf(err, cap, "%s: the directory %s above it: %s", path, dir, strerror(errno));
            return -1;
        }
        if (!pp_trusted(st.st_uid)) {
            snprintf(err, cap, "%s: the directory %s above it belongs to uid %u, who can replace "
                     "what is in it: refused (keep it under directories only you or root can "
                     "write)", path, dir, (unsigned)st.st_uid);
            return -1;
        }
        if ((st.st_mode & PP_GO_WRITE) && !((st.st_mode & S_ISVTX) && pp_trusted(child_uid))) {
            snprintf(err, cap, "%s: the directory %s above it has mode %04o, its group or others "
                     "can replace what is in it: refused (chmod go-w %s, or keep it under "
                     "directories only you or root can write)", path, dir,
                     (unsigned)(st.st_mode & 07777), dir);
            return -1;
        }
        child_uid = st.st_uid;
    }
}

int private_path_open(const char *path, enum private_path_kind kind, char *real, char *err,
                      size_t cap)
{
    struct stat st, fst, rst;
    if (pp_lstat(path, kind, &st, err, cap) != 0)
        return -1;
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY | O_NONBLOCK |
                            (kind == PRIVATE_PATH_DIR ? O_DIRECTORY : 0));
    if (fd < 0) {
        snprintf(err, cap, "%s: cannot read it: %s", path, strerror(errno));
        return -1;
    }
    if (!realpath(path, real)) {
        snprintf(err, cap, "%s: %s", path, strerror(errno));
        close(fd);
        return -1;
    }
    /* the file opened is the one looked at, and the one its resolved path names */
    if (fstat(fd, &fst) != 0 || fst.st_dev != st.st_dev || fst.st_ino != st.st_ino ||
        lstat(real, &rst) != 0 || rst.st_dev != st.st_dev || rst.st_ino != st.st_ino) {
        snprintf(err, cap, "%s: it changed while it was checked: refused", path);
        close(fd);
        return -1;
    }
    if (pp_own(path, kind, &fst, err, cap) != 0 || pp_above(path, real, fst.st_uid, err, cap) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}
