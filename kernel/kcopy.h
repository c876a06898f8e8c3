/* kcopy.h: memory copy a word at a time.  The board's C library copies
 * byte by byte (four instructions a byte); every line message goes through
 * a ring.  (Blocks that grow with the scene, the prepared frame the RC
 * forwards, go eight words a step: render/words.h.)
 * No hardware access: the host tests build it. */
#ifndef LINKS1_KERNEL_KCOPY_H
#define LINKS1_KERNEL_KCOPY_H

#include <stddef.h>
#include <stdint.h>

/* Copies n bytes from src to dst (not overlapping): a word per step while
 * both are word-aligned, the rest byte by byte.  Inline and simple: the
 * lines copy a few words at a time, where a call or an unrolled loop's
 * set-up would cost as much as the copy. */
static inline void kcopy(void *dst, const void *src, size_t n)
{
    uint8_t *d = dst;
    const uint8_t *s = src;
    if ((((uintptr_t)d | (uintptr_t)s) & 3u) == 0) {
        for (; n >= 4; n -= 4, d += 4, s += 4) {
            uint32_t w; /* a fixed-size copy: one word load and store */
            __builtin_memcpy(&w, s, 4);
            __builtin_memcpy(d, &w, 4);
        }
    }
    while (n--)
        *d++ = *s++;
}

#endif
