/* linemsg.h: the messages of the inter-unit serial lines, and their byte
 * encoding (little-endian, proto/wire.h).  No hardware access: the host
 * tests build it.
 *
 *   offset  size  field
 *   0       2     type    (proto/unitmsg.h: what the message asks or says)
 *   2       2     len     payload bytes, 0..LINE_MAX_PAYLOAD
 *   4       4     seq     sender's message counter on this line direction
 *   8       4     check   crc32 of the payload
 *   12      len   payload
 */
#ifndef LINKS1_DRIVERS_SERIAL_LINEMSG_H
#define LINKS1_DRIVERS_SERIAL_LINEMSG_H

#include <stddef.h>
#include <stdint.h>

#include "kernel/param.h"
#include "proto/unitmsg.h" /* LINEMSG_HEADER_SIZE */

#define LINEMSG_MAX_SIZE (LINEMSG_HEADER_SIZE + LINE_MAX_PAYLOAD)

struct line_msg {
    uint16_t type;
    uint16_t len;
    uint32_t seq;
    uint8_t payload[LINE_MAX_PAYLOAD];
};

enum linemsg_status {
    LINEMSG_OK = 0,
    LINEMSG_ERR_SHORT = -1,    /* fewer bytes than the header says */
    LINEMSG_ERR_TOO_LONG = -2, /* len > LINE_MAX_PAYLOAD */
    LINEMSG_ERR_CHECK = -3,    /* payload does not match its crc32 */
};

/* The header alone, for a line that copies the payload itself: writes m's
 * type, len, seq and the payload's crc32 at hdr (m->len <=
 * LINE_MAX_PAYLOAD). */
void linemsg_put_header(uint8_t *hdr, const struct line_msg *m);
/* Reads a header (its len checked with linemsg_total_size) into m's type,
 * len and seq; returns the crc32 it announces for the payload. */
uint32_t linemsg_get_header(const uint8_t *hdr, struct line_msg *m);
/* LINEMSG_OK if m's payload has crc32 check, else LINEMSG_ERR_CHECK. */
int linemsg_check_payload(const struct line_msg *m, uint32_t check);
/* Encodes m into out; returns the bytes written, or 0 if m->len is too
 * long or cap too small. */
size_t linemsg_encode(uint8_t *out, size_t cap, const struct line_msg *m);
/* Total encoded size announced by a header (>= LINEMSG_HEADER_SIZE bytes
 * at hdr), or LINEMSG_ERR_TOO_LONG. */
int linemsg_total_size(const uint8_t *hdr);
/* Decodes n bytes; returns LINEMSG_OK or a negative enum linemsg_status
 * (on LINEMSG_ERR_CHECK *m is filled all the same). */
int linemsg_decode(const uint8_t *in, size_t n, struct line_msg *m);
const char *linemsg_strerror(int status);

#endif
