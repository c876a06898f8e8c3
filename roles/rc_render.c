/* rc_render.c: the RC's part of rendering (roles/gigs.h): the broadcast of
 * the prepared frame to the NCs, the area schedule handed out over the
 * serial lines, and the data collector emptied into the frame memory. */
#include <stdint.h>
#include <string.h>

#include "drivers/framemem/dc.h"
#include "drivers/framemem/fm.h"
#include "drivers/framemem/ramfb.h"
#include "drivers/imsu/imsu.h"
#include "drivers/serial/line.h"
#include "kernel/cpu.h"
#include "kernel/klog.h"
#include "kernel/kmem.h"
#include "kernel/ktime.h"
#include "kernel/task.h"
#include "proto/hostlink.h"
#include "proto/insn_mark.h"
#include "proto/render_link.h"
#include "proto/textfmt.h"
#include "proto/wire.h"
#include "render/blob.h"
#include "proto/areas.h"
#include "roles/gigs.h"
#include "roles/unit.h"
#include "roles/unitmsg.h"

/* What the RC's two tasks share about the frame in progress. */
static struct {
    struct fm fm;
    int have_fm;         /* fm holds a finished frame (for CMD_FRAME_PULL) */
    uint32_t pixels;     /* pixels of the frame */
    volatile int active; /* the collector should fill fm */
    volatile int filled; /* the collector saw every pixel arrive */
    size_t mark;         /* kmem mark before the frame's memory */
    int marked;
    int ramfb_absent;    /* no -device ramfb: not asked again */
    uint32_t shown_w, shown_h; /* the size ramfb was last told (0: never) */
} rc_frame;

/* Per-NC state of the area hand-out. */
enum rc_nc_state { RC_NC_IDLE = 0, RC_NC_BUSY, RC_NC_STOPPING, RC_NC_STOPPED };

struct rc_run {
    struct areas sched;
    uint32_t total, done, ncs;
    uint8_t state[UNITS_MAX_CORES];
    render_stats_t stats;
    uint32_t nc_high_max, nc_private;
    int32_t status;                /* first error, LINK_OK if none */
    int trace;                     /* LINK_RENDER_TRACE: write trace marks */
    int handed;                    /* the last message served handed out ... */
    struct area last;              /* ... this area */
    char why[LINE_MAX_PAYLOAD - 4];
};

const struct fm *rc_render_fm(void)
{
    return rc_frame.have_fm ? &rc_frame.fm : NULL;
}

void rc_collect_task(void *arg)
{
    (void)arg;
    for (;;) {
        uint32_t mark = task_event_mark();
        if (!rc_frame.active || rc_frame.filled) {
            task_wait(mark, 0);
            continue;
        }
        while (rc_frame.active &&
               rc_frame.fm.pixels_written + rc_frame.fm.runs_refused < rc_frame.pixels)
            dc_collect_wait(&rc_frame.fm, ktime_deadline_ms(GIGS_WATCH_MS));
        rc_frame.filled = 1;
        task_signal_local(); /* the area task waits for this */
    }
}

__attribute__((format(printf, 3, 0)))
static void rc_fail(struct rc_run *run, int32_t status, const char *fmt, uint32_t a, uint32_t b)
{
    if (run->status != LINK_OK)
        return;
    run->status = status;
    fmt_snprintf(run->why, sizeof run->why, fmt, (unsigned)a, (unsigned)b);
}

static void rc_send_nc(uint32_t nc, struct line_msg *m)
{
    int r = line_send(nc, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
    if (r != LINE_OK)
        klog("render: send of message %u to NC %u: %s", (unsigned)m->type, (unsigned)nc,
             line_strerror(r));
}

/* Answers one NC's message: the next area, or stop. */
static void rc_on_nc(struct rc_run *run, uint32_t nc, struct line_msg *m)
{
    run->handed = 0;
    if (m->type == MSG_NC_STOPPED) {
        run->state[nc] = RC_NC_STOPPED;
        uint32_t high = wire_get_u32(m->payload);
        if (high > run->nc_high_max)
            run->nc_high_max = high;
        gigs_stats_add(&run->stats, m->payload + 4);
        return;
    }
    if (m->type != MSG_NC_REQ) {
        klog("render: unexpected message %u from NC %u", (unsigned)m->type, (unsigned)nc);
        return;
    }
    int32_t st = (int32_t)wire_get_u32(m->payload);
    if (st != 0 && run->status == LINK_OK) {
        run->status = st;
        fmt_snprintf(run->why, sizeof run->why, "NC %u: %.*s", (unsigned)nc,
                     (int)(m->len - 4), (const char *)m->payload + 4);
    }
    if (run->state[nc] == RC_NC_BUSY)
        run->done++;
    struct area a;
    if (run->status == LINK_OK && areas_next(&run->sched, &a)) {
        m->type = MSG_NC_AREA;
        m->len = 16;
        wire_put_u32(m->payload, a.x);
        wire_put_u32(m->payload + 4, a.y);
        wire_put_u32(m->payload + 8, a.w);
        wire_put_u32(m->payload + 12, a.h);
        run->state[nc] = RC_NC_BUSY;
        run->handed = 1;
        run->last = a;
    } else {
        m->type = MSG_NC_STOP;
        m->len = 0;
        run->state[nc] = RC_NC_STOPPING;
    }
    rc_send_nc(nc, m);
}

static void rc_progress(const struct rc_run *run, struct line_msg *m)
{
    m->type = MSG_RENDER_PROGRESS;
    m->len = 8;
    wire_put_u32(m->payload, run->done);
    wire_put_u32(m->payload + 4, run->total);
    line_send(UNITS_DM_CORE, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
}

/* Serves every NC's line until all have stopped and (unless a problem
 * stopped the frame) every pixel is in the frame memory.  Sleeps between
 * messages; wakes at least every GIGS_WATCH_MS to look for halted NCs. */
static void rc_serve(struct rc_run *run, struct line_msg *m)
{
    uint64_t next_progress = ktime_deadline_ms(GIGS_PROGRESS_MS);
    uint32_t reported = 0;
    for (;;) {
        uint32_t mark = task_event_mark();
        int busy = 0, moved = 0;
        for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++) {
            if (run->state[k] == RC_NC_STOPPED)
                continue;
            busy = 1;
            if (unit_is_halted(k)) {
                rc_fail(run, LINK_ERR_TIMEOUT, "NC %u halted (fault) during the frame; %u areas "
                        "were done", k, run->done);
                run->state[k] = RC_NC_STOPPED;
                continue;
            }
            if (!line_recv_ready_arm(k))
                continue;
            if (run->trace)
                insn_mark_trace_span_begin();
            if (line_try_recv(k, m) == LINE_OK) {
                rc_on_nc(run, k, m);
                moved = 1;
            } else {
                run->handed = 0;
            }
            if (run->trace) {
                /* The message served: from NC k, and the area it got. */
                insn_mark_trace_span_end();
                insn_mark_trace_bits(k, 16);
                insn_mark_trace_bits((uint32_t)run->handed, 1);
                insn_mark_trace_bits(run->handed ? run->last.x : 0, 16);
                insn_mark_trace_bits(run->handed ? run->last.y : 0, 16);
            }
        }
        int pixels_in = rc_frame.filled || run->status != LINK_OK;
        if (!busy && pixels_in)
            return;
        if (run->done != reported && ktime_passed(next_progress)) {
            rc_progress(run, m);
            reported = run->done;
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
    memcpy(w, src, src->bytes);
    render_blob_t *blob;
    render_blob_error_t err;
    render_blob_status_t st = render_blob_relocate(w, b->size, &blob, &err);
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
    /* The storage starts at the same mark every frame: ramfb needs telling
     * again only when the size changes. */
    if (!rc_frame.ramfb_absent && (w != rc_frame.shown_w || h != rc_frame.shown_h)) {
        r = ramfb_show(&rc_frame.fm);
        rc_frame.ramfb_absent = r == FWCFG_ERR_NOT_FOUND;
        if (r != FWCFG_OK && r != FWCFG_ERR_NOT_FOUND)
            klog("render: live view: %s", fwcfg_strerror(r));
        rc_frame.shown_w = w;
        rc_frame.shown_h = h;
    }
    rc_frame.pixels = w * h;
    rc_frame.filled = 0;
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
        m->len = 4 + GIGS_RESULT_SIZE;
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
    uint8_t balance = wire_get_u8(m->payload + 4);
    uint8_t flags = wire_get_u8(m->payload + 5);
    uint32_t k = wire_get_u32(m->payload + 8);
    memset(&run, 0, sizeof run);
    run.status = LINK_OK;
    run.ncs = board_ncores - UNITS_FIRST_NC;
    run.trace = (flags & LINK_RENDER_TRACE) != 0;
    uint64_t t0 = ktime_now();
    const render_blob_t *blob = NULL;
    uint32_t blob_bytes = 0;
    if (run.trace)
        insn_mark_trace_span_begin();
    int bcast = rc_broadcast(&run, &blob);
    if (run.trace)
        insn_mark_trace_span_end();
    if (bcast == 0) {
        blob_bytes = (uint32_t)blob->bytes;
        int r = areas_init(&run.sched, (enum areas_mode)balance, blob->scene.width,
                           blob->scene.height, run.ncs, k);
        if (r != AREAS_OK)
            rc_fail(&run, LINK_ERR_BAD_ARGS, "area schedule: error %d (balance %u)", (uint32_t)r,
                    balance);
    }
    if (run.status == LINK_OK &&
        rc_frame_memory(&run, blob->scene.width, blob->scene.height) == 0) {
        run.total = areas_count(&run.sched);
        uint32_t largest = rc_largest_area(&run.sched);
        dc_init(UNITS_RC_CORE); /* nobody pushes between frames */
        rc_frame.active = 1;
        task_signal_local(); /* the collector starts */
        for (uint32_t nc = UNITS_FIRST_NC; nc < board_ncores; nc++) {
            m->type = MSG_NC_START;
            m->len = 5;
            wire_put_u8(m->payload, flags);
            wire_put_u32(m->payload + 1, largest);
            run.state[nc] = RC_NC_IDLE;
            rc_send_nc(nc, m);
        }
        /* The NCs' share of the pool is the same for each (kernel/kmem.c). */
        run.nc_private = (uint32_t)cpu_of(UNITS_FIRST_NC)->mem_size;
        rc_serve(&run, m);
        rc_frame.active = 0;
        task_signal_local();
        rc_frame.have_fm = run.status == LINK_OK;
    }
    if (run.status == LINK_OK && run.total)
        rc_progress(&run, m);
    rc_done(&run, m, ktime_ticks_to_ms(ktime_now() - t0), blob_bytes);
}
