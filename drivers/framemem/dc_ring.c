/* dc_ring.c: the data collector's lock-free FIFO (see dc_ring.h for the
 * protocol and its memory ordering). */
#include "drivers/framemem/dc_ring.h"

#include "drivers/framemem/fm.h"

#include <stddef.h>
#include <string.h>

/* Bytes of a run that carry data: the header and its n pixels. */
static size_t dc_run_bytes(uint32_t n)
{
    return offsetof(struct dc_run, px) + (size_t)n * sizeof(uint32_t);
}

int dc_ring_init(struct dc_ring *r, struct dc_slot *slots, uint32_t nslots)
{
    memset(r, 0, sizeof *r);
    if (nslots < 2 || (nslots & (nslots - 1)) != 0)
        return DC_ERR_SLOTS;
    r->slots = slots;
    r->mask = nslots - 1;
    for (uint32_t i = 0; i < nslots; i++)
        slots[i].seq = i; /* free for the producer at position i */
    /* Publish the initialised ring before any other core may use it. */
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    return DC_OK;
}

int dc_ring_try_push(struct dc_ring *r, const struct dc_run *run, int *wake_consumer)
{
    *wake_consumer = 0;
    if (run->n == 0 || run->n > DC_RUN_MAX_PIXELS)
        return DC_ERR_RUN;
    uint32_t pos = __atomic_load_n(&r->head, __ATOMIC_RELAXED);
    struct dc_slot *slot;
    for (;;) {
        slot = &r->slots[pos & r->mask];
        /* Acquire: if the slot is free, the consumer's reads of its previous
         * run are done before we overwrite it. */
        uint32_t seq = __atomic_load_n(&slot->seq, __ATOMIC_ACQUIRE);
        int32_t lag = (int32_t)(seq - pos);
        if (lag == 0) {
            /* Free for position pos: claim it.  Relaxed is enough, the
             * slot's seq carries the ordering; on failure pos is reloaded. */
            if (__atomic_compare_exchange_n(&r->head, &pos, pos + 1, 1, __ATOMIC_RELAXED,
                                            __ATOMIC_RELAXED))
                break;
        } else if (lag < 0) {
            return DC_ERR_FULL; /* still holds the run of the previous lap */
        } else {
            pos = __atomic_load_n(&r->head, __ATOMIC_RELAXED); /* overtaken */
        }
    }
    memcpy(&slot->run, run, dc_run_bytes(run->n));
    /* Release: the run's bytes are visible before the slot reads full. */
    __atomic_store_n(&slot->seq, pos + 1, __ATOMIC_RELEASE);
    /* Full barrier between publishing and looking at the consumer's flag
     * (see the wake-up protocol in dc_ring.h). */
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    if (__atomic_load_n(&r->consumer_waiting, __ATOMIC_RELAXED) &&
        __atomic_exchange_n(&r->consumer_waiting, 0u, __ATOMIC_RELAXED))
        *wake_consumer = 1;
    return DC_OK;
}

/* 1 if the slot at head is free for it (the next push would succeed unless
 * another producer takes it first). */
static int dc_ring_has_room(struct dc_ring *r)
{
    uint32_t pos = __atomic_load_n(&r->head, __ATOMIC_RELAXED);
    uint32_t seq = __atomic_load_n(&r->slots[pos & r->mask].seq, __ATOMIC_ACQUIRE);
    return (int32_t)(seq - pos) >= 0;
}

int dc_ring_producer_arm(struct dc_ring *r, uint32_t producer)
{
    if (producer >= DC_MAX_PRODUCERS)
        return DC_ERR_PRODUCER;
    uint32_t bit = 1u << (producer % 32u);
    uint32_t *word = &r->producer_waiting[producer / 32u];
    __atomic_fetch_add(&r->full_waits, 1u, __ATOMIC_RELAXED);
    __atomic_fetch_or(word, bit, __ATOMIC_RELAXED);
    /* Full barrier between raising the bit and looking at the ring. */
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    if (dc_ring_has_room(r)) {
        __atomic_fetch_and(word, ~bit, __ATOMIC_RELAXED);
        return 1;
    }
    return 0;
}

int dc_ring_try_pop(struct dc_ring *r, struct dc_run *out)
{
    uint32_t pos = r->tail;
    struct dc_slot *slot = &r->slots[pos & r->mask];
    /* Acquire: the producer's copy is visible once seq says full. */
    uint32_t seq = __atomic_load_n(&slot->seq, __ATOMIC_ACQUIRE);
    if (seq != pos + 1)
        return DC_ERR_EMPTY;
    uint32_t n = slot->run.n;
    if (n > DC_RUN_MAX_PIXELS)
        n = DC_RUN_MAX_PIXELS; /* cannot happen (checked at push); bounds the copy */
    memcpy(out, &slot->run, dc_run_bytes(n));
    /* Release: our reads are done before the slot reads free for the
     * producer of the next lap. */
    __atomic_store_n(&slot->seq, pos + r->mask + 1, __ATOMIC_RELEASE);
    r->tail = pos + 1;
    return DC_OK;
}

int dc_ring_consumer_arm(struct dc_ring *r)
{
    __atomic_store_n(&r->consumer_waiting, 1u, __ATOMIC_RELAXED);
    /* Full barrier between raising the flag and looking at the ring. */
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    uint32_t pos = r->tail;
    if (__atomic_load_n(&r->slots[pos & r->mask].seq, __ATOMIC_ACQUIRE) == pos + 1) {
        __atomic_store_n(&r->consumer_waiting, 0u, __ATOMIC_RELAXED);
        return 1;
    }
    return 0;
}

int dc_ring_skip_abandoned(struct dc_ring *r)
{
    uint32_t pos = r->tail;
    if (pos == __atomic_load_n(&r->head, __ATOMIC_ACQUIRE))
        return 0;
    struct dc_slot *slot = &r->slots[pos & r->mask];
    if (__atomic_load_n(&slot->seq, __ATOMIC_ACQUIRE) == pos + 1)
        return 0; /* published: dc_ring_try_pop takes it */
    __atomic_store_n(&slot->seq, pos + r->mask + 1, __ATOMIC_RELEASE);
    r->tail = pos + 1;
    return 1;
}

uint32_t dc_ring_wake_producers(struct dc_ring *r, void (*wake)(uint32_t id, void *ctx),
                                void *ctx)
{
    uint32_t woken = 0;
    /* Full barrier between the slot frees of try_pop and looking at the
     * producers' bits. */
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    for (uint32_t w = 0; w < DC_WAIT_WORDS; w++) {
        if (__atomic_load_n(&r->producer_waiting[w], __ATOMIC_RELAXED) == 0)
            continue;
        uint32_t bits = __atomic_exchange_n(&r->producer_waiting[w], 0u, __ATOMIC_RELAXED);
        while (bits != 0) {
            uint32_t b = (uint32_t)__builtin_ctz(bits);
            bits &= bits - 1;
            wake(w * 32u + b, ctx);
            woken++;
        }
    }
    return woken;
}

int dc_run_pack(struct dc_run *run, uint32_t x, uint32_t y, const uint8_t *rgb, uint32_t n)
{
    if (n == 0 || n > DC_RUN_MAX_PIXELS || x >= FM_MAX_WIDTH || y >= FM_MAX_HEIGHT)
        return DC_ERR_RUN; /* the FM bounds also keep x and y inside 16 bits */
    run->x = (uint16_t)x;
    run->y = (uint16_t)y;
    run->n = (uint16_t)n;
    run->producer = 0;
    for (uint32_t i = 0; i < n; i++)
        run->px[i] = fm_pack(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
    return DC_OK;
}

const char *dc_strerror(int status)
{
    switch (status) {
    case DC_OK:
        return "ok";
    case DC_ERR_FULL:
        return "data collector FIFO full";
    case DC_ERR_EMPTY:
        return "data collector FIFO empty";
    case DC_ERR_RUN:
        return "pixel run must hold 1..DC_RUN_MAX_PIXELS pixels and start inside the "
               "largest frame";
    case DC_ERR_SLOTS:
        return "data collector slot count must be a power of two >= 2";
    case DC_ERR_PRODUCER:
        return "producer id must be below DC_MAX_PRODUCERS";
    default:
        return "unknown data collector error";
    }
}
