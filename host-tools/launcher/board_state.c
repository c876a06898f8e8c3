/* board_state.c: named boards' state on the disk, only its owner's (see
 * board_state.h). */
#define _GNU_SOURCE /* renameat2 */
#include "host-tools/launcher/board_state.h"
#include "host-tools/launcher/launcher.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

/* The base's path: $LINKS1_BOARDS, $XDG_RUNTIME_DIR/links1-boards,
 * /dev/shm/links1-UID or /tmp/links1-UID. */
static void board_state_base_path(char *out, size_t cap)
{
    const char *env = getenv("LINKS1_BOARDS");
    const char *xdg = getenv("XDG_RUNTIME_DIR");
    struct stat st;
    if (env && *env)
        snprintf(out, cap, "%s", env);
    else if (xdg && *xdg)
        snprintf(out, cap, "%s/%s", xdg, BOARD_STATE_XDG_DIR);
    else if (stat("/dev/shm", &st) == 0 && S_ISDIR(st.st_mode))
        snprintf(out, cap, "/dev/shm/links1-%u", (unsigned)geteuid());
    else
        snprintf(out, cap, "/tmp/links1-%u", (unsigned)geteuid());
}

/* fd (path) is a directory of this user's that no one else may enter. */
static int board_state_private(int fd, const char *what, const char *path)
{
    struct stat st;
    if (fstat(fd, &st) != 0) {
        fprintf(stderr, "links1: %s %s: %s\n", what, path, strerror(errno));
        return -1;
    }
    if (st.st_uid != geteuid()) {
        fprintf(stderr, "links1: %s %s is owned by uid %u, not by you (uid %u): refused, a "
                "board's state is kept only where no one else can change it\n", what, path,
                (unsigned)st.st_uid, (unsigned)geteuid());
        return -1;
    }
    if (st.st_mode & 077) {
        fprintf(stderr, "links1: %s %s has mode %04o, its group or others may enter it: "
                "refused (chmod 700 it, or remove it)\n", what, path,
                (unsigned)(st.st_mode & 07777));
        return -1;
    }
    return 0;
}

/* Why name (path) below at could not be opened, printed. */
static void board_state_why(int at, const char *name, int err, const char *what,
                            const char *path)
{
    struct stat st = {0};
    if (fstatat(at, name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISLNK(st.st_mode))
        fprintf(stderr, "links1: %s %s is a symbolic link: not followed, left as it is\n",
                what, path);
    else if (err == ENOTDIR || err == EISDIR || (err == 0 && !S_ISREG(st.st_mode)))
        fprintf(stderr, "links1: %s %s is not a %s: left as it is\n", what, path,
                err == ENOTDIR ? "directory" : "regular file");
    else
        fprintf(stderr, "links1: %s %s: %s\n", what, path, strerror(err));
}

/* The directory name below at opened without following a link, and
 * checked private.  Its fd, -2 when missing, -1 after printing why. */
static int board_state_open_dir(int at, const char *name, const char *what, const char *path)
{
    int fd = openat(at, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ENOENT)
            return -2;
        board_state_why(at, name, errno, what, path);
        return -1;
    }
    if (board_state_private(fd, what, path) < 0) {
        close(fd);
        return -1;
    }
    return fd;
}

int board_state_base(int create, char *path, size_t cap)
{
    char want[PATH_MAX];
    board_state_base_path(want, sizeof want);
    if (create && mkdir(want, 0700) != 0 && errno != EEXIST) {
        fprintf(stderr, "links1: the boards' state directory %s: %s\n", want, strerror(errno));
        return -1;
    }
    int fd = board_state_open_dir(AT_FDCWD, want, "the boards' state directory", want);
    if (fd < 0)
        return fd;
    /* One spelling of the path, whatever $LINKS1_BOARDS looks like: QEMU's
     * command line names it, and a board is known by it. */
    char real[PATH_MAX];
    const char *why = !realpath(want, real) ? strerror(errno)
                      : strlen(real) >= cap ? "path too long"
                                            : NULL;
    if (why) {
        fprintf(stderr, "links1: the boards' state directory %s: %s\n", want, why);
        close(fd);
        return -1;
    }
    memcpy(path, real, strlen(real) + 1);
    return fd;
}

int board_state_name_ok(const char *name)
{
    size_t n = strlen(name);
    int ok = n >= 1 && n <= BOARD_NAME_MAX && name[0] != '.' && name[0] != '-';
    for (size_t i = 0; ok && i < n; i++)
        ok = (name[i] >= 'a' && name[i] <= 'z') || (name[i] >= 'A' && name[i] <= 'Z') ||
             (name[i] >= '0' && name[i] <= '9') || strchr("_.-", name[i]);
    return ok ? 0 : -1;
}

int board_state_dir(int base_fd, const char *base, const char *name)
{
    char path[PATH_MAX + 80], what[BOARD_NAME_MAX + 32];
    snprintf(path, sizeof path, "%s/%s", base, name);
    snprintf(what, sizeof what, "board %s's directory", name);
    return board_state_open_dir(base_fd, name, what, path);
}

int board_state_make(int base_fd, const char *base, const char *name, int *lock_fd)
{
    char hidden[BOARD_NAME_MAX + 40];
    snprintf(hidden, sizeof hidden, ".starting-%s.%d", name, (int)getpid());
    *lock_fd = -1;
    if (mkdirat(base_fd, hidden, 0700) != 0) {
        fprintf(stderr, "links1: %s/%s: %s\n", base, hidden, strerror(errno));
        return -1;
    }
    int fd = board_state_open_dir(base_fd, hidden, "a new board directory", hidden);
    int lock = fd < 0 ? -1 : board_state_create(fd, BOARD_STATE_LOCK, O_RDWR);
    int r = lock < 0 ? -1 : flock(lock, LOCK_EX | LOCK_NB);
    if (r == 0) {
        r = renameat2(base_fd, hidden, base_fd, name, RENAME_NOREPLACE);
        if (r != 0 && errno == EINVAL) /* a file system without it */
            r = renameat(base_fd, hidden, base_fd, name);
    }
    if (r == 0) {
        *lock_fd = lock;
        return fd;
    }
    if (errno == EEXIST || errno == ENOTEMPTY)
        fprintf(stderr, "links1: board %s: %s/%s appeared meanwhile (another start?)\n", name,
                base, name);
    else
        fprintf(stderr, "links1: board %s: making its directory in %s: %s\n", name, base,
                strerror(errno));
    if (fd >= 0)
        unlinkat(fd, BOARD_STATE_LOCK, 0);
    if (lock >= 0)
        close(lock);
    if (fd >= 0)
        close(fd);
    unlinkat(base_fd, hidden, AT_REMOVEDIR);
    return -1;
}

int board_state_create(int dir_fd, const char *file, int flags)
{
    return openat(dir_fd, file, flags | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
}

/* A file of the directory opened without following a link, and checked a
 * regular file (a FIFO does not block the open).  Its fd and *st; -2 when
 * missing; -1 after printing why. */
static int board_state_open_file(int dir_fd, const char *file, int flags, const char *what,
                                 const char *dir, struct stat *st)
{
    char path[PATH_MAX + 96];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    int fd = openat(dir_fd, file, flags | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0 && errno == ENOENT)
        return -2;
    if (fd < 0) {
        board_state_why(dir_fd, file, errno, what, path);
        return -1;
    }
    if (fstat(fd, st) != 0 || !S_ISREG(st->st_mode)) {
        board_state_why(dir_fd, file, 0, what, path);
        close(fd);
        return -1;
    }
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    return fd;
}

/* One value of the record out of its range, printed; -1. */
static int board_state_bad(const char *name, const char *dir, const char *field, long v,
                           const char *want)
{
    fprintf(stderr, "links1: board %s: its record %s/%s says %s %ld, not %s: refused (the "
            "state is left as it is; remove %s if no board runs there)\n", name, dir,
            BOARD_STATE_INFO, field, v, want, dir);
    return -1;
}

/* The rest of a record after its arith: "machine NAME" and, for an521,
 * "nc_pids P1 P2 ..." (*nnc of them, at most AN521_MAX_BOARDS - 1).  0, or
 * -1 when it does not read as that. */
static int board_state_read_machine(const char *text, struct board_record *r, int *nnc)
{
    char m[16];
    int used = 0;
    if (sscanf(text, "machine %15s %n", m, &used) != 1 || (r->machine = machine_by_name(m)) < 0)
        return -1;
    text += used;
    if (r->machine == MACHINE_VIRT)
        return *text == 0 ? 0 : -1;
    used = 0;
    if (sscanf(text, "nc_pids%n", &used) != 0 || used == 0)
        return -1;
    text += used;
    memset(r->nc_pid, 0, sizeof r->nc_pid);
    for (*nnc = 0; *text != 0;) {
        int pid;
        used = 0;
        if (*nnc >= AN521_MAX_BOARDS - 1 || sscanf(text, " %d %n", &pid, &used) != 1)
            return -1;
        r->nc_pid[++*nnc] = pid;
        text += used;
    }
    return 0;
}

int board_state_read(int dir_fd, const char *dir, const char *name, struct board_record *r)
{
    char what[BOARD_NAME_MAX + 32];
    snprintf(what, sizeof what, "board %s's record", name);
    struct stat st;
    int fd = board_state_open_file(dir_fd, BOARD_STATE_INFO, O_RDONLY, what, dir, &st);
    if (fd < 0)
        return fd;
    char text[BOARD_STATE_RECORD_MAX + 1];
    ssize_t n = st.st_size <= BOARD_STATE_RECORD_MAX ? read(fd, text, sizeof text - 1) : -1;
    close(fd);
    int used = 0, nnc = 0, wide_used = 0;
    r->machine = MACHINE_VIRT;
    r->wide = 0;
    if (n >= 0) {
        text[n] = 0;
        if (sscanf(text, "pid %d ncores %d ram_mb %d arith %15s %n", &r->pid, &r->ncores,
                   &r->ram_mb, r->arith, &used) != 4)
            n = -1;
        else if (sscanf(text + used, "wide %d %n", &r->wide, &wide_used) == 1)
            used += wide_used;
        if (n >= 0 && ((r->wide != 0 && r->wide != 1) ||
                       (text[used] != 0 && board_state_read_machine(text + used, r, &nnc) < 0)))
            n = -1;
    }
    if (n < 0) {
        fprintf(stderr, "links1: board %s: its record %s/%s does not read as one (%lld "
                "bytes): refused, left as it is\n", name, dir, BOARD_STATE_INFO,
                (long long)st.st_size);
        return -1;
    }
    char range[64];
    if (r->pid <= 1)
        return board_state_bad(name, dir, "pid", r->pid, "a process of a board's");
    snprintf(range, sizeof range, "%d..%d", UNITS_MIN_CORES, UNITS_MAX_CORES);
    if (r->ncores < UNITS_MIN_CORES || r->ncores > UNITS_MAX_CORES)
        return board_state_bad(name, dir, "ncores", r->ncores, range);
    if (r->machine == MACHINE_AN521) {
        int boards = r->ncores / AN521_CORES_PER_BOARD;
        snprintf(range, sizeof range, "an even number up to %d (an521 boards of %d cores)",
                 AN521_CORES_PER_BOARD * AN521_MAX_BOARDS, AN521_CORES_PER_BOARD);
        if (r->ncores % AN521_CORES_PER_BOARD || boards > AN521_MAX_BOARDS)
            return board_state_bad(name, dir, "ncores", r->ncores, range);
        snprintf(range, sizeof range, "%d (the an521 shared file's MiB)", AN521_SHARED_MB);
        if (r->ram_mb != AN521_SHARED_MB)
            return board_state_bad(name, dir, "ram_mb", r->ram_mb, range);
        snprintf(range, sizeof range, "%d (one for each NC board)", boards - 1);
        if (nnc != boards - 1)
            return board_state_bad(name, dir, "nc_pids for", nnc, range);
        for (int k = 1; k < boards; k++)
            if (r->nc_pid[k] <= 1)
                return board_state_bad(name, dir, "an NC board's pid", r->nc_pid[k],
                                       "a process of a board's");
    } else {
        snprintf(range, sizeof range, "%d..%d", BOARD_MIN_RAM_MB, BOARD_MAX_RAM_MB);
        if (r->ram_mb < BOARD_MIN_RAM_MB || r->ram_mb > BOARD_MAX_RAM_MB)
            return board_state_bad(name, dir, "ram_mb", r->ram_mb, range);
    }
    if (board_arith_code(r->arith) < 0) {
        fprintf(stderr, "links1: board %s: its record %s/%s says arith '%s', not float, soft "
                "or fixed: refused\n", name, dir, BOARD_STATE_INFO, r->arith);
        return -1;
    }
    return 0;
}

int board_state_write(int dir_fd, const char *dir, const struct board_record *r)
{
    /* Written whole under a hidden name, then moved into place: a reader
     * never sees half a record. */
    static const char tmp[] = "." BOARD_STATE_INFO ".new";
    char text[BOARD_STATE_RECORD_MAX];
    int n = snprintf(text, sizeof text, "pid %d\nncores %d\nram_mb %d\narith %s\n%s", r->pid,
                     r->ncores, r->ram_mb, r->arith, r->wide ? "wide 1\n" : "");
    if (r->machine == MACHINE_AN521) {
        n += snprintf(text + n, sizeof text - (size_t)n, "machine %s\nnc_pids",
                      machine_limits(r->machine)->name);
        for (int k = 1; k < r->ncores / AN521_CORES_PER_BOARD && k < AN521_MAX_BOARDS; k++)
            n += snprintf(text + n, sizeof text - (size_t)n, " %d", r->nc_pid[k]);
        n += snprintf(text + n, sizeof text - (size_t)n, "\n");
    }
    int fd = board_state_create(dir_fd, tmp, O_WRONLY);
    int ok = fd >= 0 && write(fd, text, (size_t)n) == n;
    if (fd >= 0 && close(fd) != 0)
        ok = 0;
    if (ok && renameat(dir_fd, tmp, dir_fd, BOARD_STATE_INFO) == 0)
        return 0;
    fprintf(stderr, "links1: %s/%s: %s\n", dir, BOARD_STATE_INFO, strerror(errno));
    unlinkat(dir_fd, tmp, 0);
    return -1;
}

int board_state_lock(int dir_fd, const char *dir)
{
    struct stat st;
    int fd = board_state_open_file(dir_fd, BOARD_STATE_LOCK, O_RDWR, "the board's lock", dir,
                                   &st);
    if (fd == -2)
        return -3;
    if (fd < 0)
        return -1;
    if (flock(fd, LOCK_EX | LOCK_NB) == 0)
        return fd;
    int err = errno;
    close(fd);
    if (err == EWOULDBLOCK)
        return -2;
    fprintf(stderr, "links1: %s/%s: %s\n", dir, BOARD_STATE_LOCK, strerror(err));
    return -1;
}

int board_state_open_ram(int dir_fd, const char *dir, size_t size)
{
    struct stat st;
    int fd = board_state_open_file(dir_fd, BOARD_STATE_RAM, O_RDWR, "the board's RAM", dir, &st);
    if (fd == -2)
        fprintf(stderr, "links1: the board's RAM %s/%s: %s\n", dir, BOARD_STATE_RAM,
                strerror(ENOENT));
    if (fd < 0)
        return -1;
    if ((unsigned long long)st.st_size != (unsigned long long)size) {
        fprintf(stderr, "links1: the board's RAM %s/%s is %lld bytes, the record says %zu "
                "(%zu MiB): refused\n", dir, BOARD_STATE_RAM, (long long)st.st_size, size,
                size >> 20);
        close(fd);
        return -1;
    }
    return fd;
}

void board_state_chardev(const char *dir, char *out, size_t cap)
{
    /* wait=on: the guest starts only once `board start` is connected, so
     * no report-in is lost.  QEMU's option syntax: a comma of the path
     * doubled. */
    char esc[2 * PATH_MAX];
    snprintf(out, cap, "socket,id=link,path=%s/%s,server=on,wait=on",
             qemu_opt_escape(dir, esc, sizeof esc), BOARD_STATE_SOCKET);
}

void board_state_nc_name(const char *dir, int k, char *out, size_t cap)
{
    char esc[2 * PATH_MAX];
    snprintf(out, cap, "guest=links1-nc-board-%d:%s", k, qemu_opt_escape(dir, esc, sizeof esc));
}

/* 1 when pid runs and its command line holds an argument equal to want. */
static int board_state_runs_with(int pid, const char *want);

int board_state_alive(const char *dir, int pid)
{
    char want[2 * PATH_MAX + 160];
    board_state_chardev(dir, want, sizeof want);
    return board_state_runs_with(pid, want);
}

int board_state_nc_alive(const char *dir, int k, int pid)
{
    char want[2 * PATH_MAX + 64];
    board_state_nc_name(dir, k, want, sizeof want);
    return board_state_runs_with(pid, want);
}

/* The process of /proc/PID (proc_fd) is this user's: its real and
 * effective uid in its status are ours.  1, or 0 (another user's, or gone)
 * with its real uid in *uid (-1 when unknown). */
static int board_state_pid_ours(int proc_fd, long *uid)
{
    char text[4096];
    int fd = openat(proc_fd, "status", O_RDONLY | O_CLOEXEC);
    ssize_t n = fd >= 0 ? read(fd, text, sizeof text - 1) : -1;
    if (fd >= 0)
        close(fd);
    text[n > 0 ? n : 0] = 0;
    const char *line = strstr(text, "\nUid:");
    long real = -1, eff = -1;
    if (!line || sscanf(line + 5, "%ld %ld", &real, &eff) != 2)
        real = eff = -1;
    *uid = real;
    return real >= 0 && real == (long)getuid() && eff == (long)geteuid();
}

long board_state_pid_uid(int pid)
{
    char path[64];
    snprintf(path, sizeof path, "/proc/%d", pid);
    int fd = pid > 1 ? open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC) : -1;
    long uid = -1;
    if (fd >= 0) {
        board_state_pid_ours(fd, &uid);
        close(fd);
    }
    return uid;
}

static int board_state_runs_with(int pid, const char *want)
{
    char path[64];
    if (pid <= 1)
        return 0;
    /* Both files read through one handle of /proc/PID: a pid reused
     * between them fails the second read instead of mixing two processes. */
    snprintf(path, sizeof path, "/proc/%d", pid);
    int dir = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    long uid;
    if (dir < 0)
        return 0;
    if (!board_state_pid_ours(dir, &uid)) { /* another user's: a pid reused */
        close(dir);
        return 0;
    }
    int fd = openat(dir, "cmdline", O_RDONLY | O_CLOEXEC);
    close(dir);
    char *cmd = fd >= 0 ? malloc(BOARD_STATE_CMDLINE_MAX + 1) : NULL;
    size_t n = 0;
    while (cmd && n < BOARD_STATE_CMDLINE_MAX) {
        ssize_t k = read(fd, cmd + n, BOARD_STATE_CMDLINE_MAX - n);
        if (k <= 0)
            break;
        n += (size_t)k;
    }
    if (fd >= 0)
        close(fd);
    if (!cmd)
        return 0;
    cmd[n] = 0;
    int found = 0;
    for (size_t i = 0; i < n && !found; i += strlen(cmd + i) + 1)
        found = strcmp(cmd + i, want) == 0;
    free(cmd);
    return found;
}

int board_state_remove(int base_fd, int dir_fd, const char *dir, const char *name)
{
    static const char *const files[] = {BOARD_STATE_INFO, "." BOARD_STATE_INFO ".new",
                                        BOARD_STATE_SOCKET, BOARD_STATE_RAM, BOARD_STATE_LOG,
                                        BOARD_STATE_GDB, BOARD_STATE_LOCK};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++)
        unlinkat(dir_fd, files[i], 0); /* never follows a link: removes the link */
    if (unlinkat(base_fd, name, AT_REMOVEDIR) == 0 || errno == ENOENT)
        return 0;
    fprintf(stderr, "links1: board %s: %s could not be removed: %s (left as it is)\n", name,
            dir, strerror(errno));
    return -1;
}
