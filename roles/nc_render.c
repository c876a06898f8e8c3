/* nc_render.c: the NC's part of rendering (roles/gigs.h): per area from
 * the RC, Y clipping, X clipping and tracing (render_area), then the rows
 * into the data collector FIFO.  Its working set (clip lists and one
 * area's pixels) comes from its private memory, sized by the scene and the
 * schedule's largest area.
 *
 * Asking ahead (unless LINK_RENDER_ASK_WHEN_DONE, the paper's rule): while
 * it renders an area, the NC sends its next request once the pixels left,
 * at the rate of the pixels done so far, would take no longer than a round
 * trip to the RC (what the last request it waited for took, or less when
 * an answer came sooner), so the next area is there when it finishes. */
#include <stdint.h>
#include <string.h>

#include "drivers/framemem/dc.h"
#include "drivers/imsu/imsu.h"
#include "drivers/serial/line.h"
#include "kernel/cpu.h"
#include "kernel/klog.h"
#include "kernel/kmem.h"
#include "kernel/ktime.h"
#include "kernel/memlayout.h"
#include "proto/hostlink.h"
#include "proto/insn_mark.h"
#include "proto/render_link.h"
#include "proto/textfmt.h"
#include "proto/wire.h"
#include "render/blob.h"
#include "render/clip.h"
#include "render/lightbuf.h"
#include "render/wide.h"
#include "roles/gigs.h"
#include "roles/selftest.h"
#include "proto/unitmsg.h"

/* Per-NC state: each NC's own slot, indexed by core. */
struct nc_job {
    render_ctx_t ctx;
    render_clip_t clip;
    render_clip_options_t opt;
    rgb8_t *pixels;     /* the largest area's pixels */
    uint32_t largest;   /* and how many that is */
    void *wide;         /* escalating: the wide context (render/wide.h), or NULL */
    size_t mark;        /* kmem mark before the frame's working set */
    int marked;
    int counting;       /* the plugin counts this NC from its first frame */
    int trace;          /* LINK_RENDER_TRACE: write trace marks */
    /* asking ahead */
    int ahead;          /* 1: ask a round trip before the end (default) */
    int asked;          /* 1: a request is out, not answered yet */
    uint32_t finished;  /* areas finished in this frame */
    uint64_t sent;      /* ticks: when that request left */
    uint32_t since_ask, next_look; /* pixels since, and the next pixel to
                                      look for its answer at (no round trip
                                      seen yet) */
    uint64_t rtt;       /* ticks: a round trip to the RC, as last seen
                           (NC_RTT_UNKNOWN: none yet, ask at once) */
    uint64_t started;   /* ticks: when the current area's pixels began */
    uint64_t per_pixel; /* ticks per pixel of the last area (~0: none yet) */
    uint32_t done, area_pixels; /* the current area's pixels done, and all */
    struct line_msg *m; /* the message buffer, free while an area renders */
};
static struct nc_job nc_jobs[UNITS_MAX_CORES];
#define NC_RTT_UNKNOWN UINT64_MAX
UNIT_SHARED volatile uint32_t gigs_nc_progress[UNITS_MAX_CORES];

static void nc_send(struct line_msg *m)
{
    int r = line_send(UNITS_RC_CORE, m, 0);
    if (r != LINE_OK)
        klog("render: send to the RC: %s", line_strerror(r));
}

/* MSG_NC_REQ (or MSG_NC_DONE) with the areas finished, or a negative
 * status and text. */
static void nc_say(struct line_msg *m, uint16_t type, int32_t status, const char *why)
{
    m->type = type;
    wire_put_u32(m->payload, (uint32_t)status);
    uint32_t n = why ? (uint32_t)strlen(why) : 0;
    memcpy(m->payload + MSG_NC_REQ_SIZE, why, n);
    m->len = (uint16_t)(MSG_NC_REQ_SIZE + n);
    nc_send(m);
}

static void nc_request(struct nc_job *job, struct line_msg *m, int32_t status, const char *why)
{
    nc_say(m, MSG_NC_REQ, status, why);
    job->asked = 1;
    job->sent = ktime_now();
    job->since_ask = 0;
    job->next_look = 1;
}

/* A round trip took at most `seen` ticks (exactly, if the NC waited). */
static void nc_round_trip(struct nc_job *job, uint64_t seen, int waited)
{
    if (waited || seen < job->rtt)
        job->rtt = seen;
}

/* Escalating: the wide context on the broadcast block's wide blob, from
 * private memory; the narrow context's pixels that lose precision are
 * traced again there.  0, or -1 with why filled. */
static int nc_setup_wide(struct nc_job *job, const uint8_t *block, const render_blob_t *blob,
                         char *why, size_t cap)
{
    uint32_t at = blob->wide_offset;
    size_t bytes = render_wide_linked() ? RENDER_WIDE(wide_ctx_bytes)() : 0;
    if (!at || at >= imsu_rc_ncs.size || !bytes) {
        fmt_snprintf(why, cap, "escalation: %s",
                     !bytes ? "this firmware carries no wide arithmetic"
                            : "the broadcast block holds no wide blob");
        return -1;
    }
    if (bytes + RENDER_WIDE_CTX_ALIGN > kmem_free()) {
        fmt_snprintf(why, cap, "escalation: the wide context's %u bytes exceed the %u free bytes "
                     "of private memory", (unsigned)bytes, (unsigned)kmem_free());
        return -1;
    }
    void *mem = kmem_alloc(bytes, "wide context");
    const render_options_t *o = &job->ctx.options;
    /* checking, the wide colour is compared, never painted */
    if (RENDER_WIDE(wide_ctx_open)(mem, block + at, imsu_rc_ncs.size - at, o->use_bounds,
                                   o->use_hierarchy, o->mark_lost && !o->check_lost, why,
                                   cap) != 0)
        return -1;
    job->wide = mem;
    render_wide_escalate(&job->ctx, mem);
    return 0;
}

/* The frame's light buffer (render/lightbuf.h) in private memory, where
 * it fits beside the working set; without it shadow rays walk the whole
 * tree: the same image, more instructions. */
static void nc_light_buffer(struct nc_job *job, const render_frame_t *f)
{
    size_t bytes = render_lightbuf_bytes(f);
    if (bytes + 16 > kmem_free())
        return;
    job->ctx.light_buffer = render_lightbuf_build(f, kmem_alloc(bytes, "light buffer"), bytes);
}

/* Opens the broadcast frame and sets aside the working set; 0, or -1 with
 * why filled (the broadcast read is ended again then). */
static int nc_setup(struct nc_job *job, uint8_t flags, uint32_t largest, uint8_t clip, char *why,
                    size_t cap)
{
    uint32_t me = mycpu()->core;
    const uint8_t *block;
    uint32_t gen;
    int r = imsu_bcast_read_begin(&imsu_rc_ncs, me, &block, &gen);
    if (r != IMSU_OK) {
        fmt_snprintf(why, cap, "broadcast block: %s", imsu_strerror(r));
        return -1;
    }
    const render_blob_t *blob;
    render_blob_error_t err;
    if (render_blob_open(block, imsu_rc_ncs.size, &blob, &err) != RENDER_BLOB_OK) {
        fmt_snprintf(why, cap, "broadcast block: %s", err.message);
        imsu_bcast_read_end(&imsu_rc_ncs, me);
        return -1;
    }
    if (!job->marked) {
        job->mark = kmem_mark();
        job->marked = 1;
    }
    kmem_release_to(job->mark);
    size_t clip_bytes = (render_clip_bytes(blob->frame) + 7u) & ~(size_t)7u;
    size_t pixel_bytes = (size_t)largest * sizeof(rgb8_t);
    if (clip_bytes + pixel_bytes + 16 > kmem_free()) {
        fmt_snprintf(why, cap, "working set of %u bytes (clip lists %u, area of %u pixels) "
                     "exceeds its %u free bytes of private memory",
                     (unsigned)(clip_bytes + pixel_bytes), (unsigned)clip_bytes,
                     (unsigned)largest, (unsigned)kmem_free());
        imsu_bcast_read_end(&imsu_rc_ncs, me);
        return -1;
    }
    void *clip_mem = kmem_alloc(clip_bytes, "clip lists");
    job->pixels = kmem_alloc(pixel_bytes ? pixel_bytes : 1, "area pixels");
    job->largest = largest;
    render_clip_init(&job->clip, blob->frame, clip_mem, clip_bytes);
    render_ctx_init(&job->ctx, blob->frame);
    job->ctx.options.use_bounds = !(flags & LINK_RENDER_NO_BBOX);
    job->ctx.options.use_hierarchy = !(flags & LINK_RENDER_NO_HIERARCHY);
    job->wide = NULL;
    if (((flags & LINK_RENDER_ESCALATE) || blob->frame->options.check_lost) &&
        nc_setup_wide(job, block, blob, why, cap) != 0) {
        imsu_bcast_read_end(&imsu_rc_ncs, me);
        return -1;
    }
    nc_light_buffer(job, blob->frame);
    job->opt.y_clip = !(flags & LINK_RENDER_NO_YCLIP);
    job->opt.x_clip = !(flags & LINK_RENDER_NO_XCLIP);
    job->opt.lists = clip == LINK_CLIP_LISTS ||
                     (clip == LINK_CLIP_AUTO &&
                      blob->frame->clip_coverage <= RENDER_CLIP_LISTS_MAX_COVERAGE &&
                      blob->frame->clip_rows <= RENDER_CLIP_LISTS_MAX_ROWS);
    job->opt.progress = &gigs_nc_progress[mycpu()->core];
    return 0;
}

/* After the area's set-up and after each pixel: the trace mark, and the
 * request for the next area once the pixels left would take no longer than
 * a round trip.  While no round trip has been seen (the first area came
 * with MSG_NC_START), it asks at once and times the first one by looking
 * for the answer after 1, 2, 4, 8 ... pixels: a few looks in all, and a
 * round trip within twice the pixels' time it took.
 * Integer compares: left * elapsed <= rtt * done. */
static void nc_pixel(void *arg)
{
    struct nc_job *job = arg;
    if (job->trace)
        insn_mark_trace_pixel();
    if (!job->ahead)
        return;
    if (job->asked) {
        if (job->rtt == NC_RTT_UNKNOWN && ++job->since_ask == job->next_look) {
            job->next_look *= 2;
            if (line_recv_ready(UNITS_RC_CORE))
                job->rtt = ktime_now() - job->sent;
        }
        return;
    }
    uint64_t now = ktime_now();
    uint32_t left = job->area_pixels - job->done;
    int soon = job->rtt == NC_RTT_UNKNOWN ||
               (job->done ? (uint64_t)left * (now - job->started) <= job->rtt * job->done
                          : job->per_pixel <= job->rtt / (left ? left : 1u));
    job->done++;
    if (soon)
        nc_request(job, job->m, (int32_t)job->finished, NULL);
}

/* Renders one area and pushes its rows into the DC.  A fault planned for
 * this area (MSG_NC_AREA of MSG_NC_AREA_INJECT_SIZE bytes) comes after pushing that many rows.
 * Traced: the area's x, y, w, h (16 bits each), then marks at its start,
 * after its set-up and each pixel, and at its end. */
static int nc_area(struct nc_job *job, struct line_msg *m, char *why, size_t cap)
{
    render_area_t a = {wire_get_u16(m->payload), wire_get_u16(m->payload + 2),
                       wire_get_u16(m->payload + 4), wire_get_u16(m->payload + 6)};
    int planned = m->len >= MSG_NC_AREA_INJECT_SIZE;
    uint8_t inject = planned ? wire_get_u8(m->payload + 8) : 0;
    uint32_t inject_row = planned ? wire_get_u16(m->payload + 10) : 0;
    if (job->trace) {
        insn_mark_trace_bits(a.x, 16);
        insn_mark_trace_bits(a.y, 16);
        insn_mark_trace_bits(a.w, 16);
        insn_mark_trace_bits(a.h, 16);
        insn_mark_trace_area_begin();
    }
    if (a.w == 0 || a.h == 0 || (uint32_t)a.w * a.h > job->largest) {
        fmt_snprintf(why, cap, "area %ux%u at (%u,%u): not 1 to %u pixels (the frame's largest)",
                     (unsigned)a.w, (unsigned)a.h, (unsigned)a.x, (unsigned)a.y,
                     (unsigned)job->largest);
        return -1;
    }
    job->m = m; /* read: free to send from now */
    job->done = 0;
    job->area_pixels = a.w * a.h;
    job->started = ktime_now();
    int hook = job->trace || (job->ahead && (!job->asked || job->rtt == NC_RTT_UNKNOWN));
    render_status_t st = render_area_marked(&job->ctx, &job->clip, &a, &job->opt, job->pixels,
                                            hook ? nc_pixel : NULL, job);
    job->per_pixel = (ktime_now() - job->started) / job->area_pixels;
    if (st != RENDER_OK) {
        fmt_snprintf(why, cap, "area %ux%u at (%u,%u): %s", (unsigned)a.w, (unsigned)a.h,
                     (unsigned)a.x, (unsigned)a.y, render_status_name(st));
        return -1;
    }
    for (uint32_t r = 0; r <= a.h; r++) {
        if (inject && r == inject_row)
            selftest_fail_on_purpose(inject);
        if (r == a.h)
            break;
        const rgb8_t *row = job->pixels + (size_t)r * a.w;
        if (dc_push_span(a.x, a.y + r, (const uint8_t *)row, a.w) != DC_OK) {
            fmt_snprintf(why, cap, "data collector refused row %u of an area at x %u",
                         (unsigned)(a.y + r), (unsigned)a.x);
            return -1;
        }
    }
    if (job->trace)
        insn_mark_trace_area_end();
    return 0;
}

_Static_assert(sizeof(rgb8_t) == 3, "the DC takes rows of packed r,g,b bytes");

/* The frame's first area: the one MSG_NC_START m carries, turned into the
 * MSG_NC_AREA it stands for (1: m holds it); else a request on the line
 * (0), with why when the set-up failed. */
static int nc_first_area(struct nc_job *job, struct line_msg *m, int ok, const char *why)
{
    job->finished = 0;
    job->per_pixel = UINT64_MAX; /* no rate yet */
    job->rtt = NC_RTT_UNKNOWN;
    job->asked = 0;
    if (ok && m->len >= MSG_NC_START_SIZE + MSG_NC_AREA_SIZE) {
        m->len = (uint16_t)(m->len - MSG_NC_START_SIZE);
        memmove(m->payload, m->payload + MSG_NC_START_SIZE, m->len);
        m->type = MSG_NC_AREA;
        return 1;
    }
    nc_request(job, m, ok ? 0 : LINK_ERR_CHECK, ok ? NULL : why);
    return 0;
}

void nc_render_frame(struct line_msg *m)
{
    uint32_t me = mycpu()->core;
    struct nc_job *job = &nc_jobs[me];
    if (!job->counting) {
        job->counting = 1;
        insn_mark_count_from_here(); /* benchmarks count rendering, not boot */
    }
    uint8_t flags = wire_get_u8(m->payload);
    uint8_t clip = m->len >= MSG_NC_START_SIZE ? wire_get_u8(m->payload + 1) : LINK_CLIP_AUTO;
    uint32_t largest = m->len >= MSG_NC_START_SIZE ? wire_get_u32(m->payload + 4) : 0;
    char why[LINE_MAX_PAYLOAD / 4];
    job->trace = (flags & LINK_RENDER_TRACE) != 0;
    if (job->trace)
        insn_mark_trace_span_begin();
    int ok = nc_setup(job, flags, largest, clip, why, sizeof why) == 0;
    if (job->trace)
        insn_mark_trace_span_end();
    int reading = ok; /* inside the broadcast read */
    job->ahead = !(flags & LINK_RENDER_ASK_WHEN_DONE);
    int have = nc_first_area(job, m, ok, why); /* m holds a message not yet handled */
    for (;;) {
        if (!have) {
            int r = line_recv(UNITS_RC_CORE, m, 0);
            if (r != LINE_OK) {
                klog("render: line from the RC: %s", line_strerror(r));
                continue;
            }
            if (job->asked)
                nc_round_trip(job, ktime_now() - job->sent, 1);
        }
        have = 0;
        if (m->type == MSG_NC_STOP && m->len >= 1)
            selftest_fail_on_purpose(wire_get_u8(m->payload)); /* the test hook */
        if (m->type == MSG_NC_STOP)
            break;
        if (m->type != MSG_NC_AREA || !ok) {
            klog("render: unexpected message %u from the RC", (unsigned)m->type);
            continue;
        }
        job->asked = 0;
        if (nc_area(job, m, why, sizeof why) != 0) {
            ok = 0;
            nc_request(job, m, LINK_ERR_CHECK, why);
            continue;
        }
        job->finished++;
        if (!job->asked) {
            nc_request(job, m, (int32_t)job->finished, NULL);
            continue;
        }
        /* Asked ahead: the next area may be here already; if not, the RC
         * learns that this one is finished. */
        if (line_try_recv(UNITS_RC_CORE, m) == LINE_OK) {
            nc_round_trip(job, ktime_now() - job->sent, 0);
            have = 1;
            continue;
        }
        nc_say(m, MSG_NC_DONE, (int32_t)job->finished, NULL);
    }
    if (reading)
        imsu_bcast_read_end(&imsu_rc_ncs, me);
    m->type = MSG_NC_STOPPED;
    m->len = 4 + GIGS_STATS_SIZE;
    wire_put_u32(m->payload, (uint32_t)kmem_high_water());
    if (reading && job->wide)
        RENDER_WIDE(wide_stats_add)(job->wide, &job->ctx.stats); /* the escalations' rays */
    if (reading)
        gigs_stats_put(m->payload + 4, &job->ctx.stats);
    else
        memset(m->payload + 4, 0, GIGS_STATS_SIZE);
    nc_send(m);
}
