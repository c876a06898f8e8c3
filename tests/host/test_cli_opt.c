/* test_cli_opt.c: the argument reader every links1 command uses
 * (host-tools/opts/cli_opt.c) and the board options (board_opt): operands keep
 * their place among options, "--" ends the options, and every bad option or
 * value is refused with a message naming it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/launcher/launcher.h"
#include "host-tools/opts/cli_opt.h"
#include "tests/check.h"
#include "tests/host/capture.h"

enum { T_SIZE = CLI_OWN_CODES, T_PPM, T_FRAME, T_FRAMES };

static const struct cli_optdef t_optdefs[] = {
    {"size", "WxH", T_SIZE, "the size"},
    {"ppm", NULL, T_PPM, "write PPM\nnot PNG"},
    {"frame", "N", T_FRAME, "one frame"},
    {"frames", "A:B", T_FRAMES, "frames A..B"},
    CLI_OPTDEF_END,
};
static struct option t_options[64]; /* board_optdefs and t_optdefs (main makes it) */

/* What cli_next returned over an argv: the codes (with operands and
 * values in args) and what was printed on stderr. */
struct t_seen {
    int n;
    int codes[16];
    const char *args[16];
    char msg[256];
};

/* Runs cli_next over argv (NULL-terminated) until the end or the first
 * CLI_BAD, into *s. */
static void t_read(char **argv, struct t_seen *s)
{
    int argc = 0;
    while (argv[argc])
        argc++;
    struct capture cap;
    capture_begin(&cap, STDERR_FILENO);
    struct cli c;
    cli_init(&c, "links1 test", argc, argv, "o:h", t_options);
    s->n = 0;
    for (int code; s->n < 16 && (code = cli_next(&c)) != -1;) {
        s->codes[s->n] = code;
        s->args[s->n++] = c.arg;
        if (code == CLI_BAD)
            break;
    }
    capture_end(&cap, s->msg, sizeof s->msg);
}

static void test_operands_keep_their_place(void)
{
    char *argv[] = {"render", "a.scn", "-o", "a.png", "--ppm", "b.scn", "-ob.png",
                    "--size=40x30", "--", "--c.scn", NULL};
    struct t_seen s;
    t_read(argv, &s);
    CHECK_EQ_INT(s.n, 7);
    CHECK(s.codes[0] == CLI_OPERAND && strcmp(s.args[0], "a.scn") == 0);
    CHECK(s.codes[1] == 'o' && strcmp(s.args[1], "a.png") == 0);
    CHECK(s.codes[2] == T_PPM);
    CHECK(s.codes[3] == CLI_OPERAND && strcmp(s.args[3], "b.scn") == 0);
    CHECK(s.codes[4] == 'o' && strcmp(s.args[4], "b.png") == 0);
    CHECK(s.codes[5] == T_SIZE && strcmp(s.args[5], "40x30") == 0);
    CHECK(s.codes[6] == CLI_OPERAND && strcmp(s.args[6], "--c.scn") == 0);
    CHECK(s.msg[0] == 0);
}

/* Expects argv to end in CLI_BAD with a message containing want. */
static int t_refused(char **argv, const char *want)
{
    struct t_seen s;
    t_read(argv, &s);
    if (s.n > 0 && s.codes[s.n - 1] == CLI_BAD && strstr(s.msg, want))
        return 1;
    printf("  (got: %s)\n", s.msg);
    return 0;
}

static void test_bad_options_named(void)
{
    char *unknown[] = {"x", "a", "--sise", "3", NULL};
    CHECK(t_refused(unknown, "links1 test: unknown option '--sise' (see links1 test --help)"));
    char *short_unknown[] = {"x", "-x", NULL};
    CHECK(t_refused(short_unknown, "links1 test: unknown option '-x' (see links1 test --help)"));
    char *missing[] = {"x", "a", "--size", NULL};
    CHECK(t_refused(missing, "links1 test: --size needs a value"));
    char *missing_short[] = {"x", "a", "-o", NULL};
    CHECK(t_refused(missing_short, "links1 test: -o needs a value"));
    char *no_value[] = {"x", "--ppm=1", NULL};
    CHECK(t_refused(no_value, "links1 test: --ppm takes no value"));
    char *ambiguous[] = {"x", "--fr", "1", NULL};
    CHECK(t_refused(ambiguous, "'--fr' is ambiguous: it could be --frame --frames"));
    /* an option where a value should be is not taken for it (`board
     * start --name --help` once started a board named --help) */
    char *option_as_value[] = {"x", "--size", "--help", NULL};
    CHECK(t_refused(option_as_value, "links1 test: --size needs a value, not the option "
                                     "'--help' (--size=--help gives it that value) (see "
                                     "links1 test --help)"));
    char *option_as_short_value[] = {"x", "-o", "--ppm", NULL};
    CHECK(t_refused(option_as_short_value, "links1 test: -o needs a value, not the option "
                                           "'--ppm'"));
}

/* A value written with '=' is taken as it is, and a single dash (a
 * negative number) after an option is its value. */
static void test_values_like_options_written_out(void)
{
    char *argv[] = {"x", "--size=--odd", "-o", "-5", "-o--x", NULL};
    struct t_seen s;
    t_read(argv, &s);
    CHECK_EQ_INT(s.n, 3);
    CHECK(s.codes[0] == T_SIZE && strcmp(s.args[0], "--odd") == 0);
    CHECK(s.codes[1] == 'o' && strcmp(s.args[1], "-5") == 0);
    CHECK(s.codes[2] == 'o' && strcmp(s.args[2], "--x") == 0);
    CHECK(s.msg[0] == 0);
}

/* Runs board_opt on the one option in argv; returns its result, message in msg. */
static int t_board(char **argv, struct board_opts *o, char *msg, size_t msglen)
{
    int argc = 0;
    while (argv[argc])
        argc++;
    struct capture cap;
    capture_begin(&cap, STDERR_FILENO);
    struct cli c;
    cli_init(&c, "links1 test", argc, argv, "o:h", t_options);
    int code = cli_next(&c);
    int r = board_opt(o, &c, code);
    capture_end(&cap, msg, msglen);
    return r;
}

static void test_board_options(void)
{
    struct board_opts o;
    char msg[256];
    board_opts_init(&o);
    char *ncs[] = {"x", "--ncs", "64", NULL};
    CHECK_EQ_INT(t_board(ncs, &o, msg, sizeof msg), 1);
    CHECK_EQ_INT(o.ncores, 66);
    char *arith[] = {"x", "--arith=fixed", NULL};
    CHECK_EQ_INT(t_board(arith, &o, msg, sizeof msg), 1);
    CHECK(strcmp(o.arith, "fixed") == 0);
    char *quiet[] = {"x", "--quiet", NULL};
    CHECK_EQ_INT(t_board(quiet, &o, msg, sizeof msg), 1);
    CHECK_EQ_INT(o.quiet, 1);
    char *own[] = {"x", "--ppm", NULL};
    CHECK_EQ_INT(t_board(own, &o, msg, sizeof msg), 0);
    char *few[] = {"x", "--ncs", "0", NULL};
    CHECK_EQ_INT(t_board(few, &o, msg, sizeof msg), -1);
    CHECK(strstr(msg, "--ncs '0': want a whole number from 1 to 254 (see links1 test --help)") !=
          NULL);
    char *junk[] = {"x", "--ram", "12x", NULL};
    CHECK_EQ_INT(t_board(junk, &o, msg, sizeof msg), -1);
    CHECK(strstr(msg, "--ram '12x': want a whole number") != NULL);
    char *bad_arith[] = {"x", "--arith", "quad", NULL};
    CHECK_EQ_INT(t_board(bad_arith, &o, msg, sizeof msg), -1);
    CHECK(strstr(msg, "--arith 'quad': want float, soft, fixed, double or (render) auto") != NULL);
    CHECK_EQ_INT(o.ncores, 66); /* refused values change nothing */
    CHECK(strcmp(o.arith, "fixed") == 0);
}

static void test_numbers(void)
{
    struct cli c;
    char *argv[] = {"x", "--size", "0x20", NULL};
    cli_init(&c, "links1 test", 3, argv, "", t_options);
    CHECK_EQ_INT(cli_next(&c), T_SIZE);
    long v = 0;
    CHECK_EQ_INT(cli_long(&c, 0, 1, 100, &v), 0);
    CHECK_EQ_INT(v, 32);
    double d = 0;
    fflush(stderr);
    int saved = dup(2);
    FILE *null = fopen("/dev/null", "w");
    dup2(fileno(null), 2);
    CHECK_EQ_INT(cli_long(&c, 10, 1, 100, &v), -1); /* "0x20" is no base-10 number */
    /* each end of the range holds, one past it does not: the value is left alone */
    int n = 7;
    c.arg = "100";
    CHECK_EQ_INT(cli_long(&c, 10, 1, 100, &v), 0);
    CHECK_EQ_INT(v, 100);
    c.arg = "101";
    CHECK_EQ_INT(cli_long(&c, 10, 1, 100, &v), -1);
    CHECK_EQ_INT(v, 100);
    c.arg = "0";
    CHECK_EQ_INT(cli_long(&c, 10, 1, 100, &v), -1);
    c.arg = "65";
    CHECK_EQ_INT(cli_int(&c, 2, 64, &n), -1);
    CHECK_EQ_INT(n, 7);
    c.arg = "64";
    CHECK_EQ_INT(cli_int(&c, 2, 64, &n), 0);
    CHECK_EQ_INT(n, 64);
    CHECK_EQ_INT(cli_double(&c, 0, 1, 1e6, NULL, &d), 0);
    c.arg = "0";
    CHECK_EQ_INT(cli_double(&c, 0, 1, 1e6, "a positive number", &d), -1);
    c.arg = "nan";
    CHECK_EQ_INT(cli_double(&c, 0, 0, 1, NULL, &d), -1);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    fclose(null);
}

/* The getopt table and the help lines come from the same definitions:
 * every definition is in the table (with --help), and each shows in the
 * help as "  --name VALUE" with its text from column 21, a text's second
 * line below it; a table too small is refused. */
static void test_optdefs(void)
{
    static const struct cli_optdef *const lists[] = {t_optdefs, NULL};
    struct option small[3], table[8];
    CHECK_EQ_INT(cli_optdefs_table(lists, small, 3), -1);
    CHECK_EQ_INT(cli_optdefs_table(lists, table, 8), 0);
    CHECK(strcmp(table[1].name, "ppm") == 0 && table[1].has_arg == no_argument &&
          table[1].val == T_PPM);
    CHECK(strcmp(table[0].name, "size") == 0 && table[0].has_arg == required_argument);
    CHECK(strcmp(table[4].name, "help") == 0 && table[5].name == NULL);
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    cli_optdefs_help(f, t_optdefs);
    fclose(f);
    CHECK(strstr(text, "  --size WxH         the size\n") != NULL);
    CHECK(strstr(text, "  --ppm              write PPM\n                     not PNG\n") != NULL);
    free(text);
}

/* A command's share of another's table: the definitions picked by code,
 * in the order asked, ended; a code not there or no room is refused. */
static void test_optdefs_pick(void)
{
    struct cli_optdef out[3];
    const int codes[] = {T_FRAMES, T_PPM}, missing[] = {T_SIZE, T_FRAMES + 100};
    CHECK_EQ_INT(cli_optdefs_pick(t_optdefs, codes, 2, out, 3), 0);
    CHECK(strcmp(out[0].name, "frames") == 0 && strcmp(out[0].value, "A:B") == 0 &&
          out[0].code == T_FRAMES && strcmp(out[0].help, "frames A..B") == 0);
    CHECK(strcmp(out[1].name, "ppm") == 0 && out[1].value == NULL && out[2].name == NULL);
    CHECK_EQ_INT(cli_optdefs_pick(t_optdefs, codes, 2, out, 2), -1);
    CHECK_EQ_INT(cli_optdefs_pick(t_optdefs, missing, 2, out, 3), -1);
}

int main(void)
{
    static const struct cli_optdef *const lists[] = {board_optdefs, t_optdefs, NULL};
    if (cli_optdefs_table(lists, t_options, sizeof t_options / sizeof t_options[0]) != 0)
        return 1;
    RUN(test_optdefs);
    RUN(test_optdefs_pick);
    RUN(test_operands_keep_their_place);
    RUN(test_bad_options_named);
    RUN(test_values_like_options_written_out);
    RUN(test_board_options);
    RUN(test_numbers);
    return check_exit();
}
