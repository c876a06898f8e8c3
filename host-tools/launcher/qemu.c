/* qemu.c: the board's QEMU process: started with the board's UART on a
 * socketpair and its RAM a memfd (or, for a named board, both in its state
 * directory), a semihosting program run, the process stopped (see
 * launcher.h). */
#define _GNU_SOURCE /* memfd_create */
#include "host-tools/launcher/launcher.h"
#include "host-tools/launcher/board_state.h"
#include "host-tools/launcher/link_relay.h"
#include "host-tools/opts/exit_clean.h"
#include "host-tools/opts/self_path.h"
#include "proto/wire.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

static int board_qemu_reap(struct board *b, int timeout_ms);

/* Where an NC board writes what the plugin counted: PATH for board 0,
 * PATH.bK for board K. */
static void board_an521_file(const char *path, int board, char *out, size_t cap)
{
    if (board == 0)
        snprintf(out, cap, "%s", path);
    else
        snprintf(out, cap, "%s.b%d", path, board);
}
static void board_qemu_exit_text(const struct board *b, char *out, size_t cap);
static int board_stop_qemu(struct board *b);

void board_qemu_gone(struct board *b, char *desc, size_t cap)
{
    if (b->named && !b->qemu_pid) {
        const char *slash = strrchr(b->state_dir, '/');
        snprintf(desc, cap, "board %s: its QEMU closed the link or ended",
                 slash ? slash + 1 : b->state_dir);
    } else {
        /* On the an521 boards the link is board 0's: say which board. */
        const char *which = b->opts.machine == MACHINE_AN521 ? "an521 board 0 (the DM and "
                                                              "the RC): " : "";
        char what[96];
        if (board_qemu_reap(b, BOARD_TERM_WAIT_MS))
            board_qemu_exit_text(b, what, sizeof what);
        else
            snprintf(what, sizeof what, "QEMU (pid %d) is still running", (int)b->qemu_pid);
        snprintf(desc, cap, "%s%s", which, what);
    }
}

const char *qemu_opt_escape(const char *value, char *out, size_t cap)
{
    size_t n = 0;
    for (const char *c = value; cap > 0 && *c; c++) {
        size_t need = *c == ',' ? 2 : 1;
        if (n + need >= cap)
            break;
        out[n++] = *c;
        if (*c == ',')
            out[n++] = ',';
    }
    if (cap > 0)
        out[n] = 0;
    return out;
}

/* The emulator: $QEMU, else qemu-system-arm from $PATH. */
static const char *board_qemu_binary(void)
{
    const char *qemu = getenv("QEMU");
    return qemu && *qemu ? qemu : "qemu-system-arm";
}

/* ------------------------------------------------------------ QEMU process */

/* A QEMU just forked (pid) registered with exit_clean as the process group
 * it leads (exit_clean_in_child_group; a named board's setsid), and
 * signalled so from then on (exit_clean_kill): a $QEMU wrapper that starts
 * the emulator without exec ends with it.  b NULL or not named: the group
 * is made from this side too, so a signal sent before the child gets to
 * it reaches the group (a named board's child makes a session instead,
 * which it cannot once it leads a group). */
static void board_qemu_started(const struct board *b, pid_t pid)
{
    if (!b || !b->named)
        setpgid(pid, pid);
    exit_clean_add_group(pid);
}

static void board_qemu_exec_failed(const char *qemu)
{
    fprintf(stderr, "links1: cannot run %s: %s (install qemu-system-arm, or set $QEMU)\n",
            qemu, strerror(errno));
    _exit(127);
}

/* The counting plugin's shared object, its commas doubled, into out:
 * $LINKS1_INSN_PLUGIN, else insn-count.so next to this program. */
static void board_plugin_so(char *out, size_t cap)
{
    const char *so = getenv("LINKS1_INSN_PLUGIN");
    char self[PATH_MAX], path[PATH_MAX + 16];
    if (!so || !*so) {
        self_dir(self, sizeof self);
        snprintf(path, sizeof path, "%s/insn-count.so", self);
        so = path;
    }
    qemu_opt_escape(so, out, cap);
}

/* In the child.  A board of this tool's own (qemu_fd >= 0, the UART on a
 * socket pair, the RAM our memfd) must not outlive the tool, whatever ends
 * the tool; a named board (qemu_fd < 0: the UART a listening socket, the RAM
 * a file, both in its state directory) runs on in a session of its own. */
/* The counting plugin's -plugin argument into out, when the board counts:
 * 1, else 0.  An an521 NC board (board > 0) writes its counts and marks
 * beside the requested files (board_an521_file), which board_stop merges
 * with board 0's under the machine's core numbers. */
static int board_plugin_arg(const struct board *b, int board, char *out, size_t cap)
{
    const struct board_opts *o = &b->opts;
    if (!o->insn_count_out && !o->insn_series_out && !o->insn_trace_out &&
        !o->insn_profile_out)
        return 0;
    char file[PATH_MAX + 16], esc[2 * PATH_MAX + 40];
    board_plugin_so(out, cap);
    size_t n = strlen(out);
    if (o->insn_count_out) {
        board_an521_file(o->insn_count_out, board, file, sizeof file);
        n += (size_t)snprintf(out + n, n < cap ? cap - n : 0, ",out=%s",
                              qemu_opt_escape(file, esc, sizeof esc));
    }
    if (o->insn_series_out && board == 0)
        n += (size_t)snprintf(out + n, n < cap ? cap - n : 0, ",series=%s,every=%d",
                              qemu_opt_escape(o->insn_series_out, esc, sizeof esc),
                              o->insn_series_ms);
    if (o->insn_trace_out) {
        board_an521_file(o->insn_trace_out, board, file, sizeof file);
        n += (size_t)snprintf(out + n, n < cap ? cap - n : 0, ",trace=%s",
                              qemu_opt_escape(file, esc, sizeof esc));
    }
    if (o->insn_profile_out) {
        board_an521_file(o->insn_profile_out, board, file, sizeof file);
        int from = board == 0 ? UNITS_FIRST_NC : 0, to = -2; /* -2: every vCPU from */
        if (o->insn_profile_core >= 0) { /* one core: on an an521 board, core k is
                                            vCPU k % 2 of board k / 2 */
            int per = o->machine == MACHINE_AN521 ? 2 : o->ncores;
            int here = o->insn_profile_core / per == board;
            from = here ? o->insn_profile_core % per : 1; /* 1 to 0: none here */
            to = here ? from : 0;
        }
        n += (size_t)snprintf(out + n, n < cap ? cap - n : 0, ",profile=%s,profile_from=%d",
                              qemu_opt_escape(file, esc, sizeof esc), from);
        if (to != -2)
            n += (size_t)snprintf(out + n, n < cap ? cap - n : 0, ",profile_to=%d", to);
    }
    return 1;
}

/* The emulator's arguments for the machine: its model and memory, QEMU's
 * devices; board (an521) is which board this process is. */
static int board_qemu_machine_args(const struct board *b, int board, const char **argv, int n,
                                   char *smp, char *mem, char *loader, size_t loader_cap)
{
    if (b->opts.machine == MACHINE_AN521) {
        argv[n++] = "-M";
        argv[n++] = "mps2-an521,memory-backend=ram";
        /* QEMU's SSE-200 gives core 0 no FPU and no DSP extension; the
         * firmwares built for the M33's FPU (float, double, whose double
         * is software but whose float ABI is the FPU's, and those that
         * escalate) need both on both cores (a configuration the SSE-200
         * offers).  The soft and fixed firmwares run on the board as it
         * comes. */
        if (strcmp(b->opts.arith, "float") == 0 || strcmp(b->opts.arith, "double") == 0 ||
            b->opts.escalate) {
            argv[n++] = "-global";
            argv[n++] = "sse-200.CPU0_FPU=on";
            argv[n++] = "-global";
            argv[n++] = "sse-200.CPU0_DSP=on";
        }
        /* The board's own Ethernet chip, on a user network shut off from
         * the host and the world: QEMU otherwise warns it has no peer. */
        argv[n++] = "-nic";
        argv[n++] = "user,restrict=on,model=lan9118";
        snprintf(loader, loader_cap, "loader,addr=0x%x,data=%d,data-len=4",
                 (unsigned)AN521_BOARD_ID_ADDR, board);
        argv[n++] = "-device";
        argv[n++] = loader;
        return n;
    }
    argv[n++] = "-M";
    argv[n++] = "virt,gic-version=3,memory-backend=ram";
    argv[n++] = "-cpu";
    argv[n++] = "cortex-a15";
    argv[n++] = "-smp";
    argv[n++] = smp;
    argv[n++] = "-m";
    argv[n++] = mem;
    return n;
}

/* In the child: the board's RAM (the an521 boards' shared file) kept open
 * across exec, and its -object argument into out: QEMU maps the same file
 * through /proc, no path to look up again. */
static void board_ram_arg(const struct board *b, char *out, size_t cap)
{
    fcntl(b->ram_fd, F_SETFD, 0);
    snprintf(out, cap, "memory-backend-file,id=ram,size=%dM,mem-path=/proc/self/fd/%d,share=on",
             b->opts.ram_mb, b->ram_fd);
}

/* An an521 NC board's process (board > 0): no link of its own (its units'
 * messages go through the shared file to board 0), the shared file as its
 * PSRAM.  In the child; never returns. */
static void board_qemu_exec_nc_board(struct board *b, int board)
{
    signal(SIGPIPE, SIG_DFL);
    char ram[PATH_MAX + 96], loader[96], plugin[8 * PATH_MAX], name[2 * PATH_MAX + 64];
    if (b->named) {
        /* One of a named set: runs on in a session of its own, its output
         * in the set's log, known by its -name (board_state_nc_alive). */
        setsid();
        board_named_redirect(b);
        board_state_nc_name(b->state_dir, board, name, sizeof name);
    } else {
        exit_clean_in_child_group(); /* it ends with us, its group with it */
        int null = open("/dev/null", O_RDWR);
        if (null >= 0) {
            dup2(null, 0);
            dup2(null, 1); /* it has no link: nothing of it on our terminal */
        }
    }
    board_ram_arg(b, ram, sizeof ram);
    const char *qemu = board_qemu_binary();
    const char *argv[32];
    int n = 0;
    argv[n++] = qemu;
    n = board_qemu_machine_args(b, board, argv, n, NULL, NULL, loader, sizeof loader);
    argv[n++] = "-object";
    argv[n++] = ram;
    argv[n++] = "-display";
    argv[n++] = "none";
    argv[n++] = "-nodefaults";
    argv[n++] = "-no-reboot";
    argv[n++] = "-kernel";
    argv[n++] = b->firmware;
    if (b->named) {
        argv[n++] = "-name";
        argv[n++] = name;
    }
    if (board_plugin_arg(b, board, plugin, sizeof plugin)) {
        argv[n++] = "-plugin";
        argv[n++] = plugin;
    }
    argv[n] = NULL;
    execvp(qemu, (char *const *)argv);
    board_qemu_exec_failed(qemu);
}

static void board_qemu_exec(struct board *b, int qemu_fd)
{
    signal(SIGPIPE, SIG_DFL); /* the session's SIG_IGN is ours, not QEMU's */
    char smp[32], mem[32], chardev[2 * PATH_MAX + 160], plugin[8 * PATH_MAX], ram[PATH_MAX + 96];
    snprintf(smp, sizeof smp, "%d", b->opts.ncores);
    snprintf(mem, sizeof mem, "%dM", b->opts.ram_mb);
    if (qemu_fd >= 0) {
        exit_clean_in_child_group(); /* it ends with us, its group with it */
        fcntl(qemu_fd, F_SETFD, 0); /* keep QEMU's end open across exec */
        snprintf(chardev, sizeof chardev, "socket,id=link,fd=%d", qemu_fd);
    } else {
        setsid();
        board_named_redirect(b);
        board_named_chardev(b, chardev, sizeof chardev);
    }
    /* The RAM: our memfd, or the file made in a named board's state
     * directory, open here either way. */
    board_ram_arg(b, ram, sizeof ram);
    const char *qemu = board_qemu_binary();
    const char *argv[40];
    int n = 0;
    argv[n++] = qemu;
    char loader[96];
    n = board_qemu_machine_args(b, 0, argv, n, smp, mem, loader, sizeof loader);
    argv[n++] = "-object";
    argv[n++] = ram;
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
    char monitor_arg[2 * PATH_MAX + 40], esc[2 * PATH_MAX];
    if (monitor && *monitor) {
        snprintf(monitor_arg, sizeof monitor_arg, "unix:%s,server=on,wait=off",
                 qemu_opt_escape(monitor, esc, sizeof esc));
        argv[n++] = "-monitor";
        argv[n++] = monitor_arg;
    }
    char gdb[2 * sizeof b->gdb_socket + 32];
    if (b->opts.gdb) {
        /* Halted at the first instruction until the debugger continues;
         * the stub on a unix socket in the user's own state directory. */
        snprintf(gdb, sizeof gdb, "unix:%s,server=on,wait=off",
                 qemu_opt_escape(b->gdb_socket, esc, sizeof esc));
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
    if (board_plugin_arg(b, 0, plugin, sizeof plugin)) {
        argv[n++] = "-plugin";
        argv[n++] = plugin;
    }
    argv[n] = NULL;
    execvp(qemu, (char *const *)argv);
    board_qemu_exec_failed(qemu);
}

int board_run_semihost(const char *elf, int ram_mb)
{
    return board_run_semihost_smp(elf, ram_mb, 1, NULL);
}

int board_run_semihost_smp(const char *elf, int ram_mb, int cores, const char *trace_out)
{
    if (access(elf, R_OK) < 0) {
        fprintf(stderr, "links1: program %s: %s\n", elf, strerror(errno));
        return -1;
    }
    if (cores < 1 || cores > 8) {
        fprintf(stderr, "links1: semihosting program on %d cores: 1..8\n", cores);
        return -1;
    }
    char mem[32], smp[16], plugin[8 * PATH_MAX];
    snprintf(mem, sizeof mem, "%dM", ram_mb);
    snprintf(smp, sizeof smp, "%d", cores);
    const char *qemu = board_qemu_binary();
    /* The plain virt board; the program's semihosted console is QEMU's
     * stdio chardev, so its output is our stdout. */
    const char *argv[24] = {qemu, "-M", "virt", "-cpu", "cortex-a15", "-smp", smp, "-m", mem,
                            "-display", "none", "-nodefaults", "-no-reboot",
                            "-chardev", "stdio,id=semihost,signal=off",
                            "-semihosting-config", "enable=on,target=native,chardev=semihost",
                            "-kernel", elf};
    int n = 19;
    if (trace_out) {
        char esc[2 * PATH_MAX];
        board_plugin_so(plugin, sizeof plugin);
        size_t used = strlen(plugin);
        snprintf(plugin + used, sizeof plugin - used, ",trace=%s",
                 qemu_opt_escape(trace_out, esc, sizeof esc));
        argv[n++] = "-plugin";
        argv[n++] = plugin;
    }
    argv[n] = NULL;
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "links1: fork: %s\n", strerror(errno));
        return -1;
    }
    if (pid == 0) {
        exit_clean_in_child_group();
        int null = open("/dev/null", O_RDONLY);
        if (null >= 0)
            dup2(null, 0); /* the program reads nothing; keep a terminal cooked */
        execvp(qemu, (char *const *)argv);
        board_qemu_exec_failed(qemu);
    }
    board_qemu_started(NULL, pid);
    int st;
    while (waitpid(pid, &st, 0) < 0) {
        if (errno != EINTR) {
            fprintf(stderr, "links1: waitpid: %s\n", strerror(errno));
            exit_clean_drop_child(pid);
            return -1;
        }
    }
    exit_clean_drop_child(pid);
    if (WIFEXITED(st))
        return WEXITSTATUS(st);
    fprintf(stderr, "links1: QEMU was killed by signal %d\n", WTERMSIG(st));
    return -1;
}

/* --gdb: the stub's socket, b->gdb_socket: gdb.sock in a named board's
 * directory, else gdb-PID.sock in the user's state directory (both only
 * the user's: board_state.h).  Printed with how to attach.  0, or -1
 * after printing why. */
static int board_gdb_socket(struct board *b)
{
    char base[BOARD_STATE_BASE_MAX], file[32], path[BOARD_STATE_BASE_MAX + 40];
    int base_fd = -1;
    if (b->named) {
        snprintf(path, sizeof path, "%.2048s/%s", b->state_dir, BOARD_STATE_GDB);
    } else {
        if ((base_fd = board_state_base(1, base, sizeof base)) < 0)
            return -1;
        snprintf(file, sizeof file, "gdb-%d.sock", (int)getpid());
        unlinkat(base_fd, file, 0); /* one a process of this pid left */
        close(base_fd);
        snprintf(path, sizeof path, "%s/%s", base, file);
    }
    if (strlen(path) >= sizeof b->gdb_socket) {
        fprintf(stderr, "links1: the gdb socket path %s is too long for a unix socket "
                "(set $LINKS1_BOARDS to a shorter directory of your own)\n", path);
        return -1;
    }
    memcpy(b->gdb_socket, path, strlen(path) + 1);
    if (!b->named)
        exit_clean_add(b->gdb_socket, EXIT_CLEAN_FILE); /* QEMU makes it */
    printf("links1: QEMU's gdb stub on %s, every core halted until gdb continues: "
           "gdb-multiarch %s -ex 'target remote %s'\n", b->gdb_socket, b->firmware,
           b->gdb_socket);
    fflush(stdout);
    return 0;
}

/* The an521 boards' shared file's header (proto/board_map_an521.h),
 * before any board starts: they find the boards joined there. */
static void board_an521_header(struct board *b)
{
    if (b->opts.machine != MACHINE_AN521)
        return;
    wire_put_u32(b->ram + AN521_HDR_MAGIC_OFF, AN521_HDR_MAGIC);
    wire_put_u32(b->ram + AN521_HDR_BOARDS_OFF,
                 (uint32_t)(b->opts.ncores / AN521_CORES_PER_BOARD));
    wire_put_u32(b->ram + AN521_HDR_READY_OFF, 0);
}

/* The board's RAM as a memfd, mapped here (proto/board_map.h). */
static int board_ram_create(struct board *b)
{
    if (b->opts.machine == MACHINE_AN521)
        b->opts.ram_mb = AN521_SHARED_MB;
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
    board_an521_header(b);
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

/* The an521 boards' shape: two units per board, board 0 the DM and RC;
 * what the firmware and QEMU's model of them can do. */
static int board_an521_check(const struct board_opts *o)
{
    int ncs = o->ncores - UNITS_FIRST_NC;
    if (o->ncores % AN521_CORES_PER_BOARD != 0 ||
        o->ncores > AN521_CORES_PER_BOARD * AN521_MAX_BOARDS) {
        fprintf(stderr, "links1: %d NCs on an521 boards: each NC board carries %d NCs, so "
                "give an even number from 2 to %d\n", ncs, AN521_CORES_PER_BOARD,
                AN521_CORES_PER_BOARD * (AN521_MAX_BOARDS - 1));
        return -1;
    }
    if (o->ram_mb != BOARD_DEFAULT_RAM_MB) {
        fprintf(stderr, "links1: --ram: an an521 board's memory is fixed (its SRAMs and the "
                "%d MiB shared file)\n", AN521_SHARED_MB);
        return -1;
    }
    if (o->view || o->gdb) {
        fprintf(stderr, "links1: --%s is for the virt board; the an521 boards have %s\n",
                o->view ? "view" : "gdb",
                o->view ? "no display" : "no gdb stub wired through links1 yet");
        return -1;
    }
    return 0;
}

/* A board this tool boots: its QEMU told of when the link ends, its frames
 * numbered from 0, its firmware found and its shape checked.  0, or -1
 * after printing why. */
static int board_qemu_check(struct board *b, const struct board_opts *o)
{
    b->process_gone = board_qemu_gone;
    board_session_peer_from_zero(b); /* the board we boot numbers from 0 */
    if (board_find_firmware(o, b->firmware, sizeof b->firmware) < 0)
        return -1;
    if (o->ncores < UNITS_MIN_CORES || o->ncores > UNITS_MAX_CORES) {
        fprintf(stderr, "links1: %d cores: the board needs %d..%d\n", o->ncores,
                UNITS_MIN_CORES, UNITS_MAX_CORES);
        return -1;
    }
    if (o->machine == MACHINE_AN521)
        return board_an521_check(o);
    return 0;
}

/* A session for a board this tool boots (board_qemu_check). */
static int board_qemu_session(struct board *b, const struct board_opts *o)
{
    if (board_session_init(b, o) < 0)
        return -1;
    if (board_qemu_check(b, o) < 0) {
        board_session_close(b);
        return -1;
    }
    return 0;
}

/* The an521 NC boards, each its own QEMU on the shared file (board 0 is
 * started already). */
static int board_start_nc_boards(struct board *b)
{
    int boards = b->opts.ncores / AN521_CORES_PER_BOARD;
    for (int k = 1; k < boards; k++) {
        fflush(NULL);
        pid_t pid = fork();
        if (pid < 0) {
            fprintf(stderr, "links1: fork (an521 board %d): %s\n", k, strerror(errno));
            if (!b->named) /* a named set is abandoned whole by its caller */
                board_stop(b);
            return -1;
        }
        if (pid == 0)
            board_qemu_exec_nc_board(b, k);
        b->nc_board_pid[k] = pid;
        board_qemu_started(b, pid); /* a named set's until it is up */
    }
    return 0;
}

void board_say_booting(const struct board *b)
{
    const struct board_opts *o = &b->opts;
    if (o->quiet)
        return;
    if (o->machine == MACHINE_AN521)
        printf("links1: booting %s on %d an521 boards (board 0: DM and RC, QEMU pid %d; "
               "%d NCs on boards 1..%d)\n", b->firmware, o->ncores / AN521_CORES_PER_BOARD,
               (int)b->qemu_pid, o->ncores - UNITS_FIRST_NC,
               o->ncores / AN521_CORES_PER_BOARD - 1);
    else
        printf("links1: booting %s on %d cores (DM, RC, %d NCs), QEMU pid %d\n", b->firmware,
               o->ncores, o->ncores - UNITS_FIRST_NC, (int)b->qemu_pid);
}

/* An NC board's process gone or not: 1 once reaped. */
static int board_nc_board_reap(struct board *b, int k, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    while (b->nc_board_pid[k]) {
        pid_t r = waitpid(b->nc_board_pid[k], &b->nc_board_status[k], WNOHANG);
        if (r == b->nc_board_pid[k] || (r < 0 && errno == ECHILD)) {
            exit_clean_drop_child(b->nc_board_pid[k]);
            b->nc_board_pid[k] = 0;
            break;
        }
        if (board_now_ms() >= end)
            return 0;
        usleep(10000);
    }
    return 1;
}

/* Appends what NC board k's plugin wrote at path.bK to path, its cores
 * renumbered as the machine's (2k, 2k + 1), and removes it.  The lines are
 * the plugin's: "vcpu V COUNT" (counts 1), "V KIND COUNT" (trace marks,
 * counts 0) or "ADDR COUNT" (the profile, counts 2);
 * one that does not parse, or names a vCPU the board does not have, is
 * dropped and said. */
static void board_merge_counts(const char *path, int k, int counts)
{
    char part[PATH_MAX + 16], line[128];
    board_an521_file(path, k, part, sizeof part);
    /* Both in the run's private directory; a link there is not followed. */
    int in_fd = open(part, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    FILE *in = in_fd >= 0 ? fdopen(in_fd, "r") : NULL;
    if (!in) {
        if (in_fd >= 0)
            close(in_fd);
        return; /* the board ended before its plugin wrote (killed) */
    }
    int out_fd = open(path, O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
    FILE *out = out_fd >= 0 ? fdopen(out_fd, "a") : NULL;
    if (!out && out_fd >= 0)
        close(out_fd);
    unsigned bad = 0;
    while (out && fgets(line, sizeof line, in)) {
        unsigned v, kind;
        unsigned long long c;
        char end;
        unsigned long long addr;
        if (counts == 2 && strcmp(line, "oom\n") == 0)
            fputs(line, out); /* the reader refuses the profile */
        else if (counts == 2 && sscanf(line, "%llx %llu%c", &addr, &c, &end) == 3 &&
                 end == '\n')
            fprintf(out, "%08llx %llu\n", addr, c); /* the same image on every board */
        else if (counts == 1 && sscanf(line, "vcpu %u %llu%c", &v, &c, &end) == 3 &&
                 end == '\n' && v < AN521_CORES_PER_BOARD)
            fprintf(out, "vcpu %d %llu\n", k * AN521_CORES_PER_BOARD + (int)v, c);
        else if (counts == 0 && sscanf(line, "%u %u %llu%c", &v, &kind, &c, &end) == 4 &&
                 end == '\n' && v < AN521_CORES_PER_BOARD)
            fprintf(out, "%d %u %llu\n", k * AN521_CORES_PER_BOARD + (int)v, kind, c);
        else
            bad++;
    }
    if (bad)
        fprintf(stderr, "links1: %u line(s) of an521 board %d's %s dropped: not the "
                "plugin's\n", bad, k, counts == 2 ? "profile" : counts ? "instruction counts"
                                                                   : "trace marks");
    if (out)
        fclose(out);
    fclose(in);
    unlink(part);
}

/* Ends the an521 NC boards' processes: they have no power control and
 * nothing to keep (their state is in the shared file, which goes with the
 * command), so they are killed outright; when the plugin counts, they are
 * asked to end (SIGTERM: QEMU then lets the plugin write) and what they
 * counted is merged with board 0's. */
static void board_stop_nc_boards(struct board *b)
{
    const struct board_opts *o = &b->opts;
    int counting = o->insn_count_out || o->insn_trace_out || o->insn_profile_out;
    int any = 0;
    for (int k = 1; k < AN521_MAX_BOARDS; k++) {
        if (b->nc_board_pid[k]) {
            exit_clean_kill(b->nc_board_pid[k], counting ? SIGTERM : SIGKILL);
            any = 1;
        }
    }
    for (int k = 1; k < AN521_MAX_BOARDS; k++) {
        if (b->nc_board_pid[k] && !board_nc_board_reap(b, k, BOARD_TERM_WAIT_MS)) {
            exit_clean_kill(b->nc_board_pid[k], SIGKILL);
            board_nc_board_reap(b, k, BOARD_TERM_WAIT_MS);
        }
    }
    for (int k = 1; any && k < o->ncores / AN521_CORES_PER_BOARD; k++) {
        if (o->insn_count_out)
            board_merge_counts(o->insn_count_out, k, 1);
        if (o->insn_trace_out)
            board_merge_counts(o->insn_trace_out, k, 0);
        if (o->insn_profile_out)
            board_merge_counts(o->insn_profile_out, k, 2);
    }
}

int board_start_unannounced(struct board *b, const struct board_opts *o)
{
    if (board_qemu_session(b, o) < 0)
        return -1;
    if (board_ram_create(b) < 0) {
        board_ram_release(b);
        return -1;
    }
    if (o->gdb && board_gdb_socket(b) < 0) {
        board_ram_release(b);
        return -1;
    }
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
    board_qemu_started(b, pid);
    int tool_fd = sv[0];
    if (o->link_noise_on && (tool_fd = board_noise_relay(o, sv[0])) < 0) {
        board_stop(b);
        return -1;
    }
    board_session_open(b, tool_fd);
    if (o->machine == MACHINE_AN521)
        return board_start_nc_boards(b);
    return 0;
}

int board_start(struct board *b, const struct board_opts *o)
{
    if (board_start_unannounced(b, o) != 0)
        return -1;
    board_say_booting(b);
    return 0;
}

void board_abandon(struct board *b)
{
    if (!b->named && b->qemu_pid) {
        exit_clean_kill(b->qemu_pid, SIGKILL);
        board_qemu_reap(b, BOARD_TERM_WAIT_MS);
    }
    board_stop(b);
}

static int board_start_named_run(struct board *b, const struct board_opts *o,
                                 const char *name, int timeout_ms)
{
    if (board_session_init(b, o) < 0)
        return -1;
    b->named = 1;
    if (o->link_noise_on) {
        fprintf(stderr, "links1: --link-noise works on a board the command starts and "
                "stops, not a named board\n");
        board_session_close(b);
        return -1;
    }
    if (board_qemu_check(b, o) < 0) {
        board_session_close(b);
        return -1;
    }
    if (board_named_prepare(b, name) < 0) {
        board_stop(b);
        return -1;
    }
    if (b->opts.machine == MACHINE_AN521)
        b->opts.ram_mb = AN521_SHARED_MB; /* the shared file: every board's PSRAM */
    if (board_named_map_ram(b, 1) < 0 || (o->gdb && board_gdb_socket(b) < 0)) {
        board_named_abandon(b);
        board_stop(b);
        return -1;
    }
    board_an521_header(b);
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
    board_qemu_started(b, pid); /* until the board is up: then it runs on */
    if (b->opts.machine == MACHINE_AN521 && board_start_nc_boards(b) < 0) {
        board_named_abandon(b);
        board_stop(b);
        return -1;
    }
    if (b->opts.machine == MACHINE_AN521)
        board_say_booting(b);
    int fd = board_named_started(b, timeout_ms); /* the record names every QEMU */
    if (fd < 0) {
        board_named_abandon(b);
        board_stop(b);
        return -1;
    }
    board_session_open(b, fd);
    if (!o->quiet && b->opts.machine != MACHINE_AN521)
        printf("links1: booting %s on %d cores (DM, RC, %d NCs) as board %s, QEMU pid %d\n",
               b->firmware, o->ncores, o->ncores - 2, name, (int)pid);
    if (board_wait_reported(b, timeout_ms) < 0) {
        board_named_abandon(b);
        board_stop(b);
        return -1;
    }
    return 0;
}

int board_start_named(struct board *b, const struct board_opts *o, const char *name,
                      int timeout_ms)
{
    int r = board_start_named_run(b, o, name, timeout_ms);
    /* Up, it runs on; not up, board_named_abandon ended it: a signal from
     * now on leaves it be. */
    exit_clean_drop_child(b->qemu_pid);
    for (int k = 1; k < AN521_MAX_BOARDS; k++)
        exit_clean_drop_child(b->nc_board_pid[k]);
    return r;
}

/* Waits up to timeout_ms for QEMU to exit; returns 1 once reaped. */
static int board_qemu_reap(struct board *b, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    while (b->qemu_pid) {
        pid_t r = waitpid(b->qemu_pid, &b->qemu_status, WNOHANG);
        if (r == b->qemu_pid || (r < 0 && errno == ECHILD)) {
            exit_clean_drop_child(b->qemu_pid);
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
        board_stop_nc_boards(b);
        if (b->gdb_socket[0] && !b->qemu_pid) {
            unlink(b->gdb_socket); /* a named board's goes with its directory */
            exit_clean_drop(b->gdb_socket);
        }
    }
    board_session_close(b);
    board_ram_release(b);
    if (b->lock_fd >= 0)
        close(b->lock_fd);
    if (b->state_fd >= 0)
        close(b->state_fd);
    b->lock_fd = b->state_fd = -1;
    return r;
}

/* ------------------------------------------------------------------ stop */

static int board_stop_qemu(struct board *b);

static int board_stop_qemu(struct board *b)
{
    if (!b->qemu_pid) {
        if (b->fd >= 0)
            close(b->fd);
        b->fd = -1;
        return 0;
    }
    b->stopping = 1;
    /* Drain what the board still says (its result, last logs) until the
     * socket closes because QEMU exited. */
    if (b->fd >= 0 && board_send_cmd(b, CMD_SHUTDOWN, NULL, 0) == 0)
        board_session_drain(b, BOARD_SHUTDOWN_WAIT_MS);
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
    exit_clean_kill(b->qemu_pid, SIGTERM);
    if (board_qemu_reap(b, BOARD_TERM_WAIT_MS))
        return 1;
    fprintf(stderr, "links1: QEMU ignored SIGTERM for %d ms; killing it\n",
            BOARD_TERM_WAIT_MS);
    exit_clean_kill(b->qemu_pid, SIGKILL);
    board_qemu_reap(b, BOARD_TERM_WAIT_MS);
    return 1;
}
