/* scene_bvh.c: the automatic hierarchy (see scene_bvh.h).
 *
 * Method: a top-down bounding volume hierarchy over the primitives of each
 * cluster, built in the cluster's own coordinates.  Each node's primitives
 * are split in two by a binned surface-area heuristic: the centroids'
 * extent along each axis is cut into BVH_BINS equal bins, and of the
 * BVH_BINS - 1 planes between bins on the three axes the one with the least
 *   C_node + C_prim * (A_left * n_left + A_right * n_right) / A_node
 * wins (A: box surface area, n: primitives on each side).  A node becomes a
 * leaf when it holds at most leaf_min primitives (2), or at most leaf_cap
 * (64) and no split is cheaper than testing them all (C_prim * n), a split
 * counting also the DM's work on its two new clusters each frame
 * (C_cluster each), spread over the rays expected through the node: a
 * frame's rays (a camera ray a pixel, a shadow ray a light) times the
 * node's share of the tree root's area.  When the
 * clusters would pass SCN_MAX_CLUSTERS, the tree is built
 * again with the bounds grown by half, while leaf_min <= BVH_LEAF_MIN_TOP.  A node whose
 * centroids all coincide, or that is too near the nesting limit for the
 * heuristic's possibly lopsided splits, is split at the median centroid on
 * its longest axis instead: that tree is balanced, so it fits the remaining
 * depth.  Every node is a cluster with the identity matrix and no keys,
 * appended after the author's clusters (parents still come before their
 * children); the split cluster itself is the tree's root, so it keeps its
 * matrix, its keys and its own child clusters, and everything below it
 * moves with it.  Primitives keep their order and index: only the cluster
 * each one names changes.
 *
 * The NCs test boxes in eye space (unless the scene stays in world
 * coordinates, SCN_OPT_WORLD_SPACE), where a box cut along the cluster's
 * own axes can be much fatter than along the camera's: the tree is built
 * twice, with the primitives' boxes in each cluster's own axes and turned
 * to the frame-0 camera's, and the one whose boxes cost less in the
 * camera's axes (the sum over clusters of box area times the tests a ray
 * into it makes) is kept, the camera's only when at least
 * BVH_CAMERA_GAIN cheaper.
 */
#include "host-tools/scene/scene_bvh.h"
#include "host-tools/scene/scene_mem.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BVH_BINS 16
#define BVH_LEAF_MIN 2      /* first try: never split this few ... */
#define BVH_LEAF_MAX 8      /* ... split more than this where no plane
                               splits them (the median's leaves) ... */
#define BVH_LEAF_CAP SD_AUTO_HIERARCHY_LEAF_CAP /* ... and more than this always */
#define BVH_LEAF_MIN_TOP 32 /* last try when the clusters do not fit (all
                               three grown by half from one try to the next) */
#define BVH_COST_NODE 1.0   /* one box test ... */
#define BVH_COST_PRIM 2.0   /* ... against one primitive test ... */
#define BVH_CAMERA_GAIN 0.99 /* a tree in the camera's axes is kept when
                                its cost is below this times the other's:
                                closer than that, the NCs' work measured
                                either side of equal (docs/scene-format.md) */
#define BVH_COST_CLUSTER 6.0 /* ... and against the DM's work on a cluster
                                each frame (its load, index and
                                preparation, about 500 instructions): the
                                value where the DM's work and the NCs' both
                                fell on the SPD (docs/scene-format.md) */

/* A cluster's coordinates turned to the camera's axes (rows: right, up,
 * forward), the linear part. */
typedef double bvh_axes_t[3][3];

struct bvh_item {
    double lo[3], hi[3], c[3];
    double key; /* centroid on the median split's axis */
    int prim;
};

struct bvh_build {
    const struct sd_scene *in;
    struct sd_cluster *clusters; /* grows */
    int n_clusters, cap_clusters;
    int *prim_cluster;           /* new cluster of each primitive */
    int leaf_min, leaf_max, leaf_cap;
    double rays;      /* a frame's rays: a camera ray a pixel, a shadow ray
                         a light (0: no view, no cost of clusters) */
    double root_area; /* the box area of the tree being built */
    const bvh_axes_t *axes; /* NULL: each primitive's box in its cluster's
                               own axes; else in axes[c] (cluster c's
                               turned to the camera's) */
    struct bvh_item *items, *spare; /* room for every primitive (+1) */
    struct bvh_build_stats *stats;
};

static void bvh_box_empty(double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = HUGE_VAL;
        hi[k] = -HUGE_VAL;
    }
}

static void bvh_box_add(double lo[3], double hi[3], const double plo[3], const double phi[3])
{
    for (int k = 0; k < 3; k++) { /* no NaN here: comparisons, not libm's calls */
        lo[k] = plo[k] < lo[k] ? plo[k] : lo[k];
        hi[k] = phi[k] > hi[k] ? phi[k] : hi[k];
    }
}

static double bvh_area(const double lo[3], const double hi[3])
{
    if (lo[0] > hi[0])
        return 0;
    double d[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    return 2 * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0]);
}

void sd_prim_bounds(const struct sd_scene *s, const struct sd_prim *p, double lo[3], double hi[3])
{
    bvh_box_empty(lo, hi);
    switch (p->kind) {
    case SCN_PRIM_TRIANGLE:
        for (int v = 0; v < 3; v++)
            bvh_box_add(lo, hi, &p->v[3 * v], &p->v[3 * v]);
        break;
    case SCN_PRIM_ELLIPSOID:
    case SCN_PRIM_BOX:
        for (int k = 0; k < 3; k++) {
            lo[k] = p->v[k] - fabs(p->v[3 + k]);
            hi[k] = p->v[k] + fabs(p->v[3 + k]);
        }
        break;
    case SCN_PRIM_CONE: /* its end discs: r sqrt(1 - a_k^2) on axis k */
        for (int e = 0; e < 2; e++) {
            const double *c = &p->v[4 * e];
            double a[3] = {p->v[4] - p->v[0], p->v[5] - p->v[1], p->v[6] - p->v[2]};
            double len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), elo[3], ehi[3];
            for (int k = 0; k < 3; k++) {
                double ak = len > 0 ? a[k] / len : 0;
                double ext = c[3] * sqrt(fmax(0, 1 - ak * ak));
                elo[k] = c[k] - ext;
                ehi[k] = c[k] + ext;
            }
            bvh_box_add(lo, hi, elo, ehi);
        }
        break;
    default: /* DENSITY: every component's ball */
        for (int i = 0; i < p->count; i++) {
            const struct sd_component *c = &s->components[p->first + i];
            double clo[3], chi[3];
            for (int k = 0; k < 3; k++) {
                clo[k] = c->centre[k] - c->radius;
                chi[k] = c->centre[k] + c->radius;
            }
            bvh_box_add(lo, hi, clo, chi);
        }
        break;
    }
}

/* The box around centre c with half sizes h along the axes of a, turned
 * by a: of a box its corners' (l1: the sum of |a_ij| h_j), of an
 * ellipsoid with those semi-axes its own (the root of the sum of
 * (a_ij h_j)^2). */
static void bvh_turned_box(const double (*a)[3], const double c[3], const double h[3], int l1,
                           double lo[3], double hi[3])
{
    for (int i = 0; i < 3; i++) {
        double ci = a[i][0] * c[0] + a[i][1] * c[1] + a[i][2] * c[2], e = 0;
        for (int j = 0; j < 3; j++)
            e += l1 ? fabs(a[i][j]) * h[j] : a[i][j] * a[i][j] * h[j] * h[j];
        e = l1 ? e : sqrt(e);
        lo[i] = ci - e;
        hi[i] = ci + e;
    }
}

/* The box of primitive p in its cluster's coordinates turned by a, or as
 * they are (a NULL): a triangle's vertices turned, an ellipsoid's or a
 * density sphere's balls bounded as they turn, a box's corners, a cone's
 * box's corners. */
static void bvh_prim_box(const struct sd_scene *s, const struct sd_prim *p,
                         const double (*a)[3], double lo[3], double hi[3])
{
    if (!a || p->kind == SCN_PRIM_BOX || p->kind == SCN_PRIM_CONE) {
        sd_prim_bounds(s, p, lo, hi);
        if (!a)
            return;
        double c[3], h[3];
        for (int k = 0; k < 3; k++) {
            c[k] = 0.5 * (lo[k] + hi[k]);
            h[k] = 0.5 * (hi[k] - lo[k]);
        }
        bvh_turned_box(a, c, h, 1, lo, hi);
        return;
    }
    bvh_box_empty(lo, hi);
    if (p->kind == SCN_PRIM_ELLIPSOID) {
        bvh_turned_box(a, &p->v[0], &p->v[3], 0, lo, hi);
    } else if (p->kind == SCN_PRIM_TRIANGLE) {
        for (int v = 0; v < 3; v++) {
            const double *q = &p->v[3 * v];
            double t[3];
            for (int i = 0; i < 3; i++)
                t[i] = a[i][0] * q[0] + a[i][1] * q[1] + a[i][2] * q[2];
            bvh_box_add(lo, hi, t, t);
        }
    } else { /* DENSITY: every component's ball */
        for (int i = 0; i < p->count; i++) {
            const struct sd_component *c = &s->components[p->first + i];
            double r[3] = {c->radius, c->radius, c->radius}, clo[3], chi[3];
            bvh_turned_box(a, c->centre, r, 0, clo, chi);
            bvh_box_add(lo, hi, clo, chi);
        }
    }
}

/* The frame-0 camera's axes as rows (right, up, forward: render/prepare.c's
 * eye space up to the order and sign of the axes, which no box's area
 * sees); 0 when the scene stays in world coordinates. */
static int bvh_camera_axes(const struct sd_scene *s, double r[3][3])
{
    if (s->view.flags & SCN_OPT_WORLD_SPACE)
        return 0;
    struct sd_view v;
    struct sd_light lights[SCN_MAX_LIGHTS];
    sd_view_at(s, 0, &v, lights);
    double *f = r[2], *x = r[0], *y = r[1];
    for (int k = 0; k < 3; k++)
        f[k] = v.look_at[k] - v.eye[k];
    for (int k = 0; k < 3; k++) /* right = up x forward */
        x[k] = v.up[(k + 1) % 3] * f[(k + 2) % 3] - v.up[(k + 2) % 3] * f[(k + 1) % 3];
    for (int k = 0; k < 3; k++) /* up' = forward x right */
        y[k] = f[(k + 1) % 3] * x[(k + 2) % 3] - f[(k + 2) % 3] * x[(k + 1) % 3];
    for (int i = 0; i < 3; i++) {
        double len = sqrt(r[i][0] * r[i][0] + r[i][1] * r[i][1] + r[i][2] * r[i][2]);
        if (!(len > 0) || !isfinite(len))
            return 0;
        for (int k = 0; k < 3; k++)
            r[i][k] /= len;
    }
    return 1;
}

/* axes[c]: cluster c's coordinates turned to the camera's axes cam at
 * frame 0 (its keyed placement times its matrix, under its parent's). */
static void bvh_cluster_axes(const struct sd_scene *s, const double cam[3][3],
                             bvh_axes_t *axes)
{
    for (int c = 0; c < s->n_clusters; c++) {
        int p = c == 0 ? -1 : s->clusters[c].parent;
        const double(*up)[3] = p < 0 ? cam : (const double(*)[3])axes[p];
        double k[12], local[12];
        sd_key_matrix(s, c, 0, k);
        sd_mat_mul(k, s->clusters[c].m, local);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                axes[c][i][j] = up[i][0] * local[j] + up[i][1] * local[4 + j] +
                                up[i][2] * local[8 + j];
    }
}

/* The area of the box around it[0..n). */
static double bvh_items_area(const struct bvh_item *it, int n)
{
    double lo[3], hi[3];
    bvh_box_empty(lo, hi);
    for (int i = 0; i < n; i++)
        bvh_box_add(lo, hi, it[i].lo, it[i].hi);
    return bvh_area(lo, hi);
}

/* A new identity cluster under parent; its index, or -1 past the limit. */
static int bvh_new_cluster(struct bvh_build *b, int parent)
{
    if (b->n_clusters >= SCN_MAX_CLUSTERS)
        return -1;
    if (b->n_clusters == b->cap_clusters) {
        int cap = b->cap_clusters * 2;
        struct sd_cluster *na = scene_mem_realloc(b->clusters, (size_t)cap * sizeof *na);
        if (!na)
            return -1;
        b->clusters = na;
        b->cap_clusters = cap;
    }
    struct sd_cluster *c = &b->clusters[b->n_clusters];
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "auto%d", b->n_clusters);
    c->parent = parent;
    c->m[0] = c->m[5] = c->m[10] = 1;
    return b->n_clusters++;
}

static int bvh_cmp_key(const void *pa, const void *pb)
{
    const struct bvh_item *a = pa, *b = pb;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return (a->prim > b->prim) - (a->prim < b->prim);
}

/* Median split on the longest centroid axis: returns the left count. */
static int bvh_median(struct bvh_item *it, int n, const double clo[3], const double chi[3])
{
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (chi[k] - clo[k] > chi[axis] - clo[axis])
            axis = k;
    for (int i = 0; i < n; i++)
        it[i].key = it[i].c[axis];
    qsort(it, (size_t)n, sizeof *it, bvh_cmp_key);
    return n / 2;
}

static int bvh_bin(const struct bvh_item *it, int axis, double lo, double scale)
{
    int k = (int)((it->c[axis] - lo) * scale);
    return k < 0 ? 0 : k >= BVH_BINS ? BVH_BINS - 1 : k;
}

/* Binned SAH: best axis and bin boundary (left = bins 0..split).  Returns
 * the cost relative to the node's area, or HUGE_VAL if no plane splits. */
static double bvh_sah(const struct bvh_item *it, int n, const double clo[3], const double chi[3],
                      int *best_axis, int *best_split)
{
    double best = HUGE_VAL;
    for (int axis = 0; axis < 3; axis++) {
        double ext = chi[axis] - clo[axis];
        if (!(ext > 0))
            continue;
        double scale = BVH_BINS / ext;
        int count[BVH_BINS] = {0};
        double lo[BVH_BINS][3], hi[BVH_BINS][3];
        for (int k = 0; k < BVH_BINS; k++)
            bvh_box_empty(lo[k], hi[k]);
        for (int i = 0; i < n; i++) {
            int k = bvh_bin(&it[i], axis, clo[axis], scale);
            count[k]++;
            bvh_box_add(lo[k], hi[k], it[i].lo, it[i].hi);
        }
        /* right-to-left sweep keeps the right sides' areas and counts */
        double right_area[BVH_BINS];
        int right_n[BVH_BINS];
        double rlo[3], rhi[3];
        bvh_box_empty(rlo, rhi);
        int rn = 0;
        for (int k = BVH_BINS - 1; k > 0; k--) {
            bvh_box_add(rlo, rhi, lo[k], hi[k]);
            rn += count[k];
            right_area[k] = bvh_area(rlo, rhi);
            right_n[k] = rn;
        }
        double llo[3], lhi[3];
        bvh_box_empty(llo, lhi);
        int ln = 0;
        for (int k = 0; k < BVH_BINS - 1; k++) {
            bvh_box_add(llo, lhi, lo[k], hi[k]);
            ln += count[k];
            if (ln == 0 || right_n[k + 1] == 0)
                continue;
            double cost = bvh_area(llo, lhi) * ln + right_area[k + 1] * right_n[k + 1];
            if (cost < best) {
                best = cost;
                *best_axis = axis;
                *best_split = k;
            }
        }
    }
    return best;
}

static void bvh_leaf(struct bvh_build *b, int node, const struct bvh_item *it, int n)
{
    for (int i = 0; i < n; i++)
        b->prim_cluster[it[i].prim] = node;
    b->stats->leaves++;
    if (n > b->stats->largest_leaf)
        b->stats->largest_leaf = n;
}

/* 1 when a node of n primitives (n <= leaf_cap), its box of area `area`,
 * stays a leaf: no split pays, its split_cost (the SAH's, for a ray
 * through it) plus the DM's work on its two new clusters, spread over the
 * rays expected through it, being at least the test of all n. */
static int bvh_leaf_pays(const struct bvh_build *b, int n, double area, double split_cost)
{
    double build = 0;
    if (b->rays > 0 && b->root_area > 0) {
        double through = b->rays * area / b->root_area;
        build = through > 0 ? 2 * BVH_COST_CLUSTER / through : HUGE_VAL;
    }
    return n <= b->leaf_cap && split_cost + build >= BVH_COST_PRIM * n;
}

/* ceil(log2(ceil(n / leaf_max))): the levels a balanced tree needs. */
static int bvh_levels(int n, int leaf_max)
{
    int levels = 0;
    for (long m = leaf_max; m < n; m *= 2)
        levels++;
    return levels;
}

/* Splits items it[0..n) below cluster node; depth_left more levels may
 * hang below it; spare[0..n) is room to partition into.  0, or -1 when
 * the clusters run out. */
static int bvh_split(struct bvh_build *b, int node, struct bvh_item *it, struct bvh_item *spare,
                     int n, int depth_left, int depth)
{
    if (depth > b->stats->depth)
        b->stats->depth = depth;
    if (n <= b->leaf_min || depth_left == 0) {
        bvh_leaf(b, node, it, n);
        return 0;
    }
    double lo[3], hi[3], clo[3], chi[3];
    bvh_box_empty(lo, hi);
    bvh_box_empty(clo, chi);
    for (int i = 0; i < n; i++) {
        bvh_box_add(lo, hi, it[i].lo, it[i].hi);
        bvh_box_add(clo, chi, it[i].c, it[i].c);
    }
    int axis = 0, split = 0, left;
    double cost = HUGE_VAL;
    int balanced = depth_left < bvh_levels(n, b->leaf_max) + 2;
    if (!balanced)
        cost = bvh_sah(it, n, clo, chi, &axis, &split);
    if (cost == HUGE_VAL) {
        if (n <= b->leaf_max) {
            bvh_leaf(b, node, it, n);
            return 0;
        }
        left = bvh_median(it, n, clo, chi);
    } else {
        double area = bvh_area(lo, hi);
        double split_cost = BVH_COST_NODE + BVH_COST_PRIM * (area > 0 ? cost / area : n);
        if (bvh_leaf_pays(b, n, area, split_cost)) {
            bvh_leaf(b, node, it, n);
            return 0;
        }
        /* partition by bin into spare, stable for a deterministic tree:
         * the halves are split there, with it[] their spare room */
        double scale = BVH_BINS / (chi[axis] - clo[axis]);
        left = 0;
        for (int i = 0; i < n; i++)
            if (bvh_bin(&it[i], axis, clo[axis], scale) <= split)
                spare[left++] = it[i];
        int r = left;
        for (int i = 0; i < n; i++)
            if (bvh_bin(&it[i], axis, clo[axis], scale) > split)
                spare[r++] = it[i];
        struct bvh_item *was = it;
        it = spare;
        spare = was;
    }
    int a = bvh_new_cluster(b, node);
    int c = a < 0 ? -1 : bvh_new_cluster(b, node);
    if (c < 0)
        return -1;
    b->stats->nodes += 2;
    if (bvh_split(b, a, it, spare, left, depth_left - 1, depth + 1) != 0)
        return -1;
    return bvh_split(b, c, it + left, spare + left, n - left, depth_left - 1, depth + 1);
}

/* Nesting depth of each author cluster below the root. */
static void bvh_nesting(const struct sd_scene *s, int *nest)
{
    for (int i = 0; i < s->n_clusters; i++)
        nest[i] = i == 0 || s->clusters[i].parent < 0 ? 0 : nest[s->clusters[i].parent] + 1;
}

static int bvh_try(struct bvh_build *b, const int *nest, int leaf_min)
{
    const struct sd_scene *s = b->in;
    b->leaf_min = leaf_min;
    b->leaf_max = leaf_min * (BVH_LEAF_MAX / BVH_LEAF_MIN);
    b->leaf_cap = leaf_min * (BVH_LEAF_CAP / BVH_LEAF_MIN);
    b->n_clusters = s->n_clusters;
    memcpy(b->clusters, s->clusters, (size_t)s->n_clusters * sizeof *s->clusters);
    memset(b->stats, 0, sizeof *b->stats);
    for (int i = 0; i < s->n_prims; i++)
        b->prim_cluster[i] = s->prims[i].cluster;
    /* the primitives of each cluster, in index order */
    int *count = calloc((size_t)s->n_clusters + 1, sizeof *count);
    int *at = malloc(((size_t)s->n_clusters + 1) * sizeof *at);
    if (!count || !at) {
        free(count);
        free(at);
        return -1;
    }
    for (int i = 0; i < s->n_prims; i++)
        count[s->prims[i].cluster + 1]++;
    for (int c = 0; c < s->n_clusters; c++)
        count[c + 1] += count[c];
    memcpy(at, count, ((size_t)s->n_clusters + 1) * sizeof *at);
    struct bvh_item *items = b->items, *spare = b->spare;
    for (int i = 0; i < s->n_prims; i++) {
        int c = s->prims[i].cluster;
        struct bvh_item *it = &items[at[c]++];
        bvh_prim_box(s, &s->prims[i], b->axes ? (const double(*)[3])b->axes[c] : NULL, it->lo,
                     it->hi);
        for (int k = 0; k < 3; k++)
            it->c[k] = 0.5 * (it->lo[k] + it->hi[k]);
        it->prim = i;
    }
    free(at);
    int rc = 0;
    for (int c = 0; c < s->n_clusters && rc == 0; c++) {
        int n = count[c + 1] - count[c];
        if (n <= SD_AUTO_HIERARCHY_MIN)
            continue;
        b->stats->split_clusters++;
        b->root_area = bvh_items_area(items + count[c], n);
        rc = bvh_split(b, c, items + count[c], spare + count[c], n,
                       SCN_MAX_CLUSTER_NESTING - nest[c], 0);
    }
    free(count);
    return rc;
}

/* b's tree, larger leaves tried until its clusters fit (they need fewer):
 * 0, or -1 with *tried the last leaf_min tried. */
static int bvh_grow(struct bvh_build *b, const int *nest, int *tried)
{
    int rc = -1;
    for (int leaf_min = BVH_LEAF_MIN; rc != 0 && leaf_min <= BVH_LEAF_MIN_TOP;
         leaf_min += (leaf_min + 1) / 2) { /* 2, 3, 5, 8, 12, 18, 27 */
        rc = bvh_try(b, nest, leaf_min);
        *tried = leaf_min;
    }
    return rc;
}

/* The cost of b's tree with every primitive's box in axes (its cluster's
 * turned to the camera's): over the clusters, the box's area times the
 * tests a ray into it makes (a box test a child, a primitive test a
 * primitive).  HUGE_VAL when memory runs out. */
static double bvh_tree_cost(const struct bvh_build *b, const bvh_axes_t *axes)
{
    const struct sd_scene *s = b->in;
    size_t n = (size_t)b->n_clusters;
    double(*lo)[3] = malloc(n * sizeof *lo), (*hi)[3] = malloc(n * sizeof *hi);
    double *tests = calloc(n, sizeof *tests);
    double cost = HUGE_VAL;
    if (lo && hi && tests) {
        for (size_t c = 0; c < n; c++)
            bvh_box_empty(lo[c], hi[c]);
        for (int i = 0; i < s->n_prims; i++) {
            double plo[3], phi[3];
            int c = b->prim_cluster[i];
            bvh_prim_box(s, &s->prims[i], (const double(*)[3])axes[s->prims[i].cluster], plo,
                         phi);
            bvh_box_add(lo[c], hi[c], plo, phi);
            tests[c] += BVH_COST_PRIM;
        }
        for (int c = b->n_clusters - 1; c >= s->n_clusters; c--) { /* children after parents */
            int p = b->clusters[c].parent;
            bvh_box_add(lo[p], hi[p], lo[c], hi[c]);
            tests[p] += BVH_COST_NODE;
        }
        cost = 0;
        for (size_t c = 0; c < n; c++)
            cost += bvh_area(lo[c], hi[c]) * tests[c];
    }
    free(lo);
    free(hi);
    free(tests);
    return cost;
}

/* One of the two trees: its build (into prim_cluster and stats, the
 * primitives' boxes in axes, NULL for their clusters' own, in its own room
 * items and spare), its result, and its cost with the boxes in the
 * camera's axes (eval; NULL: not asked). */
struct bvh_candidate {
    struct bvh_build b;
    const int *nest;
    const bvh_axes_t *eval;
    int rc, tried;
    double cost;
};

static int bvh_candidate_init(struct bvh_candidate *k, const struct sd_scene *s,
                              const int *nest, int *prim_cluster, struct bvh_build_stats *stats,
                              const bvh_axes_t *axes)
{
    struct bvh_build *b = &k->b;
    size_t room = (size_t)s->n_prims + 1;
    memset(k, 0, sizeof *k);
    k->nest = nest;
    k->rc = -1;
    k->cost = HUGE_VAL;
    b->in = s;
    b->stats = stats;
    b->prim_cluster = prim_cluster;
    b->axes = axes;
    if (s->view.width > 0 && s->view.height > 0)
        b->rays = (double)s->view.width * s->view.height * (1 + s->n_lights);
    b->cap_clusters = s->n_clusters + 2 * s->n_prims / BVH_LEAF_MAX + 16;
    b->clusters = scene_mem_alloc((size_t)b->cap_clusters * sizeof *b->clusters);
    b->items = scene_mem_alloc(room * sizeof *b->items);
    b->spare = scene_mem_alloc(room * sizeof *b->spare);
    return b->clusters && b->items && b->spare && prim_cluster ? 0 : -1;
}

static void bvh_candidate_free(struct bvh_candidate *k)
{
    free(k->b.clusters);
    free(k->b.items);
    free(k->b.spare);
    k->b.clusters = NULL;
    k->b.items = k->b.spare = NULL;
}

/* Builds candidate arg and costs it (a thread's body, or called). */
static void *bvh_candidate_run(void *arg)
{
    struct bvh_candidate *k = arg;
    k->rc = bvh_grow(&k->b, k->nest, &k->tried);
    if (k->rc == 0 && k->eval)
        k->cost = bvh_tree_cost(&k->b, k->eval);
    return NULL;
}

/* own (its clusters' axes) and turned (the camera's) built side by side,
 * turned in a second thread (or after own where none starts). */
static void bvh_build_both(struct bvh_candidate *own, struct bvh_candidate *turned)
{
    pthread_t th;
    int threaded = pthread_create(&th, NULL, bvh_candidate_run, turned) == 0;
    bvh_candidate_run(own);
    if (threaded)
        pthread_join(th, NULL);
    else
        bvh_candidate_run(turned);
}

/* The camera's tree kept in own's place when it costs less by
 * BVH_CAMERA_GAIN (or own has none); own's stats say which and both
 * costs. */
static void bvh_keep_cheaper(struct bvh_candidate *own, struct bvh_candidate *turned)
{
    const struct sd_scene *s = own->b.in;
    double own_cost = own->rc == 0 ? own->cost : HUGE_VAL;
    int keep = turned->rc == 0 && turned->cost < BVH_CAMERA_GAIN * own_cost;
    if (keep) {
        memcpy(own->b.prim_cluster, turned->b.prim_cluster, (size_t)s->n_prims * sizeof(int));
        *own->b.stats = *turned->b.stats;
        struct sd_cluster *c = own->b.clusters;
        own->b.clusters = turned->b.clusters;
        own->b.n_clusters = turned->b.n_clusters;
        turned->b.clusters = c;
        own->rc = 0;
    }
    own->b.stats->camera_axes = keep;
    own->b.stats->cost_own = own_cost;
    own->b.stats->cost_camera = turned->rc == 0 ? turned->cost : HUGE_VAL;
}

/* 1 when every row of every cluster's axes is a unit axis or its
 * negative: the turned boxes are the own ones, the axes in another order. */
static int bvh_axes_aligned(const struct sd_scene *s, const bvh_axes_t *axes)
{
    for (int c = 0; c < s->n_clusters; c++)
        for (int i = 0; i < 3; i++) {
            int ones = 0, zeros = 0;
            for (int j = 0; j < 3; j++) {
                ones += fabs(axes[c][i][j]) == 1;
                zeros += axes[c][i][j] == 0;
            }
            if (ones != 1 || zeros != 2)
                return 0;
        }
    return 1;
}

/* Each author cluster's axes turned to the frame-0 camera's (malloc'ed),
 * or NULL when no second tree is to be built: the scene stays in world
 * coordinates, the turned axes are the own ones in another order, or
 * memory ran out (*oom = 1). */
static bvh_axes_t *bvh_turned_axes(const struct sd_scene *s, int *oom)
{
    double cam[3][3];
    *oom = 0;
    if (!bvh_camera_axes(s, cam))
        return NULL;
    bvh_axes_t *axes = malloc(((size_t)s->n_clusters + 1) * sizeof *axes);
    if (!axes) {
        *oom = 1;
        return NULL;
    }
    bvh_cluster_axes(s, cam, axes);
    if (!bvh_axes_aligned(s, (const bvh_axes_t *)axes))
        return axes;
    free(axes);
    return NULL;
}

int sd_auto_hierarchy(const struct sd_scene *s, struct sd_cluster **clusters, int *n_clusters,
                      int *prim_cluster, struct bvh_build_stats *stats, char *err, size_t errlen)
{
    int oom;
    bvh_axes_t *axes = bvh_turned_axes(s, &oom);
    int turn = axes != NULL;
    int *nest = malloc(((size_t)s->n_clusters + 1) * sizeof *nest);
    int *turned_cluster = turn ? scene_mem_alloc(((size_t)s->n_prims + 1) * sizeof(int)) : NULL;
    struct bvh_candidate own, turned;
    struct bvh_build_stats turned_stats;
    const bvh_axes_t *eval = (const bvh_axes_t *)axes;
    int ok = nest && !oom;
    ok = bvh_candidate_init(&own, s, nest, prim_cluster, stats, NULL) == 0 && ok;
    ok = (!turn || bvh_candidate_init(&turned, s, nest, turned_cluster, &turned_stats, eval) == 0) &&
         ok;
    if (ok) {
        bvh_nesting(s, nest);
        if (turn) {
            own.eval = eval;
            turned.eval = eval;
            bvh_build_both(&own, &turned);
            bvh_keep_cheaper(&own, &turned);
        } else {
            bvh_candidate_run(&own);
        }
    }
    if (turn)
        bvh_candidate_free(&turned);
    free(nest);
    free(turned_cluster);
    free(axes);
    struct sd_cluster *tree = own.b.clusters;
    own.b.clusters = NULL;
    bvh_candidate_free(&own);
    if (!ok || own.rc != 0) {
        free(tree);
        if (!ok)
            snprintf(err, errlen, "out of memory building the automatic hierarchy");
        else
            snprintf(err, errlen,
                     "automatic hierarchy: %d primitives need more than SCN_MAX_CLUSTERS (%d) "
                     "clusters even with leaves of %d or more; split the scene or turn "
                     "auto_hierarchy off",
                     s->n_prims, SCN_MAX_CLUSTERS, own.tried);
        return -1;
    }
    *clusters = tree;
    *n_clusters = own.b.n_clusters;
    return 0;
}
