/* tmp_dir.h: a command's private temporary directories and files: made
 * where no one else can reach them ($TMPDIR when it is an absolute path,
 * else /tmp; mkdtemp 0700 or mkostemp 0600, names no one can predict,
 * links1-WHAT-PID-XXXXXX), registered with exit_clean so that a signal
 * removes them too, and removed with no shell and without following a
 * link planted inside. */
#ifndef LINKS1_HOST_OPTS_TMP_DIR_H
#define LINKS1_HOST_OPTS_TMP_DIR_H

#include <stddef.h>

/* A private directory $TMPDIR/links1-WHAT-PID-XXXXXX (mode 0700) made
 * into out and registered with exit_clean.  First, directories and files
 * links1-WHAT-PID-* of this user's whose process PID is gone (a run ended
 * by SIGKILL) are removed: only real directories and regular files owned
 * by this user with no group or other access, never a link.  0, or -1
 * with errno set (nothing made). */
int tmp_dir_make(const char *what, char *out, size_t cap);

/* A private file $TMPDIR/links1-WHAT-PID-XXXXXX (mode 0600, O_CLOEXEC)
 * made into out and registered with exit_clean: its descriptor, or -1
 * with errno set. */
int tmp_file_make(const char *what, char *out, size_t cap);

/* The file tmp_file_make made unlinked and unregistered. */
void tmp_file_remove(const char *path);

/* Removes path and everything under it (and unregisters it); a symbolic link is removed, never
 * followed.  0, or -1 with errno set (what could be removed is gone). */
int tmp_dir_remove(const char *path);

#endif
