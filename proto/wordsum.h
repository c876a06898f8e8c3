/* wordsum.h: the word sum, the check of the shared path's bulk bytes
 * (LINK_BULK, proto/hostlink.h) and of compiled scenes (the header's
 * SCN_HDR_SUM, proto/scene_format.h).  A Fletcher-style sum of 32-bit
 * words: two adds a word where a CRC-32 takes a table step a byte.
 *
 * The bytes are read as little-endian u32 words, a last partial word
 * padded with zero bytes.  With w_0 .. w_{n-1} the words,
 *   a = w_0 + ... + w_{n-1}          (mod 2^32)
 *   b = sum of a after each word     = sum of (n - i) w_i (mod 2^32)
 *   value = a + 2 b                  = sum of (2 (n - i) + 1) w_i
 * Every weight is odd, so a change within one aligned word always
 * changes the value (single-bit flips included); words moved to other
 * places change it unless the difference times the distance in weights
 * is a multiple of 2^32.  The length is checked on its own (LINK_BULK's
 * length, the scene's total).
 *
 * Incremental use: wordsum_update over consecutive runs, each but the
 * last a multiple of 4 bytes long, is one call over all of them;
 * wordsum_join gives the sum of two runs from theirs, so a caller that
 * wants a run's own sum and its sum with a prefix reads the bytes once.
 */
#ifndef LINKS1_PROTO_WORDSUM_H
#define LINKS1_PROTO_WORDSUM_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    uint32_t a, b;   /* the two sums above */
    uint32_t words;  /* words summed (a last partial word counts) */
} wordsum_t;

#define WORDSUM_EMPTY ((wordsum_t){0, 0, 0})

void wordsum_update(wordsum_t *s, const void *data, size_t len);

/* The sum of the run summed in head followed by the run summed in tail. */
static inline wordsum_t wordsum_join(wordsum_t head, wordsum_t tail)
{
    wordsum_t s = {head.a + tail.a, head.b + tail.words * head.a + tail.b,
                   head.words + tail.words};
    return s;
}

static inline uint32_t wordsum_value(wordsum_t s) { return s.a + 2u * s.b; }

/* The value of len bytes at data. */
static inline uint32_t wordsum(const void *data, size_t len)
{
    wordsum_t s = WORDSUM_EMPTY;
    wordsum_update(&s, data, len);
    return wordsum_value(s);
}

#endif
