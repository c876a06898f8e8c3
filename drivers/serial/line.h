/* line.h: the inter-unit serial lines of LINKS-1: point-to-point message
 * channels DM<->RC and RC<->each NC.
 *
 * A line is two single-producer single-consumer rings in shared memory
 * (carved by linker/virt-memory.ld), one per direction, plus a doorbell:
 * the SGI_DOORBELL interrupt to the other end.  To avoid an interrupt per
 * message, a receiver that finds its ring empty (or a sender that finds it
 * full) raises a "waiting" flag before it sleeps, and the other end rings
 * the doorbell only when it sees the flag.  Both sides put a full barrier
 * between their ring update and their look at the other's flag, so one of
 * the two always sees the other: no wake-up is lost.
 *
 * Every message carries a per-direction sequence number (set by the line)
 * and a crc32 of its payload (drivers/serial/linemsg.h); the receiver checks
 * both, so a lost, repeated, reordered or damaged message is reported, not
 * passed on silently.
 *
 * Calls name the other end by core number; a core may only use lines it
 * is an end of.  Each direction has one sender task and one receiver task. */
#ifndef LINKS1_DRIVERS_SERIAL_LINE_H
#define LINKS1_DRIVERS_SERIAL_LINE_H

#include <stdint.h>

#include "drivers/serial/linemsg.h"

enum line_status {
    LINE_OK = 0,
    LINE_ERR_NO_LINE = -1, /* no line between this core and that one */
    LINE_ERR_FULL = -2,    /* try_send: no room now */
    LINE_ERR_EMPTY = -3,   /* try_recv: nothing there */
    LINE_ERR_TIMEOUT = -4, /* blocking call: deadline passed */
    LINE_ERR_TOO_LONG = -5,/* payload longer than LINE_MAX_PAYLOAD */
    LINE_ERR_CHECK = -6,   /* received, but its crc32 did not match */
    LINE_ERR_SEQ = -7,     /* received, but not the sequence number expected */
};

/* Core 0, before waking the others: sets up every line of the board. */
void line_init_all(uint32_t ncores);
/* Number of lines on the board (ncores - 1). */
uint32_t line_count(void);

int line_try_send(uint32_t peer, struct line_msg *m);
int line_try_recv(uint32_t peer, struct line_msg *m);
/* 1 if a message from peer waits to be taken (nothing taken or armed). */
int line_recv_ready(uint32_t peer);
/* Blocking forms: wait (sleeping) until done or deadline (ticks, 0 = none). */
int line_send(uint32_t peer, struct line_msg *m, uint64_t deadline);
int line_recv(uint32_t peer, struct line_msg *m, uint64_t deadline);

/* A line as this core sees it, looked up once (line_end_of: LINE_OK, or
 * LINE_ERR_NO_LINE) by a task that moves many messages on it (the RC, a
 * line per NC); the calls below by peer look it up per message. */
struct line_dir;
struct line_end {
    struct line_dir *out, *in; /* the directions this core sends and takes on */
    uint32_t me, peer;
};
int line_end_of(uint32_t peer, struct line_end *e);
int line_end_try_send(const struct line_end *e, struct line_msg *m);
/* line_try_recv_arm and line_recv_ready_arm (below) on a line looked up. */
int line_end_try_recv_arm(const struct line_end *e, struct line_msg *m, int *ready);
int line_end_recv_ready_arm(const struct line_end *e);

/* For a task serving several lines at once: raise the waiting flag for a
 * direction, then tell whether it is ready already (a message to take, or
 * room for a message of len payload bytes).  If none is ready, task_wait()
 * with a mark taken before the calls sleeps until a doorbell. */
int line_recv_ready_arm(uint32_t peer);
int line_send_ready_arm(uint32_t peer, uint32_t len);
/* line_try_recv, then line_recv_ready_arm, with one look-up of the line (a
 * task serving many lines takes a message and re-arms per request): the
 * status of the take; *ready whether a message is there after it. */
int line_try_recv_arm(uint32_t peer, struct line_msg *m, int *ready);

/* For the task that serves many lines without looking at each (the RC and
 * its NCs; every line has the RC at one end): every message sent to the
 * RC sets the sender's bit in the RC's pending map (one sent to another
 * core sets none: it has one line).  On the RC, line_pending_take(w)
 * returns and clears the bits of senders
 * 32w..32w+31 (a bit: look at that line; it may hold more than one message,
 * or none if it was taken by other calls); line_pending_mark(peer) sets a
 * bit again, for a line still holding messages after one was taken. */
#define LINE_PENDING_WORDS ((UNITS_MAX_CORES + 31u) / 32u)
uint32_t line_pending_take(uint32_t word);
void line_pending_mark(uint32_t peer);

const char *line_strerror(int status);

#endif
