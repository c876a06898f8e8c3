/* cmd_selftest.c: `links1 selftest NAME...`: boots the board once, waits for
 * every unit computer to report in, then runs each named check in order and
 * prints "selftest NAME: ok: ..." or "selftest NAME: FAILED: why".  The
 * board tests in tests/board/ are built on these lines. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/launcher/launcher.h"
#include "host-tools/cli/links1_cmds.h"
#include "host-tools/selftest/selftest.h"
#include "host-tools/opts/tmp_dir.h"

static const struct selftest selftests[] = {
    {"status", "the board counts every unit computer", selftest_status},
    {"ping", "ping-pong over every serial line (DM-RC, RC-each NC)", selftest_ping},
    {"imsu", "the DM's memcpy and memset, then IMSU swap both ways and broadcast, checksummed",
     selftest_imsu},
    {"stress", "--mib MiB (default 64) through the inter-unit lines", selftest_stress},
    {"link-sink", "--bytes N (default 8 MiB) of the pattern host -> board", selftest_link_sink},
    {"link-source", "--bytes N (default 8 MiB) of the pattern board -> host",
     selftest_link_source},
    {"fault", "CORE: undefined instruction on CORE is reported, others still answer",
     selftest_fault},
    {"idle", "over 5 s after boot each idle core retires under --max-insns per s",
     selftest_idle},
    {"latency", "--rounds N ping round trips RC<->NC --core K (default 2; 1: DM<->RC),\n"
                "               one after another, each timed by the board: min, median, max",
     selftest_latency},
};
#define SELFTEST_COUNT (int)(sizeof selftests / sizeof selftests[0])

enum {
    SELFTEST_OPT_MIB = CLI_OWN_CODES,
    SELFTEST_OPT_BYTES,
    SELFTEST_OPT_MAX_INSNS,
    SELFTEST_OPT_ROUNDS,
    SELFTEST_OPT_CORE,
};

static const struct cli_optdef selftest_optdefs[] = {
    {"mib", "N", SELFTEST_OPT_MIB, "MiB for stress"},
    {"bytes", "N", SELFTEST_OPT_BYTES, "bytes for link-sink and link-source"},
    {"max-insns", "N", SELFTEST_OPT_MAX_INSNS,
     "idle: most guest instructions per second an idle core may\n"
     "retire (default 10000)"},
    {"rounds", "N", SELFTEST_OPT_ROUNDS, "latency: round trips (1..1000, default 200)"},
    {"core", "K", SELFTEST_OPT_CORE,
     "latency: the far end (1: the RC, asked by the DM; an NC, asked\n"
     "by the RC; default 2)"},
    CLI_OPTDEF_END,
};

static void selftest_usage(FILE *out)
{
    fprintf(out, "usage: links1 selftest [options] NAME...\n"
                 "Boots the board, waits for every unit computer to report in, runs each\n"
                 "check and prints 'selftest NAME: ok' or 'selftest NAME: FAILED: why'.\n"
                 "Exits non-zero if any check failed.  Checks:\n");
    for (int i = 0; i < SELFTEST_COUNT; i++)
        fprintf(out, "  %-12s %s\n", selftests[i].name, selftests[i].help);
    fprintf(out, "options:\n");
    cli_optdefs_help(out, board_optdefs);
    cli_optdefs_help(out, selftest_optdefs);
}

static const struct selftest *selftest_find(const char *name)
{
    for (int i = 0; i < SELFTEST_COUNT; i++)
        if (strcmp(name, selftests[i].name) == 0)
            return &selftests[i];
    return NULL;
}

/* A check named on the command line (with its CORE for fault) onto run. */
static int selftest_add(struct cli *c, struct selftest_args *a, const struct selftest **run,
                        int *nrun)
{
    const struct selftest *t = selftest_find(c->arg);
    if (!t) {
        fprintf(stderr, "links1 selftest: no check named '%s' (see --help)\n", c->arg);
        return -1;
    }
    if (t->fn == selftest_fault) {
        long core;
        if (cli_operand_value(c) < 0 || cli_long(c, 0, 0, UNITS_MAX_CORES - 1, &core) < 0)
            return -1;
        a->fault_core = (int)core;
    }
    if (*nrun >= SELFTEST_MAX_RUN) {
        fprintf(stderr, "links1 selftest: at most %d checks per run\n", SELFTEST_MAX_RUN);
        return -1;
    }
    run[(*nrun)++] = t;
    return 0;
}

/* Parses the arguments into opts, args and the list of checks to run. */
static int selftest_parse(int argc, char **argv, struct board_opts *o,
                          struct selftest_args *a, const struct selftest **run, int *nrun)
{
    static const struct cli_optdef *const lists[] = {board_optdefs, selftest_optdefs, NULL};
    struct option longs[32];
    struct cli c;
    if (cli_optdefs_table(lists, longs, 32) != 0)
        return -1;
    cli_init(&c, "links1 selftest", argc, argv, "h", longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        int r = code == CLI_BAD ? -1 : board_opt(o, &c, code);
        long v;
        if (r < 0)
            return -1;
        if (r)
            continue;
        if (code == 'h') {
            selftest_usage(stdout);
            exit(0);
        } else if (code == SELFTEST_OPT_MIB) {
            if (cli_long(&c, 0, 1, SELFTEST_MAX_STRESS_MIB, &v) < 0)
                return -1;
            a->stress_mib = (uint32_t)v;
        } else if (code == SELFTEST_OPT_BYTES) {
            if (cli_long(&c, 0, 1, SELFTEST_MAX_LINK_BYTES, &v) < 0)
                return -1;
            a->link_bytes = (uint32_t)v;
        } else if (code == SELFTEST_OPT_MAX_INSNS) {
            if (cli_long(&c, 0, 1, SELFTEST_MAX_IDLE_INSNS, &v) < 0)
                return -1;
            a->max_insns = (uint32_t)v;
        } else if (code == SELFTEST_OPT_ROUNDS) {
            if (cli_long(&c, 0, 1, LINK_LATENCY_MAX_ROUNDS, &v) < 0)
                return -1;
            a->rounds = (uint32_t)v;
        } else if (code == SELFTEST_OPT_CORE) {
            if (cli_long(&c, 0, 1, UNITS_MAX_CORES - 1, &v) < 0)
                return -1;
            a->latency_core = (int)v;
        } else if (code != CLI_OPERAND || selftest_add(&c, a, run, nrun) < 0) {
            return -1;
        }
    }
    if (*nrun == 0) {
        return cli_usage_error("links1 selftest", "name at least one check");
    }
    if (a->latency_core >= o->ncores) {
        fprintf(stderr, "links1 selftest: --core %d, but the board has %d cores\n",
                a->latency_core, o->ncores);
        return -1;
    }
    if (a->fault_core >= o->ncores) {
        fprintf(stderr, "links1 selftest: fault core %d, but the board has %d cores\n",
                a->fault_core, o->ncores);
        return -1;
    }
    return 0;
}

int cmd_selftest(int argc, char **argv)
{
    struct board_opts o;
    struct selftest_args a = {
        .stress_mib = SELFTEST_STRESS_MIB,
        .link_bytes = SELFTEST_LINK_BYTES,
        .max_insns = SELFTEST_IDLE_MAX_INSNS,
        .fault_core = 0,
        .rounds = SELFTEST_LATENCY_ROUNDS,
        .latency_core = UNITS_FIRST_NC,
    };
    const struct selftest *run[SELFTEST_MAX_RUN];
    int nrun = 0;
    board_opts_init(&o);
    if (selftest_parse(argc, argv, &o, &a, run, &nrun) < 0)
        return 2;

    /* The idle check's series: in a private directory of the run's. */
    char dir[PATH_MAX] = "", series[PATH_MAX + 16] = "";
    for (int i = 0; i < nrun; i++) {
        if (run[i]->fn != selftest_idle || series[0])
            continue;
        if (tmp_dir_make("idle", dir, sizeof dir) != 0) {
            perror("links1 selftest: a private directory for the instruction counts");
            return 1;
        }
        snprintf(series, sizeof series, "%s/series", dir);
        selftest_idle_prepare(&o, series);
    }

    struct board b;
    int failed = 0;
    if (board_start(&b, &o) < 0 || board_wait_reported(&b, o.timeout_s * 1000) < 0) {
        printf("selftest boot: FAILED: not every unit computer reported in\n");
        board_stop(&b);
        if (dir[0])
            tmp_dir_remove(dir);
        return 1;
    }
    printf("selftest boot: ok: all %d unit computers reported in\n", o.ncores);
    for (int i = 0; i < nrun; i++) {
        char why[SELFTEST_WHY_SIZE] = "";
        long long t0 = board_now_ms();
        int r = run[i]->fn(&b, &a, why, sizeof why);
        double secs = (double)(board_now_ms() - t0) / 1000.0;
        if (r == 0) {
            printf("selftest %s: ok: %s (%.1f s)\n", run[i]->name, why, secs);
        } else {
            printf("selftest %s: FAILED: %s\n", run[i]->name, why[0] ? why : "see above");
            failed++;
        }
        fflush(stdout);
        if (b.fd < 0)
            break; /* the board is gone; later checks cannot run */
    }
    int stop = board_stop(&b);
    if (dir[0])
        tmp_dir_remove(dir);
    if (stop == 0) {
        printf("selftest shutdown: ok: the board powered off on command\n");
    } else {
        printf("selftest shutdown: FAILED: the board did not power off on command\n");
        failed++;
    }
    if (board_report_link_errors(&b)) {
        printf("selftest link-errors: FAILED: frames from the board were damaged or lost\n");
        failed++;
    } else {
        printf("selftest link-errors: ok: %u frames from the board, none damaged or lost\n",
               b.dec.stats.frames);
    }
    return failed ? 1 : 0;
}
