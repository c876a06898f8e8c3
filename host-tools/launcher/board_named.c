/* board_named.c: boards that outlive the tool that started them (see
 * launcher.h, "named boards"): starting one in its state directory, the
 * session that connects to one, stopping and listing them.  The state on
 * the disk is board_state.c's. */
#include "host-tools/launcher/launcher.h"
#include "host-tools/launcher/board_state.h"
#include "host-tools/opts/exit_clean.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host-tools/link/board_text.h"
#include "proto/wire.h"

/* What a look at a board's directory found. */
struct board_seen {
    int base_fd, dir_fd;
    char base[BOARD_STATE_BASE_MAX], dir[BOARD_STATE_BASE_MAX + BOARD_NAME_MAX + 2];
    int lock;             /* board_state_lock's answer: our fd, -2 held, -3 no lock */
    int rec;              /* board_state_read's: 0 read (r), -2 no record */
    struct board_record r;
    int alive;            /* r.pid runs, and is this board's QEMU */
};

static void board_named_unlook(struct board_seen *s)
{
    if (s->lock >= 0)
        close(s->lock);
    if (s->dir_fd >= 0)
        close(s->dir_fd);
    if (s->base_fd >= 0)
        close(s->base_fd);
    s->lock = s->dir_fd = s->base_fd = -1;
}

static int board_named_name_ok(const char *name)
{
    if (board_state_name_ok(name) == 0)
        return 0;
    fprintf(stderr, "links1: board name '%s': use 1 to %d letters, digits, '_', '.' or '-', "
            "not starting with '.' or '-'\n", name, BOARD_NAME_MAX);
    return -1;
}

/* Board name's directory opened and checked, its lock tried first (so
 * nothing is judged while someone else holds it), then its record read.
 * 1 with *s filled (board_named_unlook after); 0 when there is no such
 * board; -1 after printing why it is refused. */
static int board_named_look(const char *name, int create_base, struct board_seen *s)
{
    memset(s, 0, sizeof *s);
    s->base_fd = s->dir_fd = s->lock = -1;
    if (board_named_name_ok(name) < 0)
        return -1;
    s->base_fd = board_state_base(create_base, s->base, sizeof s->base);
    if (s->base_fd < 0)
        return s->base_fd == -2 ? 0 : -1;
    snprintf(s->dir, sizeof s->dir, "%s/%.64s", s->base, name);
    s->dir_fd = board_state_dir(s->base_fd, s->base, name);
    if (s->dir_fd < 0)
        return s->dir_fd == -2 ? 0 : -1;
    s->lock = board_state_lock(s->dir_fd, s->dir);
    if (s->lock == -1)
        return -1;
    s->rec = board_state_read(s->dir_fd, s->dir, name, &s->r);
    if (s->rec == -1)
        return -1;
    s->alive = s->rec == 0 && board_state_alive(s->dir, s->r.pid);
    return 1;
}

/* The an521 set's NC boards (0 for a virt board, whose record has none). */
static int board_named_nc_boards(const struct board_record *r)
{
    return r->machine == MACHINE_AN521 ? r->ncores / AN521_CORES_PER_BOARD : 0;
}

/* How many of the set's NC boards run (each checked to be that board of
 * this directory, not a pid reused). */
static int board_named_nc_alive(const struct board_seen *s)
{
    int n = 0;
    for (int k = 1; k < board_named_nc_boards(&s->r); k++)
        n += board_state_nc_alive(s->dir, k, s->r.nc_pid[k]);
    return n;
}

/* Every NC board of the set that still runs: SIGKILL (they have no power
 * control, and nothing of theirs is kept), then waited for. */
static void board_named_kill_nc_boards(const struct board_seen *s)
{
    for (int k = 1; k < board_named_nc_boards(&s->r); k++)
        if (board_state_nc_alive(s->dir, k, s->r.nc_pid[k]))
            exit_clean_kill(s->r.nc_pid[k], SIGKILL);
    long long end = board_now_ms() + BOARD_TERM_WAIT_MS;
    while (board_named_nc_alive(s) && board_now_ms() < end)
        usleep(20000);
}

/* Why a recorded pid that still runs is not the board's: "" when no
 * process has it. */
static const char *board_named_reused(int pid)
{
    static char why[96];
    long uid = board_state_pid_uid(pid);
    if (uid < 0)
        return "";
    if (uid == (long)getuid())
        snprintf(why, sizeof why, " (pid %d is now another program of yours)", pid);
    else
        snprintf(why, sizeof why, " (pid %d is now a process of uid %ld's)", pid, uid);
    return why;
}

/* A board whose QEMU is gone and whose lock no one else holds: reported
 * and removed (1).  0 when it stays: running, or its lock held (a board
 * starting, a session). */
static int board_named_stale(const char *name, struct board_seen *s)
{
    if (s->alive || s->lock == -2)
        return 0;
    if (s->rec == 0 && s->r.machine == MACHINE_AN521)
        fprintf(stderr, "links1: board %s: its board 0's QEMU (pid %d, the DM and the RC) is "
                "gone; stopping its NC boards and removing its stale state %s\n", name,
                s->r.pid, s->dir);
    else if (s->rec == 0)
        fprintf(stderr, "links1: board %s: its QEMU (pid %d) is gone%s; removing its stale "
                "state %s\n", name, s->r.pid, board_named_reused(s->r.pid), s->dir);
    if (s->rec == 0)
        board_named_kill_nc_boards(s);
    else
        fprintf(stderr, "links1: board %s: %s has no board record and no one holds its lock; "
                "removing it\n", name, s->dir);
    board_state_remove(s->base_fd, s->dir_fd, s->dir, name);
    return 1;
}

void board_named_chardev(const struct board *b, char *out, size_t cap)
{
    board_state_chardev(b->state_dir, out, cap);
}

void board_named_redirect(const struct board *b)
{
    /* Appended to by every QEMU of an an521 set (the directory is only its
     * owner's, and no link is followed). */
    int log = openat(b->state_fd, BOARD_STATE_LOG,
                     O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
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
    b->ram_size = (size_t)b->opts.ram_mb << 20;
    int fd;
    if (create) {
        fd = board_state_create(b->state_fd, BOARD_STATE_RAM, O_RDWR);
        if (fd < 0 || ftruncate(fd, (off_t)b->ram_size) < 0) {
            fprintf(stderr, "links1: the board's RAM %s/%s: %s\n", b->state_dir,
                    BOARD_STATE_RAM, strerror(errno));
            if (fd >= 0)
                close(fd);
            return -1;
        }
    } else if ((fd = board_state_open_ram(b->state_fd, b->state_dir, b->ram_size)) < 0) {
        return -1;
    }
    void *p = mmap(NULL, b->ram_size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    if (p == MAP_FAILED) {
        fprintf(stderr, "links1: mapping the board's RAM %s/%s: %s\n", b->state_dir,
                BOARD_STATE_RAM, strerror(errno));
        close(fd);
        return -1;
    }
    b->ram = p;
    if (create)
        b->ram_fd = fd; /* QEMU maps this file through it */
    else
        close(fd);
    return 0;
}

/* Connects to the board's UART socket, retrying while QEMU creates it.
 * child: QEMU is our child (just started), so its exit can be seen. */
static int board_named_dial(const char *dir, int pid, int child, int timeout_ms)
{
    struct sockaddr_un a = {.sun_family = AF_UNIX};
    char path[PATH_MAX + 96];
    snprintf(path, sizeof path, "%s/%s", dir, BOARD_STATE_SOCKET);
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
        if ((child && waitpid(pid, &st, WNOHANG) == pid) ||
            (!child && !board_state_alive(dir, pid))) {
            if (child) /* its state, the log too, goes: board_named_abandon prints it */
                fprintf(stderr, "links1: QEMU (pid %d) ended before its UART socket took a "
                        "connection\n", pid);
            else
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
    struct board_seen s;
    int r = board_named_look(name, 1, &s);
    if (r == 1 && s.alive)
        fprintf(stderr, "links1: board %s is already running (QEMU pid %d, %d cores); "
                "`links1 board stop %s` first\n", name, s.r.pid, s.r.ncores, name);
    else if (r == 1 && s.lock == -2)
        fprintf(stderr, "links1: board %s is starting, or its QEMU is gone while a session "
                "still holds its lock: left as it is, try again later\n", name);
    if (r < 0 || (r == 1 && !board_named_stale(name, &s))) {
        board_named_unlook(&s);
        return -1;
    }
    b->state_fd = board_state_make(s.base_fd, s.base, name, &b->lock_fd);
    snprintf(b->state_dir, sizeof b->state_dir, "%s/%.64s", s.base, name);
    board_named_unlook(&s);
    if (b->state_fd < 0) {
        b->state_dir[0] = 0;
        return -1;
    }
    return 0;
}

int board_named_started(struct board *b, int timeout_ms)
{
    struct board_record r = {(int)b->qemu_pid, b->opts.ncores, b->opts.ram_mb, "",
                             b->opts.machine, {0}, b->opts.escalate};
    snprintf(r.arith, sizeof r.arith, "%s", b->opts.arith);
    for (int k = 1; k < AN521_MAX_BOARDS; k++)
        r.nc_pid[k] = (int)b->nc_board_pid[k];
    if (board_state_write(b->state_fd, b->state_dir, &r) < 0)
        return -1;
    return board_named_dial(b->state_dir, (int)b->qemu_pid, 1, timeout_ms);
}

/* The board's name: the last part of its state directory. */
static const char *board_named_name(const struct board *b)
{
    const char *slash = strrchr(b->state_dir, '/');
    return slash ? slash + 1 : b->state_dir;
}

/* The last lines of QEMU's output in the board's log, printed (before
 * the state goes with it). */
static void board_named_log_tail(const struct board *b)
{
    enum { TAIL_BYTES = 1536 };
    struct stat st;
    int fd = b->state_fd >= 0 ? openat(b->state_fd, BOARD_STATE_LOG,
                                       O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC)
                              : -1;
    char text[TAIL_BYTES + 1];
    ssize_t n = -1;
    if (fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0)
        n = pread(fd, text, TAIL_BYTES, st.st_size > TAIL_BYTES ? st.st_size - TAIL_BYTES : 0);
    if (fd >= 0)
        close(fd);
    if (n <= 0)
        return;
    char *start = text, *end = text + n;
    if (st.st_size > TAIL_BYTES && memchr(text, '\n', (size_t)n)) /* from a whole line */
        start = (char *)memchr(text, '\n', (size_t)n) + 1;
    fprintf(stderr, "links1: board %s: the end of QEMU's output (%s/%s, removed with the "
            "board's state):\n", board_named_name(b), b->state_dir, BOARD_STATE_LOG);
    while (start < end) {
        char *nl = memchr(start, '\n', (size_t)(end - start));
        size_t len = nl ? (size_t)(nl - start) : (size_t)(end - start);
        char line[BOARD_TEXT_CAP(TAIL_BYTES)];
        fprintf(stderr, "    %s\n", board_text(start, len, line, sizeof line));
        start += len + 1;
    }
}

void board_named_abandon(struct board *b)
{
    board_named_log_tail(b);
    if (b->qemu_pid > 0) {
        exit_clean_kill(b->qemu_pid, SIGKILL);
        waitpid(b->qemu_pid, NULL, 0);
        exit_clean_drop_child(b->qemu_pid);
        b->qemu_pid = 0;
    }
    for (int k = 1; k < AN521_MAX_BOARDS; k++) { /* an an521 set's NC boards */
        if (b->nc_board_pid[k] > 0) {
            exit_clean_kill(b->nc_board_pid[k], SIGKILL);
            waitpid(b->nc_board_pid[k], NULL, 0);
            exit_clean_drop_child(b->nc_board_pid[k]);
            b->nc_board_pid[k] = 0;
        }
    }
    char base[BOARD_STATE_BASE_MAX];
    int base_fd = b->state_fd >= 0 ? board_state_base(0, base, sizeof base) : -1;
    if (base_fd >= 0) {
        board_state_remove(base_fd, b->state_fd, b->state_dir, board_named_name(b));
        close(base_fd);
    }
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
    struct board_seen s;
    memset(b, 0, sizeof *b);
    b->fd = b->ram_fd = b->lock_fd = b->state_fd = -1;
    int r = board_named_look(name, 0, &s);
    if (r == 0)
        fprintf(stderr, "links1: no board named %s is running (`links1 board start --name "
                "%s`)\n", name, name);
    else if (r == 1 && s.lock == -2)
        fprintf(stderr, "links1: board %s is in use by another links1 session (or still "
                "starting)\n", name);
    else if (r == 1 && !s.alive && board_named_stale(name, &s))
        fprintf(stderr, "links1: board %s is not running (`links1 board start --name %s`)\n",
                name, name);
    else if (r == 1 && s.lock == -3)
        fprintf(stderr, "links1: board %s: %s has no lock file: not a board's state\n", name,
                s.dir);
    if (r != 1 || s.lock < 0 || !s.alive) {
        board_named_unlook(&s);
        return -1;
    }
    int fd = board_named_dial(s.dir, s.r.pid, 0, BOARD_FRAME_TIMEOUT_MS);
    struct board_opts bo = *o;
    bo.ncores = s.r.ncores;
    bo.ram_mb = s.r.ram_mb;
    bo.machine = s.r.machine;
    static char arith[sizeof s.r.arith];
    snprintf(arith, sizeof arith, "%s", s.r.arith);
    bo.arith = arith;
    if (fd < 0 || board_attach(b, &bo, fd) < 0) {
        if (fd >= 0)
            close(fd);
        board_named_unlook(&s);
        return -1;
    }
    b->process_gone = board_qemu_gone;
    board_session_naks_ours(b, 0); /* until the board answers the session */
    b->named = 1;
    b->lock_fd = s.lock;
    b->state_fd = s.dir_fd;
    s.lock = s.dir_fd = -1; /* the session's now */
    snprintf(b->state_dir, sizeof b->state_dir, "%s", s.dir);
    int pid = s.r.pid;
    board_named_unlook(&s);
    if (board_named_map_ram(b, 0) < 0 || board_named_session(b, name) < 0) {
        board_stop(b);
        return -1;
    }
    if (!o->quiet && b->opts.machine == MACHINE_AN521)
        printf("links1: connected to board %s: %d an521 boards (board 0: DM and RC, QEMU pid "
               "%d; %d NCs on boards 1..%d), %s\n", name, b->opts.ncores / AN521_CORES_PER_BOARD,
               pid, b->opts.ncores - 2, b->opts.ncores / AN521_CORES_PER_BOARD - 1,
               b->opts.arith);
    else if (!o->quiet)
        printf("links1: connected to board %s: %d cores (DM, RC, %d NCs), %s, QEMU pid %d\n",
               name, b->opts.ncores, b->opts.ncores - 2, b->opts.arith, pid);
    return 0;
}

/* Waits up to ms for the board's QEMU (not our child) to end. */
static int board_named_gone(const char *dir, int pid, int ms)
{
    long long end = board_now_ms() + ms;
    while (board_state_alive(dir, pid)) {
        if (board_now_ms() >= end)
            return 0;
        usleep(20000);
    }
    return 1;
}

/* After its QEMU ended: the board's state removed, unless someone holds
 * its lock. */
static void board_named_clear(const char *name)
{
    struct board_seen s;
    if (board_named_look(name, 0, &s) == 1 && !s.alive && s.lock != -2)
        board_state_remove(s.base_fd, s.dir_fd, s.dir, name);
    board_named_unlook(&s);
}

/* The board's QEMU (pid, not our child) that did not power off: SIGTERM,
 * then SIGKILL.  1 once it is gone; 0 after saying why it still runs (a
 * signal refused: then it was not this user's to stop). */
static int board_named_kill(const char *name, const char *dir, int pid)
{
    fprintf(stderr, "links1: board %s did not power off; stopping QEMU (pid %d) with "
            "SIGTERM\n", name, pid);
    int sig = SIGTERM;
    for (int i = 0; i < 2 && board_state_alive(dir, pid); i++, sig = SIGKILL) {
        if (exit_clean_kill(pid, sig) != 0 && errno != ESRCH) {
            fprintf(stderr, "links1: board %s: %s to QEMU (pid %d): %s\n", name,
                    sig == SIGTERM ? "SIGTERM" : "SIGKILL", pid, strerror(errno));
            break;
        }
        board_named_gone(dir, pid, BOARD_TERM_WAIT_MS);
    }
    return !board_state_alive(dir, pid);
}

int board_stop_named(const char *name)
{
    struct board_seen s;
    int r = board_named_look(name, 0, &s);
    if (r == 0)
        fprintf(stderr, "links1: no board named %s\n", name);
    if (r != 1) {
        board_named_unlook(&s);
        return -1;
    }
    if (!s.alive) {
        int gone = board_named_stale(name, &s); /* reported and removed */
        if (gone)
            printf("links1: board %s was not running (its stale state is removed)\n", name);
        else
            fprintf(stderr, "links1: board %s: its QEMU is not running, but its lock is held "
                    "(starting, or a session still ending): left as it is\n", name);
        board_named_unlook(&s);
        return gone ? 0 : -1;
    }
    int pid = s.r.pid;
    char dir[sizeof s.dir];
    snprintf(dir, sizeof dir, "%s", s.dir);
    struct board_seen nc = s; /* an an521 set's NC boards, stopped after board 0 */
    board_named_unlook(&s); /* its lock let go: the session below takes it */
    struct board_opts o;
    board_opts_init(&o);
    o.quiet = 1;
    struct board b;
    if (board_connect(&b, &o, name) == 0) {
        b.stopping = 1;
        if (board_send_cmd(&b, CMD_SHUTDOWN, NULL, 0) == 0)
            board_session_drain(&b, BOARD_SHUTDOWN_WAIT_MS);
        board_stop(&b);
    }
    if (!board_named_gone(dir, pid, BOARD_SHUTDOWN_WAIT_MS) && !board_named_kill(name, dir, pid)) {
        fprintf(stderr, "links1: board %s is still running (QEMU pid %d): not stopped, its "
                "state left as it is\n", name, pid);
        return -1;
    }
    int rc = 0;
    board_named_kill_nc_boards(&nc);
    if (board_named_nc_alive(&nc)) {
        fprintf(stderr, "links1: board %s: an NC board's QEMU outlived SIGKILL\n", name);
        rc = -1;
    }
    board_named_clear(name);
    printf("links1: board %s stopped%s\n", name, rc ? " (but not every NC board)" : "");
    return rc;
}

/* A running an521 set: one line for the set, one for each NC board that
 * is gone (its NCs' areas then go to the others: the RC's watchdog). */
static void board_named_print_set(const char *name, const struct board_seen *s)
{
    int boards = board_named_nc_boards(&s->r), up = board_named_nc_alive(s);
    printf("board %s: running, an521, %d boards (board 0: DM and RC, QEMU pid %d; %d NCs on "
           "boards 1..%d, %d of %d NC boards running), %s%s\n", name, boards, s->r.pid,
           s->r.ncores - 2, boards - 1, up, boards - 1, s->r.arith,
           s->lock == -2 ? ", in use by a session" : "");
    for (int k = 1; k < boards; k++) {
        if (board_state_nc_alive(s->dir, k, s->r.nc_pid[k]))
            printf("board %s: NC board %d (NCs %d, %d): running, QEMU pid %d\n", name, k,
                   k * AN521_CORES_PER_BOARD, k * AN521_CORES_PER_BOARD + 1, s->r.nc_pid[k]);
        else
            printf("board %s: NC board %d (NCs %d, %d): its QEMU (pid %d) is gone\n", name, k,
                   k * AN521_CORES_PER_BOARD, k * AN521_CORES_PER_BOARD + 1, s->r.nc_pid[k]);
    }
}

/* One entry of the base for board list: 1 when it is a board running. */
static int board_named_list_one(const char *base, const char *name)
{
    if (board_state_name_ok(name) < 0) {
        fprintf(stderr, "links1: %s/%s: not a board's directory (not a board's name); left "
                "as it is\n", base, name);
        return 0;
    }
    struct board_seen s;
    int running = 0;
    if (board_named_look(name, 0, &s) == 1) {
        if (s.alive && s.r.machine == MACHINE_AN521) {
            board_named_print_set(name, &s);
            running = 1;
        } else if (s.alive) {
            printf("board %s: running, QEMU pid %d, %d cores (DM, RC, %d NCs), %s, %d MiB%s\n",
                   name, s.r.pid, s.r.ncores, s.r.ncores - 2, s.r.arith, s.r.ram_mb,
                   s.lock == -2 ? ", in use by a session" : "");
            running = 1;
        } else if (!board_named_stale(name, &s)) {
            printf("board %s: %s (its lock is held); left as it is\n", name,
                   s.rec == 0 ? "its QEMU is gone, a session still ends" : "starting");
        }
    }
    board_named_unlook(&s);
    return running;
}

int board_list_named(void)
{
    char base[BOARD_STATE_BASE_MAX];
    int base_fd = board_state_base(0, base, sizeof base);
    if (base_fd == -2) {
        printf("links1: no named boards (no state directory yet)\n");
        return 0;
    }
    if (base_fd < 0)
        return -1; /* refused, and said why */
    DIR *d = fdopendir(base_fd);
    if (!d) {
        fprintf(stderr, "links1: %s: %s\n", base, strerror(errno));
        close(base_fd);
        return -1;
    }
    int running = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        if (e->d_name[0] != '.')
            running += board_named_list_one(base, e->d_name);
    closedir(d);
    if (!running)
        printf("links1: no named board is running\n");
    return running;
}

int board_status_named(const char *name)
{
    struct board_seen s;
    int r = board_named_look(name, 0, &s);
    board_named_unlook(&s); /* its lock let go at once: a session may take it */
    if (r == 0)
        fprintf(stderr, "links1: no board named %s\n", name);
    if (r != 1)
        return -1;
    return board_named_list_one(s.base, name) ? 0 : -1;
}

int board_named_machine(const char *name, int *wide)
{
    char base[BOARD_STATE_BASE_MAX], dir[BOARD_STATE_BASE_MAX + BOARD_NAME_MAX + 2];
    if (board_named_name_ok(name) < 0)
        return -1;
    int base_fd = board_state_base(0, base, sizeof base);
    int dir_fd = base_fd >= 0 ? board_state_dir(base_fd, base, name) : base_fd;
    struct board_record r;
    int rec = -2;
    if (dir_fd >= 0) { /* read without its lock: a session may hold it */
        snprintf(dir, sizeof dir, "%s/%.64s", base, name);
        rec = board_state_read(dir_fd, dir, name, &r);
        close(dir_fd);
    }
    if (base_fd >= 0)
        close(base_fd);
    if (dir_fd == -2 || rec == -2)
        fprintf(stderr, "links1: no board named %s is running (`links1 board start --name "
                "%s`)\n", name, name);
    if (dir_fd < 0 || rec < 0)
        return -1;
    *wide = r.wide;
    return r.machine;
}
