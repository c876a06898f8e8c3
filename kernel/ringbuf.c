/* ringbuf.c: the SPSC byte ring (see ringbuf.h for the memory ordering). */
#include "kernel/ringbuf.h"

#include "kernel/kcopy.h"

int ringbuf_init(struct ringbuf *r, uint8_t *buf, uint32_t size)
{
    if (size < 2 || (size & (size - 1)) != 0)
        return -1;
    r->buf = buf;
    r->size = size;
    r->head = 0;
    r->tail = 0;
    return 0;
}

/* Copies n bytes between the ring at index pos (mod size) and flat memory,
 * in at most two pieces around the wrap. */
static void ringbuf_copy_in(struct ringbuf *r, uint32_t pos, const uint8_t *src, uint32_t n)
{
    uint32_t off = pos & (r->size - 1);
    uint32_t first = r->size - off < n ? r->size - off : n;
    kcopy(r->buf + off, src, first);
    kcopy(r->buf, src + first, n - first);
}

static void ringbuf_copy_out(const struct ringbuf *r, uint32_t pos, uint8_t *dst, uint32_t n)
{
    uint32_t off = pos & (r->size - 1);
    uint32_t first = r->size - off < n ? r->size - off : n;
    kcopy(dst, r->buf + off, first);
    kcopy(dst + first, r->buf, n - first);
}

int ringbuf_put(struct ringbuf *r, const void *data, uint32_t n)
{
    uint32_t head = r->head; /* only we write it */
    uint32_t tail = __atomic_load_n(&r->tail, __ATOMIC_ACQUIRE);
    if (r->size - (head - tail) < n)
        return -1;
    ringbuf_copy_in(r, head, data, n);
    /* Release: the bytes are in place before the consumer can see them. */
    __atomic_store_n(&r->head, head + n, __ATOMIC_RELEASE);
    return 0;
}

int ringbuf_put_byte(struct ringbuf *r, uint8_t b)
{
    return ringbuf_put(r, &b, 1);
}

int ringbuf_peek(const struct ringbuf *r, void *out, uint32_t n)
{
    uint32_t tail = r->tail;
    uint32_t head = __atomic_load_n(&r->head, __ATOMIC_ACQUIRE);
    if (head - tail < n)
        return -1;
    ringbuf_copy_out(r, tail, out, n);
    return 0;
}

int ringbuf_get(struct ringbuf *r, void *out, uint32_t n)
{
    if (ringbuf_peek(r, out, n) != 0)
        return -1;
    /* Release: we are done reading the bytes before the producer may
     * overwrite them. */
    __atomic_store_n(&r->tail, r->tail + n, __ATOMIC_RELEASE);
    return 0;
}

uint32_t ringbuf_get_some(struct ringbuf *r, void *out, uint32_t max)
{
    uint32_t tail = r->tail;
    uint32_t head = __atomic_load_n(&r->head, __ATOMIC_ACQUIRE);
    uint32_t n = head - tail < max ? head - tail : max;
    ringbuf_copy_out(r, tail, out, n);
    __atomic_store_n(&r->tail, tail + n, __ATOMIC_RELEASE);
    return n;
}
