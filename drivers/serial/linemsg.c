/* linemsg.c: inter-unit message encoding (see linemsg.h). */
#include "drivers/serial/linemsg.h"

#include <string.h>

#include "proto/crc32.h"
#include "proto/wire.h"

size_t linemsg_encode(uint8_t *out, size_t cap, const struct line_msg *m)
{
    size_t total = LINEMSG_HEADER_SIZE + (size_t)m->len;
    if (m->len > LINE_MAX_PAYLOAD || cap < total)
        return 0;
    wire_put_u16(out, m->type);
    wire_put_u16(out + 2, m->len);
    wire_put_u32(out + 4, m->seq);
    wire_put_u32(out + 8, crc32(m->payload, m->len));
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
    m->type = wire_get_u16(in);
    m->len = wire_get_u16(in + 2);
    m->seq = wire_get_u32(in + 4);
    memcpy(m->payload, in + LINEMSG_HEADER_SIZE, m->len);
    if (crc32(m->payload, m->len) != wire_get_u32(in + 8))
        return LINEMSG_ERR_CHECK;
    return LINEMSG_OK;
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
