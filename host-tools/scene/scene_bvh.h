/* scene_bvh.h: the scene compiler's automatic hierarchy.  Every cluster
 * holding more than SD_AUTO_HIERARCHY_MIN primitives becomes the root of a
 * bounding volume hierarchy of new clusters (identity matrix, no keys),
 * built with a binned surface-area heuristic; the method is described in
 * scene_bvh.c and docs/scene-format.md.  The renderer needs nothing new:
 * the nodes are ordinary clusters.  Primitives keep their indices, so the
 * image does not change (ties go to the lower primitive index).
 */
#ifndef LINKS1_HOST_SCENE_BVH_H
#define LINKS1_HOST_SCENE_BVH_H

#include <stddef.h>

#include "host-tools/scene/scene_desc.h"

#define SD_AUTO_HIERARCHY_MIN 4 /* clusters with this many primitives or
                                   fewer are left as they are */
#define SD_AUTO_HIERARCHY_LEAF_CAP 64 /* the most primitives a leaf holds
                                         (the first try's: scene_bvh.c) */

struct bvh_build_stats {
    int split_clusters; /* author clusters that got a tree */
    int nodes;          /* clusters added */
    int leaves;         /* leaf clusters (including unsplit roots) */
    int largest_leaf;   /* primitives in the fullest leaf */
    int depth;          /* deepest level below a split cluster */
    int camera_axes;    /* 1: the tree built in the frame-0 camera's axes
                           was kept (scene_bvh.c) */
    double cost_own, cost_camera; /* both trees' costs in the camera's axes
                                     (0: not built; HUGE_VAL: no tree) */
};

/* The box of primitive p in its cluster's coordinates. */
void sd_prim_bounds(const struct sd_scene *s, const struct sd_prim *p, double lo[3], double hi[3]);

/* The clusters of s with the trees added (*clusters malloc'ed, *n_clusters
 * of them: s's own first, unchanged) and the new cluster of every primitive
 * in prim_cluster[0..s->n_prims).  0, or -1 with err naming the limit
 * (SCN_MAX_CLUSTERS) when the tree cannot fit. */
int sd_auto_hierarchy(const struct sd_scene *s, struct sd_cluster **clusters, int *n_clusters,
                      int *prim_cluster, struct bvh_build_stats *stats, char *err, size_t errlen);

#endif
