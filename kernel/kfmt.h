/* kfmt.h: a small printf-style formatter for log lines and panics, so the
 * firmware needs no stdio from either C library.  No hardware access: the
 * host tests build it too.
 *
 * Conversions: %d %i %u %x %X %p %c %s %%, with flags '-' and '0', a field
 * width, and the length modifiers l, ll and z.  Output is always
 * NUL-terminated (when cap > 0) and cut at cap-1; the return value is the
 * length the full text would have had, as with snprintf. */
#ifndef LINKS1_KERNEL_KFMT_H
#define LINKS1_KERNEL_KFMT_H

#include <stdarg.h>
#include <stddef.h>

int kfmt_vsnprintf(char *out, size_t cap, const char *fmt, va_list ap);
int kfmt_snprintf(char *out, size_t cap, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
