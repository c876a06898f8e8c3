/* scene_board.c: the board's memory for a compiled scene (scene_board.h). */
#include "host-tools/scene/scene_board.h"

#include <stdio.h>
#include <stdlib.h>

#include "proto/board_map.h"
#include "proto/machines.h"
#include "render/blob.h"
#include "render/clip.h"
#include "render/scene_load.h"

int sd_board_bytes(const uint8_t *buf, size_t len, struct sd_board_bytes *out, char *err,
                   size_t errlen)
{
    render_blob_error_t berr;
    scene_t shape;
    uint32_t texels;
    scene_load_error_t lerr;
    if (render_blob_bytes_layout(buf, len, &render_layout_board, &out->blob, &berr) !=
            RENDER_BLOB_OK ||
        scene_load_shape(buf, len, &shape, &texels, &lerr) != SCENE_LOAD_OK) {
        snprintf(err, errlen, "%s", berr.message);
        return -1;
    }
    out->prims = shape.prim_count;
    out->clusters = shape.cluster_count;
    render_frame_t frame = {.cluster_count = shape.cluster_count, .width = shape.width,
                            .options = shape.options};
    out->nc_working = render_clip_bytes(&frame);
    return 0;
}

int sd_board_check(const uint8_t *buf, size_t len, size_t limit, char *err, size_t errlen)
{
    struct sd_board_bytes b;
    char why[8];
    if (sd_board_bytes(buf, len, &b, why, sizeof why) != 0 || b.blob <= limit)
        return 0;
    snprintf(err, errlen,
             "the scene needs %zu bytes of board memory for its prepared frame (%u primitives, "
             "%u clusters), more than the %zu bytes of %s",
             b.blob, b.prims, b.clusters, limit, BOARD_IMSU_BLOCK_NAME);
    return -1;
}

/* What an NC needs besides its clip lists: its tasks' stacks and the
 * pixels of an area (kernel/param.h: TASKS_PER_CORE stacks of 16 KiB). */
#define SD_NC_FIXED_BYTES (128u * 1024u)

int sd_machine_check(const uint8_t *buf, size_t len, int machine, char *err, size_t errlen)
{
    const struct machine_limits *m = machine_limits(machine);
    struct sd_board_bytes b;
    char why[8];
    if (!m || sd_board_bytes(buf, len, &b, why, sizeof why) != 0)
        return 0;
    if (b.blob > m->blob_bytes) {
        snprintf(err, errlen,
                 "the scene needs %zu bytes of board memory for its prepared frame (%u "
                 "primitives, %u clusters), more than the %zu bytes of %s on the %s machine",
                 b.blob, b.prims, b.clusters, m->blob_bytes, m->blob_name, m->name);
        return -1;
    }
    if (m->nc_bytes && b.nc_working + SD_NC_FIXED_BYTES > m->nc_bytes) {
        snprintf(err, errlen,
                 "each NC needs %zu bytes for the scene's clip lists (%u clusters) and %u for "
                 "its stacks and pixels, more than the %zu bytes of %s on the %s machine",
                 b.nc_working, b.clusters, SD_NC_FIXED_BYTES, m->nc_bytes, m->nc_name, m->name);
        return -1;
    }
    return 0;
}

int sd_extent_bits(const uint8_t *buf, size_t len, uint32_t *bits, char *err, size_t errlen)
{
    scene_t shape;
    uint32_t texels;
    scene_load_error_t e;
    if (scene_load_shape_before_load(buf, len, &shape, &texels, &e) != SCENE_LOAD_OK) {
        snprintf(err, errlen, "the compiled form: %s", e.message);
        return -1;
    }
    size_t bytes = 2 * sizeof(int32_t) * ((size_t)shape.cluster_count + 1) + 4 * ARENA_MAX_ALIGN;
    void *mem = malloc(bytes);
    if (!mem) {
        snprintf(err, errlen, "out of memory compiling the scene");
        return -1;
    }
    arena_t arena;
    arena_init(&arena, mem, bytes);
    scene_load_status_t st = scene_load_triangle_exp(buf, len, &arena, bits, &e);
    free(mem);
    if (st != SCENE_LOAD_OK)
        snprintf(err, errlen, "the compiled form: %s", e.message);
    return st == SCENE_LOAD_OK ? 0 : -1;
}
