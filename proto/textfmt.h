/* textfmt.h: the one printf-style formatter of links1: the kernel's log
 * lines and panics, the drivers' error results, the scene loader's and the
 * blob builder's messages.  It needs no stdio from either C library and
 * touches no hardware, so the firmware and the host tools share it.
 *
 * Conversions: %d %i %u %x %X %p %c %s %%, with flags '-' and '0', a field
 * width and a precision (digits or '*'; for %s the most bytes read, so
 * "%.*s" prints text that is not NUL-terminated), and the length modifiers
 * l, ll and z.  Output is always
 * NUL-terminated (when cap > 0) and cut at cap-1; the return value is the
 * length the full text would have had, as with snprintf. */
#ifndef LINKS1_PROTO_TEXTFMT_H
#define LINKS1_PROTO_TEXTFMT_H

#include <stdarg.h>
#include <stddef.h>

int fmt_vsnprintf(char *out, size_t cap, const char *fmt, va_list ap);
int fmt_snprintf(char *out, size_t cap, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
