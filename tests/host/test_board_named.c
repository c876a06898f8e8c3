/* Host tests of named boards' state (host-tools/launcher/board_named.c)
 * against hostile state: a base directory another account owns, one open
 * to others, one that is a symbolic link; planted links in and for state
 * directories; records whose values are out of range; a RAM file of the
 * wrong size; a board whose name is a prefix of another's; a board still
 * starting; a board that dies in a session.  Each is refused with a
 * message naming the problem, nothing of the victim's is written or
 * deleted, and the board keeps working for its owner.
 *
 * The board is this same program: $QEMU points at /proc/self/exe and
 * main() plays a named board's QEMU when $FAKE_NAMED is set (it listens on
 * the UART socket the -chardev names, reports every core in, answers
 * commands, and powers off on CMD_SHUTDOWN).  No emulator needed. */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host-tools/launcher/launcher.h"
#include "host-tools/opts/tmp_dir.h"
#include "proto/wire.h"
#include "tests/check.h"
#include "tests/host/fake_qemu.h"
#include "tests/host/capture.h"

/* ------------------------------------------------------------ the fake */

/* Serves one session until its end of the socket closes; 1 on
 * CMD_SHUTDOWN. */
static int fake_serve(int ncores)
{
    struct link_decoder d;
    link_decoder_init(&d);
    uint8_t byte;
    while (read(fake_fd, &byte, 1) == 1) {
        struct link_frame f;
        if (!link_decoder_push(&d, byte, &f) || f.type != LINK_CMD)
            continue;
        uint16_t cmd = wire_get_u16(f.payload);
        uint8_t r[LINK_RESULT_FIXED_SIZE + LINK_STATUS_RESULT_SIZE];
        wire_put_u16(r, cmd);
        wire_put_u16(r + 2, LINK_OK);
        struct link_status_result s = {(uint16_t)ncores, (uint16_t)ncores, 0};
        link_status_result_put(r + LINK_RESULT_FIXED_SIZE, &s);
        (void)fake_send(LINK_RESULT, r, cmd == CMD_STATUS ? sizeof r : LINK_RESULT_FIXED_SIZE); /* gone: the next accept */
        if (cmd == CMD_SHUTDOWN)
            return 1;
    }
    return 0;
}

/* A named board's QEMU: -smp N and -chardev socket,id=link,path=P,... */
static int fake_named(int argc, char **argv)
{
    int ncores = 0;
    char path[sizeof ((struct sockaddr_un *)0)->sun_path] = "";
    for (int i = 1; i + 1 < argc; i++) {
        if (strcmp(argv[i], "-smp") == 0)
            ncores = atoi(argv[i + 1]);
        if (strcmp(argv[i], "-chardev") == 0)
            sscanf(argv[i + 1], "socket,id=link,path=%107[^,]", path);
    }
    if (ncores < 3 || !path[0])
        return 9;
    struct sockaddr_un a = {.sun_family = AF_UNIX};
    memcpy(a.sun_path, path, strlen(path) + 1);
    int ls = socket(AF_UNIX, SOCK_STREAM, 0);
    if (ls < 0 || bind(ls, (struct sockaddr *)&a, sizeof a) < 0 || listen(ls, 4) < 0)
        return 8;
    for (int first = 1;; first = 0) {
        fake_fd = accept(ls, NULL, NULL);
        if (fake_fd < 0)
            return 7;
        if (first)
            for (int k = 0; k < ncores; k++)
                (void)fake_hello(k, ncores);
        int done = fake_serve(ncores);
        close(fake_fd);
        if (done)
            return 0;
    }
}

/* ------------------------------------------------------------ helpers */

static char root[64];      /* this test's own directory */
static char base[128];     /* $LINKS1_BOARDS */
static int started[64];    /* every fake QEMU started, killed at the end */
static int nstarted;

static void opts(struct board_opts *o)
{
    board_opts_init(o);
    o->ncores = 3;
    o->ram_mb = BOARD_MIN_RAM_MB;
    o->quiet = 1;
    o->firmware = "/proc/self/exe"; /* any ELF will do for the fake */
}

/* Starts the named board; its QEMU's pid, or -1.  err: what was printed. */
static int start(const char *name, char *err, size_t cap)
{
    struct board_opts o;
    opts(&o);
    struct board b;
    struct capture c;
    capture_begin(&c, STDERR_FILENO);
    int rc = board_start_named(&b, &o, name, 5000);
    capture_end(&c, err, cap);
    int pid = rc == 0 ? (int)b.qemu_pid : -1;
    if (rc == 0)
        board_stop(&b); /* this session only: the board runs on */
    if (pid > 0 && nstarted < 64)
        started[nstarted++] = pid;
    return pid;
}

/* A session on the named board opened and closed: 0, or -1 with what was
 * printed in err. */
static int session(const char *name, char *err, size_t cap)
{
    struct board_opts o;
    opts(&o);
    struct board b;
    struct capture c;
    capture_begin(&c, STDERR_FILENO);
    int rc = board_connect(&b, &o, name);
    if (rc == 0)
        board_stop(&b);
    capture_end(&c, err, cap);
    return rc;
}

static int stop(const char *name, char *out, size_t cap)
{
    struct capture c, e;
    char o2[4096];
    capture_begin(&e, STDERR_FILENO);
    capture_begin(&c, STDOUT_FILENO);
    int rc = board_stop_named(name);
    capture_end(&c, o2, sizeof o2);
    capture_end(&e, out, cap);
    return rc;
}

static int list(char *out, size_t cap)
{
    struct capture c, e;
    char o2[8192];
    capture_begin(&e, STDERR_FILENO);
    capture_begin(&c, STDOUT_FILENO);
    int n = board_list_named();
    capture_end(&c, o2, sizeof o2);
    capture_end(&e, out, cap);
    size_t len = strlen(out);
    snprintf(out + len, cap - len, "%s", o2);
    return n;
}

static int alive(int pid)
{
    char path[64], cmd[64] = "";
    snprintf(path, sizeof path, "/proc/%d/cmdline", pid);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    size_t n = fread(cmd, 1, sizeof cmd - 1, f);
    fclose(f);
    return n > 0; /* a zombie has no command line */
}

static void path_of(char *out, size_t cap, const char *a, const char *b)
{
    snprintf(out, cap, "%s/%s", a, b);
}

static int entries(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    if (!d)
        return -1;
    for (struct dirent *e; (e = readdir(d));)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static void read_file(const char *path, char *out, size_t cap)
{
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(out, 1, cap - 1, f) : 0;
    out[n] = 0;
    if (f)
        fclose(f);
}

/* A fresh base for each test: root/base (or gone when make is 0). */
static void fresh_base(int make)
{
    tmp_dir_remove(base);
    unlink(base);
    if (make)
        mkdir(base, 0700);
    setenv("LINKS1_BOARDS", base, 1);
}

static void show(const char *what, const char *text)
{
    printf("    %s: %s\n", what, text);
}

/* ------------------------------------------------------------ the tests */

static void named_base_created_private(void)
{
    fresh_base(0);
    char err[4096];
    int pid = start("b1", err, sizeof err);
    CHECK(pid > 0);
    struct stat st;
    CHECK(lstat(base, &st) == 0 && S_ISDIR(st.st_mode) && (st.st_mode & 0777) == 0700);
    CHECK_EQ_INT(session("b1", err, sizeof err), 0);
    CHECK_EQ_INT(stop("b1", err, sizeof err), 0);
    CHECK(!alive(pid));
    CHECK_EQ_INT(entries(base), 0);
}

static void named_xdg_runtime_dir(void)
{
    char xdg[160], want[200], err[4096];
    path_of(xdg, sizeof xdg, root, "xdg");
    mkdir(xdg, 0700);
    unsetenv("LINKS1_BOARDS");
    setenv("XDG_RUNTIME_DIR", xdg, 1);
    int pid = start("x1", err, sizeof err);
    CHECK(pid > 0);
    snprintf(want, sizeof want, "%s/links1-boards/x1/board", xdg);
    CHECK(access(want, F_OK) == 0);
    struct stat st;
    snprintf(want, sizeof want, "%s/links1-boards", xdg);
    CHECK(lstat(want, &st) == 0 && (st.st_mode & 0777) == 0700);
    stop("x1", err, sizeof err);
    CHECK(!alive(pid));
    unsetenv("XDG_RUNTIME_DIR");
    setenv("LINKS1_BOARDS", base, 1);
}

static void named_base_of_another_refused(void)
{
    if (geteuid() != 0) {
        printf("    (not root: a base owned by another account cannot be made here)\n");
        return;
    }
    fresh_base(1);
    CHECK(chown(base, 65534, 65534) == 0);
    char err[4096];
    int pid = start("victim", err, sizeof err);
    CHECK(pid < 0);
    CHECK(strstr(err, base) && strstr(err, "owned by uid 65534"));
    CHECK_EQ_INT(entries(base), 0);
    if (pid > 0)
        kill(pid, SIGKILL);
    show("refusal", err);
}

static void named_base_open_to_others_refused(void)
{
    fresh_base(1);
    chmod(base, 0777);
    char err[4096];
    int pid = start("victim", err, sizeof err);
    CHECK(pid < 0);
    CHECK(strstr(err, base) && strstr(err, "mode 0777"));
    CHECK_EQ_INT(entries(base), 0);
    if (pid > 0)
        kill(pid, SIGKILL);
    show("refusal", err);
    chmod(base, 0750); /* group access is refused too */
    pid = start("victim", err, sizeof err);
    CHECK(pid < 0 && strstr(err, "mode 0750"));
    if (pid > 0)
        kill(pid, SIGKILL);
    /* board list refuses it too, and says so in its status */
    CHECK_EQ_INT(list(err, sizeof err), -1);
    CHECK(strstr(err, "mode 0750") != NULL);
}

static void named_base_symlink_refused(void)
{
    char real[160], err[4096];
    fresh_base(0);
    path_of(real, sizeof real, root, "elsewhere");
    mkdir(real, 0700);
    CHECK(symlink(real, base) == 0);
    int pid = start("victim", err, sizeof err);
    CHECK(pid < 0);
    CHECK(strstr(err, base) && strstr(err, "symbolic link"));
    CHECK_EQ_INT(entries(real), 0);
    if (pid > 0)
        kill(pid, SIGKILL);
    show("refusal", err);
    unlink(base);
    rmdir(real);
}

/* The victim's directory holds files named as a board's state. */
static void victim_files(const char *dir)
{
    static const char *const names[] = {"board", "ram", "lock", "qemu.log", "link.sock"};
    mkdir(dir, 0700);
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char p[256];
        path_of(p, sizeof p, dir, names[i]);
        write_file(p, "the victim's\n");
    }
}

static void named_planted_dir_link_left_alone(void)
{
    char victim[160], link[200], out[8192];
    fresh_base(1);
    path_of(victim, sizeof victim, root, "victim");
    victim_files(victim);
    path_of(link, sizeof link, base, "evil");
    CHECK(symlink(victim, link) == 0);
    list(out, sizeof out);
    CHECK_EQ_INT(entries(victim), 5);
    CHECK(strstr(out, "evil") && strstr(out, "symbolic link"));
    char err[4096];
    CHECK(start("evil", err, sizeof err) < 0);
    CHECK_EQ_INT(entries(victim), 5);
    CHECK(stop("evil", err, sizeof err) != 0);
    CHECK_EQ_INT(entries(victim), 5);
    show("list", out);
    unlink(link);
}

static void named_record_link_refused(void)
{
    char err[4096], rec[200], copy[200], ram[200], ramcopy[200];
    fresh_base(1);
    int pid = start("b2", err, sizeof err);
    CHECK(pid > 0);
    snprintf(rec, sizeof rec, "%s/b2/board", base);
    path_of(copy, sizeof copy, root, "record-copy");
    char text[256];
    read_file(rec, text, sizeof text);
    write_file(copy, text);
    rename(rec, copy);
    CHECK(symlink(copy, rec) == 0);
    CHECK_EQ_INT(session("b2", err, sizeof err), -1);
    CHECK(strstr(err, "board b2") && strstr(err, "symbolic link"));
    show("record a link", err);
    unlink(rec);
    rename(copy, rec);
    /* the RAM file a link to a file of the right size */
    snprintf(ram, sizeof ram, "%s/b2/ram", base);
    path_of(ramcopy, sizeof ramcopy, root, "ram-elsewhere");
    int fd = open(ramcopy, O_RDWR | O_CREAT | O_TRUNC, 0600);
    CHECK(fd >= 0 && ftruncate(fd, (off_t)BOARD_MIN_RAM_MB << 20) == 0);
    close(fd);
    char aside[220];
    snprintf(aside, sizeof aside, "%s.aside", ram);
    rename(ram, aside);
    CHECK(symlink(ramcopy, ram) == 0);
    CHECK_EQ_INT(session("b2", err, sizeof err), -1);
    CHECK(strstr(err, "ram") && strstr(err, "symbolic link"));
    show("ram a link", err);
    unlink(ram);
    rename(aside, ram);
    unlink(ramcopy);
    CHECK_EQ_INT(session("b2", err, sizeof err), 0); /* the owner's board works */
    stop("b2", err, sizeof err);
    CHECK(!alive(pid));
}

/* The record rewritten with one value out of range: refused, naming it;
 * the board then works again with its own record back. */
static void record_refused(const char *name, int pid, const char *field, const char *value,
                           const char *expect)
{
    char rec[200], good[256], bad[256], err[4096];
    snprintf(rec, sizeof rec, "%s/%s/board", base, name);
    read_file(rec, good, sizeof good);
    int cores = 3, ram = BOARD_MIN_RAM_MB, p = pid;
    if (strcmp(field, "ncores") == 0)
        cores = atoi(value);
    else if (strcmp(field, "ram_mb") == 0)
        ram = atoi(value);
    else
        p = atoi(value);
    snprintf(bad, sizeof bad, "pid %d\nncores %d\nram_mb %d\narith float\n", p, cores, ram);
    write_file(rec, bad);
    CHECK_EQ_INT(session(name, err, sizeof err), -1);
    CHECK(strstr(err, expect) != NULL);
    if (!strstr(err, expect))
        show(field, err);
    write_file(rec, good);
    CHECK_EQ_INT(session(name, err, sizeof err), 0);
    CHECK(alive(pid));
}

static void named_record_values_checked(void)
{
    char err[4096];
    fresh_base(1);
    int pid = start("b3", err, sizeof err);
    CHECK(pid > 0);
    record_refused("b3", pid, "ncores", "65535", "ncores 65535, not 3..256");
    record_refused("b3", pid, "ncores", "2", "ncores 2, not 3..256");
    record_refused("b3", pid, "ram_mb", "100000", "ram_mb 100000, not 64..2048");
    record_refused("b3", pid, "pid", "1", "pid 1");
    stop("b3", err, sizeof err);
    CHECK(!alive(pid));
}

static void named_ram_wrong_size_refused(void)
{
    char err[4096], ram[200], aside[220];
    fresh_base(1);
    int pid = start("b4", err, sizeof err);
    CHECK(pid > 0);
    snprintf(ram, sizeof ram, "%s/b4/ram", base);
    snprintf(aside, sizeof aside, "%s.aside", ram);
    rename(ram, aside);
    int fd = open(ram, O_RDWR | O_CREAT | O_EXCL, 0600);
    CHECK(fd >= 0 && ftruncate(fd, 1 << 20) == 0);
    close(fd);
    CHECK_EQ_INT(session("b4", err, sizeof err), -1);
    CHECK(strstr(err, "1048576 bytes") && strstr(err, "67108864"));
    show("refusal", err);
    /* a directory where the RAM file should be */
    unlink(ram);
    mkdir(ram, 0700);
    CHECK_EQ_INT(session("b4", err, sizeof err), -1);
    CHECK(strstr(err, "not a regular file") != NULL);
    rmdir(ram);
    rename(aside, ram);
    CHECK_EQ_INT(session("b4", err, sizeof err), 0);
    stop("b4", err, sizeof err);
    CHECK(!alive(pid));
}

/* Board ab runs; a's stale record names ab's QEMU: `board stop a` must not
 * take ab's QEMU for a's (a's directory is a prefix of ab's). */
static void named_stop_prefix_spares_other(void)
{
    char err[4096], dir[200], rec[220], text[256];
    fresh_base(1);
    int ab = start("ab", err, sizeof err);
    CHECK(ab > 0);
    path_of(dir, sizeof dir, base, "a");
    mkdir(dir, 0700);
    path_of(rec, sizeof rec, dir, "board");
    snprintf(text, sizeof text, "pid %d\nncores 3\nram_mb 64\narith float\n", ab);
    write_file(rec, text);
    stop("a", err, sizeof err);
    CHECK(alive(ab));
    CHECK(access(dir, F_OK) != 0); /* a's stale state went */
    CHECK_EQ_INT(session("ab", err, sizeof err), 0);
    /* the other way round: a runs, ab's record names a's QEMU */
    int a = start("a", err, sizeof err);
    CHECK(a > 0);
    path_of(dir, sizeof dir, base, "abc");
    mkdir(dir, 0700);
    path_of(rec, sizeof rec, dir, "board");
    snprintf(text, sizeof text, "pid %d\nncores 3\nram_mb 64\narith float\n", a);
    write_file(rec, text);
    stop("abc", err, sizeof err);
    CHECK(alive(a) && alive(ab));
    stop("a", err, sizeof err);
    stop("ab", err, sizeof err);
    CHECK(!alive(a) && !alive(ab));
}

/* An an521 set's record: its shape checked like a virt board's (a whole
 * number of boards, the shared file's size, one pid for each NC board, a
 * machine there is). */
static void named_an521_record_checked(void)
{
    char err[4096], rec[200], good[256], bad[256];
    fresh_base(1);
    int pid = start("b5", err, sizeof err);
    CHECK(pid > 0);
    snprintf(rec, sizeof rec, "%s/b5/board", base);
    read_file(rec, good, sizeof good);
    static const struct {
        const char *rest, *expect;
    } cases[] = {
        {"ncores 6\nram_mb 16\narith float\nmachine an521\nnc_pids 1234\n",
         "nc_pids for 1, not 2 (one for each NC board)"},
        {"ncores 6\nram_mb 64\narith float\nmachine an521\nnc_pids 1234 1235\n",
         "ram_mb 64, not 16"},
        {"ncores 5\nram_mb 16\narith float\nmachine an521\nnc_pids 1234\n",
         "ncores 5, not an even number"},
        {"ncores 6\nram_mb 16\narith float\nmachine an521\nnc_pids 1234 1\n",
         "an NC board's pid 1"},
        {"ncores 6\nram_mb 16\narith float\nmachine vax\n", "does not read as one"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(bad, sizeof bad, "pid %d\n%s", pid, cases[i].rest);
        write_file(rec, bad);
        CHECK_EQ_INT(session("b5", err, sizeof err), -1);
        CHECK(strstr(err, cases[i].expect) != NULL);
        if (!strstr(err, cases[i].expect))
            show(cases[i].expect, err);
    }
    write_file(rec, good);
    CHECK_EQ_INT(session("b5", err, sizeof err), 0);
    stop("b5", err, sizeof err);
    CHECK(!alive(pid));
}

/* A stale an521 set (its board 0 gone) whose record names, as an NC board,
 * a process that runs but is not that board (another board's QEMU): the
 * set is reported and removed, the other process left running. */
static void named_an521_stale_spares_other(void)
{
    char err[4096], dir[200], rec[220], text[256], out[8192];
    fresh_base(1);
    int other = start("other", err, sizeof err);
    CHECK(other > 0);
    pid_t gone = fork(); /* a pid that no longer runs: the set's board 0 */
    if (gone == 0)
        _exit(0);
    waitpid(gone, NULL, 0);
    path_of(dir, sizeof dir, base, "set");
    mkdir(dir, 0700);
    path_of(rec, sizeof rec, dir, "board");
    snprintf(text, sizeof text, "pid %d\nncores 4\nram_mb 16\narith float\nmachine an521\n"
             "nc_pids %d\n", (int)gone, other);
    write_file(rec, text);
    list(out, sizeof out);
    CHECK(strstr(out, "board set: its board 0's QEMU") && strstr(out, "is gone"));
    CHECK(access(dir, F_OK) != 0);
    CHECK(alive(other));
    if (!alive(other) || access(dir, F_OK) == 0)
        show("list", out);
    stop("other", err, sizeof err);
    CHECK(!alive(other));
}

/* A directory whose lock is held and which has no record yet is a board
 * being started: never removed. */
static void named_starting_board_left_alone(void)
{
    char dir[200], lock[220], out[8192];
    fresh_base(1);
    path_of(dir, sizeof dir, base, "s");
    mkdir(dir, 0700);
    path_of(lock, sizeof lock, dir, "lock");
    int fd = open(lock, O_RDWR | O_CREAT, 0600);
    CHECK(fd >= 0 && flock(fd, LOCK_EX | LOCK_NB) == 0);
    list(out, sizeof out);
    CHECK(access(lock, F_OK) == 0);
    CHECK(strstr(out, "board s") && strstr(out, "lock is held"));
    char err[4096];
    CHECK(start("s", err, sizeof err) < 0);
    CHECK(access(lock, F_OK) == 0);
    show("list", out);
    close(fd);
    list(out, sizeof out); /* the lock let go, no record: stale, removed */
    CHECK(access(dir, F_OK) != 0);
}

/* The board's QEMU dies during a session: the error names the board. */
static void named_dead_board_named(void)
{
    char err[4096];
    fresh_base(1);
    int pid = start("d1", err, sizeof err);
    CHECK(pid > 0);
    struct board_opts o;
    opts(&o);
    struct board b;
    CHECK_EQ_INT(board_connect(&b, &o, "d1"), 0);
    kill(pid, SIGKILL);
    usleep(200000);
    struct capture c;
    capture_begin(&c, STDERR_FILENO);
    struct board_frame f;
    int status;
    const uint8_t *fields;
    size_t n;
    int rc = board_send_cmd(&b, CMD_STATUS, NULL, 0);
    if (rc == 0)
        rc = board_wait_result(&b, CMD_STATUS, 3000, &f, &status, &fields, &n);
    capture_end(&c, err, sizeof err);
    board_stop(&b);
    CHECK_EQ_INT(rc, -1);
    CHECK(strstr(err, "board d1") != NULL);
    show("message", err);
    list(err, sizeof err); /* stale: removed */
}

/* A name is letters, digits, '_', '.' and '-', never starting with '.'
 * (a hidden entry, "..") or '-' (an option: `board start --name --help`
 * must not start a board called --help): refused naming it, no board
 * started. */
static void named_names_checked(void)
{
    fresh_base(1);
    char err[4096];
    static const char *const bad[] = {"--help", "-x", "..", ".b", "a/b", ""};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char want[64];
        snprintf(want, sizeof want, "board name '%s'", bad[i]);
        CHECK_EQ_INT(start(bad[i], err, sizeof err), -1);
        CHECK(strstr(err, want) != NULL);
    }
    int pid = start("b-1.x_2", err, sizeof err);
    CHECK(pid > 0);
    stop("b-1.x_2", err, sizeof err);
    CHECK(pid <= 0 || !alive(pid));
}

int main(int argc, char **argv)
{
    if (getenv("FAKE_NAMED"))
        return fake_named(argc, argv);
    snprintf(root, sizeof root, "/tmp/links1-named-XXXXXX");
    if (!mkdtemp(root)) {
        printf("FAIL test_board_named: mkdtemp: %s\n", strerror(errno));
        return 1;
    }
    path_of(base, sizeof base, root, "base");
    setenv("QEMU", "/proc/self/exe", 1);
    setenv("FAKE_NAMED", "1", 1);
    RUN(named_names_checked);
    RUN(named_base_created_private);
    RUN(named_xdg_runtime_dir);
    RUN(named_base_of_another_refused);
    RUN(named_base_open_to_others_refused);
    RUN(named_base_symlink_refused);
    RUN(named_planted_dir_link_left_alone);
    RUN(named_record_link_refused);
    RUN(named_record_values_checked);
    RUN(named_ram_wrong_size_refused);
    RUN(named_stop_prefix_spares_other);
    RUN(named_an521_record_checked);
    RUN(named_an521_stale_spares_other);
    RUN(named_starting_board_left_alone);
    RUN(named_dead_board_named);
    for (int i = 0; i < nstarted; i++)
        if (alive(started[i]))
            kill(started[i], SIGKILL);
    fresh_base(0);
    tmp_dir_remove(root);
    return check_exit();
}
