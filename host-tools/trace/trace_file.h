/* trace_file.h: the per-area trace of one frame rendered on the board
 * (links1 render --trace FILE), the input of links1 replay.  The format,
 * its writer, its reader and the decoder of the counting plugin's marks
 * are here and nowhere else (docs/trace.md).
 *
 * A trace holds what each unit computer spent, in guest instructions:
 *   - the DM's preprocessing of the frame;
 *   - the RC's broadcast, and its serving of each area request (from
 *     version 3 an NC's first area comes with its MSG_NC_START: that
 *     area's RC cost is the hand-out alone), and of the messages that
 *     handed out none (from version 4 with their count, and the
 *     MSG_NC_DONEs among them apart);
 *   - each NC's set-up of the frame;
 *   - per area: its rectangle, the NC that drew it and in which order, its
 *     set-up (Y clipping), its push into the data collector, its total;
 *   - per pixel: what tracing that pixel took inside its area (X clipping
 *     and the rays), the finer grain a replay of other areas is built from.
 * and the broadcast's size in bytes. */
#ifndef LINKS1_HOST_TRACE_FILE_H
#define LINKS1_HOST_TRACE_FILE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define TRACE_MAGIC "links1-trace"
#define TRACE_VERSION 4
#define TRACE_ERR_MAX 256

struct trace_area {
    uint32_t x, y, w, h;
    uint32_t nc;      /* NC index, 0 .. ncs-1 (core nc + 2) */
    uint32_t order;   /* the NC's order-th area (from 0) */
    uint32_t handout; /* the RC handed it out handout-th (from 0) */
    uint64_t setup;   /* area start to the first pixel (Y clipping) */
    uint64_t push;    /* last pixel to the rows in the data collector */
    uint64_t total;   /* setup + the area's pixels + push */
    uint64_t rc;      /* the RC serving the request answered with this area */
};

struct trace {
    uint32_t width, height;
    uint32_t ncs;       /* NCs on the board */
    uint32_t balance;   /* enum areas_mode of the board's run */
    uint32_t k;         /* its --areas K (0: the board's default for its NCs) */
    uint32_t guided;    /* its --guided F (0: the board's default for its NCs) */
    uint32_t flags;     /* enum link_render_flag of the run */
    uint32_t first_with_start; /* 1: each NC's first area (order 0) came with
                                  its MSG_NC_START (version 3); 0: it asked */
    uint32_t other_counted; /* 1: rc_other_count holds the messages of
                               rc_other (version 4) */
    uint64_t dm_prepare;   /* DM: render_blob_prepare of the frame */
    uint64_t rc_broadcast; /* RC: the blob into the broadcast block */
    uint32_t broadcast_bytes;
    uint64_t rc_other;  /* RC: serving messages that handed out no area */
    uint32_t rc_other_count; /* how many (other_counted) */
    uint64_t rc_done;   /* of them, the MSG_NC_DONEs (other_counted) */
    uint32_t rc_done_count;
    uint64_t *nc_setup; /* [ncs]: each NC's set-up of the frame */
    uint32_t nareas;
    struct trace_area *areas; /* in handout order */
    uint32_t *pixel;    /* [width * height]: each pixel's instructions */
};

void trace_free(struct trace *t);
/* The trace as text to f (the caller makes and closes the file: an
 * output file is written whole through host-tools/opts/out_file.h); name
 * names it in err.  0, or -1 with err filled. */
int trace_write(FILE *f, const char *name, const struct trace *t, char *err, size_t cap);
/* Reads and checks a trace: the areas cover the screen once, each area's
 * total is its set-up, pixels and push.  0, or -1 with err naming the
 * problem (and the line). */
int trace_read(const char *path, struct trace *t, char *err, size_t cap);
/* Checks the parts of t that trace_read checks; 0 or -1 with err. */
int trace_check(const struct trace *t, char *err, size_t cap);
/* Sum of the area's pixels in the trace. */
uint64_t trace_pixels_sum(const struct trace *t, uint32_t x, uint32_t y, uint32_t w, uint32_t h);

/* Prices the same frame at f times the width and height (host-tools/
 * trace_scale.c): pixel (x, y) costs what traced pixel (x / f, y / f) did;
 * each area covers the f x f blocks of its pixels, with its set-up and
 * RC serving as traced and its push times f * f.  The frame's DM, RC and
 * NC set-ups stay.  For a row traced at a reduced size (links1 replay
 * --scale).  0, or -1 with err filled (t unchanged when the size is
 * refused). */
int trace_scale(struct trace *t, uint32_t f, char *err, size_t cap);

/* Builds t from the plugin's trace= file (proto/insn_mark.h marks: core 0
 * the DM, core 1 the RC, cores 2.. the NCs) for a frame of width x height
 * on ncs NCs.  The caller sets balance, k, flags and broadcast_bytes
 * after.  0, or -1 with err filled. */
int trace_decode_marks(const char *marks_path, uint32_t width, uint32_t height, uint32_t ncs,
                       struct trace *t, char *err, size_t cap);

/* The DM's first spans (a SPAN_BEGIN mark followed by a SPAN_END) in the
 * plugin's trace= file, in the order it ran them: len[0..*n), *n at most
 * cap.  0, or -1 with err filled. */
int trace_dm_spans(const char *marks_path, uint64_t *len, size_t cap, size_t *n, char *err,
                   size_t errcap);

#endif
