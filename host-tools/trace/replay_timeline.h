/* replay_timeline.h: the machine at work over one replayed frame, as a
 * gnuplot script (links1 replay --timeline OUT.png draws it through
 * host-tools/image/chart.h).  One row per unit computer, time across in
 * milliseconds on the replay's equal-speed unit computers: the DM
 * preparing the frame, the RC broadcasting it and handing out each area,
 * each NC setting up and computing its areas (neighbouring areas in two
 * shades), and an NC's idle time as the pale bar behind its work. */
#ifndef LINKS1_HOST_REPLAY_TIMELINE_H
#define LINKS1_HOST_REPLAY_TIMELINE_H

#include <stdio.h>

#include "host-tools/trace/replay.h"
#include "host-tools/trace/trace_file.h"

/* What a bar of the timeline shows: its gnuplot line type. */
enum timeline_bar {
    TIMELINE_IDLE = 1,      /* an NC waiting (the whole frame, behind its work) */
    TIMELINE_DM_PREPARE,    /* the DM preparing the frame */
    TIMELINE_RC_BROADCAST,  /* the RC broadcasting it */
    TIMELINE_RC_HANDOUT,    /* the RC serving a request: an area handed out */
    TIMELINE_NC_SETUP,      /* an NC setting up the frame */
    TIMELINE_NC_AREA,       /* an NC computing an area */
    TIMELINE_NC_AREA_NEXT,  /* the same, the NC's next area (the other shade) */
    TIMELINE_BARS           /* how many there are, plus one */
};

/* Rows: 0 the DM, 1 the RC, 2 + n NC n. */
#define TIMELINE_ROW_DM 0
#define TIMELINE_ROW_RC 1
#define TIMELINE_ROW_NC0 2

/* Writes the gnuplot script (pngcairo terminal, data inline) of replay r
 * of trace t under configuration c; title heads the chart. */
void replay_timeline_script(FILE *f, const struct trace *t, const struct replay_cfg *c,
                            const struct replay_result *r, const char *title);

#endif
