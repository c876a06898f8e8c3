/* board_text.c: the board's text escaped for printing (board_text.h). */
#include "host-tools/link/board_text.h"

#include <stdio.h>

char *board_text(const void *p, size_t n, char *out, size_t cap)
{
    const unsigned char *s = p;
    size_t k = 0;
    if (cap == 0)
        return out;
    for (size_t i = 0; i < n; i++) {
        char esc[5];
        size_t len;
        if (s[i] == '\\') {
            esc[0] = esc[1] = '\\';
            len = 2;
        } else if (s[i] >= ' ' && s[i] <= '~') {
            esc[0] = (char)s[i];
            len = 1;
        } else {
            snprintf(esc, sizeof esc, "\\x%02x", s[i]);
            len = 4;
        }
        if (k + len >= cap)
            break;
        for (size_t j = 0; j < len; j++)
            out[k++] = esc[j];
    }
    out[k] = 0;
    return out;
}
