/* gigs.h: the image generation subsystem (GIGS) of LINKS-1 on the board:
 * what the DM, RC and NC programs share to render a frame.
 *
 *   host --CMD_SCENE_LOAD--> DM   keeps the compiled scene, checks it by
 *                                 building frame 0 (render_blob_build) in the
 *                                 IMSU block it holds
 *   host --CMD_RENDER------> DM   frame k prepared in its block -> IMSU swap
 *                                 -> MSG_RENDER_FRAME to the RC; then, for an
 *                                 animation, prepares k+1 in the other block
 *                                 while k renders (the paper's pipelining)
 *   RC: copies the blob into the broadcast block and relocates it there (the
 *       broadcast), MSG_NC_START to every NC, then one area per MSG_NC_REQ
 *       (proto/areas.h schedule) until none is left; collects the DC FIFO
 *       into the frame memory in a second task; MSG_RENDER_PROGRESS and
 *       MSG_RENDER_DONE to the DM
 *   NC: Y clipping, X clipping and tracing of each area (render_area), its
 *       rows pushed into the DC FIFO, then the next MSG_NC_REQ
 *   host --CMD_FRAME_PULL--> DM   streams the RC's frame memory
 *
 * The collector runs on the RC: the DM is busy preparing the next frame and
 * talking to the host while a frame renders, whereas the RC only answers
 * area requests, so it has the idle time to drain the FIFO. */
#ifndef LINKS1_ROLES_GIGS_H
#define LINKS1_ROLES_GIGS_H

#include <stdint.h>

#include "drivers/framemem/fm.h"
#include "drivers/serial/linemsg.h"
#include "proto/wire.h"
#include "render/render.h"

/* Render statistics on the serial lines: the nine counters, the lost and
 * the escalated pixels of render_stats_t, then the camera rays that hit. */
#define GIGS_STATS_SIZE 88

static inline void gigs_stats_put(uint8_t *p, const render_stats_t *s)
{
    const uint64_t v[9] = {s->primary, s->shadow, s->reflection, s->refraction,
                           s->transmission, s->box_tests, s->prim_tests,
                           s->primary_box_tests, s->primary_prim_tests};
    for (int i = 0; i < 9; i++)
        wire_put_u64(p + 8 * i, v[i]);
    wire_put_u32(p + 72, s->precision_lost_pixels);
    wire_put_u32(p + 76, s->escalated_pixels);
    wire_put_u64(p + 80, s->primary_hit);
}

/* Adds the counters at p to *s. */
static inline void gigs_stats_add(render_stats_t *s, const uint8_t *p)
{
    uint64_t *v[9] = {&s->primary, &s->shadow, &s->reflection, &s->refraction,
                      &s->transmission, &s->box_tests, &s->prim_tests,
                      &s->primary_box_tests, &s->primary_prim_tests};
    for (int i = 0; i < 9; i++)
        *v[i] += wire_get_u64(p + 8 * i);
    s->precision_lost_pixels += wire_get_u32(p + 72);
    s->escalated_pixels += wire_get_u32(p + 76);
    s->primary_hit += wire_get_u64(p + 80);
}

/* MSG_RENDER_DONE on success: u32 ncs, u32 areas, u32 render_ms,
 * u32 rc_high, u32 nc_high_max, u32 nc_private, u32 blob_bytes,
 * u32 dc_full_waits, then the summed stats. */
#define GIGS_RESULT_FIXED 32
#define GIGS_RESULT_SIZE (GIGS_RESULT_FIXED + GIGS_STATS_SIZE)

/* RC: renders the frame the DM swapped over (m holds MSG_RENDER_FRAME) and
 * answers the DM; m is reused for the answer. */
void rc_render_frame(struct line_msg *m);
/* RC: the collector task (the RC's second task). */
void rc_collect_task(void *arg);
/* The frame memory of the last frame the RC finished, NULL before the
 * first.  The DM reads it after MSG_RENDER_DONE and before its next
 * MSG_RENDER_FRAME: the line's message order makes the pixels visible. */
const struct fm *rc_render_fm(void);

/* Each NC's progress word: +1 per pixel it renders (render_clip_options_t
 * progress), read by the RC's watchdog (roles/rc_nc.c), which gives up an
 * NC only when its word has also stood still for GIGS_WATCH_FLOOR_MS. */
extern volatile uint32_t gigs_nc_progress[UNITS_MAX_CORES];

/* NC: renders areas until MSG_NC_STOP (m holds MSG_NC_START). */
void nc_render_frame(struct line_msg *m);

/* DM command handlers (roles/dm_render.c). */
void dm_cmd_scene_load(uint16_t cmd);
void dm_cmd_render(uint16_t cmd);
void dm_cmd_frame_pull(uint16_t cmd);

#endif
