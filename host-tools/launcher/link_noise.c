/* link_noise.c: byte damage for the host link's noise relay (see link_noise.h). */
#include "host-tools/launcher/link_noise.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static uint64_t noise_next(struct link_noise *z)
{
    /* splitmix64 */
    uint64_t x = (z->state += 0x9E3779B97F4A7C15ull);
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

void link_noise_init(struct link_noise *z, double rate, uint64_t seed)
{
    z->rate = rate;
    z->state = seed;
    z->bytes = z->flipped = z->dropped = z->duplicated = z->inserted = 0;
}

size_t link_noise_apply(struct link_noise *z, const uint8_t *in, size_t n, uint8_t *out)
{
    /* A byte is hit when a uniform 53-bit draw falls below rate * 2^53. */
    uint64_t limit = (uint64_t)(z->rate * 9007199254740992.0);
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        z->bytes++;
        uint8_t b = in[i];
        if (limit == 0 || (noise_next(z) >> 11) >= limit) {
            out[k++] = b;
            continue;
        }
        uint64_t r = noise_next(z);
        switch (r & 3) {
        case 0: out[k++] = (uint8_t)(b ^ (1u << ((r >> 2) & 7))); z->flipped++; break;
        case 1: z->dropped++; break;
        case 2: out[k++] = b; out[k++] = b; z->duplicated++; break;
        default: out[k++] = (uint8_t)(r >> 8); out[k++] = b; z->inserted++; break;
        }
    }
    return k;
}

int link_noise_parse(const char *s, double *rate, uint64_t *seed, char *why, size_t whylen)
{
    char *end;
    errno = 0;
    double r = strtod(s, &end);
    if (end == s || errno || !isfinite(r) || r < 0 || r > 1 || (*end && *end != ':')) {
        snprintf(why, whylen, "'%s': RATE must be a number from 0 to 1 (e.g. 1e-3), "
                 "optionally followed by :SEED", s);
        return -1;
    }
    uint64_t sd = 1;
    if (*end == ':') {
        const char *p = end + 1;
        errno = 0;
        unsigned long long v = strtoull(p, &end, 10);
        if (end == p || *end || errno || *p == '-') {
            snprintf(why, whylen, "'%s': SEED must be a non-negative integer", s);
            return -1;
        }
        sd = v;
    }
    *rate = r;
    *seed = sd;
    return 0;
}
