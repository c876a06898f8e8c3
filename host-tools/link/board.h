/* board.h: one link session with the emulated LINKS-1 board, over the
 * board's UART (a socket the launcher hands over: host-tools/launcher/).
 *
 * Frames from the board are decoded as they arrive.  LOG text, HELLO
 * (report-in) and FAULT frames are printed (the board's text escaped,
 * board_text.h) and recorded at once, whatever the
 * caller is waiting for; every other frame (RESULT, DATA, ACK) is queued
 * until board_wait_frame() asks for its type.  Every call that waits takes a
 * timeout and returns an error naming what did not come.
 */
#ifndef LINKS1_HOST_BOARD_H
#define LINKS1_HOST_BOARD_H

#include <stddef.h>
#include <stdint.h>
#include <sys/types.h>

#include "proto/board_map_an521.h"
#include "proto/hostlink.h"
#include "proto/machines.h"
#include "proto/units.h"

/* Milliseconds to wait for one answer frame (a command's result, a DATA or
 * ACK frame of a transfer) before calling the board unresponsive. */
#define BOARD_FRAME_TIMEOUT_MS 20000
/* Frames other than LOG/HELLO/FAULT wait here until someone asks for them;
 * a transfer keeps at most LINK_DATA_WINDOW DATA frames in flight, so a
 * full queue means the board broke the window. */
#define BOARD_FRAME_QUEUE 32
/* Faults remembered for the caller to check (all are printed). */
#define BOARD_MAX_FAULTS 64
/* Bytes of each remembered fault's text kept (with the terminator). */
#define BOARD_FAULT_TEXT 256
/* Bytes read from the link per read() call, and the pause (microseconds)
 * after a wake-up that lets bytes gather before reading. */
#define BOARD_READ_CHUNK 4096
#define BOARD_READ_BATCH_US 200

struct board_arq;

struct board_opts {
    int machine;            /* enum machine_id (proto/machines.h) */
    int ncores;             /* -smp; on an521, 2 per board */
    const char *arith;      /* float | soft | fixed */
    const char *firmware;   /* ELF path, or NULL: found by board_find_firmware */
    int escalate;           /* 1: the firmware that escalates (links1-<arith>-esc.elf) */
    int ram_mb;             /* -m */
    int timeout_s;          /* report-in timeout */
    const char *insn_count_out; /* non-NULL: load the counting plugin, write here */
    const char *insn_series_out; /* non-NULL: the counting plugin appends a line of
                                    every core's count here every insn_series_ms */
    int insn_series_ms;
    const char *insn_trace_out; /* non-NULL: the counting plugin writes every trace
                                   mark here (proto/insn_mark.h) */
    const char *insn_profile_out; /* non-NULL: the counting plugin writes the NCs'
                                     instructions per block address here */
    int insn_profile_core;  /* the one core profiled, or -1: the NCs */
    int quiet;              /* 1: do not print LOG lines or the board-up line
                               (faults always) */
    int verbose;            /* 1: a line per unit computer reporting in */
    int gdb;                /* 1: QEMU's gdb stub on a unix socket in the user's
                               state directory (board.gdb_socket), every core
                               halted until the debugger continues */
    int view;               /* 1: -device ramfb and a display (links1 render --view) */
    int link;               /* bulk bytes: LINK_PATH_SHARED (--link fast, the
                               default) or LINK_PATH_SERIAL (--link serial) */
    int link_noise_on;      /* --link-noise RATE[:SEED] given: a noisy relay
                               between us and QEMU (host-tools/launcher/link_relay.h) */
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
    pid_t qemu_pid;             /* 0 once reaped (on an521: board 0's) */
    pid_t nc_board_pid[AN521_MAX_BOARDS]; /* an521: the NC boards' QEMUs (index
                                   = board number; 0 once reaped) */
    int nc_board_status[AN521_MAX_BOARDS]; /* ... their waitpid status */
    int qemu_status;            /* waitpid status once reaped */
    int fd;                     /* our end of the UART socket, -1 when closed */
    int ram_fd;                 /* the board's RAM (memfd), -1 when none */
    uint8_t *ram;               /* ... mapped here: byte k is guest address
                                   BOARD_RAM_BASE + k (NULL when none) */
    size_t ram_size;
    struct link_decoder dec;    /* board -> host frames */
    uint16_t tx_seq;            /* host -> board frame counter */
    struct board_arq *arq;      /* the retransmission's state (go-back-N, proto/
                                   link_arq.h): private to host-tools/link/ */
    int link_failed;            /* the retransmission gave up: every wait fails */
    uint32_t frames_resent;     /* our frames the retransmission sent again */
    uint32_t frames_dropped_dup;/* board frames dropped as taken already */
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
    char host_drop_text[LINK_MAX_PAYLOAD + 1]; /* and its text (escaped: board_text.h) */
    char fault_text[BOARD_MAX_FAULTS][BOARD_FAULT_TEXT]; /* text of each kept fault
                                                             (escaped) */
    int named;                  /* 1: a named board (board_named.c), which runs
                                   on after this session */
    char state_dir[4096];       /* a named board's state directory */
    int state_fd;               /* ... open (the launcher's), -1 when none */
    int lock_fd;                /* a named board's lock, held by this session */
    char gdb_socket[108];       /* --gdb: the stub's unix socket (the launcher's) */
    long long started_ms;       /* board_now_ms() when QEMU was started */
    /* Set by the launcher: what happened to the board's process once its
     * link ended (reaped, still running, ...), written into desc. */
    void (*process_gone)(struct board *b, char *desc, size_t cap);
};

/* ---- the session's life ----
 * The launcher (host-tools/launcher/launcher.h) starts a board and opens a
 * session on it; the host tests play the board on the other end of a
 * socketpair (board_attach). */
/* b emptied, o copied, the retransmission's state allocated, SIGPIPE
 * ignored (a write to a link whose far end is gone fails with an error).
 * 0, or -1 after printing why.  Every session ends with board_session_close (the
 * launcher's board_stop calls it). */
int board_session_init(struct board *b, const struct board_opts *o);
/* The session's link is fd (made non-blocking). */
void board_session_open(struct board *b, int fd);
/* A board this tool booted numbers its frames from 0 (otherwise the first
 * frame heard sets the numbering). */
void board_session_peer_from_zero(struct board *b);
/* 1: the board's NAKs name our numbering; 0 while a session on a board left
 * running opens (a NAK then may name an earlier session's seq). */
void board_session_naks_ours(struct board *b, int ours);
/* Takes what the board still says until the link closes or timeout_ms
 * pass, dropping it (a shutdown in progress: end-of-file is expected). */
void board_session_drain(struct board *b, int timeout_ms);
/* A session opened on a board left running: what an earlier session left
 * (a cut frame's bytes, its dropped-frame reports, queued frames) is
 * forgotten, and every unit computer counts as reported in (they did,
 * before this session).  Returns the bytes and frames forgotten. */
uint32_t board_session_adopt(struct board *b);
/* Closes the link and frees the session's state; safe to call twice. */
void board_session_close(struct board *b);
/* board_session_init and board_session_open in one: 0, or -1. */
int board_attach(struct board *b, const struct board_opts *o, int fd);

/* Frames queued and not yet taken. */
int board_queued(const struct board *b);
/* Takes the first queued frame of a type in mask (bit 1 << type) into out
 * without waiting: 1 if there was one, else 0. */
int board_take_queued(struct board *b, uint32_t mask, struct board_frame *out);

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

/* Waits for the result of cmd and checks it: status LINK_OK and at least
 * min_fields bytes of fields.  0 with *fields and *nfields set (pointing
 * into out); -1 with why naming what went wrong (no result, the board's own
 * text and status, a result too short). */
int board_wait_ok(struct board *b, uint16_t cmd, int timeout_ms, size_t min_fields,
                  struct board_frame *out, const uint8_t **fields, size_t *nfields,
                  char *why, size_t cap);

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
