/* exit_clean.c: temporary files and children cleaned up when a signal ends
 * the program (exit_clean.h).  The registry is static arrays whose slots
 * are claimed and freed with atomic operations, so the handler, whichever
 * thread it runs on, sees a slot either whole or not at all; the handler
 * itself calls only async-signal-safe functions (kill, waitpid, nanosleep,
 * unlink, unlinkat, openat, the getdents64 system call, close, sigaction,
 * sigprocmask, raise, write, _Fork; the command's child then execvp, which
 * allocates nothing in glibc).  ^Z stops the registered process groups
 * with the program, and continuing it continues them. */
#define _GNU_SOURCE
#include "host-tools/opts/exit_clean.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define EXIT_CLEAN_DEPTH 8          /* deeper than any directory a command makes */
#define EXIT_CLEAN_DENTS 4096       /* bytes of directory entries read at a time */
#define EXIT_CLEAN_PASSES 16        /* re-reads of a directory still not empty */
#define EXIT_CLEAN_POLL_MS 10

enum ec_slot { EC_FREE, EC_READY, EC_FILLING };

struct ec_path {
    int state; /* enum ec_slot, atomically */
    enum exit_clean_kind kind;
    char path[PATH_MAX];
};

static struct ec_path ec_paths[EXIT_CLEAN_MAX_PATHS];
static pid_t ec_children[EXIT_CLEAN_MAX_CHILDREN]; /* 0: free; atomically */
static pid_t ec_owner;                             /* the process that installed */
static int ec_busy;                                /* a handler is cleaning */
static const int ec_signals[] = {SIGINT, SIGTERM, SIGHUP};
#define EC_NSIGNALS (int)(sizeof ec_signals / sizeof ec_signals[0])
static int ec_ignored[EC_NSIGNALS]; /* ignored when the program started */

/* A command's words and notes packed into buf (each ended by a 0): argv
 * points into it, done and failed are the notes' offsets. */
struct ec_command {
    int state; /* enum ec_slot, atomically */
    char buf[EXIT_CLEAN_COMMAND_BYTES];
    char *argv[EXIT_CLEAN_COMMAND_WORDS + 1];
    size_t done, failed;
};
static struct ec_command ec_commands[EXIT_CLEAN_MAX_COMMANDS];

/* The entries of a directory found in a getdents64 buffer. */
struct ec_dirent64 {
    uint64_t d_ino;
    int64_t d_off;
    unsigned short d_reclen;
    unsigned char d_type;
    char d_name[];
};
static char ec_dents[EXIT_CLEAN_DEPTH][EXIT_CLEAN_DENTS];

/* Removes one entry of the directory open as dfd: 1 when removed. */
static int ec_remove_entry(int dfd, const char *name, int depth);

/* Empties the directory open as dfd, re-reading it while a pass removes
 * something (removal under getdents may skip an entry). */
static void ec_empty(int dfd, int depth)
{
    for (int pass = 0; pass < EXIT_CLEAN_PASSES; pass++) {
        int removed = 0, left = 0;
        long n;
        lseek(dfd, 0, SEEK_SET);
        while ((n = syscall(SYS_getdents64, dfd, ec_dents[depth], EXIT_CLEAN_DENTS)) > 0) {
            for (long off = 0; off < n;) {
                struct ec_dirent64 *d = (struct ec_dirent64 *)(ec_dents[depth] + off);
                if (d->d_reclen == 0 || off + d->d_reclen > n)
                    break;
                off += d->d_reclen;
                const char *name = d->d_name;
                if (name[0] == '.' && (!name[1] || (name[1] == '.' && !name[2])))
                    continue;
                if (ec_remove_entry(dfd, name, depth))
                    removed++;
                else
                    left++;
            }
        }
        if (!left || !removed)
            return;
    }
}

static int ec_remove_entry(int dfd, const char *name, int depth)
{
    if (unlinkat(dfd, name, 0) == 0)
        return 1;
    if (errno != EISDIR || depth + 1 >= EXIT_CLEAN_DEPTH)
        return 0;
    int sub = openat(dfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (sub >= 0) {
        ec_empty(sub, depth + 1);
        close(sub);
    }
    return unlinkat(dfd, name, AT_REMOVEDIR) == 0;
}

static void ec_remove_dir(const char *path)
{
    int dfd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (dfd < 0)
        return;
    ec_empty(dfd, 0);
    close(dfd);
    rmdir(path);
}

/* The process a registry value names: v, or -v for its group. */
static pid_t ec_pid_of(pid_t v) { return v < 0 ? -v : v; }

/* sig to v: a process (v > 0), or -v's process group (v < 0), which is
 * then -v alone when it leads no group yet. */
static int ec_kill(pid_t v, int sig)
{
    int r = kill(v, sig);
    if (r == 0 || v > 0 || errno != ESRCH)
        return r;
    return kill(-v, sig);
}

static void ec_sleep_ms(long ms)
{
    struct timespec t = {0, ms * 1000000L};
    nanosleep(&t, NULL);
}

/* The n children of pids[] (0: none; -PID: PID and its process group)
 * waited for up to EXIT_CLEAN_CHILD_WAIT_MS, then sent SIGKILL; status[i]
 * (when status is not NULL) the wait status of pids[i]'s process, or -1
 * when it was killed or not ours. */
static void ec_wait(pid_t *pids, int *status, int n)
{
    int left = 0;
    for (int i = 0; i < n; i++) {
        left += pids[i] != 0;
        if (status)
            status[i] = -1;
    }
    for (long waited = 0; left > 0; waited += EXIT_CLEAN_POLL_MS) {
        for (int i = 0; i < n; i++) {
            int st = 0;
            pid_t pid = ec_pid_of(pids[i]);
            pid_t r = pid ? waitpid(pid, &st, WNOHANG) : 0;
            if (pid && (r == pid || (r < 0 && errno == ECHILD))) {
                if (status && r == pid)
                    status[i] = st;
                pids[i] = 0;
                left--;
            }
        }
        if (left == 0 || waited >= EXIT_CLEAN_CHILD_WAIT_MS)
            break;
        ec_sleep_ms(EXIT_CLEAN_POLL_MS);
    }
    for (int i = 0; i < n; i++) {
        if (pids[i] != 0) {
            ec_kill(pids[i], SIGKILL);
            waitpid(ec_pid_of(pids[i]), NULL, 0);
        }
    }
}

/* Every registered child sent SIGTERM and waited for (ec_wait). */
static void ec_stop_children(void)
{
    static pid_t left[EXIT_CLEAN_MAX_CHILDREN];
    int nleft = 0;
    for (int i = 0; i < EXIT_CLEAN_MAX_CHILDREN; i++) {
        pid_t pid = __atomic_load_n(&ec_children[i], __ATOMIC_SEQ_CST);
        if (pid != 0 && ec_kill(pid, SIGTERM) == 0)
            left[nleft++] = pid;
    }
    ec_wait(left, NULL, nleft);
}

static void ec_say(const char *line)
{
    size_t n = strlen(line);
    if (n && write(2, line, n) == (ssize_t)n)
        (void)!write(2, "\n", 1);
}

/* Every registered command run in turn (fork, the three signals let go,
 * execvp), each waited for (ec_wait) and its note written to stderr. */
static void ec_run_commands(void)
{
    for (int i = 0; i < EXIT_CLEAN_MAX_COMMANDS; i++) {
        struct ec_command *c = &ec_commands[i];
        if (__atomic_load_n(&c->state, __ATOMIC_SEQ_CST) != EC_READY)
            continue;
        pid_t pid = _Fork();
        if (pid == 0) {
            sigset_t none;
            sigemptyset(&none);
            sigprocmask(SIG_SETMASK, &none, NULL);
            execvp(c->argv[0], c->argv);
            _exit(127);
        }
        int st = -1;
        if (pid > 0)
            ec_wait(&pid, &st, 1);
        ec_say(st != -1 && WIFEXITED(st) && WEXITSTATUS(st) == 0 ? c->buf + c->done
                                                               : c->buf + c->failed);
    }
}

static void ec_handler(int sig)
{
    if (getpid() == ec_owner && !__atomic_exchange_n(&ec_busy, 1, __ATOMIC_SEQ_CST)) {
        ec_stop_children(); /* first: a child may still be writing a file below */
        ec_run_commands();
        for (int i = 0; i < EXIT_CLEAN_MAX_PATHS; i++) {
            if (__atomic_load_n(&ec_paths[i].state, __ATOMIC_SEQ_CST) != EC_READY)
                continue;
            if (ec_paths[i].kind == EXIT_CLEAN_DIR)
                ec_remove_dir(ec_paths[i].path);
            else
                unlink(ec_paths[i].path);
        }
    } else if (getpid() == ec_owner) {
        return; /* another thread is cleaning, and then dies of its signal */
    }
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = SIG_DFL;
    sigaction(sig, &sa, NULL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, sig);
    raise(sig);
    sigprocmask(SIG_UNBLOCK, &one, NULL); /* delivered here: the default action */
    _exit(128 + sig);                     /* not reached */
}

/* sig to every registered process group (exit_clean_add_group): the
 * terminal's ^Z and fg reach the program's group alone. */
static void ec_signal_groups(int sig)
{
    for (int i = 0; i < EXIT_CLEAN_MAX_CHILDREN; i++) {
        pid_t v = __atomic_load_n(&ec_children[i], __ATOMIC_SEQ_CST);
        if (v < 0)
            ec_kill(v, sig);
    }
}

/* ^Z (SIGTSTP): the registered groups stopped (SIGSTOP), then the program
 * by the default action; continued (fg, bg: SIGCONT), it continues them. */
static void ec_stop_handler(int sig)
{
    int saved = errno, owner = getpid() == ec_owner;
    if (owner)
        ec_signal_groups(SIGSTOP);
    struct sigaction dfl, old;
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, &old);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, sig);
    raise(sig);
    sigprocmask(SIG_UNBLOCK, &one, NULL); /* stopped here until SIGCONT */
    sigaction(sig, &old, NULL);
    if (owner)
        ec_signal_groups(SIGCONT);
    errno = saved;
}

void exit_clean_install(void)
{
    ec_owner = getpid();
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = ec_handler;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < EC_NSIGNALS; i++)
        sigaddset(&sa.sa_mask, ec_signals[i]); /* one handler at a time per thread */
    for (int i = 0; i < EC_NSIGNALS; i++) {
        struct sigaction old;
        if (sigaction(ec_signals[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN) {
            ec_ignored[i] = 1;
            continue;
        }
        sigaction(ec_signals[i], &sa, NULL);
    }
    struct sigaction old, stop;
    memset(&stop, 0, sizeof stop);
    stop.sa_handler = ec_stop_handler;
    sigemptyset(&stop.sa_mask);
    stop.sa_flags = SA_RESTART; /* a wait or read under way goes on once continued */
    if (sigaction(SIGTSTP, NULL, &old) == 0 && old.sa_handler != SIG_IGN)
        sigaction(SIGTSTP, &stop, NULL);
}

int exit_clean_add(const char *path, enum exit_clean_kind kind)
{
    size_t n = strlen(path);
    if (n >= PATH_MAX)
        return -1;
    for (int i = 0; i < EXIT_CLEAN_MAX_PATHS; i++) {
        int expect = EC_FREE;
        if (!__atomic_compare_exchange_n(&ec_paths[i].state, &expect, EC_FILLING, 0,
                                         __ATOMIC_SEQ_CST, __ATOMIC_SEQ_CST))
            continue;
        memcpy(ec_paths[i].path, path, n + 1);
        ec_paths[i].kind = kind;
        __atomic_store_n(&ec_paths[i].state, EC_READY, __ATOMIC_SEQ_CST);
        return 0;
    }
    return -1;
}

void exit_clean_drop(const char *path)
{
    for (int i = 0; i < EXIT_CLEAN_MAX_PATHS; i++) {
        if (__atomic_load_n(&ec_paths[i].state, __ATOMIC_SEQ_CST) == EC_READY &&
            strcmp(ec_paths[i].path, path) == 0) {
            __atomic_store_n(&ec_paths[i].state, EC_FREE, __ATOMIC_SEQ_CST);
            return;
        }
    }
}

/* v (a pid, or -pid for its group) in a free slot of ec_children */
static void ec_add_child(pid_t v)
{
    for (int i = 0; v != 0 && i < EXIT_CLEAN_MAX_CHILDREN; i++) {
        pid_t expect = 0;
        if (__atomic_compare_exchange_n(&ec_children[i], &expect, v, 0, __ATOMIC_SEQ_CST,
                                        __ATOMIC_SEQ_CST))
            return;
    }
}

void exit_clean_add_child(pid_t pid)
{
    if (pid > 0)
        ec_add_child(pid);
}

void exit_clean_add_group(pid_t pid)
{
    if (pid > 0)
        ec_add_child(-pid);
}

void exit_clean_drop_child(pid_t pid)
{
    for (int i = 0; pid > 0 && i < EXIT_CLEAN_MAX_CHILDREN; i++) {
        pid_t expect = pid, group = -pid;
        if (__atomic_compare_exchange_n(&ec_children[i], &expect, 0, 0, __ATOMIC_SEQ_CST,
                                        __ATOMIC_SEQ_CST) ||
            __atomic_compare_exchange_n(&ec_children[i], &group, 0, 0, __ATOMIC_SEQ_CST,
                                        __ATOMIC_SEQ_CST))
            return;
    }
}

int exit_clean_kill(pid_t pid, int sig)
{
    return pid > 0 ? ec_kill(-pid, sig) : -1;
}

/* s copied into c->buf at *at: its offset, or -1 when it does not fit. */
static long ec_pack(struct ec_command *c, size_t *at, const char *s)
{
    size_t n = strlen(s) + 1;
    if (n > sizeof c->buf - *at)
        return -1;
    memcpy(c->buf + *at, s, n);
    *at += n;
    return (long)(*at - n);
}

/* argv, done and failed packed into c: 0, or -1 when they do not fit. */
static int ec_fill(struct ec_command *c, const char *const *argv, const char *done,
                   const char *failed)
{
    size_t at = 0;
    int k = 0;
    for (; argv[k]; k++) {
        long off = k < EXIT_CLEAN_COMMAND_WORDS ? ec_pack(c, &at, argv[k]) : -1;
        if (off < 0)
            return -1;
        c->argv[k] = c->buf + off;
    }
    c->argv[k] = NULL;
    long d = ec_pack(c, &at, done), f = ec_pack(c, &at, failed);
    if (k == 0 || d < 0 || f < 0)
        return -1;
    c->done = (size_t)d;
    c->failed = (size_t)f;
    return 0;
}

int exit_clean_add_command(const char *const *argv, const char *done, const char *failed)
{
    for (int i = 0; i < EXIT_CLEAN_MAX_COMMANDS; i++) {
        int expect = EC_FREE;
        if (!__atomic_compare_exchange_n(&ec_commands[i].state, &expect, EC_FILLING, 0,
                                         __ATOMIC_SEQ_CST, __ATOMIC_SEQ_CST))
            continue;
        if (ec_fill(&ec_commands[i], argv, done, failed) != 0) {
            __atomic_store_n(&ec_commands[i].state, EC_FREE, __ATOMIC_SEQ_CST);
            return -1;
        }
        __atomic_store_n(&ec_commands[i].state, EC_READY, __ATOMIC_SEQ_CST);
        return i;
    }
    return -1;
}

void exit_clean_drop_command(int slot)
{
    if (slot >= 0 && slot < EXIT_CLEAN_MAX_COMMANDS)
        __atomic_store_n(&ec_commands[slot].state, EC_FREE, __ATOMIC_SEQ_CST);
}

void exit_clean_in_child(void)
{
    for (int i = 0; i < EC_NSIGNALS; i++)
        if (!ec_ignored[i])
            signal(ec_signals[i], SIG_DFL);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (ec_owner && getppid() != ec_owner)
        _exit(1); /* the parent died before the line above */
}

void exit_clean_in_child_group(void)
{
    exit_clean_in_child();
    setpgid(0, 0);
}

void exit_clean_hold(sigset_t *old)
{
    sigset_t set;
    sigemptyset(&set);
    for (int i = 0; i < EC_NSIGNALS; i++)
        sigaddset(&set, ec_signals[i]);
    sigprocmask(SIG_BLOCK, &set, old);
}

void exit_clean_release(const sigset_t *old)
{
    sigprocmask(SIG_SETMASK, old, NULL);
}
