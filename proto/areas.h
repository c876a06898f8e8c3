/* areas.h: how the RC cuts the screen into areas (LINKS-1's "small
 * screens") and in what order it hands them out.
 *
 * An area is a rectangle of whole pixels.  The paper measures its dynamic
 * balancing with equal rectangles from a grid (Fig. 10: 64 = 8x8 areas,
 * best at 1024 = 32x32 on 512x480), and notes that areas made of one
 * scanline or part of one make Y clipping most effective.  Three schedules
 * (docs/areas.md):
 *
 *   AREAS_STATIC      one area per NC: the grid of ncs equal areas, each
 *                     NC drawing one (areas_one_per_nc), whenever it asks.
 *   AREAS_DYNAMIC     the grid of k equal areas ("simple dynamic"), given
 *                     out one per area request.
 *   AREAS_DECREASING  guided self-scheduling: each next area holds about
 *                     remaining pixels / (AREAS_GUIDED_FACTOR * ncs), but
 *                     never fewer pixels than one area of the k-area grid.
 *                     First bands of whole scanlines, then pieces of one
 *                     scanline, a scanline's as equal as whole pixels
 *                     allow; no area larger than the one before it but
 *                     by that rounding (a pixel).
 *   AREAS_LINES       simple dynamic on the paper's job unit, "one scanline
 *                     or part of one": k >= height cuts every scanline into
 *                     k/height equal pieces (rounded as the grid rounds),
 *                     k < height gives k bands of whole scanlines.  Given
 *                     out one per area request, as AREAS_DYNAMIC.
 *
 * Every schedule covers the screen exactly once: every area lies inside the
 * screen, no two overlap, together they are the whole screen.  Areas come
 * in raster order (top band first, left to right).
 *
 * Pure computation: no globals, no hardware, no allocation, so the same
 * file runs on the RC, in the host tool and in the host tests. */
#ifndef LINKS1_PROTO_AREAS_H
#define LINKS1_PROTO_AREAS_H

#include <stdint.h>

/* Largest screen side.  The frame memory stops at 1024x1024; this bound
 * only keeps every pixel count of a schedule well inside 32 bits. */
#define AREAS_MAX_DIM 4096u
/* Areas of the simple dynamic grid when the caller passes k = 0 (the
 * host's --areas default too): the paper's best count on 512x480 with 64
 * NCs (Fig. 10). */
#define AREAS_DEFAULT_K 1024u
/* Guided self-scheduling divisor: an area takes 1/(factor * ncs) of what is
 * left.  1 gives the first NCs so much that the last areas cannot even the
 * finish; 2 leaves half the screen to balance with smaller areas. */
#define AREAS_MAX_GUIDED_FACTOR 64u

enum areas_mode {
    AREAS_STATIC = 0,
    AREAS_DYNAMIC = 1,
    AREAS_DECREASING = 2,
    AREAS_LINES = 3,
};
#define AREAS_MODES 4

enum areas_status {
    AREAS_OK = 0,
    AREAS_ERR_MODE = -1,   /* not one of enum areas_mode */
    AREAS_ERR_SIZE = -2,   /* width or height 0 or above AREAS_MAX_DIM */
    AREAS_ERR_NCS = -3,    /* no NC */
    AREAS_ERR_FACTOR = -4, /* guided factor not 1..AREAS_MAX_GUIDED_FACTOR, or set late */
};

struct area {
    uint32_t x, y; /* top-left pixel */
    uint32_t w, h; /* width and height, both >= 1 */
};

/* One schedule in progress.  Fields are private to areas.c. */
struct areas {
    enum areas_mode mode;
    uint32_t width, height; /* screen */
    uint32_t ncs;           /* node computers sharing the screen */
    uint32_t k;             /* grid areas (static: ncs, clamped) */
    /* grid schedules */
    uint32_t bands;         /* bands of scanlines in the grid */
    uint32_t band;          /* band of the next area */
    uint32_t col;           /* area of the next area within its band */
    /* decreasing schedule */
    uint32_t min_pixels;    /* no area smaller than this (but a piece) */
    uint32_t next_y;        /* first scanline not yet fully handed out */
    uint32_t next_x;        /* next pixel of scanline next_y (0: line start) */
    uint32_t pieces;        /* pieces scanline next_y is cut into */
    uint32_t piece;         /* the next one of them */
    uint32_t pixels_left;   /* pixels not yet handed out */
    uint32_t handed;        /* areas handed out so far */
    uint32_t factor;        /* guided divisor (AREAS_GUIDED_FACTOR unless set) */
    uint32_t y0;            /* added to every area's y (areas_set_origin) */
};

/* The decreasing schedule's k and guided factor for ncs NCs when the
 * caller leaves them to the board (k = 0, no factor set): of k in
 * 4096..65536 (in quarter steps of each power of two) and factors 1..4,
 * the one whose worst speed-up over the traces of demo, glass and
 * molecule at 512x480 in `links1 replay` is nearest each scene's best, NCs
 * asking ahead (tests/bench/areas_rule.py, docs/areas.md). */
void areas_decreasing_defaults(uint32_t ncs, uint32_t *k, uint32_t *factor);
/* The k and factor a schedule of mode for ncs NCs takes when given k and
 * factor (0: its default; static's k is ncs; the grids use no factor and
 * keep 0), before k is clamped to the pixels: what areas_init and
 * areas_set_guided_factor make of them. */
void areas_settings(enum areas_mode mode, uint32_t ncs, uint32_t k, uint32_t factor,
                    uint32_t *k_out, uint32_t *factor_out);

/* Starts a schedule for a width x height screen shared by ncs NCs.  k is
 * the grid's area count for AREAS_DYNAMIC and AREAS_LINES (0 = AREAS_DEFAULT_K) and the
 * smallest-area bound of AREAS_DECREASING (0 = areas_decreasing_defaults,
 * which also sets the factor); AREAS_STATIC ignores it.  A grid
 * never has more areas than pixels: k (or ncs) is clamped to width*height.
 * Returns AREAS_OK or an enum areas_status error, leaving *s unusable. */
int areas_init(struct areas *s, enum areas_mode mode, uint32_t width, uint32_t height,
               uint32_t ncs, uint32_t k);
/* Sets the decreasing schedule's guided divisor (an area takes 1/(factor *
 * ncs) of what is left; 1..AREAS_MAX_GUIDED_FACTOR) before its first area;
 * AREAS_OK, or AREAS_ERR_FACTOR (the schedule is left as it was). */
int areas_set_guided_factor(struct areas *s, uint32_t factor);
/* Moves the whole schedule down by y0 scanlines: a schedule of a band of
 * the screen (its height the band's rows) hands out the band's areas in
 * screen coordinates.  Set before the first area, as the factor is. */
void areas_set_origin(struct areas *s, uint32_t y0);
/* Writes the next area and returns 1, or returns 0 once the screen is all
 * handed out. */
int areas_next(struct areas *s, struct area *a);
/* Areas the whole schedule hands out (from its start, whatever s has
 * already handed out). */
uint32_t areas_count(const struct areas *s);
/* Areas handed out so far. */
uint32_t areas_handed(const struct areas *s);
/* 1 if the schedule is one area per NC (AREAS_STATIC): the RC gives an NC
 * a second area of it only when no NC still in the frame is without one. */
int areas_one_per_nc(const struct areas *s);

/* "static", "dynamic", "decreasing", "lines". */
const char *areas_mode_name(enum areas_mode mode);
/* Parses a mode name; AREAS_OK, or AREAS_ERR_MODE for an unknown name. */
int areas_mode_parse(const char *name, enum areas_mode *mode);
const char *areas_strerror(int status);

#endif
