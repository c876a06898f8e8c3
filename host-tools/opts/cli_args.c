/* cli_args.c: see cli_args.h. */
#include "host-tools/opts/cli_args.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "render/limits.h"

int cli_parse_frames(const char *arg, long *first, long *last)
{
    char *end;
    *first = strtol(arg, &end, 10);
    if (end == arg || *first < 0)
        return -1;
    *last = *first;
    if (*end == ':') {
        const char *b = end + 1;
        *last = strtol(b, &end, 10);
        if (end == b || *last < *first)
            return -1;
    }
    return *end ? -1 : 0;
}

int cli_parse_band(const char *arg, long *band, long *bands)
{
    char *end;
    errno = 0;
    *band = strtol(arg, &end, 10);
    if (errno || end == arg || *end != '/' || *band < 0)
        return -1;
    const char *b = end + 1;
    *bands = strtol(b, &end, 10);
    if (errno || end == b || *end || *bands > 65535 || *band >= *bands)
        return -1;
    return 0;
}

int cli_parse_size(const char *arg, int *width, int *height)
{
    char tail;
    if (sscanf(arg, "%dx%d%c", width, height, &tail) != 2)
        return -1;
    if (*width < 1 || *height < 1 || *width > RENDER_MAX_WIDTH || *height > RENDER_MAX_HEIGHT)
        return -1;
    return 0;
}

const char *cli_size_want(void)
{
    static char want[48];
    snprintf(want, sizeof want, "WxH within %dx%d", RENDER_MAX_WIDTH, RENDER_MAX_HEIGHT);
    return want;
}
