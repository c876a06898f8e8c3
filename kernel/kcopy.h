/* kcopy.h: memory copy a word at a time, inline, for the few words of a
 * line message on its way through a ring (larger copies: the firmware's
 * memcpy, kernel/mem.c).
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
