/* seed_frames.c: writes the seed inputs of fuzz_hostlink into a directory:
 * byte streams of host-link frames made with the one encoder
 * (proto/hostlink.c) and the payload put functions, as the board and the
 * host send them.  Usage: seed_frames DIR */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "proto/hostlink.h"
#include "proto/render_link.h"
#include "proto/wire.h"

static uint8_t stream[8 * LINK_MAX_FRAME];
static size_t used;
static uint16_t seq;

static void add(uint8_t type, uint8_t flags, const void *payload, size_t len)
{
    size_t n = link_frame_encode(stream + used, sizeof stream - used, type, flags, seq++,
                                 payload, len);
    if (n == 0) {
        fprintf(stderr, "seed_frames: stream full\n");
        exit(1);
    }
    used += n;
}

static void save(const char *dir, const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(stream, 1, used, f) != used || fclose(f) != 0) {
        fprintf(stderr, "seed_frames: cannot write %s\n", path);
        exit(1);
    }
    used = 0;
    seq = 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: seed_frames DIR\n");
        return 2;
    }
    const char *dir = argv[1];
    uint8_t p[LINK_MAX_PAYLOAD];

    /* a board reporting in: a byte of the ncores the harness takes from byte 0 */
    struct link_hello h = {0, ROLE_DM, 1, 0x80000000u, 4, 0};
    for (uint16_t c = 0; c < 4; c++) {
        h.core = c;
        h.role = c >= ROLE_NC ? ROLE_NC : (uint8_t)c;
        h.mpidr = 0x80000000u | c;
        link_hello_put(p, &h);
        add(LINK_HELLO, 0, p, LINK_HELLO_SIZE);
    }
    add(LINK_LOG, 0, "links1 firmware up\nsecond line", 30);
    save(dir, "hello");

    struct link_fault ft = {3, ROLE_NC, FAULT_DATA_ABORT, 0xdead0000u, 0x40001234u, 0x805};
    link_fault_put(p, &ft);
    memcpy(p + LINK_FAULT_FIXED_SIZE, "data abort in the NC", 20);
    add(LINK_FAULT, 0, p, LINK_FAULT_FIXED_SIZE + 20);
    save(dir, "fault");

    /* a command answered, a dropped-frame report, a transfer */
    wire_put_u16(p, CMD_STATUS);
    wire_put_u16(p + 2, LINK_OK);
    struct link_status_result st = {4, 4, 0};
    link_status_result_put(p + LINK_RESULT_FIXED_SIZE, &st);
    add(LINK_RESULT, 0, p, LINK_RESULT_FIXED_SIZE + LINK_STATUS_RESULT_SIZE);
    wire_put_u16(p, 0);
    wire_put_u16(p + 2, (uint16_t)LINK_ERR_BAD_FRAME);
    memcpy(p + LINK_RESULT_FIXED_SIZE, "host link: frame dropped", 24);
    add(LINK_RESULT, 0, p, LINK_RESULT_FIXED_SIZE + 24);
    for (int i = 0; i < LINK_DATA_CHUNK; i++)
        p[i] = link_pattern_byte((uint32_t)i);
    add(LINK_DATA, 0, p, LINK_DATA_CHUNK);
    add(LINK_DATA, LINK_FLAG_LAST, p, 100);
    wire_put_u16(p, 6);
    add(LINK_ACK, 0, p, LINK_ACK_SIZE);
    save(dir, "transfer");

    /* rendering: progress, the scene info and the render statistics */
    struct link_progress g = {0, 3, 16, 4800, 76800};
    link_progress_put(p, &g);
    add(LINK_PROGRESS, 0, p, LINK_PROGRESS_SIZE);
    wire_put_u16(p, CMD_SCENE_LOAD);
    wire_put_u16(p + 2, LINK_OK);
    struct link_scene_info si = {.width = 320, .height = 240, .frames = 1, .compiled_bytes = 812,
                                 .blob_bytes = 90000, .blob_limit = 8u << 20};
    link_scene_info_put(p + LINK_RESULT_FIXED_SIZE, &si);
    add(LINK_RESULT, 0, p, LINK_RESULT_FIXED_SIZE + LINK_SCENE_INFO_SIZE);
    struct link_render_stats rs;
    memset(&rs, 0, sizeof rs);
    rs.ncs = 8;
    rs.areas = 16;
    rs.primary = 76800;
    wire_put_u16(p, CMD_RENDER);
    link_render_stats_put(p + LINK_RESULT_FIXED_SIZE, &rs);
    add(LINK_RESULT, 0, p, LINK_RESULT_FIXED_SIZE + LINK_RENDER_STATS_SIZE);
    save(dir, "render");

    /* noise: junk, a frame cut short, a frame with a bad CRC, then a good one */
    memcpy(stream, "junkL1", 6);
    used = 6;
    add(LINK_LOG, 0, "cut", 3);
    used -= 2;
    add(LINK_LOG, 0, "bad crc", 7);
    stream[used - 1] ^= 0x5a;
    add(LINK_LOG, 0, "good", 4);
    save(dir, "noise");

    /* the host's side: commands with their arguments */
    wire_put_u16(p, CMD_SCENE_LOAD);
    wire_put_u32(p + LINK_CMD_FIXED_SIZE, 812);
    add(LINK_CMD, 0, p, LINK_CMD_FIXED_SIZE + LINK_SCENE_LOAD_ARGS_SIZE);
    struct link_render_args ra = {.frame = 0, .balance = LINK_BALANCE_DYNAMIC,
                                  .flags = LINK_RENDER_PREPARE_NEXT, .areas = 64};
    wire_put_u16(p, CMD_RENDER);
    link_render_args_put(p + LINK_CMD_FIXED_SIZE, &ra);
    add(LINK_CMD, 0, p, LINK_CMD_FIXED_SIZE + LINK_RENDER_ARGS_SIZE);
    save(dir, "commands");
    return 0;
}
