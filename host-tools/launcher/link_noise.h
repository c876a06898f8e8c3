/* link_noise.h: the byte damage of `links1 render --link-noise RATE[:SEED]`
 * (a test hook): each byte passing through is, with probability RATE, hit by
 * one of four kinds of damage, chosen evenly: a bit flipped, the byte
 * dropped, the byte duplicated, or a random byte inserted before it.
 * Deterministic for a seed. */
#ifndef LINKS1_HOST_LINK_NOISE_H
#define LINKS1_HOST_LINK_NOISE_H

#include <stddef.h>
#include <stdint.h>

struct link_noise {
    double rate;      /* damage events per byte, 0..1 */
    uint64_t state;   /* PRNG state */
    uint64_t bytes;   /* bytes taken in */
    uint64_t flipped, dropped, duplicated, inserted;
};

void link_noise_init(struct link_noise *z, double rate, uint64_t seed);

/* Passes n bytes from in through the noise into out (room for 2 * n bytes);
 * returns the bytes written to out. */
size_t link_noise_apply(struct link_noise *z, const uint8_t *in, size_t n, uint8_t *out);

/* Parses "RATE[:SEED]" (RATE in 0..1); 0, or -1 with why filled. */
int link_noise_parse(const char *s, double *rate, uint64_t *seed, char *why, size_t whylen);

#endif
