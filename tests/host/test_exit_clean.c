/* Host tests of what a signal leaves (host-tools/opts/exit_clean.c): a
 * program that installed the handlers and registered a private directory
 * (with files, a subdirectory and a link to a file outside it), an
 * out_file's temporary file and a child, then gets SIGINT, SIGTERM or
 * SIGHUP: it dies of that signal, the directory and the temporary file are
 * gone, the link's target is untouched and the child has ended, and so
 * has what a child registered as a process group (exit_clean_add_group)
 * started without exec, as a $QEMU wrapper script starts QEMU; SIGTSTP
 * (^Z) stops such a group with the program and SIGCONT continues both; a
 * directory unregistered stays; a child the program forks (not exec'ed)
 * that gets the signal just dies, leaving its parent's files; stale
 * links1-WHAT-PID-* directories of a dead process are swept by the next
 * tmp_dir_make, a live process's are not. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host-tools/opts/exit_clean.h"
#include "host-tools/opts/out_file.h"
#include "host-tools/opts/tmp_dir.h"
#include "tests/check.h"

static char base[64];     /* the test's own directory: TMPDIR */
static char outside[128]; /* a file the planted link points at */

static int exists(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0;
}

/* What the child reports through the pipe: its private dir, the out_file's
 * temporary file, its own child's pid, and a kept directory. */
struct report {
    char dir[PATH_MAX], tmp[PATH_MAX], kept[PATH_MAX];
    pid_t grandchild;
    pid_t group_leader, group_member; /* exit_clean_add_group's, and its child */
};

/* pid's state letter in /proc (R, S, T, Z, ...), 0 when it is gone. */
static char state_of(pid_t pid)
{
    char path[64], stat[256] = "";
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    int fd = open(path, O_RDONLY);
    if (fd < 0)
        return 0;
    ssize_t n = read(fd, stat, sizeof stat - 1);
    close(fd);
    const char *end = n > 0 ? strrchr(stat, ')') : NULL; /* "pid (comm) S ..." */
    return end && end[1] == ' ' ? end[2] : 0;
}

/* A zombie counts as gone: an orphan waits there for init to reap it. */
static int gone(pid_t pid)
{
    char st = state_of(pid);
    return st == 0 || st == 'Z';
}

/* pid stopped (want 1) or not (0) within two seconds */
static int stopped_soon(pid_t pid, int want)
{
    for (int i = 0; i < 200 && (state_of(pid) == 'T') != want; i++)
        usleep(10000);
    return (state_of(pid) == 'T') == want;
}

/* gone(pid) within two seconds */
static int gone_soon(pid_t pid)
{
    for (int i = 0; i < 200 && !gone(pid); i++)
        usleep(10000);
    return gone(pid);
}

/* A child leading a group of its own (exit_clean_in_child_group) that
 * starts a process without exec, as a $QEMU wrapper script does; both
 * sleep.  The leader's pid, the other's in *member. */
static pid_t start_group(pid_t *member)
{
    int fds[2];
    if (pipe(fds) != 0)
        _exit(2);
    pid_t g = fork();
    if (g == 0) {
        exit_clean_in_child_group();
        pid_t m = fork();
        if (m == 0) {
            execlp("sleep", "sleep", "30", (char *)NULL);
            _exit(127);
        }
        if (write(fds[1], &m, sizeof m) != (ssize_t)sizeof m)
            _exit(2);
        execlp("sleep", "sleep", "30", (char *)NULL);
        _exit(127);
    }
    exit_clean_add_group(g);
    close(fds[1]);
    if (read(fds[0], member, sizeof *member) != (ssize_t)sizeof *member)
        _exit(2);
    close(fds[0]);
    return g;
}

static void child_side(int fd, int keep_one)
{
    signal(SIGINT, SIG_DFL); /* a test run in the background has SIGINT ignored */
    signal(SIGHUP, SIG_DFL);
    exit_clean_install();
    struct report r;
    memset(&r, 0, sizeof r);
    char err[256], p[PATH_MAX + 32];
    if (tmp_dir_make("test", r.dir, sizeof r.dir) != 0)
        _exit(2);
    snprintf(p, sizeof p, "%s/a", r.dir);
    close(open(p, O_WRONLY | O_CREAT, 0600));
    snprintf(p, sizeof p, "%s/sub", r.dir);
    mkdir(p, 0700);
    snprintf(p, sizeof p, "%s/sub/b", r.dir);
    close(open(p, O_WRONLY | O_CREAT, 0600));
    snprintf(p, sizeof p, "%s/sub/link", r.dir);
    if (symlink(outside, p) != 0)
        _exit(2);
    if (keep_one) { /* made and dropped: not removed by the signal */
        if (tmp_dir_make("kept", r.kept, sizeof r.kept) != 0)
            _exit(2);
        exit_clean_drop(r.kept);
    }
    struct out_file o;
    snprintf(p, sizeof p, "%s/out.txt", base);
    if (out_file_open(&o, p, err, sizeof err) != 0)
        _exit(2);
    snprintf(r.tmp, sizeof r.tmp, "%s", o.tmp);
    pid_t g = fork();
    if (g == 0) {
        exit_clean_in_child();
        execlp("sleep", "sleep", "30", (char *)NULL);
        _exit(127);
    }
    exit_clean_add_child(g);
    r.grandchild = g;
    r.group_leader = start_group(&r.group_member);
    if (write(fd, &r, sizeof r) != (ssize_t)sizeof r)
        _exit(2);
    close(fd);
    for (;;)
        pause();
}

/* Runs child_side, sends sig once it has reported; its wait status. */
static int run_child(int sig, int keep_one, struct report *r)
{
    int fds[2];
    if (pipe(fds) != 0)
        return -1;
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        child_side(fds[1], keep_one);
    }
    close(fds[1]);
    ssize_t n = read(fds[0], r, sizeof *r);
    close(fds[0]);
    if (n != (ssize_t)sizeof *r) {
        kill(pid, SIGKILL);
        waitpid(pid, NULL, 0);
        return -1;
    }
    kill(pid, sig);
    int st = 0;
    waitpid(pid, &st, 0);
    return st;
}

static void check_signal(int sig, int keep_one)
{
    struct report r;
    int st = run_child(sig, keep_one, &r);
    CHECK(st != -1 && WIFSIGNALED(st) && WTERMSIG(st) == sig);
    CHECK(!exists(r.dir));
    CHECK(!exists(r.tmp));
    CHECK(exists(outside)); /* the link removed, not followed */
    CHECK(kill(r.grandchild, 0) != 0 && errno == ESRCH);
    CHECK(gone_soon(r.group_leader));
    CHECK(gone_soon(r.group_member)); /* not the leader's child alone: its group */
    if (keep_one) {
        CHECK(exists(r.kept));
        tmp_dir_remove(r.kept);
    }
}

/* ^Z: a program with a group registered gets SIGTSTP: it stops, and so
 * does the group (its leader and the process the leader started); SIGCONT
 * continues all three; SIGTERM then ends them. */
static void exit_clean_sigtstp_stops_groups(void)
{
    int fds[2];
    CHECK(pipe(fds) == 0);
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        signal(SIGTSTP, SIG_DFL); /* a test run in the background may ignore it */
        exit_clean_install();
        pid_t pids[2];
        pids[0] = start_group(&pids[1]);
        if (write(fds[1], pids, sizeof pids) != (ssize_t)sizeof pids)
            _exit(2);
        for (;;)
            pause();
    }
    close(fds[1]);
    pid_t pids[2] = {0, 0};
    int got = read(fds[0], pids, sizeof pids) == (ssize_t)sizeof pids;
    close(fds[0]);
    CHECK(got);
    int st = 0;
    kill(pid, SIGTSTP);
    CHECK(waitpid(pid, &st, WUNTRACED) == pid && WIFSTOPPED(st));
    CHECK(got && stopped_soon(pids[0], 1) && stopped_soon(pids[1], 1));
    kill(pid, SIGCONT);
    CHECK(waitpid(pid, &st, WCONTINUED) == pid && WIFCONTINUED(st));
    CHECK(got && stopped_soon(pids[0], 0) && stopped_soon(pids[1], 0));
    kill(pid, SIGTERM);
    waitpid(pid, &st, 0);
    CHECK(WIFSIGNALED(st) && WTERMSIG(st) == SIGTERM);
    CHECK(got && gone_soon(pids[0]) && gone_soon(pids[1]));
}

static void exit_clean_sigterm_cleans(void) { check_signal(SIGTERM, 0); }
static void exit_clean_sigint_cleans(void) { check_signal(SIGINT, 1); }
static void exit_clean_sighup_cleans(void) { check_signal(SIGHUP, 0); }

/* A forked child (no exec) that gets the signal dies of it and removes
 * nothing of its parent's. */
static void exit_clean_forked_child_leaves_parent(void)
{
    exit_clean_install();
    char dir[PATH_MAX];
    CHECK_EQ_INT(tmp_dir_make("parent", dir, sizeof dir), 0);
    pid_t pid = fork();
    if (pid == 0) {
        raise(SIGTERM);
        _exit(0);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    CHECK(WIFSIGNALED(st) && WTERMSIG(st) == SIGTERM);
    CHECK(exists(dir));
    CHECK_EQ_INT(tmp_dir_remove(dir), 0);
    CHECK(!exists(dir));
}

/* A dead process's links1-WHAT-PID-* swept; a live one's and a link kept. */
static void exit_clean_stale_swept(void)
{
    pid_t dead = fork();
    if (dead == 0)
        _exit(0);
    waitpid(dead, NULL, 0);
    char stale[PATH_MAX], live[PATH_MAX], link[PATH_MAX], open_dir[PATH_MAX], fresh[PATH_MAX];
    snprintf(stale, sizeof stale, "%s/links1-sweep-%d-abcdef", base, (int)dead);
    snprintf(open_dir, sizeof open_dir, "%s/links1-sweep-%d-ghijkl", base, (int)dead);
    snprintf(live, sizeof live, "%s/links1-sweep-%d-abcdef", base, (int)getppid());
    snprintf(link, sizeof link, "%s/links1-sweep-%d-zzzzzz", base, (int)dead);
    CHECK(mkdir(stale, 0700) == 0 && mkdir(live, 0700) == 0 && mkdir(open_dir, 0755) == 0);
    CHECK(symlink(outside, link) == 0);
    char f[PATH_MAX + 8];
    snprintf(f, sizeof f, "%s/x", stale);
    close(open(f, O_WRONLY | O_CREAT, 0600));
    CHECK_EQ_INT(tmp_dir_make("sweep", fresh, sizeof fresh), 0);
    CHECK(!exists(stale));
    CHECK(exists(live));
    CHECK(exists(open_dir)); /* open to others: not one of ours */
    CHECK(exists(link) && exists(outside));
    struct stat st;
    CHECK(stat(fresh, &st) == 0 && (st.st_mode & 0777) == 0700 && st.st_uid == geteuid());
    tmp_dir_remove(fresh);
    rmdir(live);
    rmdir(open_dir);
    unlink(link);
}

int main(void)
{
    snprintf(base, sizeof base, "/tmp/links1-test-exit-clean.XXXXXX");
    if (!mkdtemp(base)) {
        perror("mkdtemp");
        return 1;
    }
    setenv("TMPDIR", base, 1);
    snprintf(outside, sizeof outside, "%s/outside.txt", base);
    close(open(outside, O_WRONLY | O_CREAT, 0600));
    RUN(exit_clean_sigterm_cleans);
    RUN(exit_clean_sigint_cleans);
    RUN(exit_clean_sighup_cleans);
    RUN(exit_clean_sigtstp_stops_groups);
    RUN(exit_clean_forked_child_leaves_parent);
    RUN(exit_clean_stale_swept);
    unlink(outside);
    tmp_dir_remove(base);
    return check_exit();
}
