/* scene_lex.h: the tokenizer of the text scene format.
 *
 * Tokens: words ([A-Za-z_][A-Za-z0-9_.-]*), numbers (anything strtod reads,
 * starting with a digit, sign or point), strings ("..." without escapes or
 * newlines), and the braces.  '#' starts a comment to the end of the line.
 * Errors leave through longjmp to the parser's recovery point with
 * "file:line:col: what" in the error buffer, so no caller sees a half-read
 * value.
 */
#ifndef LINKS1_HOST_SCENE_LEX_H
#define LINKS1_HOST_SCENE_LEX_H

#include <setjmp.h>
#include <stddef.h>

#define LEX_TOKEN_MAX 256 /* longest word, number or string */

enum lex_kind { LEX_END, LEX_WORD, LEX_NUMBER, LEX_STRING, LEX_OPEN, LEX_CLOSE };

struct lex {
    const char *file;       /* name for messages */
    const char *text;
    size_t pos;
    int line, col;          /* of the next unread character */
    /* the current token */
    enum lex_kind kind;
    char tok[LEX_TOKEN_MAX];
    double num;
    int tok_line, tok_col;
    /* error exit */
    jmp_buf *fail;
    char *err;
    size_t errlen;
};

void lex_init(struct lex *lx, const char *file, const char *text, jmp_buf *fail,
              char *err, size_t errlen);
void lex_next(struct lex *lx);                /* reads the next token */
/* A number token of up to 15 decimal digits and a power of ten within
 * 10^+-22 (most of a scene's): 1 and its value, the double strtod gives;
 * 0 for the rest, which lex_next hands to strtod. */
int lex_decimal(const char *s, double *out);
void lex_error(struct lex *lx, const char *fmt, ...)
    __attribute__((noreturn, format(printf, 2, 3)));

/* Helpers that consume the current token or fail naming what was expected. */
int lex_is_word(const struct lex *lx, const char *w);
void lex_expect(struct lex *lx, enum lex_kind kind, const char *what);
double lex_number(struct lex *lx, const char *what);
double lex_number_in(struct lex *lx, const char *what, double lo, double hi);
int lex_int(struct lex *lx, const char *what, int lo, int hi);
void lex_vec3(struct lex *lx, const char *what, double v[3]);
void lex_word(struct lex *lx, const char *what, char *out, size_t outlen);

#endif
