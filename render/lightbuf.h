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
 * covers, and a 32nd of the grid more on each side (for rounding, for the
 * primitives' uncertain edges, and for a ray that starts a little off its
 * hit and so passes beside the light, not through it); near a point
 * light, where such a ray turns by more than half that on its way to the
 * item, as many cells more as it may turn across; an item whose box comes
 * within 8 such offsets of a point light (or holds it), or is saturated,
 * in every cell.  A ray whose walk meets an item's box (or an edge of it
 * in doubt) therefore finds the item in its cell: walking the cell's
 * items box first gives the walk of the tree the same primitives to test
 * (test_lightbuf).
 *
 * The NC builds its buffer once a frame as it sets up
 * (render_lightbuf_build, in memory of render_lightbuf_bytes; the trace
 * counts it in the NC's set-up); render_ctx_t.light_buffer points at it.
 * The same image with it or without (test_lightbuf). */
#ifndef RENDER_LIGHTBUF_H
#define RENDER_LIGHTBUF_H

#include "render/render.h"
#include "render/vec3.h"

#define RENDER_LB_ITEMS 32 /* items a light's cells list: a bit of a mask each */
#define RENDER_LB_CELLS 128 /* cells along a grid's edge: 6 KiB a light;
                               finer than the margin, fewer items a cell */
#define RENDER_LB_CLUSTER 0x80000000u /* an item that is a cluster's subtree */

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
    /* Item k a box primitive: 1 + the face of its local cube (2 axis, + 1
     * for the - face) the light lies beyond (a parallel light: the one its
     * direction leaves by most), else 0.  A shadow ray beyond that face
     * at both its ends misses the item (prim_face_clear): not walked. */
    uint8_t face[RENDER_LB_ITEMS];
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
/* The cell of coordinate x in a grid from x0 at s cells a unit, clamped. */
static inline int render_lb_grid_cell(num_t x, num_t x0, num_t s)
{
    num_t c = num_mul(num_sub(x, x0), s);
    if (!num_gt(c, NUM_ZERO))
        return 0;
    if (!num_lt(c, num_from_int(RENDER_LB_CELLS - 1)))
        return RENDER_LB_CELLS - 1;
    return num_floor_nonneg_int(c); /* 0 < c < RENDER_LB_CELLS - 1 */
}

/* Where a point p falls on a parallel light's plane: along the direction
 * onto the plane of its major axis. */
static inline void render_lb_project(const render_lb_light_t *l, vec3_t p, num_t *u, num_t *v)
{
    *u = vec3_dot(p, l->pu);
    *v = vec3_dot(p, l->pv);
}

/* The cell of direction d (from the light) on the cube: its face, by the
 * major axis and its sign, and the other two components over it. */
static inline uint32_t render_lb_cube_mask(const render_lb_light_t *l, vec3_t d)
{
    num_t ax = num_abs(d.x), ay = num_abs(d.y), az = num_abs(d.z);
    int face;
    num_t dm, du, dv;
    if (num_ge(ax, ay) && num_ge(ax, az)) {
        face = 0, dm = d.x, du = d.y, dv = d.z;
    } else if (num_ge(ay, az)) {
        face = 2, dm = d.y, du = d.z, dv = d.x;
    } else {
        face = 4, dm = d.z, du = d.x, dv = d.y;
    }
    if (num_lt(dm, NUM_ZERO)) {
        face++;
        dm = num_neg(dm);
    }
    if (!num_gt(dm, NUM_ZERO))
        return UINT32_MAX;
    const render_lb_grid_t *g = &l->grid[face];
    num_t inv = num_recip(dm);
    int u = render_lb_grid_cell(num_mul(du, inv), g->u0, g->su);
    int v = render_lb_grid_cell(num_mul(dv, inv), g->v0, g->sv);
    return l->always | (l->mask[face][0][u] & l->mask[face][1][v]);
}

/* The items a shadow ray from origin along dir towards light may meet:
 * inline, as it is asked for every shadow ray. */
static inline uint32_t render_lightbuf_mask(const render_lightbuf_t *lb, uint32_t light,
                                            vec3_t origin, vec3_t dir)
{
    const render_lb_light_t *l = &lb->light[light];
    uint32_t all = lb->item_count == 32 ? UINT32_MAX : (UINT32_C(1) << lb->item_count) - 1;
    if (l->kind == RENDER_LB_CUBE)
        return render_lb_cube_mask(l, vec3_neg(dir)) & all;
    if (l->kind == RENDER_LB_ALL)
        return all;
    num_t u, v;
    render_lb_project(l, origin, &u, &v);
    const render_lb_grid_t *g = &l->grid[0];
    const uint32_t(*cells)[RENDER_LB_CELLS] = l->mask[0];
    return (l->always | (cells[0][render_lb_grid_cell(u, g->u0, g->su)] &
                         cells[1][render_lb_grid_cell(v, g->v0, g->sv)])) &
           all;
}

#endif
