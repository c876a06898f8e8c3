/* link_arq.c: stop-and-wait retransmission of the host link (see link_arq.h). */
#include "proto/link_arq.h"

#include "proto/wire.h"

void link_arq_tx_init(struct link_arq_tx *t, uint16_t first_seq, uint64_t timeout)
{
    t->size = 0;
    t->next_seq = first_seq;
    t->seq = 0;
    t->tries = 0;
    t->timeout = timeout;
    t->deadline = 0;
    t->resends = 0;
}

size_t link_arq_tx_frame(struct link_arq_tx *t, uint8_t type, uint8_t flags,
                         const void *payload, size_t len, uint64_t now)
{
    if (t->size)
        return 0;
    size_t n = link_frame_encode(t->frame, sizeof t->frame, type, flags, t->next_seq,
                                 payload, len);
    if (n == 0)
        return 0;
    t->size = n;
    t->seq = t->next_seq++;
    t->tries = 1;
    t->deadline = now + t->timeout;
    return n;
}

/* One more send of the pending frame, or the end of trying. */
static enum link_arq_action arq_tx_again(struct link_arq_tx *t, uint64_t now)
{
    if (t->tries >= LINK_ARQ_MAX_TRIES)
        return LINK_ARQ_GIVE_UP;
    t->tries++;
    t->resends++;
    t->deadline = now + t->timeout;
    return LINK_ARQ_RESEND;
}

enum link_arq_action link_arq_tx_answer(struct link_arq_tx *t, const struct link_frame *f,
                                        uint64_t now)
{
    if (!t->size)
        return LINK_ARQ_IDLE;
    if (f->length < LINK_ACK_SIZE || wire_get_u16(f->payload) != t->seq)
        return LINK_ARQ_WAIT;
    if (f->type == LINK_ACK) {
        t->size = 0;
        return LINK_ARQ_IDLE;
    }
    if (f->type == LINK_NAK)
        return arq_tx_again(t, now);
    return LINK_ARQ_WAIT;
}

enum link_arq_action link_arq_tx_poll(struct link_arq_tx *t, uint64_t now)
{
    if (!t->size)
        return LINK_ARQ_IDLE;
    if (now < t->deadline)
        return LINK_ARQ_WAIT;
    return arq_tx_again(t, now);
}

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
    if (f->seq == (uint16_t)(r->expect - 1))
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
