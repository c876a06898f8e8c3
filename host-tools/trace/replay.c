/* replay.c: the discrete-event replay of a traced frame (replay.h). */
#include "host-tools/trace/replay.h"

#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

__attribute__((format(printf, 3, 4)))
static int replay_fail(char *err, size_t cap, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, cap, fmt, ap);
    va_end(ap);
    return -1;
}

void replay_free(struct replay_result *r)
{
    free(r->areas);
    free(r->nc_insns);
    free(r->nc_setup_end);
    memset(r, 0, sizeof *r);
}

/* 1 if the board handed traced area a out with its NC's start. */
static int replay_traced_first(const struct trace *t, const struct trace_area *a)
{
    return t->first_with_start && a->order == 0;
}

/* 1 if each NC asks for its first area once set up: a trace of a board
 * before version 3, or the what-if. */
static int replay_by_request(const struct trace *t, const struct replay_cfg *c)
{
    return c->first_by_request || !t->first_with_start;
}

/* Prices areas from the trace. */
struct replay_pricer {
    const struct trace *t;
    uint32_t *owner;  /* [w*h]: the traced area holding each pixel */
    uint64_t *prefix; /* [(w+1)*(h+1)]: 2-D prefix sums of the pixel costs */
    uint64_t rc_mean; /* the RC serving one request that hands out an area */
    uint64_t start_mean; /* the RC handing an NC its first area with its start */
    uint64_t setup_mean; /* an NC's set-up of the frame */
    uint64_t done_mean;  /* the RC serving an NC's MSG_NC_DONE, the traced mean;
                            0 when the trace holds none (before version 4) */
};

static int replay_pricer_init(struct replay_pricer *p, const struct trace *t)
{
    memset(p, 0, sizeof *p);
    p->t = t;
    size_t n = (size_t)t->width * t->height;
    p->owner = malloc(n * sizeof *p->owner);
    p->prefix = calloc((size_t)(t->width + 1) * (t->height + 1), sizeof *p->prefix);
    if (!p->owner || !p->prefix)
        return -1;
    uint64_t rc[2] = {0, 0}, kind[2] = {0, 0};
    for (uint32_t i = 0; i < t->nareas; i++) {
        const struct trace_area *a = &t->areas[i];
        int first = replay_traced_first(t, a);
        rc[first] += a->rc;
        kind[first]++;
        for (uint32_t y = a->y; y < a->y + a->h; y++)
            for (uint32_t x = a->x; x < a->x + a->w; x++)
                p->owner[(size_t)y * t->width + x] = i;
    }
    /* a trace with none of a kind prices it as the other */
    p->rc_mean = kind[0] ? rc[0] / kind[0] : rc[1] / kind[1];
    p->start_mean = kind[1] ? rc[1] / kind[1] : p->rc_mean;
    uint64_t s = 0;
    for (uint32_t i = 0; i < t->ncs; i++)
        s += t->nc_setup[i];
    p->setup_mean = s / t->ncs;
    p->done_mean = t->other_counted && t->rc_done_count ? t->rc_done / t->rc_done_count : 0;
    size_t W = t->width + 1;
    for (uint32_t y = 0; y < t->height; y++)
        for (uint32_t x = 0; x < t->width; x++)
            p->prefix[(y + 1) * W + x + 1] = t->pixel[(size_t)y * t->width + x] +
                                             p->prefix[y * W + x + 1] +
                                             p->prefix[(y + 1) * W + x] - p->prefix[y * W + x];
    return 0;
}

static void replay_pricer_free(struct replay_pricer *p)
{
    free(p->owner);
    free(p->prefix);
}

/* The NC's instructions for area a, and the RC's for handing it out (with
 * the NC's start when first). */
static uint64_t replay_price(const struct replay_pricer *p, const struct area *a, int first,
                             int *exact, uint64_t *rc)
{
    const struct trace *t = p->t;
    const struct trace_area *o = &t->areas[p->owner[(size_t)a->y * t->width + a->x]];
    *rc = first ? p->start_mean : p->rc_mean;
    if (o->x == a->x && o->y == a->y && o->w == a->w && o->h == a->h) {
        *exact = 1;
        if (replay_traced_first(t, o) == first)
            *rc = o->rc;
        return o->total;
    }
    *exact = 0;
    size_t W = t->width + 1;
    uint64_t sum = p->prefix[(a->y + a->h) * W + a->x + a->w] - p->prefix[a->y * W + a->x + a->w] -
                   p->prefix[(a->y + a->h) * W + a->x] + p->prefix[a->y * W + a->x];
    uint64_t push = o->push * a->w * a->h / ((uint64_t)o->w * o->h);
    return o->setup + sum + push;
}

/* The next area for NC nc: from the schedule, or the NC's own recorded
 * list.  1, or 0 when there is none. */
struct replay_source {
    struct areas sched;
    const struct trace *t;
    int as_recorded;
    uint32_t *next_of_nc; /* as recorded: the order of each NC's next area */
    uint32_t **list;      /* as recorded: per NC, its areas' indexes in order */
    uint32_t *count;      /* as recorded: per NC, its area count */
};

static int replay_next(struct replay_source *s, uint32_t nc, struct area *a)
{
    if (!s->as_recorded)
        return areas_next(&s->sched, a);
    if (s->next_of_nc[nc] >= s->count[nc])
        return 0;
    const struct trace_area *ta = &s->t->areas[s->list[nc][s->next_of_nc[nc]++]];
    *a = (struct area){ta->x, ta->y, ta->w, ta->h};
    return 1;
}

static double replay_line(const struct replay_cfg *c, uint32_t bytes)
{
    return c->line_us + c->byte_us * bytes;
}

/* One replay under way: the NCs' pending requests and the RC's time. */
struct replay_state {
    const struct trace *t;
    const struct replay_cfg *c;
    struct replay_result *r;
    struct replay_source src;
    struct replay_pricer p;
    uint32_t total;     /* areas the schedule hands out */
    double us_per;      /* microseconds per instruction */
    double t0;          /* the NCs start setting up */
    double *pending;    /* [ncs]: the NC's request arrives at the RC, or INF */
    double *sent;       /* [ncs]: when that request left */
    double *busy_until; /* [ncs]: the NC's work ends */
    double *computing;  /* [ncs]: the NC's computing so far */
    double *rtt;        /* [ncs]: the round trip the NC last saw (< 0: none) */
    double *area_start; /* [ncs]: when the NC's current area began */
    uint32_t *area_px;  /* [ncs]: its pixels */
    double *done_at;    /* [ncs]: the NC's MSG_NC_DONE arrives at the RC, or INF */
    double rc_free, rc_busy;
};

static void replay_source_free(struct replay_source *src, uint32_t ncs)
{
    if (src->list)
        for (uint32_t n = 0; n < ncs; n++)
            free(src->list[n]);
    free(src->list);
    free(src->count);
    free(src->next_of_nc);
}

/* As recorded: each NC's areas in its order.  0, or -1 (out of memory). */
static int replay_source_recorded(struct replay_source *src, const struct trace *t)
{
    src->next_of_nc = calloc(t->ncs, sizeof *src->next_of_nc);
    src->count = calloc(t->ncs, sizeof *src->count);
    src->list = calloc(t->ncs, sizeof *src->list);
    if (!src->next_of_nc || !src->count || !src->list)
        return -1;
    for (uint32_t i = 0; i < t->nareas; i++)
        src->count[t->areas[i].nc]++;
    for (uint32_t n = 0; n < t->ncs; n++)
        if (!(src->list[n] = calloc(src->count[n] ? src->count[n] : 1, sizeof **src->list)))
            return -1;
    for (uint32_t i = 0; i < t->nareas; i++)
        src->list[t->areas[i].nc][t->areas[i].order] = i;
    return 0;
}

static void replay_state_free(struct replay_state *s)
{
    replay_pricer_free(&s->p);
    free(s->pending);
    free(s->sent);
    free(s->busy_until);
    free(s->computing);
    free(s->rtt);
    free(s->area_start);
    free(s->area_px);
    free(s->done_at);
    replay_source_free(&s->src, s->t->ncs);
}

/* The schedule, the pricer and the arrays.  0, or -1 with err filled. */
static int replay_state_init(struct replay_state *s, char *err, size_t cap)
{
    const struct trace *t = s->t;
    const struct replay_cfg *c = s->c;
    struct replay_result *r = s->r;
    s->src.t = t;
    s->src.as_recorded = c->as_recorded;
    int st = areas_init(&s->src.sched, c->as_recorded ? AREAS_STATIC : c->balance, t->width,
                        t->height, c->ncs, c->k);
    if (st == AREAS_OK && c->guided)
        st = areas_set_guided_factor(&s->src.sched, c->guided);
    if (st != AREAS_OK)
        return replay_fail(err, cap, "area schedule: %s", areas_strerror(st));
    s->total = c->as_recorded ? t->nareas : areas_count(&s->src.sched);
    s->pending = malloc(c->ncs * sizeof *s->pending);
    s->sent = malloc(c->ncs * sizeof *s->sent);
    s->busy_until = calloc(c->ncs, sizeof *s->busy_until);
    s->computing = calloc(c->ncs, sizeof *s->computing);
    s->rtt = malloc(c->ncs * sizeof *s->rtt);
    s->area_start = calloc(c->ncs, sizeof *s->area_start);
    s->area_px = calloc(c->ncs, sizeof *s->area_px);
    s->done_at = malloc(c->ncs * sizeof *s->done_at);
    for (uint32_t n = 0; s->rtt && n < c->ncs; n++)
        s->rtt[n] = -1;
    for (uint32_t n = 0; s->done_at && n < c->ncs; n++)
        s->done_at[n] = INFINITY;
    r->areas = calloc(s->total, sizeof *r->areas);
    r->nc_insns = calloc(c->ncs, sizeof *r->nc_insns);
    r->nc_setup_end = calloc(c->ncs, sizeof *r->nc_setup_end);
    if (replay_pricer_init(&s->p, t) != 0 || !s->pending || !s->sent || !s->busy_until ||
        !s->computing || !s->rtt || !s->area_start || !s->area_px || !s->done_at || !r->areas ||
        !r->nc_insns || !r->nc_setup_end ||
        (c->as_recorded && replay_source_recorded(&s->src, t) != 0))
        return replay_fail(err, cap, "out of memory");
    return 0;
}

/* When NC nc asks for the area after one it computes from start to end:
 * asking ahead, the round trip it last saw before the end, never before
 * the start, and at the start while it has seen none (its first area came
 * with its start); else at the end. */
static double replay_ask_time(const struct replay_state *s, uint32_t nc, double start, double end)
{
    if (!s->c->prefetch)
        return end;
    if (s->rtt[nc] < 0)
        return start;
    return end - s->rtt[nc] > start ? end - s->rtt[nc] : start;
}

/* The round trip NC nc sees when the answer to its request arrives
 * (roles/nc_render.c): all of it if it was waiting (idle since its area
 * ended); while it has seen none, up to its next look for the answer
 * (after 1, 2, 4 ... of its area's pixels, taken as equally long) or its
 * area's end; else from its request to its area's end, when it finds the
 * answer there, which lowers its estimate only. */
static void replay_see_round_trip(struct replay_state *s, uint32_t nc, double arrive)
{
    double end = s->busy_until[nc], seen_at = end;
    if (arrive > end) {
        s->rtt[nc] = arrive - s->sent[nc];
        return;
    }
    if (s->rtt[nc] < 0) {
        double per = (end - s->area_start[nc]) / (s->area_px[nc] ? s->area_px[nc] : 1);
        uint64_t k = 1;
        while (s->area_start[nc] + (double)k * per < arrive)
            k *= 2;
        double look = s->area_start[nc] + (double)k * per;
        seen_at = look < end ? look : end;
    }
    double seen = seen_at - s->sent[nc];
    if (s->rtt[nc] < 0 || seen < s->rtt[nc])
        s->rtt[nc] = seen;
}

/* NC nc computes area a (insns instructions) from start; it asks again. */
static void replay_compute(struct replay_state *s, uint32_t nc, const struct area *a,
                           uint64_t insns, int exact, int with_start, double served[3],
                           double start)
{
    struct replay_result *r = s->r;
    double end = start + (double)insns * s->us_per;
    r->areas[r->nareas++] = (struct replay_area){a->x, a->y, a->w, a->h, nc, insns, exact,
                                                 with_start, served[0], served[1],
                                                 served[2], start, end};
    r->exact += (uint32_t)exact;
    s->busy_until[nc] = end;
    s->area_start[nc] = start;
    s->area_px[nc] = a->w * a->h;
    s->computing[nc] += end - start;
    r->nc_insns[nc] += insns;
    s->sent[nc] = replay_ask_time(s, nc, start, end);
    s->pending[nc] = s->sent[nc] + replay_line(s->c, REPLAY_REQUEST_BYTES);
}

/* Each NC set up from the broadcast on, and its first request on the line
 * (replay_start_areas moves both later). */
static void replay_setup(struct replay_state *s)
{
    const struct replay_cfg *c = s->c;
    s->t0 = (double)((c->pipelined ? 0 : s->t->dm_prepare) + s->t->rc_broadcast) * s->us_per;
    for (uint32_t n = 0; n < c->ncs; n++) {
        uint64_t setup = c->as_recorded ? s->t->nc_setup[n] : s->p.setup_mean;
        s->r->nc_setup_end[n] = s->busy_until[n] = s->t0 + (double)setup * s->us_per;
        s->computing[n] = (double)setup * s->us_per;
        s->sent[n] = s->busy_until[n];
        s->pending[n] = s->sent[n] + replay_line(c, REPLAY_REQUEST_BYTES);
    }
    s->rc_free = s->t0;
}

/* The board's start: the RC starts the NCs in turn, handing each its first
 * area with the start; an NC sets up from then and computes it.  An NC
 * for which no area is left asks once set up. */
static void replay_start_areas(struct replay_state *s)
{
    for (uint32_t n = 0; n < s->c->ncs; n++) {
        struct area a;
        int have = replay_next(&s->src, n, &a), exact = 0;
        uint64_t rc_insns = 0, insns = 0;
        if (have)
            insns = replay_price(&s->p, &a, 1, &exact, &rc_insns);
        double handed = s->rc_free + (double)rc_insns * s->us_per;
        double served[3] = {s->rc_free, s->rc_free, handed}, shift = handed - s->t0;
        s->rc_busy += handed - s->rc_free;
        s->rc_free = handed;
        s->r->nc_setup_end[n] += shift;
        s->busy_until[n] += shift;
        s->sent[n] += shift;
        s->pending[n] += shift;
        if (have)
            replay_compute(s, n, &a, insns, exact, 1, served, s->busy_until[n]);
    }
}

/* NC nc asked ahead for the area after its current one (ending at
 * busy_until), and the answer arrives at `arrive` (INFINITY: none comes):
 * if that is after the end, the NC sends MSG_NC_DONE there
 * (roles/nc_render.c), which the RC serves in its turn. */
static void replay_done_if_late(struct replay_state *s, uint32_t nc, double arrive)
{
    if (s->p.done_mean && s->c->prefetch && s->sent[nc] < s->busy_until[nc] &&
        arrive > s->busy_until[nc])
        s->done_at[nc] = s->busy_until[nc] + replay_line(s->c, REPLAY_REQUEST_BYTES);
}

/* The RC serves NC nc's MSG_NC_DONE, which arrived before any request
 * waiting. */
static void replay_serve_done(struct replay_state *s, uint32_t nc)
{
    double start = s->rc_free > s->done_at[nc] ? s->rc_free : s->done_at[nc];
    double end = start + (double)s->p.done_mean * s->us_per;
    s->rc_busy += end - start;
    s->rc_free = end;
    s->done_at[nc] = INFINITY;
    s->r->dones++;
}

/* The NC whose message reaches the RC first, *done set when that is a
 * MSG_NC_DONE; first: when it arrives (INFINITY: none is coming). */
static uint32_t replay_next_message(const struct replay_state *s, int *done, double *first)
{
    uint32_t nc = 0;
    *first = INFINITY;
    *done = 0;
    for (uint32_t n = 0; n < s->c->ncs; n++) {
        if (s->pending[n] < *first) {
            *first = s->pending[n];
            nc = n;
            *done = 0;
        }
        if (s->done_at[n] < *first) {
            *first = s->done_at[n];
            nc = n;
            *done = 1;
        }
    }
    return nc;
}

/* The RC serves messages in the order they arrive until every NC is told
 * to stop.  0, or -1 with err filled. */
static int replay_serve(struct replay_state *s, char *err, size_t cap)
{
    for (;;) {
        int done;
        double first;
        uint32_t nc = replay_next_message(s, &done, &first);
        if (first == INFINITY)
            return 0;
        if (done) {
            replay_serve_done(s, nc);
            continue;
        }
        struct area a;
        int have = replay_next(&s->src, nc, &a), exact = 0;
        uint64_t rc_insns = s->p.rc_mean, insns = 0;
        if (have)
            insns = replay_price(&s->p, &a, 0, &exact, &rc_insns);
        double start = s->rc_free > first ? s->rc_free : first;
        double end = start + (double)rc_insns * s->us_per;
        s->rc_free = end;
        s->rc_busy += end - start;
        if (!have) {
            s->pending[nc] = INFINITY;
            replay_done_if_late(s, nc, INFINITY); /* parked until told to stop */
            continue;
        }
        if (s->r->nareas == s->total)
            return replay_fail(err, cap, "the schedule handed out more areas than it counts");
        double arrive = end + replay_line(s->c, REPLAY_ANSWER_BYTES);
        replay_done_if_late(s, nc, arrive);
        double served[3] = {s->sent[nc], start, end};
        replay_see_round_trip(s, nc, arrive);
        replay_compute(s, nc, &a, insns, exact, 0, served,
                       arrive > s->busy_until[nc] ? arrive : s->busy_until[nc]);
    }
}

/* The frame's end, and how busy the NCs and the RC were. */
static void replay_totals(struct replay_state *s)
{
    double frame = s->t0, work = 0;
    for (uint32_t n = 0; n < s->c->ncs; n++) {
        if (s->busy_until[n] > frame)
            frame = s->busy_until[n];
        work += s->computing[n];
    }
    s->r->frame_us = frame;
    s->r->busy = frame > 0 ? work / (s->c->ncs * frame) : 0;
    s->r->rc_busy = frame > 0 ? s->rc_busy / frame : 0;
}

int replay_run(const struct trace *t, const struct replay_cfg *c, struct replay_result *r,
               char *err, size_t cap)
{
    memset(r, 0, sizeof *r);
    if (c->ncs == 0 || c->ncs > 4096)
        return replay_fail(err, cap, "NC count %" PRIu32 ": must be 1..4096", c->ncs);
    if (!(c->mips > 0) || !(c->line_us >= 0) || !(c->byte_us >= 0))
        return replay_fail(err, cap, "--mips must be above 0, --line-us and --byte-us at least 0");
    if (c->as_recorded && c->ncs != t->ncs)
        return replay_fail(err, cap, "--as-recorded replays the board's %" PRIu32 " NCs, not %"
                           PRIu32, t->ncs, c->ncs);
    struct replay_state s;
    memset(&s, 0, sizeof s);
    s.t = t;
    s.c = c;
    s.r = r;
    s.us_per = 1.0 / c->mips;
    int rc = replay_state_init(&s, err, cap);
    if (rc == 0) {
        replay_setup(&s);
        if (!replay_by_request(t, c))
            replay_start_areas(&s);
    }
    if (rc == 0)
        rc = replay_serve(&s, err, cap);
    if (rc == 0)
        replay_totals(&s);
    replay_state_free(&s);
    if (rc != 0)
        replay_free(r);
    return rc;
}

int replay_check_legal(const struct trace *t, const struct replay_cfg *c,
                       const struct replay_result *r, char *err, size_t cap)
{
    const double eps = 1e-6;
    size_t n = (size_t)t->width * t->height;
    uint8_t *seen = calloc(n, 1);
    double *last_end = calloc(c->ncs, sizeof *last_end);
    double *last_start = calloc(c->ncs, sizeof *last_start);
    int rc = 0;
    if (!seen || !last_end || !last_start) {
        rc = replay_fail(err, cap, "out of memory");
        goto out;
    }
    struct areas sched;
    if (!c->as_recorded &&
        (areas_init(&sched, c->balance, t->width, t->height, c->ncs, c->k) != AREAS_OK ||
         (c->guided && areas_set_guided_factor(&sched, c->guided) != AREAS_OK))) {
        rc = replay_fail(err, cap, "bad schedule");
        goto out;
    }
    if (!c->as_recorded && r->nareas != areas_count(&sched)) {
        rc = replay_fail(err, cap, "%" PRIu32 " areas handed out, the schedule has %" PRIu32,
                         r->nareas, areas_count(&sched));
        goto out;
    }
    for (uint32_t n2 = 0; n2 < c->ncs; n2++)
        last_end[n2] = last_start[n2] = r->nc_setup_end[n2];
    /* Requests the RC served: each starts after the one before it ended. */
    double rc_free = 0;
    for (uint32_t i = 0; i < r->nareas && rc == 0; i++) {
        const struct replay_area *a = &r->areas[i];
        struct area want;
        if (!c->as_recorded && (!areas_next(&sched, &want) || want.x != a->x ||
                                want.y != a->y || want.w != a->w || want.h != a->h)) {
            rc = replay_fail(err, cap, "area %" PRIu32 " is not the schedule's next", i);
            break;
        }
        if (a->nc >= c->ncs) {
            rc = replay_fail(err, cap, "area %" PRIu32 " went to NC %" PRIu32, i, a->nc);
            break;
        }
        double line_req = a->with_start ? 0 : replay_line(c, REPLAY_REQUEST_BYTES);
        double line_ans = a->with_start ? 0 : replay_line(c, REPLAY_ANSWER_BYTES);
        double asked_after = c->prefetch ? last_start[a->nc] : last_end[a->nc];
        if (a->with_start && (replay_by_request(t, c) || i >= c->ncs || a->nc != i))
            rc = replay_fail(err, cap, "area %" PRIu32 " came with a start, but it is not NC %"
                             PRIu32 "'s first", i, a->nc);
        else if (!a->with_start && a->request_sent + eps < asked_after)
            rc = replay_fail(err, cap, "area %" PRIu32 ": NC %" PRIu32 " asked before it %s "
                             "its previous area", i, a->nc, c->prefetch ? "started" : "finished");
        else if (a->serve_start + eps < a->request_sent + line_req)
            rc = replay_fail(err, cap, "area %" PRIu32 ": served before the request arrived", i);
        else if (a->serve_start + eps < rc_free)
            rc = replay_fail(err, cap, "area %" PRIu32 ": the RC served two requests at once",
                             i);
        else if (a->start + eps < a->serve_end + line_ans || a->start + eps < last_end[a->nc])
            rc = replay_fail(err, cap, "area %" PRIu32 ": NC %" PRIu32 " started it before the "
                             "answer arrived or while busy", i, a->nc);
        else if (a->end < a->start)
            rc = replay_fail(err, cap, "area %" PRIu32 " ends before it starts", i);
        if (rc)
            break;
        rc_free = a->serve_end;
        last_end[a->nc] = a->end;
        last_start[a->nc] = a->start;
        for (uint32_t y = a->y; y < a->y + a->h && rc == 0; y++)
            for (uint32_t x = a->x; x < a->x + a->w; x++)
                if (y >= t->height || x >= t->width || seen[(size_t)y * t->width + x]++) {
                    rc = replay_fail(err, cap, "area %" PRIu32 " is off the screen or overlaps "
                                     "another", i);
                    break;
                }
    }
    for (size_t p = 0; p < n && rc == 0; p++)
        if (!seen[p])
            rc = replay_fail(err, cap, "pixel (%zu,%zu) was handed to no NC", p % t->width,
                             p / t->width);
out:
    free(seen);
    free(last_end);
    free(last_start);
    return rc;
}

int replay_check_board(const struct trace *t, char *err, size_t cap)
{
    struct areas sched;
    int st = areas_init(&sched, (enum areas_mode)t->balance, t->width, t->height, t->ncs, t->k);
    if (st == AREAS_OK && t->guided && t->balance == AREAS_DECREASING)
        st = areas_set_guided_factor(&sched, t->guided);
    if (st != AREAS_OK)
        return replay_fail(err, cap, "the trace's schedule: %s", areas_strerror(st));
    uint32_t *next = calloc(t->ncs, sizeof *next);
    if (!next)
        return replay_fail(err, cap, "out of memory");
    int rc = 0;
    for (uint32_t i = 0; i < t->nareas && rc == 0; i++) {
        const struct trace_area *a = &t->areas[i];
        struct area want;
        if (!areas_next(&sched, &want))
            rc = replay_fail(err, cap, "the board handed out %" PRIu32 " areas, the schedule "
                             "has %" PRIu32, t->nareas, areas_count(&sched));
        else if (want.x != a->x || want.y != a->y || want.w != a->w || want.h != a->h)
            rc = replay_fail(err, cap, "area %" PRIu32 " of the board, %" PRIu32 "x%" PRIu32
                             " at (%" PRIu32 ",%" PRIu32 "), is not the schedule's next, %"
                             PRIu32 "x%" PRIu32 " at (%" PRIu32 ",%" PRIu32 ")", i, a->w, a->h,
                             a->x, a->y, want.w, want.h, want.x, want.y);
        else if (a->nc >= t->ncs || a->order != next[a->nc]++)
            rc = replay_fail(err, cap, "area %" PRIu32 ": NC %" PRIu32 " drew it as its area %"
                             PRIu32 ", out of its order", i, a->nc, a->order);
    }
    struct area more;
    if (rc == 0 && areas_next(&sched, &more))
        rc = replay_fail(err, cap, "the board handed out %" PRIu32 " areas, the schedule has %"
                         PRIu32, t->nareas, areas_count(&sched));
    free(next);
    return rc;
}
