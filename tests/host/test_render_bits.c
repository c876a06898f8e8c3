/* test_render_bits.c: one CRC-32 line per rendered image, so the same
 * renderer built for the host and for the board's CPU (run under QEMU with
 * semihosting) can be compared bit for bit.  tests/bench/check_arm_bits.sh builds
 * it with the compiled scenes embedded (bits_scenes.h, generated) and
 * compares the lines.  Images are rendered at BITS_WIDTH x BITS_HEIGHT (the
 * scene's camera, a smaller frame) to keep emulated runs short.  Each scene
 * is rendered twice: plainly, and relocated to another block and rendered
 * by areas with screen clipping; both lines must carry the same CRC. */
#include <stdint.h>
#include <stdio.h>

#include "proto/crc32.h"
#include "render/clip.h"
#include "render/relocate.h"
#include "render/render.h"
#include "render/scene_load.h"

#include "bits_scenes.h"

#define BITS_WIDTH 96
#define BITS_HEIGHT 72

#define BITS_AREA_W 16 /* the NC's way: areas of 16x8 pixels */
#define BITS_AREA_H 8
#define BITS_COPY_BYTES (1 << 20)

static _Alignas(RENDER_RELOCATE_ALIGN) uint8_t bits_memory[24 << 20];
static _Alignas(RENDER_RELOCATE_ALIGN) uint8_t bits_copy[BITS_COPY_BYTES];
static rgb8_t bits_row[BITS_WIDTH];
static rgb8_t bits_image[BITS_WIDTH * BITS_HEIGHT];
static uint16_t bits_clip_memory[2 * 1024];

/* The board's way: the scene and frame copied to another block and
 * relocated (the RC's broadcast), the original wrecked, then every area
 * rendered with Y and X clipping (an NC).  Prints "NAME/area" with the
 * image's CRC, which must equal the plain render's. */
static void bits_render_area(const char *name, const scene_t *scene, const render_frame_t *frame,
                             size_t used)
{
    if (used > BITS_COPY_BYTES) {
        printf("%s/area: blob of %lu bytes over BITS_COPY_BYTES\n", name, (unsigned long)used);
        return;
    }
    for (size_t i = 0; i < used; i++)
        bits_copy[i] = bits_memory[i];
    const char *bad;
    render_frame_t *moved = (render_frame_t *)frame;
    if (render_relocate(bits_copy, used, (uintptr_t)bits_memory, &scene, &moved, &bad) != RENDER_OK) {
        printf("%s/area: relocation refused: %s\n", name, bad);
        return;
    }
    for (size_t i = 0; i < used; i++)
        bits_memory[i] = 0xA5;
    render_clip_t clip;
    if (render_clip_init(&clip, moved, bits_clip_memory, sizeof bits_clip_memory) != RENDER_OK) {
        printf("%s/area: clipping working set over bits_clip_memory\n", name);
        return;
    }
    render_ctx_t ctx;
    render_ctx_init(&ctx, moved);
    render_clip_options_t opt = {1, 1, NULL, 0};
    static rgb8_t tile[BITS_AREA_W * BITS_AREA_H];
    for (uint32_t y = 0; y < BITS_HEIGHT; y += BITS_AREA_H)
        for (uint32_t x = 0; x < BITS_WIDTH; x += BITS_AREA_W) {
            render_area_t a = {x, y, BITS_AREA_W, BITS_AREA_H}; /* 96x72 is a whole number of them */
            if (render_area(&ctx, &clip, &a, &opt, tile) != RENDER_OK) {
                printf("%s/area: area refused\n", name);
                return;
            }
            for (uint32_t r = 0; r < a.h; r++)
                for (uint32_t c = 0; c < a.w; c++)
                    bits_image[(y + r) * BITS_WIDTH + x + c] = tile[r * a.w + c];
        }
    uint32_t crc = crc32_update(0, bits_image, sizeof bits_image);
    printf("%s %s/area %ux%u crc %08lx rays %lu\n", NUM_NAME, name, BITS_WIDTH, BITS_HEIGHT, (unsigned long)crc,
           (unsigned long)(ctx.stats.primary + ctx.stats.shadow + ctx.stats.reflection + ctx.stats.refraction +
                           ctx.stats.transmission));
}

static void bits_render(const char *name, const uint8_t *data, size_t len)
{
    arena_t arena;
    arena_init(&arena, bits_memory, sizeof bits_memory);
    /* the scene_t in the arena too, so the arena is a self-contained blob */
    scene_t *scene = ARENA_NEW_ARRAY(&arena, scene_t, 1);
    scene_load_error_t err;
    if (scene_load(data, len, &arena, scene, &err) != SCENE_LOAD_OK) {
        printf("%s: load failed: %s\n", name, err.message);
        return;
    }
    scene->width = BITS_WIDTH;
    scene->height = BITS_HEIGHT;
    render_frame_t *frame;
    render_status_t st = render_prepare(scene, 0, &arena, &frame);
    if (st != RENDER_OK) {
        printf("%s: %s\n", name, render_status_name(st));
        return;
    }
    render_ctx_t ctx;
    render_ctx_init(&ctx, frame);
    uint32_t crc = 0;
    for (uint32_t y = 0; y < BITS_HEIGHT; y++) {
        render_span(&ctx, y, 0, BITS_WIDTH, bits_row);
        crc = crc32_update(crc, bits_row, sizeof bits_row);
    }
    printf("%s %s %ux%u crc %08lx rays %lu\n", NUM_NAME, name, BITS_WIDTH, BITS_HEIGHT, (unsigned long)crc,
           (unsigned long)(ctx.stats.primary + ctx.stats.shadow + ctx.stats.reflection + ctx.stats.refraction +
                           ctx.stats.transmission));
    bits_render_area(name, scene, frame, arena.used);
}

#if defined(__arm__)
/* Semihosting SYS_EXIT (0x18) with ADP_Stopped_ApplicationExit: ends QEMU. */
static void bits_exit(void)
{
    register int r0 __asm__("r0") = 0x18;
    register int r1 __asm__("r1") = 0x20026;
    __asm__ volatile("svc 0xab" : : "r"(r0), "r"(r1) : "memory");
}
#else
static void bits_exit(void) {}
#endif

int main(void)
{
    for (size_t i = 0; i < sizeof bits_scenes / sizeof bits_scenes[0]; i++)
        bits_render(bits_scenes[i].name, bits_scenes[i].data, bits_scenes[i].len);
    fflush(stdout);
    bits_exit();
    return 0;
}
