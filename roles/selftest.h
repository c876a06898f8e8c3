/* selftest.h: the pieces of the bring-up tests the roles share: test
 * patterns, the inter-unit stress streams, and faults on purpose. */
#ifndef LINKS1_ROLES_SELFTEST_H
#define LINKS1_ROLES_SELFTEST_H

#include <stddef.h>
#include <stdint.h>

#include "drivers/serial/linemsg.h"

/* Fills / checks n bytes (a multiple of 4) with the pattern of (seed, seq);
 * check returns the number of words that differ. */
void selftest_fill(uint8_t *p, size_t n, uint32_t seed, uint32_t seq);
uint32_t selftest_check(const uint8_t *p, size_t n, uint32_t seed, uint32_t seq);

/* The firmware's memcpy and memset (kernel/mem.c) against a byte at a
 * time, in scratch (SELFTEST_MEM_SCRATCH bytes, word-aligned): every
 * length to 300, then every seventh to 1,100, and two long ones, at
 * destination and source offsets aligned, word-aligned and not; each copy
 * and fill must change exactly its bytes.  Returns the cases wrong (0 when
 * all are right) out of *cases, the first wrong one in *first ("memcpy
 * 301 bytes, offsets 1 and 0"). */
#define SELFTEST_MEM_LONG 65539
/* a buffer: the longest case, its offset and margin, to a multiple of 8 */
#define SELFTEST_MEM_BUFFER ((SELFTEST_MEM_LONG + 32 + 7) / 8 * 8)
#define SELFTEST_MEM_SCRATCH (2 * SELFTEST_MEM_BUFFER)
uint32_t selftest_mem(uint8_t *scratch, uint32_t *cases, char *first, size_t cap);

/* One stress stream: messages to send to, or receive from, one peer. */
struct selftest_stream {
    uint32_t peer;      /* the other core */
    int sending;        /* 1 send, 0 receive */
    uint32_t left;      /* messages still to go */
    uint32_t seq;       /* next message number (pattern and order check) */
    uint64_t bytes;     /* payload bytes moved (received ones checked) */
    uint32_t errors;    /* bad crc, wrong order, wrong content, wrong type */
};

void selftest_stream_init(struct selftest_stream *s, uint32_t peer, int sending,
                        uint32_t msgs);
/* Steps every stream with non-blocking line calls until all are done,
 * sleeping on the doorbell when none can move.  Returns 0, or -1 if nothing
 * moved for STRESS_STALL_MS (a peer died): the streams say how far they got. */
int selftest_stress_run(struct selftest_stream *s, uint32_t n);

/* Makes this core fault now with enum link_fault_kind kind, or one of the
 * FAULT_INJECT_* spinlock misuses; never returns. */
void selftest_fault_now(uint8_t kind) __attribute__((noreturn));
/* The failure of the render test hook (proto/render_link.h, enum
 * link_inject_kind): this core fails as a real one would and says nothing
 * about it; returns only for an unknown kind (logged). */
void selftest_fail_on_purpose(uint8_t kind);
/* 1 if kind is one selftest_fault_now knows. */
int selftest_fault_kind_valid(uint8_t kind);

/* Small helpers for message payloads. */
void selftest_msg_set(struct line_msg *m, uint16_t type, uint16_t len);

/* Receives from peer until a message of the given type comes (others are
 * logged and dropped: late answers of an earlier, timed-out request).
 * Returns LINE_OK or the line error (LINE_ERR_TIMEOUT at deadline). */
int selftest_recv_type(uint32_t peer, uint16_t type, struct line_msg *m,
                       uint64_t deadline);

/* rounds (1..LINK_LATENCY_MAX_ROUNDS) MSG_PING round trips with peer, one
 * after another, each timed in ktime ticks from the send to its MSG_PONG;
 * their min, median and max into mmm[0..2] and the rounds done into *done.
 * Returns LINE_OK, or the line error of the round that failed (a wrong
 * token counts as LINE_ERR_CHECK). */
int selftest_latency(uint32_t peer, uint32_t rounds, struct line_msg *m, uint32_t *done,
                     uint32_t mmm[3]);

#endif
