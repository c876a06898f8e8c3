/* dm_render.c: the DM's part of rendering (roles/gigs.h): it keeps the
 * compiled scene, prepares each frame (render_blob_prepare: hierarchy, world
 * and eye coordinates, boxes, screen rectangles) in the IMSU block it
 * holds, swaps it to the RC, relays progress, and streams the frame memory
 * back to the host. */
#include <stdint.h>
#include <string.h>

#include "drivers/imsu/imsu.h"
#include "drivers/serial/hostlink_tx.h"
#include "drivers/serial/line.h"
#include "kernel/cpu.h"
#include "kernel/kmem.h"
#include "kernel/ktime.h"
#include "kernel/memlayout.h"
#include "kernel/task.h"
#include "proto/areas.h"
#include "proto/board_map.h"
#include "proto/hostlink.h"
#include "proto/insn_mark.h"
#include "proto/render_link.h"
#include "proto/scene_format.h"
#include "proto/textfmt.h"
#include "proto/wire.h"
#include "render/blob.h"
#include "render/limits.h"
#include "render/wide.h"
#include "roles/dm.h"
#include "roles/gigs.h"
#include "roles/selftest.h"
#include "roles/unit.h"
#include "proto/unitmsg.h"

/* The scene the host loaded; len 0 = none. */
static struct {
    uint8_t *compiled;    /* the compiled scene, in DM private memory */
    uint32_t len;
    size_t mark;          /* kmem mark before it: a new scene starts here */
    int marked;
    uint16_t width, height;
    uint32_t frames;
    uint32_t max_depth;   /* the scene's recursion depth: the NCs' stack */
    int check_lost;       /* the scene asks its lost pixels checked in the
                             wide arithmetic: every frame has a wide blob */
    uint32_t blob_bytes;  /* render_blob_bytes bound */
    int32_t prepared;     /* frame prepared in the block the DM holds, or -1 */
    uint32_t prepare_ms;  /* what preparing it took, wherever it was done
                             (the scene's upload, or the frame before's
                             render): told with the frame */
    int loaded[2];        /* IMSU block A / B holds this scene, loaded: a
                             frame is prepared there without loading again */
    uint32_t load_id;     /* this scene's number (blob->scene_id, never 0):
                             the RC then copies only the frame part of the
                             next blobs of the same load */
    int wide_loaded[2];   /* block A / B holds this scene's wide blob too */
    int wide_refused;     /* the wide blob did not fit beside the scene: an
                             escalation asked of this scene is dropped */
    char wide_why[RENDER_BLOB_MSG_MAX]; /* why, from dm_load_wide */
    int prepared_wide;    /* the frame prepared holds the wide blob */
    uint32_t body_sum;    /* the scene's word sum after its header, summed
                             while its shared-path upload was checked */
    int summed;           /* body_sum was summed so (the check's time told) */
    int sum_known;        /* body_sum holds it, summed so or checked by a
                             load: later loads, narrow or wide, need not sum */
    uint32_t load_ms;     /* the last load into a block took (the index too) */
} dm_scene;

static const char dm_blob_limit_name[] = MACHINE_IMSU_BLOCK_NAME;

_Static_assert(sizeof "scene refused: " - 1 + RENDER_BLOB_MSG_MAX <= KLOG_MAX,
               "a refusal is cut on the DM's log line: raise KLOG_MAX");

/* The renderer's messages may already say "scene refused: "; said once. */
static const char *dm_refusal(const char *message)
{
    static const char prefix[] = "scene refused: ";
    return strncmp(message, prefix, sizeof prefix - 1) == 0 ? message + sizeof prefix - 1
                                                           : message;
}

/* Receiving the compiled scene. */
struct dm_scene_rx {
    uint8_t *buf;
    uint32_t cap;
    char why[RENDER_BLOB_MSG_MAX];
};

static int dm_scene_chunk(void *ctx, const uint8_t *data, uint32_t n, uint64_t offset)
{
    struct dm_scene_rx *rx = ctx;
    if (offset + n > rx->cap) {
        fmt_snprintf(rx->why, sizeof rx->why,
                     "the scene is longer than the %u bytes CMD_SCENE_LOAD announced",
                     (unsigned)rx->cap);
        return -1;
    }
    memcpy(rx->buf + offset, data, n);
    return 0;
}

/* Where the wide blob starts in block: past the narrow blob's bound. */
static size_t dm_wide_at(const uint8_t *block)
{
    const render_blob_t *blob = (const render_blob_t *)block;
    return (blob->bound + RENDER_RELOCATE_ALIGN - 1) & ~(size_t)(RENDER_RELOCATE_ALIGN - 1);
}

/* The wide blob (escalation, render/wide.h) loaded past the narrow one in
 * block, held, when the firmware carries the wide arithmetic: part of the
 * scene's load, done with the narrow load in its span, told what the
 * narrow load found (scene_load_known_of: its word sum, scaling, checks
 * and index).  Refused (no room,
 * or the wide loader's checks): wide_refused and wide_why say so, and an
 * escalation asked of this scene is dropped (or fails, checking lost
 * pixels). */
static void dm_load_wide(uint8_t *block, int held, size_t size)
{
    if (!render_wide_linked())
        return;
    size_t at = dm_wide_at(block);
    int r = at < size ? 0 : -1;
    if (r != 0)
        fmt_snprintf(dm_scene.wide_why, sizeof dm_scene.wide_why,
                     "no room past the scene's %zu bytes", ((const render_blob_t *)block)->bound);
    if (r == 0) {
        scene_load_known_t known =
            scene_load_known_of(&((const render_blob_t *)block)->scene, dm_scene.body_sum);
        r = RENDER_WIDE(wide_blob_load)(dm_scene.compiled, dm_scene.len, &known,
                                        block + at, size - at,
                                        "the rest of " MACHINE_IMSU_BLOCK_NAME, dm_scene.load_id,
                                        dm_scene.wide_why, sizeof dm_scene.wide_why);
    }
    dm_scene.wide_loaded[held] = r == 0;
    if (r != 0)
        dm_scene.wide_refused = 1;
}

/* The wide blob of frame prepared in the block, loaded there already
 * (dm_load_wide); 0, or -1 with err filled. */
static int dm_prepare_wide(uint8_t *block, int held, uint32_t frame, size_t size,
                           render_blob_error_t *err)
{
    err->status = RENDER_BLOB_ERR_PREPARE;
    size_t at = dm_wide_at(block);
    char why[RENDER_BLOB_MSG_MAX];
    int r = -1;
    if (!dm_scene.wide_loaded[held])
        fmt_snprintf(why, sizeof why, "%s",
                     dm_scene.wide_why[0] ? dm_scene.wide_why : "the wide blob is not loaded");
    else
        r = RENDER_WIDE(wide_blob_prepare)(block + at, frame, size - at, why, sizeof why);
    if (r != 0) {
        fmt_snprintf(err->message, sizeof err->message, "escalation: %s", why);
        return -1;
    }
    ((render_blob_t *)block)->wide_offset = (uint32_t)at;
    return 0;
}

/* The DM's IMSU block opened for writing: *held (A or B) and *block; 0, or
 * -1 with err filled. */
static int dm_block_begin(int *held, uint8_t **block, render_blob_error_t *err)
{
    struct imsu_pair *p = &imsu_dm_rc;
    *held = imsu_held(p, UNITS_DM_CORE);
    int r = imsu_write_begin(p, UNITS_DM_CORE, *held, block);
    if (r != IMSU_OK) {
        err->status = RENDER_BLOB_ERR_BLOCK;
        fmt_snprintf(err->message, sizeof err->message, "IMSU %s: %s", p->name,
                     imsu_strerror(r));
        return -1;
    }
    return 0;
}

/* What a frame's preparation holds besides the narrow blob. */
enum dm_wide {
    DM_WIDE_NONE,  /* nothing */
    DM_WIDE_ASKED, /* the wide blob (escalating): its failure fails the frame */
    DM_WIDE_READY  /* the wide blob when it loaded (the upload's frame 0, whole
                      for an escalating render): its failure leaves it out */
};

/* The block the DM holds loaded with the scene: the narrow blob and, when
 * the firmware carries it, the wide one (dm_load_wide).  One span, the
 * load's time in load_ms. */
static render_blob_status_t dm_load(uint8_t *block, int held, render_blob_error_t *err)
{
    struct imsu_pair *p = &imsu_dm_rc;
    render_blob_t *blob = (render_blob_t *)block;
    uint64_t l0 = ktime_now();
    insn_mark_trace_span_begin(); /* the load, the index included (docs/trace.md) */
    scene_load_known_t sum = {.body_sum = dm_scene.body_sum}; /* the sum alone */
    render_blob_status_t st =
        render_blob_load_summed(dm_scene.compiled, dm_scene.len, dm_scene.sum_known ? &sum : NULL,
                                block, p->size, dm_blob_limit_name, &blob, err);
    if (st == RENDER_BLOB_OK && !dm_scene.sum_known) { /* the header's, checked */
        dm_scene.body_sum = wire_get_u32(dm_scene.compiled + SCN_HDR_SUM);
        dm_scene.sum_known = 1;
    }
    if (st == RENDER_BLOB_OK) {
        blob->scene_id = dm_scene.load_id;
        dm_load_wide(block, held, p->size);
    }
    insn_mark_trace_span_end();
    dm_scene.load_ms = ktime_ticks_to_ms(ktime_now() - l0);
    dm_scene.loaded[held] = st == RENDER_BLOB_OK;
    return st;
}

/* Builds frame into the block the DM holds, with its wide blob as wide
 * says; 0, or -1 with err filled.  The scene is loaded into a block once
 * (its checks, its arrays); each frame after that is only the paper's
 * preprocessing: eye coordinates, boxes, screen rectangles, in one span
 * for the narrow and the wide blob alike. */
static int dm_prepare(uint32_t frame, enum dm_wide wide, render_blob_error_t *err)
{
    struct imsu_pair *p = &imsu_dm_rc;
    int held;
    uint8_t *block;
    if (dm_block_begin(&held, &block, err) != 0)
        return -1;
    render_blob_t *blob = (render_blob_t *)block;
    render_blob_status_t st = dm_scene.loaded[held] ? RENDER_BLOB_OK : dm_load(block, held, err);
    int with_wide = wide == DM_WIDE_ASKED || (wide == DM_WIDE_READY && dm_scene.wide_loaded[held]);
    uint64_t t0 = ktime_now();
    insn_mark_trace_span_begin(); /* the preprocessing of one frame (docs/trace.md) */
    if (st == RENDER_BLOB_OK) {
        blob->wide_offset = 0;
        st = render_blob_prepare(blob, frame, p->size, err);
    }
    if (st == RENDER_BLOB_OK && with_wide && dm_prepare_wide(block, held, frame, p->size, err) != 0) {
        with_wide = 0;
        if (wide == DM_WIDE_ASKED)
            st = err->status;
    }
    insn_mark_trace_span_end();
    imsu_write_end(p, UNITS_DM_CORE);
    dm_scene.prepared = st == RENDER_BLOB_OK ? (int32_t)frame : -1;
    dm_scene.prepared_wide = with_wide;
    dm_scene.prepare_ms = ktime_ticks_to_ms(ktime_now() - t0);
    return st == RENDER_BLOB_OK ? 0 : -1;
}

/* The checks a scene must pass before anything renders, past the loader's:
 * the NCs' stack for its recursion depth. */
static int dm_scene_fits_units(uint16_t cmd)
{
    const render_blob_t *blob = (const render_blob_t *)imsu_read_block(&imsu_dm_rc, UNITS_DM_CORE);
    uint32_t depth = blob->scene.options.max_depth;
    if (RENDER_STACK_BYTES(depth) + GIGS_NC_STACK_MARGIN > TASK_STACK_SIZE) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS,
                       "scene refused: max_depth %u needs %u bytes of NC stack, more than "
                       "TASK_STACK_SIZE (%u bytes)",
                       (unsigned)depth, (unsigned)(RENDER_STACK_BYTES(depth) + GIGS_NC_STACK_MARGIN),
                       (unsigned)TASK_STACK_SIZE);
        return -1;
    }
    return 0;
}

/* Escalation's checks: a firmware that carries the wide arithmetic, and
 * the NCs' stack for it (the wide renderer runs on the narrow one's stack,
 * below render_pixel). */
static int dm_escalation_fits(uint16_t cmd)
{
    if (!render_wide_linked()) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS,
                       "CMD_RENDER: escalation asked of a firmware without a wide arithmetic "
                       "(the escalating builds are links1-float-esc.elf and links1-fixed-esc.elf)");
        return -1;
    }
    uint32_t depth = dm_scene.max_depth;
    size_t need = RENDER_WIDE(wide_stack_bytes)(depth) + RENDER_WIDE_CALL_STACK +
                  GIGS_NC_STACK_MARGIN;
    if (need > TASK_STACK_SIZE) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS,
                       "CMD_RENDER: escalation at max_depth %u needs %u bytes of NC stack for the "
                       "%s renderer, more than TASK_STACK_SIZE (%u bytes)",
                       (unsigned)depth, (unsigned)need, RENDER_WIDE(wide_arith_name),
                       (unsigned)TASK_STACK_SIZE);
        return -1;
    }
    return 0;
}

void dm_cmd_scene_load(uint16_t cmd)
{
    if (dm_frame.length < LINK_CMD_FIXED_SIZE + LINK_SCENE_LOAD_ARGS_SIZE) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_SCENE_LOAD needs u32 bytes (4 bytes), got %u",
                       (unsigned)(dm_frame.length - LINK_CMD_FIXED_SIZE));
        return;
    }
    uint32_t len = wire_get_u32(dm_frame.payload + LINK_CMD_FIXED_SIZE);
    int path = dm_bulk_path(cmd, LINK_SCENE_LOAD_ARGS_SIZE);
    if (path < 0)
        return;
    /* The old scene goes first: its memory holds the new one. */
    if (!dm_scene.marked) {
        insn_mark_count_from_here(); /* benchmarks count from the first scene */
        dm_scene.mark = kmem_mark();
        dm_scene.marked = 1;
    }
    kmem_release_to(dm_scene.mark);
    dm_scene.len = 0;
    dm_scene.prepared = -1;
    dm_scene.loaded[0] = dm_scene.loaded[1] = 0;
    dm_scene.wide_loaded[0] = dm_scene.wide_loaded[1] = 0;
    dm_scene.wide_refused = 0;
    dm_scene.wide_why[0] = 0;
    if (++dm_scene.load_id == 0) /* 0 is "unnumbered" */
        dm_scene.load_id = 1;
    struct dm_scene_rx rx = {NULL, 0, ""};
    size_t room = kmem_free();
    if (len == 0 || len > SCN_MAX_SIZE || len > room)
        fmt_snprintf(rx.why, sizeof rx.why,
                     "a compiled scene of %u bytes: must be 1..SCN_MAX_SIZE (%u) and fit the "
                     "DM's free private memory (%u bytes)",
                     (unsigned)len, (unsigned)SCN_MAX_SIZE, (unsigned)room);
    else
        rx = (struct dm_scene_rx){kmem_alloc(len, "compiled scene"), len, ""};
    uint64_t got = 0;
    uint32_t crc = 0;
    dm_scene.summed = dm_scene.sum_known = 0;
    if (path == LINK_PATH_SHARED) {
        /* The host writes the scene straight into its buffer; refused
         * before the offer when it cannot be taken. */
        if (rx.why[0]) {
            hostlink_error(cmd, LINK_ERR_BAD_ARGS, "scene refused: %s", rx.why);
            return;
        }
        uint32_t n = 0;
        if (dm_bulk_receive(cmd, rx.buf, len, SCN_SUM_START, &n, &dm_scene.body_sum) != LINK_OK)
            return; /* the shared path already answered */
        got = n;
        dm_scene.summed = dm_scene.sum_known = 1;
    } else {
        insn_mark_trace_span_begin(); /* the upload, its frames checked (docs/trace.md) */
        int r = dm_transfer_receive(cmd, dm_scene_chunk, &rx, &got, &crc);
        insn_mark_trace_span_end();
        if (r != LINK_OK && r != LINK_ERR_CHECK)
            return; /* the transfer already answered */
    }
    if (rx.why[0] == 0 && got != len)
        fmt_snprintf(rx.why, sizeof rx.why, "received %u bytes, CMD_SCENE_LOAD announced %u",
                     (unsigned)got, (unsigned)len);
    if (rx.why[0]) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "scene refused: %s", rx.why);
        return;
    }
    /* The size bound from the header, then a full build of frame 0: the
     * loader's checks (the CRC once) and render_prepare's; with the wide
     * blob when it loaded, so that an escalating render finds frame 0
     * prepared whole. */
    render_blob_error_t err;
    dm_scene.compiled = rx.buf;
    dm_scene.len = len;
    if (dm_prepare(0, DM_WIDE_READY, &err) != 0) {
        dm_scene.len = 0;
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "scene refused: %s", dm_refusal(err.message));
        return;
    }
    if (dm_scene_fits_units(cmd) != 0) {
        dm_scene.len = 0;
        return;
    }
    const render_blob_t *blob = (const render_blob_t *)imsu_read_block(&imsu_dm_rc, UNITS_DM_CORE);
    dm_scene.width = blob->scene.width;
    dm_scene.height = blob->scene.height;
    dm_scene.frames = blob->scene.frame_count;
    dm_scene.max_depth = blob->scene.options.max_depth;
    dm_scene.check_lost = blob->scene.options.check_lost;
    dm_scene.blob_bytes = (uint32_t)blob->bound;
    uint32_t check_ms = dm_scene.summed ? ktime_ticks_to_ms(dm_bulk_check_ticks) : 0;
    struct link_scene_info info = {dm_scene.width, dm_scene.height, dm_scene.frames, len,
                                   (uint32_t)blob->bound, (uint32_t)imsu_dm_rc.size, check_ms,
                                   dm_scene.load_ms, dm_scene.prepare_ms,
                                   blob->scene.prim_count};
    uint8_t f[LINK_SCENE_INFO_SIZE];
    link_scene_info_put(f, &info);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

/* Relays the RC's progress until MSG_RENDER_DONE arrives in m.  Looks
 * every GIGS_WATCH_MS whether the RC halted (LINE_ERR_NO_LINE then). */
static int dm_await_frame(uint32_t frame, struct line_msg *m)
{
    for (;;) {
        int r = line_recv(UNITS_RC_CORE, m, ktime_deadline_ms(GIGS_WATCH_MS));
        if (r == LINE_ERR_TIMEOUT && !unit_is_halted(UNITS_RC_CORE))
            continue;
        if (r == LINE_ERR_TIMEOUT)
            return LINE_ERR_NO_LINE;
        if (r != LINE_OK)
            return r;
        if (m->type == MSG_RENDER_DONE)
            return LINE_OK;
        if (m->type != MSG_RENDER_PROGRESS)
            continue;
        struct link_progress g = {frame, wire_get_u32(m->payload), wire_get_u32(m->payload + 4),
                                  wire_get_u32(m->payload + 8), wire_get_u32(m->payload + 12)};
        uint8_t p[LINK_PROGRESS_SIZE];
        link_progress_put(p, &g);
        hostlink_send(LINK_PROGRESS, 0, p, sizeof p);
    }
}

static void dm_render_result(uint16_t cmd, const struct link_render_args *a,
                             uint32_t prepare_ms, const struct line_msg *m)
{
    uint32_t frame = a->frame;
    const uint8_t *q = m->payload + 4;
    struct link_render_stats s;
    memset(&s, 0, sizeof s);
    s.frame = frame;
    s.ncs = wire_get_u32(q);
    s.areas = wire_get_u32(q + 4);
    s.render_ms = wire_get_u32(q + 8);
    s.rc_high = wire_get_u32(q + 12);
    s.nc_high_max = wire_get_u32(q + 16);
    s.nc_private = wire_get_u32(q + 20);
    s.blob_bytes = wire_get_u32(q + 24);
    s.dc_full_waits = wire_get_u32(q + 28);
    render_stats_t rs;
    memset(&rs, 0, sizeof rs);
    gigs_stats_add(&rs, q + GIGS_RESULT_FIXED);
    s.prepare_ms = prepare_ms;
    s.primary = rs.primary;
    s.primary_hit = rs.primary_hit;
    s.shadow = rs.shadow;
    s.reflection = rs.reflection;
    s.refraction = rs.refraction;
    s.transmission = rs.transmission;
    s.box_tests = rs.box_tests;
    s.prim_tests = rs.prim_tests;
    s.primary_prim_tests = rs.primary_prim_tests;
    s.precision_lost_pixels = rs.precision_lost_pixels;
    s.escalated_pixels = rs.escalated_pixels;
    s.flags = a->flags;
    s.dm_high = (uint32_t)kmem_high_water();
    uint8_t f[LINK_RENDER_STATS_SIZE + LINK_RENDER_FAILS_SIZE(LINK_REISSUE_LIST_MAX)];
    link_render_stats_put(f, &s);
    /* What the frame lost and got back: passed on as the RC wrote it. */
    uint32_t extra = m->len > 4 + GIGS_RESULT_SIZE ? m->len - 4 - GIGS_RESULT_SIZE : 0;
    if (extra > sizeof f - LINK_RENDER_STATS_SIZE)
        extra = sizeof f - LINK_RENDER_STATS_SIZE;
    memcpy(f + LINK_RENDER_STATS_SIZE, q + GIGS_RESULT_SIZE, extra);
    hostlink_result(cmd, LINK_OK, f, LINK_RENDER_STATS_SIZE + extra);
}

_Static_assert(12 + LINK_INJECT_SIZE(LINK_INJECT_MAX) <= LINE_MAX_PAYLOAD,
               "a full fault plan must fit MSG_RENDER_FRAME");
_Static_assert(4 + GIGS_RESULT_SIZE + LINK_RENDER_FAILS_SIZE(LINK_REISSUE_LIST_MAX) <=
                   LINE_MAX_PAYLOAD,
               "the failures must fit MSG_RENDER_DONE");
_Static_assert(LINK_RESULT_FIXED_SIZE + LINK_RENDER_STATS_SIZE +
                   LINK_RENDER_FAILS_SIZE(LINK_REISSUE_LIST_MAX) <= LINK_MAX_PAYLOAD,
               "the failures must fit the CMD_RENDER result");

/* The wide blob left out of the frame prepared whole in the block the DM
 * holds (the upload's frame 0) for a render that does not escalate: the
 * RC then broadcasts the narrow blob alone.  0, or -1 with err filled. */
static int dm_drop_wide(render_blob_error_t *err)
{
    int held;
    uint8_t *block;
    if (dm_block_begin(&held, &block, err) != 0)
        return -1;
    ((render_blob_t *)block)->wide_offset = 0;
    imsu_write_end(&imsu_dm_rc, UNITS_DM_CORE);
    dm_scene.prepared_wide = 0;
    return 0;
}

/* Frame a->frame prepared as asked, unless prepared already (a frame
 * prepared without the wide blob and asked with it is prepared again,
 * whole, so that its preparation is one span).  An escalation
 * (LINK_RENDER_ESCALATE, not the scene's check_lost) whose wide blob does
 * not fit the IMSU block beside the scene is dropped: the flag cleared in
 * *a, the frame prepared without it, and the result's flags say so.  0,
 * or -1 with err filled. */
static int dm_prepare_asked(struct link_render_args *a, int *escalate, render_blob_error_t *err)
{
    int droppable = (a->flags & LINK_RENDER_ESCALATE) && !dm_scene.check_lost;
    if (droppable && dm_scene.wide_refused) {
        a->flags &= (uint8_t)~LINK_RENDER_ESCALATE;
        *escalate = 0;
    }
    int here = dm_scene.prepared == (int32_t)a->frame;
    if (here && dm_scene.prepared_wide == *escalate)
        return 0;
    if (here && !*escalate)
        return dm_drop_wide(err);
    if (dm_prepare(a->frame, *escalate ? DM_WIDE_ASKED : DM_WIDE_NONE, err) == 0)
        return 0;
    if (!droppable || !dm_scene.wide_refused || !*escalate)
        return -1;
    a->flags &= (uint8_t)~LINK_RENDER_ESCALATE; /* refused loading this block */
    *escalate = 0;
    return dm_prepare(a->frame, DM_WIDE_NONE, err);
}

void dm_cmd_render(uint16_t cmd)
{
    if (dm_frame.length < LINK_CMD_FIXED_SIZE + LINK_RENDER_ARGS_SIZE) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_RENDER needs %u bytes of arguments, got %u",
                       (unsigned)LINK_RENDER_ARGS_SIZE,
                       (unsigned)(dm_frame.length - LINK_CMD_FIXED_SIZE));
        return;
    }
    struct link_render_args a;
    link_render_args_get(dm_frame.payload + LINK_CMD_FIXED_SIZE, &a);
    /* The test hook's fault plan, if any, goes to the RC as it came. */
    const uint8_t *plan = dm_frame.payload + LINK_CMD_FIXED_SIZE + LINK_RENDER_ARGS_SIZE;
    uint32_t plan_bytes = dm_frame.length - LINK_CMD_FIXED_SIZE - LINK_RENDER_ARGS_SIZE;
    if (plan_bytes && (plan_bytes < LINK_INJECT_FIXED_SIZE || plan[0] > LINK_INJECT_MAX ||
                       plan_bytes != (uint32_t)LINK_INJECT_SIZE(plan[0]))) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS,
                       "CMD_RENDER: a fault plan of %u bytes: want 2 + 6 per entry, at most "
                       "LINK_INJECT_MAX (%u) entries",
                       (unsigned)plan_bytes, (unsigned)LINK_INJECT_MAX);
        return;
    }
    if (dm_scene.len == 0) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_RENDER: no scene loaded (CMD_SCENE_LOAD first)");
        return;
    }
    if (a.frame >= dm_scene.frames || a.balance > LINK_BALANCE_LINES ||
        (a.flags & ~LINK_RENDER_FLAGS_ALL) || a.guided > AREAS_MAX_GUIDED_FACTOR ||
        a.clip >= LINK_CLIP_MODES) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS,
                       "CMD_RENDER: frame %u (scene has %u), balance %u (0..3), flags 0x%x, "
                       "guided factor %u (0..64) or clipping %u (0..2) out of range",
                       (unsigned)a.frame, (unsigned)dm_scene.frames, (unsigned)a.balance,
                       (unsigned)a.flags, (unsigned)a.guided, (unsigned)a.clip);
        return;
    }
    int escalate = (a.flags & LINK_RENDER_ESCALATE) || dm_scene.check_lost;
    if (escalate && dm_escalation_fits(cmd) != 0)
        return;
    render_blob_error_t err;
    if (dm_prepare_asked(&a, &escalate, &err) != 0) {
        hostlink_error(cmd, LINK_ERR_CHECK, "frame %u: %s", (unsigned)a.frame, err.message);
        return;
    }
    /* prepared now, at the upload or while the frame before rendered */
    uint32_t prepare_ms = dm_scene.prepare_ms;
    int r = imsu_swap(&imsu_dm_rc, UNITS_DM_CORE);
    if (r != IMSU_OK) {
        hostlink_error(cmd, LINK_ERR_CHECK, "IMSU swap to the RC: %s", imsu_strerror(r));
        return;
    }
    dm_scene.prepared = -1; /* the block the DM holds now is the RC's old one */
    struct line_msg *m = &dm_msg;
    m->type = MSG_RENDER_FRAME;
    m->len = (uint16_t)(LINK_RENDER_ARGS_SIZE + plan_bytes);
    memcpy(m->payload + LINK_RENDER_ARGS_SIZE, plan, plan_bytes);
    link_render_args_put(m->payload, &a); /* K and factor 0: the RC's defaults */
    r = line_send(UNITS_RC_CORE, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "CMD_RENDER: the RC did not take the frame (%s)",
                       line_strerror(r));
        return;
    }
    /* Pipelining: the next frame is prepared while this one renders.  An
     * error here is reported when that frame is asked for. */
    if ((a.flags & LINK_RENDER_PREPARE_NEXT) && a.frame + 1 < dm_scene.frames)
        (void)dm_prepare(a.frame + 1, escalate ? DM_WIDE_ASKED : DM_WIDE_NONE, &err);
    /* The test hook: the DM's own planned failure, while the RC renders. */
    for (uint32_t i = 0; i < (plan_bytes ? plan[0] : 0u); i++) {
        struct link_inject e;
        link_inject_get(plan + LINK_INJECT_FIXED_SIZE + i * LINK_INJECT_ENTRY_SIZE, &e);
        if (e.core == UNITS_DM_CORE)
            selftest_fail_on_purpose(e.kind);
    }
    r = dm_await_frame(a.frame, m);
    if (r == LINE_ERR_NO_LINE) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "frame %u: the RC (core %u) halted with a fault: "
                       "the board cannot render on", (unsigned)a.frame, (unsigned)UNITS_RC_CORE);
        return;
    }
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "CMD_RENDER: line from the RC: %s",
                       line_strerror(r));
        return;
    }
    int32_t status = (int32_t)wire_get_u32(m->payload);
    if (status != LINK_OK) {
        hostlink_error(cmd, (int16_t)status, "frame %u: %.*s", (unsigned)a.frame,
                       (int)(m->len - 4), (const char *)m->payload + 4);
        return;
    }
    dm_render_result(cmd, &a, prepare_ms, m);
}

static void dm_frame_fill(void *ctx, uint8_t *data, uint32_t n, uint32_t offset)
{
    const struct fm *fm = ctx;
    /* offset and n are whole bytes; pixels are 3 bytes: go pixel by pixel
     * over the ones this chunk touches. */
    for (uint32_t i = 0; i < n; i++) {
        uint32_t b = offset + i, px = b / 3;
        uint32_t v = fm->pixels[px];
        uint32_t c = b % 3;
        data[i] = c == 0 ? fm_red(v) : c == 1 ? fm_green(v) : fm_blue(v);
    }
}

void dm_cmd_frame_pull(uint16_t cmd)
{
    const struct fm *fm = rc_render_fm();
    if (!fm) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_FRAME_PULL: no frame rendered yet");
        return;
    }
    int path = dm_bulk_path(cmd, 0);
    if (path < 0)
        return;
    uint32_t crc = 0;
    if (path == LINK_PATH_SHARED) {
        /* The frame memory as it is: the host reads it where it lies. */
        crc = dm_bulk_send(fm->pixels, (uint32_t)fm_bytes(fm));
    } else {
        uint32_t total = fm->width * fm->height * 3;
        if (dm_transfer_send(cmd, dm_frame_fill, (void *)fm, total, &crc) != LINK_OK)
            return;
    }
    uint8_t f[LINK_FRAME_INFO_SIZE];
    wire_put_u16(f, (uint16_t)fm->width);
    wire_put_u16(f + 2, (uint16_t)fm->height);
    wire_put_u32(f + 4, crc);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}
