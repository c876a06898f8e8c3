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
    int quiet;              /* 1: do not print LOG/HELLO lines (faults always) */
    int view;               /* 1: -device ramfb and a display (links1 render --view) */
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
    struct link_decoder dec;    /* board -> host frames */
    uint16_t tx_seq;            /* host -> board frame counter */
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
};

/* Fills o with the defaults (BOARD_DEFAULT_*). */
void board_opts_init(struct board_opts *o);

/* The board options every board subcommand takes (--smp, --arith,
 * --firmware, --timeout, --ram, --quiet): entries for the subcommand's
 * getopt_long table, and their codes. */
enum board_opt_code {
    BOARD_OPT_SMP = CLI_BOARD_CODES,
    BOARD_OPT_ARITH,
    BOARD_OPT_FIRMWARE,
    BOARD_OPT_TIMEOUT,
    BOARD_OPT_RAM,
    BOARD_OPT_QUIET,
};
#define BOARD_LONG_OPTIONS                                       \
    {"smp", required_argument, NULL, BOARD_OPT_SMP},             \
    {"arith", required_argument, NULL, BOARD_OPT_ARITH},         \
    {"firmware", required_argument, NULL, BOARD_OPT_FIRMWARE},   \
    {"timeout", required_argument, NULL, BOARD_OPT_TIMEOUT},     \
    {"ram", required_argument, NULL, BOARD_OPT_RAM},             \
    {"quiet", no_argument, NULL, BOARD_OPT_QUIET}

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

/* Starts QEMU.  Returns 0, or -1 after printing why. */
int board_start(struct board *b, const struct board_opts *o);

/* A session on an already open link fd (no QEMU: the host tests play the
 * board on the other end of a socketpair); board_start uses it too. */
void board_attach(struct board *b, const struct board_opts *o, int fd);

/* Runs a semihosting program (not the firmware: one core, no link) on the
 * plain virt board, its console output on our stdout, until it ends the
 * emulator (semihosting SYS_EXIT).  Returns QEMU's exit status, or -1 after
 * printing why. */
int board_run_semihost(const char *elf, int ram_mb);

/* Waits until every core has sent HELLO.  Returns 0, or -1 after printing
 * the missing cores (timeout) or why the board stopped. */
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
 * or length, seq gaps or junk, and frames from the host the board dropped. */
uint32_t board_link_errors(const struct board *b);
/* Prints the decoder's counters when any is non-zero; returns that count. */
uint32_t board_report_link_errors(const struct board *b);

/* Shuts the board down: CMD_SHUTDOWN, wait for QEMU to exit, SIGTERM, and
 * SIGKILL only as a last resort.  Returns 0 when QEMU exited by itself after
 * the command, 1 when it had to be signalled, -1 on error.  Safe to call
 * twice and after QEMU died. */
int board_stop(struct board *b);

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
