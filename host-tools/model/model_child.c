/* model_child.c: model_load in a child process (model_child.h).
 *
 * The child (fork) resets the crash signals to their default action, sends
 * nothing to the terminal, reads the file with the loader and writes one
 * byte, 'M' and the model (model_wire.h) or 'E' and the loader's message,
 * to a pipe, then _exits.  The parent first checks that the file is a
 * regular one (a FIFO, a directory or a device is refused unread, at once),
 * then reads the pipe until its end, at most max_bytes and until the
 * deadline, then reaps the child and judges: a
 * signal, a non-zero exit status, the deadline or the size passed, or bytes
 * that do not read back as a model, each give their own message. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "host-tools/model/model_child.h"
#include "host-tools/model/model_wire.h"

#define CHILD_EXIT_SEND_FAILED 3 /* the child could not write the pipe */
#define CHILD_FIRST_BUF 65536u

static long long child_now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

static unsigned child_cpu_s(const struct model_child_limits *lim)
{
    return lim->cpu_s ? lim->cpu_s : MODEL_CHILD_CPU_S;
}

static unsigned child_memory_mb(const struct model_child_limits *lim)
{
    return lim->memory_mb ? lim->memory_mb : MODEL_CHILD_MEMORY_MB;
}

/* In the child: its CPU time and the memory it may add limited. */
static void child_limits(const struct model_child_limits *lim)
{
    struct rlimit cpu = {child_cpu_s(lim), child_cpu_s(lim) + 1};
    setrlimit(RLIMIT_CPU, &cpu);
    /* The address space it has now (pages, /proc/self/statm), and more. */
    char text[64] = "";
    int fd = open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
        ssize_t n = read(fd, text, sizeof text - 1);
        text[n > 0 ? n : 0] = 0;
        close(fd);
    }
    unsigned long long pages = strtoull(text, NULL, 10);
    unsigned long long now = pages * (unsigned long long)sysconf(_SC_PAGESIZE);
    rlim_t as = (rlim_t)(now + ((unsigned long long)child_memory_mb(lim) << 20));
    struct rlimit mem = {as, as};
    setrlimit(RLIMIT_AS, &mem);
}

/* The child's side: never returns. */
static void child_run(const char *path, model_loader_fn load, const struct model_child_limits *lim,
                      int fd)
{
    static const int crash[] = {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT, SIGPIPE, SIGTERM, SIGXCPU};
    for (size_t i = 0; i < sizeof crash / sizeof crash[0]; i++)
        signal(crash[i], SIG_DFL); /* a crash ends the child by its signal */
    prctl(PR_SET_PDEATHSIG, SIGKILL); /* and it ends with its parent */
    struct rlimit no_core = {0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    child_limits(lim);
    int null = open("/dev/null", O_RDWR);
    if (null >= 0) { /* the library's own complaints stay out of the terminal */
        dup2(null, STDIN_FILENO);
        dup2(null, STDOUT_FILENO);
        dup2(null, STDERR_FILENO);
    }
    struct model m;
    static char err[4096];
    err[0] = 0;
    int ok = 1;
    if (load(path, &m, err, sizeof err) == 0) {
        ok = write(fd, "M", 1) == 1 && model_wire_send(fd, &m) == 0;
    } else {
        size_t n = strnlen(err, sizeof err);
        ok = write(fd, "E", 1) == 1 && write(fd, err, n) == (ssize_t)n;
    }
    _exit(ok ? 0 : CHILD_EXIT_SEND_FAILED);
}

struct child_got {
    unsigned char *buf;
    size_t len, cap;
    int timed_out, too_big, read_errno;
};

/* Reads fd to its end into g, within max bytes and until deadline. */
static void child_read(int fd, size_t max, long long deadline, struct child_got *g)
{
    for (;;) {
        long long left = deadline - child_now_ms();
        if (left <= 0) {
            g->timed_out = 1;
            return;
        }
        struct pollfd p = {fd, POLLIN, 0};
        int r = poll(&p, 1, left > 1000000 ? 1000000 : (int)left);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            g->read_errno = errno;
            return;
        }
        if (r == 0)
            continue; /* the deadline is checked above */
        if (g->len == g->cap) {
            if (g->cap > max) {
                g->too_big = 1;
                return;
            }
            size_t cap = g->cap ? 2 * g->cap : CHILD_FIRST_BUF;
            if (cap > max + 1)
                cap = max + 1;
            unsigned char *b = realloc(g->buf, cap);
            if (!b) {
                g->read_errno = ENOMEM;
                return;
            }
            g->buf = b, g->cap = cap;
        }
        ssize_t k = read(fd, g->buf + g->len, g->cap - g->len);
        if (k < 0 && errno == EINTR)
            continue;
        if (k < 0) {
            g->read_errno = errno;
            return;
        }
        if (k == 0)
            return;
        g->len += (size_t)k;
        if (g->len > max) {
            g->too_big = 1;
            return;
        }
    }
}

/* Reaps pid by the deadline, killing it when it is not done by then (or
 * at once when kill_now).  Its wait status; *late set when it was killed
 * for the deadline. */
static int child_reap(pid_t pid, long long deadline, int kill_now, int *late)
{
    int st = 0;
    if (kill_now)
        kill(pid, SIGKILL);
    for (;;) {
        pid_t r = waitpid(pid, &st, WNOHANG);
        if (r == pid || (r < 0 && errno != EINTR))
            return st;
        if (r == 0 && child_now_ms() >= deadline) {
            *late = 1;
            kill(pid, SIGKILL);
            while (waitpid(pid, &st, 0) < 0 && errno == EINTR) {
            }
            return st;
        }
        struct timespec nap = {0, 2000000};
        nanosleep(&nap, NULL);
    }
}

/* The child's message into err, its unprintable bytes as '?'. */
static void child_message(const unsigned char *b, size_t n, char *err, size_t errlen)
{
    size_t k = 0;
    for (; k < n && k + 1 < errlen; k++)
        err[k] = b[k] >= ' ' && b[k] <= '~' ? (char)b[k] : '?';
    if (errlen)
        err[k] = 0;
}

/* What the child's end tells, into err.  -1 always. */
static int child_judge(const char *path, int st, const struct child_got *g,
                       const struct model_child_limits *lim, int late, char *err, size_t errlen)
{
    if (g->timed_out || late) {
        snprintf(err, errlen, "%s: the model library did not finish reading it within %g s "
                              "(stopped); the file is malformed or too big",
                 path, lim->timeout_ms / 1000.0);
    } else if (g->too_big) {
        snprintf(err, errlen, "%s: the model library handed back more than %zu bytes "
                              "(stopped); the model is too big to import",
                 path, lim->max_bytes);
    } else if (WIFSIGNALED(st) && WTERMSIG(st) == SIGXCPU) {
        snprintf(err, errlen, "%s: the model library used more than %u s of CPU time reading "
                              "it (stopped); the file is malformed or too big",
                 path, child_cpu_s(lim));
    } else if (WIFSIGNALED(st)) {
        int sig = WTERMSIG(st);
        const char *abbrev = sigabbrev_np(sig);
        snprintf(err, errlen, "%s: the model library crashed (signal %d, SIG%s) while reading "
                              "it; the file is malformed or unsupported (or needs more than "
                              "the %u MiB a reader may take)",
                 path, sig, abbrev ? abbrev : "?", child_memory_mb(lim));
    } else if (WIFEXITED(st) && WEXITSTATUS(st) != 0) {
        snprintf(err, errlen, "%s: the model library failed (exit status %d) while reading "
                              "it; the file is malformed or unsupported (or needs more than "
                              "the %u MiB a reader may take)",
                 path, WEXITSTATUS(st), child_memory_mb(lim));
    } else if (g->read_errno) {
        snprintf(err, errlen, "%s: reading the model library's answer: %s", path,
                 strerror(g->read_errno));
    } else {
        snprintf(err, errlen, "%s: the model library ended without handing back the model",
                 path);
    }
    return -1;
}

int model_file_check(int fd, const char *path, size_t max, char *err, size_t errlen)
{
    struct stat st;
    int rc = fstat(fd, &st);
    if (rc == 0 && S_ISREG(st.st_mode) && (unsigned long long)st.st_size <= max)
        return 0;
    if (rc == 0 && S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "%s: %lld bytes, more than %zu: not read", path,
                 (long long)st.st_size, max);
        return -1;
    }
    snprintf(err, errlen, "%s: not a regular file (%s): not read", path,
             rc != 0 ? strerror(errno) : S_ISDIR(st.st_mode) ? "a directory"
             : S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISSOCK(st.st_mode) ? "a socket" : "a device");
    return -1;
}

/* path names a regular file (opened without blocking, so a FIFO is
 * refused at once rather than read until the deadline).  0, or -1 with
 * "PATH: why" in err. */
static int child_regular(const char *path, char *err, size_t errlen)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    int rc = model_file_check(fd, path, SIZE_MAX, err, errlen);
    close(fd);
    return rc;
}

int model_child_load(const char *path, model_loader_fn load, const struct model_child_limits *lim,
                     struct model *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    if (child_regular(path, err, errlen) != 0)
        return -1;
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
        snprintf(err, errlen, "%s: cannot start the model reader: %s", path, strerror(errno));
        return -1;
    }
    long long deadline = child_now_ms() + lim->timeout_ms;
    pid_t pid = fork();
    if (pid < 0) {
        snprintf(err, errlen, "%s: cannot start the model reader: %s", path, strerror(errno));
        close(fds[0]), close(fds[1]);
        return -1;
    }
    if (pid == 0) {
        close(fds[0]);
        child_run(path, load, lim, fds[1]);
    }
    close(fds[1]);
    struct child_got g = {NULL, 0, 0, 0, 0, 0};
    child_read(fds[0], lim->max_bytes, deadline, &g);
    close(fds[0]);
    int late = 0;
    int st = child_reap(pid, deadline, g.timed_out || g.too_big, &late);
    int rc = -1;
    if (g.timed_out || g.too_big || late || g.read_errno || !WIFEXITED(st) ||
        WEXITSTATUS(st) != 0 || g.len == 0) {
        child_judge(path, st, &g, lim, late, err, errlen);
    } else if (g.buf[0] == 'E' && g.len > 1) {
        child_message(g.buf + 1, g.len - 1, err, errlen);
    } else if (g.buf[0] == 'E') {
        snprintf(err, errlen, "%s: the model library refused it without saying why", path);
    } else if (g.buf[0] != 'M') {
        snprintf(err, errlen, "%s: the model library handed back malformed data (it began "
                              "with byte %u)", path, g.buf[0]);
    } else {
        char why[256];
        rc = model_wire_take(g.buf + 1, g.len - 1, m, why, sizeof why);
        if (rc != 0)
            snprintf(err, errlen, "%s: the model library handed back malformed data (%s)",
                     path, why);
    }
    free(g.buf);
    return rc;
}

int model_load(const char *path, struct model *m, char *err, size_t errlen)
{
    static const struct model_child_limits lim = {MODEL_CHILD_TIMEOUT_MS, MODEL_CHILD_MAX_BYTES,
                                                   MODEL_CHILD_CPU_S, MODEL_CHILD_MEMORY_MB};
    return model_child_load(path, model_assimp_load, &lim, m, err, errlen);
}
