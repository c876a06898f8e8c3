/* render/lightbuf.h: the light buffer (Haines and Greenberg, 1986): for
 * each light, a grid of directions listing the parts of the scene a shadow
 * ray in that direction may meet, so that a shadow ray walks only those.
 *
 * The parts ("items") are the top of the cluster tree cut at
 * RENDER_LB_ITEMS: the root is replaced by its own primitives and its
 * children, and so on breadth first while the count stays within it.  A
 * point or spot light gets a cube of six faces of RENDER_LB_CELLS x
 * RENDER_LB_CELLS cells around it; a parallel light a grid as fine on the
 * plane across its direction, onto which a shadow ray (all of it) projects
 * to one point.  An item is listed in every cell its box's projection
 * covers, one cell more on each side (for rounding, and for a ray that
 * starts a little off its hit and so passes beside the light, not
 * through it); an item whose box comes nearer a point light than
 * RENDER_LB_NEAR times that offset, or whose box is saturated, in every
 * cell.  A ray whose walk meets an item's box therefore finds the item in
 * its cell: walking the cell's items box first gives the walk of the tree
 * the same primitives to test (test_lightbuf).
 *
 * The NC builds its buffer once a frame as it sets up
 * (render_lightbuf_build, in memory of render_lightbuf_bytes; the trace
 * counts it in the NC's set-up); render_ctx_t.light_buffer points at it.
 * The same image with it or without (test_lightbuf). */
#ifndef RENDER_LIGHTBUF_H
#define RENDER_LIGHTBUF_H

#include "render/render.h"

#define RENDER_LB_ITEMS 32 /* items a light's cells list: a bit of a mask each */
#define RENDER_LB_CELLS 32 /* cells along a grid's edge */
#define RENDER_LB_CLUSTER 0x80000000u /* an item that is a cluster's subtree */
#define RENDER_LB_NEAR 4 /* an item nearer a point light than this times a
                            ray's offset from it times the cells a unit of
                            its finest grid: in every cell */

enum render_lb_kind {
    RENDER_LB_ALL,    /* no grid: every cell lists every item */
    RENDER_LB_CUBE,   /* a point or spot light: six faces around it */
    RENDER_LB_PLANE,  /* a parallel light: one grid across its direction */
};

/* A grid of cells over coordinates u, v: cell (u - u0) su, (v - v0) sv,
 * clamped to the grid. */
typedef struct {
    num_t u0, v0;
    num_t su, sv;     /* cells a unit */
} render_lb_grid_t;

typedef struct {
    uint8_t kind;     /* enum render_lb_kind */
    uint8_t faces;    /* RENDER_LB_CUBE: the faces that see the root's box
                         (bit `face`); the others list nothing */
    vec3_t at;        /* RENDER_LB_CUBE: the light's position */
    vec3_t pu, pv;    /* RENDER_LB_PLANE: a point's coordinates on the
                         plane of the direction's major axis, along it:
                         its dot products with these */
    uint32_t always;  /* items every cell lists */
    /* RENDER_LB_CUBE: face 2m (+) or 2m + 1 (-) of major axis m, over the
     * other two components (m+1, m+2 mod 3) over the major one's size,
     * across the root's box as it is seen there; RENDER_LB_PLANE: grid 0,
     * over the plane of the major axis, across the root's box's shadow */
    render_lb_grid_t grid[6];
    /* An item covers a rectangle of a grid's cells, so a cell's items are
     * those of its column and its row: cell (u, v) lists
     * mask[grid][0][u] & mask[grid][1][v], exactly the items whose
     * rectangle holds it. */
    uint32_t mask[6][2][RENDER_LB_CELLS]; /* [grid][0: u, 1: v][cell] */
} render_lb_light_t;

typedef struct render_lightbuf {
    uint32_t item_count;
    uint32_t item[RENDER_LB_ITEMS]; /* a primitive's index, or a cluster's
                                       with RENDER_LB_CLUSTER */
    uint32_t light_count;
    render_lb_light_t light[];      /* frame->light_count */
} render_lightbuf_t;

/* The bytes render_lightbuf_build needs for frame f. */
size_t render_lightbuf_bytes(const render_frame_t *f);
/* Builds f's light buffer in mem (bytes of it, aligned for a num_t): NULL
 * when bytes fall short or f has no cluster tree. */
const render_lightbuf_t *render_lightbuf_build(const render_frame_t *f, void *mem, size_t bytes);
/* The items a shadow ray from origin along dir towards light may meet. */
uint32_t render_lightbuf_mask(const render_lightbuf_t *lb, uint32_t light, vec3_t origin,
                              vec3_t dir);

#endif
