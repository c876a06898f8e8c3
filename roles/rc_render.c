/* rc_render.c: the RC's part of rendering (roles/gigs.h): the broadcast of
 * the prepared frame to the NCs, the area schedule handed out over the
 * serial lines, and the data collector emptied into the frame memory. */
#include <stdint.h>
#include <string.h>

#include "drivers/framemem/dc.h"
#include "drivers/framemem/fm.h"
#include "drivers/framemem/fm_view.h"
#include "drivers/imsu/imsu.h"
#include "drivers/serial/line.h"
#include "kernel/cpu.h"
#include "kernel/klog.h"
#include "kernel/kmem.h"
#include "kernel/ktime.h"
#include "kernel/task.h"
#include "proto/hostlink.h"
#include "proto/insn_mark.h"
#include "proto/textfmt.h"
#include "proto/wire.h"
#include "render/blob.h"
#include "render/wide.h"
#include "proto/areas.h"
#include "roles/gigs.h"
#include "roles/rc_run.h"
#include "roles/unit.h"
#include "proto/unitmsg.h"

/* What the RC's two tasks share about the frame in progress. */
static struct {
    struct fm fm;
    int have_fm;         /* fm holds a finished frame (for CMD_FRAME_PULL) */
    uint32_t pixels;     /* pixels of the frame */
    volatile int active; /* the collector should fill fm */
    volatile int finishing; /* no NC will push again: take the rest */
    volatile int filled; /* the collector took the rest */
    uint32_t given_up;   /* DC positions a failed NC claimed, never filled */
    size_t mark;         /* kmem mark before the frame's memory */
    int marked;
    int view_absent;    /* the machine has no display: not asked again */
    uint32_t shown_w, shown_h; /* the size the view was last told (0: never) */
} rc_frame;

const struct fm *rc_render_fm(void)
{
    return rc_frame.have_fm ? &rc_frame.fm : NULL;
}

/* Collects the DC into the frame memory while the frame is active; once
 * the area task says no NC will push again, takes what is left (giving up
 * what a failed NC claimed and never filled) and says so. */
void rc_collect_task(void *arg)
{
    (void)arg;
    for (;;) {
        uint32_t mark = task_event_mark();
        if (!rc_frame.active || rc_frame.filled) {
            task_wait(mark, 0);
            continue;
        }
        if (rc_frame.finishing) {
            rc_frame.given_up = dc_collect_final(&rc_frame.fm);
            rc_frame.filled = 1;
            task_signal_local(); /* the area task waits for this */
            continue;
        }
        dc_collect_until(&rc_frame.fm, ktime_deadline_ms(GIGS_WATCH_MS), &rc_frame.finishing);
    }
}

static void rc_progress(const struct rc_run *run, struct line_msg *m)
{
    m->type = MSG_RENDER_PROGRESS;
    m->len = 16;
    wire_put_u32(m->payload, run->done);
    wire_put_u32(m->payload + 4, run->total);
    /* Rows a failed NC sent are written again by the NC given its area:
     * the count may pass the frame's pixels. */
    uint32_t written = rc_frame.fm.pixels_written;
    wire_put_u32(m->payload + 8, written < rc_frame.pixels ? written : rc_frame.pixels);
    wire_put_u32(m->payload + 12, rc_frame.pixels);
    line_send(UNITS_DM_CORE, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
}

/* Serves every NC's line until all have stopped or failed, then (unless a
 * problem stopped the frame) until the collector has taken every pixel.
 * Sleeps between messages; wakes at least every GIGS_WATCH_MS to look for
 * failed NCs. */
static void rc_serve(struct rc_run *run, struct line_msg *m)
{
    uint64_t next_progress = ktime_deadline_ms(GIGS_PROGRESS_MS);
    uint32_t reported = 0, reported_px = 0;
    for (;;) {
        uint32_t mark = task_event_mark();
        int moved = rc_nc_poll(run, m);
        if (rc_nc_all_stopped(run)) {
            if (!rc_frame.finishing) {
                rc_frame.finishing = 1;
                task_signal_local();
            }
            if (rc_frame.filled || run->status != LINK_OK)
                return;
        }
        if ((run->done != reported || rc_frame.fm.pixels_written != reported_px) &&
            ktime_passed(next_progress)) {
            rc_progress(run, m);
            reported = run->done;
            reported_px = rc_frame.fm.pixels_written;
            next_progress = ktime_deadline_ms(GIGS_PROGRESS_MS);
        }
        if (moved)
            task_yield(); /* the collector shares this core */
        else
            task_wait(mark, ktime_deadline_ms(GIGS_WATCH_MS));
    }
}

/* The largest area of the schedule, in pixels: what each NC sets aside. */
static uint32_t rc_largest_area(const struct areas *sched)
{
    struct areas copy = *sched;
    struct area a;
    uint32_t most = 0;
    while (areas_next(&copy, &a))
        if (a.w * a.h > most)
            most = a.w * a.h;
    return most;
}

/* Escalating: the wide blob at offset at of the DM's block src to the same
 * offset of the broadcast block w (size bytes).  0, or -1 with why. */
static int rc_broadcast_wide(uint8_t *w, size_t size, const render_blob_t *src, uint32_t at,
                             char *why, size_t cap)
{
    if (size > imsu_dm_rc.size)
        size = imsu_dm_rc.size; /* what both blocks hold */
    if (at >= size || !render_wide_linked()) {
        fmt_snprintf(why, cap, "a wide blob at %u bytes: past the block, or the firmware "
                     "carries no wide arithmetic", (unsigned)at);
        return -1;
    }
    return RENDER_WIDE(wide_blob_copy_frame)(w + at, size - at, (const uint8_t *)src + at, why,
                                             cap);
}

/* Broadcast: the blob from the block the DM swapped over into the
 * broadcast block, relocated there.  0, or -1 with run->why set. */
static int rc_broadcast(struct rc_run *run, const render_blob_t **out)
{
    const render_blob_t *src = (const render_blob_t *)imsu_read_block(&imsu_dm_rc, UNITS_RC_CORE);
    struct imsu_bcast *b = &imsu_rc_ncs;
    if (src->magic != RENDER_BLOB_MAGIC || src->bytes > b->size) {
        rc_fail(run, LINK_ERR_CHECK, "the IMSU block holds no blob, or %u bytes, more than the "
                "%u of the broadcast block", (unsigned)src->bytes, (unsigned)b->size);
        return -1;
    }
    uint8_t *w;
    int r = imsu_bcast_write_begin(b, UNITS_RC_CORE, &w);
    if (r != IMSU_OK) {
        rc_fail(run, LINK_ERR_CHECK, "broadcast block: IMSU error %d (%u)", (uint32_t)r, 0);
        return -1;
    }
    /* kernel/mem.c's memcpy: serial work before any NC starts, and the one
     * part of the RC's frame that grows with the scene; the scene part only
     * when the broadcast block does not hold this load of the scene yet,
     * the frame header alone when it holds the frame's world part */
    render_blob_t *blob;
    render_blob_error_t err;
    render_blob_status_t st = render_blob_copy_frame(w, b->size, src, &blob, NULL, &err);
    /* escalating: the wide blob too, at the same offset (render/wide.h) */
    uint32_t at = st == RENDER_BLOB_OK ? src->wide_offset : 0;
    if (at && rc_broadcast_wide(w, b->size, src, at, err.message, sizeof err.message) != 0) {
        blob->magic = 0; /* the next frame is copied whole */
        st = RENDER_BLOB_ERR_NOT_BLOB;
    }
    imsu_bcast_write_end(b, UNITS_RC_CORE);
    if (st != RENDER_BLOB_OK) {
        run->status = LINK_ERR_CHECK;
        fmt_snprintf(run->why, sizeof run->why, "broadcast: %s", err.message);
        return -1;
    }
    *out = blob;
    return 0;
}

/* Frame memory for this frame from the RC's private memory; the live view
 * is pointed at it. */
static int rc_frame_memory(struct rc_run *run, uint32_t w, uint32_t h)
{
    if (!rc_frame.marked) {
        rc_frame.mark = kmem_mark();
        rc_frame.marked = 1;
    }
    kmem_release_to(rc_frame.mark);
    rc_frame.have_fm = 0;
    size_t bytes = FM_BYTES(w, h);
    if (bytes > kmem_free()) {
        rc_fail(run, LINK_ERR_CHECK, "frame memory of %u bytes does not fit the RC's %u free "
                "bytes of private memory", (uint32_t)bytes, (uint32_t)kmem_free());
        return -1;
    }
    int r = fm_init(&rc_frame.fm, kmem_alloc(bytes, "frame memory"), bytes, w, h);
    if (r != FM_OK) {
        rc_fail(run, LINK_ERR_CHECK, "frame memory %ux%u refused", w, h);
        return -1;
    }
    /* The storage starts at the same mark every frame: the view needs telling
     * again only when the size changes. */
    if (!rc_frame.view_absent && (w != rc_frame.shown_w || h != rc_frame.shown_h)) {
        const char *why = "";
        r = fm_view_show(&rc_frame.fm, &why);
        rc_frame.view_absent = r == FM_VIEW_ABSENT;
        if (r == FM_VIEW_FAILED)
            klog("render: live view: %s", why);
        rc_frame.shown_w = w;
        rc_frame.shown_h = h;
    }
    rc_frame.pixels = w * h;
    rc_frame.finishing = 0;
    rc_frame.filled = 0;
    rc_frame.given_up = 0;
    return 0;
}

static void rc_done(struct rc_run *run, struct line_msg *m, uint32_t render_ms, uint32_t blob_bytes)
{
    m->type = MSG_RENDER_DONE;
    wire_put_u32(m->payload, (uint32_t)run->status);
    if (run->status != LINK_OK) {
        uint32_t n = (uint32_t)strlen(run->why);
        memcpy(m->payload + 4, run->why, n);
        m->len = (uint16_t)(4 + n);
    } else {
        uint8_t *q = m->payload + 4;
        const uint32_t v[8] = {run->ncs, run->total, render_ms, (uint32_t)kmem_high_water(),
                               run->nc_high_max, run->nc_private, blob_bytes, dc_full_waits()};
        for (int i = 0; i < 8; i++)
            wire_put_u32(q + 4 * i, v[i]);
        gigs_stats_put(q + GIGS_RESULT_FIXED, &run->stats);
        m->len = (uint16_t)(4 + GIGS_RESULT_SIZE +
                            link_render_fails_put(q + GIGS_RESULT_SIZE, &run->fails));
    }
    int r = line_send(UNITS_DM_CORE, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
    if (r != LINE_OK)
        klog("render: the DM did not take the result: %s", line_strerror(r));
}

void rc_render_frame(struct line_msg *m)
{
    static struct rc_run run;
    static int counting; /* the plugin counts the RC from its first frame */
    if (!counting) {
        counting = 1;
        insn_mark_count_from_here();
    }
    struct link_render_args args;
    link_render_args_get(m->payload, &args);
    uint8_t flags = args.flags;
    memset(&run, 0, sizeof run);
    run.status = LINK_OK;
    const uint32_t at = LINK_RENDER_ARGS_SIZE;
    uint32_t planned = m->len >= at + LINK_INJECT_FIXED_SIZE ? wire_get_u8(m->payload + at) : 0;
    if (at + LINK_INJECT_SIZE(planned) > m->len)
        planned = 0; /* the DM checked it: cannot happen */
    rc_nc_begin(&run, m->payload + at + LINK_INJECT_FIXED_SIZE, planned);
    if (run.ncs == 0)
        rc_fail(&run, LINK_ERR_CHECK, "all %u NCs failed in earlier frames; %u are left",
                board_ncores - UNITS_FIRST_NC, 0);
    uint64_t t0 = ktime_now();
    const render_blob_t *blob = NULL;
    uint32_t blob_bytes = 0;
    run.trace = (flags & LINK_RENDER_TRACE) != 0;
    int bcast = -1;
    if (run.status == LINK_OK) {
        if (run.trace)
            insn_mark_trace_span_begin();
        bcast = rc_broadcast(&run, &blob);
        if (run.trace)
            insn_mark_trace_span_end();
    }
    if (bcast == 0) {
        blob_bytes = (uint32_t)blob->bytes;
        uint32_t h = blob->scene.height;
        if (args.rows == 0 ? args.row0 != 0 : (uint32_t)args.row0 + args.rows > h) {
            rc_fail(&run, LINK_ERR_BAD_ARGS, "a band ending before scanline %u (or of no "
                    "scanlines from a scanline other than 0): the frame has %u",
                    (uint32_t)args.row0 + args.rows, h);
        } else {
            int r = areas_init(&run.sched, (enum areas_mode)args.balance, blob->scene.width,
                               args.rows ? args.rows : h, run.ncs, args.areas);
            if (r == AREAS_OK && args.guided && args.balance == LINK_BALANCE_DECREASING)
                r = areas_set_guided_factor(&run.sched, args.guided);
            areas_set_origin(&run.sched, args.row0);
            if (r != AREAS_OK)
                rc_fail(&run, LINK_ERR_BAD_ARGS, "area schedule: error %d (balance %u)",
                        (uint32_t)r, args.balance);
        }
    }
    if (run.status == LINK_OK &&
        rc_frame_memory(&run, blob->scene.width, blob->scene.height) == 0) {
        if (args.rows) /* a band: its pixels make the frame */
            rc_frame.pixels = blob->scene.width * args.rows;
        run.total = areas_count(&run.sched);
        run.one_per_nc = areas_one_per_nc(&run.sched);
        uint32_t largest = rc_largest_area(&run.sched);
        dc_init(UNITS_RC_CORE); /* nobody pushes between frames */
        rc_frame.active = 1;
        task_signal_local(); /* the collector starts */
        rc_nc_start(&run, m, flags, largest, args.clip);
        /* The NCs' share of the pool is the same for each (kernel/kmem.c). */
        run.nc_private = (uint32_t)cpu_of(UNITS_FIRST_NC)->mem_size;
        rc_serve(&run, m);
        /* Every area was drawn by an NC that then asked for more: its
         * pixels are all here, some twice when a failed NC had sent part
         * of an area (the same pixels: the frame is the same). */
        if (run.status == LINK_OK && rc_frame.fm.pixels_written < rc_frame.pixels)
            rc_fail(&run, LINK_ERR_CHECK, "the frame memory holds %u of the frame's %u pixels",
                    rc_frame.fm.pixels_written, rc_frame.pixels);
        if (rc_frame.given_up)
            klog("render: %u data collector runs claimed by failed NCs were given up",
                 (unsigned)rc_frame.given_up);
        rc_frame.active = 0;
        task_signal_local();
        rc_frame.have_fm = run.status == LINK_OK;
    }
    if (run.status == LINK_OK && run.total)
        rc_progress(&run, m);
    rc_done(&run, m, ktime_ticks_to_ms(ktime_now() - t0), blob_bytes);
}
