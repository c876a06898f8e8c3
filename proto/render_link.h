/* render_link.h: the arguments and results of the rendering commands of the
 * host link (CMD_SCENE_LOAD, CMD_RENDER, CMD_FRAME_PULL, LINK_PROGRESS in
 * proto/hostlink.h).  One definition for the host tool and the DM; every
 * field little-endian (proto/wire.h), at the offsets the put/get functions
 * below write, and nowhere else.
 *
 * A session: CMD_SCENE_LOAD once per scene (a refused scene leaves the
 * board without a scene, still running: the next CMD_SCENE_LOAD is taken),
 * then per frame CMD_RENDER and CMD_FRAME_PULL. */
#ifndef LINKS1_PROTO_RENDER_LINK_H
#define LINKS1_PROTO_RENDER_LINK_H

#include <stdint.h>

#include "proto/units.h"
#include "proto/wire.h"

/* CMD_SCENE_LOAD arguments: u32 bytes of the compiled scene that follow. */
#define LINK_SCENE_LOAD_ARGS_SIZE 4

/* CMD_SCENE_LOAD result. */
#define LINK_SCENE_INFO_SIZE 36
struct link_scene_info {
    uint16_t width, height;  /* image size */
    uint32_t frames;         /* frames of the animation */
    uint32_t compiled_bytes; /* bytes received */
    uint32_t blob_bytes;     /* bound of one prepared frame (render_blob_bytes) */
    uint32_t blob_limit;     /* the IMSU block it must fit in */
    uint32_t check_ms;       /* the DM's time: the upload's check (shared path) */
    uint32_t load_ms;        /* the load into its IMSU block, the index included */
    uint32_t prepare_ms;     /* frame 0's preparation */
    uint32_t prims;          /* the scene's primitives */
};

/* CMD_RENDER switches: each turns one speed-up off (the image stays the
 * same), or asks the DM to prepare the next frame while this one renders. */
enum link_render_flag {
    LINK_RENDER_NO_YCLIP = 1u << 0,
    LINK_RENDER_NO_XCLIP = 1u << 1,
    LINK_RENDER_NO_BBOX = 1u << 2,
    LINK_RENDER_NO_HIERARCHY = 1u << 3,
    LINK_RENDER_PREPARE_NEXT = 1u << 4, /* pipelining of animations */
    LINK_RENDER_TRACE = 1u << 5,        /* RC and NCs write trace marks
                                           (proto/insn_mark.h, docs/trace.md) */
    LINK_RENDER_ASK_WHEN_DONE = 1u << 6, /* the paper's rule: an NC asks for its
                                            next area once it has finished one
                                            (default: one round trip ahead) */
    LINK_RENDER_ESCALATE = 1u << 7,     /* a pixel that lost precision is traced
                                           again in the wide arithmetic
                                           (render/wide.h; the -esc firmware) */
};
#define LINK_RENDER_FLAGS_ALL 0xFFu

/* How the NCs clip (render/clip.h): by the frame's clusters per pixel and
 * per scanline (render_frame_t.clip_coverage, clip_rows; render/limits.h),
 * or always the paper's lists, or always in the hierarchy. */
enum link_clip { LINK_CLIP_AUTO = 0, LINK_CLIP_LISTS = 1, LINK_CLIP_TREE = 2 };
#define LINK_CLIP_MODES 3

/* Balancing modes: the values of proto/areas.h enum areas_mode. */
enum link_balance {
    LINK_BALANCE_STATIC = 0,
    LINK_BALANCE_DYNAMIC = 1,
    LINK_BALANCE_DECREASING = 2,
    LINK_BALANCE_LINES = 3, /* simple dynamic on whole and partial scanlines */
};

/* CMD_RENDER arguments. */
#define LINK_RENDER_ARGS_SIZE 16
struct link_render_args {
    uint32_t frame;   /* frame index, 0 .. frames-1 */
    uint8_t balance;  /* enum link_balance */
    uint8_t flags;    /* enum link_render_flag */
    uint8_t guided;   /* decreasing: the guided factor, 1..AREAS_MAX_GUIDED_FACTOR;
                         0 = the board's default for its NC count */
    uint8_t clip;     /* enum link_clip */
    uint32_t areas;   /* K: areas of the dynamic grid / smallest-area bound of
                         the decreasing schedule; 0 = the board's default */
    uint16_t row0;    /* a band of the frame: scanlines row0 .. row0+rows-1 only, */
    uint16_t rows;    /* the schedule cut from the band; rows 0 = the whole frame
                         (row0 0) */
};

/* CMD_RENDER may carry, after its LINK_RENDER_ARGS_SIZE bytes, a fault
 * plan (a test hook, `links1 render --inject-faults`): u8 count, u8 0, then
 * count entries of LINK_INJECT_ENTRY_SIZE.  Entry i makes NC core fail
 * while it holds its area-th area of the frame, after pushing row * (h + 1)
 * / 256 of the area's h rows (0: before any), or when told to stop if it
 * gets fewer areas.  The RC carries the plan out by marking the messages it
 * sends; it learns of the failure only as it would of a real one. */
enum link_inject_kind {
    LINK_INJECT_UNDEF = 1,      /* executes an undefined instruction */
    LINK_INJECT_DATA_ABORT = 2, /* loads from an unmapped address */
    LINK_INJECT_HANG = 3,       /* interrupts off, halts without a word */
    LINK_INJECT_SILENT = 4,     /* stops answering, interrupts on */
};
#define LINK_INJECT_KINDS 4
#define LINK_INJECT_MAX 128 /* entries in one plan */
#define LINK_INJECT_FIXED_SIZE 2
#define LINK_INJECT_ENTRY_SIZE 6
#define LINK_INJECT_SIZE(n) (LINK_INJECT_FIXED_SIZE + (n) * LINK_INJECT_ENTRY_SIZE)
struct link_inject {
    uint16_t core;
    uint8_t kind; /* enum link_inject_kind */
    uint8_t row;  /* 0..255: how far into the area */
    uint16_t area;/* the NC's how-manieth area of the frame (0 = its first) */
};

static inline void link_inject_put(uint8_t *p, const struct link_inject *e)
{
    wire_put_u16(p, e->core);
    wire_put_u8(p + 2, e->kind);
    wire_put_u8(p + 3, e->row);
    wire_put_u16(p + 4, e->area);
}
static inline void link_inject_get(const uint8_t *p, struct link_inject *e)
{
    e->core = wire_get_u16(p);
    e->kind = wire_get_u8(p + 2);
    e->row = wire_get_u8(p + 3);
    e->area = wire_get_u16(p + 4);
}

/* What the frame lost and got back: may follow the CMD_RENDER result's
 * LINK_RENDER_STATS_SIZE bytes (and the RC's MSG_RENDER_DONE, which the DM
 * passes on).  u16 NCs failed in this frame, u16 areas re-issued, u16 NCs
 * failed before (left out of this frame), u16 0, a bitmap of the cores that
 * failed in this frame, a bitmap of those of them the watchdog caught (the
 * rest halted with a fault), then min(re-issued, LINK_REISSUE_LIST_MAX)
 * entries: u16 core that failed, u16 x, y, w, h of its area. */
#define LINK_CORE_MAP_SIZE (UNITS_MAX_CORES / 8)
#define LINK_REISSUE_LIST_MAX 48
#define LINK_REISSUE_ENTRY_SIZE 10
#define LINK_RENDER_FAILS_FIXED (8 + 2 * LINK_CORE_MAP_SIZE)
#define LINK_RENDER_FAILS_SIZE(n) (LINK_RENDER_FAILS_FIXED + (n) * LINK_REISSUE_ENTRY_SIZE)
struct link_render_fails {
    uint16_t failed, reissued, failed_before;
    uint8_t failed_map[LINK_CORE_MAP_SIZE];
    uint8_t watchdog_map[LINK_CORE_MAP_SIZE];
    struct link_reissue {
        uint16_t core, x, y, w, h;
    } area[LINK_REISSUE_LIST_MAX];
};

static inline int link_core_map_has(const uint8_t *map, uint32_t core)
{
    return core < UNITS_MAX_CORES && (map[core / 8] >> (core % 8)) & 1u;
}
static inline void link_core_map_set(uint8_t *map, uint32_t core)
{
    if (core < UNITS_MAX_CORES)
        map[core / 8] = (uint8_t)(map[core / 8] | (1u << (core % 8)));
}

/* Bytes link_render_fails_put writes. */
static inline uint32_t link_render_fails_size(const struct link_render_fails *f)
{
    uint32_t n = f->reissued < LINK_REISSUE_LIST_MAX ? f->reissued : LINK_REISSUE_LIST_MAX;
    return LINK_RENDER_FAILS_SIZE(n);
}
static inline uint32_t link_render_fails_put(uint8_t *p, const struct link_render_fails *f)
{
    wire_put_u16(p, f->failed);
    wire_put_u16(p + 2, f->reissued);
    wire_put_u16(p + 4, f->failed_before);
    wire_put_u16(p + 6, 0);
    for (uint32_t i = 0; i < LINK_CORE_MAP_SIZE; i++) {
        p[8 + i] = f->failed_map[i];
        p[8 + LINK_CORE_MAP_SIZE + i] = f->watchdog_map[i];
    }
    uint32_t n = f->reissued < LINK_REISSUE_LIST_MAX ? f->reissued : LINK_REISSUE_LIST_MAX;
    uint8_t *q = p + LINK_RENDER_FAILS_FIXED;
    for (uint32_t i = 0; i < n; i++, q += LINK_REISSUE_ENTRY_SIZE) {
        const struct link_reissue *a = &f->area[i];
        wire_put_u16(q, a->core);
        wire_put_u16(q + 2, a->x);
        wire_put_u16(q + 4, a->y);
        wire_put_u16(q + 6, a->w);
        wire_put_u16(q + 8, a->h);
    }
    return LINK_RENDER_FAILS_SIZE(n);
}
/* 0, or -1 if len bytes cannot hold what the header announces. */
static inline int link_render_fails_get(const uint8_t *p, uint32_t len,
                                        struct link_render_fails *f)
{
    if (len < LINK_RENDER_FAILS_FIXED)
        return -1;
    f->failed = wire_get_u16(p);
    f->reissued = wire_get_u16(p + 2);
    f->failed_before = wire_get_u16(p + 4);
    for (uint32_t i = 0; i < LINK_CORE_MAP_SIZE; i++) {
        f->failed_map[i] = p[8 + i];
        f->watchdog_map[i] = p[8 + LINK_CORE_MAP_SIZE + i];
    }
    uint32_t n = f->reissued < LINK_REISSUE_LIST_MAX ? f->reissued : LINK_REISSUE_LIST_MAX;
    if (len < LINK_RENDER_FAILS_SIZE(n))
        return -1;
    const uint8_t *q = p + LINK_RENDER_FAILS_FIXED;
    for (uint32_t i = 0; i < n; i++, q += LINK_REISSUE_ENTRY_SIZE) {
        struct link_reissue *a = &f->area[i];
        a->core = wire_get_u16(q);
        a->x = wire_get_u16(q + 2);
        a->y = wire_get_u16(q + 4);
        a->w = wire_get_u16(q + 6);
        a->h = wire_get_u16(q + 8);
    }
    return 0;
}

/* LINK_PROGRESS payload. */
#define LINK_PROGRESS_SIZE 20
struct link_progress {
    uint32_t frame;
    uint32_t areas_done;  /* areas finished (their pixels sent to the DC) */
    uint32_t areas_total; /* areas of this frame's schedule */
    uint32_t pixels_done; /* pixels in the frame memory */
    uint32_t pixels_total;/* pixels of the frame */
};

/* CMD_RENDER result. */
#define LINK_RENDER_STATS_SIZE 128
struct link_render_stats {
    uint32_t frame, ncs, areas;
    uint32_t prepare_ms;   /* the DM preparing this frame (0: prepared while
                              the previous frame rendered) */
    uint32_t render_ms;    /* the RC's broadcast to the last pixel in the FM */
    uint64_t primary, shadow, reflection, refraction, transmission; /* rays */
    uint64_t box_tests, prim_tests, primary_prim_tests;
    uint32_t precision_lost_pixels;
    uint32_t dm_high, rc_high;  /* private memory high-water marks, bytes */
    uint32_t nc_high_max;       /* the largest NC high-water mark */
    uint32_t nc_private;        /* each NC's private memory, bytes */
    uint32_t blob_bytes;        /* the prepared frame broadcast to the NCs */
    uint32_t dc_full_waits;     /* times an NC found the DC FIFO full */
    uint32_t escalated_pixels;  /* pixels traced again in the wide arithmetic
                                   (LINK_RENDER_ESCALATE) */
    uint64_t primary_hit;       /* camera rays that hit something */
    uint32_t flags;             /* the flags the frame rendered with: those asked,
                                   less LINK_RENDER_ESCALATE when the scene's wide
                                   copy did not fit the DM's IMSU block beside it */
};

/* CMD_FRAME_PULL result: u16 width, u16 height, u32 crc (of the r,g,b
 * bytes on the serial path, of the frame memory's words on the shared
 * path). */
#define LINK_FRAME_INFO_SIZE 8
/* Bytes per pixel of the frame memory as the shared path carries it. */
#define LINK_FRAME_WORD_SIZE 4

/* One pixel of the frame memory on the shared path (a little-endian u32
 * 0x00RRGGBB) into r, g, b bytes. */
static inline void link_frame_word_rgb(const uint8_t *word, uint8_t *rgb)
{
    uint32_t v = wire_get_u32(word);
    rgb[0] = (uint8_t)(v >> 16);
    rgb[1] = (uint8_t)(v >> 8);
    rgb[2] = (uint8_t)v;
}

static inline void link_scene_info_put(uint8_t *p, const struct link_scene_info *s)
{
    wire_put_u16(p, s->width);
    wire_put_u16(p + 2, s->height);
    wire_put_u32(p + 4, s->frames);
    wire_put_u32(p + 8, s->compiled_bytes);
    wire_put_u32(p + 12, s->blob_bytes);
    wire_put_u32(p + 16, s->blob_limit);
    wire_put_u32(p + 20, s->check_ms);
    wire_put_u32(p + 24, s->load_ms);
    wire_put_u32(p + 28, s->prepare_ms);
    wire_put_u32(p + 32, s->prims);
}
static inline void link_scene_info_get(const uint8_t *p, struct link_scene_info *s)
{
    s->width = wire_get_u16(p);
    s->height = wire_get_u16(p + 2);
    s->frames = wire_get_u32(p + 4);
    s->compiled_bytes = wire_get_u32(p + 8);
    s->blob_bytes = wire_get_u32(p + 12);
    s->blob_limit = wire_get_u32(p + 16);
    s->check_ms = wire_get_u32(p + 20);
    s->load_ms = wire_get_u32(p + 24);
    s->prepare_ms = wire_get_u32(p + 28);
    s->prims = wire_get_u32(p + 32);
}

static inline void link_render_args_put(uint8_t *p, const struct link_render_args *a)
{
    wire_put_u32(p, a->frame);
    wire_put_u8(p + 4, a->balance);
    wire_put_u8(p + 5, a->flags);
    wire_put_u8(p + 6, a->guided);
    wire_put_u8(p + 7, a->clip);
    wire_put_u32(p + 8, a->areas);
    wire_put_u16(p + 12, a->row0);
    wire_put_u16(p + 14, a->rows);
}
static inline void link_render_args_get(const uint8_t *p, struct link_render_args *a)
{
    a->frame = wire_get_u32(p);
    a->balance = wire_get_u8(p + 4);
    a->flags = wire_get_u8(p + 5);
    a->guided = wire_get_u8(p + 6);
    a->clip = wire_get_u8(p + 7);
    a->areas = wire_get_u32(p + 8);
    a->row0 = wire_get_u16(p + 12);
    a->rows = wire_get_u16(p + 14);
}

static inline void link_progress_put(uint8_t *p, const struct link_progress *g)
{
    wire_put_u32(p, g->frame);
    wire_put_u32(p + 4, g->areas_done);
    wire_put_u32(p + 8, g->areas_total);
    wire_put_u32(p + 12, g->pixels_done);
    wire_put_u32(p + 16, g->pixels_total);
}
static inline void link_progress_get(const uint8_t *p, struct link_progress *g)
{
    g->frame = wire_get_u32(p);
    g->areas_done = wire_get_u32(p + 4);
    g->areas_total = wire_get_u32(p + 8);
    g->pixels_done = wire_get_u32(p + 12);
    g->pixels_total = wire_get_u32(p + 16);
}

static inline void link_render_stats_put(uint8_t *p, const struct link_render_stats *s)
{
    const uint32_t a[5] = {s->frame, s->ncs, s->areas, s->prepare_ms, s->render_ms};
    const uint64_t r[8] = {s->primary, s->shadow, s->reflection, s->refraction,
                           s->transmission, s->box_tests, s->prim_tests, s->primary_prim_tests};
    const uint32_t b[8] = {s->precision_lost_pixels, s->dm_high, s->rc_high, s->nc_high_max,
                           s->nc_private, s->blob_bytes, s->dc_full_waits, s->escalated_pixels};
    for (int i = 0; i < 5; i++)
        wire_put_u32(p + 4 * i, a[i]);
    for (int i = 0; i < 8; i++)
        wire_put_u64(p + 20 + 8 * i, r[i]);
    for (int i = 0; i < 8; i++)
        wire_put_u32(p + 84 + 4 * i, b[i]);
    wire_put_u64(p + 116, s->primary_hit);
    wire_put_u32(p + 124, s->flags);
}
static inline void link_render_stats_get(const uint8_t *p, struct link_render_stats *s)
{
    uint32_t *a[5] = {&s->frame, &s->ncs, &s->areas, &s->prepare_ms, &s->render_ms};
    uint64_t *r[8] = {&s->primary, &s->shadow, &s->reflection, &s->refraction,
                      &s->transmission, &s->box_tests, &s->prim_tests, &s->primary_prim_tests};
    uint32_t *b[8] = {&s->precision_lost_pixels, &s->dm_high, &s->rc_high, &s->nc_high_max,
                      &s->nc_private, &s->blob_bytes, &s->dc_full_waits, &s->escalated_pixels};
    for (int i = 0; i < 5; i++)
        *a[i] = wire_get_u32(p + 4 * i);
    for (int i = 0; i < 8; i++)
        *r[i] = wire_get_u64(p + 20 + 8 * i);
    for (int i = 0; i < 8; i++)
        *b[i] = wire_get_u32(p + 84 + 4 * i);
    s->primary_hit = wire_get_u64(p + 116);
    s->flags = wire_get_u32(p + 124);
}

#endif
