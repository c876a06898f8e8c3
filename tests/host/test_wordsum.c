/* Host tests of the word sum (proto/wordsum.h): the shared path's check
 * and the compiled scene's. */
#include <string.h>

#include "proto/wordsum.h"
#include "tests/check.h"

static void wordsum_value_of_known_words(void)
{
    /* words 1, 2, 3: a = 6, b = 1 + 3 + 6 = 10, value 26; a last partial
     * word is padded with zero bytes */
    const unsigned char w[12] = {1, 0, 0, 0, 2, 0, 0, 0, 3, 0, 0, 0};
    CHECK_EQ_INT(wordsum(w, 12), 26);
    CHECK_EQ_INT(wordsum(w, 9), 26);
    CHECK_EQ_INT(wordsum("", 0), 0);
}

/* Runs joined at every word boundary give the one pass's value, from
 * every start alignment (the eight-word steps take aligned runs only). */
static void wordsum_join_matches_one_pass(void)
{
    _Alignas(4) unsigned char buf[200];
    for (int i = 0; i < 200; i++)
        buf[i] = (unsigned char)(i * 53 + 17);
    int bad = 0;
    for (size_t off = 0; off < 4; off++) {
        size_t n = sizeof buf - off;
        uint32_t whole = wordsum(buf + off, n);
        for (size_t cut = 0; cut <= n; cut += 4) {
            wordsum_t head = WORDSUM_EMPTY, tail = WORDSUM_EMPTY, both = WORDSUM_EMPTY;
            wordsum_update(&head, buf + off, cut);
            wordsum_update(&tail, buf + off + cut, n - cut);
            wordsum_update(&both, buf + off, cut);
            wordsum_update(&both, buf + off + cut, n - cut);
            bad += wordsum_value(wordsum_join(head, tail)) != whole;
            bad += wordsum_value(both) != whole;
        }
    }
    CHECK_EQ_INT(bad, 0);
}

/* The same bytes give the same value aligned (the four-lane and eight-word
 * steps) and at every other alignment (word by word), at every length, and
 * after a prefix that leaves a and b not zero. */
static void wordsum_steps_match_word_by_word(void)
{
    _Alignas(16) unsigned char aligned[520], moved[524];
    for (int i = 0; i < 520; i++)
        aligned[i] = (unsigned char)(i * 101 + 7 + (i >> 5));
    int bad = 0;
    for (size_t off = 1; off < 4; off++) {
        memcpy(moved + off, aligned, sizeof aligned);
        for (size_t n = 0; n <= sizeof aligned; n += 1 + (n > 80) * 3) {
            bad += wordsum(aligned, n) != wordsum(moved + off, n);
            wordsum_t x = WORDSUM_EMPTY, y = WORDSUM_EMPTY;
            wordsum_update(&x, "prefix!!", 8);
            wordsum_update(&y, "prefix!!", 8);
            wordsum_update(&x, aligned, n);
            wordsum_update(&y, moved + off, n);
            bad += wordsum_value(x) != wordsum_value(y) || x.words != y.words;
        }
    }
    CHECK_EQ_INT(bad, 0);
}

/* Every single-bit flip, and every change of one aligned word, is seen. */
static void wordsum_detects_word_changes(void)
{
    _Alignas(4) unsigned char buf[96];
    for (int i = 0; i < 96; i++)
        buf[i] = (unsigned char)(i * 37 + 11);
    uint32_t ref = wordsum(buf, sizeof buf);
    int missed = 0;
    for (int bit = 0; bit < 96 * 8; bit++) {
        buf[bit / 8] ^= (unsigned char)(1u << (bit % 8));
        missed += wordsum(buf, sizeof buf) == ref;
        buf[bit / 8] ^= (unsigned char)(1u << (bit % 8));
    }
    for (int w = 0; w < 24; w++) { /* the word's bytes all changed */
        unsigned char keep[4];
        memcpy(keep, buf + 4 * w, 4);
        for (int k = 0; k < 4; k++)
            buf[4 * w + k] ^= (unsigned char)(0x5a + k);
        missed += wordsum(buf, sizeof buf) == ref;
        memcpy(buf + 4 * w, keep, 4);
    }
    CHECK_EQ_INT(missed, 0);
}

int main(void)
{
    RUN(wordsum_value_of_known_words);
    RUN(wordsum_join_matches_one_pass);
    RUN(wordsum_steps_match_word_by_word);
    RUN(wordsum_detects_word_changes);
    return check_exit();
}
