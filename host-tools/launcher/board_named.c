/* board_named.c: boards that outlive the tool that started them (see
 * board.h, "named boards"): their state directory, the session that
 * connects to one, stopping and listing them. */
#include "host-tools/launcher/launcher.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include "proto/wire.h"

/* What the state directory records of a board. */
struct board_named_info {
    int pid, ncores, ram_mb;
    char arith[16];
};

static void board_named_base(char *out, size_t cap)
{
    const char *env = getenv("LINKS1_BOARDS");
    struct stat st;
    if (env && *env)
        snprintf(out, cap, "%s", env);
    else if (stat("/dev/shm", &st) == 0 && S_ISDIR(st.st_mode))
        snprintf(out, cap, "/dev/shm/links1-%u", (unsigned)getuid());
    else
        snprintf(out, cap, "/tmp/links1-%u", (unsigned)getuid());
}

/* NAME: 1..64 of [A-Za-z0-9_.-], not starting with '.'. */
static int board_named_dir(const char *name, char *out, size_t cap)
{
    size_t n = strlen(name);
    int ok = n >= 1 && n <= 64 && name[0] != '.';
    for (size_t i = 0; ok && i < n; i++)
        ok = (name[i] >= 'a' && name[i] <= 'z') || (name[i] >= 'A' && name[i] <= 'Z') ||
             (name[i] >= '0' && name[i] <= '9') || strchr("_.-", name[i]);
    if (!ok) {
        fprintf(stderr, "links1: board name '%s': use 1 to 64 letters, digits, '_', '.' or "
                "'-', not starting with '.'\n", name);
        return -1;
    }
    char base[3000];
    board_named_base(base, sizeof base);
    snprintf(out, cap, "%.3000s/%.64s", base, name);
    return 0;
}

static void board_named_path(const char *dir, const char *file, char *out, size_t cap)
{
    snprintf(out, cap, "%s/%s", dir, file);
}

/* 0 with *info, or -1 when the directory holds no readable record. */
static int board_named_read(const char *dir, struct board_named_info *info)
{
    char path[4200];
    board_named_path(dir, BOARD_STATE_INFO, path, sizeof path);
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    int n = fscanf(f, "pid %d ncores %d ram_mb %d arith %15s", &info->pid, &info->ncores,
                   &info->ram_mb, info->arith);
    fclose(f);
    return n == 4 ? 0 : -1;
}

static int board_named_write(const struct board *b)
{
    char path[4200];
    board_named_path(b->state_dir, BOARD_STATE_INFO, path, sizeof path);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "links1: %s: %s\n", path, strerror(errno));
        return -1;
    }
    fprintf(f, "pid %d\nncores %d\nram_mb %d\narith %s\n", (int)b->qemu_pid, b->opts.ncores,
            b->opts.ram_mb, b->opts.arith);
    return fclose(f) == 0 ? 0 : -1;
}

/* The board's QEMU is alive: pid exists and its command line names this
 * state directory (a pid reused by another program does not count). */
static int board_named_alive(const char *dir, int pid)
{
    char path[64], cmd[8192];
    snprintf(path, sizeof path, "/proc/%d/cmdline", pid);
    FILE *f = pid > 0 ? fopen(path, "r") : NULL;
    if (!f)
        return 0;
    size_t n = fread(cmd, 1, sizeof cmd - 1, f);
    fclose(f);
    for (size_t i = 0; i < n; i++)
        if (cmd[i] == 0)
            cmd[i] = ' ';
    cmd[n] = 0;
    return strstr(cmd, dir) != NULL;
}

static void board_named_remove(const char *dir)
{
    static const char *const files[] = {BOARD_STATE_INFO, BOARD_STATE_SOCKET, BOARD_STATE_RAM,
                                        BOARD_STATE_LOG, BOARD_STATE_LOCK};
    char path[4200];
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        board_named_path(dir, files[i], path, sizeof path);
        unlink(path);
    }
    rmdir(dir);
}

/* A directory whose QEMU is gone: reported and removed.  1 when it was
 * stale (or held no record), 0 when its board runs (*info filled). */
static int board_named_check_stale(const char *name, const char *dir,
                                   struct board_named_info *info)
{
    struct stat st;
    if (stat(dir, &st) != 0)
        return 1;
    if (board_named_read(dir, info) == 0 && board_named_alive(dir, info->pid))
        return 0;
    if (board_named_read(dir, info) == 0)
        fprintf(stderr, "links1: board %s: its QEMU (pid %d) is gone; removing its stale "
                "state %s\n", name, info->pid, dir);
    else
        fprintf(stderr, "links1: board %s: %s has no board record; removing it\n", name, dir);
    board_named_remove(dir);
    return 1;
}

/* Takes the board's lock for this session: one session at a time. */
static int board_named_lock(const char *name, const char *dir, int quiet)
{
    char path[4200];
    board_named_path(dir, BOARD_STATE_LOCK, path, sizeof path);
    int fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    if (fd < 0) {
        fprintf(stderr, "links1: %s: %s\n", path, strerror(errno));
        return -1;
    }
    if (flock(fd, LOCK_EX | LOCK_NB) < 0) {
        if (!quiet)
            fprintf(stderr, "links1: board %s is in use by another links1 session\n", name);
        close(fd);
        return -1;
    }
    return fd;
}

void board_named_redirect(const struct board *b)
{
    char path[4200];
    board_named_path(b->state_dir, BOARD_STATE_LOG, path, sizeof path);
    int log = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    int null = open("/dev/null", O_RDONLY);
    if (null >= 0)
        dup2(null, 0);
    if (log >= 0) {
        dup2(log, 1);
        dup2(log, 2);
    }
}

int board_named_map_ram(struct board *b, int create)
{
    char path[4200];
    board_named_path(b->state_dir, BOARD_STATE_RAM, path, sizeof path);
    b->ram_size = (size_t)b->opts.ram_mb << 20;
    int fd = open(path, O_RDWR | O_CLOEXEC | (create ? O_CREAT | O_EXCL : 0), 0600);
    if (fd < 0 || (create && ftruncate(fd, (off_t)b->ram_size) < 0)) {
        fprintf(stderr, "links1: the board's RAM %s: %s\n", path, strerror(errno));
        if (fd >= 0)
            close(fd);
        return -1;
    }
    void *p = mmap(NULL, b->ram_size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    close(fd);
    if (p == MAP_FAILED) {
        fprintf(stderr, "links1: mapping the board's RAM %s: %s\n", path, strerror(errno));
        return -1;
    }
    b->ram = p;
    return 0;
}

/* Connects to the board's UART socket, retrying while QEMU creates it.
 * child: QEMU is our child (just started), so its exit can be seen. */
static int board_named_dial(const char *dir, int pid, int child, int timeout_ms)
{
    struct sockaddr_un a = {.sun_family = AF_UNIX};
    char path[4200];
    board_named_path(dir, BOARD_STATE_SOCKET, path, sizeof path);
    if (strlen(path) >= sizeof a.sun_path) {
        fprintf(stderr, "links1: socket path %s is too long ($LINKS1_BOARDS shorter)\n", path);
        return -1;
    }
    memcpy(a.sun_path, path, strlen(path) + 1);
    long long end = board_now_ms() + timeout_ms;
    for (;;) {
        int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
        if (fd < 0) {
            fprintf(stderr, "links1: socket: %s\n", strerror(errno));
            return -1;
        }
        if (connect(fd, (struct sockaddr *)&a, sizeof a) == 0)
            return fd;
        int err = errno;
        close(fd);
        int st;
        if ((child && waitpid(pid, &st, WNOHANG) == pid) || (!child && kill(pid, 0) < 0)) {
            fprintf(stderr, "links1: QEMU (pid %d) ended before its UART socket took a "
                    "connection; its output is in %s/%s\n", pid, dir, BOARD_STATE_LOG);
            return -1;
        }
        if (board_now_ms() >= end) {
            fprintf(stderr, "links1: cannot connect to %s: %s\n", path, strerror(err));
            return -1;
        }
        usleep(20000);
    }
}

int board_named_prepare(struct board *b, const char *name)
{
    char base[4096];
    board_named_base(base, sizeof base);
    if (mkdir(base, 0700) < 0 && errno != EEXIST) {
        fprintf(stderr, "links1: %s: %s\n", base, strerror(errno));
        return -1;
    }
    if (board_named_dir(name, b->state_dir, sizeof b->state_dir) < 0)
        return -1;
    struct board_named_info info;
    if (!board_named_check_stale(name, b->state_dir, &info)) {
        fprintf(stderr, "links1: board %s is already running (QEMU pid %d, %d cores); "
                "`links1 board stop %s` first\n", name, info.pid, info.ncores, name);
        return -1;
    }
    if (mkdir(b->state_dir, 0700) < 0) {
        fprintf(stderr, "links1: %s: %s\n", b->state_dir, strerror(errno));
        return -1;
    }
    b->lock_fd = board_named_lock(name, b->state_dir, 0);
    return b->lock_fd < 0 ? -1 : 0;
}

int board_named_started(struct board *b, int timeout_ms)
{
    if (board_named_write(b) < 0)
        return -1;
    return board_named_dial(b->state_dir, (int)b->qemu_pid, 1, timeout_ms);
}

void board_named_abandon(struct board *b)
{
    if (b->qemu_pid > 0) {
        kill(b->qemu_pid, SIGKILL);
        waitpid(b->qemu_pid, NULL, 0);
        b->qemu_pid = 0;
    }
    if (b->state_dir[0])
        board_named_remove(b->state_dir);
}

/* Opens the session: CMD_STATUS flagged LINK_FLAG_SESSION; what an earlier
 * session left (results, progress, the end of a cut frame) is dropped. */
static int board_named_session(struct board *b, const char *name)
{
    uint8_t p[LINK_CMD_FIXED_SIZE];
    wire_put_u16(p, CMD_STATUS);
    if (board_send(b, LINK_CMD, LINK_FLAG_SESSION, p, sizeof p) < 0)
        return -1;
    int stale = 0;
    for (;;) {
        struct board_frame f;
        if (board_wait_frame_of(b, 0xFFFFFFFFu, BOARD_SESSION_WAIT_MS, &f,
                                "the board's answer to a new session") < 0) {
            fprintf(stderr, "links1: board %s did not answer (busy with an earlier session's "
                    "command for over %d s?)\n", name, BOARD_SESSION_WAIT_MS / 1000);
            return -1;
        }
        if (f.type != LINK_RESULT || f.length < LINK_RESULT_FIXED_SIZE ||
            wire_get_u16(f.payload) != CMD_STATUS) {
            stale++;
            continue;
        }
        struct link_status_result r = {0, 0, 0};
        if (f.length >= LINK_RESULT_FIXED_SIZE + LINK_STATUS_RESULT_SIZE)
            link_status_result_get(f.payload + LINK_RESULT_FIXED_SIZE, &r);
        if (wire_get_u16(f.payload + 2) != LINK_OK || r.ncores != b->opts.ncores ||
            r.reported != r.ncores || r.halted) {
            fprintf(stderr, "links1: board %s: %u of %u unit computers up, %u halted (its "
                    "record says %d cores); `links1 board stop %s` and start it again\n",
                    name, r.reported, r.ncores, r.halted, b->opts.ncores, name);
            return -1;
        }
        board_session_naks_ours(b, 1);
        break;
    }
    uint32_t cut = board_session_adopt(b);
    if ((stale || cut) && !b->opts.quiet)
        printf("links1: board %s: dropped what an earlier session left: %d frame(s), %u "
               "byte(s) or frame(s) of a cut frame\n", name, stale, cut);
    return 0;
}

int board_connect(struct board *b, const struct board_opts *o, const char *name)
{
    char dir[4096];
    struct board_named_info info;
    memset(b, 0, sizeof *b);
    b->fd = b->ram_fd = b->lock_fd = -1;
    if (board_named_dir(name, dir, sizeof dir) < 0)
        return -1;
    struct stat st;
    if (stat(dir, &st) != 0) {
        fprintf(stderr, "links1: no board named %s is running (`links1 board start --name "
                "%s`)\n", name, name);
        return -1;
    }
    if (board_named_check_stale(name, dir, &info))
        return -1;
    int lock = board_named_lock(name, dir, 0);
    if (lock < 0)
        return -1;
    int fd = board_named_dial(dir, info.pid, 0, BOARD_FRAME_TIMEOUT_MS);
    if (fd < 0) {
        close(lock);
        return -1;
    }
    struct board_opts bo = *o;
    bo.ncores = info.ncores;
    bo.ram_mb = info.ram_mb;
    static char arith[16];
    snprintf(arith, sizeof arith, "%s", info.arith);
    bo.arith = arith;
    if (board_attach(b, &bo, fd) < 0) {
        close(fd);
        close(lock);
        return -1;
    }
    board_session_naks_ours(b, 0); /* until the board answers the session */
    b->named = 1;
    b->lock_fd = lock;
    snprintf(b->state_dir, sizeof b->state_dir, "%s", dir);
    if (board_named_map_ram(b, 0) < 0 || board_named_session(b, name) < 0) {
        board_stop(b);
        return -1;
    }
    if (!o->quiet)
        printf("links1: connected to board %s: %d cores (DM, RC, %d NCs), %s, QEMU pid %d\n",
               name, info.ncores, info.ncores - 2, info.arith, info.pid);
    return 0;
}

/* Waits up to ms for a process that is not our child to end. */
static int board_named_gone(const char *dir, int pid, int ms)
{
    long long end = board_now_ms() + ms;
    while (board_named_alive(dir, pid)) {
        if (board_now_ms() >= end)
            return 0;
        usleep(20000);
    }
    return 1;
}

int board_stop_named(const char *name)
{
    char dir[4096];
    struct board_named_info info;
    if (board_named_dir(name, dir, sizeof dir) < 0)
        return -1;
    struct stat st;
    if (stat(dir, &st) != 0) {
        fprintf(stderr, "links1: no board named %s\n", name);
        return -1;
    }
    if (board_named_check_stale(name, dir, &info))
        return 0; /* reported and removed */
    struct board_opts o;
    board_opts_init(&o);
    o.quiet = 1;
    struct board b;
    int rc = 0;
    if (board_connect(&b, &o, name) == 0) {
        b.stopping = 1;
        if (board_send_cmd(&b, CMD_SHUTDOWN, NULL, 0) == 0)
            board_session_drain(&b, BOARD_SHUTDOWN_WAIT_MS);
        board_stop(&b);
    }
    if (!board_named_gone(dir, info.pid, BOARD_SHUTDOWN_WAIT_MS)) {
        fprintf(stderr, "links1: board %s did not power off; stopping QEMU (pid %d) with "
                "SIGTERM\n", name, info.pid);
        kill(info.pid, SIGTERM);
        if (!board_named_gone(dir, info.pid, BOARD_TERM_WAIT_MS)) {
            kill(info.pid, SIGKILL);
            board_named_gone(dir, info.pid, BOARD_TERM_WAIT_MS);
        }
        rc = 1;
    }
    board_named_remove(dir);
    printf("links1: board %s stopped\n", name);
    return rc;
}

int board_list_named(void)
{
    char base[4096];
    board_named_base(base, sizeof base);
    DIR *d = opendir(base);
    int running = 0;
    if (!d) {
        printf("links1: no named boards (%s does not exist)\n", base);
        return 0;
    }
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        char dir[4400];
        snprintf(dir, sizeof dir, "%s/%s", base, e->d_name);
        struct board_named_info info;
        if (board_named_check_stale(e->d_name, dir, &info))
            continue;
        int lock = board_named_lock(e->d_name, dir, 1);
        printf("board %s: running, QEMU pid %d, %d cores (DM, RC, %d NCs), %s, %d MiB%s\n",
               e->d_name, info.pid, info.ncores, info.ncores - 2, info.arith, info.ram_mb,
               lock < 0 ? ", in use by a session" : "");
        if (lock >= 0)
            close(lock);
        running++;
    }
    closedir(d);
    if (!running)
        printf("links1: no named board is running\n");
    return running;
}
