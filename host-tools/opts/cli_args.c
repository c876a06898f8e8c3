/* cli_args.c: see cli_args.h. */
#include "host-tools/opts/cli_args.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>

#include "render/limits.h"

/* The decimal number at *p (digits only: no sign, no space) into *out,
 * *p moved past it: 0, or -1 when there are no digits, or the number is
 * outside lo..hi (one too big for a long too). */
static int cli_number(const char **p, long lo, long hi, long *out)
{
    char *end;
    if (**p < '0' || **p > '9')
        return -1;
    errno = 0;
    long v = strtol(*p, &end, 10);
    if (errno || v < lo || v > hi)
        return -1;
    *p = end;
    *out = v;
    return 0;
}

int cli_parse_frames(const char *arg, long *first, long *last)
{
    if (cli_number(&arg, 0, LONG_MAX, first) < 0)
        return -1;
    *last = *first;
    if (*arg == ':' && (++arg, cli_number(&arg, *first, LONG_MAX, last) < 0))
        return -1;
    return *arg ? -1 : 0;
}

int cli_parse_band(const char *arg, long *band, long *bands)
{
    if (cli_number(&arg, 0, 65534, band) < 0 || *arg++ != '/' ||
        cli_number(&arg, *band + 1, 65535, bands) < 0)
        return -1;
    return *arg ? -1 : 0;
}

int cli_parse_size(const char *arg, int *width, int *height)
{
    long w, h;
    if (cli_number(&arg, 1, RENDER_MAX_WIDTH, &w) < 0 || *arg++ != 'x' ||
        cli_number(&arg, 1, RENDER_MAX_HEIGHT, &h) < 0 || *arg)
        return -1;
    *width = (int)w;
    *height = (int)h;
    return 0;
}

const char *cli_size_want(void)
{
    static char want[48];
    snprintf(want, sizeof want, "WxH within %dx%d", RENDER_MAX_WIDTH, RENDER_MAX_HEIGHT);
    return want;
}
