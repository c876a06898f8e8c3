/* cmd_replay.c: `links1 replay FILE --ncs LIST ...`: a traced frame
 * (links1 render --trace) replayed on equal-speed unit computers
 * (host-tools/trace/replay.h), one line per NC count. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/cli/links1_cmds.h"
#include "host-tools/image/chart.h"
#include "host-tools/opts/cli_opt.h"
#include "host-tools/trace/replay.h"
#include "host-tools/trace/replay_timeline.h"
#include "host-tools/trace/trace_file.h"
#include "proto/render_link.h"

#define REPLAY_MAX_COUNTS 64

struct replay_opts {
    const char *file;
    const char *timeline; /* --timeline OUT.png, or NULL */
    uint32_t ncs[REPLAY_MAX_COUNTS];
    int ncounts;
    struct replay_cfg cfg;
    int have_balance, have_k, have_guided, have_ask, per_nc, check, paper;
    uint32_t scale;
};

enum replay_opt_code {
    REPLAY_OPT_NCS = CLI_OWN_CODES,
    REPLAY_OPT_BALANCE,
    REPLAY_OPT_AREAS,
    REPLAY_OPT_MIPS,
    REPLAY_OPT_LINE_US,
    REPLAY_OPT_BYTE_US,
    REPLAY_OPT_PREFETCH,
    REPLAY_OPT_ASK,
    REPLAY_OPT_GUIDED,
    REPLAY_OPT_PIPELINED,
    REPLAY_OPT_FIRST_BY_REQUEST,
    REPLAY_OPT_AS_RECORDED,
    REPLAY_OPT_PER_NC,
    REPLAY_OPT_CHECK,
    REPLAY_OPT_SCALE,
    REPLAY_OPT_PAPER,
    REPLAY_OPT_TIMELINE,
};

static const struct cli_optdef replay_optdefs[] = {
    {"ncs", "LIST", REPLAY_OPT_NCS, "NC counts, e.g. 1,2,4,8,16,32,64,128,254"},
    {"per-nc", NULL, REPLAY_OPT_PER_NC, "also print each NC's instructions"},
    {"check", NULL, REPLAY_OPT_CHECK,
     "check that the board's handout in the trace is its schedule's,\n"
     "and each replay a legal handout of its own"},
    {"scale", "F", REPLAY_OPT_SCALE,
     "price the frame at F times the traced width and height, each\n"
     "pixel at its traced pixel's instructions (1..64)"},
    {"timeline", "OUT.png", REPLAY_OPT_TIMELINE,
     "draw the frame replayed at the one NC count given: a row per\n"
     "unit computer (needs gnuplot)"},
    CLI_OPTDEF_END,
};

/* The what-ifs: a schedule or a speed other than the board's. */
static const struct cli_optdef replay_whatif_optdefs[] = {
    {"balance", "M", REPLAY_OPT_BALANCE, "static, dynamic, decreasing or lines"},
    {"areas", "K", REPLAY_OPT_AREAS,
     "areas of the dynamic or lines grid / smallest-area bound of\n"
     "decreasing"},
    {"guided", "F", REPLAY_OPT_GUIDED, "decreasing: each area takes 1/(F * NCs) of what is left"},
    {"ask", "ahead|finished", REPLAY_OPT_ASK,
     "when an NC asks for its next area: a round trip before it\n"
     "expects to finish, or once it has (the paper's rule)"},
    {"prefetch", NULL, REPLAY_OPT_PREFETCH, "the same as --ask ahead"},
    {"paper", NULL, REPLAY_OPT_PAPER,
     "the paper's schedule: --balance lines --areas HEIGHT --ask\n"
     "finished (an option given beside it wins)"},
    {"mips", "R", REPLAY_OPT_MIPS, "instructions per microsecond of every unit (default 1.0)"},
    {"line-us", "U", REPLAY_OPT_LINE_US, "latency of one serial-line message (default 1000)"},
    {"byte-us", "B", REPLAY_OPT_BYTE_US, "microseconds per byte on a line (default 520.8)"},
    {"pipelined", NULL, REPLAY_OPT_PIPELINED, "the DM prepared the frame during the previous one"},
    {"first-by-request", NULL, REPLAY_OPT_FIRST_BY_REQUEST,
     "each NC asks for its first area once set up (the board\n"
     "hands it out with the NC's start)"},
    {"as-recorded", NULL, REPLAY_OPT_AS_RECORDED,
     "each NC gets the areas the board gave it, in its order"},
    CLI_OPTDEF_END,
};

static void replay_usage(FILE *out)
{
    fprintf(out, "usage: links1 replay TRACE --ncs LIST [options]\n"
                 "Replays a frame traced on the board (links1 render --trace) on equal-speed\n"
                 "unit computers: one line per NC count with the frame time, the speed-up over\n"
                 "one NC, and how busy the NCs were.  Without the what-if options it replays\n"
                 "what the board does.\n"
                 "options:\n");
    cli_optdefs_help(out, replay_optdefs);
    fprintf(out, "what-if options:\n");
    cli_optdefs_help(out, replay_whatif_optdefs);
}

/* "1,2,4": 0, or -1 if not a list of 1..4096. */
static int replay_parse_list(const char *s, struct replay_opts *o)
{
    o->ncounts = 0;
    while (*s) {
        char *end;
        long v = strtol(s, &end, 10);
        if (end == s || v < 1 || v > 4096 || (*end != ',' && *end != 0) ||
            o->ncounts == REPLAY_MAX_COUNTS)
            return -1;
        o->ncs[o->ncounts++] = (uint32_t)v;
        s = *end ? end + 1 : end;
    }
    return o->ncounts ? 0 : -1;
}

static int replay_take(struct replay_opts *o, const struct cli *c, int code)
{
    long n;
    enum areas_mode m;
    switch (code) {
    case CLI_OPERAND:
        if (o->file) {
            return cli_usage_error("links1 replay", "%s: one trace at a time", c->arg);
        }
        o->file = c->arg;
        return 0;
    case REPLAY_OPT_NCS:
        return replay_parse_list(c->arg, o) == 0
                   ? 0 : cli_bad_value(c, "NC counts 1..4096 separated by commas (at most 64)");
    case REPLAY_OPT_BALANCE:
        if (areas_mode_parse(c->arg, &m) != AREAS_OK)
            return cli_bad_value(c, "static, dynamic, decreasing or lines");
        o->cfg.balance = m;
        o->have_balance = 1;
        return 0;
    case REPLAY_OPT_AREAS:
        if (cli_long(c, 10, 1, 1 << 22, &n) < 0)
            return -1;
        o->cfg.k = (uint32_t)n;
        o->have_k = 1;
        return 0;
    case REPLAY_OPT_MIPS:
        return cli_double(c, 0, 1, 1e6, "instructions per microsecond above 0", &o->cfg.mips);
    case REPLAY_OPT_LINE_US:
        return cli_double(c, 0, 0, 1e9, "microseconds, 0 or more", &o->cfg.line_us);
    case REPLAY_OPT_BYTE_US:
        return cli_double(c, 0, 0, 1e9, "microseconds, 0 or more", &o->cfg.byte_us);
    case REPLAY_OPT_PAPER:
        o->paper = 1;
        return 0;
    case REPLAY_OPT_PREFETCH:
        o->cfg.prefetch = 1;
        o->have_ask = 1;
        return 0;
    case REPLAY_OPT_ASK:
        if (strcmp(c->arg, "ahead") != 0 && strcmp(c->arg, "finished") != 0)
            return cli_bad_value(c, "ahead or finished");
        o->cfg.prefetch = strcmp(c->arg, "ahead") == 0;
        o->have_ask = 1;
        return 0;
    case REPLAY_OPT_GUIDED:
        if (cli_long(c, 10, 1, AREAS_MAX_GUIDED_FACTOR, &n) < 0)
            return -1;
        o->cfg.guided = (uint32_t)n;
        o->have_guided = 1;
        return 0;
    case REPLAY_OPT_PIPELINED:
        o->cfg.pipelined = 1;
        return 0;
    case REPLAY_OPT_FIRST_BY_REQUEST:
        o->cfg.first_by_request = 1;
        return 0;
    case REPLAY_OPT_AS_RECORDED:
        o->cfg.as_recorded = 1;
        return 0;
    case REPLAY_OPT_PER_NC:
        o->per_nc = 1;
        return 0;
    case REPLAY_OPT_CHECK:
        o->check = 1;
        return 0;
    case REPLAY_OPT_SCALE:
        if (cli_long(c, 10, 1, 64, &n) < 0)
            return -1;
        o->scale = (uint32_t)n;
        return 0;
    case REPLAY_OPT_TIMELINE:
        o->timeline = c->arg;
        return 0;
    }
    return -1;
}

/* Returns 0, 1 (--help shown) or -1. */
static int replay_parse(struct replay_opts *o, int argc, char **argv)
{
    memset(o, 0, sizeof *o);
    o->scale = 1;
    o->cfg.mips = REPLAY_DEFAULT_MIPS;
    o->cfg.line_us = REPLAY_DEFAULT_LINE_US;
    o->cfg.byte_us = REPLAY_DEFAULT_BYTE_US;
    static const struct cli_optdef *const lists[] = {replay_optdefs, replay_whatif_optdefs, NULL};
    struct option longs[32];
    if (cli_optdefs_table(lists, longs, 32) != 0)
        return -1;
    struct cli c;
    cli_init(&c, "links1 replay", argc, argv, "h", longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        if (code == 'h') {
            replay_usage(stdout);
            return 1;
        }
        if (code == CLI_BAD || replay_take(o, &c, code) != 0)
            return -1;
    }
    if (!o->file || o->ncounts == 0) {
        return cli_usage_error("links1 replay", "name a TRACE and --ncs LIST");
    }
    if (o->timeline && o->ncounts != 1) {
        return cli_usage_error("links1 replay", "--timeline draws one frame: give one NC count "
                               "(--ncs N)");
    }
    return 0;
}

/* The timeline of replay r into o->timeline.  0, or 1 after saying why. */
static int replay_draw_timeline(const struct replay_opts *o, const struct trace *t,
                                const struct replay_cfg *c, const struct replay_result *r)
{
    char err[PATH_MAX + 256], title[PATH_MAX + 128];
    const char *name = strrchr(o->file, '/') ? strrchr(o->file, '/') + 1 : o->file;
    snprintf(title, sizeof title, "%s: %ux%u on %u NCs, frame %.1f ms at %.1f MIPS", name,
             (unsigned)t->width, (unsigned)t->height, (unsigned)c->ncs, r->frame_us / 1000.0,
             c->mips);
    struct chart ch;
    if (chart_open(&ch, o->timeline, err, sizeof err) != 0) {
        fprintf(stderr, "links1 replay: --timeline %s\n", err);
        return 1;
    }
    replay_timeline_script(ch.script, t, c, r, title);
    if (chart_close(&ch, err, sizeof err) != 0) {
        fprintf(stderr, "links1 replay: --timeline %s\n", err);
        return 1;
    }
    printf("  timeline: %s\n", o->timeline);
    return 0;
}

/* The schedule replayed: what was given, the trace's where not (--paper:
 * the paper's, but what was given beside it).  1 when it is a what-if,
 * a schedule or speed other than the board's (an option that only repeats
 * what the board ran, as --paper on a paper-mode trace, is not). */
static int replay_settle(struct replay_opts *o, const struct trace *t)
{
    if (o->paper) {
        if (!o->have_balance)
            o->cfg.balance = AREAS_LINES;
        if (!o->have_k)
            o->cfg.k = t->height;
        if (!o->have_ask)
            o->cfg.prefetch = 0;
        o->have_balance = o->have_k = o->have_ask = 1;
        printf("links1 replay: paper mode: areas %s K %u, ask %s\n",
               areas_mode_name(o->cfg.balance), (unsigned)o->cfg.k,
               o->cfg.prefetch ? "ahead" : "finished");
    }
    int board_ahead = !(t->flags & LINK_RENDER_ASK_WHEN_DONE);
    if (!o->have_balance)
        o->cfg.balance = (enum areas_mode)t->balance;
    if (!o->have_k)
        o->cfg.k = t->k;
    if (!o->have_guided)
        o->cfg.guided = t->guided;
    if (!o->have_ask)
        o->cfg.prefetch = board_ahead;
    return (o->have_balance && o->cfg.balance != (enum areas_mode)t->balance) ||
           (o->have_k && o->cfg.k != t->k) || (o->have_guided && o->cfg.guided != t->guided) ||
           (o->have_ask && o->cfg.prefetch != board_ahead) || o->cfg.pipelined ||
           (o->cfg.first_by_request && t->first_with_start) || o->cfg.mips != REPLAY_DEFAULT_MIPS ||
           o->cfg.line_us != REPLAY_DEFAULT_LINE_US || o->cfg.byte_us != REPLAY_DEFAULT_BYTE_US;
}

static void replay_say_trace(const struct replay_opts *o, const struct trace *t, int what_if)
{
    if (o->scale > 1)
        printf("scaled %ux: each pixel of the %ux%u frame priced at its traced pixel's\n",
               (unsigned)o->scale, (unsigned)t->width, (unsigned)t->height);
    printf("trace %s: %ux%u, %u areas on %u NCs (%s); DM %llu, RC broadcast %llu insns; "
           "%u bytes broadcast\n", o->file, (unsigned)t->width, (unsigned)t->height,
           (unsigned)t->nareas, (unsigned)t->ncs, areas_mode_name((enum areas_mode)t->balance),
           (unsigned long long)t->dm_prepare, (unsigned long long)t->rc_broadcast,
           (unsigned)t->broadcast_bytes);
    printf("replayed: %s; %s%s\n", what_if ? "a what-if" : "what the board does",
           o->cfg.prefetch ? "NCs asking ahead" : "NCs asking when finished",
           o->cfg.balance == AREAS_DECREASING && (!o->cfg.k || !o->cfg.guided)
               ? "; K and factor by NC count where not given"
               : "");
}

/* One NC count replayed and its line printed (with --per-nc, --check and
 * --timeline what they add).  0, or 1 after saying why. */
static int replay_one(const struct replay_opts *o, const struct trace *t, uint32_t ncs,
                      const struct replay_result *base)
{
    char err[TRACE_ERR_MAX];
    struct replay_cfg c = o->cfg;
    c.ncs = ncs;
    struct replay_result res;
    if (replay_run(t, &c, &res, err, sizeof err) != 0) {
        fprintf(stderr, "links1 replay: --ncs %u: %s\n", (unsigned)c.ncs, err);
        return 1;
    }
    uint64_t most = 0;
    for (uint32_t n = 0; n < c.ncs; n++)
        most = res.nc_insns[n] > most ? res.nc_insns[n] : most;
    uint32_t k, factor;
    areas_settings(c.balance, c.ncs, c.k, c.guided, &k, &factor);
    printf("ncs %u balance %s areas %u frame_ms %.1f speed-up %.2f busy %.1f%% rc_busy "
           "%.1f%% exact %u/%u largest_nc_insns %llu k %u factor %u dones %u ask %s\n",
           (unsigned)c.ncs, c.as_recorded ? "as-recorded" : areas_mode_name(c.balance),
           (unsigned)res.nareas, res.frame_us / 1000.0, base->frame_us / res.frame_us,
           100.0 * res.busy, 100.0 * res.rc_busy, (unsigned)res.exact, (unsigned)res.nareas,
           (unsigned long long)most, (unsigned)k, (unsigned)factor, (unsigned)res.dones,
           c.prefetch ? "ahead" : "finished");
    if (o->per_nc)
        for (uint32_t n = 0; n < c.ncs; n++)
            printf("  nc %u insns %llu\n", (unsigned)n, (unsigned long long)res.nc_insns[n]);
    int rc = o->timeline ? replay_draw_timeline(o, t, &c, &res) : 0;
    if (o->check) {
        if (replay_check_legal(t, &c, &res, err, sizeof err) != 0) {
            fprintf(stderr, "links1 replay: --ncs %u: not a legal handout: %s\n",
                    (unsigned)c.ncs, err);
            rc = 1;
        } else {
            printf("  legal handout of %u areas\n", (unsigned)res.nareas);
        }
    }
    replay_free(&res);
    return rc;
}

/* The trace read and scaled.  0, or 1 after saying why. */
static int replay_load(const struct replay_opts *o, struct trace *t)
{
    char err[TRACE_ERR_MAX];
    if (trace_read(o->file, t, err, sizeof err) != 0) {
        fprintf(stderr, "links1 replay: %s\n", err);
        return 1;
    }
    if (trace_scale(t, o->scale, err, sizeof err) != 0) {
        fprintf(stderr, "links1 replay: %s: %s\n", o->file, err);
        trace_free(t);
        return 1;
    }
    return 0;
}

int cmd_replay(int argc, char **argv)
{
    struct replay_opts o;
    int r = replay_parse(&o, argc, argv);
    if (r != 0)
        return r > 0 ? 0 : 2;
    struct trace t;
    if (replay_load(&o, &t) != 0)
        return 1;
    replay_say_trace(&o, &t, replay_settle(&o, &t));
    char err[TRACE_ERR_MAX];
    if (o.check && o.scale == 1) {
        if (replay_check_board(&t, err, sizeof err) != 0) {
            fprintf(stderr, "links1 replay: %s: the board's handout: %s\n", o.file, err);
            trace_free(&t);
            return 1;
        }
        printf("board handout: the schedule's %u areas in its order\n", (unsigned)t.nareas);
    }
    struct replay_cfg one = o.cfg;
    one.ncs = 1;
    one.as_recorded = 0;
    struct replay_result base;
    if (replay_run(&t, &one, &base, err, sizeof err) != 0) {
        fprintf(stderr, "links1 replay: %s\n", err);
        trace_free(&t);
        return 1;
    }
    int rc = 0;
    for (int i = 0; i < o.ncounts && rc == 0; i++)
        rc = replay_one(&o, &t, o.ncs[i], &base);
    replay_free(&base);
    trace_free(&t);
    return rc;
}
