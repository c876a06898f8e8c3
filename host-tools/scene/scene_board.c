/* scene_board.c: the board's memory for a compiled scene (scene_board.h). */
#include "host-tools/scene/scene_board.h"

#include <stdio.h>

#include "proto/board_map.h"
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
    render_frame_t frame = {.cluster_count = shape.cluster_count};
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
