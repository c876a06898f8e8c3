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
#include "proto/crc32.h"
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

/* The header as three words, in the layout above on a little-endian core:
 * type | len << 16, seq, check.  The one definition of the header:
 * linemsg_put_header writes these words' bytes; the lines, whose rings
 * hold whole words, store the words themselves. */
#define LINEMSG_HEADER_WORDS (LINEMSG_HEADER_SIZE / 4)
_Static_assert(LINEMSG_HEADER_SIZE == 12, "the header is three words");
static inline void linemsg_header_words(uint32_t w[LINEMSG_HEADER_WORDS], const struct line_msg *m,
                                        uint32_t check)
{
    w[0] = (uint32_t)m->type | (uint32_t)m->len << 16;
    w[1] = m->seq;
    w[2] = check;
}
/* Reads header words into m's type, len (unchecked: see linemsg_total_size)
 * and seq; returns the crc32 they announce for the payload. */
static inline uint32_t linemsg_header_from_words(const uint32_t w[LINEMSG_HEADER_WORDS],
                                                 struct line_msg *m)
{
    m->type = (uint16_t)w[0];
    m->len = (uint16_t)(w[0] >> 16);
    m->seq = w[1];
    return w[2];
}

/* The header alone, for a line that copies the payload itself: writes m's
 * type, len, seq and the payload's crc32 at hdr (m->len <=
 * LINE_MAX_PAYLOAD). */
void linemsg_put_header(uint8_t *hdr, const struct line_msg *m);
/* Reads a header (its len checked with linemsg_total_size) into m's type,
 * len and seq; returns the crc32 it announces for the payload. */
uint32_t linemsg_get_header(const uint8_t *hdr, struct line_msg *m);
/* The crc32 of m's payload: inline for the few words of most messages
 * (payload[] is word-aligned). */
_Static_assert(offsetof(struct line_msg, payload) % 4 == 0 && _Alignof(struct line_msg) >= 4,
               "a message's payload is word-aligned");
static inline uint32_t linemsg_payload_crc(const struct line_msg *m)
{
    return crc32_short(__builtin_assume_aligned(m->payload, 4), m->len);
}
/* LINEMSG_OK if m's payload has crc32 check, else LINEMSG_ERR_CHECK. */
static inline int linemsg_check_payload(const struct line_msg *m, uint32_t check)
{
    return linemsg_payload_crc(m) == check ? LINEMSG_OK : LINEMSG_ERR_CHECK;
}
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
