/* rc_run.h: the RC's state of one frame's area hand-out, shared by
 * rc_render.c (the frame) and rc_nc.c (the NCs: areas, failures, the
 * watchdog).  Private to the RC.
 *
 * An NC fails when it halts with a fault (its core's halted word, set by
 * kernel/fault.c, which the RC reads) or when the watchdog finds it silent
 * too long: holding an area for GIGS_WATCH_FACTOR times the area's
 * expected time plus GIGS_WATCH_FLOOR_MS, or not answering a start or a
 * stop within GIGS_WATCH_FLOOR_MS, and in either case its progress word
 * (gigs_nc_progress, +1 per pixel) standing still for GIGS_WATCH_FLOOR_MS:
 * an area that costs more than expected is no failure while its pixels
 * come.  A failed NC is out for good: its broadcast read is ended for it,
 * the DC drops its later runs, the RC never writes to it again, and the
 * areas it held go to the next NCs that ask.  An NC that asks while nothing
 * is left waits (parked) until the last busy NC is done: an area may still
 * come back.
 *
 * Asking ahead (the default; LINK_RENDER_ASK_WHEN_DONE turns it off): an
 * NC asks for its next area about one round trip before it expects to
 * finish the one it renders, so it may hold two, the one it renders and the
 * next.  Each request (MSG_NC_REQ) and each MSG_NC_DONE carries how many
 * areas the NC has finished in this frame; the RC takes that many of its
 * oldest held areas as done. */
#ifndef LINKS1_ROLES_RC_RUN_H
#define LINKS1_ROLES_RC_RUN_H

#include <stdint.h>

#include "drivers/serial/line.h"
#include "kernel/param.h"
#include "proto/areas.h"
#include "proto/render_link.h"
#include "render/render.h"

enum rc_nc_state {
    RC_NC_OUT = 0,  /* not in this frame (failed before) */
    RC_NC_IDLE,     /* started, no request yet */
    RC_NC_BUSY,     /* holds an area or two (and may be asking for the next) */
    RC_NC_PARKED,   /* holds none and asked while nothing was left */
    RC_NC_STOPPING, /* told to stop */
    RC_NC_STOPPED,  /* stopped, or failed in this frame */
    RC_NC_STATES,
};

/* Areas one NC may hold: the one it renders and the one it asked ahead for. */
#define RC_NC_HELD_MAX 2u

struct rc_nc {
    uint8_t state;       /* enum rc_nc_state */
    uint8_t nheld;       /* areas it holds, oldest first in held[] */
    uint8_t asking;      /* 1: its last request is not answered yet */
    struct area held[RC_NC_HELD_MAX];
    uint32_t finished;   /* areas it said it finished in this frame */
    uint64_t since;      /* ticks: when its oldest held area became its
                            current one, or its start or stop */
    uint32_t progress;   /* its progress word when last looked at */
    uint64_t moved;      /* ticks: when that word last changed */
    uint32_t peers_then; /* every NC's progress words summed, then */
    uint32_t given;      /* areas it got in this frame */
    struct link_inject inject; /* a planned failure (kind 0: none) */
    struct line_end line; /* its serial line, looked up at the frame's start */
};

struct rc_run {
    struct areas sched;
    int one_per_nc;  /* areas_one_per_nc(&sched), asked once a frame */
    uint32_t total, done, ncs;
    struct rc_nc nc[UNITS_MAX_CORES];
    uint32_t in_state[RC_NC_STATES]; /* NCs in each state: O(1) checks per pass */
    uint64_t next_scan;              /* ticks: the watchdog's next look at every NC */
    struct area again[UNITS_MAX_CORES]; /* areas taken back from failed NCs */
    uint32_t nagain;
    uint64_t slow_ticks;  /* the slowest finished area per pixel: its ticks */
    uint32_t slow_pixels; /* and pixels (0: none finished yet) */
    render_stats_t stats;
    uint32_t nc_high_max, nc_private;
    struct link_render_fails fails;
    struct link_inject self_inject; /* the RC's own planned failure (kind 0: none):
                                     * once inject.area areas are done */
    int32_t status;                /* first error, LINK_OK if none */
    int trace;                     /* LINK_RENDER_TRACE: write trace marks */
    char why[LINE_MAX_PAYLOAD - 4];
};

/* Records the first error of the frame (fmt takes two unsigned). */
void rc_fail(struct rc_run *run, int32_t status, const char *fmt, uint32_t a, uint32_t b);

/* Marks the NCs that failed before as out, counts the rest into run->ncs,
 * and takes the fault plan (LINK_INJECT_SIZE(n) bytes at plan, n may be 0). */
void rc_nc_begin(struct rc_run *run, const uint8_t *plan, uint32_t n);
/* Sends MSG_NC_START (flags, largest area, clipping) to every NC in the
 * frame. */
void rc_nc_start(struct rc_run *run, struct line_msg *m, uint8_t flags, uint32_t largest,
                 uint8_t clip);
/* One pass: the messages of the NCs whose lines have some (the line
 * driver's pending map, not a look at every line), areas handed out or
 * stops; every GIGS_WATCH_MS, the watchdog's look at every NC.  Returns 1
 * if any message moved. */
int rc_nc_poll(struct rc_run *run, struct line_msg *m);
/* 1 once every NC of the frame has stopped or failed. */
int rc_nc_all_stopped(const struct rc_run *run);

#endif
