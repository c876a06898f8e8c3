/* board_text.h: text that came from the board (LOG lines, fault texts,
 * refusals, reports of dropped frames) made safe to print: a board, or
 * anything on the far end of the link, must not be able to drive the
 * terminal with escape sequences or hide what it printed behind control
 * characters. */
#ifndef LINKS1_HOST_BOARD_TEXT_H
#define LINKS1_HOST_BOARD_TEXT_H

#include <stddef.h>

/* Room board_text needs for n bytes of board text (the terminator too). */
#define BOARD_TEXT_CAP(n) (4 * (size_t)(n) + 1)

/* The n bytes at p into out as printable ASCII: ' '..'~' as they are but
 * '\\' as "\\\\", every other byte (control characters, ESC, bytes above
 * 0x7e) as "\xHH".  Always terminated; cut at a whole escape when cap is
 * short.  Returns out. */
char *board_text(const void *p, size_t n, char *out, size_t cap);

#endif
