/* trace_file.c: the trace format's writer, reader and checks (trace_file.h,
 * docs/trace.md). */
#define _POSIX_C_SOURCE 200809L
#include "host-tools/trace/trace_file.h"

#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "proto/areas.h"
#include "proto/render_link.h"

__attribute__((format(printf, 3, 4)))
static int trace_fail(char *err, size_t cap, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, cap, fmt, ap);
    va_end(ap);
    return -1;
}

void trace_free(struct trace *t)
{
    free(t->nc_setup);
    free(t->areas);
    free(t->pixel);
    memset(t, 0, sizeof *t);
}

uint64_t trace_pixels_sum(const struct trace *t, uint32_t x, uint32_t y, uint32_t w, uint32_t h)
{
    uint64_t sum = 0;
    for (uint32_t py = y; py < y + h; py++)
        for (uint32_t px = x; px < x + w; px++)
            sum += t->pixel[(size_t)py * t->width + px];
    return sum;
}

int trace_check(const struct trace *t, char *err, size_t cap)
{
    if (t->width == 0 || t->height == 0 || t->width > AREAS_MAX_DIM || t->height > AREAS_MAX_DIM)
        return trace_fail(err, cap, "screen %" PRIu32 "x%" PRIu32 ": each side must be 1..%u",
                          t->width, t->height, AREAS_MAX_DIM);
    if (t->ncs == 0 || t->nareas == 0)
        return trace_fail(err, cap, "%" PRIu32 " NCs and %" PRIu32 " areas: need at least one "
                          "of each", t->ncs, t->nareas);
    size_t n = (size_t)t->width * t->height;
    uint8_t *seen = calloc(n, 1);
    if (!seen)
        return trace_fail(err, cap, "out of memory");
    int rc = 0;
    for (uint32_t i = 0; i < t->nareas && rc == 0; i++) {
        const struct trace_area *a = &t->areas[i];
        if (a->w == 0 || a->h == 0 || a->x >= t->width || a->w > t->width - a->x ||
            a->y >= t->height || a->h > t->height - a->y) {
            rc = trace_fail(err, cap, "area %" PRIu32 " (%" PRIu32 ",%" PRIu32 " %" PRIu32 "x%"
                            PRIu32 ") is not inside the %" PRIu32 "x%" PRIu32 " screen",
                            i, a->x, a->y, a->w, a->h, t->width, t->height);
            break;
        }
        if (a->nc >= t->ncs) {
            rc = trace_fail(err, cap, "area %" PRIu32 ": NC %" PRIu32 ", the board had %" PRIu32,
                            i, a->nc, t->ncs);
            break;
        }
        for (uint32_t py = a->y; py < a->y + a->h && rc == 0; py++)
            for (uint32_t px = a->x; px < a->x + a->w; px++) {
                if (seen[(size_t)py * t->width + px]++) {
                    rc = trace_fail(err, cap, "area %" PRIu32 " overlaps another at pixel (%"
                                    PRIu32 ",%" PRIu32 ")", i, px, py);
                    break;
                }
            }
        if (rc)
            break;
        uint64_t sum = trace_pixels_sum(t, a->x, a->y, a->w, a->h);
        if (a->setup + sum + a->push != a->total)
            rc = trace_fail(err, cap, "area %" PRIu32 ": set-up %" PRIu64 " + pixels %" PRIu64
                            " + push %" PRIu64 " is not its total %" PRIu64,
                            i, a->setup, sum, a->push, a->total);
    }
    for (size_t p = 0; p < n && rc == 0; p++)
        if (!seen[p])
            rc = trace_fail(err, cap, "pixel (%zu,%zu) is in no area", p % t->width,
                            p / t->width);
    free(seen);
    return rc;
}

int trace_write(FILE *f, const char *name, const struct trace *t, char *err, size_t cap)
{
    /* a version 1 or 2 trace read in is written as version 2, one of
     * version 3 as 3 */
    int v = !t->first_with_start ? 2 : t->other_counted ? TRACE_VERSION : 3;
    fprintf(f, "%s %d\n", TRACE_MAGIC, v);
    fprintf(f, "screen %" PRIu32 " %" PRIu32 "\n", t->width, t->height);
    fprintf(f, "run ncs %" PRIu32 " balance %s k %" PRIu32 " guided %" PRIu32 " flags %" PRIu32
            "\n", t->ncs, areas_mode_name((enum areas_mode)t->balance), t->k, t->guided, t->flags);
    fprintf(f, "dm_prepare %" PRIu64 "\n", t->dm_prepare);
    fprintf(f, "broadcast bytes %" PRIu32 " rc %" PRIu64 "\n", t->broadcast_bytes,
            t->rc_broadcast);
    if (v >= 4)
        fprintf(f, "rc_other %" PRIu64 " messages %" PRIu32 " done %" PRIu32 " %" PRIu64 "\n",
                t->rc_other, t->rc_other_count, t->rc_done_count, t->rc_done);
    else
        fprintf(f, "rc_other %" PRIu64 "\n", t->rc_other);
    for (uint32_t i = 0; i < t->ncs; i++)
        fprintf(f, "nc %" PRIu32 " setup %" PRIu64 "\n", i, t->nc_setup[i]);
    fprintf(f, "areas %" PRIu32 "\n", t->nareas);
    for (uint32_t i = 0; i < t->nareas; i++) {
        const struct trace_area *a = &t->areas[i];
        fprintf(f, "area %" PRIu32 " %" PRIu32 " %" PRIu32 " %" PRIu32 " nc %" PRIu32
                " order %" PRIu32 " setup %" PRIu64 " push %" PRIu64 " total %" PRIu64
                " rc %" PRIu64 "\n", a->x, a->y, a->w, a->h, a->nc, a->order, a->setup,
                a->push, a->total, a->rc);
    }
    for (uint32_t y = 0; y < t->height; y++) {
        fprintf(f, "row %" PRIu32, y);
        for (uint32_t x = 0; x < t->width; x++)
            fprintf(f, " %" PRIu32, t->pixel[(size_t)y * t->width + x]);
        fputc('\n', f);
    }
    fputs("end\n", f);
    if (ferror(f) || fflush(f) != 0)
        return trace_fail(err, cap, "%s: write error", name);
    return 0;
}

/* ---- reader ---- */

struct trace_in {
    FILE *f;
    char *line;
    size_t cap;
    unsigned long no; /* line number */
    const char *path;
};

/* The next line without its newline, or NULL at the end. */
static char *trace_line(struct trace_in *in)
{
    ssize_t n = getline(&in->line, &in->cap, in->f);
    if (n < 0)
        return NULL;
    in->no++;
    if (n > 0 && in->line[n - 1] == '\n')
        in->line[n - 1] = 0;
    return in->line;
}

/* Reads a decimal number at *p (after blanks); 0, or -1 if there is none
 * or it is larger than max. */
static int trace_num(char **p, uint64_t max, uint64_t *v)
{
    char *s = *p;
    while (*s == ' ')
        s++;
    if (*s < '0' || *s > '9')
        return -1;
    errno = 0;
    char *end;
    unsigned long long n = strtoull(s, &end, 10);
    if (errno || n > max || (*end != ' ' && *end != 0))
        return -1;
    *v = n;
    *p = end;
    return 0;
}

/* Matches the word w at *p (after blanks). */
static int trace_word(char **p, const char *w)
{
    char *s = *p;
    while (*s == ' ')
        s++;
    size_t n = strlen(w);
    if (strncmp(s, w, n) != 0 || (s[n] != ' ' && s[n] != 0))
        return -1;
    *p = s + n;
    return 0;
}

static int trace_end_of_line(char *p)
{
    while (*p == ' ')
        p++;
    return *p == 0 ? 0 : -1;
}

#define U32 UINT32_MAX
#define U64 UINT64_MAX

/* Each part of the file below reads its lines from in into t; 0, or -1
 * with "PATH line N: what it wants" in err. */
#define WANT(cond, what)                                                                        \
    do {                                                                                        \
        if (!(cond))                                                                            \
            return trace_fail(err, cap, "%s line %lu: %s", in->path, in->no, what);             \
    } while (0)

/* "run ncs N balance MODE k K guided G flags F" (version 1: no guided). */
static int trace_parse_run(struct trace_in *in, struct trace *t, int v1, char *err, size_t cap)
{
    char mode[16];
    uint64_t v[4];
    char *p = trace_line(in);
    WANT(p && trace_word(&p, "run") == 0 && trace_word(&p, "ncs") == 0 &&
         trace_num(&p, 4096, &v[0]) == 0 && v[0] && trace_word(&p, "balance") == 0 &&
         sscanf(p, " %15s", mode) == 1, "want 'run ncs N balance MODE k K guided G flags F'");
    enum areas_mode m;
    WANT(areas_mode_parse(mode, &m) == AREAS_OK, "unknown balance mode");
    p = strstr(p, mode) + strlen(mode);
    v[3] = 0;
    WANT(trace_word(&p, "k") == 0 && trace_num(&p, U32, &v[1]) == 0 &&
         (v1 || (trace_word(&p, "guided") == 0 &&
                 trace_num(&p, AREAS_MAX_GUIDED_FACTOR, &v[3]) == 0)) &&
         trace_word(&p, "flags") == 0 && trace_num(&p, U32, &v[2]) == 0 &&
         trace_end_of_line(p) == 0, "want 'run ncs N balance MODE k K guided G flags F'");
    t->ncs = (uint32_t)v[0];
    t->balance = (uint32_t)m;
    t->k = (uint32_t)v[1];
    t->guided = (uint32_t)v[3];
    t->flags = (uint32_t)v[2];
    if (v1) {
        /* The board of version 1: K 1024 and factor 2 by default, NCs
         * asking once they had finished. */
        if (t->k == 0)
            t->k = 1024;
        t->guided = 2;
        t->flags |= LINK_RENDER_ASK_WHEN_DONE;
    }
    return 0;
}

/* The magic and version, the screen, the run, the DM's and RC's counts. */
static int trace_parse_head(struct trace_in *in, struct trace *t, char *err, size_t cap)
{
    uint64_t v[2];
    char *p = trace_line(in);
    WANT(p && trace_word(&p, TRACE_MAGIC) == 0 && trace_num(&p, U32, &v[0]) == 0,
         "not a links1 trace (want '" TRACE_MAGIC " 4')");
    WANT(v[0] >= 1 && v[0] <= TRACE_VERSION, "trace version not 1 to 4");
    int v1 = v[0] == 1;
    t->first_with_start = v[0] >= 3;
    t->other_counted = v[0] >= 4;
    p = trace_line(in);
    WANT(p && trace_word(&p, "screen") == 0 && trace_num(&p, AREAS_MAX_DIM, &v[0]) == 0 &&
         trace_num(&p, AREAS_MAX_DIM, &v[1]) == 0 && trace_end_of_line(p) == 0 && v[0] && v[1],
         "want 'screen W H' (1..4096 each)");
    t->width = (uint32_t)v[0];
    t->height = (uint32_t)v[1];
    if (trace_parse_run(in, t, v1, err, cap) != 0)
        return -1;
    p = trace_line(in);
    WANT(p && trace_word(&p, "dm_prepare") == 0 && trace_num(&p, U64, &t->dm_prepare) == 0 &&
         trace_end_of_line(p) == 0, "want 'dm_prepare INSNS'");
    p = trace_line(in);
    WANT(p && trace_word(&p, "broadcast") == 0 && trace_word(&p, "bytes") == 0 &&
         trace_num(&p, U32, &v[0]) == 0 && trace_word(&p, "rc") == 0 &&
         trace_num(&p, U64, &t->rc_broadcast) == 0 && trace_end_of_line(p) == 0,
         "want 'broadcast bytes B rc INSNS'");
    t->broadcast_bytes = (uint32_t)v[0];
    p = trace_line(in);
    WANT(p && trace_word(&p, "rc_other") == 0 && trace_num(&p, U64, &t->rc_other) == 0,
         "want 'rc_other INSNS'");
    if (t->other_counted) {
        WANT(trace_word(&p, "messages") == 0 && trace_num(&p, U32, &v[0]) == 0 &&
             trace_word(&p, "done") == 0 && trace_num(&p, v[0], &v[1]) == 0 &&
             trace_num(&p, t->rc_other, &t->rc_done) == 0,
             "want 'rc_other INSNS messages N done M INSNS' (M <= N, its INSNS within)");
        t->rc_other_count = (uint32_t)v[0];
        t->rc_done_count = (uint32_t)v[1];
    }
    WANT(trace_end_of_line(p) == 0,
         "want 'rc_other INSNS' (version 4: 'messages N done M INSNS' after)");
    return 0;
}

/* "nc I setup INSNS" for each NC in order. */
static int trace_parse_setups(struct trace_in *in, struct trace *t, char *err, size_t cap)
{
    uint64_t v;
    t->nc_setup = calloc(t->ncs, sizeof *t->nc_setup);
    WANT(t->nc_setup, "out of memory");
    for (uint32_t i = 0; i < t->ncs; i++) {
        char *p = trace_line(in);
        WANT(p && trace_word(&p, "nc") == 0 && trace_num(&p, U32, &v) == 0 && v == i &&
             trace_word(&p, "setup") == 0 && trace_num(&p, U64, &t->nc_setup[i]) == 0 &&
             trace_end_of_line(p) == 0, "want 'nc I setup INSNS' for each NC in order");
    }
    return 0;
}

/* "areas N", then N lines "area X Y W H nc N order I setup S push P total T rc R". */
static int trace_parse_areas(struct trace_in *in, struct trace *t, char *err, size_t cap)
{
    uint64_t v[6];
    char *p = trace_line(in);
    WANT(p && trace_word(&p, "areas") == 0 && trace_num(&p, (uint64_t)t->width * t->height,
                                                          &v[0]) == 0 && v[0] &&
         trace_end_of_line(p) == 0, "want 'areas N' (1 .. the screen's pixels)");
    t->nareas = (uint32_t)v[0];
    t->areas = calloc(t->nareas, sizeof *t->areas);
    WANT(t->areas, "out of memory");
    for (uint32_t i = 0; i < t->nareas; i++) {
        struct trace_area *a = &t->areas[i];
        p = trace_line(in);
        WANT(p && trace_word(&p, "area") == 0 && trace_num(&p, U32, &v[0]) == 0 &&
             trace_num(&p, U32, &v[1]) == 0 && trace_num(&p, U32, &v[2]) == 0 &&
             trace_num(&p, U32, &v[3]) == 0 && trace_word(&p, "nc") == 0 &&
             trace_num(&p, U32, &v[4]) == 0 && trace_word(&p, "order") == 0 &&
             trace_num(&p, U32, &v[5]) == 0 && trace_word(&p, "setup") == 0 &&
             trace_num(&p, U64, &a->setup) == 0 && trace_word(&p, "push") == 0 &&
             trace_num(&p, U64, &a->push) == 0 && trace_word(&p, "total") == 0 &&
             trace_num(&p, U64, &a->total) == 0 && trace_word(&p, "rc") == 0 &&
             trace_num(&p, U64, &a->rc) == 0 && trace_end_of_line(p) == 0,
             "want 'area X Y W H nc N order I setup S push P total T rc R'");
        a->x = (uint32_t)v[0];
        a->y = (uint32_t)v[1];
        a->w = (uint32_t)v[2];
        a->h = (uint32_t)v[3];
        a->nc = (uint32_t)v[4];
        a->order = (uint32_t)v[5];
        a->handout = i;
    }
    return 0;
}

/* "row Y" and the row's pixel costs for each row in order, then "end". */
static int trace_parse_rows(struct trace_in *in, struct trace *t, char *err, size_t cap)
{
    uint64_t v;
    t->pixel = calloc((size_t)t->width * t->height, sizeof *t->pixel);
    WANT(t->pixel, "out of memory");
    for (uint32_t y = 0; y < t->height; y++) {
        char *p = trace_line(in);
        WANT(p && trace_word(&p, "row") == 0 && trace_num(&p, U32, &v) == 0 && v == y,
             "want 'row Y' followed by the row's pixel costs, rows in order");
        for (uint32_t x = 0; x < t->width; x++)
            WANT(trace_num(&p, U32, &v) == 0 && (t->pixel[(size_t)y * t->width + x] =
                                                     (uint32_t)v, 1),
                 "a row needs one cost (0..2^32-1) per pixel");
        WANT(trace_end_of_line(p) == 0, "more costs than the screen is wide");
    }
    char *p = trace_line(in);
    WANT(p && strcmp(p, "end") == 0, "want 'end' after the last row (a cut-off trace?)");
    WANT(trace_line(in) == NULL, "text after 'end'");
    return 0;
}
#undef WANT

static int trace_parse(struct trace_in *in, struct trace *t, char *err, size_t cap)
{
    if (trace_parse_head(in, t, err, cap) != 0 || trace_parse_setups(in, t, err, cap) != 0 ||
        trace_parse_areas(in, t, err, cap) != 0 || trace_parse_rows(in, t, err, cap) != 0)
        return -1;
    return 0;
}

int trace_read(const char *path, struct trace *t, char *err, size_t cap)
{
    memset(t, 0, sizeof *t);
    struct trace_in in = {fopen(path, "r"), NULL, 0, 0, path};
    if (!in.f)
        return trace_fail(err, cap, "%s: %s", path, strerror(errno));
    int rc = trace_parse(&in, t, err, cap);
    free(in.line);
    fclose(in.f);
    char why[TRACE_ERR_MAX];
    if (rc == 0 && trace_check(t, why, sizeof why) != 0)
        rc = trace_fail(err, cap, "%s: %s", path, why);
    if (rc != 0)
        trace_free(t);
    return rc;
}
