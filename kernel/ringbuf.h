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
uint32_t ringbuf_used(const struct ringbuf *r);
uint32_t ringbuf_free(const struct ringbuf *r);
/* Copies n bytes in; 0, or -1 (nothing written) if fewer than n are free. */
int ringbuf_put(struct ringbuf *r, const void *data, uint32_t n);
/* Puts one record of two pieces (na bytes at a, then nb at b) without
 * joining them first; 0, or -1 (nothing written) if fewer than na + nb are
 * free. */
int ringbuf_put2(struct ringbuf *r, const void *a, uint32_t na, const void *b, uint32_t nb);
/* Copies n bytes out; 0, or -1 (nothing taken) if fewer than n are there. */
int ringbuf_get(struct ringbuf *r, void *out, uint32_t n);
/* Copies n bytes out without taking them; 0 or -1 as ringbuf_get. */
int ringbuf_peek(const struct ringbuf *r, void *out, uint32_t n);
/* Takes skip + n bytes, copying out only the last n (the first skip were
 * read with ringbuf_peek); 0, or -1 (nothing taken) if fewer are there. */
int ringbuf_get_after(struct ringbuf *r, uint32_t skip, void *out, uint32_t n);
/* Producer side, for byte streams: puts one byte; 0, or -1 if full. */
int ringbuf_put_byte(struct ringbuf *r, uint8_t b);
/* Takes up to max bytes; returns how many. */
uint32_t ringbuf_get_some(struct ringbuf *r, void *out, uint32_t max);

#endif
