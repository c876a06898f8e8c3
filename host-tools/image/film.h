/* film.h: frames encoded into one film by the ffmpeg command (the Debian
 * package ffmpeg) as they come: each frame goes to ffmpeg's standard input
 * as a PNG (`-f image2pipe -c:v png -i -`), ffmpeg started with posix_spawnp
 * from an argument array (no shell).  The film is written whole or not at
 * all (host-tools/opts/out_file.h): ffmpeg writes a temporary file beside
 * OUT, renamed over OUT only once ffmpeg has ended well; a failed or
 * missing ffmpeg leaves nothing named OUT.
 *
 * OUT's ending picks the film:
 *   .mp4   H.264 (libx264), yuv420p
 *   .webm  VP9 (libvpx-vp9), yuv420p
 *   .apng  animated PNG, the frames' own RGB, played in a loop
 * yuv420p halves the chroma both ways, so an odd width or height is padded
 * by one black column or row on the right or bottom (film_padded says so).
 */
#ifndef LINKS1_HOST_IMAGE_FILM_H
#define LINKS1_HOST_IMAGE_FILM_H

#include <stddef.h>
#include <stdio.h>
#include <sys/types.h>

#include "host-tools/image/image_io.h"
#include "host-tools/opts/out_file.h"

#define FILM_DEFAULT_FPS 12
#define FILM_MAX_FPS 240
#define FILM_PROGRAM "ffmpeg" /* looked up in PATH */

enum film_kind { FILM_NONE = 0, FILM_MP4, FILM_WEBM, FILM_APNG };

/* The film OUT's ending names, FILM_NONE for anything else (numbered
 * images then, as before). */
enum film_kind film_kind_of(const char *out);

/* 0 when FILM_PROGRAM is an executable file in PATH, else -1 with a
 * message saying so and how to install it: checked before a board boots. */
int film_program_check(char *err, size_t cap);

struct film {
    enum film_kind kind;
    struct out_file out;    /* OUT and the temporary file ffmpeg writes */
    FILE *pipe;             /* ffmpeg's standard input */
    pid_t pid;              /* ffmpeg, 0 once waited for */
    char log[PATH_MAX];     /* ffmpeg's standard error: a private file (tmp_file_make) */
    int width, height;      /* every frame's size */
    long frames;            /* frames written */
};

/* Starts ffmpeg for a film at path of width x height frames at fps frames
 * a second.  0, or -1 with "PATH: why" in err and nothing left behind. */
int film_open(struct film *fm, const char *path, int width, int height, int fps, char *err,
              size_t cap);

/* One frame (of the film's size) to ffmpeg.  0, or -1 with why in err
 * (ffmpeg stopped: its last message); film_abort then. */
int film_frame(struct film *fm, const struct image *img, char *err, size_t cap);

/* The end of the frames: ffmpeg finishes the film, which then becomes
 * OUT.  0, or -1 with why in err (ffmpeg's exit and last message), and
 * nothing named OUT is made. */
int film_close(struct film *fm, char *err, size_t cap);

/* ffmpeg stopped and its temporary file removed; OUT untouched.  Safe on
 * a film never opened (zeroed) or already closed. */
void film_abort(struct film *fm);

/* 1 when width x height is padded to even sides (mp4, webm). */
int film_padded(enum film_kind kind, int width, int height);

#endif
