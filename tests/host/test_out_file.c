/* Host tests of output files (host-tools/opts/out_file.c): written whole
 * through a temporary file beside OUT, with a plain create's mode; nothing
 * left after a write given up; OUT a symbolic link, a FIFO or a directory
 * refused, their targets untouched; a link planted at any name beside OUT
 * not written through. */
#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "host-tools/opts/out_file.h"
#include "host-tools/opts/tmp_dir.h"
#include "tests/check.h"

static char dir[64];

static int entries(void)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d)
        closedir(d);
    return n;
}

static void at(char *out, size_t cap, const char *name)
{
    snprintf(out, cap, "%s/%s", dir, name);
}

static void slurp(const char *path, char *out, size_t cap)
{
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(out, 1, cap - 1, f) : 0;
    out[n] = 0;
    if (f)
        fclose(f);
}

static void out_file_written_whole(void)
{
    char path[128], got[64], err[512];
    at(path, sizeof path, "a.txt");
    struct out_file o;
    mode_t mask = umask(022);
    CHECK_EQ_INT(out_file_open(&o, path, err, sizeof err), 0);
    fputs("first", o.f);
    CHECK(access(path, F_OK) != 0); /* nothing at OUT until the commit */
    CHECK_EQ_INT(out_file_commit(&o, err, sizeof err), 0);
    slurp(path, got, sizeof got);
    CHECK(strcmp(got, "first") == 0);
    struct stat st;
    CHECK(stat(path, &st) == 0 && (st.st_mode & 0777) == 0644);
    /* over an older OUT */
    CHECK_EQ_INT(out_file_open(&o, path, err, sizeof err), 0);
    fputs("second", o.f);
    CHECK_EQ_INT(out_file_commit(&o, err, sizeof err), 0);
    slurp(path, got, sizeof got);
    CHECK(strcmp(got, "second") == 0);
    CHECK_EQ_INT(entries(), 1);
    umask(mask);
    unlink(path);
}

static void out_file_abort_leaves_nothing(void)
{
    char path[128], err[512];
    at(path, sizeof path, "b.txt");
    struct out_file o;
    CHECK_EQ_INT(out_file_open(&o, path, err, sizeof err), 0);
    fputs("half", o.f);
    out_file_abort(&o);
    out_file_abort(&o); /* twice is harmless */
    CHECK_EQ_INT(entries(), 0);
    /* an OUT that cannot be put in place (a directory appeared there) */
    CHECK_EQ_INT(out_file_open(&o, path, err, sizeof err), 0);
    mkdir(path, 0700);
    CHECK_EQ_INT(out_file_commit(&o, err, sizeof err), -1);
    CHECK(strstr(err, "b.txt") && strstr(err, "directory"));
    CHECK_EQ_INT(entries(), 1);
    rmdir(path);
    /* no directory to put it in */
    char missing[160];
    at(missing, sizeof missing, "no/such/c.txt");
    CHECK_EQ_INT(out_file_open(&o, missing, err, sizeof err), -1);
    CHECK(strstr(err, "c.txt") != NULL);
}

static void out_file_refuses_odd_targets(void)
{
    char victim[128], link[128], fifo[128], sub[128], got[64], err[512];
    at(victim, sizeof victim, "victim");
    at(link, sizeof link, "link.png");
    at(fifo, sizeof fifo, "fifo.png");
    at(sub, sizeof sub, "sub.png");
    FILE *f = fopen(victim, "w");
    fputs("the victim's", f);
    fclose(f);
    CHECK(symlink(victim, link) == 0);
    CHECK(mkfifo(fifo, 0600) == 0);
    CHECK(mkdir(sub, 0700) == 0);
    struct out_file o;
    CHECK_EQ_INT(out_file_open(&o, link, err, sizeof err), -1);
    CHECK(strstr(err, "symbolic link") != NULL);
    CHECK_EQ_INT(out_file_open(&o, fifo, err, sizeof err), -1);
    CHECK(strstr(err, "FIFO") != NULL);
    CHECK_EQ_INT(out_file_open(&o, sub, err, sizeof err), -1);
    CHECK(strstr(err, "directory") != NULL);
    slurp(victim, got, sizeof got);
    CHECK(strcmp(got, "the victim's") == 0);
    struct stat st;
    CHECK(lstat(link, &st) == 0 && S_ISLNK(st.st_mode));
    CHECK(lstat(fifo, &st) == 0 && S_ISFIFO(st.st_mode));
    CHECK_EQ_INT(entries(), 4);
    /* a link planted at the old fixed names beside OUT is not used */
    char out[128], part[160];
    at(out, sizeof out, "frame.png");
    snprintf(part, sizeof part, "%s.part", out);
    CHECK(symlink(victim, part) == 0);
    CHECK_EQ_INT(out_file_open(&o, out, err, sizeof err), 0);
    fputs("frame", o.f);
    CHECK_EQ_INT(out_file_commit(&o, err, sizeof err), 0);
    slurp(victim, got, sizeof got);
    CHECK(strcmp(got, "the victim's") == 0);
    slurp(out, got, sizeof got);
    CHECK(strcmp(got, "frame") == 0);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/links1-out-XXXXXX");
    if (!mkdtemp(dir)) {
        printf("FAIL test_out_file: mkdtemp\n");
        return 1;
    }
    RUN(out_file_written_whole);
    RUN(out_file_abort_leaves_nothing);
    RUN(out_file_refuses_odd_targets);
    tmp_dir_remove(dir);
    return check_exit();
}
