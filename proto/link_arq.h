/* link_arq.h: stop-and-wait retransmission for the host link (issue 12,
 * "the host link survives noise").  One definition for both ends; the
 * firmware and the host tool drive it with their own clocks.
 *
 * Each direction numbers its frames (the seq of proto/hostlink.h).  The
 * sender keeps the one frame not yet acknowledged (struct link_arq_tx) and
 * sends it again when the receiver answers LINK_NAK for its seq, or when no
 * LINK_ACK came within the timeout; after LINK_ARQ_MAX_TRIES sends it gives
 * up and its caller ends the transfer with an error naming the frame.  The
 * receiver (struct link_arq_rx) takes a frame with the seq it expects,
 * answers a repeat of the frame it took last with its ACK again and drops
 * it, and answers anything else, or a damaged frame (the decoder counted a
 * CRC or length error), with a NAK naming the seq it expects.  Frames are
 * CRC-32 checked, so a frame is either taken exactly once, bit-exact, or
 * the sender gives up: never wrong data.
 *
 * LINK_ACK / LINK_NAK payload: u16 seq (LINK_ACK_SIZE bytes). */
#ifndef LINKS1_PROTO_LINK_ARQ_H
#define LINKS1_PROTO_LINK_ARQ_H

#include <stddef.h>
#include <stdint.h>

#include "proto/hostlink.h"

#define LINK_NAK 10            /* frame type: u16 seq the receiver expects */
#define LINK_ARQ_MAX_TRIES 64  /* sends of one frame before the sender gives up: a
                               * 1 KiB DATA frame crosses whole at 1e-3 a third of
                               * the time, so 64 tries fail once in ~1e12 */

struct link_arq_tx {
    uint8_t frame[LINK_MAX_FRAME]; /* the frame not yet acknowledged, encoded */
    size_t size;                   /* its bytes; 0 when none is pending */
    uint16_t next_seq;             /* seq of the next new frame */
    uint16_t seq;                  /* seq of the pending frame */
    unsigned tries;                /* times it was sent */
    uint64_t timeout;              /* wait for its ACK, in the caller's clock units */
    uint64_t deadline;             /* when to send it again */
    uint32_t resends;              /* frames sent again, in total */
};

enum link_arq_action {
    LINK_ARQ_IDLE = 0,    /* nothing pending */
    LINK_ARQ_WAIT = 1,    /* a frame waits for its ACK */
    LINK_ARQ_RESEND = 2,  /* send tx->frame (tx->size bytes) again now */
    LINK_ARQ_GIVE_UP = 3, /* LINK_ARQ_MAX_TRIES sends and no ACK: an error */
};

void link_arq_tx_init(struct link_arq_tx *t, uint16_t first_seq, uint64_t timeout);

/* Encodes a new frame into t->frame and makes it the pending one; returns
 * its size (send t->frame now), or 0 when a frame is still pending or the
 * payload is too long. */
size_t link_arq_tx_frame(struct link_arq_tx *t, uint8_t type, uint8_t flags,
                         const void *payload, size_t len, uint64_t now);

/* A LINK_ACK or LINK_NAK from the receiver.  Returns LINK_ARQ_IDLE when it
 * acknowledged the pending frame, LINK_ARQ_RESEND when a NAK asks for it
 * again, LINK_ARQ_GIVE_UP when that was its last try, else LINK_ARQ_WAIT
 * (an answer about another frame: stale, ignored). */
enum link_arq_action link_arq_tx_answer(struct link_arq_tx *t, const struct link_frame *f,
                                        uint64_t now);

/* What the sender must do at time now (send again at the timeout). */
enum link_arq_action link_arq_tx_poll(struct link_arq_tx *t, uint64_t now);

struct link_arq_rx {
    int known;       /* a frame was taken: expect is valid */
    uint16_t expect; /* seq of the next new frame */
};

enum link_arq_verdict {
    LINK_ARQ_NEW = 0,   /* take the frame, answer ACK seq */
    LINK_ARQ_DUP = 1,   /* the last frame again: answer ACK seq, drop it */
    LINK_ARQ_OTHER = 2, /* not the one expected: answer NAK expect, drop it */
};

void link_arq_rx_init(struct link_arq_rx *r);

/* The verdict on a good (CRC-checked) frame; a frame flagged
 * LINK_FLAG_SESSION starts the numbering again and is always new. */
enum link_arq_verdict link_arq_rx_take(struct link_arq_rx *r, const struct link_frame *f);

/* Encodes the receiver's answer (LINK_ACK or LINK_NAK with u16 seq) into
 * out; returns its size. */
size_t link_arq_answer_encode(uint8_t *out, size_t cap, uint8_t type, uint16_t frame_seq,
                              uint16_t about);

#endif
