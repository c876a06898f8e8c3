/* arith_auto.h: `--arith auto` of `links1 ref` and `links1 render`: for one
 * scene, the cheapest arithmetic and format the unit computer can run that
 * keeps the target PSNR, judged from a low-resolution pre-render
 * (docs/renderer.md, "--arith auto").  `--auto` (opts.model) chooses the
 * model with it: density steps and min_weight (adaptive depth) per
 * candidate, against double at the most accurate model (ARITH_AUTO_REF_*),
 * then the cheapest candidate as below (docs/renderer.md, "--auto").
 *
 *   error  each candidate's host build against the double build, both at
 *          the pre-render size: PSNR over the image, and PSNR over the
 *          pixels it flagged as lost precision (--mark-lost), which must
 *          meet the target on their own
 *   cost   NC guest instructions per pixel of the same pre-render on the
 *          board (links1 render --count-insns) with the candidate's
 *          firmware of the machine rendering (--machine: on an521 the
 *          M33's builds, soft and fixed without an FPU); the host's fixed formats other than the board's
 *          Q12.19 run the same code with other shift counts and take the
 *          fixed firmware's count
 *   pick   the cheapest candidate that meets the target; among those
 *          within ARITH_AUTO_TIE of the cheapest, the most accurate */
#ifndef LINKS1_HOST_SCENE_ARITH_AUTO_H
#define LINKS1_HOST_SCENE_ARITH_AUTO_H

#include <stddef.h>

#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_opts.h"

#define ARITH_AUTO_TARGET_DB 40.0   /* --target-db default */
#define ARITH_AUTO_PIXELS 3072      /* the pre-render has at most this many pixels (64x48) */
/* --auto's host pre-render (the model search and each candidate's error):
 * thin features (a density sphere's) decide a few pixels, and a 64x48
 * pre-render misjudges their steps (docs/results/arith-auto.md, "--auto");
 * host renders are cheap, the board's cost pre-render stays at
 * ARITH_AUTO_PIXELS */
#define ARITH_AUTO_MODEL_PIXELS 19200 /* 160x120 */
/* --auto on a render larger than its pre-render: the whole pre-render must
 * keep this much more than the target (thin features' PSNR moves by 1-2.5
 * dB between 160x120, 200x150 and 320x240: docs/results/arith-auto.md) */
#define ARITH_AUTO_MARGIN_DB 2.0
/* --auto on a render larger than its pre-render: a density sphere's steps
 * are judged again at the render's size for the candidates costing at
 * most this many times the cheapest so judged (auto_confirm_cheapest) */
#define ARITH_AUTO_CONFIRM_REACH 2.0
/* --auto: the flagged pixels must keep the target on their own when they
 * are at least this share of the pre-render; a PSNR over fewer (4 of
 * 19200 on tir_chain 1 in float) says little, and the whole image judges
 * them */
#define ARITH_AUTO_MIN_FLAGGED 0.001
#define ARITH_AUTO_TIE 0.01         /* costs this close count as equal */
#define ARITH_AUTO_NCS 2            /* NCs of the board pre-render (the count is their sum) */
/* --auto: the reference model (SCN_MAX_DENSITY_STEPS steps, the lowest
 * min_weight rung), the most accurate a candidate may take, and the highest */
#define ARITH_AUTO_REF_WEIGHT (1.0 / 4096)
#define ARITH_AUTO_MAX_WEIGHT (1.0 / 4)       /* the highest */

enum arith_auto_target {
    ARITH_AUTO_HOST,  /* links1 ref: every host build (fixed formats of links1-ref-fixedN) */
    ARITH_AUTO_BOARD, /* links1 render: board firmware only */
};

struct arith_auto_opts {
    int fpu;              /* 1: the unit computer has VFP (float a candidate); 0: none */
    int machine;          /* ARITH_AUTO_BOARD: the machine whose firmware the costs are
                             counted on (enum machine_id, proto/machines.h) */
    double target_db;
    enum arith_auto_target target;
    int width, height;    /* the render's size (--size), 0: the scene's */
    const char *const *words; /* options both links1-ref-* and links1 render take
                                 (--max-depth, --frame, ...), NULL-terminated */
    int model;            /* 1: --auto: density steps and min_weight chosen too
                             (words hold neither) */
};

struct arith_auto_choice {
    char build[24];   /* the host build: links1-ref-<build> */
    char arith[8];    /* the board firmware of the same bits: float, soft or fixed */
    char label[24];   /* "fixed Q12.19", "soft", ... */
    int density_steps;  /* --auto: the steps chosen; -1: the scene's (no density sphere) */
    double min_weight;  /* --auto: the min_weight chosen; -1: not --auto */
    int escalate;       /* --arith auto: 1 when the pick traces lost pixels again in
                           double (--escalate; the board's -esc firmware) */
};

/* The options of a scene (scene_file.h) and its first frame as words for
 * opts.words, stored in w. */
struct arith_auto_words {
    struct scene_opts_words given; /* the scene options given (scene_opts.h) */
    const char *words[SCENE_OPTS_MAX_WORDS + 2]; /* those, then --frame N */
    char frame[24];
};
struct scene_file_opts;
void arith_auto_scene_words(const struct scene_file_opts *so, long frame,
                            struct arith_auto_words *w);

/* "--fpu vfp|none": 1, 0, or -1 for another word. */
int arith_auto_fpu(const char *word);

/* Chooses for the scene at path; prints the candidates and the pick (two
 * lines on stdout, prefixed by prog; with --auto the second names the
 * binding knob).  0, or -1 after printing why
 * (the double build refuses the scene, no candidate meets the target,
 * a pre-render failed). */
int arith_auto_pick(const char *prog, const char *path, const struct arith_auto_opts *o,
                    struct arith_auto_choice *out);

#endif
