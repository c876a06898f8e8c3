/* fuzz_scene_load.c: libFuzzer harness of the compiled-form loader
 * (render/scene_load.c) and of what the board's DM does with an uploaded
 * scene: render_blob_bytes, render_blob_build (scene_load + render_prepare
 * of the first and the last frame), the RC's relocation after a copy, and
 * a few pixels as an NC would trace them.
 *
 * Each input is tried twice: as it is, then with its total size and word sum
 * made right, so the fuzzer also reaches the records behind the checksum. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "proto/wordsum.h"
#include "proto/scene_format.h"
#include "proto/wire.h"
#include "render/blob.h"
#include "render/scene_load.h"

#define FUZZ_BLOCK (8u * 1024u * 1024u) /* a DM block for the fuzzer's small inputs (the board's: BOARD_IMSU_BLOCK_BYTES) */

static uint8_t *fuzz_block(int which)
{
    static uint8_t *blocks[2];
    if (!blocks[which]) {
        blocks[which] = aligned_alloc(RENDER_RELOCATE_ALIGN, FUZZ_BLOCK);
        if (!blocks[which])
            abort();
    }
    return blocks[which];
}

static void fuzz_pixels(const render_blob_t *blob)
{
    render_ctx_t ctx;
    render_ctx_init(&ctx, blob->frame);
    uint32_t w = blob->scene.width, h = blob->scene.height;
    uint32_t xs[3] = {0, w / 2, w - 1}, ys[3] = {0, h / 2, h - 1};
    for (int i = 0; i < 3; i++)
        render_pixel(&ctx, xs[i], ys[i]);
}

static void fuzz_one(const uint8_t *buf, size_t len)
{
    uint8_t *block = fuzz_block(0);
    arena_t arena;
    arena_init(&arena, block, FUZZ_BLOCK);
    scene_t scene;
    scene_load_error_t lerr;
    if (scene_load(buf, len, &arena, &scene, &lerr) != SCENE_LOAD_OK) {
        if (lerr.message[0] == 0 || arena.used != 0)
            abort(); /* a refusal names its reason and leaves the arena as it was */
        return;
    }
    render_blob_error_t berr;
    size_t bound;
    if (render_blob_bytes(buf, len, &bound, &berr) != RENDER_BLOB_OK)
        abort(); /* the loader took it: the shape must be readable */
    uint32_t frames[2] = {0, scene.frame_count - 1};
    for (int f = 0; f < (scene.frame_count > 1 ? 2 : 1); f++) {
        render_blob_t *blob;
        if (render_blob_build(buf, len, frames[f], block, FUZZ_BLOCK, "the fuzz block", &blob,
                              &berr) != RENDER_BLOB_OK) {
            if (berr.message[0] == 0)
                abort();
            continue;
        }
        if (blob->bytes > bound || blob->peak > bound)
            abort(); /* render_blob_bytes is the bound the DM sizes memory by */
        uint8_t *copy = fuzz_block(1);
        memcpy(copy, block, blob->bytes);
        render_blob_t *moved;
        if (render_blob_relocate(copy, FUZZ_BLOCK, &moved, &berr) != RENDER_BLOB_OK)
            abort();
        fuzz_pixels(moved);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_one(data, size);
    if (size < SCN_HEADER_SIZE || size > SCN_MAX_SIZE)
        return 0;
    uint8_t *fixed = malloc(size);
    if (!fixed)
        abort();
    memcpy(fixed, data, size);
    wire_put_u32(fixed + SCN_HDR_TOTAL, (uint32_t)size);
    wire_put_u32(fixed + SCN_HDR_SUM, wordsum(fixed + SCN_SUM_START, size - SCN_SUM_START));
    fuzz_one(fixed, size);
    free(fixed);
    return 0;
}
