/* render/words.h: large blocks copied and zeroed eight words a step.
 *
 * The board's C library copies and fills byte by byte (about four
 * instructions a byte).  Two blocks grow with the scene every frame: the
 * arena's zeroed arrays the DM prepares a frame into (render/arena.c), and
 * the prepared blob the RC copies into the broadcast block
 * (render_blob_copy).  Both go through here, 32 bytes a step (the compiler
 * makes each step load-multiple / store-multiple), so a triangle's few
 * hundred bytes cost tens of instructions, not a thousand.
 *
 * Small copies (a line message's few words) stay with kernel/kcopy.h,
 * inline, where a call's set-up would cost as much as the copy.
 * No hardware access, no num_t: the host tests build it. */
#ifndef LINKS1_RENDER_WORDS_H
#define LINKS1_RENDER_WORDS_H

#include <stddef.h>

/* Bytes moved per step of the loops: eight 32-bit words. */
#define WORDS_STEP_BYTES 32

/* Copies n bytes from src to dst (not overlapping): whole steps while both
 * are word-aligned, the rest a word, then a byte, at a time. */
void words_copy(void *dst, const void *src, size_t n);

/* Sets n bytes at dst to zero, the same way. */
void words_zero(void *dst, size_t n);

#endif
