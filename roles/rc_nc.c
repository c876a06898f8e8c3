/* rc_nc.c: the RC's side of the NCs while a frame renders (rc_run.h): it
 * answers their area requests, notices the ones that fail (a fault, or the
 * watchdog) and hands their areas to others, and carries out the test
 * hook's fault plan by marking the messages it sends. */
#include <stdint.h>
#include <string.h>

#include "drivers/framemem/dc.h"
#include "drivers/imsu/imsu.h"
#include "drivers/serial/line.h"
#include "kernel/cpu.h"
#include "kernel/klog.h"
#include "kernel/ktime.h"
#include "proto/hostlink.h"
#include "proto/insn_mark.h"
#include "proto/textfmt.h"
#include "proto/wire.h"
#include "roles/gigs.h"
#include "roles/rc_run.h"
#include "roles/selftest.h"
#include "roles/unit.h"
#include "proto/unitmsg.h"

/* The steps of answering a request, inlined into rc_nc_serve: the RC's
 * cost per area bounds how small the last areas can be on many NCs
 * (docs/areas.md). */
#define RC_INLINE static inline __attribute__((always_inline))

/* NCs given up for failed since the board started: out of later frames. */
static uint8_t rc_nc_gone[UNITS_MAX_CORES];

void rc_fail(struct rc_run *run, int32_t status, const char *fmt, uint32_t a, uint32_t b)
{
    if (run->status != LINK_OK)
        return;
    run->status = status;
    fmt_snprintf(run->why, sizeof run->why, fmt, (unsigned)a, (unsigned)b);
}

RC_INLINE void rc_nc_send(struct rc_run *run, uint32_t nc, struct line_msg *m)
{
    /* Nearly always there is room: the deadline is worked out only when
     * there is none (the RC pays this per area request). */
    int r = line_end_try_send(&run->nc[nc].line, m);
    if (r == LINE_ERR_FULL)
        r = line_send(nc, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
    if (r != LINE_OK)
        klog("render: send of message %u to NC %u: %s", (unsigned)m->type, (unsigned)nc,
             line_strerror(r));
}

/* NC k goes to state s; the counts per state follow. */
static void rc_nc_set(struct rc_run *run, uint32_t k, enum rc_nc_state s)
{
    struct rc_nc *n = &run->nc[k];
    if (n->state == s)
        return; /* a busy NC asking ahead stays busy */
    run->in_state[n->state]--;
    run->in_state[s]++;
    n->state = (uint8_t)s;
}

void rc_nc_begin(struct rc_run *run, const uint8_t *plan, uint32_t n)
{
    run->ncs = 0;
    memset(run->in_state, 0, sizeof run->in_state);
    run->in_state[RC_NC_OUT] = board_ncores - UNITS_FIRST_NC;
    for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++) {
        run->nc[k].state = RC_NC_OUT;
        if (line_end_of(k, &run->nc[k].line) != LINE_OK) {
            klog("render: no serial line to NC %u", (unsigned)k);
            rc_nc_gone[k] = 1;
        }
        if (rc_nc_gone[k]) {
            run->fails.failed_before++;
            /* One given up while only slow may have begun a read since. */
            (void)imsu_bcast_read_abandon(&imsu_rc_ncs, k);
        } else {
            rc_nc_set(run, k, RC_NC_IDLE);
            run->ncs++;
        }
    }
    for (uint32_t i = 0; i < n; i++) {
        struct link_inject e;
        link_inject_get(plan + i * LINK_INJECT_ENTRY_SIZE, &e);
        if (e.kind < 1 || e.kind > LINK_INJECT_KINDS || e.core == UNITS_DM_CORE)
            continue; /* the DM's is the DM's */
        if (e.core == UNITS_RC_CORE)
            run->self_inject = e;
        else if (e.core < board_ncores && !rc_nc_gone[e.core])
            run->nc[e.core].inject = e;
        else
            klog("render: fault plan entry %u (core %u, kind %u) ignored", (unsigned)i,
                 (unsigned)e.core, (unsigned)e.kind);
    }
}

/* NC k takes area a: it holds it from now.  Writes the MSG_NC_AREA
 * payload at p (with the fault plan's failure when this is the area it
 * plans for); returns its length. */
RC_INLINE uint16_t rc_nc_hand(struct rc_run *run, uint32_t k, const struct area *a, uint8_t *p)
{
    struct rc_nc *n = &run->nc[k];
    uint16_t len = MSG_NC_AREA_SIZE;
    wire_put_u16(p, (uint16_t)a->x);
    wire_put_u16(p + 2, (uint16_t)a->y);
    wire_put_u16(p + 4, (uint16_t)a->w);
    wire_put_u16(p + 6, (uint16_t)a->h);
    if (n->inject.kind && n->given == n->inject.area) {
        len = MSG_NC_AREA_INJECT_SIZE;
        wire_put_u8(p + 8, n->inject.kind);
        wire_put_u8(p + 9, 0);
        wire_put_u16(p + 10, (uint16_t)(n->inject.row * (a->h + 1) / 256));
    }
    n->given++;
    if (n->nheld == 0)
        n->since = ktime_now();
    n->held[n->nheld++] = *a;
    n->asking = 0;
    rc_nc_set(run, k, RC_NC_BUSY);
    return len;
}

/* Traced (docs/trace.md): after the span of serving NC k, the NC, whether
 * it got an area, and the area's x and y; one that got none, the type of
 * the message served (0: none) and 0. */
static void rc_nc_trace_served(const struct rc_run *run, uint32_t k, int handed, uint16_t type)
{
    insn_mark_trace_span_end();
    insn_mark_trace_bits(k, 16);
    const struct rc_nc *n = &run->nc[k];
    const struct area *a = &n->held[n->nheld ? n->nheld - 1u : 0u]; /* the one given last */
    insn_mark_trace_bits((uint32_t)handed, 1);
    insn_mark_trace_bits(handed ? a->x : type, 16);
    insn_mark_trace_bits(handed ? a->y : 0, 16);
}

/* NC k's MSG_NC_START in m (its fields written already), with its first
 * area while one is left: it sets up and starts on it with no request on
 * the line.  Traced, the hand-out and its message are a record as a
 * request served. */
static void rc_nc_start_one(struct rc_run *run, uint32_t k, struct line_msg *m)
{
    m->type = MSG_NC_START;
    m->len = MSG_NC_START_SIZE;
    if (run->trace)
        insn_mark_trace_span_begin();
    struct area a;
    int handed = run->status == LINK_OK && areas_next(&run->sched, &a);
    if (handed) /* rc_nc_hand starts its clock */
        m->len = (uint16_t)(m->len + rc_nc_hand(run, k, &a, m->payload + MSG_NC_START_SIZE));
    else
        run->nc[k].since = ktime_now();
    rc_nc_send(run, k, m);
    if (run->trace)
        rc_nc_trace_served(run, k, handed, 0);
}

void rc_nc_start(struct rc_run *run, struct line_msg *m, uint8_t flags, uint32_t largest,
                 uint8_t clip)
{
    /* What the pending map holds from before the frame is stale: every
     * line is looked at once below. */
    for (uint32_t w = 0; w < LINE_PENDING_WORDS; w++)
        (void)line_pending_take(w);
    /* The fields every NC's start shares; each adds its first area. */
    wire_put_u8(m->payload, flags);
    wire_put_u8(m->payload + 1, clip);
    wire_put_u16(m->payload + 2, 0);
    wire_put_u32(m->payload + 4, largest);
    for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++) {
        if (run->nc[k].state == RC_NC_OUT)
            continue;
        rc_nc_start_one(run, k, m);
        /* Its doorbell armed; a message there already is looked at. */
        if (line_end_recv_ready_arm(&run->nc[k].line))
            line_pending_mark(k);
    }
    run->next_scan = ktime_deadline_ms(GIGS_WATCH_MS);
}

/* NC k failed: out for good; the areas it held go back to be handed out. */
static void rc_nc_lost(struct rc_run *run, uint32_t k, int by_watchdog)
{
    if (k >= UNITS_MAX_CORES)
        return;
    struct rc_nc *n = &run->nc[k];
    rc_nc_gone[k] = 1;
    dc_ignore_producer(k);
    (void)imsu_bcast_read_abandon(&imsu_rc_ncs, k);
    struct link_render_fails *f = &run->fails;
    f->failed++;
    link_core_map_set(f->failed_map, k);
    if (by_watchdog)
        link_core_map_set(f->watchdog_map, k);
    const char *how = by_watchdog ? "stopped answering" : "halted with a fault";
    if (n->nheld == 0)
        klog("render: NC %u %s (it held no area)", (unsigned)k, how);
    for (uint32_t i = 0; i < n->nheld; i++) {
        const struct area *a = &n->held[i];
        run->again[run->nagain++] = *a;
        if (f->reissued < LINK_REISSUE_LIST_MAX)
            f->area[f->reissued] = (struct link_reissue){(uint16_t)k, (uint16_t)a->x,
                                                         (uint16_t)a->y, (uint16_t)a->w,
                                                         (uint16_t)a->h};
        f->reissued++;
        klog("render: NC %u %s; its area %ux%u at (%u,%u) goes to another NC", (unsigned)k, how,
             (unsigned)a->w, (unsigned)a->h, (unsigned)a->x, (unsigned)a->y);
    }
    n->nheld = 0;
    n->asking = 0;
    rc_nc_set(run, k, RC_NC_STOPPED);
}

/* 1 if NC k has been silent longer than the watchdog allows: past its
 * deadline, its progress word still for GIGS_WATCH_FLOOR_MS while the
 * others' (peers: every NC's words summed now) moved on by
 * GIGS_WATCH_PEER_PIXELS, or still for GIGS_WATCH_ALONE_MS. */
static int rc_nc_overdue(struct rc_run *run, uint32_t k, uint32_t peers)
{
    struct rc_nc *n = &run->nc[k];
    uint64_t now = ktime_now(), allow;
    uint32_t p = gigs_nc_progress[k];
    if (p != n->progress || n->moved < n->since) {
        n->progress = p;
        n->moved = now;
        n->peers_then = peers;
    }
    if (now <= n->since || now - n->moved <= ktime_ms_to_ticks(GIGS_WATCH_FLOOR_MS))
        return 0;
    if (peers - n->peers_then < GIGS_WATCH_PEER_PIXELS &&
        now - n->moved <= ktime_ms_to_ticks(GIGS_WATCH_ALONE_MS))
        return 0; /* the others did not get on either: the host is slow */
    switch (n->state) {
    case RC_NC_BUSY:
        if (run->slow_pixels == 0) {
            allow = ktime_ms_to_ticks(GIGS_WATCH_FIRST_MS);
        } else {
            uint64_t pixels = (uint64_t)n->held[0].w * n->held[0].h;
            allow = GIGS_WATCH_FACTOR * run->slow_ticks * pixels / run->slow_pixels +
                    ktime_ms_to_ticks(GIGS_WATCH_FLOOR_MS);
        }
        break;
    case RC_NC_IDLE:
        allow = ktime_ms_to_ticks(GIGS_WATCH_FIRST_MS);
        break;
    case RC_NC_STOPPING:
        allow = ktime_ms_to_ticks(GIGS_WATCH_FLOOR_MS);
        break;
    default:
        return 0; /* parked: waiting for the RC */
    }
    return now - n->since > allow;
}

/* NC k's state from what it holds and whether it asks. */
static void rc_nc_settle(struct rc_run *run, uint32_t k)
{
    const struct rc_nc *n = &run->nc[k];
    rc_nc_set(run, k, n->nheld ? RC_NC_BUSY : n->asking ? RC_NC_PARKED : RC_NC_IDLE);
}

/* NC k says it has finished `finished` areas of the frame: its oldest held
 * ones up to that count are done, now. */
static void rc_nc_finished(struct rc_run *run, uint32_t k, uint32_t finished)
{
    struct rc_nc *n = &run->nc[k];
    uint32_t newly = finished - n->finished;
    if (newly == 0)
        return; /* a request ahead: its area goes on */
    if (newly > n->nheld) {
        klog("render: NC %u says it finished %u areas; it held %u", (unsigned)k,
             (unsigned)newly, (unsigned)n->nheld);
        newly = n->nheld;
    }
    n->finished += newly;
    run->done += newly;
    uint64_t now = ktime_now();
    /* The slowest rate: the oldest area's alone (any other finished in
     * the same message took no time of its own). */
    uint64_t ticks = now - n->since;
    uint32_t pixels = n->held[0].w * n->held[0].h; /* <= 2^24: AREAS_MAX_DIM */
    if (run->slow_pixels == 0 || ticks * run->slow_pixels > run->slow_ticks * pixels) {
        run->slow_ticks = ticks;
        run->slow_pixels = pixels;
    }
    _Static_assert(RC_NC_HELD_MAX == 2, "the one left, if any, moves to the front");
    n->nheld = (uint8_t)(n->nheld - newly);
    if (n->nheld)
        n->held[0] = n->held[RC_NC_HELD_MAX - 1];
    n->since = now; /* the next one is its current area from now */
}

/* One message from NC k. */
static void rc_nc_message(struct rc_run *run, uint32_t k, struct line_msg *m)
{
    struct rc_nc *n = &run->nc[k];
    if (m->type == MSG_NC_STOPPED) {
        rc_nc_set(run, k, RC_NC_STOPPED);
        uint32_t high = wire_get_u32(m->payload);
        if (high > run->nc_high_max)
            run->nc_high_max = high;
        gigs_stats_add(&run->stats, m->payload + 4);
        return;
    }
    if ((m->type != MSG_NC_REQ && m->type != MSG_NC_DONE) ||
        (n->state != RC_NC_IDLE && n->state != RC_NC_BUSY && n->state != RC_NC_PARKED)) {
        klog("render: unexpected message %u from NC %u", (unsigned)m->type, (unsigned)k);
        return;
    }
    int32_t st = (int32_t)wire_get_u32(m->payload);
    if (st < 0) {
        if (run->status == LINK_OK) {
            run->status = st;
            fmt_snprintf(run->why, sizeof run->why, "NC %u: %.*s", (unsigned)k,
                         (int)(m->len - 4), (const char *)m->payload + 4);
        }
        n->nheld = 0; /* the frame has failed: what it held is not rendered */
    } else {
        rc_nc_finished(run, k, (uint32_t)st);
    }
    if (m->type == MSG_NC_REQ) {
        if (n->asking || n->nheld >= RC_NC_HELD_MAX)
            klog("render: NC %u asked again while holding %u areas", (unsigned)k,
                 (unsigned)n->nheld);
        n->asking = n->nheld < RC_NC_HELD_MAX;
    }
    rc_nc_settle(run, k);
}

/* Static balancing: 1 if NC k, which has had its area, must leave the
 * schedule's next one to an NC of the frame that has had none yet (one
 * that asked late: it has not failed, so its area waits for it).  Areas
 * taken back from failed NCs go to whoever asks. */
static int rc_nc_static_waits(const struct rc_run *run, uint32_t k)
{
    if (!run->one_per_nc || run->nc[k].given == 0)
        return 0;
    for (uint32_t j = UNITS_FIRST_NC; j < board_ncores; j++) {
        const struct rc_nc *o = &run->nc[j];
        if (o->given == 0 && (o->state == RC_NC_IDLE || o->state == RC_NC_BUSY ||
                              o->state == RC_NC_PARKED))
            return 1;
    }
    return 0;
}

/* Gives NC k, which asks, the next area (one taken back first); 0 if none
 * is left, or none for it. */
RC_INLINE int rc_nc_give(struct rc_run *run, uint32_t k, struct line_msg *m)
{
    struct rc_nc *n = &run->nc[k];
    struct area a;
    if (!n->asking || n->nheld >= RC_NC_HELD_MAX)
        return 0;
    if (run->nagain)
        a = run->again[--run->nagain];
    else if (rc_nc_static_waits(run, k) || !areas_next(&run->sched, &a))
        return 0;
    m->type = MSG_NC_AREA;
    m->len = rc_nc_hand(run, k, &a, m->payload);
    rc_nc_send(run, k, m);
    return 1;
}

static void rc_nc_stop(struct rc_run *run, uint32_t k, struct line_msg *m)
{
    struct rc_nc *n = &run->nc[k];
    m->type = MSG_NC_STOP;
    m->len = 0;
    if (n->inject.kind && n->given <= n->inject.area) {
        m->len = 4; /* it got fewer areas than the plan: it fails now */
        wire_put_u8(m->payload, n->inject.kind);
        wire_put_u8(m->payload + 1, 0);
        wire_put_u16(m->payload + 2, 0);
    }
    n->asking = 0;
    rc_nc_set(run, k, RC_NC_STOPPING);
    n->since = ktime_now();
    rc_nc_send(run, k, m);
}

/* 1 if an area is left to give (one taken back, or the schedule's next). */
static int rc_nc_area_left(const struct rc_run *run)
{
    struct areas peek = run->sched;
    struct area a;
    return run->nagain > 0 || areas_next(&peek, &a);
}

/* Areas to parked NCs; once none is busy and none is left, stops them.
 * Looks at every NC only while some are parked (the frame's end). */
static void rc_nc_dispatch(struct rc_run *run, struct line_msg *m)
{
    if (run->in_state[RC_NC_PARKED] == 0)
        return;
    if (run->status == LINK_OK && rc_nc_area_left(run)) {
        for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++) {
            /* An NC that waited while every area was out gets one taken
             * back.  Traced, only a hand-out is a record. */
            if (run->nc[k].state != RC_NC_PARKED || !rc_nc_area_left(run))
                continue;
            if (!run->trace) {
                (void)rc_nc_give(run, k, m);
            } else {
                insn_mark_trace_span_begin();
                rc_nc_trace_served(run, k, rc_nc_give(run, k, m), 0);
            }
        }
    }
    if (run->in_state[RC_NC_BUSY] + run->in_state[RC_NC_IDLE] && run->status == LINK_OK)
        return;
    for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++)
        if (run->nc[k].state == RC_NC_PARKED)
            rc_nc_stop(run, k, m);
}

/* NC k's line has a message (its pending bit): one is served, the request
 * answered at once (the area, or parked), and the line armed again.
 * Returns 1 if a message moved.  Not inlined into rc_nc_poll: fewer
 * registers spilled on the request's path. */
__attribute__((noinline)) static int rc_nc_serve(struct rc_run *run, uint32_t k,
                                                 struct line_msg *m)
{
    struct rc_nc *n = &run->nc[k];
    if (n->state == RC_NC_OUT || n->state == RC_NC_STOPPED)
        return 0; /* failed: its line is not read again */
    if (unit_is_halted(k)) {
        rc_nc_lost(run, k, 0);
        return 0;
    }
    if (run->trace)
        insn_mark_trace_span_begin();
    int more, handed = 0;
    int got = line_end_try_recv_arm(&n->line, m, &more) == LINE_OK;
    /* A second message there already is served in the next pass. */
    if (more)
        line_pending_mark(k);
    if (got) {
        rc_nc_message(run, k, m);
        if (n->asking && run->status == LINK_OK)
            handed = rc_nc_give(run, k, m);
    }
    if (run->trace)
        rc_nc_trace_served(run, k, handed, got ? m->type : 0);
    return got;
}

/* The watchdog: every NC that halted or is overdue has failed.  An NC with
 * a message waiting is served first (and its line is marked, in case its
 * pending bit was missed). */
static void rc_nc_scan(struct rc_run *run)
{
    uint32_t peers = 0; /* wraps: only differences are used */
    for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++)
        peers += gigs_nc_progress[k];
    for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++) {
        struct rc_nc *n = &run->nc[k];
        if (n->state == RC_NC_OUT || n->state == RC_NC_STOPPED)
            continue;
        if (unit_is_halted(k))
            rc_nc_lost(run, k, 0);
        else if (line_end_recv_ready_arm(&n->line))
            line_pending_mark(k);
        else if (rc_nc_overdue(run, k, peers))
            rc_nc_lost(run, k, 1);
    }
}

int rc_nc_poll(struct rc_run *run, struct line_msg *m)
{
    if (run->self_inject.kind && run->done >= run->self_inject.area)
        selftest_fail_on_purpose(run->self_inject.kind); /* the test hook */
    int moved = 0;
    uint32_t words = (board_ncores + 31u) / 32u;
    for (uint32_t w = 0; w < words; w++) {
        uint32_t bits = line_pending_take(w);
        while (bits) {
            uint32_t k = 32u * w + (uint32_t)__builtin_ctz(bits);
            bits &= bits - 1u;
            if (k >= UNITS_FIRST_NC && k < board_ncores)
                moved |= rc_nc_serve(run, k, m);
        }
    }
    if (ktime_passed(run->next_scan)) {
        rc_nc_scan(run);
        run->next_scan = ktime_deadline_ms(GIGS_WATCH_MS);
    }
    rc_nc_dispatch(run, m);
    if (rc_nc_all_stopped(run) && run->done < run->total)
        rc_fail(run, LINK_ERR_TIMEOUT, "every NC failed; %u of %u areas were done", run->done,
                run->total);
    return moved;
}

int rc_nc_all_stopped(const struct rc_run *run)
{
    return run->in_state[RC_NC_OUT] + run->in_state[RC_NC_STOPPED] ==
           board_ncores - UNITS_FIRST_NC;
}
