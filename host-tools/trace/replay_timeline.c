/* replay_timeline.c: a replayed frame as a gnuplot timeline
 * (replay_timeline.h). */
#include "host-tools/trace/replay_timeline.h"

#include <inttypes.h>
#include <stdlib.h>

static const struct {
    const char *colour, *name;
} timeline_kinds[TIMELINE_BARS] = {
    [TIMELINE_IDLE] = {"#eeeeee", "NC idle"},
    [TIMELINE_DM_PREPARE] = {"#cc3311", "DM preparing the frame"},
    [TIMELINE_RC_BROADCAST] = {"#ee7733", "RC broadcasting it"},
    [TIMELINE_RC_HANDOUT] = {"#33bbee", "RC handing out an area"},
    [TIMELINE_NC_SETUP] = {"#aaaa00", "NC setting up"},
    [TIMELINE_NC_AREA] = {"#0077bb", "NC computing an area"},
    [TIMELINE_NC_AREA_NEXT] = {"#009988", "its next area"},
};

/* The time axis: seconds for a frame of 10 s or more, else milliseconds. */
static double timeline_unit_us(double frame_us) { return frame_us >= 1e7 ? 1e6 : 1e3; }

/* One bar: from..to microseconds on row, in units of unit_us. */
static void timeline_bar(FILE *f, double unit_us, double from_us, double to_us, uint32_t row,
                         enum timeline_bar kind)
{
    if (to_us > from_us)
        fprintf(f, "%.6f %.6f %" PRIu32 " %d\n", from_us / unit_us, to_us / unit_us, row,
                (int)kind);
}

/* The rows' names: every NC up to 16 of them, else every NCs/16-th. */
static void timeline_ytics(FILE *f, uint32_t ncs)
{
    uint32_t step = ncs <= 16 ? 1 : (ncs + 15) / 16;
    fprintf(f, "set ytics (\"DM\" %d, \"RC\" %d", TIMELINE_ROW_DM, TIMELINE_ROW_RC);
    for (uint32_t n = 0; n < ncs; n += step)
        fprintf(f, ", \"NC %" PRIu32 "\" %" PRIu32, n, TIMELINE_ROW_NC0 + n);
    fprintf(f, ")\n");
}

static void timeline_head(FILE *f, uint32_t ncs, double frame_us, const char *title)
{
    double unit = timeline_unit_us(frame_us);
    uint32_t rows = TIMELINE_ROW_NC0 + ncs;
    unsigned height = 220 + (rows < 80 ? rows * 10 : 800);
    fprintf(f, "set terminal pngcairo size 1000,%u font \",9\" noenhanced\n", height);
    fprintf(f, "set title \"%s\"\n", title);
    fprintf(f, "set xlabel \"%s on equal-speed unit computers\"\n", unit > 1e3 ? "s" : "ms");
    fprintf(f, "set xrange [0:%.6f]\nset yrange [%.1f:-0.6]\n", frame_us / unit * 1.001,
            rows - 0.4);
    fprintf(f, "set grid x\nset style fill solid 1.0 noborder\n");
    fprintf(f, "set key outside bottom center horizontal\n");
    timeline_ytics(f, ncs);
    for (int k = 1; k < TIMELINE_BARS; k++)
        fprintf(f, "set linetype %d lc rgb \"%s\"\n", k, timeline_kinds[k].colour);
}

static void timeline_data(FILE *f, const struct trace *t, const struct replay_cfg *c,
                          const struct replay_result *r)
{
    double us = 1.0 / c->mips, u = timeline_unit_us(r->frame_us);
    double dm_end = c->pipelined ? 0 : (double)t->dm_prepare * us;
    double t0 = dm_end + (double)t->rc_broadcast * us;
    fprintf(f, "$bars << EOD\n");
    for (uint32_t n = 0; n < c->ncs; n++)
        timeline_bar(f, u, t0, r->frame_us, TIMELINE_ROW_NC0 + n, TIMELINE_IDLE);
    timeline_bar(f, u, 0, dm_end, TIMELINE_ROW_DM, TIMELINE_DM_PREPARE);
    timeline_bar(f, u, dm_end, t0, TIMELINE_ROW_RC, TIMELINE_RC_BROADCAST);
    for (uint32_t n = 0; n < c->ncs; n++)
        timeline_bar(f, u, t0, r->nc_setup_end[n], TIMELINE_ROW_NC0 + n, TIMELINE_NC_SETUP);
    uint32_t *shade = calloc(c->ncs, sizeof *shade);
    for (uint32_t i = 0; i < r->nareas; i++) {
        const struct replay_area *a = &r->areas[i];
        timeline_bar(f, u, a->serve_start, a->serve_end, TIMELINE_ROW_RC, TIMELINE_RC_HANDOUT);
        int next = shade ? (int)(shade[a->nc]++ & 1) : 0;
        timeline_bar(f, u, a->start, a->end, TIMELINE_ROW_NC0 + a->nc,
                     next ? TIMELINE_NC_AREA_NEXT : TIMELINE_NC_AREA);
    }
    free(shade);
    fprintf(f, "EOD\n");
}

void replay_timeline_script(FILE *f, const struct trace *t, const struct replay_cfg *c,
                            const struct replay_result *r, const char *title)
{
    timeline_head(f, c->ncs, r->frame_us, title);
    timeline_data(f, t, c, r);
    fprintf(f, "plot $bars using (($1 + $2) / 2):3:(($2 - $1) / 2):(0.4):4 "
               "with boxxyerror lc variable notitle");
    for (int k = 1; k < TIMELINE_BARS; k++)
        fprintf(f, ", \\\n  keyentry with boxes lc %d title \"%s\"", k, timeline_kinds[k].name);
    fprintf(f, "\n");
}
