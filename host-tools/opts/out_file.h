/* out_file.h: an output file (every command's -o OUT, render's frames and
 * --trace) written whole or not at all, and never through anything planted
 * beside it: the bytes go to a temporary file that mkstemp makes in OUT's
 * own directory (a name no one can predict, O_EXCL), which is flushed,
 * fsync'ed and then renamed over OUT; on any error it is removed.  OUT
 * itself must be missing or a regular file: a symbolic link, a FIFO, a
 * device or a directory there is refused, not written through or replaced.
 * The file gets the mode a plain create would (0666 less the umask). */
#ifndef LINKS1_HOST_OPTS_OUT_FILE_H
#define LINKS1_HOST_OPTS_OUT_FILE_H

#include <limits.h>
#include <stddef.h>
#include <stdio.h>

struct out_file {
    FILE *f;                /* write OUT's bytes here */
    char path[PATH_MAX];    /* OUT */
    char tmp[PATH_MAX];     /* the temporary file beside it */
};

/* OUT checked before any work is done for it (out_file_open checks it
 * again): a usable path, missing or a regular file, in a directory there
 * that this user can make a file in.  0, or -1 with "OUT: why" in err. */
int out_file_check(const char *path, char *err, size_t cap);

/* The temporary file for OUT opened in o->f.  0, or -1 with "OUT: why" in
 * err (nothing made). */
int out_file_open(struct out_file *o, const char *path, char *err, size_t cap);

/* o->f flushed, fsync'ed and closed, then renamed over OUT.  0, or -1
 * with "OUT: why" in err and the temporary file removed. */
int out_file_commit(struct out_file *o, char *err, size_t cap);

/* o->f closed and the temporary file removed (a write that failed);
 * nothing happens to OUT.  Safe to call on an o never opened (zeroed) or
 * already committed. */
void out_file_abort(struct out_file *o);

/* The file at from (a regular file of the command's own, from one of its
 * private directories; a link there is not followed) copied to OUT
 * through out_file_open and out_file_commit.  0, or -1 with why in err. */
int out_file_copy(const char *from, const char *path, char *err, size_t cap);

/* len bytes of data written to path whole or not at all.  0, or -1 with
 * "PATH: why" in err. */
int out_file_write(const char *path, const void *data, size_t len, char *err, size_t cap);

#endif
