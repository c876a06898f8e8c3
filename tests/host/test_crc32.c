/* Host tests of the CRC-32 used by frames and compiled scenes. */
#include <string.h>

#include "proto/crc32.h"
#include "tests/check.h"

static void crc32_check_value(void)
{
    CHECK_EQ_INT(crc32("123456789", 9), 0xCBF43926u);
    CHECK_EQ_INT(crc32("", 0), 0);
    CHECK_EQ_INT(crc32("a", 1), 0xE8B7BE43u);
}

static void crc32_incremental_matches_one_shot(void)
{
    const char *s = "The quick brown fox jumps over the lazy dog";
    size_t n = strlen(s);
    uint32_t whole = crc32(s, n);
    CHECK_EQ_INT(whole, 0x414FA339u);
    for (size_t cut = 0; cut <= n; cut++)
        CHECK_EQ_INT(crc32_update(crc32(s, cut), s + cut, n - cut), whole);
}

static void crc32_detects_single_bit_flips(void)
{
    unsigned char buf[64];
    for (int i = 0; i < 64; i++)
        buf[i] = (unsigned char)(i * 37 + 11);
    uint32_t ref = crc32(buf, sizeof buf);
    int missed = 0;
    for (int bit = 0; bit < 64 * 8; bit++) {
        buf[bit / 8] ^= (unsigned char)(1u << (bit % 8));
        missed += crc32(buf, sizeof buf) == ref;
        buf[bit / 8] ^= (unsigned char)(1u << (bit % 8));
    }
    CHECK_EQ_INT(missed, 0);
}

/* Word-aligned runs take four bytes per step: the same value as one byte
 * per call (which never does), at every start alignment and length. */
static void crc32_word_steps_match_byte_steps(void)
{
    _Alignas(4) unsigned char buf[72];
    for (int i = 0; i < 72; i++)
        buf[i] = (unsigned char)(i * 91 + 7);
    int bad = 0;
    for (size_t off = 0; off < 4; off++) {
        for (size_t n = 0; n + off <= sizeof buf; n += 5) {
            uint32_t bytewise = 0;
            for (size_t i = 0; i < n; i++)
                bytewise = crc32_update(bytewise, buf + off + i, 1);
            bad += crc32(buf + off, n) != bytewise;
        }
    }
    CHECK_EQ_INT(bad, 0);
}

/* The lines' inline crc32 of a few words gives crc32's value for every
 * length and alignment (crc32_update where it does not take the words). */
static void crc32_short_matches_crc32(void)
{
    _Alignas(4) uint8_t buf[24];
    int bad = 0;
    for (int i = 0; i < 24; i++)
        buf[i] = (uint8_t)(0x5A ^ (i * 37));
    for (size_t off = 0; off < 4; off++)
        for (size_t n = 0; n + off <= 20; n++)
            bad += crc32_short(buf + off, n) != crc32(buf + off, n);
    CHECK_EQ_INT(bad, 0);
}

int main(void)
{
    RUN(crc32_check_value);
    RUN(crc32_incremental_matches_one_shot);
    RUN(crc32_detects_single_bit_flips);
    RUN(crc32_word_steps_match_byte_steps);
    RUN(crc32_short_matches_crc32);
    return check_exit();
}
