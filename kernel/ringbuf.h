/* ringbuf.h: a single-producer, single-consumer byte ring.
 *
 * No hardware access, so the host tests build it.  The producer only
 * writes head, the consumer only writes tail; each publishes its index
 * with a release store and reads the other's with an acquire load, so the
 * bytes a put copied in are visible to the consumer before the new head is,
 * and the consumer is done reading bytes before the producer may reuse
 * them.  This makes it safe between two cores (the inter-unit lines) as
 * well as between an interrupt handler and a task on one core (the UART).
 *
 * Indices run freely modulo 2^32; size is a power of two, so used = head -
 * tail works across the wrap.  Puts and gets of a record are all or
 * nothing: a reader never sees half a message. */
#ifndef LINKS1_KERNEL_RINGBUF_H
#define LINKS1_KERNEL_RINGBUF_H

#include <stdint.h>

struct ringbuf {
    uint8_t *buf;  /* storage, size bytes */
    uint32_t size; /* power of two */
    uint32_t head; /* total bytes ever put (producer writes) */
    uint32_t tail; /* total bytes ever taken (consumer writes) */
};

/* Returns 0, or -1 if size is not a power of two >= 2. */
int ringbuf_init(struct ringbuf *r, uint8_t *buf, uint32_t size);
/* Bytes in the ring, and free (inline: a line asks per message). */
static inline uint32_t ringbuf_used(const struct ringbuf *r)
{
    uint32_t head = __atomic_load_n(&r->head, __ATOMIC_ACQUIRE);
    uint32_t tail = __atomic_load_n(&r->tail, __ATOMIC_ACQUIRE);
    return head - tail;
}
static inline uint32_t ringbuf_free(const struct ringbuf *r)
{
    return r->size - ringbuf_used(r);
}
/* Copies n bytes in; 0, or -1 (nothing written) if fewer than n are free. */
int ringbuf_put(struct ringbuf *r, const void *data, uint32_t n);
/* Copies n bytes out; 0, or -1 (nothing taken) if fewer than n are there. */
int ringbuf_get(struct ringbuf *r, void *out, uint32_t n);
/* Copies n bytes out without taking them; 0 or -1 as ringbuf_get. */
int ringbuf_peek(const struct ringbuf *r, void *out, uint32_t n);
/* Producer side, for byte streams: puts one byte; 0, or -1 if full. */
int ringbuf_put_byte(struct ringbuf *r, uint8_t b);
/* Takes up to max bytes; returns how many. */
uint32_t ringbuf_get_some(struct ringbuf *r, void *out, uint32_t max);

/* Word records (the inter-unit lines): a ring that only these touch holds
 * whole words, so head and tail stay multiples of 4 and no word straddles
 * the wrap (buf word-aligned, size a power of two >= 4).  Each word is one
 * load and one store, without the two pieces of a byte copy around the
 * wrap, and a record short of the end without the wrap's mask either: a
 * line message is a few words, and the RC moves two a request.
 * Inline: a call would cost as much as the copy. */
static inline uint32_t ringbuf_word_slot(const struct ringbuf *r, uint32_t byte_index)
{
    return (byte_index & (r->size - 1u)) / 4u;
}

/* Puts one record of na words at a, then nb at b (either may be unaligned
 * flat memory); 0, or -1 (nothing written) if fewer than 4 * (na + nb)
 * bytes are free. */
static inline int ringbuf_put_words(struct ringbuf *r, const void *a, uint32_t na,
                                    const void *b, uint32_t nb)
{
    uint32_t head = r->head; /* only we write it */
    uint32_t tail = __atomic_load_n(&r->tail, __ATOMIC_ACQUIRE);
    if ((r->size - (head - tail)) / 4u < na + nb)
        return -1;
    uint8_t *ring = r->buf;
    uint32_t mask = r->size / 4u - 1u, at = ringbuf_word_slot(r, head);
    if (at + na + nb <= mask + 1u) { /* no wrap: word after word */
        uint8_t *to = ring + 4u * at;
        for (uint32_t i = 0; i < na; i++, to += 4)
            __builtin_memcpy(to, (const uint8_t *)a + 4u * i, 4);
        for (uint32_t i = 0; i < nb; i++, to += 4)
            __builtin_memcpy(to, (const uint8_t *)b + 4u * i, 4);
    } else {
        for (uint32_t i = 0; i < na; i++, at = (at + 1u) & mask)
            __builtin_memcpy(ring + 4u * at, (const uint8_t *)a + 4u * i, 4);
        for (uint32_t i = 0; i < nb; i++, at = (at + 1u) & mask)
            __builtin_memcpy(ring + 4u * at, (const uint8_t *)b + 4u * i, 4);
    }
    /* Release: the words are in place before the consumer can see them. */
    __atomic_store_n(&r->head, head + 4u * (na + nb), __ATOMIC_RELEASE);
    return 0;
}

/* Consumer side: the words in the ring (one acquire of head: every word
 * counted is in place). */
static inline uint32_t ringbuf_words_in(const struct ringbuf *r)
{
    uint32_t head = __atomic_load_n(&r->head, __ATOMIC_ACQUIRE);
    return (head - r->tail) / 4u; /* tail: only we write it */
}

/* Copies n words out, starting skip words past the oldest, taking none:
 * the caller has seen skip + n words there (ringbuf_words_in). */
static inline void ringbuf_read_words(const struct ringbuf *r, uint32_t skip, void *out,
                                      uint32_t n)
{
    const uint8_t *ring = r->buf;
    uint32_t mask = r->size / 4u - 1u, at = (ringbuf_word_slot(r, r->tail) + skip) & mask;
    if (at + n <= mask + 1u) { /* no wrap: word after word */
#pragma GCC unroll 4
        for (uint32_t i = 0; i < n; i++)
            __builtin_memcpy((uint8_t *)out + 4u * i, ring + 4u * (at + i), 4);
    } else {
        for (uint32_t i = 0; i < n; i++, at = (at + 1u) & mask)
            __builtin_memcpy((uint8_t *)out + 4u * i, ring + 4u * at, 4);
    }
}

/* Takes the n oldest words, read already. */
static inline void ringbuf_take_words(struct ringbuf *r, uint32_t n)
{
    /* Release: we are done reading the words before the producer may
     * overwrite them. */
    __atomic_store_n(&r->tail, r->tail + 4u * n, __ATOMIC_RELEASE);
}

#endif
