/* dc_ring.h: the data collector's FIFO: many producers (the NCs), one
 * consumer (the unit computer that writes the frame memory).
 *
 * Lock-free, bounded, never drops: a ring of DC_RING_SLOTS slots, each with
 * a sequence number saying whose turn it is (slot i of lap L is free for
 * the producer at position L*SLOTS + i when seq == that position, and full
 * for the consumer when seq == position + 1).
 *   - A producer claims a position by compare-and-swap on head, copies its
 *     run into the slot, then publishes it with a release store of seq.
 *   - The consumer reads seq with an acquire load, so the run's bytes the
 *     producer copied before its release are visible; it copies the run out
 *     and hands the slot to the next lap with a release store of seq, so its
 *     reads are done before any producer may overwrite the slot.
 * A full ring makes try_push fail; the producer then waits (dc.h) and
 * retries: nothing is dropped.  A producer that claimed a position but has
 * not published it yet holds up the consumer at that slot only until it
 * publishes (a copy of at most DC_RUN_MAX_PIXELS words).
 *
 * Sleeping without lost wake-ups (the protocol of drivers/serial/line.h):
 * a side that finds nothing to do raises its "waiting" flag, then a full
 * barrier, then looks again (dc_ring_*_arm returns whether it can go on);
 * the other side, after its own ring update, a full barrier, then takes
 * the flags it finds raised and wakes those waiters.  One of the two
 * always sees the other.  The consumer has one flag; producers have one
 * bit each in a bitmap, indexed by producer id (core number).
 *
 * No hardware access (GCC __atomic builtins only): the host tests run it
 * with threads. */
#ifndef LINKS1_DRIVERS_FRAMEMEM_DC_RING_H
#define LINKS1_DRIVERS_FRAMEMEM_DC_RING_H

#include <stdint.h>

#include "drivers/framemem/fm_param.h"

#define DC_WAIT_WORDS ((DC_MAX_PRODUCERS + 31u) / 32u)

enum dc_status {
    DC_OK = 0,
    DC_ERR_FULL = -1,    /* try_push: no free slot now */
    DC_ERR_EMPTY = -2,   /* try_pop: no published run now */
    DC_ERR_RUN = -3,     /* run with 0 or more than DC_RUN_MAX_PIXELS pixels,
                          * or (dc_run_pack) starting outside FM_MAX_* */
    DC_ERR_SLOTS = -4,   /* slot count not a power of two >= 2 */
    DC_ERR_PRODUCER = -5,/* producer id >= DC_MAX_PRODUCERS */
};

/* A run of finished pixels on one scanline, packed 0x00RRGGBB (fm.h). */
struct dc_run {
    uint16_t x, y;     /* first pixel */
    uint16_t n;        /* pixels, 1..DC_RUN_MAX_PIXELS */
    uint16_t producer; /* who pushed it (core number), for statistics */
    uint32_t px[DC_RUN_MAX_PIXELS];
};

struct dc_slot {
    uint32_t seq;      /* turn number, see above */
    struct dc_run run;
};

struct dc_ring {
    struct dc_slot *slots;
    uint32_t mask;     /* slots - 1 */
    uint32_t head;     /* next position to claim (producers, CAS) */
    uint32_t tail;     /* next position to take (consumer only) */
    uint32_t consumer_waiting;               /* flag, see above */
    uint32_t producer_waiting[DC_WAIT_WORDS]; /* bitmap, see above */
    uint32_t full_waits; /* producer_arm calls: how often the FIFO filled */
};

/* slots: nslots entries (power of two), owned by the ring from now on. */
int dc_ring_init(struct dc_ring *r, struct dc_slot *slots, uint32_t nslots);

/* Producer: copies run in (only its n pixels).  On DC_OK, *wake_consumer
 * is 1 if the consumer was waiting and must be woken by the caller. */
int dc_ring_try_push(struct dc_ring *r, const struct dc_run *run, int *wake_consumer);
/* Producer about to sleep on a full ring: raises its bit; returns 1 if a
 * slot is free after all (retry instead of sleeping). */
int dc_ring_producer_arm(struct dc_ring *r, uint32_t producer);

/* Consumer: copies the oldest run out (its header and n pixels). */
int dc_ring_try_pop(struct dc_ring *r, struct dc_run *out);
/* Consumer about to sleep on an empty ring: raises its flag; returns 1 if
 * a run is ready after all. */
int dc_ring_consumer_arm(struct dc_ring *r);
/* Consumer, after popping: clears the raised producer bits and calls
 * wake(id, ctx) for each.  Returns how many it woke. */
uint32_t dc_ring_wake_producers(struct dc_ring *r, void (*wake)(uint32_t id, void *ctx),
                                void *ctx);

/* Consumer, once no producer will push again (each has stopped or failed):
 * if the oldest claimed position was never published (its producer failed
 * between claiming and publishing), gives it up so the positions after it
 * can be taken, and returns 1; 0 if there is none to give up. */
int dc_ring_skip_abandoned(struct dc_ring *r);

/* Fills run from n r,g,b byte triples (the renderer's rgb8_t array). */
int dc_run_pack(struct dc_run *run, uint32_t x, uint32_t y, const uint8_t *rgb, uint32_t n);

const char *dc_strerror(int status);

#endif
