/* scene_lex.c: tokenizer of the text scene format (see scene_lex.h). */
#include "host-tools/scene/scene_lex.h"

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void lex_init(struct lex *lx, const char *file, const char *text, jmp_buf *fail,
              char *err, size_t errlen)
{
    memset(lx, 0, sizeof *lx);
    lx->file = file;
    lx->text = text;
    lx->line = 1;
    lx->col = 1;
    lx->fail = fail;
    lx->err = err;
    lx->errlen = errlen;
}

void lex_error(struct lex *lx, const char *fmt, ...)
{
    int n = snprintf(lx->err, lx->errlen, "%s:%d:%d: ", lx->file, lx->tok_line,
                     lx->tok_col);
    if (n >= 0 && (size_t)n < lx->errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(lx->err + n, lx->errlen - (size_t)n, fmt, ap);
        va_end(ap);
    }
    longjmp(*lx->fail, 1);
}

static int lex_peekc(const struct lex *lx) { return (unsigned char)lx->text[lx->pos]; }

static void lex_advance(struct lex *lx)
{
    if (lx->text[lx->pos] == '\n') {
        lx->line++;
        lx->col = 1;
    } else {
        lx->col++;
    }
    lx->pos++;
}

static void lex_skip_space(struct lex *lx)
{
    for (;;) {
        int c = lex_peekc(lx);
        if (c == '#') {
            while (lex_peekc(lx) && lex_peekc(lx) != '\n')
                lex_advance(lx);
        } else if (c && isspace(c)) {
            lex_advance(lx);
        } else {
            return;
        }
    }
}

/* A word goes on through letters, digits, '_', '.' and '-' (never the
 * text's ending NUL). */
static int lex_word_char(int c)
{
    return isalnum(c) || c == '_' || c == '.' || c == '-';
}

/* A number goes on to a space, a brace, '#', '"' or the text's end. */
static int lex_number_char(int c)
{
    return c && !isspace(c) && c != '{' && c != '}' && c != '#' && c != '"';
}

/* Exact powers of ten: 10^22 is the last a double holds exactly. */
static const double lex_pow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                   1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                   1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

int lex_decimal(const char *s, double *out)
{
    int neg = *s == '-';
    if (*s == '-' || *s == '+')
        s++;
    uint64_t m = 0;
    int digits = 0, scale = 0; /* value = m * 10^scale */
    for (; isdigit((unsigned char)*s); s++, digits++)
        m = m * 10 + (uint64_t)(*s - '0');
    if (*s == '.')
        for (s++; isdigit((unsigned char)*s); s++, digits++, scale--)
            m = m * 10 + (uint64_t)(*s - '0');
    if (*s == 'e' || *s == 'E') {
        const char *e = s + 1;
        int eneg = *e == '-';
        if (*e == '-' || *e == '+')
            e++;
        int x = 0, xd = 0;
        for (; isdigit((unsigned char)*e) && xd < 4; e++, xd++)
            x = x * 10 + (*e - '0');
        if (xd == 0 || isdigit((unsigned char)*e))
            return 0;
        scale += eneg ? -x : x;
        s = e;
    }
    /* Up to 15 digits hold m below 2^53, so m and 10^|scale| are doubles
     * and one division or product rounds the decimal once, as strtod
     * does (round to nearest, doubles evaluated as doubles). */
    if (*s != 0 || digits == 0 || digits > 15 || scale < -22 || scale > 22 ||
        FLT_EVAL_METHOD != 0)
        return 0;
    double v = (double)m;
    v = scale < 0 ? v / lex_pow10[-scale] : v * lex_pow10[scale];
    *out = neg ? -v : v;
    return 1;
}

static void lex_take(struct lex *lx, size_t *n)
{
    if (*n + 1 >= sizeof lx->tok)
        lex_error(lx, "token longer than %d characters", LEX_TOKEN_MAX - 1);
    lx->tok[(*n)++] = (char)lex_peekc(lx);
    lex_advance(lx);
}

void lex_next(struct lex *lx)
{
    lex_skip_space(lx);
    lx->tok_line = lx->line;
    lx->tok_col = lx->col;
    size_t n = 0;
    int c = lex_peekc(lx);
    if (c == 0) {
        lx->kind = LEX_END;
        strcpy(lx->tok, "end of file");
        return;
    }
    if (c == '{' || c == '}') {
        lx->kind = c == '{' ? LEX_OPEN : LEX_CLOSE;
        lex_take(lx, &n);
    } else if (isalpha(c) || c == '_') {
        lx->kind = LEX_WORD;
        while (lex_word_char(lex_peekc(lx)))
            lex_take(lx, &n);
    } else if (isdigit(c) || c == '-' || c == '+' || c == '.') {
        lx->kind = LEX_NUMBER;
        while (lex_number_char(lex_peekc(lx)))
            lex_take(lx, &n);
        lx->tok[n] = 0;
        char *end = lx->tok + n;
        if (!lex_decimal(lx->tok, &lx->num)) /* the rest: strtod's */
            lx->num = strtod(lx->tok, &end);
        if (*end != 0 || end == lx->tok)
            lex_error(lx, "'%s' is not a number", lx->tok);
        if (!isfinite(lx->num))
            lex_error(lx, "'%s' is not a finite number", lx->tok);
    } else if (c == '"') {
        lx->kind = LEX_STRING;
        lex_advance(lx);
        while (lex_peekc(lx) != '"') {
            if (lex_peekc(lx) == 0 || lex_peekc(lx) == '\n')
                lex_error(lx, "string not closed on its line");
            lex_take(lx, &n);
        }
        lex_advance(lx);
    } else {
        lex_error(lx, "unexpected character '%c'", c);
    }
    lx->tok[n] = 0;
}

int lex_is_word(const struct lex *lx, const char *w)
{
    return lx->kind == LEX_WORD && strcmp(lx->tok, w) == 0;
}

void lex_expect(struct lex *lx, enum lex_kind kind, const char *what)
{
    if (lx->kind != kind)
        lex_error(lx, "expected %s, found '%s'", what, lx->tok);
    lex_next(lx);
}

double lex_number(struct lex *lx, const char *what)
{
    if (lx->kind != LEX_NUMBER)
        lex_error(lx, "expected a number (%s), found '%s'", what, lx->tok);
    double v = lx->num;
    lex_next(lx);
    return v;
}

double lex_number_in(struct lex *lx, const char *what, double lo, double hi)
{
    if (lx->kind == LEX_NUMBER && (lx->num < lo || lx->num > hi))
        lex_error(lx, "%s must be %g..%g, not %s", what, lo, hi, lx->tok);
    return lex_number(lx, what);
}

int lex_int(struct lex *lx, const char *what, int lo, int hi)
{
    if (lx->kind != LEX_NUMBER)
        lex_error(lx, "expected an integer (%s), found '%s'", what, lx->tok);
    double v = lx->num;
    if (v != floor(v))
        lex_error(lx, "%s must be a whole number, not %s", what, lx->tok);
    if (v < lo || v > hi)
        lex_error(lx, "%s must be %d..%d, not %s", what, lo, hi, lx->tok);
    lex_next(lx);
    return (int)v;
}

void lex_vec3(struct lex *lx, const char *what, double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = lex_number(lx, what);
}

void lex_word(struct lex *lx, const char *what, char *out, size_t outlen)
{
    if (lx->kind != LEX_WORD)
        lex_error(lx, "expected %s, found '%s'", what, lx->tok);
    if (strlen(lx->tok) >= outlen)
        lex_error(lx, "%s '%s' is longer than %zu characters", what, lx->tok,
                  outlen - 1);
    strcpy(out, lx->tok);
    lex_next(lx);
}
