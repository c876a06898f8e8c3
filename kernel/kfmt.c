/* kfmt.c: the log formatter (see kfmt.h). */
#include "kernel/kfmt.h"

#include <stdint.h>

struct kfmt_out {
    char *buf;
    size_t cap;
    size_t len; /* characters produced so far, even past cap */
};

static void kfmt_putc(struct kfmt_out *o, char c)
{
    if (o->len + 1 < o->cap)
        o->buf[o->len] = c;
    o->len++;
}

static void kfmt_pad(struct kfmt_out *o, char c, int n)
{
    while (n-- > 0)
        kfmt_putc(o, c);
}

/* Writes text of length n into a field of width w. */
static void kfmt_field(struct kfmt_out *o, const char *s, int n, int w, int left,
                       char pad)
{
    if (!left)
        kfmt_pad(o, pad, w - n);
    for (int i = 0; i < n; i++)
        kfmt_putc(o, s[i]);
    if (left)
        kfmt_pad(o, ' ', w - n);
}

static void kfmt_number(struct kfmt_out *o, unsigned long long v, int neg,
                        unsigned base, int upper, int w, int left, char pad)
{
    const char *digits = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    char tmp[24];
    int n = 0;
    do {
        tmp[n++] = digits[v % base];
        v /= base;
    } while (v);
    if (neg) {
        if (pad == '0' && !left) {
            /* The sign goes before the zero padding: -0042. */
            kfmt_putc(o, '-');
            w--;
        } else {
            tmp[n++] = '-';
        }
    }
    char rev[24];
    for (int i = 0; i < n; i++)
        rev[i] = tmp[n - 1 - i];
    kfmt_field(o, rev, n, w, left, pad);
}

int kfmt_vsnprintf(char *out, size_t cap, const char *fmt, va_list ap)
{
    struct kfmt_out o = {out, cap, 0};
    for (const char *p = fmt; *p; p++) {
        if (*p != '%') {
            kfmt_putc(&o, *p);
            continue;
        }
        p++;
        int left = 0;
        char pad = ' ';
        for (;; p++) {
            if (*p == '-')
                left = 1;
            else if (*p == '0')
                pad = '0';
            else
                break;
        }
        int w = 0;
        while (*p >= '0' && *p <= '9')
            w = w * 10 + (*p++ - '0');
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
            long long v = lng == 2 ? va_arg(ap, long long)
                        : lng == 1 ? va_arg(ap, long)
                        : lng == 3 ? (long long)va_arg(ap, size_t)
                                   : va_arg(ap, int);
            unsigned long long mag = v < 0 ? 0ull - (unsigned long long)v
                                           : (unsigned long long)v;
            kfmt_number(&o, mag, v < 0, 10, 0, w, left, pad);
            break;
        }
        case 'u':
        case 'x':
        case 'X': {
            unsigned long long v = lng == 2 ? va_arg(ap, unsigned long long)
                                 : lng == 1 ? va_arg(ap, unsigned long)
                                 : lng == 3 ? va_arg(ap, size_t)
                                            : va_arg(ap, unsigned);
            kfmt_number(&o, v, 0, *p == 'u' ? 10 : 16, *p == 'X', w, left, pad);
            break;
        }
        case 'p':
            kfmt_putc(&o, '0');
            kfmt_putc(&o, 'x');
            kfmt_number(&o, (uintptr_t)va_arg(ap, void *), 0, 16, 0, w, left, pad);
            break;
        case 'c': {
            char c = (char)va_arg(ap, int);
            kfmt_field(&o, &c, 1, w, left, ' ');
            break;
        }
        case 's': {
            const char *s = va_arg(ap, const char *);
            if (!s)
                s = "(null)";
            int n = 0;
            while (s[n])
                n++;
            kfmt_field(&o, s, n, w, left, ' ');
            break;
        }
        case '%':
            kfmt_putc(&o, '%');
            break;
        case '\0':
            p--; /* a lone '%' at the end: print nothing more */
            break;
        default:
            /* Unknown conversion: show it rather than guess. */
            kfmt_putc(&o, '%');
            kfmt_putc(&o, *p);
            break;
        }
    }
    if (cap)
        out[o.len < cap ? o.len : cap - 1] = '\0';
    return (int)o.len;
}

int kfmt_snprintf(char *out, size_t cap, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = kfmt_vsnprintf(out, cap, fmt, ap);
    va_end(ap);
    return n;
}
