/* hostlink.h: the framed protocol between the host tool and the board over
 * the PL011 UART.  One definition for both sides.
 *
 * Every byte on the line belongs to a frame, so log text and data share the
 * one line without ambiguity:
 *
 *   offset  size  field
 *   0       2     sync: 'L' '1'
 *   2       1     type    (enum link_type)
 *   3       1     flags   (LINK_FLAG_*)
 *   4       2     seq     sender's frame counter, +1 per frame, wraps at 2^16
 *   6       2     length  payload bytes, 0..LINK_MAX_PAYLOAD
 *   8       len   payload (fields little-endian, see proto/wire.h)
 *   8+len   4     crc32 of bytes 2 .. 8+len-1 (type through payload)
 *
 * Each direction numbers its own frames (LINK_NAK, unnumbered, excepted).  A
 * receiver that sees a gap or a repeat in seq, or a bad CRC, counts it
 * (struct link_stats) and asks for the frames again (proto/link_arq.h: every
 * frame is kept for resending, go-back-N); the emulated line itself never
 * drops bytes, so any such count is the damage of the --link-noise test hook
 * (docs/host-link.md) or a bug.
 * After a bad frame the decoder resynchronises on the next 'L' '1'.
 */
#ifndef LINKS1_PROTO_HOSTLINK_H
#define LINKS1_PROTO_HOSTLINK_H

#include <stddef.h>
#include <stdint.h>

#define LINK_SYNC0 'L'
#define LINK_SYNC1 '1'
#define LINK_HEADER_SIZE 8
#define LINK_CRC_SIZE 4
#define LINK_MAX_PAYLOAD 2048
#define LINK_MAX_FRAME (LINK_HEADER_SIZE + LINK_MAX_PAYLOAD + LINK_CRC_SIZE)

enum link_type {
    LINK_LOG = 1,    /* board -> host: log text, UTF-8, no terminator */
    LINK_HELLO = 2,  /* board -> host: a unit computer reports in (link_hello) */
    LINK_FAULT = 3,  /* board -> host: a core faulted and halted (link_fault) */
    LINK_CMD = 4,    /* host -> board: a command (u16 enum link_cmd, then args) */
    LINK_RESULT = 5, /* board -> host: a command's result (u16 cmd, i16 status, text) */
    LINK_DATA = 6,   /* either way: a chunk of a bulk transfer */
    LINK_ACK = 7,    /* either way: u16 seq of the last DATA frame taken in */
    LINK_PROGRESS = 8, /* board -> host: rendering progress (proto/render_link.h) */
    LINK_BULK = 9,   /* either way: bulk bytes in the board's shared RAM (link_bulk) */
    LINK_NAK = 10,   /* either way, unnumbered: the retransmission's request, u16 seq
                      * the receiver expects next (proto/link_arq.h) */
};

/* LINK_CMD payload: u16 enum link_cmd, then that command's arguments
 * (little-endian).  The board answers every command with one LINK_RESULT:
 * u16 cmd, i16 status (0 = success, negative = error), then the command's
 * result fields or, on error, text naming the problem.  Later issues add the
 * render commands after these. */
enum link_cmd {
    CMD_STATUS = 1,      /* -> struct link_status_result */
    CMD_LINE_PING = 2,   /* ping-pong over every serial line -> link_count_result */
    CMD_IMSU_TEST = 3,   /* the DM's memcpy and memset, then swap both ways + broadcast,
                            checksummed -> link_count_result */
    CMD_LINE_STRESS = 4, /* u32 MiB through the inter-unit lines -> link_stress_result */
    CMD_LINK_SINK = 5,   /* host sends DATA frames; board checks -> link_transfer_result */
    CMD_LINK_SOURCE = 6, /* u32 bytes: board sends DATA frames of a known pattern
                          * -> link_transfer_result */
    CMD_FAULT_INJECT = 7,/* u16 core, u8 kind: that core executes the fault */
    CMD_SHUTDOWN = 8,    /* board powers off (PSCI SYSTEM_OFF) */
    /* Rendering (arguments and results in proto/render_link.h): */
    CMD_SCENE_LOAD = 9,  /* u32 bytes, then one DATA transfer of the compiled
                          * scene -> struct link_scene_info */
    CMD_RENDER = 10,     /* struct link_render_args; LINK_PROGRESS frames while
                          * it renders -> struct link_render_stats */
    CMD_FRAME_PULL = 11, /* board sends the frame memory as one DATA transfer
                          * (rows of r,g,b bytes) -> u16 width, u16 height, u32 check
                          * (the transfer's CRC-32; the shared path's word sum) */
    CMD_LINE_LATENCY = 12, /* u32 rounds, u16 core: that many MSG_PING round trips, one
                            * after another, on core's line (core 1: DM<->RC; an NC:
                            * RC<->NC), each timed -> struct link_latency_result */
};
/* CMD_LINK_SINK, CMD_LINK_SOURCE, CMD_SCENE_LOAD and CMD_FRAME_PULL take one
 * more optional u8 after their arguments: the path of their bulk bytes
 * (absent = LINK_PATH_SERIAL).  See "the shared-memory path" below. */
enum link_path {
    LINK_PATH_SERIAL = 0, /* LINK_DATA frames with LINK_ACK flow control */
    LINK_PATH_SHARED = 1, /* the board's RAM, shared with the host (LINK_BULK) */
};

enum link_flag {
    LINK_FLAG_LAST = 1u << 0, /* DATA: the last chunk of a transfer */
    LINK_FLAG_SESSION = 1u << 1, /* any frame: the sender starts its numbering
                                  * again here (a new host session on a board
                                  * left running); no seq gap is counted */
    LINK_FLAG_POLL = 1u << 2,    /* LINK_NAK: the sender heard nothing for a while;
                                  * answer with a LINK_NAK naming your own expected seq */
    LINK_FLAG_GONE = 1u << 3,    /* LINK_NAK: the seq asked for is no longer held
                                  * for resending: the link gives up */
};

/* LINK_RESULT status values (i16).  Every error result carries text naming
 * the problem after the status. */
enum link_status {
    LINK_OK = 0,
    LINK_ERR_UNKNOWN_CMD = -1, /* command number not in enum link_cmd */
    LINK_ERR_BAD_ARGS = -2,    /* payload too short/long or an argument out of range */
    LINK_ERR_BAD_FRAME = -3,   /* a frame was dropped (bad CRC, bad length, seq gap);
                                * sent with cmd 0 as soon as the board sees it */
    LINK_ERR_TIMEOUT = -4,     /* a unit computer did not answer in time */
    LINK_ERR_CHECK = -5,       /* data arrived but a checksum/sequence check failed */
    LINK_ERR_PROTOCOL = -6,    /* unexpected frame during a transfer */
};

/* Roles of the unit computers, by core number: 0 DM, 1 RC, 2.. NCs. */
enum unit_role { ROLE_DM = 0, ROLE_RC = 1, ROLE_NC = 2 };
/* The role of core k (proto/units.h: UNITS_DM_CORE, UNITS_RC_CORE, NCs). */
uint8_t unit_role_of_core(uint32_t core);
/* "DM", "RC", "NC", or "?" for another value. */
const char *unit_role_name(uint8_t role);

/* LINK_HELLO payload */
#define LINK_HELLO_SIZE 12
struct link_hello {
    uint16_t core;    /* core number, 0 .. ncores-1 */
    uint8_t role;     /* enum unit_role */
    uint8_t variant;  /* the build's arithmetic: enum links1_arith (proto/arith.h) */
    uint32_t mpidr;   /* the core's MPIDR */
    uint16_t ncores;  /* cores on the board */
    uint16_t reserved;
};

/* LINK_FAULT payload: fixed part, then the text of what happened. */
#define LINK_FAULT_FIXED_SIZE 16
enum link_fault_kind {
    FAULT_UNDEF = 1,          /* undefined instruction */
    FAULT_PREFETCH_ABORT = 2, /* instruction fetch abort */
    FAULT_DATA_ABORT = 3,     /* data abort */
    FAULT_PANIC = 4,          /* software panic (kernel or driver check) */
};
/* CMD_FAULT_INJECT kinds beyond enum link_fault_kind: kernel checks that
 * must panic (reported as FAULT_PANIC, the text naming the lock). */
#define FAULT_INJECT_LOCK_TWICE 0x10  /* take a spinlock this core holds */
#define FAULT_INJECT_UNLOCK_FREE 0x11 /* release a spinlock nobody holds */
struct link_fault {
    uint16_t core;
    uint8_t role;
    uint8_t kind;   /* enum link_fault_kind */
    uint32_t addr;  /* faulting instruction (undef/prefetch) or data address */
    uint32_t pc;    /* pc at the fault */
    uint32_t status;/* DFSR/IFSR, or 0 */
};

/* ---- bulk transfers and the link tests ----
 *
 * A transfer is a run of LINK_DATA frames, each carrying 1..LINK_DATA_CHUNK
 * payload bytes, the last one flagged LINK_FLAG_LAST.  The receiver answers
 * every DATA frame it has taken in with a LINK_ACK whose payload is that
 * frame's u16 seq.  The sender keeps at most LINK_DATA_WINDOW DATA frames
 * unacknowledged: an ACK for seq s acknowledges every DATA frame up to s, so
 * the receiver never has to hold more than the window, and a slow receiver
 * slows the sender instead of losing bytes.
 *
 * CMD_LINK_SINK (no arguments): the host then sends one transfer of the
 * pattern below; after its LAST frame the board answers LINK_RESULT with
 * u64 bytes received, u32 crc32 of them.
 * CMD_LINK_SOURCE (u32 bytes): the board sends one transfer of that many
 * pattern bytes, then LINK_RESULT with u64 bytes sent, u32 crc32 of them.
 */
#define LINK_DATA_CHUNK 1024
#define LINK_DATA_WINDOW 4
#define LINK_ACK_SIZE 2
#define LINK_CMD_FIXED_SIZE 2    /* u16 enum link_cmd */
#define LINK_RESULT_FIXED_SIZE 4 /* u16 cmd, i16 status */

/* Byte i of the link tests' known pattern.  A hash of the offset rather than
 * a counter, so a chunk that is lost, repeated or delivered out of order
 * changes the bytes (and their CRC), not only the count. */
static inline uint8_t link_pattern_byte(uint32_t i)
{
    uint32_t x = i * 2654435761u;
    return (uint8_t)((x >> 24) ^ i);
}

/* ---- the shared-memory path (LINK_PATH_SHARED) ----
 *
 * The host tool backs the board's whole RAM with a file it maps too
 * (proto/board_map.h: file offset = guest address - BOARD_RAM_BASE).  Bulk
 * bytes then move as one memcpy on the host; only a LINK_BULK frame saying
 * where they are crosses the serial link, with the bytes' word sum
 * (proto/wordsum.h: two adds a word, where a CRC-32 costs a table step a
 * byte):
 *
 *   offset  size  field
 *   0       4     offset   bytes from BOARD_RAM_BASE
 *   4       4     length   bytes
 *   8       4     sum      word sum of those bytes (0 in an offer)
 *
 * Host -> board (CMD_LINK_SINK, CMD_SCENE_LOAD): the board answers the
 * command with a LINK_BULK offer (offset, room in bytes, sum 0) of memory it
 * set aside, or at once with an error LINK_RESULT when it cannot take the
 * bytes.  The host writes its bytes there and sends LINK_BULK (offset,
 * length <= room, sum); the board checks the offset, the length and the sum
 * of what it finds, answers LINK_ACK with that frame's seq (the bytes are on
 * the board), and then the command's LINK_RESULT as on the serial path.  When
 * the sum does not match, the board offers the same memory again (a new
 * LINK_BULK offer) and the host copies its bytes again, up to LINK_BULK_TRIES
 * offers in all; then the board answers an error.  A scene's sum is taken in
 * the same pass as its header's (SCN_HDR_SUM), which the loader then
 * compares without reading the bytes again.
 *
 * Board -> host (CMD_LINK_SOURCE, CMD_FRAME_PULL): the board sends LINK_BULK
 * (offset, length, sum) of bytes already in its RAM, then the command's
 * LINK_RESULT.  They stay valid until the host's next command.  The frame
 * memory is sent as it is held, one little-endian u32 0x00RRGGBB per pixel,
 * row after row (proto/render_link.h link_frame_word_rgb), and the check of
 * CMD_FRAME_PULL's result is then the word sum of those words.  When the
 * bytes the host finds do not have the sum, the host sends CMD_FRAME_PULL
 * again, up to LINK_BULK_TRIES times in all (the frame memory is unchanged
 * until the next CMD_RENDER).  The link tests' results (CMD_LINK_SINK,
 * CMD_LINK_SOURCE) carry the CRC-32 of the pattern on both paths. */
#define LINK_BULK_SIZE 12
#define LINK_BULK_TRIES 3
struct link_bulk {
    uint32_t offset, length, sum;
};
void link_bulk_put(uint8_t *p, const struct link_bulk *k);
void link_bulk_get(const uint8_t *p, struct link_bulk *k);

/* ---- command results ----
 * The fields of a successful LINK_RESULT, after u16 cmd and i16 status.  The
 * board writes them with the _put functions, the host reads them with _get. */

/* CMD_STATUS: u16 cores on the board, u16 reported in, u16 halted (faulted). */
#define LINK_STATUS_RESULT_SIZE 6
struct link_status_result {
    uint16_t ncores, reported, halted;
};

/* CMD_LINE_PING (serial lines) and CMD_IMSU_TEST (IMSU blocks): u32 how many
 * passed, u32 how many were tried.  Both answer an error when ok != total. */
#define LINK_COUNT_RESULT_SIZE 8
struct link_count_result {
    uint32_t ok, total;
};

/* CMD_LINE_STRESS: u64 bytes checked, u32 errors, u32 messages of other
 * kinds skipped on the way. */
#define LINK_STRESS_RESULT_SIZE 16
struct link_stress_result {
    uint64_t bytes;
    uint32_t errors, skipped;
};

/* CMD_LINK_SINK and CMD_LINK_SOURCE: u64 bytes moved, u32 crc32 of them,
 * u32 bytes that differ from link_pattern_byte (the sink's check; the
 * source sends the pattern, so 0). */
#define LINK_TRANSFER_RESULT_SIZE 16
struct link_transfer_result {
    uint64_t bytes;
    uint32_t crc, differ;
};

void link_status_result_put(uint8_t *p, const struct link_status_result *r);
void link_status_result_get(const uint8_t *p, struct link_status_result *r);
void link_count_result_put(uint8_t *p, const struct link_count_result *r);
void link_count_result_get(const uint8_t *p, struct link_count_result *r);
/* CMD_LINE_LATENCY: its arguments, the most rounds it takes, and its
 * result: u32 rounds, u32 ticks per second of the counter that timed them,
 * then the round trips' u32 min, median and max in those ticks. */
#define LINK_LATENCY_ARGS_SIZE 6
#define LINK_LATENCY_MAX_ROUNDS 1000u
#define LINK_LATENCY_RESULT_SIZE 20
struct link_latency_result {
    uint32_t rounds, freq, min, median, max;
};
void link_latency_result_put(uint8_t *p, const struct link_latency_result *r);
void link_latency_result_get(const uint8_t *p, struct link_latency_result *r);

void link_stress_result_put(uint8_t *p, const struct link_stress_result *r);
void link_stress_result_get(const uint8_t *p, struct link_stress_result *r);
void link_transfer_result_put(uint8_t *p, const struct link_transfer_result *r);
void link_transfer_result_get(const uint8_t *p, struct link_transfer_result *r);

/* ---- framing ---- */

/* Writes one frame into out (capacity cap); returns its size, or 0 if the
 * payload is too long or out too small. */
size_t link_frame_encode(uint8_t *out, size_t cap, uint8_t type, uint8_t flags,
                         uint16_t seq, const void *payload, size_t len);

/* Streaming decoder: push bytes one at a time as they arrive. */
struct link_stats {
    uint32_t frames;    /* good frames delivered */
    uint32_t crc_errors;/* frames dropped for a bad CRC */
    uint32_t bad_length;/* headers with length > LINK_MAX_PAYLOAD */
    uint32_t junk_bytes;/* bytes skipped while looking for sync */
    uint32_t seq_gaps;  /* frames whose seq was not last+1 */
    uint32_t stalls;    /* partial frames given up by link_decoder_unstick */
};

struct link_decoder {
    uint8_t buf[LINK_MAX_FRAME]; /* the frame being assembled */
    size_t have;                 /* bytes of it so far */
    size_t delivered;            /* bytes of buf that made the frame last delivered;
                                    bytes after them (found while resynchronising)
                                    are kept for the next push */
    int seq_known;               /* a frame has been seen, next_seq is valid */
    uint16_t next_seq;           /* seq expected next */
    struct link_stats stats;
};

/* A decoded frame; payload points into the decoder and is valid until the
 * next push. */
struct link_frame {
    uint8_t type, flags;
    uint16_t seq, length;
    const uint8_t *payload;
};

void link_decoder_init(struct link_decoder *d);

/* Returns 1 and fills *f when b completes a good frame, else 0. */
int link_decoder_push(struct link_decoder *d, uint8_t b, struct link_frame *f);

/* For a receiver whose line went quiet in the middle of a frame (a damaged
 * length field makes the decoder wait for bytes that never come): gives up
 * the partial frame's first byte and rescans the rest for sync.  Returns 1
 * and fills *f when a good frame was waiting behind it, else 0.  Call it
 * again until it returns 0 and no partial frame is left (d->have). */
int link_decoder_unstick(struct link_decoder *d, struct link_frame *f);

/* ---- payload encodings ---- */
void link_hello_put(uint8_t *p, const struct link_hello *h);
void link_hello_get(const uint8_t *p, struct link_hello *h);
void link_fault_put(uint8_t *p, const struct link_fault *f);
void link_fault_get(const uint8_t *p, struct link_fault *f);

#endif
