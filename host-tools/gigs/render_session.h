/* render_session.h: the rendering commands of the host link, host side
 * (proto/render_link.h): upload a compiled scene, render a frame while
 * showing progress, pull the frame memory.  Each returns 0, or -1 after
 * printing what went wrong (the board's own text when it refused). */
#ifndef LINKS1_HOST_RENDER_SESSION_H
#define LINKS1_HOST_RENDER_SESSION_H

#include <stddef.h>
#include <stdint.h>

#include "host-tools/link/board.h"
#include "host-tools/image/image_io.h"
#include "proto/render_link.h"

/* links1 render: NCs when --ncs is not given (a 10-core board), and the
 * most milliseconds the board may stay silent while a frame renders (no
 * progress frame, no result) before the host gives up: one area of a big
 * scene on one NC can take minutes under emulation. */
#define RENDER_DEFAULT_NCS 8
#define RENDER_SILENCE_MS (20 * 60 * 1000)
/* How often the terminal's progress line is redrawn at most. */
#define RENDER_PROGRESS_REDRAW_MS 250
/* Characters of the progress line's bar. */
#define RENDER_PROGRESS_BAR 30

/* CMD_SCENE_LOAD and the scene's bytes, on the path b->opts.link names
 * (the shared RAM, or one DATA transfer).  *upload_ms: from the command to
 * the board's ACK of the last bytes (before its checks of the scene);
 * *load_ms: from then to the DM's answer (the scene checked and loaded,
 * frame 0 prepared). */
int render_session_load(struct board *b, const uint8_t *scene, size_t len,
                        struct link_scene_info *info, long long *upload_ms, long long *load_ms);

/* CMD_RENDER; with progress set, a progress line on stderr (areas done of
 * total, elapsed, estimate) while the board renders.  plan: plan_len bytes
 * of fault plan (proto/render_link.h) sent after the arguments, or NULL.
 * fails: what the frame lost and got back (all 0 if nothing). */
int render_session_frame(struct board *b, const struct link_render_args *a, int progress,
                         const uint8_t *plan, size_t plan_len, struct link_render_stats *stats,
                         struct link_render_fails *fails);

/* CMD_FRAME_PULL of the width x height frame (the scene's, as its upload
 * said) on the path b->opts.link names, into img (malloc'ed; image_free
 * it); *pull_ms: from the command to the checked result.  No more than the
 * frame's own bytes are taken: a board that sends more is refused at the
 * first byte beyond. */
int render_session_pull(struct board *b, int width, int height, struct image *img,
                        long long *pull_ms);

#endif
