/* Host tests of private paths (host-tools/opts/private_path.c): a file or
 * directory of yours that only you can write is taken, resolved, a link on
 * the way above it followed; one that its group or others may write, or
 * that sits under such a directory (not sticky), is refused naming the fix;
 * a symbolic link, a FIFO and the wrong kind are refused without hanging. */
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "host-tools/opts/private_path.h"
#include "host-tools/opts/tmp_dir.h"
#include "tests/check.h"

static char dir[64];

static void at(char *out, size_t cap, const char *name)
{
    snprintf(out, cap, "%s/%s", dir, name);
}

/* A file name below dir made with mode. */
static void make_file(const char *name, mode_t mode)
{
    char path[128];
    at(path, sizeof path, name);
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd >= 0) {
        (void)!write(fd, ":\n", 2);
        close(fd);
    }
    chmod(path, mode);
}

/* private_path_open on name below dir: 1 when taken (fd closed), else 0
 * with the message in err, which must hold want. */
static int taken(const char *name, enum private_path_kind kind, const char *want)
{
    char path[128], real[PATH_MAX], err[2 * PATH_MAX + 512];
    at(path, sizeof path, name);
    err[0] = 0;
    int fd = private_path_open(path, kind, real, err, sizeof err);
    if (fd >= 0) {
        close(fd);
        return 1;
    }
    if (!strstr(err, want))
        printf("  message: %s (want '%s')\n", err, want);
    return strstr(err, want) ? 0 : -1;
}

static void private_path_takes_yours(void)
{
    char path[128], real[PATH_MAX], want[PATH_MAX], err[1024];
    make_file("hosts", 0644);
    CHECK_EQ_INT(taken("hosts", PRIVATE_PATH_FILE, ""), 1);
    CHECK_EQ_INT(taken(".", PRIVATE_PATH_DIR, ""), 1);
    /* a link on the way above is followed; real is the resolved path */
    at(path, sizeof path, "sub");
    mkdir(path, 0755);
    make_file("sub/f", 0600);
    at(path, sizeof path, "via");
    CHECK(symlink("sub", path) == 0);
    at(path, sizeof path, "via/f");
    int fd = private_path_open(path, PRIVATE_PATH_FILE, real, err, sizeof err);
    CHECK(fd >= 0);
    if (fd >= 0)
        close(fd);
    at(path, sizeof path, "sub/f");
    CHECK(realpath(path, want) && strcmp(real, want) == 0);
    /* a sticky world-writable directory above (like /tmp) is fine */
    at(path, sizeof path, "sticky");
    mkdir(path, 0700);
    chmod(path, 01777);
    make_file("sticky/hosts", 0644);
    CHECK_EQ_INT(taken("sticky/hosts", PRIVATE_PATH_FILE, ""), 1);
}

static void private_path_refuses_writable(void)
{
    char path[128];
    make_file("w666", 0666);
    CHECK_EQ_INT(taken("w666", PRIVATE_PATH_FILE, "mode 0666, its group or others may write it: "
                                                  "refused (chmod go-w "), 0);
    make_file("w620", 0620);
    CHECK_EQ_INT(taken("w620", PRIVATE_PATH_FILE, "mode 0620"), 0);
    at(path, sizeof path, "d2775");
    mkdir(path, 0700);
    chmod(path, 02775);
    CHECK_EQ_INT(taken("d2775", PRIVATE_PATH_DIR, "mode 2775"), 0);
    /* a file of mode 0644 under a directory its group may write */
    make_file("d2775/hosts", 0644);
    CHECK_EQ_INT(taken("d2775/hosts", PRIVATE_PATH_FILE, "/d2775 above it has mode 2775, its "
                                                         "group or others can replace"), 0);
}

static void private_path_refuses_links_and_kinds(void)
{
    char path[128], target[128];
    make_file("target", 0644);
    at(path, sizeof path, "link");
    at(target, sizeof target, "target");
    CHECK(symlink(target, path) == 0);
    CHECK_EQ_INT(taken("link", PRIVATE_PATH_FILE, "a symbolic link: refused"), 0);
    at(path, sizeof path, "dlink");
    CHECK(symlink(".", path) == 0);
    CHECK_EQ_INT(taken("dlink", PRIVATE_PATH_DIR, "a symbolic link: refused"), 0);
    at(path, sizeof path, "fifo");
    CHECK(mkfifo(path, 0600) == 0);
    CHECK_EQ_INT(taken("fifo", PRIVATE_PATH_FILE, "not a regular file"), 0);
    CHECK_EQ_INT(taken("target", PRIVATE_PATH_DIR, "not a directory"), 0);
    CHECK_EQ_INT(taken("missing", PRIVATE_PATH_FILE, "cannot read it: No such file"), 0);
}

int main(void)
{
    umask(022);
    snprintf(dir, sizeof dir, "/tmp/links1-private-XXXXXX");
    if (!mkdtemp(dir)) {
        printf("FAIL test_private_path: mkdtemp\n");
        return 1;
    }
    RUN(private_path_takes_yours);
    RUN(private_path_refuses_writable);
    RUN(private_path_refuses_links_and_kinds);
    tmp_dir_remove(dir);
    return check_exit();
}
