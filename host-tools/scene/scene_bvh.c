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
 */
#include "host-tools/scene/scene_bvh.h"
#include "host-tools/scene/scene_mem.h"

#include <math.h>
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
#define BVH_COST_CLUSTER 6.0 /* ... and against the DM's work on a cluster
                                each frame (its load, index and
                                preparation, about 500 instructions): the
                                value where the DM's work and the NCs' both
                                fell on the SPD (docs/scene-format.md) */

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
    struct bvh_item *items = scene_mem_alloc(((size_t)s->n_prims + 1) * sizeof *items);
    struct bvh_item *spare = scene_mem_alloc(((size_t)s->n_prims + 1) * sizeof *spare);
    if (!count || !items || !spare) {
        free(count);
        free(items);
        free(spare);
        return -1;
    }
    for (int i = 0; i < s->n_prims; i++)
        count[s->prims[i].cluster + 1]++;
    for (int c = 0; c < s->n_clusters; c++)
        count[c + 1] += count[c];
    int *at = malloc(((size_t)s->n_clusters + 1) * sizeof *at);
    if (!at) {
        free(count);
        free(items);
        free(spare);
        return -1;
    }
    memcpy(at, count, ((size_t)s->n_clusters + 1) * sizeof *at);
    for (int i = 0; i < s->n_prims; i++) {
        struct bvh_item *it = &items[at[s->prims[i].cluster]++];
        sd_prim_bounds(s, &s->prims[i], it->lo, it->hi);
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
    free(items);
    free(spare);
    return rc;
}

int sd_auto_hierarchy(const struct sd_scene *s, struct sd_cluster **clusters, int *n_clusters,
                      int *prim_cluster, struct bvh_build_stats *stats, char *err, size_t errlen)
{
    struct bvh_build b;
    memset(&b, 0, sizeof b);
    b.in = s;
    b.stats = stats;
    b.prim_cluster = prim_cluster;
    if (s->view.width > 0 && s->view.height > 0)
        b.rays = (double)s->view.width * s->view.height * (1 + s->n_lights);
    b.cap_clusters = s->n_clusters + 2 * s->n_prims / BVH_LEAF_MAX + 16;
    b.clusters = scene_mem_alloc((size_t)b.cap_clusters * sizeof *b.clusters);
    int *nest = malloc(((size_t)s->n_clusters + 1) * sizeof *nest);
    if (!b.clusters || !nest) {
        free(b.clusters);
        free(nest);
        snprintf(err, errlen, "out of memory building the automatic hierarchy");
        return -1;
    }
    bvh_nesting(s, nest);
    int rc = -1;
    /* larger leaves need fewer clusters: widen until they fit */
    int tried = 0;
    for (int leaf_min = BVH_LEAF_MIN; rc != 0 && leaf_min <= BVH_LEAF_MIN_TOP;
         leaf_min += (leaf_min + 1) / 2) { /* 2, 3, 5, 8, 12, 18, 27 */
        rc = bvh_try(&b, nest, leaf_min);
        tried = leaf_min;
    }
    free(nest);
    if (rc != 0) {
        snprintf(err, errlen,
                 "automatic hierarchy: %d primitives need more than SCN_MAX_CLUSTERS (%d) "
                 "clusters even with leaves of %d or more; split the scene or turn "
                 "auto_hierarchy off",
                 s->n_prims, SCN_MAX_CLUSTERS, tried);
        free(b.clusters);
        return -1;
    }
    *clusters = b.clusters;
    *n_clusters = b.n_clusters;
    return 0;
}
