/* scene_file.h: a scene file as `links1 ref` and `links1 render` take it
 * (a text scene, compiled here, or an already compiled .l1s file) and the
 * names of their per-frame output files. */
#ifndef LINKS1_HOST_SCENE_FILE_H
#define LINKS1_HOST_SCENE_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "host-tools/scene/scene_desc.h"

/* Changes to a text scene before it is compiled. */
struct scene_file_opts {
    int width, height;  /* --size WxH; 0: the scene's */
    int max_depth;      /* --max-depth D; -1: the scene's */
    double min_weight;  /* --min-weight W (adaptive depth); -1: the scene's */
    int density_steps;  /* the density root finder's steps; -1: the scene's */
    int aa_depth;       /* --aa N: anti-aliasing on, N cuts at most; -1: the scene's */
    double aa_threshold; /* --aa-threshold T; -1: the scene's */
    int no_aa;          /* --no-aa: 1 turns the scene's anti-aliasing off */
    int refractionless; /* --refractionless on|off: 1 or 0; -1: the scene's */
    int refraction;     /* --refraction on|off: 1 or 0; -1: the scene's */
    int no_auto_hierarchy; /* --no-auto-hierarchy: 1 compiles without it */
    int mark_lost;      /* --mark-lost: 1 paints pixels that lost precision */
    int check_lost;     /* --check-lost: 1 checks them in double (SCN_OPT_CHECK_LOST) */
    int world_space;    /* --world-space: 1 prepares in world coordinates
                           (SCN_OPT_WORLD_SPACE) */
    int paper;          /* --paper: 1 sets paper mode (sd_paper_apply) before the
                           other changes, which win over it */
    int spd_rules;      /* --spd-rules: 1 sets Haines's SPD rules (SCN_OPT_SPD_RULES,
                           512x512, depth 4 after the camera ray's, min_weight 0,
                           refraction on, refractionless off, shadows on) before
                           the other changes, which win over it */
    int machine;        /* the machine it is for (proto/machines.h): its limits */
    const char *textures_from[SD_TEXTURES_FROM_MAX + 1]; /* --textures-from DIR: more
                           directories a map's image may come from, NULL-ended */
};

/* How a text scene was compiled (scene_file_bytes_info). */
struct scene_file_info {
    int auto_hierarchy; /* 1 on, 0 off, -1 unknown (a compiled file) */
    int own_clusters;   /* the scene's own clusters, root included (-1 unknown) */
};

/* No changes: the scene as written. */
void scene_file_opts_init(struct scene_file_opts *o);

/* 1 when s ends with suffix. */
int scene_file_ends_with(const char *s, const char *suffix);

/* --textures-from DIR: dir added to o's textures_from when it may be one
 * (sd_textures_from_ok: not / nor a system root nor the home directory)
 * and fewer than SD_TEXTURES_FROM_MAX are given.  0, or -1 with err. */
int scene_file_textures_from(struct scene_file_opts *o, const char *dir, char *err,
                             size_t errlen);

/* The scene at path: a file ending in .nff read as NFF (nff_read.h), any
 * other as the text form (sd_parse_file); -1 with err as those say. */
int scene_file_parse(const char *path, struct sd_scene *s, char *err, size_t errlen);
/* The same, a text scene's map images also read from below the
 * directories of the NULL-ended list textures_from (sd_parse_file_from). */
int scene_file_parse_from(const char *path, const char *const *textures_from,
                          struct sd_scene *s, char *err, size_t errlen);

/* The compiled bytes of the scene at path (malloc'ed into *buf, *len): a
 * file ending in .l1s read as is (refused when empty, over SCN_MAX_SIZE, or
 * when o asks for a change), any other compiled from text (or NFF) with o's
 * changes.
 * 0, or -1 with err saying why ("PATH: why"). */
int scene_file_bytes(const char *path, const struct scene_file_opts *o, uint8_t **buf,
                     size_t *len, char *err, size_t errlen);

/* scene_file_bytes, and how it compiled the scene into *info. */
int scene_file_bytes_info(const char *path, const struct scene_file_opts *o, uint8_t **buf,
                          size_t *len, struct scene_file_info *info, char *err, size_t errlen);

/* out with the frame number before its extension: "a.png", 7 -> "a-0007.png". */
void scene_file_frame_path(const char *out, long frame, char *buf, size_t n);
/* o's changes made to s (paper mode first: the others win over it); when
 * paper mode faceted cones or cylinders, a line on stderr says how many. */
void scene_opts_apply(const struct scene_file_opts *o, struct sd_scene *s);

/* The name (without "--") of the first option o gives that changes the
 * scene ("max-depth"), or NULL when none does (--textures-from changes
 * nothing). */
const char *scene_opts_given(const struct scene_file_opts *o);

/* The name of the first option o gives of those --auto chooses itself
 * (min_weight, density steps, paper mode's fixed depth), or NULL. */
const char *scene_opts_model_given(const struct scene_file_opts *o);

/* The words that give o again on a command line: every option o gives,
 * its value after it; for a pre-render of --arith auto or --auto, only
 * those that change what is judged (not --size, which the pre-render
 * sets, nor --mark-lost, --check-lost and --world-space). */
enum scene_opts_for { SCENE_OPTS_ALL, SCENE_OPTS_PRE_RENDER };
#define SCENE_OPTS_MAX_WORDS (2 * (16 + SD_TEXTURES_FROM_MAX) + 1)
#define SCENE_OPTS_MAX_FLAGS 16 /* options o can give, --textures-from once */
struct scene_opts_words {
    const char *w[SCENE_OPTS_MAX_WORDS]; /* NULL-ended */
    char flag[SCENE_OPTS_MAX_FLAGS][24], value[SCENE_OPTS_MAX_FLAGS][40];
};
/* Fills w from o; the count of words. */
int scene_opts_words(const struct scene_file_opts *o, enum scene_opts_for use,
                     struct scene_opts_words *w);

#endif
