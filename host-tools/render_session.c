/* render_session.c: the rendering commands, host side (see render_session.h). */
#include "host-tools/render_session.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "proto/crc32.h"
#include "proto/wire.h"

/* Waits for one ACK of the frames in flight (oldest first) and drops those
 * it covers. */
static int render_session_take_ack(struct board *b, uint16_t *inflight, int *n)
{
    struct board_frame f;
    if (board_wait_frame(b, LINK_ACK, BOARD_FRAME_TIMEOUT_MS, &f, "ACK of a scene DATA frame") < 0)
        return -1;
    uint16_t acked = f.length == LINK_ACK_SIZE ? wire_get_u16(f.payload) : 0;
    int k = 0;
    while (k < *n && inflight[k] != acked)
        k++;
    if (f.length != LINK_ACK_SIZE || k == *n) {
        fprintf(stderr, "links1: bad ACK during the scene upload (%u bytes, seq %u)\n",
                f.length, acked);
        return -1;
    }
    k++;
    memmove(inflight, inflight + k, (size_t)(*n - k) * sizeof *inflight);
    *n -= k;
    return 0;
}

/* The result of cmd: 0 with *fields and *n set on LINK_OK; -1 after printing the
 * board's text otherwise. */
static int render_session_result(struct board *b, uint16_t cmd, const char *what,
                                 struct board_frame *f, const uint8_t **fields, size_t *n,
                                 size_t want, int timeout_ms)
{
    int status;
    if (board_wait_result(b, cmd, timeout_ms, f, &status, fields, n) < 0)
        return -1;
    if (status != LINK_OK) {
        fprintf(stderr, "links1: %s: the board says: %.*s (%s)\n", what, (int)*n,
                (const char *)*fields, board_status_name(status));
        return -1;
    }
    if (*n < want) {
        fprintf(stderr, "links1: %s: result of %zu bytes, want %zu\n", what, *n, want);
        return -1;
    }
    return 0;
}

int render_session_load(struct board *b, const uint8_t *scene, size_t len,
                        struct link_scene_info *info)
{
    uint8_t args[LINK_SCENE_LOAD_ARGS_SIZE];
    wire_put_u32(args, (uint32_t)len);
    if (board_send_cmd(b, CMD_SCENE_LOAD, args, sizeof args) < 0)
        return -1;
    uint16_t inflight[LINK_DATA_WINDOW];
    int n = 0;
    for (size_t off = 0; off < len;) {
        size_t k = len - off < LINK_DATA_CHUNK ? len - off : LINK_DATA_CHUNK;
        while (n >= LINK_DATA_WINDOW)
            if (render_session_take_ack(b, inflight, &n) < 0)
                return -1;
        int seq = board_send(b, LINK_DATA, off + k == len ? LINK_FLAG_LAST : 0, scene + off, k);
        if (seq < 0)
            return -1;
        inflight[n++] = (uint16_t)seq;
        off += k;
    }
    while (n > 0)
        if (render_session_take_ack(b, inflight, &n) < 0)
            return -1;
    struct board_frame f;
    const uint8_t *fields;
    size_t nf;
    /* the DM answers once it has loaded the scene and prepared frame 0: a
     * big scene keeps it silent as long as preparing a frame may */
    if (render_session_result(b, CMD_SCENE_LOAD, "scene upload", &f, &fields, &nf,
                              LINK_SCENE_INFO_SIZE, RENDER_SILENCE_MS) < 0)
        return -1;
    link_scene_info_get(fields, info);
    return 0;
}

/* Takes the first queued PROGRESS or RESULT frame into out; 1 if one was
 * there, 0 if none. */
static int render_session_take(struct board *b, struct board_frame *out)
{
    for (int i = 0; i < b->queued; i++) {
        if (b->queue[i].type != LINK_PROGRESS && b->queue[i].type != LINK_RESULT)
            continue;
        *out = b->queue[i];
        memmove(&b->queue[i], &b->queue[i + 1], (size_t)(b->queued - i - 1) * sizeof b->queue[0]);
        b->queued--;
        return 1;
    }
    return 0;
}

static void render_session_show(const struct link_progress *g, long long t0, int final)
{
    double s = (double)(board_now_ms() - t0) / 1000.0;
    double left = g->areas_done ? s * (g->areas_total - g->areas_done) / g->areas_done : 0;
    fprintf(stderr, "\rframe %u: %u of %u areas, %.1f s elapsed, about %.1f s left   %s",
            g->frame, g->areas_done, g->areas_total, s, left, final ? "\n" : "");
    fflush(stderr);
}

int render_session_frame(struct board *b, const struct link_render_args *a, int progress,
                         struct link_render_stats *stats)
{
    uint8_t args[LINK_RENDER_ARGS_SIZE];
    link_render_args_put(args, a);
    if (board_send_cmd(b, CMD_RENDER, args, sizeof args) < 0)
        return -1;
    long long t0 = board_now_ms(), heard = t0, drawn = 0;
    struct link_progress last = {a->frame, 0, 0};
    for (;;) {
        struct board_frame f;
        if (!render_session_take(b, &f)) {
            if (board_now_ms() - heard > RENDER_SILENCE_MS) {
                fprintf(stderr, "\nlinks1: frame %u: the board said nothing for %d s "
                        "(RENDER_SILENCE_MS)\n", a->frame, RENDER_SILENCE_MS / 1000);
                return -1;
            }
            if (board_pump(b, RENDER_PROGRESS_REDRAW_MS) < 0) {
                fprintf(stderr, "\nlinks1: frame %u: the board stopped while rendering\n",
                        a->frame);
                return -1;
            }
            continue;
        }
        heard = board_now_ms();
        if (f.type == LINK_PROGRESS && f.length >= LINK_PROGRESS_SIZE) {
            link_progress_get(f.payload, &last);
            if (progress && heard - drawn >= RENDER_PROGRESS_REDRAW_MS) {
                render_session_show(&last, t0, 0);
                drawn = heard;
            }
            continue;
        }
        if (f.type != LINK_RESULT || f.length < LINK_RESULT_FIXED_SIZE ||
            wire_get_u16(f.payload) != CMD_RENDER) {
            fprintf(stderr, "\nlinks1: frame %u: unexpected frame type %u while rendering\n",
                    a->frame, f.type);
            return -1;
        }
        if (progress && last.areas_total)
            render_session_show(&last, t0, 1);
        int status = (int16_t)wire_get_u16(f.payload + 2);
        const uint8_t *fields = f.payload + LINK_RESULT_FIXED_SIZE;
        size_t n = f.length - LINK_RESULT_FIXED_SIZE;
        if (status != LINK_OK) {
            fprintf(stderr, "links1: frame %u: the board says: %.*s (%s)\n", a->frame, (int)n,
                    (const char *)fields, board_status_name(status));
            return -1;
        }
        if (n < LINK_RENDER_STATS_SIZE) {
            fprintf(stderr, "links1: frame %u: render result of %zu bytes, want %d\n",
                    a->frame, n, LINK_RENDER_STATS_SIZE);
            return -1;
        }
        link_render_stats_get(fields, stats);
        return 0;
    }
}

int render_session_pull(struct board *b, struct image *img)
{
    if (board_send_cmd(b, CMD_FRAME_PULL, NULL, 0) < 0)
        return -1;
    size_t cap = 0, have = 0;
    uint8_t *buf = NULL;
    uint32_t crc = 0;
    for (;;) {
        struct board_frame f;
        if (board_wait_frame(b, LINK_DATA, BOARD_FRAME_TIMEOUT_MS, &f, "frame memory DATA") < 0) {
            free(buf);
            return -1;
        }
        if (have + f.length > cap) {
            cap = cap ? 2 * cap + f.length : 1u << 20;
            uint8_t *nb = realloc(buf, cap);
            if (!nb) {
                fprintf(stderr, "links1: out of memory for the frame\n");
                free(buf);
                return -1;
            }
            buf = nb;
        }
        memcpy(buf + have, f.payload, f.length);
        have += f.length;
        crc = crc32_update(crc, f.payload, f.length);
        uint8_t ack[LINK_ACK_SIZE];
        wire_put_u16(ack, f.seq);
        if (board_send(b, LINK_ACK, 0, ack, sizeof ack) < 0) {
            free(buf);
            return -1;
        }
        if (f.flags & LINK_FLAG_LAST)
            break;
    }
    struct board_frame f;
    const uint8_t *fields;
    size_t nf;
    if (render_session_result(b, CMD_FRAME_PULL, "frame pull", &f, &fields, &nf,
                              LINK_FRAME_INFO_SIZE, BOARD_FRAME_TIMEOUT_MS) < 0) {
        free(buf);
        return -1;
    }
    int w = wire_get_u16(fields), h = wire_get_u16(fields + 2);
    if ((size_t)w * (size_t)h * 3 != have || wire_get_u32(fields + 4) != crc) {
        fprintf(stderr, "links1: frame pull: %zu bytes with crc 0x%08x, the board says %dx%d "
                "pixels with crc 0x%08x\n", have, crc, w, h, wire_get_u32(fields + 4));
        free(buf);
        return -1;
    }
    img->width = w;
    img->height = h;
    img->rgb = buf;
    return 0;
}
