/* dm.h: what the parts of the DM program share (roles/dm.c: tasks and
 * command dispatch; roles/dm_checks.c: line and IMSU checks;
 * roles/dm_transfer.c: host-link bulk transfers). */
#ifndef LINKS1_ROLES_DM_H
#define LINKS1_ROLES_DM_H

#include <stdint.h>

#include "drivers/serial/linemsg.h"
#include "proto/hostlink.h"

/* A host frame taken from the queue. */
struct dm_frame {
    uint8_t type, flags;
    uint16_t seq, length;
    uint8_t payload[LINK_MAX_PAYLOAD];
};

extern struct dm_frame dm_frame;  /* the frame the command task works on */
extern struct line_msg dm_msg;    /* the DM's line message buffer */
extern uint32_t dm_link_errors;   /* host -> board frames dropped so far */

/* Takes the next queued host frame into dm_frame; 0, or -1 at deadline. */
int dm_next_frame(uint64_t deadline);
/* In a transfer: when dm_frame opens a new host session (LINK_FLAG_SESSION:
 * the transfer's host went away), answers cmd's error, keeps the frame for
 * the next dm_next_frame and returns 1; else 0. */
int dm_session_interrupts(uint16_t cmd);
/* Sends m to the RC and waits for its answer of answer_type into m. */
int dm_rc_request(struct line_msg *m, uint16_t answer_type, uint32_t timeout_ms);

/* Bulk transfers over the host link with DATA/ACK flow control
 * (proto/hostlink.h), for the link tests and for later uploads (scenes)
 * and downloads (frames).  On failure they have already sent the command's
 * error LINK_RESULT, naming the problem, and return its negative status;
 * on success the caller sends the result.
 *
 * Receive: hands each chunk to fn (offset = bytes before it); a non-zero
 * return refuses the transfer (the rest is still taken and ACKed, then
 * LINK_ERR_CHECK returned; fn must have reported why, or the caller does).
 * Send: fn fills each chunk of n bytes at offset; total bytes in all. */
typedef int (*dm_chunk_in_fn)(void *ctx, const uint8_t *data, uint32_t n, uint64_t offset);
typedef void (*dm_chunk_out_fn)(void *ctx, uint8_t *data, uint32_t n, uint32_t offset);
int dm_transfer_receive(uint16_t cmd, dm_chunk_in_fn fn, void *ctx, uint64_t *bytes,
                        uint32_t *crc);
int dm_transfer_send(uint16_t cmd, dm_chunk_out_fn fn, void *ctx, uint32_t total,
                     uint32_t *crc);

/* The shared-memory path (roles/dm_bulk.c, proto/hostlink.h LINK_BULK).
 * dm_bulk_path: the path byte after a command's args bytes of arguments
 * (absent: LINK_PATH_SERIAL); -1 after answering an error for a bad one.
 * dm_bulk_receive: offers room bytes at buf to the host, waits for its
 * LINK_BULK, checks it and its word sum (proto/wordsum.h) and ACKs it;
 * LINK_OK with *len and *tail_sum, the word sum of the bytes from split on
 * (a multiple of 4; 0: all of them; past the end: none), which the one
 * pass over the bytes gives too, or the negative status of the error it
 * has already answered.
 * dm_bulk_send: tells the host len bytes at buf are there; returns their
 * word sum. */
extern uint64_t dm_bulk_check_ticks; /* the last dm_bulk_receive's time summing */
int dm_bulk_path(uint16_t cmd, uint32_t args);
int dm_bulk_receive(uint16_t cmd, uint8_t *buf, uint32_t room, uint32_t split, uint32_t *len,
                    uint32_t *tail_sum);
uint32_t dm_bulk_send(const void *buf, uint32_t len);

/* Command handlers: each answers with one LINK_RESULT. */
void dm_cmd_line_ping(uint16_t cmd);
void dm_cmd_line_latency(uint16_t cmd);
void dm_cmd_imsu_test(uint16_t cmd);
void dm_cmd_line_stress(uint16_t cmd);
void dm_cmd_link_sink(uint16_t cmd);
void dm_cmd_link_source(uint16_t cmd);

#endif
