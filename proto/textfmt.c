/* textfmt.c: the shared formatter (see textfmt.h). */
#include "proto/textfmt.h"

#include <stdint.h>

struct fmt_out {
    char *buf;
    size_t cap;
    size_t len; /* characters produced so far, even past cap */
};

/* One conversion's flags, field width and precision. */
struct fmt_spec {
    int left;  /* '-': pad on the right */
    char pad;  /* ' ', or '0' for '0' without '-' and without a precision */
    int width; /* minimum field width */
    int prec;  /* precision, -1 when none was given */
};

static void fmt_putc(struct fmt_out *o, char c)
{
    if (o->len + 1 < o->cap)
        o->buf[o->len] = c;
    o->len++;
}

static void fmt_pad(struct fmt_out *o, char c, int n)
{
    while (n-- > 0)
        fmt_putc(o, c);
}

/* Writes text of length n into the field of spec s. */
static void fmt_field(struct fmt_out *o, const char *text, int n, const struct fmt_spec *s)
{
    if (!s->left)
        fmt_pad(o, s->pad, s->width - n);
    for (int i = 0; i < n; i++)
        fmt_putc(o, text[i]);
    if (s->left)
        fmt_pad(o, ' ', s->width - n);
}

static void fmt_number(struct fmt_out *o, unsigned long long v, int neg, unsigned base,
                       int upper, struct fmt_spec s)
{
    const char *digits = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    char tmp[24];
    int n = 0;
    if (v != 0 || s.prec != 0) {
        do {
            tmp[n++] = digits[v % base];
            v /= base;
        } while (v);
    }
    /* The precision is a minimum number of digits. */
    while (n < s.prec && n < (int)sizeof tmp - 1)
        tmp[n++] = '0';
    if (neg) {
        if (s.pad == '0' && !s.left) {
            /* The sign goes before the zero padding: -0042. */
            fmt_putc(o, '-');
            s.width--;
        } else {
            tmp[n++] = '-';
        }
    }
    char rev[24];
    for (int i = 0; i < n; i++)
        rev[i] = tmp[n - 1 - i];
    fmt_field(o, rev, n, &s);
}

/* Reads flags, width and precision after a '%'; returns where the length
 * modifier or conversion starts. */
static const char *fmt_parse_spec(const char *p, struct fmt_spec *s, va_list *ap)
{
    s->left = 0;
    s->pad = ' ';
    s->width = 0;
    s->prec = -1;
    for (;; p++) {
        if (*p == '-')
            s->left = 1;
        else if (*p == '0')
            s->pad = '0';
        else
            break;
    }
    if (*p == '*') {
        s->width = va_arg(*ap, int);
        if (s->width < 0) {
            s->left = 1;
            s->width = -s->width;
        }
        p++;
    } else {
        while (*p >= '0' && *p <= '9')
            s->width = s->width * 10 + (*p++ - '0');
    }
    if (*p == '.') {
        p++;
        s->prec = 0;
        if (*p == '*') {
            s->prec = va_arg(*ap, int);
            if (s->prec < 0)
                s->prec = -1; /* a negative precision counts as none */
            p++;
        } else {
            while (*p >= '0' && *p <= '9')
                s->prec = s->prec * 10 + (*p++ - '0');
        }
    }
    if (s->left || s->prec >= 0)
        s->pad = ' ';
    return p;
}

int fmt_vsnprintf(char *out, size_t cap, const char *fmt, va_list ap)
{
    struct fmt_out o = {out, cap, 0};
    va_list args;
    va_copy(args, ap);
    for (const char *p = fmt; *p; p++) {
        if (*p != '%') {
            fmt_putc(&o, *p);
            continue;
        }
        struct fmt_spec s;
        p = fmt_parse_spec(p + 1, &s, &args);
        int lng = 0; /* 0 int, 1 long, 2 long long, 3 size_t */
        if (*p == 'l') {
            lng = 1;
            if (*++p == 'l') {
                lng = 2;
                p++;
            }
        } else if (*p == 'z') {
            lng = 3;
            p++;
        }
        switch (*p) {
        case 'd':
        case 'i': {
            long long v = lng == 2 ? va_arg(args, long long)
                        : lng == 1 ? va_arg(args, long)
                        : lng == 3 ? (long long)va_arg(args, size_t)
                                   : va_arg(args, int);
            unsigned long long mag = v < 0 ? 0ull - (unsigned long long)v
                                           : (unsigned long long)v;
            fmt_number(&o, mag, v < 0, 10, 0, s);
            break;
        }
        case 'u':
        case 'x':
        case 'X': {
            unsigned long long v = lng == 2 ? va_arg(args, unsigned long long)
                                 : lng == 1 ? va_arg(args, unsigned long)
                                 : lng == 3 ? va_arg(args, size_t)
                                            : va_arg(args, unsigned);
            fmt_number(&o, v, 0, *p == 'u' ? 10 : 16, *p == 'X', s);
            break;
        }
        case 'p':
            fmt_putc(&o, '0');
            fmt_putc(&o, 'x');
            fmt_number(&o, (uintptr_t)va_arg(args, void *), 0, 16, 0, s);
            break;
        case 'c': {
            char c = (char)va_arg(args, int);
            s.pad = ' ';
            fmt_field(&o, &c, 1, &s);
            break;
        }
        case 's': {
            const char *str = va_arg(args, const char *);
            if (!str)
                str = "(null)";
            /* With a precision, no byte past it is read: the text need
             * not be NUL-terminated. */
            int n = 0;
            while ((s.prec < 0 || n < s.prec) && str[n])
                n++;
            s.pad = ' ';
            fmt_field(&o, str, n, &s);
            break;
        }
        case '%':
            fmt_putc(&o, '%');
            break;
        case '\0':
            p--; /* a lone '%' at the end: print nothing more */
            break;
        default:
            /* Unknown conversion: show it rather than guess. */
            fmt_putc(&o, '%');
            fmt_putc(&o, *p);
            break;
        }
    }
    va_end(args);
    if (cap)
        out[o.len < cap ? o.len : cap - 1] = '\0';
    return (int)o.len;
}

int fmt_snprintf(char *out, size_t cap, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = fmt_vsnprintf(out, cap, fmt, ap);
    va_end(ap);
    return n;
}
