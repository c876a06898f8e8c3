/* test_trace.c: trace files (host-tools/trace/trace_file.h) round-trip and are
 * refused when damaged; the replay (host-tools/trace/replay.h) gives each NC
 * exactly the board's instructions under static balancing, and a legal
 * handout of the schedule under dynamic and decreasing balancing; a trace
 * scaled to a larger size (trace_scale) keeps its costs per pixel block. */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/opts/tmp_dir.h"
#include "host-tools/trace/replay.h"
#include "host-tools/trace/replay_timeline.h"
#include "host-tools/trace/trace_file.h"
#include "proto/areas.h"
#include "proto/render_link.h"
#include "tests/check.h"

static uint32_t test_rand_state = 12345;
static uint32_t test_rand(void)
{
    test_rand_state = test_rand_state * 1103515245u + 12345u;
    return test_rand_state >> 8;
}

/* A trace as the board would leave it: the schedule's areas handed out
 * round robin over ncs NCs, random per-pixel, set-up and push costs. */
static void make_trace(struct trace *t, enum areas_mode mode, uint32_t w, uint32_t h,
                       uint32_t ncs, uint32_t k)
{
    memset(t, 0, sizeof *t);
    t->width = w;
    t->height = h;
    t->ncs = ncs;
    t->balance = (uint32_t)mode;
    t->k = k;
    t->dm_prepare = 400000 + test_rand() % 1000;
    t->rc_broadcast = 80000 + test_rand() % 1000;
    t->broadcast_bytes = 20000;
    t->rc_other = 5000;
    t->first_with_start = 1;
    t->other_counted = 1;
    t->rc_other_count = 3;
    t->rc_done = 900;
    t->rc_done_count = 2;
    t->nc_setup = calloc(ncs, sizeof *t->nc_setup);
    for (uint32_t i = 0; i < ncs; i++)
        t->nc_setup[i] = 966;
    t->pixel = calloc((size_t)w * h, sizeof *t->pixel);
    for (size_t p = 0; p < (size_t)w * h; p++)
        t->pixel[p] = 1000 + test_rand() % 50000;
    struct areas s;
    struct area a;
    areas_init(&s, mode, w, h, ncs, k);
    t->nareas = areas_count(&s);
    t->areas = calloc(t->nareas, sizeof *t->areas);
    uint32_t *order = calloc(ncs, sizeof *order);
    for (uint32_t i = 0; areas_next(&s, &a); i++) {
        struct trace_area *ta = &t->areas[i];
        ta->x = a.x;
        ta->y = a.y;
        ta->w = a.w;
        ta->h = a.h;
        ta->nc = i % ncs;
        ta->order = order[ta->nc]++;
        ta->handout = i;
        ta->setup = 200 + test_rand() % 300;
        ta->push = 40ull * a.w * a.h;
        ta->rc = 1557;
        ta->total = ta->setup + ta->push + trace_pixels_sum(t, a.x, a.y, a.w, a.h);
    }
    free(order);
}

static int same_trace(const struct trace *a, const struct trace *b)
{
    if (a->width != b->width || a->height != b->height || a->ncs != b->ncs ||
        a->balance != b->balance || a->k != b->k || a->guided != b->guided ||
        a->flags != b->flags || a->first_with_start != b->first_with_start ||
        a->dm_prepare != b->dm_prepare || a->rc_broadcast != b->rc_broadcast ||
        a->broadcast_bytes != b->broadcast_bytes || a->rc_other != b->rc_other ||
        a->other_counted != b->other_counted || a->rc_other_count != b->rc_other_count ||
        a->rc_done != b->rc_done || a->rc_done_count != b->rc_done_count ||
        a->nareas != b->nareas)
        return 0;
    if (memcmp(a->nc_setup, b->nc_setup, a->ncs * sizeof *a->nc_setup) != 0 ||
        memcmp(a->pixel, b->pixel, (size_t)a->width * a->height * sizeof *a->pixel) != 0)
        return 0;
    for (uint32_t i = 0; i < a->nareas; i++)
        if (memcmp(&a->areas[i], &b->areas[i], sizeof a->areas[i]) != 0)
            return 0;
    return 1;
}

static char test_dir[] = "/tmp/links1-test-trace-XXXXXX";

/* The trace written to path: 0, or -1 with err. */
static int write_trace(const char *path, const struct trace *t, char *err, size_t cap)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, cap, "%s: cannot write", path);
        return -1;
    }
    int rc = trace_write(f, path, t, err, cap);
    return fclose(f) != 0 ? -1 : rc;
}

static void test_trace_round_trips(void)
{
    struct trace t, back;
    char err[TRACE_ERR_MAX], path[128];
    snprintf(path, sizeof path, "%s/rt.trace", test_dir);
    make_trace(&t, AREAS_DECREASING, 37, 23, 3, 64);
    CHECK_EQ_INT(trace_check(&t, err, sizeof err), 0);
    CHECK_EQ_INT(write_trace(path, &t, err, sizeof err), 0);
    int r = trace_read(path, &back, err, sizeof err);
    if (r != 0)
        printf("  %s\n", err);
    CHECK_EQ_INT(r, 0);
    CHECK(r == 0 && same_trace(&t, &back));
    if (r == 0)
        trace_free(&back);
    /* one of version 3 (no count of the other messages) stays version 3 */
    t.other_counted = 0;
    t.rc_other_count = t.rc_done_count = 0;
    t.rc_done = 0;
    CHECK_EQ_INT(write_trace(path, &t, err, sizeof err), 0);
    r = trace_read(path, &back, err, sizeof err);
    CHECK_EQ_INT(r, 0);
    CHECK(r == 0 && same_trace(&t, &back));
    if (r == 0)
        trace_free(&back);
    trace_free(&t);
}

/* Writes t with one line replaced (or cut after it) and expects the reader
 * to refuse it with a message holding want. */
static void expect_refused(const struct trace *t, const char *prefix, const char *repl,
                           const char *want)
{
    char err[TRACE_ERR_MAX], path[128], bad[128];
    snprintf(path, sizeof path, "%s/good.trace", test_dir);
    snprintf(bad, sizeof bad, "%s/bad.trace", test_dir);
    write_trace(path, t, err, sizeof err);
    FILE *in = fopen(path, "r"), *out = fopen(bad, "w");
    char line[1 << 16];
    int done = 0;
    while (in && out && fgets(line, sizeof line, in)) {
        if (!done && strncmp(line, prefix, strlen(prefix)) == 0) {
            done = 1;
            if (!repl)
                break;
            fputs(repl, out);
            continue;
        }
        fputs(line, out);
    }
    if (in)
        fclose(in);
    if (out)
        fclose(out);
    CHECK(done);
    struct trace back;
    int r = trace_read(bad, &back, err, sizeof err);
    CHECK(r != 0);
    if (r == 0) {
        trace_free(&back);
        return;
    }
    if (!strstr(err, want)) {
        char m[400];
        snprintf(m, sizeof m, "message '%s' does not name '%s'", err, want);
        check_fail(__FILE__, __LINE__, m);
    }
}

static void test_damaged_traces_are_refused(void)
{
    struct trace t;
    make_trace(&t, AREAS_DYNAMIC, 16, 8, 2, 4); /* 4 areas of 4x8 */
    expect_refused(&t, "links1-trace", "links1-trace 9\n", "version");
    expect_refused(&t, "row 5", NULL, "want 'row Y'");
    expect_refused(&t, "area 4 0 4 8", "area 2 0 4 8 nc 1 order 0 setup 1 push 1 total 2 rc 1\n",
                   "overlaps");
    expect_refused(&t, "area 0 0 4 8", "area 0 0 4 8 nc 0 order 0 setup 1 push 1 total 2 rc 1\n",
                   "is not its total");
    expect_refused(&t, "area 0 0 4 8", "area 0 0 4 8 nc 7 order 0 setup 1 push 1 total 2 rc 1\n",
                   "NC 7");
    expect_refused(&t, "end", NULL, "want 'end'");
    expect_refused(&t, "run ", "run ncs 2 balance guided k 4 flags 0\n", "balance mode");
    expect_refused(&t, "rc_other", "rc_other 5000 messages 3 done 4 100\n", "M <= N");
    expect_refused(&t, "rc_other", "rc_other 5000 messages 3 done 2 6000\n", "within");
    expect_refused(&t, "rc_other", "rc_other 5000\n", "messages N done M");
    trace_free(&t);
}

/* The schedule the board ran is in the trace: K and factor (0: by the NC
 * count), and the rule of asking (flags).  A version-1 trace reads as the
 * board of then ran: K 1024 and factor 2 by default, asking when finished.
 * replay_check_board finds the board's handout to be that schedule and
 * names an area out of it. */
static void test_trace_records_schedule(void)
{
    struct trace t, back;
    char err[TRACE_ERR_MAX], path[128], v1[128];
    snprintf(path, sizeof path, "%s/sched.trace", test_dir);
    snprintf(v1, sizeof v1, "%s/v1.trace", test_dir);
    make_trace(&t, AREAS_DECREASING, 40, 30, 3, 0);
    t.flags = LINK_RENDER_ASK_WHEN_DONE;
    CHECK_EQ_INT(replay_check_board(&t, err, sizeof err), 0);
    t.guided = 3; /* no longer the schedule the areas came from */
    CHECK(replay_check_board(&t, err, sizeof err) != 0 && strstr(err, "not the schedule's next"));
    t.guided = 0;
    struct trace_area keep = t.areas[1];
    t.areas[1].order = 7;
    CHECK(replay_check_board(&t, err, sizeof err) != 0 && strstr(err, "out of its order"));
    t.areas[1] = keep;
    CHECK_EQ_INT(write_trace(path, &t, err, sizeof err), 0);
    int r = trace_read(path, &back, err, sizeof err);
    CHECK(r == 0 && same_trace(&t, &back));
    if (r == 0)
        trace_free(&back);
    /* the same file as version 1 wrote it */
    FILE *in = fopen(path, "r"), *out = fopen(v1, "w");
    char line[1 << 16];
    while (in && out && fgets(line, sizeof line, in)) {
        if (strncmp(line, "links1-trace", 12) == 0)
            fputs("links1-trace 1\n", out);
        else if (strncmp(line, "run ", 4) == 0)
            fprintf(out, "run ncs 3 balance decreasing k 0 flags 0\n");
        else if (strncmp(line, "rc_other ", 9) == 0)
            fputs("rc_other 5000\n", out); /* not counted before version 4 */
        else
            fputs(line, out);
    }
    if (in)
        fclose(in);
    if (out)
        fclose(out);
    r = trace_read(v1, &back, err, sizeof err);
    CHECK(r == 0 && back.k == 1024 && back.guided == 2 &&
          (back.flags & LINK_RENDER_ASK_WHEN_DONE) && !back.first_with_start);
    if (r == 0)
        trace_free(&back);
    expect_refused(&t, "run ", "run ncs 3 balance decreasing k 0 guided 65 flags 0\n",
                   "guided G");
    trace_free(&t);
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* Static balancing: timing decides only which NC gets which area; the
 * per-NC instructions are the board's, exactly. */
static void test_static_replay_is_exact(void)
{
    struct trace t;
    char err[TRACE_ERR_MAX];
    make_trace(&t, AREAS_STATIC, 64, 48, 8, 0);
    uint64_t board[8] = {0};
    for (uint32_t i = 0; i < t.nareas; i++)
        board[t.areas[i].nc] += t.areas[i].total;
    for (int as_recorded = 0; as_recorded <= 1; as_recorded++) {
        struct replay_cfg c = {.ncs = 8, .balance = AREAS_STATIC, .mips = 1.0, .line_us = 1000,
                              .byte_us = 520.8, .as_recorded = as_recorded};
        struct replay_result r;
        CHECK_EQ_INT(replay_run(&t, &c, &r, err, sizeof err), 0);
        CHECK_EQ_INT(r.nareas, 8);
        CHECK_EQ_INT(r.exact, 8);
        uint64_t got[8], want[8];
        memcpy(got, r.nc_insns, sizeof got);
        memcpy(want, board, sizeof want);
        if (as_recorded) {
            for (int n = 0; n < 8; n++)
                CHECK_EQ_INT(got[n], want[n]);
        } else {
            qsort(got, 8, sizeof got[0], cmp_u64);
            qsort(want, 8, sizeof want[0], cmp_u64);
            for (int n = 0; n < 8; n++)
                CHECK_EQ_INT(got[n], want[n]);
        }
        CHECK_EQ_INT(replay_check_legal(&t, &c, &r, err, sizeof err), 0);
        /* an answer crosses its line in line_us plus byte_us for each of
         * the board's answer's bytes (proto/unitmsg.h), and the NC starts
         * on it at once */
        double line = c.line_us + c.byte_us * (LINEMSG_HEADER_SIZE + MSG_NC_AREA_SIZE);
        for (uint32_t i = 0; i < r.nareas; i++)
            if (!r.areas[i].with_start)
                CHECK_NEAR(r.areas[i].start - r.areas[i].serve_end, line, 1e-6);
        replay_free(&r);
    }
    trace_free(&t);
}

/* Dynamic and decreasing, any NC count, with and without prefetching: the
 * replay hands out the schedule's areas once each, legally; and a
 * tampered replay is caught. */
static void test_dynamic_replay_is_legal(void)
{
    struct trace t;
    char err[TRACE_ERR_MAX];
    make_trace(&t, AREAS_DYNAMIC, 64, 48, 4, 64);
    const uint32_t ncs[] = {1, 2, 3, 7, 16, 64};
    for (int mode = AREAS_DYNAMIC; mode <= AREAS_DECREASING; mode++)
        for (size_t i = 0; i < sizeof ncs / sizeof ncs[0]; i++)
            for (int pre = 0; pre <= 1; pre++) {
                struct replay_cfg c = {.ncs = ncs[i], .balance = (enum areas_mode)mode,
                                       .k = 256, .mips = 1.0, .line_us = 1000,
                                       .byte_us = 520.8, .prefetch = pre,
                                       .guided = mode == AREAS_DECREASING ? 1u + (uint32_t)i : 0,
                                       .pipelined = pre};
                t.first_with_start = (uint32_t)(i % 2); /* the board's, or before */
                struct replay_result r;
                CHECK_EQ_INT(replay_run(&t, &c, &r, err, sizeof err), 0);
                int ok = replay_check_legal(&t, &c, &r, err, sizeof err);
                if (ok != 0)
                    printf("  ncs %u mode %d prefetch %d: %s\n", ncs[i], mode, pre, err);
                CHECK_EQ_INT(ok, 0);
                uint64_t sum = 0;
                for (uint32_t n = 0; n < c.ncs; n++)
                    sum += r.nc_insns[n];
                CHECK(sum > 0);
                CHECK(r.busy > 0 && r.busy <= 1.0);
                uint32_t j = r.nareas - 1; /* the last area: a served request */
                if (r.nareas > c.ncs + 1 && ncs[i] > 1) {
                    /* The RC serving two at once, an area given twice. */
                    struct replay_result bad = r;
                    double keep = r.areas[j].serve_start;
                    r.areas[j].serve_start = r.areas[j - 1].serve_start - 1;
                    CHECK(replay_check_legal(&t, &c, &bad, err, sizeof err) != 0);
                    r.areas[j].serve_start = keep;
                    struct replay_area a2 = r.areas[j];
                    r.areas[j].x = r.areas[j - 1].x;
                    r.areas[j].y = r.areas[j - 1].y;
                    CHECK(replay_check_legal(&t, &c, &bad, err, sizeof err) != 0);
                    r.areas[j] = a2;
                    CHECK_EQ_INT(replay_check_legal(&t, &c, &bad, err, sizeof err), 0);
                }
                replay_free(&r);
            }
    /* One NC replayed on one NC: the frame is its work plus the lines. */
    struct replay_cfg c1 = {.ncs = 1, .balance = AREAS_DYNAMIC, .k = 64, .mips = 2.0};
    struct replay_result r1;
    CHECK_EQ_INT(replay_run(&t, &c1, &r1, err, sizeof err), 0);
    uint64_t all = t.dm_prepare + t.rc_broadcast + t.nc_setup[0];
    for (uint32_t i = 0; i < t.nareas; i++)
        all += t.areas[i].total + t.areas[i].rc;
    CHECK_NEAR(r1.frame_us, (double)all / 2.0, 1e-3);
    replay_free(&r1);
    /* Its first area came with its start: asking for it instead puts a
     * request and its answer on the lines first. */
    struct replay_cfg c2 = c1;
    struct replay_result r2;
    c2.line_us = 1000;
    CHECK_EQ_INT(replay_run(&t, &c2, &r1, err, sizeof err), 0);
    c2.first_by_request = 1;
    CHECK_EQ_INT(replay_run(&t, &c2, &r2, err, sizeof err), 0);
    CHECK(r1.nareas > 1 && r1.areas[0].with_start && !r2.areas[0].with_start);
    CHECK_NEAR(r2.frame_us - r1.frame_us, 2000.0, 1e-3);
    replay_free(&r1);
    replay_free(&r2);
    /* Asking for every area, at 100 us a byte and no more a message: each
     * area's request and answer add their bytes' time, in turn. */
    struct replay_cfg c3 = c1;
    c3.first_by_request = 1;
    CHECK_EQ_INT(replay_run(&t, &c3, &r1, err, sizeof err), 0);
    c3.byte_us = 100;
    CHECK_EQ_INT(replay_run(&t, &c3, &r2, err, sizeof err), 0);
    CHECK_NEAR(r2.frame_us - r1.frame_us,
               100.0 * r1.nareas * (REPLAY_REQUEST_BYTES + REPLAY_ANSWER_BYTES), 1e-3);
    replay_free(&r1);
    replay_free(&r2);
    trace_free(&t);
}

/* An NC asking ahead whose answer comes after its area's end sends
 * MSG_NC_DONE (roles/nc_render.c): the RC serves each for the trace's
 * mean of them, and nothing else changes in what it serves; none asking
 * when finished, nor from a trace that does not count them. */
static void test_replay_serves_done(void)
{
    struct trace t;
    char err[TRACE_ERR_MAX];
    make_trace(&t, AREAS_DECREASING, 64, 48, 4, 256);
    for (uint32_t i = 0; i < t.nareas; i++)
        t.areas[i].rc = 400000; /* a slow RC: answers come late */
    struct replay_cfg c = {.ncs = 16, .balance = AREAS_DECREASING, .k = 256, .mips = 1.0,
                           .line_us = 1000, .byte_us = 520.8, .prefetch = 1};
    struct replay_result with, without;
    CHECK_EQ_INT(replay_run(&t, &c, &with, err, sizeof err), 0);
    CHECK_EQ_INT(replay_check_legal(&t, &c, &with, err, sizeof err), 0);
    t.other_counted = 0;
    CHECK_EQ_INT(replay_run(&t, &c, &without, err, sizeof err), 0);
    CHECK(with.dones > 0);
    CHECK_EQ_INT(without.dones, 0);
    double mean = (double)(t.rc_done / t.rc_done_count);
    CHECK_NEAR(with.rc_busy * with.frame_us - without.rc_busy * without.frame_us,
               with.dones * mean, 1e-6 * with.frame_us);
    CHECK(with.frame_us > without.frame_us);
    replay_free(&with);
    replay_free(&without);
    t.other_counted = 1;
    c.prefetch = 0;
    CHECK_EQ_INT(replay_run(&t, &c, &with, err, sizeof err), 0);
    CHECK_EQ_INT(with.dones, 0);
    replay_free(&with);
    trace_free(&t);
}

/* trace_scale: a trace priced at f times the size keeps each pixel's
 * cost over its f x f block, each area's set-up and RC serving, f * f its
 * push; the result passes trace_check (areas cover the screen once, totals
 * add up); a scale past the largest screen is refused, naming it. */
static void test_trace_scale(void)
{
    struct trace t, s;
    make_trace(&t, AREAS_DYNAMIC, 16, 12, 3, 24);
    s = t; /* a deep copy */
    s.nc_setup = malloc(t.ncs * sizeof *s.nc_setup);
    s.areas = malloc(t.nareas * sizeof *s.areas);
    s.pixel = malloc(16 * 12 * sizeof *s.pixel);
    memcpy(s.nc_setup, t.nc_setup, t.ncs * sizeof *s.nc_setup);
    memcpy(s.areas, t.areas, t.nareas * sizeof *s.areas);
    memcpy(s.pixel, t.pixel, 16 * 12 * sizeof *s.pixel);
    char err[TRACE_ERR_MAX];
    CHECK_EQ_INT(trace_scale(&s, 3, err, sizeof err), 0);
    CHECK_EQ_INT(s.width, 48);
    CHECK_EQ_INT(s.height, 36);
    CHECK_EQ_INT(s.nareas, t.nareas);
    CHECK(trace_pixels_sum(&s, 0, 0, 48, 36) == 9 * trace_pixels_sum(&t, 0, 0, 16, 12));
    int same = 1;
    for (uint32_t y = 0; y < 36; y++)
        for (uint32_t x = 0; x < 48; x++)
            same &= s.pixel[y * 48 + x] == t.pixel[(y / 3) * 16 + x / 3];
    for (uint32_t i = 0; i < t.nareas; i++) {
        const struct trace_area *a = &t.areas[i], *b = &s.areas[i];
        same &= b->x == 3 * a->x && b->y == 3 * a->y && b->w == 3 * a->w && b->h == 3 * a->h;
        same &= b->setup == a->setup && b->rc == a->rc && b->push == 9 * a->push && b->nc == a->nc;
        same &= b->total == a->setup + 9 * (a->total - a->setup);
    }
    CHECK(same);
    CHECK(s.dm_prepare == t.dm_prepare && s.rc_broadcast == t.rc_broadcast);
    /* a replay of the scaled trace on a grid of its own is a legal handout */
    struct replay_cfg c = {.ncs = 4, .balance = AREAS_DYNAMIC, .k = 96, .mips = 1, .line_us = 1000,
                           .byte_us = 520.8};
    struct replay_result r;
    CHECK_EQ_INT(replay_run(&s, &c, &r, err, sizeof err), 0);
    CHECK_EQ_INT(replay_check_legal(&s, &c, &r, err, sizeof err), 0);
    replay_free(&r);
    CHECK_EQ_INT(trace_scale(&t, 1, err, sizeof err), 0);
    CHECK_EQ_INT(t.width, 16);
    CHECK_EQ_INT(trace_scale(&t, AREAS_MAX_DIM, err, sizeof err), -1);
    CHECK(strstr(err, "scale") != NULL);
    CHECK_EQ_INT(t.width, 16);
    trace_free(&t);
    trace_free(&s);
}

static void test_replay_refuses_bad_settings(void)
{
    struct trace t;
    char err[TRACE_ERR_MAX];
    make_trace(&t, AREAS_STATIC, 8, 8, 2, 0);
    struct replay_result r;
    struct replay_cfg c = {.ncs = 0, .balance = AREAS_DYNAMIC, .k = 4, .mips = 1.0};
    CHECK(replay_run(&t, &c, &r, err, sizeof err) != 0 && strstr(err, "NC count"));
    c.ncs = 2;
    c.mips = 0;
    CHECK(replay_run(&t, &c, &r, err, sizeof err) != 0 && strstr(err, "--mips"));
    c.mips = 1;
    c.ncs = 3;
    c.as_recorded = 1;
    CHECK(replay_run(&t, &c, &r, err, sizeof err) != 0 && strstr(err, "as-recorded"));
    c.as_recorded = 0;
    c.balance = AREAS_DECREASING;
    c.guided = AREAS_MAX_GUIDED_FACTOR + 1;
    CHECK(replay_run(&t, &c, &r, err, sizeof err) != 0 && strstr(err, "guided factor"));
    trace_free(&t);
}

/* The timeline's bars (replay_timeline.h): one DM bar and one RC broadcast
 * bar before the NCs start, one RC hand-out bar and one NC bar per area,
 * the NC's on its own row; an NC's areas never overlap, and every bar lies
 * within the frame.  Read back from the script's data block. */
static void test_replay_timeline_bars(void)
{
    struct trace t;
    char err[TRACE_ERR_MAX];
    make_trace(&t, AREAS_DYNAMIC, 64, 48, 4, 64);
    struct replay_cfg c = {.ncs = 5, .balance = AREAS_DYNAMIC, .k = 64, .mips = 1.0,
                           .line_us = 1000, .byte_us = 520.8, .prefetch = 1};
    struct replay_result r;
    CHECK_EQ_INT(replay_run(&t, &c, &r, err, sizeof err), 0);
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    CHECK(f != NULL);
    if (!f)
        return;
    replay_timeline_script(f, &t, &c, &r, "test");
    fclose(f);
    unsigned count[TIMELINE_BARS] = {0};
    double last_end[TIMELINE_ROW_NC0 + 5] = {0}, unit = r.frame_us >= 1e7 ? 1e6 : 1e3;
    int bad_row = 0, overlap = 0, outside = 0;
    char *data = strstr(text, "$bars << EOD\n");
    CHECK(data != NULL && strstr(text, "\nplot $bars") != NULL);
    for (char *line = data ? strchr(data, '\n') + 1 : NULL; line && strncmp(line, "EOD", 3);
         line = strchr(line, '\n') + 1) {
        double from, to;
        unsigned row;
        int kind;
        if (sscanf(line, "%lf %lf %u %d", &from, &to, &row, &kind) != 4 || kind < 1 ||
            kind >= TIMELINE_BARS || row >= TIMELINE_ROW_NC0 + c.ncs) {
            bad_row = 1;
            break;
        }
        count[kind]++;
        outside |= from < 0 || to > r.frame_us / unit + 1e-6 || to <= from;
        int nc_bar = kind == TIMELINE_NC_AREA || kind == TIMELINE_NC_AREA_NEXT ||
                     kind == TIMELINE_NC_SETUP;
        bad_row |= (nc_bar || kind == TIMELINE_IDLE) != (row >= TIMELINE_ROW_NC0);
        if (nc_bar) {
            overlap |= from < last_end[row] - 1e-6;
            last_end[row] = to;
        }
    }
    CHECK(!bad_row && !overlap && !outside);
    CHECK_EQ_INT(count[TIMELINE_DM_PREPARE], 1);
    CHECK_EQ_INT(count[TIMELINE_RC_BROADCAST], 1);
    CHECK_EQ_INT(count[TIMELINE_IDLE], c.ncs);
    CHECK_EQ_INT(count[TIMELINE_NC_SETUP], c.ncs);
    CHECK_EQ_INT(count[TIMELINE_NC_AREA] + count[TIMELINE_NC_AREA_NEXT], r.nareas);
    CHECK_EQ_INT(count[TIMELINE_RC_HANDOUT], r.nareas);
    free(text);
    replay_free(&r);
    trace_free(&t);
}

int main(void)
{
    if (!mkdtemp(test_dir)) {
        perror("mkdtemp");
        return 1;
    }
    RUN(test_trace_round_trips);
    RUN(test_damaged_traces_are_refused);
    RUN(test_trace_records_schedule);
    RUN(test_static_replay_is_exact);
    RUN(test_dynamic_replay_is_legal);
    RUN(test_replay_serves_done);
    RUN(test_replay_refuses_bad_settings);
    RUN(test_trace_scale);
    RUN(test_replay_timeline_bars);
    if (tmp_dir_remove(test_dir) != 0) /* no shell, no link followed */
        printf("FAIL cleanup: %s: %s\n", test_dir, strerror(errno));
    return check_exit();
}
