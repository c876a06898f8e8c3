/* cli_args.h: option values shared by `links1 ref` and `links1 render`. */
#ifndef LINKS1_HOST_SCENE_CLI_ARGS_H
#define LINKS1_HOST_SCENE_CLI_ARGS_H

/* "N" or "A:B" (inclusive, A <= B, both >= 0) into *first, *last.
 * Returns 0, or -1 when arg is not of that form. */
int cli_parse_frames(const char *arg, long *first, long *last);

/* "I/N" with 0 <= I < N <= 65535 (band I of N) into *band, *bands.
 * Returns 0, or -1 when arg is not of that form. */
int cli_parse_band(const char *arg, long *band, long *bands);

/* "WxH" with 1 <= W <= RENDER_MAX_WIDTH and 1 <= H <= RENDER_MAX_HEIGHT
 * (the frame memory).  Returns 0, or -1 when arg is not of that form. */
int cli_parse_size(const char *arg, int *width, int *height);

/* What cli_parse_size wants, for the error message: "WxH within 1024x1024". */
const char *cli_size_want(void);

#endif
