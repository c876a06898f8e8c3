/* cli_opt.c: see cli_opt.h. */
#include "host-tools/opts/cli_opt.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cli_init(struct cli *c, const char *prog, int argc, char **argv, const char *shorts,
              const struct option *longs)
{
    memset(c, 0, sizeof *c);
    c->prog = prog;
    c->argc = argc;
    c->argv = argv;
    c->longs = longs;
    /* '-': operands in place; ':': a missing value returns ':' */
    snprintf(c->shorts, sizeof c->shorts, "-:%s", shorts);
    opterr = 0;
    optind = 0; /* glibc: start over from argv[1] */
}

/* The long option word names ("--na" or "--name=value"): the exact match,
 * else the only one it abbreviates; *matches counts those it abbreviates. */
static const struct option *cli_find(const struct cli *c, const char *word, int *matches)
{
    const char *name = word + 2;
    size_t n = strcspn(name, "=");
    const struct option *hit = NULL;
    *matches = 0;
    for (const struct option *o = c->longs; o && o->name; o++) {
        if (strncmp(o->name, name, n) != 0)
            continue;
        if (strlen(o->name) == n) {
            *matches = 1;
            return o;
        }
        ++*matches;
        hit = o;
    }
    return *matches == 1 ? hit : NULL;
}

/* Ends a usage error's line: where to read what is wanted. */
static void cli_see_help(const struct cli *c)
{
    fprintf(stderr, " (see %s --help)\n", c->prog);
}

/* Prints what is wrong with the option getopt_long just refused. */
static void cli_report(const struct cli *c, int code)
{
    const char *word = optind > 0 && optind <= c->argc ? c->argv[optind - 1] : "";
    int matches = 0;
    const struct option *o = strncmp(word, "--", 2) == 0 ? cli_find(c, word, &matches) : NULL;
    int is_long = strncmp(word, "--", 2) == 0 && (optopt == 0 || (o && o->val == optopt));
    if (!is_long && code == ':') {
        fprintf(stderr, "%s: -%c needs a value", c->prog, optopt);
    } else if (!is_long) {
        fprintf(stderr, "%s: unknown option '-%c'", c->prog, optopt);
    } else if (code == ':' && o) {
        fprintf(stderr, "%s: --%s needs a value", c->prog, o->name);
    } else if (o && o->has_arg == no_argument && strchr(word, '=')) {
        fprintf(stderr, "%s: --%s takes no value ('%s')", c->prog, o->name, word);
    } else if (matches > 1) {
        fprintf(stderr, "%s: '%s' is ambiguous: it could be", c->prog, word);
        size_t n = strcspn(word + 2, "=");
        for (const struct option *p = c->longs; p->name; p++)
            if (strncmp(p->name, word + 2, n) == 0)
                fprintf(stderr, " --%s", p->name);
    } else {
        fprintf(stderr, "%s: unknown option '%s'", c->prog, word);
    }
    cli_see_help(c);
}

/* Whether the value getopt_long just took for an option is the next word
 * and that word is itself a long option (`--name --help`): such a value
 * is refused, not taken; written `--name=--help` it is taken. */
static int cli_value_is_option(const struct cli *c)
{
    const char *word = optind > 0 && optind <= c->argc ? c->argv[optind - 1] : NULL;
    return optarg && optarg == word && strncmp(optarg, "--", 2) == 0 && optarg[2];
}

int cli_next(struct cli *c)
{
    c->arg = NULL;
    c->name[0] = 0;
    if (c->rest) {
        if (optind >= c->argc)
            return -1;
        c->arg = c->argv[optind++];
        return CLI_OPERAND;
    }
    int idx = -1;
    int code = getopt_long(c->argc, c->argv, c->shorts, c->longs, &idx);
    if (code == -1 && optind < c->argc) { /* "--" ends the options */
        c->rest = 1;
        return cli_next(c);
    }
    if (code == '?' || code == ':') {
        cli_report(c, code);
        return CLI_BAD;
    }
    if (cli_value_is_option(c)) {
        const char *opt = idx >= 0 ? c->longs[idx].name : NULL;
        if (opt)
            fprintf(stderr, "%s: --%s needs a value, not the option '%s' (--%s=%s gives it "
                    "that value)", c->prog, opt, optarg, opt, optarg);
        else
            fprintf(stderr, "%s: -%c needs a value, not the option '%s'", c->prog, code,
                    optarg);
        cli_see_help(c);
        return CLI_BAD;
    }
    c->arg = optarg;
    if (idx >= 0)
        snprintf(c->name, sizeof c->name, "--%s", c->longs[idx].name);
    else if (code != CLI_OPERAND && code != -1)
        snprintf(c->name, sizeof c->name, "-%c", code);
    return code;
}

int cli_operand_value(struct cli *c)
{
    snprintf(c->name, sizeof c->name, "%s", c->arg ? c->arg : "");
    if (optind >= c->argc) {
        fprintf(stderr, "%s: %s needs a value", c->prog, c->name);
        cli_see_help(c);
        return -1;
    }
    c->arg = c->argv[optind++];
    return 0;
}

int cli_bad_value(const struct cli *c, const char *want)
{
    fprintf(stderr, "%s: %s '%s': want %s", c->prog, c->name, c->arg ? c->arg : "", want);
    cli_see_help(c);
    return -1;
}

int cli_long(const struct cli *c, int base, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = c->arg ? strtol(c->arg, &end, base) : 0;
    if (!c->arg || errno || end == c->arg || *end || v < lo || v > hi) {
        char want[96];
        snprintf(want, sizeof want, "a whole number from %ld to %ld", lo, hi);
        return cli_bad_value(c, want);
    }
    *out = v;
    return 0;
}

int cli_int(const struct cli *c, int lo, int hi, int *out)
{
    long v;
    if (cli_long(c, 10, lo, hi, &v) < 0)
        return -1;
    *out = (int)v;
    return 0;
}

int cli_double(const struct cli *c, double lo, int lo_open, double hi, const char *want,
               double *out)
{
    char *end;
    errno = 0;
    double v = c->arg ? strtod(c->arg, &end) : 0;
    if (!c->arg || errno || end == c->arg || *end || !(v >= lo && v <= hi) ||
        (lo_open && v == lo)) {
        char range[96];
        snprintf(range, sizeof range, "a number from %g to %g", lo, hi);
        return cli_bad_value(c, want ? want : range);
    }
    *out = v;
    return 0;
}

int cli_usage_error(const char *prog, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", prog);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, " (see %s --help)\n", prog);
    return -1;
}

int cli_optdefs_table(const struct cli_optdef *const *lists, struct option *out, size_t cap)
{
    size_t n = 0;
    for (; *lists; lists++)
        for (const struct cli_optdef *d = *lists; d->name; d++) {
            if (n + 2 >= cap)
                return -1;
            int has = !d->value ? no_argument : *d->value ? required_argument
                                                          : optional_argument;
            out[n++] = (struct option){d->name, has, NULL, d->code};
        }
    out[n++] = (struct option){"help", no_argument, NULL, 'h'};
    out[n] = (struct option){NULL, 0, NULL, 0};
    return 0;
}

int cli_optdefs_pick(const struct cli_optdef *defs, const int *codes, size_t n,
                     struct cli_optdef *out, size_t cap)
{
    if (n >= cap)
        return -1;
    for (size_t i = 0; i < n; i++) {
        const struct cli_optdef *d = defs;
        while (d->name && d->code != codes[i])
            d++;
        if (!d->name)
            return -1;
        out[i] = *d;
    }
    out[n] = (struct cli_optdef)CLI_OPTDEF_END;
    return 0;
}

/* The help column: an option's text starts here. */
#define CLI_HELP_COLUMN 21

void cli_optdefs_help(FILE *f, const struct cli_optdef *defs)
{
    for (const struct cli_optdef *d = defs; d->name; d++) {
        int shown = d->value && *d->value;
        int w = fprintf(f, "  --%s%s%s", d->name, shown ? " " : "", shown ? d->value : "");
        const char *line = d->help;
        if (w >= CLI_HELP_COLUMN - 1)
            w = fprintf(f, "\n") - 1;
        while (line) {
            const char *end = strchr(line, '\n');
            int len = end ? (int)(end - line) : (int)strlen(line);
            fprintf(f, "%*s%.*s\n", CLI_HELP_COLUMN - w, "", len, line);
            w = 0;
            line = end ? end + 1 : NULL;
        }
    }
}
