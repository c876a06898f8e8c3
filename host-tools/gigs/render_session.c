/* render_session.c: the rendering commands, host side (see render_session.h). */
#include "host-tools/gigs/render_session.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/link/board_text.h"
#include "host-tools/link/link_shared.h"
#include "host-tools/link/link_transfer.h"
#include "host-tools/gigs/render_faults.h"
#include "proto/crc32.h"
#include "proto/wire.h"

/* The result of cmd: 0 with *fields and *n set on LINK_OK; -1 after printing the
 * board's text otherwise. */
static int render_session_result(struct board *b, uint16_t cmd, const char *what,
                                 struct board_frame *f, const uint8_t **fields, size_t *n,
                                 size_t want, int timeout_ms)
{
    char why[LINK_MAX_PAYLOAD + 96];
    if (board_wait_ok(b, cmd, timeout_ms, want, f, fields, n, why, sizeof why) < 0) {
        fprintf(stderr, "links1: %s: %s\n", what, why);
        return -1;
    }
    return 0;
}

int render_session_load(struct board *b, const uint8_t *scene, size_t len,
                        struct link_scene_info *info, long long *upload_ms, long long *load_ms)
{
    uint8_t args[LINK_SCENE_LOAD_ARGS_SIZE + 1];
    wire_put_u32(args, (uint32_t)len);
    args[LINK_SCENE_LOAD_ARGS_SIZE] = (uint8_t)b->opts.link;
    long long t0 = board_now_ms();
    if (board_send_cmd(b, CMD_SCENE_LOAD, args, sizeof args) < 0)
        return -1;
    /* On the shared path a refusal comes instead of the offer (r = 1): the
     * result below prints it. */
    int r = b->opts.link == LINK_PATH_SHARED ? link_shared_send(b, scene, len)
                                             : link_transfer_send(b, scene, len);
    if (r < 0)
        return -1;
    *upload_ms = board_now_ms() - t0;
    struct board_frame f;
    const uint8_t *fields;
    size_t nf;
    /* the DM answers once it has loaded the scene and prepared frame 0: a
     * big scene keeps it silent as long as preparing a frame may */
    if (render_session_result(b, CMD_SCENE_LOAD, "scene upload", &f, &fields, &nf,
                              LINK_SCENE_INFO_SIZE, RENDER_SILENCE_MS) < 0)
        return -1;
    link_scene_info_get(fields, info);
    *load_ms = board_now_ms() - t0 - *upload_ms;
    return 0;
}

/* Takes the first queued PROGRESS or RESULT frame into out; 1 if one was
 * there, 0 if none. */
static int render_session_take(struct board *b, struct board_frame *out)
{
    return board_take_queued(b, (1u << LINK_PROGRESS) | (1u << LINK_RESULT), out);
}

/* The progress line: a bar of the pixels in the frame memory, and the time
 * left estimated from them.  Pixels, not areas: with decreasing areas the
 * first few areas hold most of the pixels, so areas done says far too
 * little of the work done. */
static void render_session_show(const struct link_progress *g, long long t0, int final)
{
    double s = (double)(board_now_ms() - t0) / 1000.0;
    double part = g->pixels_total ? (double)g->pixels_done / g->pixels_total : 0;
    char bar[RENDER_PROGRESS_BAR + 1];
    int full = (int)(part * RENDER_PROGRESS_BAR);
    for (int i = 0; i < RENDER_PROGRESS_BAR; i++)
        bar[i] = i < full ? '#' : '.';
    bar[RENDER_PROGRESS_BAR] = 0;
    char left[48];
    if (final || part >= 1)
        snprintf(left, sizeof left, "done");
    else if (g->pixels_done)
        snprintf(left, sizeof left, "about %.1f s left", s * (1 - part) / part);
    else
        snprintf(left, sizeof left, "time left unknown yet");
    fprintf(stderr, "\rframe %u [%s] %3.0f%%, %u of %u areas, %.1f s, %s   %s", g->frame, bar,
            100 * part, g->areas_done, g->areas_total, s, left, final ? "\n" : "");
    fflush(stderr);
}

int render_session_frame(struct board *b, const struct link_render_args *a, int progress,
                         const uint8_t *plan, size_t plan_len, struct link_render_stats *stats,
                         struct link_render_fails *fails)
{
    uint8_t args[LINK_RENDER_ARGS_SIZE + LINK_INJECT_SIZE(LINK_INJECT_MAX)];
    link_render_args_put(args, a);
    if (plan_len > sizeof args - LINK_RENDER_ARGS_SIZE)
        plan_len = 0;
    if (plan_len)
        memcpy(args + LINK_RENDER_ARGS_SIZE, plan, plan_len);
    memset(fails, 0, sizeof *fails);
    if (board_send_cmd(b, CMD_RENDER, args, LINK_RENDER_ARGS_SIZE + plan_len) < 0)
        return -1;
    long long t0 = board_now_ms(), heard = t0, drawn = 0;
    struct link_progress last = {a->frame, 0, 0, 0, 0};
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
            int down = render_faults_unit_down(b->faults, b->nfaults < BOARD_MAX_FAULTS
                                                              ? b->nfaults : BOARD_MAX_FAULTS);
            if (down >= 0) {
                fprintf(stderr, "\nlinks1: frame %u: the %s (core %u) failed while rendering\n",
                        a->frame, unit_role_name(b->faults[down].role),
                        b->faults[down].core);
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
        if (progress && last.pixels_total)
            render_session_show(&last, t0, 1);
        int status = (int16_t)wire_get_u16(f.payload + 2);
        const uint8_t *fields = f.payload + LINK_RESULT_FIXED_SIZE;
        size_t n = f.length - LINK_RESULT_FIXED_SIZE;
        if (status != LINK_OK) {
            char text[BOARD_TEXT_CAP(LINK_MAX_PAYLOAD)];
            fprintf(stderr, "links1: frame %u: the board says: %s (%s)\n", a->frame,
                    board_text(fields, n, text, sizeof text), board_status_name(status));
            return -1;
        }
        if (n < LINK_RENDER_STATS_SIZE) {
            fprintf(stderr, "links1: frame %u: render result of %zu bytes, want %d\n",
                    a->frame, n, LINK_RENDER_STATS_SIZE);
            return -1;
        }
        link_render_stats_get(fields, stats);
        if (n > LINK_RENDER_STATS_SIZE &&
            link_render_fails_get(fields + LINK_RENDER_STATS_SIZE,
                                  (uint32_t)(n - LINK_RENDER_STATS_SIZE), fails) != 0) {
            fprintf(stderr, "links1: frame %u: the failure report of %zu bytes is cut short\n",
                    a->frame, n - LINK_RENDER_STATS_SIZE);
            return -1;
        }
        return 0;
    }
}

/* The frame memory as one DATA transfer of r,g,b bytes into *buf (want
 * bytes: the frame's own size, and not a byte more); *have bytes with CRC
 * *crc. */
static int render_session_pull_serial(struct board *b, size_t want, uint8_t **buf,
                                      size_t *have, uint32_t *crc)
{
    *buf = malloc(want ? want : 1);
    if (!*buf) {
        fprintf(stderr, "links1: out of memory for the frame\n");
        return -1;
    }
    for (;;) {
        struct board_frame f;
        if (board_wait_frame(b, LINK_DATA, BOARD_FRAME_TIMEOUT_MS, &f, "frame memory DATA") < 0)
            return -1;
        if (f.length > want - *have) {
            fprintf(stderr, "links1: frame pull: the board sent more than the frame's %zu "
                    "bytes (%zu, then a DATA frame of %u); stopped\n", want, *have, f.length);
            return -1;
        }
        memcpy(*buf + *have, f.payload, f.length);
        *have += f.length;
        *crc = crc32_update(*crc, f.payload, f.length);
        uint8_t ack[LINK_ACK_SIZE];
        wire_put_u16(ack, f.seq);
        if (board_send(b, LINK_ACK, 0, ack, sizeof ack) < 0)
            return -1;
        if (f.flags & LINK_FLAG_LAST)
            return 0;
    }
}

/* The frame memory read where it lies in the board's RAM, one u32 word per
 * pixel (want words' bytes, no other size), into *buf as r,g,b bytes.
 * r = 1: the board answered instead. */
static int render_session_pull_shared(struct board *b, size_t want, uint8_t **buf,
                                      size_t *words, uint32_t *crc)
{
    struct link_bulk k;
    const uint8_t *data;
    int r = link_shared_receive(b, &k, &data);
    if (r != 0)
        return r;
    if (k.length != want) {
        fprintf(stderr, "links1: frame pull: the board offers %u bytes of frame memory, the "
                "frame is %zu\n", k.length, want);
        return -1;
    }
    size_t px = k.length / LINK_FRAME_WORD_SIZE;
    *buf = malloc(px ? px * 3 : 1);
    if (!*buf) {
        fprintf(stderr, "links1: out of memory for the frame\n");
        return -1;
    }
    for (size_t i = 0; i < px; i++)
        link_frame_word_rgb(data + i * LINK_FRAME_WORD_SIZE, *buf + i * 3);
    *words = k.length;
    *crc = k.sum;
    return 0;
}

int render_session_pull(struct board *b, int width, int height, struct image *img,
                        long long *pull_ms)
{
    int shared = b->opts.link == LINK_PATH_SHARED;
    uint8_t arg = (uint8_t)b->opts.link;
    long long t0 = board_now_ms();
    uint8_t *buf = NULL;
    size_t have = 0; /* bytes as the board sent them */
    uint32_t crc = 0;
    int r;
    size_t per_px = shared ? LINK_FRAME_WORD_SIZE : 3;
    if (width < 1 || height < 1 || width > IMAGE_MAX_SIDE || height > IMAGE_MAX_SIDE) {
        fprintf(stderr, "links1: frame pull: a %dx%d frame\n", width, height);
        return -1;
    }
    size_t want = (size_t)width * (size_t)height * per_px;
    for (int t = 1;; t++) {
        if (board_send_cmd(b, CMD_FRAME_PULL, &arg, sizeof arg) < 0)
            return -1;
        free(buf);
        buf = NULL;
        have = 0;
        crc = 0;
        r = shared ? render_session_pull_shared(b, want, &buf, &have, &crc)
                   : render_session_pull_serial(b, want, &buf, &have, &crc);
        if (r != -2 || t == LINK_BULK_TRIES)
            break;
        /* The shared bytes did not have the board's CRC: its result, then
         * the pull again (proto/hostlink.h, LINK_BULK_TRIES). */
        struct board_frame f;
        const uint8_t *fields;
        size_t nf;
        if (render_session_result(b, CMD_FRAME_PULL, "frame pull", &f, &fields, &nf,
                                  LINK_FRAME_INFO_SIZE, BOARD_FRAME_TIMEOUT_MS) < 0)
            return -1;
        fprintf(stderr, "links1: frame pull: again (try %d of %d)\n", t + 1, LINK_BULK_TRIES);
    }
    if (r < 0) {
        free(buf);
        return -1;
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
    if (w != width || h != height || want != have || wire_get_u32(fields + 4) != crc) {
        fprintf(stderr, "links1: frame pull: %zu bytes with crc 0x%08x, the board says %dx%d "
                "pixels with crc 0x%08x\n", have, crc, w, h, wire_get_u32(fields + 4));
        free(buf);
        return -1;
    }
    img->width = w;
    img->height = h;
    img->rgb = buf;
    *pull_ms = board_now_ms() - t0;
    return 0;
}
