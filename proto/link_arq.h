/* link_arq.h: retransmission for the host link (docs/host-link.md, "the
 * host link survives noise").  One definition for both ends; the firmware
 * and the host tool drive it with their own clocks.
 *
 * Go-back-N (below): every numbered frame is kept for resending, the
 * receiver takes only the seq it expects (struct link_arq_rx) and NAKs a
 * gap, a silent sender is polled.  Each direction numbers its frames (the
 * seq of proto/hostlink.h).  Frames are CRC-32 checked, so a frame is
 * either taken exactly once, bit-exact, or the transfer ends with an error
 * naming the frame: never wrong data.
 *
 * LINK_ACK / LINK_NAK payload: u16 seq (LINK_ACK_SIZE bytes). */
#ifndef LINKS1_PROTO_LINK_ARQ_H
#define LINKS1_PROTO_LINK_ARQ_H

#include <stddef.h>
#include <stdint.h>

#include "proto/hostlink.h"

#define LINK_ARQ_MAX_TRIES 64  /* polls in a row with nothing heard before the host
                               * gives up (LINK_ARQ_POLL_MS apart: 16 s) */

struct link_arq_rx {
    int known;       /* a frame was taken: expect is valid */
    uint16_t expect; /* seq of the next new frame */
};

enum link_arq_verdict {
    LINK_ARQ_NEW = 0,   /* take the frame, answer ACK seq */
    LINK_ARQ_DUP = 1,   /* a frame already taken (seq behind expect): drop it
                         */
    LINK_ARQ_OTHER = 2, /* ahead of the one expected: answer NAK expect, drop it */
};

void link_arq_rx_init(struct link_arq_rx *r);

/* The verdict on a good (CRC-checked) frame; a frame flagged
 * LINK_FLAG_SESSION starts the numbering again and is always new. */
enum link_arq_verdict link_arq_rx_take(struct link_arq_rx *r, const struct link_frame *f);

/* Encodes the receiver's answer (LINK_ACK or LINK_NAK with u16 seq) into
 * out; returns its size. */
size_t link_arq_answer_encode(uint8_t *out, size_t cap, uint8_t type, uint16_t frame_seq,
                              uint16_t about);

/* ---- the wired link: go-back-N ----
 *
 * Every numbered frame a side sends is kept in its struct link_arq_store
 * until newer frames push it out.  The receiver takes frames in seq order
 * only (link_arq_rx_take); on a frame ahead of the one it expects, or a
 * damaged frame, it sends LINK_NAK with the seq it expects (at most once per
 * LINK_ARQ_NAK_MS for the same seq, struct link_arq_nak), and the sender
 * resends the frames it holds from that seq on (up to LINK_ARQ_RESEND_BYTES).  A side that waits and
 * hears nothing for LINK_ARQ_POLL_MS sends LINK_NAK flagged LINK_FLAG_POLL:
 * the other side resends from the seq named and answers with a LINK_NAK of
 * its own expected seq, so a lost last frame in either direction is sent
 * again.  Only the host polls, and only once it has seen damage, so a clean
 * link never carries a poll.  A NAK for a seq the sender no longer holds is answered with
 * LINK_NAK flagged LINK_FLAG_GONE: the transfer ends with an error.  Frames
 * are CRC-checked and taken once each in order, so the layers above see
 * the exact stream or an error, never wrong data, and a repeated command is
 * never carried out twice. */
#define LINK_ARQ_STORE_BYTES (64 * 1024) /* bytes of frames kept for resending */
#define LINK_ARQ_STORE_FRAMES 256        /* frames kept at most (a power of two) */
#define LINK_ARQ_NAK_MS 100    /* a NAK for the same seq again no sooner than this */
#define LINK_ARQ_RESEND_BYTES (6 * 1024) /* a NAK's resend stops after the frame
                                * that reaches this many bytes: a DATA window and
                                * what came with it, ~20..60 ms of the line, shorter
                                * than LINK_ARQ_NAK_MS, so repeated NAKs cannot stack
                                * resends faster than the line drains them; frames
                                * after it are asked for by the next NAK or poll */
#define LINK_ARQ_MAX_ASKS 48   /* NAKs in a row for one seq before the receiver gives
                                * up (~5 s): a 1 KiB frame crosses whole at 1e-3 per
                                * byte a third of the time, so 48 fail once in ~1e9 */
#define LINK_ARQ_POLL_MS 250   /* a waiting side's silence before it polls */
#define LINK_ARQ_STALL_MS 2000 /* the host: a partial frame this long without a
                                * byte, on a link seen damaged, is damage (its
                                * length field spoilt): it polls from then on */
#define LINK_ARQ_STALL_CLEAN_MS 10000 /* the same on a link never seen damaged:
                                       * long, so a busy emulator's pause (a vCPU
                                       * not run for seconds mid-frame while 66
                                       * boot) is not taken for damage */
#define LINK_ARQ_FLUSH_BYTES LINK_MAX_FRAME /* zero bytes the host sends before a
                                * poll: they complete a partial frame whose damaged
                                * length field keeps the board's decoder waiting (it
                                * then fails its CRC and is asked for again); the
                                * board needs no timer, so a busy emulator's pause is
                                * never taken for a stall */

struct link_arq_store {
    uint8_t bytes[LINK_ARQ_STORE_BYTES]; /* frames, one after another, wrapping */
    uint64_t pos;                        /* bytes ever put */
    struct {
        uint64_t pos;  /* where the frame starts, in bytes ever put */
        uint16_t size; /* its bytes (0: none) */
        uint16_t seq;
    } idx[LINK_ARQ_STORE_FRAMES];        /* by seq % LINK_ARQ_STORE_FRAMES */
    uint16_t next_seq;                   /* seq of the next frame put */
    uint32_t held;                       /* frames put, at most LINK_ARQ_STORE_FRAMES */
};

void link_arq_store_init(struct link_arq_store *s, uint16_t first_seq);

/* Encodes the next numbered frame (seq s->next_seq) into out and keeps a
 * copy; returns its size (send out now), or 0 when the payload is too long
 * or out too small. */
size_t link_arq_store_frame(struct link_arq_store *s, uint8_t *out, size_t cap, uint8_t type,
                            uint8_t flags, const void *payload, size_t len);

/* Frames to resend for a NAK of seq from: the count from `from` to the
 * newest (0 when from is the next seq, nothing to resend), or -1 when frame
 * `from` is not held (pushed out, or never sent). */
int link_arq_store_span(const struct link_arq_store *s, uint16_t from);

/* The frames of a NAK's resend from `from`: span (link_arq_store_span)
 * cut after the frame that reaches LINK_ARQ_RESEND_BYTES. */
int link_arq_store_resend_count(const struct link_arq_store *s, uint16_t from, int span);

/* Copies the kept frame seq into out; returns its size, 0 if not held. */
size_t link_arq_store_get(const struct link_arq_store *s, uint16_t seq, uint8_t *out,
                          size_t cap);

/* The NAK rate limit of a receiver (and its give-up count). */
struct link_arq_nak {
    int sent;        /* a NAK was sent: seq and at are valid */
    uint16_t seq;    /* the seq it named */
    uint64_t at;     /* when, in the caller's clock (ms) */
    unsigned tries;  /* NAKs sent for seq in a row */
};

/* 1 when a NAK for expect is due at now (none for it in the last gap),
 * recording it as sent; else 0. */
int link_arq_nak_due(struct link_arq_nak *n, uint16_t expect, uint64_t now, uint64_t gap);

/* Encodes a LINK_NAK (unnumbered: seq 0) naming expect, with flags
 * (LINK_FLAG_POLL, LINK_FLAG_GONE); returns its size. */
size_t link_arq_nak_encode(uint8_t *out, size_t cap, uint8_t flags, uint16_t expect);

#endif
