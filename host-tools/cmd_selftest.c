/* cmd_selftest.c: `links1 selftest NAME...`: boots the board once, waits for
 * every unit computer to report in, then runs each named check in order and
 * prints "selftest NAME: ok: ..." or "selftest NAME: FAILED: why".  The
 * board tests in tests/board/ are built on these lines. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/board.h"
#include "host-tools/links1_cmds.h"
#include "host-tools/selftest.h"

static const struct selftest selftests[] = {
    {"status", "the board counts every unit computer", selftest_status},
    {"ping", "ping-pong over every serial line (DM-RC, RC-each NC)", selftest_ping},
    {"imsu", "IMSU swap both ways and broadcast, checksummed", selftest_imsu},
    {"stress", "--mib MiB (default 64) through the inter-unit lines", selftest_stress},
    {"link-sink", "--bytes N (default 8 MiB) of the pattern host -> board", selftest_link_sink},
    {"link-source", "--bytes N (default 8 MiB) of the pattern board -> host",
     selftest_link_source},
    {"fault", "CORE: undefined instruction on CORE is reported, others still answer",
     selftest_fault},
    {"idle", "over 5 s after boot each idle core retires under --max-insns per s",
     selftest_idle},
};
#define SELFTEST_COUNT (int)(sizeof selftests / sizeof selftests[0])

static void selftest_usage(FILE *out)
{
    fprintf(out, "usage: links1 selftest [options] NAME...\n"
                 "Boots the board, waits for every unit computer to report in, runs each\n"
                 "check and prints 'selftest NAME: ok' or 'selftest NAME: FAILED: why'.\n"
                 "Exits non-zero if any check failed.  Checks:\n");
    for (int i = 0; i < SELFTEST_COUNT; i++)
        fprintf(out, "  %-12s %s\n", selftests[i].name, selftests[i].help);
    fprintf(out, "options:\n%s"
                 "  --mib N          MiB for stress\n"
                 "  --bytes N        bytes for link-sink and link-source\n"
                 "  --max-insns N    idle: most guest instructions per second an idle\n"
                 "                   core may retire (default 10000)\n",
            board_opts_usage);
}

static const struct selftest *selftest_find(const char *name)
{
    for (int i = 0; i < SELFTEST_COUNT; i++)
        if (strcmp(name, selftests[i].name) == 0)
            return &selftests[i];
    return NULL;
}

/* Parses an unsigned option value in [lo, hi]. */
static int selftest_parse_u32(const char *opt, const char *s, unsigned long lo, unsigned long hi,
                     uint32_t *out)
{
    char *end;
    errno = 0;
    unsigned long v = strtoul(s, &end, 0);
    if (errno || end == s || *end || v < lo || v > hi || s[0] == '-') {
        fprintf(stderr, "links1 selftest: %s '%s': want a number from %lu to %lu\n", opt, s,
                lo, hi);
        return -1;
    }
    *out = (uint32_t)v;
    return 0;
}

/* Parses the arguments into opts, args and the list of checks to run. */
static int selftest_parse(int argc, char **argv, struct board_opts *o,
                          struct selftest_args *a, const struct selftest **run, int *nrun)
{
    for (int i = 1; i < argc; i++) {
        int r = board_parse_opt(o, argc, argv, &i);
        if (r < 0)
            return -1;
        if (r)
            continue;
        const char *s = argv[i];
        const char *val = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0) {
            selftest_usage(stdout);
            exit(0);
        } else if (strcmp(s, "--mib") == 0 || strcmp(s, "--bytes") == 0 ||
                   strcmp(s, "--max-insns") == 0) {
            if (!val) {
                fprintf(stderr, "links1 selftest: %s needs a value\n", s);
                return -1;
            }
            i++;
            if (s[2] == 'm' && s[3] == 'i' &&
                selftest_parse_u32(s, val, 1, SELFTEST_MAX_STRESS_MIB, &a->stress_mib) < 0)
                return -1;
            if (s[2] == 'b' && selftest_parse_u32(s, val, 1, SELFTEST_MAX_LINK_BYTES, &a->link_bytes) < 0)
                return -1;
            if (s[2] == 'm' && s[3] == 'a' &&
                selftest_parse_u32(s, val, 1, SELFTEST_MAX_IDLE_INSNS, &a->max_insns) < 0)
                return -1;
        } else if (s[0] == '-') {
            fprintf(stderr, "links1 selftest: unknown option '%s'\n", s);
            return -1;
        } else {
            const struct selftest *t = selftest_find(s);
            if (!t) {
                fprintf(stderr, "links1 selftest: no check named '%s' (see --help)\n", s);
                return -1;
            }
            if (t->fn == selftest_fault) {
                uint32_t core;
                if (!val || selftest_parse_u32("fault CORE", val, 0, UNITS_MAX_CORES - 1, &core) < 0) {
                    fprintf(stderr, "links1 selftest: fault needs the core to fault\n");
                    return -1;
                }
                a->fault_core = (int)core;
                i++;
            }
            if (*nrun >= SELFTEST_MAX_RUN) {
                fprintf(stderr, "links1 selftest: at most %d checks per run\n",
                        SELFTEST_MAX_RUN);
                return -1;
            }
            run[(*nrun)++] = t;
        }
    }
    if (*nrun == 0) {
        fprintf(stderr, "links1 selftest: name at least one check\n");
        selftest_usage(stderr);
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
    };
    const struct selftest *run[SELFTEST_MAX_RUN];
    int nrun = 0;
    board_opts_init(&o);
    if (selftest_parse(argc, argv, &o, &a, run, &nrun) < 0)
        return 2;

    char series[64] = "";
    for (int i = 0; i < nrun; i++)
        if (run[i]->fn == selftest_idle && !series[0] &&
            selftest_idle_prepare(&o, series, sizeof series) < 0)
            return 1;

    struct board b;
    int failed = 0;
    if (board_start(&b, &o) < 0 || board_wait_reported(&b, o.timeout_s * 1000) < 0) {
        printf("selftest boot: FAILED: not every unit computer reported in\n");
        board_stop(&b);
        if (series[0])
            unlink(series);
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
    if (series[0])
        unlink(series);
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
