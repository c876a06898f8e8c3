/* tmp_dir.h: removing a temporary directory a command made (mkdtemp), with
 * no shell and without following a link planted inside it. */
#ifndef LINKS1_HOST_OPTS_TMP_DIR_H
#define LINKS1_HOST_OPTS_TMP_DIR_H

/* Removes path and everything under it; a symbolic link is removed, never
 * followed.  0, or -1 with errno set (what could be removed is gone). */
int tmp_dir_remove(const char *path);

#endif
