/* tmp_dir.c: a temporary directory removed (see tmp_dir.h). */
#define _GNU_SOURCE
#include "host-tools/opts/tmp_dir.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define TMP_DIR_MAX_DEPTH 16 /* deeper than anything a command makes */

/* Empties the directory open as dfd (closed here). */
static int tmp_dir_empty(int dfd, int depth)
{
    DIR *d = fdopendir(dfd);
    if (!d) {
        close(dfd);
        return -1;
    }
    int rc = 0, saved = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        struct stat st;
        if (fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0)
            continue;
        int flags = 0;
        if (S_ISDIR(st.st_mode)) {
            int sub = depth < TMP_DIR_MAX_DEPTH
                          ? openat(dirfd(d), e->d_name,
                                   O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC)
                          : -1;
            if (sub < 0 || tmp_dir_empty(sub, depth + 1) != 0) {
                rc = -1;
                saved = errno ? errno : ENOTEMPTY;
                continue;
            }
            flags = AT_REMOVEDIR;
        }
        if (unlinkat(dirfd(d), e->d_name, flags) != 0) {
            rc = -1;
            saved = errno;
        }
    }
    closedir(d);
    if (rc)
        errno = saved;
    return rc;
}

int tmp_dir_remove(const char *path)
{
    int dfd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (dfd < 0)
        return -1;
    if (tmp_dir_empty(dfd, 0) != 0)
        return -1;
    return rmdir(path);
}
