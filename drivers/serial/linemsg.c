/* linemsg.c: inter-unit message encoding (see linemsg.h). */
#include "drivers/serial/linemsg.h"

#include <string.h>

#include "proto/crc32.h"
#include "proto/wire.h"

void linemsg_put_header(uint8_t *hdr, const struct line_msg *m)
{
    uint32_t w[LINEMSG_HEADER_WORDS];
    linemsg_header_words(w, m, linemsg_payload_crc(m));
    for (uint32_t i = 0; i < LINEMSG_HEADER_WORDS; i++)
        wire_put_u32(hdr + 4 * i, w[i]);
}

uint32_t linemsg_get_header(const uint8_t *hdr, struct line_msg *m)
{
    uint32_t w[LINEMSG_HEADER_WORDS];
    for (uint32_t i = 0; i < LINEMSG_HEADER_WORDS; i++)
        w[i] = wire_get_u32(hdr + 4 * i);
    return linemsg_header_from_words(w, m);
}

size_t linemsg_encode(uint8_t *out, size_t cap, const struct line_msg *m)
{
    size_t total = LINEMSG_HEADER_SIZE + (size_t)m->len;
    if (m->len > LINE_MAX_PAYLOAD || cap < total)
        return 0;
    linemsg_put_header(out, m);
    memcpy(out + LINEMSG_HEADER_SIZE, m->payload, m->len);
    return total;
}

int linemsg_total_size(const uint8_t *hdr)
{
    uint16_t len = wire_get_u16(hdr + 2);
    if (len > LINE_MAX_PAYLOAD)
        return LINEMSG_ERR_TOO_LONG;
    return LINEMSG_HEADER_SIZE + len;
}

int linemsg_decode(const uint8_t *in, size_t n, struct line_msg *m)
{
    if (n < LINEMSG_HEADER_SIZE)
        return LINEMSG_ERR_SHORT;
    int total = linemsg_total_size(in);
    if (total < 0)
        return total;
    if (n < (size_t)total)
        return LINEMSG_ERR_SHORT;
    uint32_t check = linemsg_get_header(in, m);
    memcpy(m->payload, in + LINEMSG_HEADER_SIZE, m->len);
    return linemsg_check_payload(m, check);
}

const char *linemsg_strerror(int status)
{
    switch (status) {
    case LINEMSG_OK: return "ok";
    case LINEMSG_ERR_SHORT: return "message shorter than its header says";
    case LINEMSG_ERR_TOO_LONG: return "message longer than LINE_MAX_PAYLOAD";
    case LINEMSG_ERR_CHECK: return "message payload fails its crc32";
    }
    return "unknown message status";
}
