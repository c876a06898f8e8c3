/* board.h: one session with the emulated LINKS-1 board.
 *
 * board_start() runs qemu-system-arm with the board's UART on one end of a
 * socketpair (QEMU's "-chardev socket,fd=N"): no file-system path to clean
 * up, no race to connect, no pty name to discover, and a socket gives both
 * sides back-pressure, so a slow reader slows the writer instead of losing
 * bytes.  When QEMU exits the socket reads end-of-file.
 *
 * Frames from the board are decoded as they arrive.  LOG text, HELLO
 * (report-in) and FAULT frames are printed and recorded at once, whatever the
 * caller is waiting for; every other frame (RESULT, DATA, ACK) is queued
 * until board_wait_frame() asks for its type.  Every call that waits takes a
 * timeout and returns an error naming what did not come.
 */
#ifndef LINKS1_HOST_BOARD_H
#define LINKS1_HOST_BOARD_H

#include <stddef.h>
#include <stdint.h>
#include <sys/types.h>

#include "host-tools/cli_opt.h"
#include "host-tools/links1_params.h"
#include "proto/hostlink.h"
#include "proto/link_arq.h"

struct board_opts {
    int ncores;             /* -smp */
    const char *arith;      /* float | soft | fixed */
    const char *firmware;   /* ELF path, or NULL: found by board_find_firmware */
    int ram_mb;             /* -m */
    int timeout_s;          /* report-in timeout */
    const char *insn_count_out; /* non-NULL: load the counting plugin, write here */
    const char *insn_series_out; /* non-NULL: the counting plugin appends a line of
                                    every core's count here every insn_series_ms */
    int insn_series_ms;
    const char *insn_trace_out; /* non-NULL: the counting plugin writes every trace
                                   mark here (proto/insn_mark.h) */
    int quiet;              /* 1: do not print LOG lines or the board-up line
                               (faults always) */
    int verbose;            /* 1: a line per unit computer reporting in */
    int gdb_port;           /* non-zero: QEMU's gdb stub on 127.0.0.1:gdb_port,
                               every core halted until the debugger continues */
    int view;               /* 1: -device ramfb and a display (links1 render --view) */
    int link;               /* bulk bytes: LINK_PATH_SHARED (--link fast, the
                               default) or LINK_PATH_SERIAL (--link serial) */
    int link_noise_on;      /* --link-noise RATE[:SEED] given: a noisy relay
                               between us and QEMU (host-tools/link_relay.h) */
    double link_noise;      /* its damage events per byte, each way */
    uint64_t link_noise_seed;
};

/* A frame copied out of the decoder, valid as long as the caller keeps it. */
struct board_frame {
    uint8_t type, flags;
    uint16_t seq, length;
    uint8_t payload[LINK_MAX_PAYLOAD];
};

struct board {
    struct board_opts opts;
    char firmware[4096];        /* the ELF actually booted */
    pid_t qemu_pid;             /* 0 once reaped */
    int qemu_status;            /* waitpid status once reaped */
    int fd;                     /* our end of the UART socket, -1 when closed */
    int ram_fd;                 /* the board's RAM (memfd), -1 when none */
    uint8_t *ram;               /* ... mapped here: byte k is guest address
                                   BOARD_RAM_BASE + k (NULL when none) */
    size_t ram_size;
    struct link_decoder dec;    /* board -> host frames */
    uint16_t tx_seq;            /* host -> board frame counter */
    /* The retransmission (proto/link_arq.h, go-back-N; host-tools/board.c): */
    struct link_arq_store arq_tx; /* our numbered frames, kept for resending */
    struct link_arq_rx arq_rx;  /* the board's frames, taken in seq order */
    struct link_arq_nak arq_nak;/* our NAKs' rate limit and give-up count */
    long long arq_heard_ms;     /* when the last good frame came */
    long long arq_byte_ms;      /* when the last byte came */
    int arq_armed;              /* the link was seen damaged: poll when silent */
    int arq_damage_seen;        /* the link was ever seen damaged (stall rule) */
    int arq_gap;                /* a board frame we lack is asked for */
    int arq_polls;              /* polls in a row with no frame heard */
    int arq_failed;             /* the retransmission gave up: every wait fails */
    int arq_naks_heard;         /* 1: the board's NAKs name our numbering (0 while a
                                   session on a board left running opens: a NAK
                                   then may name an earlier session's seq) */
    uint32_t arq_resends;       /* our frames sent again */
    uint32_t arq_dups;          /* board frames dropped as taken already */
    int arq_writing;            /* inside a frame's write: NAKs and resends wait */
    int arq_resend_due;         /* a resend from arq_resend_from waits for the write */
    uint16_t arq_resend_from;
    int arq_nak_due;            /* a NAK (flags arq_nak_flags + 1) waits for the write */
    uint8_t arq_nak_flags;
    uint16_t arq_asked_from;    /* the seq the board's NAKs last named */
    int arq_asked;              /* NAKs in a row for it (LINK_ARQ_MAX_ASKS) */
    int reported_count;         /* distinct cores that sent HELLO */
    uint8_t reported[UNITS_MAX_CORES]; /* 1 once core k sent HELLO */
    int hello_errors;           /* HELLOs with a wrong role/ncores/variant/core */
    struct link_fault faults[BOARD_MAX_FAULTS];
    int nfaults;                /* faults seen (only the first BOARD_MAX_FAULTS kept) */
    struct board_frame queue[BOARD_FRAME_QUEUE]; /* RESULT/DATA/ACK not yet taken */
    int queued;
    int stopping;               /* 1 during board_stop: end-of-file is expected */
    uint32_t host_frames_dropped; /* board's reports (RESULT for cmd 0) of frames
                                     from the host it dropped */
    int host_drop_status;       /* status of the last such report */
    char host_drop_text[LINK_MAX_PAYLOAD + 1]; /* and its text */
    char fault_text[BOARD_MAX_FAULTS][BOARD_FAULT_TEXT]; /* text of each kept fault */
    int named;                  /* 1: a named board (board_named.c), which runs
                                   on after this session */
    char state_dir[4096];       /* a named board's state directory */
    int lock_fd;                /* a named board's lock, held by this session */
    long long started_ms;       /* board_now_ms() when QEMU was started */
};

/* Fills o with the defaults (BOARD_DEFAULT_*). */
void board_opts_init(struct board_opts *o);

/* The board options every board subcommand takes (--smp, --arith,
 * --firmware, --timeout, --ram, --quiet, --link, --verbose, --gdb, --link-noise): entries for the subcommand's
 * getopt_long table, and their codes. */
enum board_opt_code {
    BOARD_OPT_SMP = CLI_BOARD_CODES,
    BOARD_OPT_ARITH,
    BOARD_OPT_FIRMWARE,
    BOARD_OPT_TIMEOUT,
    BOARD_OPT_RAM,
    BOARD_OPT_QUIET,
    BOARD_OPT_LINK,
    BOARD_OPT_VERBOSE,
    BOARD_OPT_GDB,
    BOARD_OPT_LINK_NOISE,
};
#define BOARD_LONG_OPTIONS                                       \
    {"smp", required_argument, NULL, BOARD_OPT_SMP},             \
    {"arith", required_argument, NULL, BOARD_OPT_ARITH},         \
    {"firmware", required_argument, NULL, BOARD_OPT_FIRMWARE},   \
    {"timeout", required_argument, NULL, BOARD_OPT_TIMEOUT},     \
    {"ram", required_argument, NULL, BOARD_OPT_RAM},             \
    {"quiet", no_argument, NULL, BOARD_OPT_QUIET},               \
    {"link", required_argument, NULL, BOARD_OPT_LINK},           \
    {"verbose", no_argument, NULL, BOARD_OPT_VERBOSE},           \
    {"gdb", required_argument, NULL, BOARD_OPT_GDB},             \
    {"link-noise", required_argument, NULL, BOARD_OPT_LINK_NOISE}

/* Takes the board option cli_next() returned as code into o.  Returns 1
 * when it took it, 0 when code is not a board option, -1 after printing
 * what is wrong with its value. */
int board_opt(struct board_opts *o, const struct cli *c, int code);

/* The usage lines of the board options, for each subcommand's --help. */
extern const char board_opts_usage[];

/* Resolves the firmware ELF into out: opts->firmware, else
 * $FW_DIR/links1-<arith>.elf, else links1-<arith>.elf next to this program.
 * Returns 0, or -1 after printing where it looked. */
int board_find_firmware(const struct board_opts *o, char *out, size_t cap);

/* Starts QEMU, its RAM a memfd mapped here too (b->ram: the shared-memory
 * path of proto/hostlink.h).  Returns 0, or -1 after printing why. */
int board_start(struct board *b, const struct board_opts *o);

/* A session on an already open link fd (no QEMU: the host tests play the
 * board on the other end of a socketpair); board_start uses it too. */
void board_attach(struct board *b, const struct board_opts *o, int fd);

/* Runs a semihosting program (not the firmware: one core, no link) on the
 * plain virt board, its console output on our stdout, until it ends the
 * emulator (semihosting SYS_EXIT).  Returns QEMU's exit status, or -1 after
 * printing why. */
int board_run_semihost(const char *elf, int ram_mb);

/* Waits until every core has sent HELLO, then (unless quiet) prints one line
 * "board up: N unit computers in T s".  Returns 0, or -1 after printing the
 * missing cores (timeout) or why the board stopped. */
int board_wait_reported(struct board *b, int timeout_ms);

/* Sends one frame; returns its seq, or -1 after printing why. */
int board_send(struct board *b, uint8_t type, uint8_t flags, const void *payload,
               size_t len);

/* Writes bytes to the board's UART as they are: no framing, tx_seq
 * untouched.  For tests that must send damaged frames (encode one with
 * link_frame_encode, then spoil a byte).  Returns 0, or -1 after printing
 * why. */
int board_send_raw(struct board *b, const void *bytes, size_t n);

/* Sends LINK_CMD cmd with args (len bytes, may be 0). */
int board_send_cmd(struct board *b, uint16_t cmd, const void *args, size_t len);

/* Waits for the next queued frame of the given type.  Returns 0 with *out
 * filled, or -1 after printing what did not come (what names it). */
int board_wait_frame(struct board *b, uint8_t type, int timeout_ms,
                     struct board_frame *out, const char *what);

/* Waits for the next queued frame of any type in mask (bit 1 << type). */
int board_wait_frame_of(struct board *b, uint32_t mask, int timeout_ms,
                        struct board_frame *out, const char *what);

/* Puts a frame taken by board_wait_frame* back at the head of the queue,
 * for the caller that waits for it next. */
void board_unget_frame(struct board *b, const struct board_frame *f);

/* Waits for the LINK_RESULT of cmd; checks its size and cmd field.  On
 * success *status is the board's status, *fields and *nfields its result bytes
 * (pointing into out).  Returns 0, or -1 after printing why. */
int board_wait_result(struct board *b, uint16_t cmd, int timeout_ms,
                      struct board_frame *out, int *status,
                      const uint8_t **fields, size_t *nfields);

/* Reads and handles whatever arrives for up to timeout_ms (LOG/HELLO/FAULT
 * printed, others queued).  Returns 0, or -1 if the board stopped. */
int board_pump(struct board *b, int timeout_ms);

/* Link errors seen so far, both ways: frames from the board with a bad CRC
 * or length, seq gaps or junk, and frames from the host the board dropped.
 * The retransmission repairs them; board_arq_failed says when it could not. */
uint32_t board_link_errors(const struct board *b);
/* Prints the decoder's counters (and the frames sent again) when any is
 * non-zero; returns that count. */
uint32_t board_report_link_errors(const struct board *b);
/* 1 once the retransmission gave up (an error was printed naming the frame). */
int board_arq_failed(const struct board *b);

/* Shuts the board down: CMD_SHUTDOWN, wait for QEMU to exit, SIGTERM, and
 * SIGKILL only as a last resort.  Returns 0 when QEMU exited by itself after
 * the command, 1 when it had to be signalled, -1 on error.  Safe to call
 * twice and after QEMU died. */
int board_stop(struct board *b);

/* ---- named boards (host-tools/board_named.c) ----
 * `links1 board start --name NAME` leaves a board running for later
 * sessions (`links1 render --board NAME`).  Its state directory
 * ($LINKS1_BOARDS, else /dev/shm/links1-UID, else /tmp/links1-UID, then
 * NAME/) holds QEMU's pid and the board's shape (BOARD_STATE_INFO), the
 * UART as a listening socket, the shared RAM file, QEMU's own output and a
 * lock that one session at a time holds.  A board whose QEMU is gone leaves
 * a stale directory: found, reported and removed by start, stop and list. */
#define BOARD_STATE_INFO "board"
#define BOARD_STATE_SOCKET "link.sock"
#define BOARD_STATE_RAM "ram"
#define BOARD_STATE_LOG "qemu.log"
#define BOARD_STATE_LOCK "lock"
#define BOARD_DEFAULT_NAME "default"

/* Starts QEMU as the named board and waits for every unit computer to
 * report in; the board then runs on without this tool.  0, or -1 after
 * printing why (a board of that name already running, QEMU failing). */
int board_start_named(struct board *b, const struct board_opts *o, const char *name,
                      int timeout_ms);
/* A session on the named board: maps its RAM, connects to its UART, opens
 * the session (LINK_FLAG_SESSION) and checks that every unit computer is up.
 * o gives quiet and link; the shape comes from the board.  0, or -1 after
 * printing why. */
int board_connect(struct board *b, const struct board_opts *o, const char *name);
/* Shuts the named board down and removes its state.  0, or -1. */
int board_stop_named(const char *name);
/* Prints every named board: running (pid, cores) or stale (then removed).
 * Returns the number running. */
int board_list_named(void);
/* board_start_named's steps (board.c starts the process between them):
 * the state directory made, a stale one removed, the lock taken; the record
 * written and the UART socket connected (returns its fd); everything undone
 * after a failure. */
int board_named_prepare(struct board *b, const char *name);
int board_named_started(struct board *b, int timeout_ms);
void board_named_abandon(struct board *b);
/* In QEMU's child process: its output into the state directory. */
void board_named_redirect(const struct board *b);
/* The named board's RAM file mapped into b (board_start_named creates it
 * with create = 1).  0, or -1 after printing why. */
int board_named_map_ram(struct board *b, int create);

/* Handles one decoded frame (used by the reader in board.c): prints LOG,
 * checks and records HELLO, prints and records FAULT, queues the rest.
 * Returns 0, or -1 when the queue is full (the board broke the window). */
int board_handle_frame(struct board *b, const struct link_frame *f);

/* Name of a LINK_RESULT status ("timeout", ...). */
const char *board_status_name(int status);

/* Milliseconds on the monotonic clock. */
long long board_now_ms(void);

/* The code (proto/arith.h) of an arithmetic the board runs, by name, or -1
 * for a name that is not one of them. */
int board_arith_code(const char *arith);

/* Role name of core k ("DM", "RC", "NC"). */
const char *board_role_name(int core);

#endif
