/* replay.h: a discrete-event replay of one traced frame (trace_file.h) on
 * LINKS-1's equal-speed unit computers (links1 replay, docs/trace.md).
 *
 *   - Every unit computer executes mips million instructions per second.
 *   - The DM prepares the frame, the RC broadcasts it and starts each NC
 *     in turn, handing it its first area with the start (the RC's
 *     instructions for the hand-out as traced); each NC sets up and
 *     computes that area, asking for the next one over its serial line.
 *     (A trace of version 1 or 2, or first_by_request: the NCs set up,
 *     then each sends a request for its first area.)
 *   - A message takes line_us plus byte_us per byte to cross a line.
 *   - The RC serves one request at a time, in the order they arrive, and
 *     answers with the schedule's next area (or stop).
 *   - An NC computes its area, then asks again; with prefetch it asks for
 *     the next area one round trip (both lines and the RC's mean service)
 *     before it expects to finish the current one, never before it starts
 *     it: an NC knows how many of the area's pixels are left, and the
 *     replay takes its estimate of the time they need as exact.  During
 *     its first area it has seen no round trip: it asks as it starts.
 *     One whose answer comes after its area's end (or none: the schedule
 *     is out) sends MSG_NC_DONE then, which the RC serves in its turn for
 *     the traced MSG_NC_DONEs' mean (a trace before version 4 has none).
 * An area the trace holds costs exactly what the board counted.  Any
 * other area is priced from the trace's per-pixel costs, plus the set-up
 * of the traced area holding its first pixel and the push of that traced
 * area scaled to its pixels (an estimate: docs/trace.md says how close). */
#ifndef LINKS1_HOST_REPLAY_H
#define LINKS1_HOST_REPLAY_H

#include <stdint.h>

#include "host-tools/trace/trace_file.h"
#include "proto/areas.h"
#include "proto/unitmsg.h"

/* Defaults (docs/trace.md): the paper states none of these. */
#define REPLAY_DEFAULT_MIPS 1.0     /* a Z8001 with its APU, order of magnitude */
#define REPLAY_DEFAULT_LINE_US 1000.0 /* software at both ends of a message */
#define REPLAY_DEFAULT_BYTE_US 520.8  /* 19,200 baud, 10 bits per byte */
/* Bytes on the line: a request (header, status) and an answer (header,
 * x, y, w, h), the sizes of the board's own messages (proto/unitmsg.h). */
#define REPLAY_REQUEST_BYTES (LINEMSG_HEADER_SIZE + MSG_NC_REQ_SIZE)
#define REPLAY_ANSWER_BYTES (LINEMSG_HEADER_SIZE + MSG_NC_AREA_SIZE)

struct replay_cfg {
    uint32_t ncs;
    enum areas_mode balance;
    uint32_t k;           /* --areas (0: the schedule's default, areas_init) */
    double mips, line_us, byte_us;
    int prefetch;         /* ask for the next area a round trip before the end */
    uint32_t guided;      /* decreasing: the guided factor (0: by NC count) */
    int pipelined;        /* the DM prepared the frame while the previous one
                             rendered: the frame starts at the broadcast */
    int first_by_request; /* each NC asks for its first area once set up
                             (a trace before version 3 replays so) */
    int as_recorded;      /* hand each NC the areas the board gave it, in
                             its order (ncs must be the trace's) */
};

/* What happened to one area. */
struct replay_area {
    uint32_t x, y, w, h;
    uint32_t nc;
    uint64_t insns;        /* the NC's instructions for it */
    int exact;             /* 1: the trace holds this area */
    int with_start;        /* 1: an NC's first area, handed out with its start */
    double request_sent;   /* the NC sent the request that got it */
    double serve_start, serve_end; /* the RC serving that request */
    double start, end;     /* the NC computing it */
};

struct replay_result {
    double frame_us;       /* DM start to the last area's end */
    double busy;           /* NCs' computing / (ncs * frame), 0..1 */
    double rc_busy;        /* RC serving / frame */
    uint32_t dones;        /* MSG_NC_DONEs the RC served (asking ahead, an
                              answer that came after the area's end) */
    uint32_t nareas, exact;
    struct replay_area *areas; /* in handout order */
    uint64_t *nc_insns;    /* [ncs]: set-up + its areas */
    double *nc_setup_end;  /* [ncs]: when each NC first asked */
};

/* 0, or -1 with err filled (bad configuration). */
int replay_run(const struct trace *t, const struct replay_cfg *c, struct replay_result *r,
               char *err, size_t cap);
/* Checks that r is a legal handout of c's schedule: every area of the
 * schedule handed out once, in the schedule's order, covering the screen;
 * the RC serves one request at a time and only after it arrived; an NC
 * computes one area at a time, only after the answer crossed the line,
 * and asks again only after it finished (or, prefetching, started) the
 * previous one.  0, or -1 with err naming the first violation. */
int replay_check_legal(const struct trace *t, const struct replay_cfg *c,
                       const struct replay_result *r, char *err, size_t cap);
void replay_free(struct replay_result *r);
/* Checks the board's own handout in t: its areas, in the order the RC
 * handed them out, are the schedule the trace records (balance, K and
 * factor, the defaults for the trace's NC count where it records 0), and
 * each NC's areas are numbered 0, 1, ... in that order.  0, or -1 with err
 * naming the first difference. */
int replay_check_board(const struct trace *t, char *err, size_t cap);

#endif
