/* link_arq_sim.c: stop-and-wait retransmission through simulated noise
 * (see link_arq_sim.h). */
#include "host-tools/link_arq_sim.h"

#include <stdlib.h>
#include <string.h>

#include "host-tools/link_noise.h"
#include "proto/link_arq.h"

#define SIM_TIMEOUT 4      /* steps without an ACK before the sender sends again */
#define SIM_QUIET 6        /* steps with no good frame before an end unsticks its decoder */
#define SIM_OUT (1u << 20)

struct sim_pipe {
    uint8_t buf[4 * LINK_MAX_FRAME + 64];
    size_t n;
    struct link_noise noise;
    uint64_t wire;  /* bytes sent into the pipe, before the noise */
};

struct sim {
    struct sim_pipe down, up; /* sender -> receiver, receiver -> sender */
    struct link_arq_tx tx;
    struct link_arq_rx rx;
    struct link_decoder rdec, sdec;
    uint16_t rseq;          /* the receiver's own frame numbering (its answers) */
    uint8_t *out;           /* what the receiver took, in order */
    size_t out_n;
    uint32_t rx_errors;     /* decoder errors the receiver already NAKed */
    unsigned quiet_r, quiet_s; /* steps since each end's decoder gave a frame */
};

static void sim_send(struct sim_pipe *p, const uint8_t *b, size_t n)
{
    p->wire += n;
    static uint8_t tmp[2 * LINK_MAX_FRAME];
    size_t k = link_noise_apply(&p->noise, b, n, tmp);
    if (p->n + k <= sizeof p->buf) { /* a full pipe loses the bytes, like noise */
        memcpy(p->buf + p->n, tmp, k);
        p->n += k;
    }
}

static uint32_t sim_dec_errors(const struct link_decoder *d)
{
    return d->stats.crc_errors + d->stats.bad_length;
}

static void sim_answer(struct sim *s, uint8_t type, uint16_t about)
{
    uint8_t f[LINK_HEADER_SIZE + LINK_ACK_SIZE + LINK_CRC_SIZE];
    size_t n = link_arq_answer_encode(f, sizeof f, type, s->rseq++, about);
    sim_send(&s->up, f, n);
}

static void sim_receiver_frame(struct sim *s, const struct link_frame *f)
{
    switch (link_arq_rx_take(&s->rx, f)) {
    case LINK_ARQ_NEW:
        if (s->out_n + f->length <= SIM_OUT) {
            memcpy(s->out + s->out_n, f->payload, f->length);
            s->out_n += f->length;
        }
        sim_answer(s, LINK_ACK, f->seq);
        break;
    case LINK_ARQ_DUP: sim_answer(s, LINK_ACK, f->seq); break;
    default: sim_answer(s, LINK_NAK, s->rx.expect); break;
    }
}

/* The receiver takes in what the down pipe holds. */
static void sim_receiver_step(struct sim *s)
{
    struct link_frame f;
    if (++s->quiet_r >= SIM_QUIET) {
        while (s->rdec.have > s->rdec.delivered) {
            if (link_decoder_unstick(&s->rdec, &f))
                sim_receiver_frame(s, &f);
        }
        s->quiet_r = 0;
    }
    for (size_t i = 0; i < s->down.n; i++) {
        int got = link_decoder_push(&s->rdec, s->down.buf[i], &f);
        if (sim_dec_errors(&s->rdec) != s->rx_errors) {
            s->rx_errors = sim_dec_errors(&s->rdec);
            if (s->rx.known)
                sim_answer(s, LINK_NAK, s->rx.expect);
        }
        if (got) {
            s->quiet_r = 0;
            sim_receiver_frame(s, &f);
        }
    }
    s->down.n = 0;
}

/* The sender reads answers and keeps its clock; returns the action. */
static enum link_arq_action sim_sender_step(struct sim *s, uint64_t now)
{
    struct link_frame f;
    enum link_arq_action a = LINK_ARQ_WAIT;
    s->quiet_s++;
    for (size_t i = 0; i < s->up.n && a != LINK_ARQ_GIVE_UP; i++) {
        if (!link_decoder_push(&s->sdec, s->up.buf[i], &f))
            continue;
        s->quiet_s = 0;
        if (f.type != LINK_ACK && f.type != LINK_NAK)
            continue;
        a = link_arq_tx_answer(&s->tx, &f, now);
        if (a == LINK_ARQ_RESEND)
            sim_send(&s->down, s->tx.frame, s->tx.size);
    }
    s->up.n = 0;
    if (s->quiet_s >= SIM_QUIET) {
        while (s->sdec.have > s->sdec.delivered && a != LINK_ARQ_GIVE_UP) {
            if (link_decoder_unstick(&s->sdec, &f) && (f.type == LINK_ACK || f.type == LINK_NAK))
                a = link_arq_tx_answer(&s->tx, &f, now);
        }
        s->quiet_s = 0;
    }
    if (a == LINK_ARQ_GIVE_UP)
        return a;
    a = link_arq_tx_poll(&s->tx, now);
    if (a == LINK_ARQ_RESEND)
        sim_send(&s->down, s->tx.frame, s->tx.size);
    return a;
}

uint8_t link_arq_sim_byte(uint32_t i)
{
    return link_pattern_byte(i * 7u + 3u);
}


/* Sends msgs messages of msg_len bytes through noise at rate each way. */
struct link_arq_sim_result link_arq_sim_run(double rate, uint64_t seed, unsigned msgs, size_t msg_len,
                                 uint16_t first_seq)
{
    static struct sim s;
    memset(&s, 0, sizeof s);
    struct link_arq_sim_result r;
    memset(&r, 0, sizeof r);
    s.out = malloc(SIM_OUT);
    if (!s.out || msg_len == 0 || msg_len > LINK_MAX_PAYLOAD) {
        free(s.out);
        return r; /* neither completed nor exact: the caller sees a failure */
    }
    link_noise_init(&s.down.noise, rate, seed);
    link_noise_init(&s.up.noise, rate, seed ^ 0x5555);
    link_arq_tx_init(&s.tx, first_seq, SIM_TIMEOUT);
    link_arq_rx_init(&s.rx);
    link_decoder_init(&s.rdec);
    link_decoder_init(&s.sdec);
    uint8_t msg[LINK_MAX_PAYLOAD];
    unsigned next = 0;
    enum link_arq_action a = LINK_ARQ_IDLE;
    uint64_t steps = 0;
    for (uint64_t now = 0; now < 1000000; now++) {
        steps = now + 1;
        if (a == LINK_ARQ_IDLE && next < msgs) {
            for (size_t i = 0; i < msg_len; i++)
                msg[i] = link_arq_sim_byte((uint32_t)(r.sent_bytes + i));
            size_t n = link_arq_tx_frame(&s.tx, LINK_DATA, 0, msg, msg_len, now);
            if (n == 0)
                break;
            sim_send(&s.down, s.tx.frame, n);
            r.sent_bytes += msg_len;
            next++;
        }
        sim_receiver_step(&s);
        a = sim_sender_step(&s, now);
        if (a == LINK_ARQ_GIVE_UP)
            break;
        if (a == LINK_ARQ_IDLE && next == msgs) {
            r.completed = 1;
            break;
        }
    }
    r.taken_bytes = s.out_n;
    r.exact_prefix = s.out_n <= r.sent_bytes;
    for (size_t i = 0; i < s.out_n && r.exact_prefix; i++)
        r.exact_prefix = s.out[i] == link_arq_sim_byte((uint32_t)i);
    r.resends = s.tx.resends;
    r.wire_bytes = s.down.wire + s.up.wire;
    r.steps = steps;
    free(s.out);
    return r;
}

