/* scene_paper.h: paper mode (docs/scene-format.md, "Paper mode"): every
 * choice the LINKS-1 paper made, set at once by `options { paper on }` or
 * `--paper`.  The scene's part is compiled in (sd_paper_apply,
 * scene_desc.h); the render's part (the schedule, the rule of asking, the
 * clipping) is set here from the compiled scene's SCN_OPT_PAPER flag, so a
 * compiled .l1s file keeps its mode.  What paper mode set is printed in one
 * line (scene_paper_line), built from the compiled bytes and the render
 * arguments actually sent. */
#ifndef LINKS1_HOST_SCENE_PAPER_H
#define LINKS1_HOST_SCENE_PAPER_H

#include <stddef.h>
#include <stdint.h>

#include "proto/render_link.h"

/* What a compiled scene holds of paper mode. */
struct scene_paper {
    int paper;           /* SCN_OPT_PAPER */
    int width, height;
    uint32_t frames;     /* of the animation, 1 for a still */
    int max_depth;
    double min_weight;   /* 0: no weight cut-off */
    int materials;       /* all */
    int mirror_or_clear; /* materials with src or trc above 0 */
    int by_angle;        /* of those, src/trc by angle (fresnel > 0) */
    uint32_t clusters;   /* compiled clusters, root included */
};

/* Reads the VIEW, MATERIALS and CLUSTERS sections of a compiled scene:
 * 0, or -1 with err saying what is malformed. */
int scene_paper_read(const uint8_t *buf, size_t len, struct scene_paper *p, char *err,
                     size_t errlen);

/* Render options the command line gave itself: paper mode leaves them. */
#define SCENE_PAPER_GAVE_BALANCE 1u
#define SCENE_PAPER_GAVE_AREAS 2u
#define SCENE_PAPER_GAVE_ASK 4u
#define SCENE_PAPER_GAVE_CLIP 8u
#define SCENE_PAPER_GAVE_ESCALATE 16u

/* The paper's render choices into *a, but those in given: simple dynamic
 * balancing on the paper's job unit (LINK_BALANCE_LINES) with one area per
 * scanline (K = the height), an NC asking once it has finished, the
 * paper's clipping lists, no escalation. */
void scene_paper_args(const struct scene_paper *p, unsigned given, struct link_render_args *a);

/* One line of what the frame runs with, each of paper mode's settings by
 * name ("paper mode: src/trc by angle (4 of 4 materials that reflect or
 * transmit), depth fixed at 5 (min_weight 0), areas lines K 480 (whole
 * scanlines), ask finished, clip lists, clusters 37 (auto_hierarchy off:
 * the scene's own)").  auto_hierarchy: 1 on, 0 off, -1 unknown (a
 * compiled file); own: the scene's own clusters (root included). */
void scene_paper_line(const struct scene_paper *p, const struct link_render_args *a,
                      int auto_hierarchy, int own, char *out, size_t cap);

#endif
