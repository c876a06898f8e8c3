/* cli_opt.h: how every host program of links1 reads its arguments:
 * getopt_long in argument order (an operand comes back where it stands, so
 * "SCENE -o OUT SCENE2 -o OUT2" keeps its pairs), and one style of error
 * that names the option and what it wants:
 *
 *   links1 render: --ncs '0': want a whole number from 1 to 254 (see links1 render --help)
 *   links1 render: --size needs a value (see links1 render --help)
 *   links1 render: unknown option '--sise' (see links1 render --help)
 *
 * A command defines each option once, as a struct cli_optdef: getopt's
 * table and the --help lines are made from the same definitions, so the
 * help names every option the command takes and nothing else.
 */
#ifndef LINKS1_HOST_CLI_OPT_H
#define LINKS1_HOST_CLI_OPT_H

#include <getopt.h>
#include <stddef.h>
#include <stdio.h>

#define CLI_OPERAND 1    /* cli_next: an argument that is not an option (in c->arg) */
#define CLI_BAD '?'      /* cli_next: a bad option, already reported */
/* Long-option codes: the board's (board.h) from CLI_BOARD_CODES, a
 * command's own from CLI_OWN_CODES; short options are their letter. */
#define CLI_BOARD_CODES 0x100
#define CLI_SCENE_CODES 0x180
#define CLI_OWN_CODES 0x200

struct cli {
    const char *prog;           /* "links1 render": the start of every message */
    int argc;
    char **argv;                /* argv[0] is the command's own name */
    const struct option *longs; /* ends with an all-zero entry */
    char shorts[32];            /* "-:" and the short options */
    const char *arg;            /* the option's value, or the operand */
    char name[64];              /* the option just read as written: "--size", "-o" */
    int rest;                   /* 1 after "--": everything left is an operand */
};

/* Starts reading argv[1..argc-1]; shorts as for getopt ("o:h"). */
void cli_init(struct cli *c, const char *prog, int argc, char **argv, const char *shorts,
              const struct option *longs);

/* The next option's code (its letter or long-option val), CLI_OPERAND, -1
 * at the end, or CLI_BAD after printing what is wrong (unknown, ambiguous,
 * missing value, value given to an option that takes none). */
int cli_next(struct cli *c);

/* The word right after the operand just read, as that operand's value
 * (selftest's "fault CORE"): 0 with c->arg set and c->name the operand,
 * or -1 after printing "PROG: OPERAND needs a value". */
int cli_operand_value(struct cli *c);

/* c->arg as a whole number in [lo, hi] (base 0 also takes 0x...).
 * 0, or -1 after printing "PROG: NAME 'ARG': want ...". */
int cli_long(const struct cli *c, int base, long lo, long hi, long *out);
int cli_int(const struct cli *c, int lo, int hi, int *out);
/* c->arg as a number in [lo, hi], the more than lo when lo_open; want
 * names what is wanted in the error (NULL: "a number from LO to HI"). */
int cli_double(const struct cli *c, double lo, int lo_open, double hi, const char *want,
               double *out);

/* Prints "PROG: NAME 'ARG': want WANT (see PROG --help)" for the option
 * just read; returns -1. */
int cli_bad_value(const struct cli *c, const char *want);

/* Prints "PROG: WHAT (see PROG --help)" for a usage error of the command
 * line as a whole (a missing operand, two options that do not go
 * together); returns -1.  The command then exits 2. */
__attribute__((format(printf, 2, 3))) int cli_usage_error(const char *prog, const char *fmt,
                                                          ...);

/* One option of a command. */
struct cli_optdef {
    const char *name;  /* its long name, without "--" */
    const char *value; /* what its value is called in the help ("N", "on|off"); NULL:
                          none; "": none shown, but a value given is still read
                          (getopt's optional_argument) for the option to refuse it */
    int code;          /* what cli_next returns for it */
    const char *help;  /* what it does: lines separated by '\n' */
};
#define CLI_OPTDEF_END {NULL, NULL, 0, NULL}

/* A number's macro as text, for a help line: "1.." CLI_STR(FILM_MAX_FPS). */
#define CLI_STR_(x) #x
#define CLI_STR(x) CLI_STR_(x)

/* getopt's table for the definitions of lists (a NULL-terminated list of
 * tables, each ending with CLI_OPTDEF_END), --help added, into out (cap
 * entries).  0, or -1 when out is too small. */
int cli_optdefs_table(const struct cli_optdef *const *lists, struct option *out, size_t cap);

/* The definitions of defs that codes[0..n-1] name, in that order, into
 * out (cap entries, CLI_OPTDEF_END added): the options a command shares
 * with another command's table, defined there once.  0, or -1 when a code
 * is not in defs or out is too small. */
int cli_optdefs_pick(const struct cli_optdef *defs, const int *codes, size_t n,
                     struct cli_optdef *out, size_t cap);

/* The help lines of defs: "  --name VALUE" and its text from column 21. */
void cli_optdefs_help(FILE *f, const struct cli_optdef *defs);

#endif
