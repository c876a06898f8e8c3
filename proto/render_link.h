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

#include "proto/wire.h"

/* CMD_SCENE_LOAD arguments: u32 bytes of the compiled scene that follow. */
#define LINK_SCENE_LOAD_ARGS_SIZE 4

/* CMD_SCENE_LOAD result. */
#define LINK_SCENE_INFO_SIZE 20
struct link_scene_info {
    uint16_t width, height;  /* image size */
    uint32_t frames;         /* frames of the animation */
    uint32_t compiled_bytes; /* bytes received */
    uint32_t blob_bytes;     /* bound of one prepared frame (render_blob_bytes) */
    uint32_t blob_limit;     /* the IMSU block it must fit in */
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
};
#define LINK_RENDER_FLAGS_ALL 0x3Fu

/* Balancing modes: the values of proto/areas.h enum areas_mode. */
enum link_balance { LINK_BALANCE_STATIC = 0, LINK_BALANCE_DYNAMIC = 1, LINK_BALANCE_DECREASING = 2 };

/* CMD_RENDER arguments. */
#define LINK_RENDER_ARGS_SIZE 12
struct link_render_args {
    uint32_t frame;   /* frame index, 0 .. frames-1 */
    uint8_t balance;  /* enum link_balance */
    uint8_t flags;    /* enum link_render_flag */
    uint32_t areas;   /* K: areas of the dynamic grid / smallest-area bound of
                         the decreasing schedule; 0 = the board's default */
};

/* LINK_PROGRESS payload. */
#define LINK_PROGRESS_SIZE 12
struct link_progress {
    uint32_t frame;
    uint32_t areas_done;  /* areas finished (their pixels sent to the DC) */
    uint32_t areas_total; /* areas of this frame's schedule */
};

/* CMD_RENDER result. */
#define LINK_RENDER_STATS_SIZE 112
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
};

/* CMD_FRAME_PULL result. */
#define LINK_FRAME_INFO_SIZE 8

static inline void link_scene_info_put(uint8_t *p, const struct link_scene_info *s)
{
    wire_put_u16(p, s->width);
    wire_put_u16(p + 2, s->height);
    wire_put_u32(p + 4, s->frames);
    wire_put_u32(p + 8, s->compiled_bytes);
    wire_put_u32(p + 12, s->blob_bytes);
    wire_put_u32(p + 16, s->blob_limit);
}
static inline void link_scene_info_get(const uint8_t *p, struct link_scene_info *s)
{
    s->width = wire_get_u16(p);
    s->height = wire_get_u16(p + 2);
    s->frames = wire_get_u32(p + 4);
    s->compiled_bytes = wire_get_u32(p + 8);
    s->blob_bytes = wire_get_u32(p + 12);
    s->blob_limit = wire_get_u32(p + 16);
}

static inline void link_render_args_put(uint8_t *p, const struct link_render_args *a)
{
    wire_put_u32(p, a->frame);
    wire_put_u8(p + 4, a->balance);
    wire_put_u8(p + 5, a->flags);
    wire_put_u16(p + 6, 0);
    wire_put_u32(p + 8, a->areas);
}
static inline void link_render_args_get(const uint8_t *p, struct link_render_args *a)
{
    a->frame = wire_get_u32(p);
    a->balance = wire_get_u8(p + 4);
    a->flags = wire_get_u8(p + 5);
    a->areas = wire_get_u32(p + 8);
}

static inline void link_progress_put(uint8_t *p, const struct link_progress *g)
{
    wire_put_u32(p, g->frame);
    wire_put_u32(p + 4, g->areas_done);
    wire_put_u32(p + 8, g->areas_total);
}
static inline void link_progress_get(const uint8_t *p, struct link_progress *g)
{
    g->frame = wire_get_u32(p);
    g->areas_done = wire_get_u32(p + 4);
    g->areas_total = wire_get_u32(p + 8);
}

static inline void link_render_stats_put(uint8_t *p, const struct link_render_stats *s)
{
    const uint32_t a[5] = {s->frame, s->ncs, s->areas, s->prepare_ms, s->render_ms};
    const uint64_t r[8] = {s->primary, s->shadow, s->reflection, s->refraction,
                           s->transmission, s->box_tests, s->prim_tests, s->primary_prim_tests};
    const uint32_t b[7] = {s->precision_lost_pixels, s->dm_high, s->rc_high, s->nc_high_max,
                           s->nc_private, s->blob_bytes, s->dc_full_waits};
    for (int i = 0; i < 5; i++)
        wire_put_u32(p + 4 * i, a[i]);
    for (int i = 0; i < 8; i++)
        wire_put_u64(p + 20 + 8 * i, r[i]);
    for (int i = 0; i < 7; i++)
        wire_put_u32(p + 84 + 4 * i, b[i]);
}
static inline void link_render_stats_get(const uint8_t *p, struct link_render_stats *s)
{
    uint32_t *a[5] = {&s->frame, &s->ncs, &s->areas, &s->prepare_ms, &s->render_ms};
    uint64_t *r[8] = {&s->primary, &s->shadow, &s->reflection, &s->refraction,
                      &s->transmission, &s->box_tests, &s->prim_tests, &s->primary_prim_tests};
    uint32_t *b[7] = {&s->precision_lost_pixels, &s->dm_high, &s->rc_high, &s->nc_high_max,
                      &s->nc_private, &s->blob_bytes, &s->dc_full_waits};
    for (int i = 0; i < 5; i++)
        *a[i] = wire_get_u32(p + 4 * i);
    for (int i = 0; i < 8; i++)
        *r[i] = wire_get_u64(p + 20 + 8 * i);
    for (int i = 0; i < 7; i++)
        *b[i] = wire_get_u32(p + 84 + 4 * i);
}

#endif
