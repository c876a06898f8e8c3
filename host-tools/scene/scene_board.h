/* scene_board.h: does a compiled scene fit the board?  The host compiler
 * asks before anything is uploaded, so a scene too big for the board's
 * memory is refused when it is compiled (links1 compile, ref, render), with
 * the limit and the counts named, rather than by the DM after an upload.
 */
#ifndef LINKS1_HOST_SCENE_BOARD_H
#define LINKS1_HOST_SCENE_BOARD_H

#include <stddef.h>
#include <stdint.h>

#include "proto/board_map.h"

/* What the board's memory gives one scene: the bytes of an IMSU block
 * (proto/board_map.h), which holds the DM's loaded scene and prepared frame
 * and, copied, the NCs' broadcast. */
#define SD_BOARD_BLOB_LIMIT ((size_t)BOARD_IMSU_BLOCK_BYTES)

struct sd_board_bytes {
    size_t blob;            /* the blob the DM builds (render_blob_bytes on
                               the board's layout), scratch included */
    size_t nc_working;      /* what each NC allocates for its clip lists */
    uint32_t prims, clusters;
};

/* The board's bytes for the compiled scene buf[0..len): 0, or -1 when its
 * header or section table is refused (err says why). */
int sd_board_bytes(const uint8_t *buf, size_t len, struct sd_board_bytes *out, char *err,
                   size_t errlen);

/* 0 when the scene's blob fits limit bytes; -1 with err naming the limit
 * (BOARD_IMSU_BLOCK_NAME), the bytes and the counts when it does not.  A
 * scene whose header is refused passes: the loader names that problem. */
int sd_board_check(const uint8_t *buf, size_t len, size_t limit, char *err, size_t errlen);

/* The EXTENT section's value (proto/scene_format.h) of the compiled scene
 * buf[0..len): the triangles' exponent as the loader works it out where a
 * scene does not state it (scene_load_triangle_exp), in *bits.  0, or -1
 * with err when the header or the section table is refused. */
int sd_extent_bits(const uint8_t *buf, size_t len, uint32_t *bits, char *err, size_t errlen);

/* 0 when the scene fits machine (proto/machines.h): its blob an IMSU block,
 * its NCs' working set an NC's memory; -1 with err naming the limit, the
 * machine and the bytes when it does not. */
int sd_machine_check(const uint8_t *buf, size_t len, int machine, char *err, size_t errlen);

#endif
