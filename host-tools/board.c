/* board.c: start QEMU, frame I/O with the board, stop QEMU (see board.h). */
#define _GNU_SOURCE /* memfd_create */
#include "host-tools/board.h"
#include "host-tools/link_relay.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "proto/board_map.h"
#include "proto/wire.h"

long long board_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

const char *board_role_name(int core)
{
    return core == ROLE_DM ? "DM" : core == ROLE_RC ? "RC" : "NC";
}

/* ------------------------------------------------------------ QEMU process */

/* The emulator: $QEMU, else qemu-system-arm from $PATH. */
static const char *board_qemu_binary(void)
{
    const char *qemu = getenv("QEMU");
    return qemu && *qemu ? qemu : "qemu-system-arm";
}

static void board_qemu_exec_failed(const char *qemu)
{
    fprintf(stderr, "links1: cannot run %s: %s (install qemu-system-arm, or set $QEMU)\n",
            qemu, strerror(errno));
    _exit(127);
}

/* In the child.  A board of this tool's own (qemu_fd >= 0, the UART on a
 * socket pair, the RAM our memfd) must not outlive the tool, whatever ends
 * the tool; a named board (qemu_fd < 0: the UART a listening socket, the RAM
 * a file, both in its state directory) runs on in a session of its own. */
static void board_qemu_exec(struct board *b, int qemu_fd)
{
    char smp[32], mem[32], chardev[PATH_MAX + 64], plugin[3 * PATH_MAX], ram[PATH_MAX + 96];
    snprintf(smp, sizeof smp, "%d", b->opts.ncores);
    snprintf(mem, sizeof mem, "%dM", b->opts.ram_mb);
    if (qemu_fd >= 0) {
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        fcntl(qemu_fd, F_SETFD, 0); /* keep QEMU's end open across exec */
        snprintf(chardev, sizeof chardev, "socket,id=link,fd=%d", qemu_fd);
        /* The RAM is our memfd, shared: QEMU opens it again through /proc. */
        fcntl(b->ram_fd, F_SETFD, 0);
        snprintf(ram, sizeof ram, "memory-backend-file,id=ram,size=%dM,"
                 "mem-path=/proc/self/fd/%d,share=on", b->opts.ram_mb, b->ram_fd);
    } else {
        setsid();
        board_named_redirect(b);
        /* wait=on: the guest starts only once `board start` is connected,
         * so no report-in is lost. */
        snprintf(chardev, sizeof chardev, "socket,id=link,path=%s/%s,server=on,wait=on",
                 b->state_dir, BOARD_STATE_SOCKET);
        snprintf(ram, sizeof ram, "memory-backend-file,id=ram,size=%dM,mem-path=%s/%s,share=on",
                 b->opts.ram_mb, b->state_dir, BOARD_STATE_RAM);
    }
    const char *qemu = board_qemu_binary();
    const char *argv[40];
    int n = 0;
    argv[n++] = qemu;
    argv[n++] = "-M";
    argv[n++] = "virt,gic-version=3,memory-backend=ram";
    argv[n++] = "-object";
    argv[n++] = ram;
    argv[n++] = "-cpu";
    argv[n++] = "cortex-a15";
    argv[n++] = "-smp";
    argv[n++] = smp;
    argv[n++] = "-m";
    argv[n++] = mem;
    argv[n++] = "-display";
    /* --view: the frame memory shown live through ramfb in QEMU's display
     * ($LINKS1_DISPLAY, default gtk). */
    const char *display = getenv("LINKS1_DISPLAY");
    argv[n++] = !b->opts.view ? "none" : display && *display ? display : "gtk";
    argv[n++] = "-nodefaults";
    if (b->opts.view) {
        argv[n++] = "-device";
        argv[n++] = "ramfb";
    }
    /* $LINKS1_MONITOR=PATH: QEMU's human monitor on a unix socket, e.g. for
     * `screendump` of the ramfb view while a frame renders. */
    const char *monitor = getenv("LINKS1_MONITOR");
    char monitor_arg[PATH_MAX + 40];
    if (monitor && *monitor) {
        snprintf(monitor_arg, sizeof monitor_arg, "unix:%s,server=on,wait=off", monitor);
        argv[n++] = "-monitor";
        argv[n++] = monitor_arg;
    }
    char gdb[48];
    if (b->opts.gdb_port) {
        /* Halted at the first instruction until the debugger continues. */
        snprintf(gdb, sizeof gdb, "tcp:127.0.0.1:%d", b->opts.gdb_port);
        argv[n++] = "-gdb";
        argv[n++] = gdb;
        argv[n++] = "-S";
    }
    argv[n++] = "-no-reboot"; /* a reset request ends the run instead of looping */
    argv[n++] = "-chardev";
    argv[n++] = chardev;
    argv[n++] = "-serial";
    argv[n++] = "chardev:link";
    argv[n++] = "-kernel";
    argv[n++] = b->firmware;
    if (b->opts.insn_count_out || b->opts.insn_series_out || b->opts.insn_trace_out) {
        const char *so = getenv("LINKS1_INSN_PLUGIN");
        char self[PATH_MAX], args[2 * PATH_MAX];
        if (!so || !*so) {
            ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
            self[len > 0 ? len : 0] = 0;
            char *slash = strrchr(self, '/');
            if (slash)
                *slash = 0;
            snprintf(plugin, sizeof plugin, "%s/insn-count.so", self);
        } else {
            snprintf(plugin, sizeof plugin, "%s", so);
        }
        if (b->opts.insn_count_out)
            snprintf(args, sizeof args, ",out=%s", b->opts.insn_count_out);
        else
            args[0] = 0;
        if (b->opts.insn_series_out)
            snprintf(args + strlen(args), sizeof args - strlen(args), ",series=%s,every=%d",
                     b->opts.insn_series_out, b->opts.insn_series_ms);
        if (b->opts.insn_trace_out)
            snprintf(args + strlen(args), sizeof args - strlen(args), ",trace=%s",
                     b->opts.insn_trace_out);
        snprintf(plugin + strlen(plugin), sizeof plugin - strlen(plugin), "%s", args);
        argv[n++] = "-plugin";
        argv[n++] = plugin;
    }
    argv[n] = NULL;
    execvp(qemu, (char *const *)argv);
    board_qemu_exec_failed(qemu);
}

int board_run_semihost(const char *elf, int ram_mb)
{
    if (access(elf, R_OK) < 0) {
        fprintf(stderr, "links1: program %s: %s\n", elf, strerror(errno));
        return -1;
    }
    char mem[32];
    snprintf(mem, sizeof mem, "%dM", ram_mb);
    const char *qemu = board_qemu_binary();
    /* One core of the plain virt board; the program's semihosted console
     * is QEMU's stdio chardev, so its output is our stdout. */
    const char *argv[] = {qemu, "-M", "virt", "-cpu", "cortex-a15", "-m", mem,
                          "-display", "none", "-nodefaults", "-no-reboot",
                          "-chardev", "stdio,id=semihost,signal=off",
                          "-semihosting-config", "enable=on,target=native,chardev=semihost",
                          "-kernel", elf, NULL};
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "links1: fork: %s\n", strerror(errno));
        return -1;
    }
    if (pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        int null = open("/dev/null", O_RDONLY);
        if (null >= 0)
            dup2(null, 0); /* the program reads nothing; keep a terminal cooked */
        execvp(qemu, (char *const *)argv);
        board_qemu_exec_failed(qemu);
    }
    int st;
    while (waitpid(pid, &st, 0) < 0) {
        if (errno != EINTR) {
            fprintf(stderr, "links1: waitpid: %s\n", strerror(errno));
            return -1;
        }
    }
    if (WIFEXITED(st))
        return WEXITSTATUS(st);
    fprintf(stderr, "links1: QEMU was killed by signal %d\n", WTERMSIG(st));
    return -1;
}

static void board_init(struct board *b, const struct board_opts *o)
{
    memset(b, 0, sizeof *b);
    b->opts = *o;
    b->fd = -1;
    b->ram_fd = -1;
    b->lock_fd = -1;
    b->started_ms = board_now_ms();
    link_decoder_init(&b->dec);
    /* We number our frames from 0; the board's numbering is learnt from its
     * first frame, except on a board we boot (board_start: from 0). */
    link_arq_store_init(&b->arq_tx, 0);
    link_arq_rx_init(&b->arq_rx);
    b->arq_heard_ms = b->arq_byte_ms = b->started_ms;
    b->arq_naks_heard = 1;
}

/* The board's RAM as a memfd, mapped here (proto/board_map.h). */
static int board_ram_create(struct board *b)
{
    b->ram_size = (size_t)b->opts.ram_mb << 20;
    b->ram_fd = memfd_create("links1-board-ram", MFD_CLOEXEC);
    if (b->ram_fd < 0 || ftruncate(b->ram_fd, (off_t)b->ram_size) < 0) {
        fprintf(stderr, "links1: the board's %d MiB of shared RAM: %s\n", b->opts.ram_mb,
                strerror(errno));
        return -1;
    }
    void *p = mmap(NULL, b->ram_size, PROT_READ | PROT_WRITE, MAP_SHARED, b->ram_fd, 0);
    if (p == MAP_FAILED) {
        fprintf(stderr, "links1: mapping the board's RAM: %s\n", strerror(errno));
        return -1;
    }
    b->ram = p;
    return 0;
}

static void board_ram_release(struct board *b)
{
    if (b->ram)
        munmap(b->ram, b->ram_size);
    if (b->ram_fd >= 0)
        close(b->ram_fd);
    b->ram = NULL;
    b->ram_fd = -1;
}

static void board_take_fd(struct board *b, int fd)
{
    b->fd = fd;
    fcntl(b->fd, F_SETFL, fcntl(b->fd, F_GETFL) | O_NONBLOCK);
}

void board_attach(struct board *b, const struct board_opts *o, int fd)
{
    board_init(b, o);
    board_take_fd(b, fd);
}

/* --link-noise: a relay between our end (returned) and QEMU's socket. */
static int board_noise_relay(const struct board_opts *o, int qemu_side)
{
    int rv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, rv) < 0) {
        fprintf(stderr, "links1: socketpair: %s\n", strerror(errno));
        close(qemu_side);
        return -1;
    }
    /* Like a line, and unlike a socket, the relay holds few bytes: a small
     * send buffer on each hop towards the board, so a resend is not queued
     * behind ~200 KiB of older bytes (the host writes faster than the
     * board reads; a late resend makes the board ask again, and the asks
     * pile up: at 1e-3 on the serial path, seed 3 rendered in 23 s before,
     * 10 s after). */
    int small = BOARD_RELAY_SNDBUF;
    setsockopt(rv[0], SOL_SOCKET, SO_SNDBUF, &small, sizeof small);
    setsockopt(qemu_side, SOL_SOCKET, SO_SNDBUF, &small, sizeof small);
    if (link_relay_start(rv[1], qemu_side, o->link_noise, o->link_noise_seed) < 0) {
        close(rv[0]);
        close(rv[1]);
        close(qemu_side);
        return -1;
    }
    if (!o->quiet)
        printf("links1: link noise %g per byte each way (seed %llu)\n", o->link_noise,
               (unsigned long long)o->link_noise_seed);
    return rv[0];
}

int board_start(struct board *b, const struct board_opts *o)
{
    board_init(b, o);
    b->arq_rx.known = 1; /* the board we boot numbers its frames from 0 */
    if (board_find_firmware(o, b->firmware, sizeof b->firmware) < 0)
        return -1;
    if (o->ncores < UNITS_MIN_CORES || o->ncores > UNITS_MAX_CORES) {
        fprintf(stderr, "links1: %d cores: the board needs %d..%d\n", o->ncores,
                UNITS_MIN_CORES, UNITS_MAX_CORES);
        return -1;
    }
    if (board_ram_create(b) < 0) {
        board_ram_release(b);
        return -1;
    }
    /* A write to a socket QEMU has closed must fail with EPIPE, not kill us. */
    signal(SIGPIPE, SIG_IGN);
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) < 0) {
        fprintf(stderr, "links1: socketpair: %s\n", strerror(errno));
        return -1;
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "links1: fork: %s\n", strerror(errno));
        close(sv[0]);
        close(sv[1]);
        return -1;
    }
    if (pid == 0)
        board_qemu_exec(b, sv[1]);
    close(sv[1]);
    b->qemu_pid = pid;
    int tool_fd = sv[0];
    if (o->link_noise_on && (tool_fd = board_noise_relay(o, sv[0])) < 0) {
        board_stop(b);
        return -1;
    }
    board_take_fd(b, tool_fd);
    if (!o->quiet)
        printf("links1: booting %s on %d cores (DM, RC, %d NCs), QEMU pid %d\n",
               b->firmware, o->ncores, o->ncores - 2, (int)pid);
    return 0;
}

int board_start_named(struct board *b, const struct board_opts *o, const char *name,
                      int timeout_ms)
{
    board_init(b, o);
    b->arq_rx.known = 1; /* the board we boot numbers its frames from 0 */
    b->named = 1;
    if (o->link_noise_on) {
        fprintf(stderr, "links1: --link-noise works on a board the command starts and "
                "stops, not a named board\n");
        return -1;
    }
    if (board_find_firmware(o, b->firmware, sizeof b->firmware) < 0)
        return -1;
    if (o->ncores < UNITS_MIN_CORES || o->ncores > UNITS_MAX_CORES) {
        fprintf(stderr, "links1: %d cores: the board needs %d..%d\n", o->ncores,
                UNITS_MIN_CORES, UNITS_MAX_CORES);
        return -1;
    }
    if (board_named_prepare(b, name) < 0) {
        if (b->lock_fd >= 0)
            board_named_abandon(b);
        b->state_dir[0] = 0;
        board_stop(b);
        return -1;
    }
    if (board_named_map_ram(b, 1) < 0) {
        board_named_abandon(b);
        board_stop(b);
        return -1;
    }
    signal(SIGPIPE, SIG_IGN);
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "links1: fork: %s\n", strerror(errno));
        board_named_abandon(b);
        board_stop(b);
        return -1;
    }
    if (pid == 0)
        board_qemu_exec(b, -1);
    b->qemu_pid = pid;
    int fd = board_named_started(b, timeout_ms);
    if (fd < 0) {
        board_named_abandon(b);
        board_stop(b);
        return -1;
    }
    board_take_fd(b, fd);
    if (!o->quiet)
        printf("links1: booting %s on %d cores (DM, RC, %d NCs) as board %s, QEMU pid %d\n",
               b->firmware, o->ncores, o->ncores - 2, name, (int)pid);
    if (board_wait_reported(b, timeout_ms) < 0) {
        board_named_abandon(b);
        board_stop(b);
        return -1;
    }
    return 0;
}

/* Waits up to timeout_ms for QEMU to exit; returns 1 once reaped. */
static int board_qemu_reap(struct board *b, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    while (b->qemu_pid) {
        pid_t r = waitpid(b->qemu_pid, &b->qemu_status, WNOHANG);
        if (r == b->qemu_pid || (r < 0 && errno == ECHILD)) {
            b->qemu_pid = 0;
            break;
        }
        if (board_now_ms() >= end)
            return 0;
        usleep(10000);
    }
    return 1;
}

static void board_qemu_exit_text(const struct board *b, char *out, size_t cap)
{
    int st = b->qemu_status;
    if (WIFEXITED(st))
        snprintf(out, cap, "QEMU exited with status %d", WEXITSTATUS(st));
    else if (WIFSIGNALED(st))
        snprintf(out, cap, "QEMU was killed by signal %d", WTERMSIG(st));
    else
        snprintf(out, cap, "QEMU stopped (wait status 0x%x)", st);
}

/* ------------------------------------------------------- incoming frames */

/* The socket reached end-of-file or failed: QEMU is gone. */
static int board_lost(struct board *b, const char *why)
{
    char desc[96];
    if (b->fd >= 0) {
        close(b->fd);
        b->fd = -1;
    }
    if (b->stopping)
        return -1; /* the shutdown we asked for */
    if (b->named && !b->qemu_pid)
        snprintf(desc, sizeof desc, "the named board's QEMU closed the link or ended");
    else if (board_qemu_reap(b, BOARD_TERM_WAIT_MS))
        board_qemu_exit_text(b, desc, sizeof desc);
    else
        snprintf(desc, sizeof desc, "QEMU (pid %d) is still running", (int)b->qemu_pid);
    fprintf(stderr, "links1: the board stopped talking (%s): %s\n", why, desc);
    return -1;
}

/* ---- the retransmission (proto/link_arq.h, go-back-N) ---- */

static int board_write_all(struct board *b, const uint8_t *p, size_t n, int timeout_ms);

/* The retransmission gives up: every wait from now on fails. */
static int board_arq_give_up(struct board *b, const char *why)
{
    if (!b->arq_failed)
        fprintf(stderr, "links1: the host link gave up: %s (noise on the link: %u bad CRC, "
                "%u bad length, %u junk bytes from the board; %u frames from the host "
                "dropped by the board)\n", why, b->dec.stats.crc_errors,
                b->dec.stats.bad_length, b->dec.stats.junk_bytes, b->host_frames_dropped);
    b->arq_failed = 1;
    return -1;
}

/* A NAK asked for while a frame is being written (the write reads the board
 * meanwhile) goes out after it, never inside it (board_write_all). */
static int board_send_nak(struct board *b, uint8_t flags)
{
    if (b->arq_writing) {
        b->arq_nak_due = 1;
        b->arq_nak_flags = flags;
        return 0;
    }
    uint8_t f[LINK_HEADER_SIZE + LINK_ACK_SIZE + LINK_CRC_SIZE];
    size_t n = link_arq_nak_encode(f, sizeof f, flags, b->arq_rx.expect);
    return board_write_all(b, f, n, BOARD_FRAME_TIMEOUT_MS);
}

/* The board's frame we expect was lost (a gap, a damaged frame): ask for it,
 * at most once per LINK_ARQ_NAK_MS, and give up after LINK_ARQ_MAX_ASKS
 * asks in a row. */
static int board_arq_lost(struct board *b)
{
    b->arq_armed = b->arq_damage_seen = b->arq_gap = 1;
    if (!b->arq_rx.known)
        return 0; /* the board's numbering is not known yet: nothing to name */
    if (!link_arq_nak_due(&b->arq_nak, b->arq_rx.expect, (uint64_t)board_now_ms(),
                          LINK_ARQ_NAK_MS))
        return 0;
    if (b->arq_nak.tries > LINK_ARQ_MAX_ASKS) {
        char why[96];
        snprintf(why, sizeof why, "frame %u from the board did not come through whole after "
                 "%d requests", b->arq_rx.expect, LINK_ARQ_MAX_ASKS);
        return board_arq_give_up(b, why);
    }
    return board_send_nak(b, 0);
}

static int board_arq_resend(struct board *b, uint16_t from);

/* A LINK_NAK from the board: our frames from the seq it names, sent again.
 * One naming our next frame says the board lacks nothing of ours (its
 * answer to a poll, or to the junk of our poll's zero bytes): the link is
 * back in step when it answers our poll and we lack nothing either, and
 * polling stops. */
static int board_arq_nak_in(struct board *b, const struct link_frame *f, int polled)
{
    if (f->length < LINK_ACK_SIZE || !b->arq_naks_heard) {
        b->arq_armed = 1;
        return 0;
    }
    uint16_t from = wire_get_u16(f->payload);
    if (!(f->flags & LINK_FLAG_GONE) && from == b->arq_tx.next_seq && !b->arq_writing) {
        /* (the decoder still holds this frame: bytes past it are partial) */
        if (polled && !b->arq_gap && b->dec.have <= b->dec.delivered)
            b->arq_armed = 0;
        return 0;
    }
    b->arq_armed = b->arq_damage_seen = 1;
    char why[96];
    if (f->flags & LINK_FLAG_GONE) {
        snprintf(why, sizeof why, "the board no longer holds its frame %u that we asked for",
                 from);
        return board_arq_give_up(b, why);
    }
    if (b->arq_writing) { /* resent after the frame being written */
        b->arq_resend_due = 1;
        b->arq_resend_from = from;
        return 0;
    }
    return board_arq_resend(b, from);
}

/* Our kept frames from seq from on, sent again (up to LINK_ARQ_RESEND_BYTES). */
static int board_arq_resend(struct board *b, uint16_t from)
{
    char why[96];
    int span = link_arq_store_span(&b->arq_tx, from);
    if (span > 0) {
        b->arq_asked = b->arq_asked && b->arq_asked_from == from ? b->arq_asked + 1 : 1;
        b->arq_asked_from = from;
        if (b->arq_asked > LINK_ARQ_MAX_ASKS) {
            snprintf(why, sizeof why, "our frame %u did not reach the board whole after %d "
                     "resends", from, LINK_ARQ_MAX_ASKS);
            return board_arq_give_up(b, why);
        }
    }
    if (span < 0) {
        snprintf(why, sizeof why, "the board asked for our frame %u, no longer held", from);
        board_send_nak(b, LINK_FLAG_GONE);
        return board_arq_give_up(b, why);
    }
    span = link_arq_store_resend_count(&b->arq_tx, from, span);
    for (int i = 0; i < span; i++) {
        uint8_t frame[LINK_MAX_FRAME];
        size_t n = link_arq_store_get(&b->arq_tx, (uint16_t)(from + i), frame, sizeof frame);
        if (board_write_all(b, frame, n, BOARD_FRAME_TIMEOUT_MS) < 0)
            return -1;
        b->arq_resends++;
    }
    return 0;
}

/* A good frame from the board: NAKs answered, numbered frames handled in
 * seq order only, each once. */
static int board_arq_frame(struct board *b, const struct link_frame *f)
{
    int polled = b->arq_polls > 0;
    b->arq_heard_ms = board_now_ms();
    b->arq_polls = 0;
    if (f->type == LINK_NAK)
        return board_arq_nak_in(b, f, polled);
    switch (link_arq_rx_take(&b->arq_rx, f)) {
    case LINK_ARQ_NEW:
        b->arq_gap = 0;
        return board_handle_frame(b, f);
    case LINK_ARQ_DUP:
        b->arq_dups++;
        return 0;
    default:
        return board_arq_lost(b);
    }
}

/* Nothing heard for LINK_ARQ_POLL_MS on a link seen damaged: our partial
 * frame is given up, the board's is completed by LINK_ARQ_FLUSH_BYTES zero
 * bytes, and a poll asks the board to send again what we lack and to name
 * what it lacks. */
static int board_arq_poll(struct board *b)
{
    struct link_frame f;
    while (b->dec.have) {
        if (link_decoder_unstick(&b->dec, &f) && board_arq_frame(b, &f) < 0)
            return -1;
    }
    b->arq_heard_ms = board_now_ms();
    if (!b->arq_rx.known)
        return 0; /* the first good frame sets the numbering */
    if (++b->arq_polls > LINK_ARQ_MAX_TRIES) {
        char why[96];
        snprintf(why, sizeof why, "%d polls over %d s brought no frame from the board",
                 LINK_ARQ_MAX_TRIES, LINK_ARQ_MAX_TRIES * LINK_ARQ_POLL_MS / 1000);
        return board_arq_give_up(b, why);
    }
    static const uint8_t zeros[LINK_ARQ_FLUSH_BYTES];
    if (board_write_all(b, zeros, sizeof zeros, BOARD_FRAME_TIMEOUT_MS) < 0)
        return -1;
    return board_send_nak(b, LINK_FLAG_POLL);
}

int board_arq_failed(const struct board *b)
{
    return b->arq_failed;
}

/* Reads what is available now and handles every completed frame. */
static int board_read_available(struct board *b)
{
    uint8_t buf[BOARD_READ_CHUNK];
    for (;;) {
        ssize_t n = read(b->fd, buf, sizeof buf);
        if (n == 0)
            return board_lost(b, "end of the UART socket");
        if (n < 0) {
            if (errno == EINTR)
                continue;
            if (errno == EAGAIN || errno == EWOULDBLOCK)
                return 0;
            return board_lost(b, strerror(errno));
        }
        b->arq_byte_ms = board_now_ms();
        for (ssize_t i = 0; i < n; i++) {
            struct link_frame f;
            const struct link_stats *s = &b->dec.stats;
            uint32_t damaged = s->crc_errors + s->bad_length, junk = s->junk_bytes;
            int got = link_decoder_push(&b->dec, buf[i], &f);
            if (s->crc_errors + s->bad_length != damaged && board_arq_lost(b) < 0)
                return -1;
            if (s->junk_bytes != junk)
                b->arq_armed = b->arq_damage_seen = 1;
            if (got && board_arq_frame(b, &f) < 0)
                return -1;
        }
        fflush(stdout);
        if ((size_t)n < sizeof buf)
            return 0; /* drained: no need for a read that says EAGAIN */
    }
}

/* How long a partial frame may wait for its next byte before it counts as
 * damage: long on a link never seen damaged. */
static long long board_arq_stall_ms(const struct board *b)
{
    return b->arq_damage_seen ? LINK_ARQ_STALL_MS : LINK_ARQ_STALL_CLEAN_MS;
}

int board_pump(struct board *b, int timeout_ms)
{
    if (b->fd < 0 || b->arq_failed)
        return -1;
    int wait = timeout_ms < 0 ? 0 : timeout_ms;
    if (b->arq_armed || b->dec.have) {
        long long due = b->arq_armed ? b->arq_heard_ms + LINK_ARQ_POLL_MS
                                     : b->arq_byte_ms + board_arq_stall_ms(b);
        due -= board_now_ms();
        if (due < wait)
            wait = due < 0 ? 0 : (int)due;
    }
    struct pollfd p = {.fd = b->fd, .events = POLLIN};
    int r = poll(&p, 1, wait);
    if (r < 0 && errno != EINTR) {
        fprintf(stderr, "links1: poll: %s\n", strerror(errno));
        return -1;
    }
    if (r > 0) {
        /* QEMU writes the UART to the socket one byte at a time; a short
         * pause lets a batch gather, so a fast stream costs one read per
         * batch instead of a wake-up per byte (host CPU QEMU needs). */
        struct timespec batch = {0, BOARD_READ_BATCH_US * 1000L};
        nanosleep(&batch, NULL);
        if (board_read_available(b) < 0)
            return -1;
    }
    /* A partial frame that waits long for its bytes is damage no frame
     * showed (its length field spoilt): the link is then polled too. */
    long long quiet = board_now_ms() - b->arq_heard_ms;
    if (!b->arq_armed && b->dec.have && board_now_ms() - b->arq_byte_ms >= board_arq_stall_ms(b))
        b->arq_armed = 1;
    if (b->arq_armed && quiet >= LINK_ARQ_POLL_MS && board_arq_poll(b) < 0)
        return -1;
    return 0;
}

static void board_print_missing(const struct board *b)
{
    fprintf(stderr, "links1: %d of %d unit computers did not report in:",
            b->opts.ncores - b->reported_count, b->opts.ncores);
    const char *sep = "";
    for (int k = 0; k < b->opts.ncores; k++) {
        if (b->reported[k])
            continue;
        /* A run of silent cores, never spanning two roles. */
        int e = k;
        while (k >= ROLE_NC && e + 1 < b->opts.ncores && !b->reported[e + 1])
            e++;
        if (e > k)
            fprintf(stderr, "%s cores %d-%d (NCs)", sep, k, e);
        else
            fprintf(stderr, "%s core %d (%s)", sep, k, board_role_name(k));
        sep = ",";
        k = e;
    }
    fprintf(stderr, "\n");
}

int board_wait_reported(struct board *b, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    while (b->reported_count < b->opts.ncores && b->hello_errors == 0) {
        long long left = end - board_now_ms();
        if (left <= 0) {
            board_print_missing(b);
            fprintf(stderr, "links1: (waited %.1f s; --timeout S waits longer)\n",
                    timeout_ms / 1000.0);
            return -1;
        }
        if (board_pump(b, (int)left) < 0) {
            board_print_missing(b);
            return -1;
        }
    }
    if (b->hello_errors) {
        fprintf(stderr, "links1: %d bad report-in frame(s)\n", b->hello_errors);
        return -1;
    }
    if (!b->opts.quiet)
        printf("links1: board up: %d unit computers in %.1f s\n", b->opts.ncores,
               (double)(board_now_ms() - b->started_ms) / 1000.0);
    return 0;
}

/* ------------------------------------------------------- outgoing frames */

static int board_write_frame(struct board *b, const uint8_t *p, size_t n, int timeout_ms);

/* Writes whole frames: a NAK or a resend the board asks for while the write
 * waits (and reads) goes out after them, so no frame is cut by another. */
static int board_write_all(struct board *b, const uint8_t *p, size_t n, int timeout_ms)
{
    b->arq_writing++;
    int r = board_write_frame(b, p, n, timeout_ms);
    b->arq_writing--;
    while (r == 0 && !b->arq_writing && (b->arq_resend_due || b->arq_nak_due)) {
        if (b->arq_resend_due) {
            b->arq_resend_due = 0;
            r = board_arq_resend(b, b->arq_resend_from);
        } else {
            b->arq_nak_due = 0;
            r = board_send_nak(b, b->arq_nak_flags);
        }
    }
    return r;
}

static int board_write_frame(struct board *b, const uint8_t *p, size_t n, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    while (n) {
        if (b->fd < 0)
            return -1;
        ssize_t w = write(b->fd, p, n);
        if (w > 0) {
            p += w;
            n -= (size_t)w;
            continue;
        }
        if (w < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
            return board_lost(b, strerror(errno));
        /* The board is not taking bytes: keep reading what it sends meanwhile,
         * so neither side can block the other. */
        long long left = end - board_now_ms();
        if (left <= 0) {
            fprintf(stderr, "links1: the board took no input for %d ms\n", timeout_ms);
            return -1;
        }
        struct pollfd pf = {.fd = b->fd, .events = POLLIN | POLLOUT};
        if (poll(&pf, 1, (int)left) > 0 && (pf.revents & (POLLIN | POLLHUP)) &&
            board_read_available(b) < 0)
            return -1;
    }
    return 0;
}

int board_send(struct board *b, uint8_t type, uint8_t flags, const void *payload,
               size_t len)
{
    uint8_t frame[LINK_MAX_FRAME];
    uint16_t seq = b->tx_seq;
    b->arq_tx.next_seq = seq; /* kept for resending (proto/link_arq.h) */
    size_t n = link_arq_store_frame(&b->arq_tx, frame, sizeof frame, type, flags, payload, len);
    if (n == 0) {
        fprintf(stderr, "links1: frame payload of %zu bytes is over the %d-byte limit\n",
                len, LINK_MAX_PAYLOAD);
        return -1;
    }
    if (board_write_all(b, frame, n, BOARD_FRAME_TIMEOUT_MS) < 0)
        return -1;
    b->tx_seq++;
    return seq;
}

int board_send_raw(struct board *b, const void *bytes, size_t n)
{
    if (b->fd < 0) {
        fprintf(stderr, "links1: the board's link is closed\n");
        return -1;
    }
    return board_write_all(b, bytes, n, BOARD_FRAME_TIMEOUT_MS);
}

int board_send_cmd(struct board *b, uint16_t cmd, const void *args, size_t len)
{
    uint8_t p[LINK_MAX_PAYLOAD];
    if (len > sizeof p - LINK_CMD_FIXED_SIZE) {
        fprintf(stderr, "links1: command %u: %zu bytes of arguments is too many\n", cmd, len);
        return -1;
    }
    wire_put_u16(p, cmd);
    if (len)
        memcpy(p + LINK_CMD_FIXED_SIZE, args, len);
    return board_send(b, LINK_CMD, 0, p, LINK_CMD_FIXED_SIZE + len) < 0 ? -1 : 0;
}

void board_unget_frame(struct board *b, const struct board_frame *f)
{
    if (b->queued == BOARD_FRAME_QUEUE)
        b->queued--; /* cannot happen: the frame was just taken from it */
    memmove(&b->queue[1], &b->queue[0], (size_t)b->queued * sizeof b->queue[0]);
    b->queue[0] = *f;
    b->queued++;
}

int board_wait_frame(struct board *b, uint8_t type, int timeout_ms,
                     struct board_frame *out, const char *what)
{
    return board_wait_frame_of(b, 1u << type, timeout_ms, out, what);
}

int board_wait_frame_of(struct board *b, uint32_t mask, int timeout_ms,
                        struct board_frame *out, const char *what)
{
    long long end = board_now_ms() + timeout_ms;
    for (;;) {
        for (int i = 0; i < b->queued; i++) {
            if (b->queue[i].type >= 32 || !(mask & (1u << b->queue[i].type)))
                continue;
            *out = b->queue[i];
            memmove(&b->queue[i], &b->queue[i + 1],
                    (size_t)(b->queued - i - 1) * sizeof b->queue[0]);
            b->queued--;
            return 0;
        }
        long long left = end - board_now_ms();
        if (left <= 0) {
            fprintf(stderr, "links1: no %s from the board within %d ms\n", what, timeout_ms);
            return -1;
        }
        if (board_pump(b, (int)left) < 0) {
            fprintf(stderr, "links1: gave up waiting for %s\n", what);
            return -1;
        }
    }
}

int board_wait_result(struct board *b, uint16_t cmd, int timeout_ms,
                      struct board_frame *out, int *status,
                      const uint8_t **fields, size_t *nfields)
{
    char what[64];
    snprintf(what, sizeof what, "result of command %u", cmd);
    if (board_wait_frame(b, LINK_RESULT, timeout_ms, out, what) < 0)
        return -1;
    if (out->length < LINK_RESULT_FIXED_SIZE) {
        fprintf(stderr, "links1: RESULT frame of %u bytes, want at least %d\n", out->length,
                LINK_RESULT_FIXED_SIZE);
        return -1;
    }
    uint16_t got = wire_get_u16(out->payload);
    if (got != cmd) {
        fprintf(stderr, "links1: waited for the result of command %u, got one for %u\n",
                cmd, got);
        return -1;
    }
    *status = (int16_t)wire_get_u16(out->payload + 2);
    *fields = out->payload + LINK_RESULT_FIXED_SIZE;
    *nfields = out->length - LINK_RESULT_FIXED_SIZE;
    return 0;
}

uint32_t board_link_errors(const struct board *b)
{
    const struct link_stats *s = &b->dec.stats;
    return s->crc_errors + s->bad_length + s->junk_bytes + s->seq_gaps +
           b->host_frames_dropped;
}

uint32_t board_report_link_errors(const struct board *b)
{
    const struct link_stats *s = &b->dec.stats;
    uint32_t n = board_link_errors(b);
    if (n)
        fprintf(stderr, "links1: link errors: from the board %u bad CRC, %u bad length, "
                "%u junk bytes, %u seq gaps (in %u good frames); %u frames from the host "
                "dropped by the board; %u of our frames sent again, %u of the board's taken "
                "twice and dropped\n", s->crc_errors, s->bad_length, s->junk_bytes,
                s->seq_gaps, s->frames, b->host_frames_dropped, b->arq_resends, b->arq_dups);
    return n;
}

/* ------------------------------------------------------------------ stop */

static int board_stop_qemu(struct board *b);

int board_stop(struct board *b)
{
    int r = 0;
    if (b->named) {
        /* A named board runs on: only this session ends. */
        if (b->fd >= 0)
            close(b->fd);
        b->fd = -1;
        b->qemu_pid = 0;
    } else {
        r = board_stop_qemu(b);
    }
    board_ram_release(b);
    if (b->lock_fd >= 0)
        close(b->lock_fd);
    b->lock_fd = -1;
    return r;
}

static int board_stop_qemu(struct board *b)
{
    if (!b->qemu_pid) {
        if (b->fd >= 0)
            close(b->fd);
        b->fd = -1;
        return 0;
    }
    b->stopping = 1;
    if (b->fd >= 0 && board_send_cmd(b, CMD_SHUTDOWN, NULL, 0) == 0) {
        /* Drain what the board still says (its result, last logs) until the
         * socket closes because QEMU exited. */
        long long end = board_now_ms() + BOARD_SHUTDOWN_WAIT_MS;
        while (b->fd >= 0 && board_now_ms() < end) {
            if (board_pump(b, (int)(end - board_now_ms())) < 0)
                break;
            b->queued = 0; /* nothing waits for these any more */
        }
    }
    if (b->fd >= 0) {
        close(b->fd);
        b->fd = -1;
    }
    if (board_qemu_reap(b, b->qemu_pid ? 500 : 0)) {
        if (WIFEXITED(b->qemu_status) && WEXITSTATUS(b->qemu_status) == 0)
            return 0;
        char desc[96];
        board_qemu_exit_text(b, desc, sizeof desc);
        fprintf(stderr, "links1: at shutdown %s\n", desc);
        return -1;
    }
    fprintf(stderr, "links1: the board did not power off within %d ms of the shutdown "
            "command; stopping QEMU (pid %d) with SIGTERM\n", BOARD_SHUTDOWN_WAIT_MS,
            (int)b->qemu_pid);
    kill(b->qemu_pid, SIGTERM);
    if (board_qemu_reap(b, BOARD_TERM_WAIT_MS))
        return 1;
    fprintf(stderr, "links1: QEMU ignored SIGTERM for %d ms; killing it\n",
            BOARD_TERM_WAIT_MS);
    kill(b->qemu_pid, SIGKILL);
    board_qemu_reap(b, BOARD_TERM_WAIT_MS);
    return 1;
}
