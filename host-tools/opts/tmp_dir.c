/* tmp_dir.c: a temporary directory removed (see tmp_dir.h). */
#define _GNU_SOURCE
#include "host-tools/opts/tmp_dir.h"
#include "host-tools/opts/exit_clean.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
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
    int rc = rmdir(path);
    if (rc == 0)
        exit_clean_drop(path);
    return rc;
}

/* Where the temporary files go: $TMPDIR when it is an absolute path of a
 * sensible length, else /tmp. */
static const char *tmp_base(void)
{
    const char *t = getenv("TMPDIR");
    return t && t[0] == '/' && strlen(t) < PATH_MAX / 2 ? t : "/tmp";
}

/* Removes base/name when it is a stale links1-WHAT-PID-* of this user's:
 * a real directory or regular file, owned by this user, no group or other
 * access, and no process PID. */
static void tmp_sweep_one(int base_fd, const char *base, const char *name, size_t prefix)
{
    char *end;
    errno = 0;
    long pid = strtol(name + prefix, &end, 10);
    if (errno || end == name + prefix || *end != '-' || pid <= 0 || pid > INT_MAX ||
        pid == (long)getpid() || kill((pid_t)pid, 0) == 0 || errno != ESRCH)
        return;
    struct stat st;
    if (fstatat(base_fd, name, &st, AT_SYMLINK_NOFOLLOW) != 0 || st.st_uid != geteuid() ||
        (st.st_mode & 077) != 0)
        return;
    char path[PATH_MAX];
    if (snprintf(path, sizeof path, "%s/%s", base, name) >= (int)sizeof path)
        return;
    if (S_ISDIR(st.st_mode))
        tmp_dir_remove(path);
    else if (S_ISREG(st.st_mode))
        unlinkat(base_fd, name, 0);
}

/* Every stale links1-WHAT-PID-* of this user's in base removed. */
static void tmp_sweep(const char *base, const char *what)
{
    char prefix[64];
    int n = snprintf(prefix, sizeof prefix, "links1-%s-", what);
    if (n < 0 || n >= (int)sizeof prefix)
        return;
    DIR *d = opendir(base);
    if (!d)
        return;
    for (struct dirent *e; (e = readdir(d));)
        if (strncmp(e->d_name, prefix, (size_t)n) == 0)
            tmp_sweep_one(dirfd(d), base, e->d_name, (size_t)n);
    closedir(d);
}

/* base/links1-WHAT-PID-XXXXXX into out: 0, or -1 (ENAMETOOLONG). */
static int tmp_template(const char *base, const char *what, char *out, size_t cap)
{
    int n = snprintf(out, cap, "%s/links1-%s-%d-XXXXXX", base, what, (int)getpid());
    if (n < 0 || (size_t)n >= cap) {
        errno = ENAMETOOLONG;
        return -1;
    }
    return 0;
}

/* The name template of a new temporary WHAT in $TMPDIR into out, a
 * killed run's WHATs swept first.  0, or -1 (too long). */
static int tmp_name(const char *what, char *out, size_t cap)
{
    const char *base = tmp_base();
    tmp_sweep(base, what);
    return tmp_template(base, what, out, cap);
}

int tmp_dir_make(const char *what, char *out, size_t cap)
{
    if (tmp_name(what, out, cap) < 0)
        return -1;
    sigset_t old;
    exit_clean_hold(&old);
    int rc = mkdtemp(out) ? 0 : -1;
    int saved = errno;
    if (rc == 0)
        exit_clean_add(out, EXIT_CLEAN_DIR);
    exit_clean_release(&old);
    errno = saved;
    return rc;
}

int tmp_file_make(const char *what, char *out, size_t cap)
{
    if (tmp_name(what, out, cap) < 0)
        return -1;
    sigset_t old;
    exit_clean_hold(&old);
    int fd = mkostemp(out, O_CLOEXEC);
    int saved = errno;
    if (fd >= 0)
        exit_clean_add(out, EXIT_CLEAN_FILE);
    exit_clean_release(&old);
    errno = saved;
    return fd;
}

void tmp_file_remove(const char *path)
{
    unlink(path);
    exit_clean_drop(path);
}
