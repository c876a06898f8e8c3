/* chart.h: a chart drawn by the gnuplot command (the Debian package
 * gnuplot-nox) into the PNG file OUT, written whole or not at all
 * (host-tools/opts/out_file.h).  gnuplot is started with posix_spawnp from
 * an argument array (no shell); the caller writes its script, data
 * included, to gnuplot's standard input; gnuplot writes the PNG to its
 * standard output, which is OUT's temporary file, renamed over OUT only
 * once gnuplot has ended well.  The script sets the terminal (pngcairo)
 * and never "set output". */
#ifndef LINKS1_HOST_IMAGE_CHART_H
#define LINKS1_HOST_IMAGE_CHART_H

#include <stddef.h>
#include <stdio.h>
#include <sys/types.h>

#include "host-tools/opts/out_file.h"

#define CHART_PROGRAM "gnuplot" /* looked up in PATH */

struct chart {
    struct out_file out; /* OUT and the temporary file gnuplot writes */
    FILE *script;        /* gnuplot's standard input: write the script here */
    pid_t pid;           /* gnuplot, 0 once waited for */
};

/* gnuplot started for the chart OUT.  0, or -1 with "OUT: why" in err and
 * nothing left behind (gnuplot missing says which package has it). */
int chart_open(struct chart *c, const char *path, char *err, size_t cap);

/* The script ends; gnuplot draws and the PNG becomes OUT.  0, or -1 with
 * why in err and nothing named OUT. */
int chart_close(struct chart *c, char *err, size_t cap);

/* gnuplot stopped and the temporary file removed; nothing happens to
 * OUT.  Safe on a zeroed or closed chart. */
void chart_abort(struct chart *c);

#endif
