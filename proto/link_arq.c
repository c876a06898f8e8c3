/* link_arq.c: retransmission of the host link (see link_arq.h). */
#include "proto/link_arq.h"

#include "proto/wire.h"

void link_arq_rx_init(struct link_arq_rx *r)
{
    r->known = 0;
    r->expect = 0;
}

enum link_arq_verdict link_arq_rx_take(struct link_arq_rx *r, const struct link_frame *f)
{
    if ((f->flags & LINK_FLAG_SESSION) || !r->known || f->seq == r->expect) {
        r->known = 1;
        r->expect = (uint16_t)(f->seq + 1);
        return LINK_ARQ_NEW;
    }
    /* Behind the expected seq (within half the seq space): taken already. */
    if ((uint16_t)(r->expect - f->seq) <= 0x8000u)
        return LINK_ARQ_DUP;
    return LINK_ARQ_OTHER;
}

size_t link_arq_answer_encode(uint8_t *out, size_t cap, uint8_t type, uint16_t frame_seq,
                              uint16_t about)
{
    uint8_t p[LINK_ACK_SIZE];
    wire_put_u16(p, about);
    return link_frame_encode(out, cap, type, 0, frame_seq, p, sizeof p);
}

/* ---- go-back-N ---- */

void link_arq_store_init(struct link_arq_store *s, uint16_t first_seq)
{
    s->pos = 0;
    for (unsigned i = 0; i < LINK_ARQ_STORE_FRAMES; i++)
        s->idx[i].size = 0;
    s->next_seq = first_seq;
    s->held = 0;
}

size_t link_arq_store_frame(struct link_arq_store *s, uint8_t *out, size_t cap, uint8_t type,
                            uint8_t flags, const void *payload, size_t len)
{
    size_t n = link_frame_encode(out, cap, type, flags, s->next_seq, payload, len);
    if (n == 0)
        return 0;
    unsigned slot = s->next_seq % LINK_ARQ_STORE_FRAMES;
    s->idx[slot].size = 0; /* invalid while its bytes change */
    for (size_t i = 0; i < n; i++)
        s->bytes[(s->pos + i) % LINK_ARQ_STORE_BYTES] = out[i];
    s->idx[slot].pos = s->pos;
    s->idx[slot].seq = s->next_seq;
    s->idx[slot].size = (uint16_t)n;
    s->pos += n;
    s->next_seq++;
    if (s->held < LINK_ARQ_STORE_FRAMES)
        s->held++;
    return n;
}

/* The slot of frame seq when its bytes are still held, else -1. */
static int arq_store_slot(const struct link_arq_store *s, uint16_t seq)
{
    unsigned slot = seq % LINK_ARQ_STORE_FRAMES;
    uint16_t back = (uint16_t)(s->next_seq - seq); /* 1 for the newest */
    if (back == 0 || back > s->held || s->idx[slot].size == 0 || s->idx[slot].seq != seq)
        return -1;
    if (s->pos - s->idx[slot].pos > LINK_ARQ_STORE_BYTES)
        return -1; /* newer frames wrote over it */
    return (int)slot;
}

int link_arq_store_span(const struct link_arq_store *s, uint16_t from)
{
    if (from == s->next_seq)
        return 0;
    if (arq_store_slot(s, from) < 0)
        return -1;
    return (uint16_t)(s->next_seq - from);
}

int link_arq_store_resend_count(const struct link_arq_store *s, uint16_t from, int span)
{
    size_t bytes = 0;
    int k = 0;
    while (k < span && bytes < LINK_ARQ_RESEND_BYTES) {
        int slot = arq_store_slot(s, (uint16_t)(from + k));
        if (slot < 0)
            break;
        bytes += s->idx[slot].size;
        k++;
    }
    return k;
}

size_t link_arq_store_get(const struct link_arq_store *s, uint16_t seq, uint8_t *out,
                          size_t cap)
{
    int slot = arq_store_slot(s, seq);
    if (slot < 0 || s->idx[slot].size > cap)
        return 0;
    size_t n = s->idx[slot].size;
    for (size_t i = 0; i < n; i++)
        out[i] = s->bytes[(s->idx[slot].pos + i) % LINK_ARQ_STORE_BYTES];
    return n;
}

int link_arq_nak_due(struct link_arq_nak *n, uint16_t expect, uint64_t now, uint64_t gap)
{
    if (n->sent && n->seq == expect && now - n->at < gap)
        return 0;
    n->tries = n->sent && n->seq == expect ? n->tries + 1 : 1;
    n->sent = 1;
    n->seq = expect;
    n->at = now;
    return 1;
}

size_t link_arq_nak_encode(uint8_t *out, size_t cap, uint8_t flags, uint16_t expect)
{
    uint8_t p[LINK_ACK_SIZE];
    wire_put_u16(p, expect);
    return link_frame_encode(out, cap, LINK_NAK, flags, 0, p, sizeof p);
}
