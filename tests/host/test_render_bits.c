/* test_render_bits.c: one CRC-32 line per rendered image, so the same
 * renderer built for the host and for the board's CPU (run under QEMU with
 * semihosting) can be compared bit for bit.  render/check-arm-bits.sh builds
 * it with the compiled scenes embedded (bits_scenes.h, generated) and
 * compares the lines.  Images are rendered at BITS_WIDTH x BITS_HEIGHT (the
 * scene's camera, a smaller frame) to keep emulated runs short. */
#include <stdint.h>
#include <stdio.h>

#include "proto/crc32.h"
#include "render/render.h"
#include "render/scene_load.h"

#include "bits_scenes.h"

#define BITS_WIDTH 96
#define BITS_HEIGHT 72

static uint8_t bits_memory[24 << 20];
static rgb8_t bits_row[BITS_WIDTH];

static void bits_render(const char *name, const uint8_t *data, size_t len)
{
    arena_t arena;
    arena_init(&arena, bits_memory, sizeof bits_memory);
    scene_t scene;
    scene_load_error_t err;
    if (scene_load(data, len, &arena, &scene, &err) != SCENE_LOAD_OK) {
        printf("%s: load failed: %s\n", name, err.message);
        return;
    }
    scene.width = BITS_WIDTH;
    scene.height = BITS_HEIGHT;
    render_frame_t *frame;
    render_status_t st = render_prepare(&scene, 0, &arena, &frame);
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
