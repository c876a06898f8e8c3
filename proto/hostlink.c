/* hostlink.c: frame encoder, streaming decoder and payload encodings of the
 * host link (see hostlink.h).  Used by the firmware and by the host tool. */
#include "proto/hostlink.h"

#include <string.h>

#include "proto/crc32.h"
#include "proto/units.h"
#include "proto/wire.h"

size_t link_frame_encode(uint8_t *out, size_t cap, uint8_t type, uint8_t flags,
                         uint16_t seq, const void *payload, size_t len)
{
    size_t total = LINK_HEADER_SIZE + len + LINK_CRC_SIZE;
    if (len > LINK_MAX_PAYLOAD || cap < total)
        return 0;
    out[0] = LINK_SYNC0;
    out[1] = LINK_SYNC1;
    out[2] = type;
    out[3] = flags;
    wire_put_u16(out + 4, seq);
    wire_put_u16(out + 6, (uint16_t)len);
    if (len)
        memcpy(out + LINK_HEADER_SIZE, payload, len);
    wire_put_u32(out + LINK_HEADER_SIZE + len,
                 crc32(out + 2, LINK_HEADER_SIZE - 2 + len));
    return total;
}

void link_decoder_init(struct link_decoder *d)
{
    memset(d, 0, sizeof *d);
}

/* Drops the first byte of the partial frame and rescans the rest for sync,
 * so a corrupted header never hides a good frame that starts inside it. */
static void decoder_resync(struct link_decoder *d)
{
    size_t i;
    for (i = 1; i < d->have; i++) {
        if (d->buf[i] == LINK_SYNC0 && (i + 1 == d->have || d->buf[i + 1] == LINK_SYNC1))
            break;
    }
    d->stats.junk_bytes += (uint32_t)i;
    memmove(d->buf, d->buf + i, d->have - i);
    d->have -= i;
}

/* Delivers the frame at the start of the buffer, if one is complete and good. */
static int decoder_scan(struct link_decoder *d, struct link_frame *f)
{
    for (;;) {
        if (d->have >= 1 && d->buf[0] != LINK_SYNC0) {
            decoder_resync(d);
            continue;
        }
        if (d->have >= 2 && d->buf[1] != LINK_SYNC1) {
            decoder_resync(d);
            continue;
        }
        if (d->have < LINK_HEADER_SIZE)
            return 0;
        uint16_t len = wire_get_u16(d->buf + 6);
        if (len > LINK_MAX_PAYLOAD) {
            d->stats.bad_length++;
            decoder_resync(d);
            continue;
        }
        size_t total = LINK_HEADER_SIZE + (size_t)len + LINK_CRC_SIZE;
        if (d->have < total)
            return 0;
        uint32_t want = wire_get_u32(d->buf + LINK_HEADER_SIZE + len);
        if (crc32(d->buf + 2, LINK_HEADER_SIZE - 2 + (size_t)len) != want) {
            d->stats.crc_errors++;
            decoder_resync(d);
            continue;
        }
        /* A good frame: deliver it.  The buffer is reused from the next push. */
        f->type = d->buf[2];
        f->flags = d->buf[3];
        f->seq = wire_get_u16(d->buf + 4);
        f->length = len;
        f->payload = d->buf + LINK_HEADER_SIZE;
        if (f->type != LINK_NAK) { /* unnumbered */
            /* A gap is a frame ahead of the next expected; one behind is a
             * frame sent again (proto/link_arq.h), not a loss. */
            int16_t ahead = (int16_t)(f->seq - d->next_seq);
            int session = (f->flags & LINK_FLAG_SESSION) != 0;
            if (d->seq_known && ahead > 0 && !session)
                d->stats.seq_gaps++;
            if (!d->seq_known || ahead >= 0 || session)
                d->next_seq = (uint16_t)(f->seq + 1);
            d->seq_known = 1;
        }
        d->stats.frames++;
        d->delivered = total;
        return 1;
    }
}

/* The last frame's payload had to stay valid until now; drop it, keeping any
 * bytes after it (a frame recovered by a resync can be followed by bytes of
 * the next one). */
static void decoder_drop_delivered(struct link_decoder *d)
{
    if (d->delivered) {
        memmove(d->buf, d->buf + d->delivered, d->have - d->delivered);
        d->have -= d->delivered;
        d->delivered = 0;
    }
}

int link_decoder_push(struct link_decoder *d, uint8_t b, struct link_frame *f)
{
    decoder_drop_delivered(d);
    d->buf[d->have++] = b;
    return decoder_scan(d, f);
}

int link_decoder_unstick(struct link_decoder *d, struct link_frame *f)
{
    decoder_drop_delivered(d);
    if (d->have == 0)
        return 0;
    d->stats.stalls++;
    decoder_resync(d);
    return decoder_scan(d, f);
}

void link_hello_put(uint8_t *p, const struct link_hello *h)
{
    wire_put_u16(p, h->core);
    wire_put_u8(p + 2, h->role);
    wire_put_u8(p + 3, h->variant);
    wire_put_u32(p + 4, h->mpidr);
    wire_put_u16(p + 8, h->ncores);
    wire_put_u16(p + 10, h->reserved);
}

void link_hello_get(const uint8_t *p, struct link_hello *h)
{
    h->core = wire_get_u16(p);
    h->role = wire_get_u8(p + 2);
    h->variant = wire_get_u8(p + 3);
    h->mpidr = wire_get_u32(p + 4);
    h->ncores = wire_get_u16(p + 8);
    h->reserved = wire_get_u16(p + 10);
}

void link_fault_put(uint8_t *p, const struct link_fault *f)
{
    wire_put_u16(p, f->core);
    wire_put_u8(p + 2, f->role);
    wire_put_u8(p + 3, f->kind);
    wire_put_u32(p + 4, f->addr);
    wire_put_u32(p + 8, f->pc);
    wire_put_u32(p + 12, f->status);
}

void link_fault_get(const uint8_t *p, struct link_fault *f)
{
    f->core = wire_get_u16(p);
    f->role = wire_get_u8(p + 2);
    f->kind = wire_get_u8(p + 3);
    f->addr = wire_get_u32(p + 4);
    f->pc = wire_get_u32(p + 8);
    f->status = wire_get_u32(p + 12);
}

void link_status_result_put(uint8_t *p, const struct link_status_result *r)
{
    wire_put_u16(p, r->ncores);
    wire_put_u16(p + 2, r->reported);
    wire_put_u16(p + 4, r->halted);
}

void link_status_result_get(const uint8_t *p, struct link_status_result *r)
{
    r->ncores = wire_get_u16(p);
    r->reported = wire_get_u16(p + 2);
    r->halted = wire_get_u16(p + 4);
}

void link_count_result_put(uint8_t *p, const struct link_count_result *r)
{
    wire_put_u32(p, r->ok);
    wire_put_u32(p + 4, r->total);
}

void link_count_result_get(const uint8_t *p, struct link_count_result *r)
{
    r->ok = wire_get_u32(p);
    r->total = wire_get_u32(p + 4);
}

void link_latency_result_put(uint8_t *p, const struct link_latency_result *r)
{
    wire_put_u32(p, r->rounds);
    wire_put_u32(p + 4, r->freq);
    wire_put_u32(p + 8, r->min);
    wire_put_u32(p + 12, r->median);
    wire_put_u32(p + 16, r->max);
}

void link_latency_result_get(const uint8_t *p, struct link_latency_result *r)
{
    r->rounds = wire_get_u32(p);
    r->freq = wire_get_u32(p + 4);
    r->min = wire_get_u32(p + 8);
    r->median = wire_get_u32(p + 12);
    r->max = wire_get_u32(p + 16);
}

void link_stress_result_put(uint8_t *p, const struct link_stress_result *r)
{
    wire_put_u64(p, r->bytes);
    wire_put_u32(p + 8, r->errors);
    wire_put_u32(p + 12, r->skipped);
}

void link_stress_result_get(const uint8_t *p, struct link_stress_result *r)
{
    r->bytes = wire_get_u64(p);
    r->errors = wire_get_u32(p + 8);
    r->skipped = wire_get_u32(p + 12);
}

void link_transfer_result_put(uint8_t *p, const struct link_transfer_result *r)
{
    wire_put_u64(p, r->bytes);
    wire_put_u32(p + 8, r->crc);
    wire_put_u32(p + 12, r->differ);
}

void link_transfer_result_get(const uint8_t *p, struct link_transfer_result *r)
{
    r->bytes = wire_get_u64(p);
    r->crc = wire_get_u32(p + 8);
    r->differ = wire_get_u32(p + 12);
}

void link_bulk_put(uint8_t *p, const struct link_bulk *k)
{
    wire_put_u32(p, k->offset);
    wire_put_u32(p + 4, k->length);
    wire_put_u32(p + 8, k->sum);
}

void link_bulk_get(const uint8_t *p, struct link_bulk *k)
{
    k->offset = wire_get_u32(p);
    k->length = wire_get_u32(p + 4);
    k->sum = wire_get_u32(p + 8);
}

uint8_t unit_role_of_core(uint32_t core)
{
    if (core == UNITS_DM_CORE)
        return ROLE_DM;
    if (core == UNITS_RC_CORE)
        return ROLE_RC;
    return ROLE_NC;
}

const char *unit_role_name(uint8_t role)
{
    switch (role) {
    case ROLE_DM: return "DM";
    case ROLE_RC: return "RC";
    case ROLE_NC: return "NC";
    }
    return "?";
}
