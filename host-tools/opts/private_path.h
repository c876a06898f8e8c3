/* private_path.h: a file or directory that only you (or root) can change,
 * checked before a command trusts what is in it (a file of commands it
 * hands on) or writes into it: not a symbolic link, owned by you (a file
 * may also be root's), no write bit for its group or others, and every
 * directory above it (the path resolved) writable by no one but you or
 * root, except a sticky one like /tmp, where no one can rename or remove
 * an entry of yours (or root's).  Used by `links1 farm` for its hosts file
 * and its output directory. */
#ifndef LINKS1_HOST_OPTS_PRIVATE_PATH_H
#define LINKS1_HOST_OPTS_PRIVATE_PATH_H

#include <stddef.h>

enum private_path_kind {
    PRIVATE_PATH_FILE, /* a regular file of yours or root's, to read */
    PRIVATE_PATH_DIR,  /* a directory of yours, to write into */
};

/* path opened read-only without following a link (a directory with
 * O_DIRECTORY) and checked as above.  Its fd (O_CLOEXEC), with path
 * resolved into real (PATH_MAX bytes); or -1 with "PATH: what is wrong
 * (the fix)" in err. */
int private_path_open(const char *path, enum private_path_kind kind, char *real, char *err,
                      size_t cap);

#endif
