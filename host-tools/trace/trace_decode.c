/* trace_decode.c: a trace (trace_file.h) from the counting plugin's
 * trace= file: lines "CORE KIND COUNT", core by core, each core's marks in
 * the order it executed them (proto/insn_mark.h, docs/trace.md). */
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/trace/trace_file.h"
#include "proto/insn_mark.h"
#include "proto/unitmsg.h"
#include "proto/units.h"

struct mark {
    uint8_t kind;
    uint64_t count;
};

struct marks {
    struct mark *m;
    size_t n, cap;
};

__attribute__((format(printf, 3, 4)))
static int decode_fail(char *err, size_t cap, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, cap, fmt, ap);
    va_end(ap);
    return -1;
}

/* Reads the bits at *i (n of them, most significant first). */
static int decode_bits(const struct marks *c, size_t *i, int n, uint32_t *v)
{
    *v = 0;
    for (int b = 0; b < n; b++, (*i)++) {
        if (*i >= c->n || c->m[*i].kind > INSN_TRACE_BIT1)
            return -1;
        *v = *v << 1 | c->m[*i].kind;
    }
    return 0;
}

/* The DM: the last span (the frame's preprocessing). */
static int decode_dm(const struct marks *c, struct trace *t, char *err, size_t cap)
{
    int have = 0;
    for (size_t i = 0; i + 1 < c->n; i++)
        if (c->m[i].kind == INSN_TRACE_SPAN_BEGIN && c->m[i + 1].kind == INSN_TRACE_SPAN_END) {
            t->dm_prepare = c->m[i + 1].count - c->m[i].count;
            have = 1;
        }
    return have ? 0 : decode_fail(err, cap, "the DM left no preprocessing span");
}

/* The area handed out with its top-left pixel at (x, y), or -1: at[] maps
 * each pixel to 1 + the index of the area starting there. */
static int decode_area_index(const struct trace *t, const uint32_t *at, uint32_t x, uint32_t y)
{
    if (x >= t->width || y >= t->height)
        return -1;
    return (int)at[(size_t)y * t->width + x] - 1;
}

/* The RC: the broadcast span, then per NC started (its first area handed
 * out with its MSG_NC_START) and per message served a span and its record
 * (NC core 16 bits, handed 1, x 16, y 16). */
static int decode_rc(const struct marks *c, struct trace *t, char *err, size_t cap)
{
    size_t i = 0;
    if (c->n < 2 || c->m[0].kind != INSN_TRACE_SPAN_BEGIN || c->m[1].kind != INSN_TRACE_SPAN_END)
        return decode_fail(err, cap, "the RC's marks do not start with the broadcast");
    t->rc_broadcast = c->m[1].count - c->m[0].count;
    i = 2;
    uint32_t cap_areas = 1024;
    t->areas = calloc(cap_areas, sizeof *t->areas);
    if (!t->areas)
        return decode_fail(err, cap, "out of memory");
    while (i < c->n) {
        if (i + 1 >= c->n || c->m[i].kind != INSN_TRACE_SPAN_BEGIN ||
            c->m[i + 1].kind != INSN_TRACE_SPAN_END)
            return decode_fail(err, cap, "RC mark %zu: want a served message's span", i);
        uint64_t cost = c->m[i + 1].count - c->m[i].count;
        i += 2;
        uint32_t core, handed, x, y;
        if (decode_bits(c, &i, 16, &core) || decode_bits(c, &i, 1, &handed) ||
            decode_bits(c, &i, 16, &x) || decode_bits(c, &i, 16, &y))
            return decode_fail(err, cap, "RC mark %zu: a served message's record is cut", i);
        if (!handed) { /* x: the message's type (roles/rc_nc.c) */
            t->rc_other += cost;
            t->rc_other_count++;
            if (x == MSG_NC_DONE) {
                t->rc_done += cost;
                t->rc_done_count++;
            }
            continue;
        }
        if (core < (uint32_t)UNITS_FIRST_NC || core - (uint32_t)UNITS_FIRST_NC >= t->ncs)
            return decode_fail(err, cap, "the RC handed an area to core %" PRIu32
                               ", not an NC", core);
        if (t->nareas == cap_areas) {
            cap_areas *= 2;
            struct trace_area *a = realloc(t->areas, cap_areas * sizeof *a);
            if (!a)
                return decode_fail(err, cap, "out of memory");
            t->areas = a;
        }
        struct trace_area *a = &t->areas[t->nareas];
        memset(a, 0, sizeof *a);
        a->x = x;
        a->y = y;
        a->nc = core - (uint32_t)UNITS_FIRST_NC;
        a->handout = t->nareas;
        a->rc = cost;
        a->w = 0; /* from the NC */
        t->nareas++;
    }
    return 0;
}

/* An NC: its set-up span, then per area: x, y, w, h (16 bits each),
 * AREA_BEGIN, PIXEL after the set-up and after each pixel, AREA_END. */
static int decode_nc(const struct marks *c, uint32_t nc, struct trace *t, const uint32_t *at,
                     uint8_t *got, char *err, size_t cap)
{
    if (c->n < 2 || c->m[0].kind != INSN_TRACE_SPAN_BEGIN || c->m[1].kind != INSN_TRACE_SPAN_END)
        return decode_fail(err, cap, "NC %" PRIu32 ": its marks do not start with its set-up",
                           nc);
    t->nc_setup[nc] = c->m[1].count - c->m[0].count;
    size_t i = 2;
    uint32_t order = 0;
    while (i < c->n) {
        uint32_t x, y, w, h;
        if (decode_bits(c, &i, 16, &x) || decode_bits(c, &i, 16, &y) ||
            decode_bits(c, &i, 16, &w) || decode_bits(c, &i, 16, &h))
            return decode_fail(err, cap, "NC %" PRIu32 " mark %zu: an area's rectangle is cut",
                               nc, i);
        int k = decode_area_index(t, at, x, y);
        if (k < 0 || t->areas[k].nc != nc || got[k])
            return decode_fail(err, cap, "NC %" PRIu32 " drew the area at (%" PRIu32 ",%" PRIu32
                               "), which the RC did not hand it", nc, x, y);
        if (w == 0 || h == 0 || x >= t->width || w > t->width - x || y >= t->height ||
            h > t->height - y)
            return decode_fail(err, cap, "NC %" PRIu32 ": area %" PRIu32 "x%" PRIu32 " at (%"
                               PRIu32 ",%" PRIu32 ") is off the screen", nc, w, h, x, y);
        size_t need = 2 + (size_t)w * h + 1;
        if (i + need > c->n || c->m[i].kind != INSN_TRACE_AREA_BEGIN ||
            c->m[i + need - 1].kind != INSN_TRACE_AREA_END)
            return decode_fail(err, cap, "NC %" PRIu32 ": the marks of area (%" PRIu32 ",%"
                               PRIu32 ") are not begin, %zu pixel marks, end", nc, x, y,
                               need - 2);
        for (size_t j = i + 1; j < i + need - 1; j++)
            if (c->m[j].kind != INSN_TRACE_PIXEL)
                return decode_fail(err, cap, "NC %" PRIu32 ": a mark of kind %u inside area (%"
                                   PRIu32 ",%" PRIu32 ")", nc, c->m[j].kind, x, y);
        struct trace_area *a = &t->areas[k];
        got[k] = 1;
        a->w = w;
        a->h = h;
        a->order = order++;
        a->setup = c->m[i + 1].count - c->m[i].count;
        size_t pm = i + 1; /* the mark before each pixel's */
        for (uint32_t py = y; py < y + h; py++)
            for (uint32_t px = x; px < x + w; px++, pm++) {
                uint64_t d = c->m[pm + 1].count - c->m[pm].count;
                t->pixel[(size_t)py * t->width + px] = d > UINT32_MAX ? UINT32_MAX : (uint32_t)d;
            }
        a->push = c->m[i + need - 1].count - c->m[pm].count;
        a->total = c->m[i + need - 1].count - c->m[i].count;
        i += need;
    }
    return 0;
}

static int decode_load(const char *path, struct marks *cores, uint32_t ncores, char *err,
                       size_t cap)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return decode_fail(err, cap, "trace marks %s: cannot open", path);
    char line[96];
    int rc = 0;
    unsigned long no = 0;
    while (rc == 0 && fgets(line, sizeof line, f)) {
        no++;
        unsigned core, kind;
        unsigned long long count;
        if (strcmp(line, "oom\n") == 0) {
            rc = decode_fail(err, cap, "the counting plugin ran out of memory for the marks");
            break;
        }
        if (sscanf(line, "%u %u %llu", &core, &kind, &count) != 3 || core >= ncores ||
            kind >= INSN_TRACE_KINDS) {
            rc = decode_fail(err, cap, "trace marks %s line %lu: want 'CORE KIND COUNT'", path,
                             no);
            break;
        }
        struct marks *c = &cores[core];
        if (c->n == c->cap) {
            size_t ncap = c->cap ? 2 * c->cap : 4096;
            struct mark *m = realloc(c->m, ncap * sizeof *m);
            if (!m) {
                rc = decode_fail(err, cap, "out of memory");
                break;
            }
            c->m = m;
            c->cap = ncap;
        }
        c->m[c->n++] = (struct mark){(uint8_t)kind, count};
    }
    fclose(f);
    return rc;
}

int trace_decode_marks(const char *marks_path, uint32_t width, uint32_t height, uint32_t ncs,
                       struct trace *t, char *err, size_t cap)
{
    memset(t, 0, sizeof *t);
    t->width = width;
    t->height = height;
    t->ncs = ncs;
    t->first_with_start = 1; /* the board's RC: roles/rc_nc.c */
    t->other_counted = 1;
    uint32_t ncores = ncs + (uint32_t)UNITS_FIRST_NC;
    struct marks *cores = calloc(ncores, sizeof *cores);
    t->nc_setup = calloc(ncs, sizeof *t->nc_setup);
    t->pixel = calloc((size_t)width * height, sizeof *t->pixel);
    uint8_t *got = NULL;
    uint32_t *at = NULL;
    int rc = -1;
    if (!cores || !t->nc_setup || !t->pixel) {
        decode_fail(err, cap, "out of memory");
        goto out;
    }
    if (decode_load(marks_path, cores, ncores, err, cap) != 0 ||
        decode_dm(&cores[UNITS_DM_CORE], t, err, cap) != 0 ||
        decode_rc(&cores[UNITS_RC_CORE], t, err, cap) != 0)
        goto out;
    got = calloc(t->nareas ? t->nareas : 1, 1);
    at = calloc((size_t)width * height, sizeof *at);
    if (!got || !at) {
        decode_fail(err, cap, "out of memory");
        goto out;
    }
    for (uint32_t i = 0; i < t->nareas; i++) {
        const struct trace_area *a = &t->areas[i];
        if (a->x >= width || a->y >= height || at[(size_t)a->y * width + a->x]) {
            decode_fail(err, cap, "the RC handed out (%" PRIu32 ",%" PRIu32 ") twice or off "
                        "the screen", a->x, a->y);
            goto out;
        }
        at[(size_t)a->y * width + a->x] = i + 1;
    }
    for (uint32_t nc = 0; nc < ncs; nc++)
        if (decode_nc(&cores[(uint32_t)UNITS_FIRST_NC + nc], nc, t, at, got, err, cap) != 0)
            goto out;
    for (uint32_t i = 0; i < t->nareas; i++)
        if (!got[i]) {
            decode_fail(err, cap, "the area at (%" PRIu32 ",%" PRIu32 ") was handed out but "
                        "no NC marks drawing it", t->areas[i].x, t->areas[i].y);
            goto out;
        }
    rc = trace_check(t, err, cap);
out:
    for (uint32_t k = 0; cores && k < ncores; k++)
        free(cores[k].m);
    free(cores);
    free(got);
    free(at);
    if (rc != 0)
        trace_free(t);
    return rc;
}

int trace_dm_spans(const char *marks_path, uint64_t *len, size_t cap, size_t *n, char *err,
                   size_t errcap)
{
    *n = 0;
    FILE *f = fopen(marks_path, "r");
    if (!f)
        return decode_fail(err, errcap, "trace marks %s: cannot open", marks_path);
    char line[96];
    int rc = 0, open = 0;
    unsigned long long begin = 0;
    while (rc == 0 && *n < cap && fgets(line, sizeof line, f)) {
        unsigned core, kind;
        unsigned long long count;
        if (sscanf(line, "%u %u %llu", &core, &kind, &count) != 3 || kind >= INSN_TRACE_KINDS)
            rc = decode_fail(err, errcap, "trace marks %s: a line is not 'CORE KIND COUNT'",
                             marks_path);
        else if (core != UNITS_DM_CORE)
            break; /* core by core: the DM's come first */
        else if (kind == INSN_TRACE_SPAN_BEGIN)
            open = 1, begin = count;
        else if (kind == INSN_TRACE_SPAN_END && open && count >= begin)
            len[(*n)++] = count - begin, open = 0;
        else
            open = 0;
    }
    fclose(f);
    return rc;
}
