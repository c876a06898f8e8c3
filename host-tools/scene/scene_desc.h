/* scene_desc.h: a scene as the host tools hold it between the text form
 * (scene_parse.c) and the outputs: the compiled form (scene_compile.c) and
 * POV-Ray (scene_pov.c).  It mirrors proto/scene_format.h record for record,
 * in double precision, with names kept for error messages.
 */
#ifndef LINKS1_HOST_SCENE_DESC_H
#define LINKS1_HOST_SCENE_DESC_H

#include <stddef.h>
#include <stdio.h>
#include <stdint.h>

#include "proto/scene_format.h"

struct sd_view {
    double eye[3], look_at[3], up[3];
    double fov;             /* horizontal, degrees */
    int width, height;
    double background[3];
    int max_depth;
    double min_weight;      /* adaptive depth: 0..1, 0 = off */
    int density_steps;      /* SCN_MIN_DENSITY_STEPS..SCN_MAX_DENSITY_STEPS */
    int aa_depth;           /* 0..SCN_MAX_AA_DEPTH, with SCN_OPT_ANTIALIAS */
    double aa_threshold;    /* 0..1, with SCN_OPT_ANTIALIAS */
    unsigned flags;         /* SCN_OPT_* */
    int frames;
    int haze;               /* 1: haze { colour R G B  distance D } (SCN_SEC_HAZE) */
    double haze_colour[3];  /* 0..1 */
    double haze_distance;   /* 0 < D <= SCN_MAX_COORD */
};

struct sd_light {
    int kind;               /* enum scn_light_kind */
    double colour[3], position[3], direction[3];
    double cone, falloff;   /* degrees */
};

struct sd_material {
    char name[SCN_MAX_NAME];
    double colour[3], dic, drc;
    double src, trc;        /* at normal incidence */
    double fresnel;         /* 0 = constant src/trc */
    double ior;
    int phong;
    int colour_map, bump_map; /* map index or -1 */
    int normal_map;           /* map index (a NORMAL map) or -1; not with bump_map */
    int dic_map, drc_map, src_map, trc_map; /* ATTRIBUTE map index or -1 */
};

/* Every map index of m set to -1 (none). */
static inline void sd_material_no_maps(struct sd_material *m)
{
    m->colour_map = m->bump_map = m->normal_map = -1;
    m->dic_map = m->drc_map = m->src_map = m->trc_map = -1;
}

struct sd_map {
    char name[SCN_MAX_NAME];
    int kind;               /* enum scn_map_kind */
    int width, height;
    uint8_t *texels;        /* width * height * bytes per texel, malloc'ed;
                               the compiled form's bytes (proto/scene_format.h) */
    double repeat_u, repeat_v, bump_depth;
};

/* Bytes per texel of a map of that kind (enum scn_map_kind). */
static inline unsigned sd_map_texel_bytes(int kind)
{
    return kind == SCN_MAP_COLOUR   ? SCN_MAP_COLOUR_BYTES
           : kind == SCN_MAP_NORMAL ? SCN_MAP_NORMAL_BYTES
           : kind == SCN_MAP_BUMP   ? SCN_MAP_BUMP_BYTES
                                    : SCN_MAP_ATTRIBUTE_BYTES;
}

/* The name of a map kind in the text form: colour, bump, normal, attribute. */
static inline const char *sd_map_kind_name(int kind)
{
    return kind == SCN_MAP_COLOUR   ? "colour"
           : kind == SCN_MAP_BUMP   ? "bump"
           : kind == SCN_MAP_NORMAL ? "normal"
                                    : "attribute";
}

struct sd_key {
    int frame;
    double translate[3], rotate[3], scale[3]; /* rotate: degrees about x, y, z */
};

/* A key of the camera (target -1) or of light `target`: its values at
 * frame, every one given (the parser fills those a key leaves out from the
 * key before).  Angles in degrees, as written; the compiler turns them into
 * the tangent and cosines that interpolate. */
struct sd_view_key {
    int frame;
    int target;
    double eye[3], look_at[3], up[3], fov;                      /* the camera */
    double colour[3], position[3], direction[3], cone, falloff; /* a light */
};

struct sd_cluster {
    char name[SCN_MAX_NAME];
    int parent;             /* -1 for the root */
    double m[12];           /* 3x4 row-major, cluster -> parent */
    int key_first, key_count;
};

struct sd_component {
    double centre[3], radius, weight;
};

struct sd_prim {
    int kind;               /* enum scn_prim_kind */
    int material, cluster;
    double v[SCN_PRIM_MAX_VALUES]; /* as in proto/scene_format.h */
    int first, count;       /* DENSITY: into components[] */
    int capped;             /* CONE: enum scn_cone_caps */
    int smooth;             /* TRIANGLE: 1 with vertex normals n (beyond the paper) */
    double n[9];            /* smooth: unit normals at v0, v1, v2, cluster coordinates */
};

struct sd_scene {
    struct sd_view view;
    struct sd_light lights[SCN_MAX_LIGHTS];
    int n_lights;
    struct sd_material *materials;
    int n_materials;
    struct sd_map maps[SCN_MAX_MAPS];
    int n_maps;
    struct sd_cluster *clusters;
    int n_clusters;
    struct sd_prim *prims;
    int n_prims;
    struct sd_component *components;
    int n_components;
    struct sd_key *keys;
    int n_keys;
    struct sd_view_key *view_keys; /* each target's keys together, frames rising */
    int n_view_keys;
    int no_auto_hierarchy;  /* 1: sd_compile keeps the author's clusters
                               as they are (scene_bvh.h); text form
                               `options { auto_hierarchy off }` */
    int paper;              /* 1: paper mode (`options { paper on }`,
                               --paper; sd_paper_apply) */
    int paper_faceted;      /* cones and cylinders paper mode made into
                               SD_CONE_SIDES facets round (sd_paper_apply) */
    unsigned written;       /* SD_WROTE_*: options the text set itself */
};

/* Options a scene's options block wrote itself: paper mode leaves them as
 * written. */
#define SD_WROTE_MIN_WEIGHT 1u
#define SD_WROTE_FRESNEL 2u
#define SD_WROTE_AUTO_HIERARCHY 4u

#define SD_ERR_MAX 512 /* room for "file:line:col: message" */

/* Parses the text scene at path into *s.  On failure returns -1 with
 * "file:line:col: what is wrong" in err and *s empty.  A map statement's
 * image is read only from below the scene file's directory
 * (sd_image_open_below). */
int sd_parse_file(const char *path, struct sd_scene *s, char *err, size_t errlen);
int sd_parse_text(const char *name, const char *text, struct sd_scene *s,
                  char *err, size_t errlen);
/* The same, map images also read from below the directories of the
 * NULL-ended list textures_from (at most SD_TEXTURES_FROM_MAX; each one
 * the caller has checked with sd_textures_from_ok, scene_import.h). */
#define SD_TEXTURES_FROM_MAX 4
int sd_parse_file_from(const char *path, const char *const *textures_from, struct sd_scene *s,
                       char *err, size_t errlen);
int sd_parse_text_from(const char *name, const char *text, const char *const *textures_from,
                       struct sd_scene *s, char *err, size_t errlen);
void sd_free(struct sd_scene *s);
/* The view of a scene that sets none: camera, size, depth, options. */
void sd_view_defaults(struct sd_view *v);

/* Paper mode (docs/scene-format.md, "Paper mode"): every choice the paper
 * made that the scene holds, except those the text wrote itself (written):
 * min_weight 0 (a fixed depth, no weight cut-off), no automatic hierarchy
 * when the scene has clusters of its own (more than the root), and the
 * SCN_OPT_PAPER flag for the render's schedule.  src/trc by angle is the
 * text form's default already (a material's own `fresnel 0` stays). */
void sd_paper_apply(struct sd_scene *s);
/* Paper mode keeps the paper's four primitives: every cone and cylinder
 * becomes SD_CONE_SIDES facets round (and fans over its end discs when it
 * is capped), counted in s->paper_faceted; -1 with err when the triangles
 * would pass SCN_MAX_PRIMS or memory runs out.  sd_paper_apply calls it
 * (and leaves the cones as they are on failure: the compiler then still
 * has a scene). */
#define SD_CONE_SIDES 16
int sd_paper_facet_cones(struct sd_scene *s, char *err, size_t errlen);

/* The compiled form in a malloc'ed buffer (*out, *len); -1 with err if the
 * scene exceeds a limit of the format.  Unless s->no_auto_hierarchy, big
 * clusters are split into a bounding volume hierarchy first (scene_bvh.h). */
int sd_compile(const struct sd_scene *s, uint8_t **out, size_t *len,
               char *err, size_t errlen);

/* The POV-Ray 3.7 form of frame `frame` to f (name names it in err; the
 * caller makes and closes the file); -1 with err naming what POV-Ray
 * cannot carry when strict is set (otherwise such parts are approximated
 * and listed as comments in the output). */
int sd_export_pov(const struct sd_scene *s, int frame, int strict, FILE *f, const char *name,
                  char *err, size_t errlen);

/* Keyframe placement K(frame) of cluster c as a 3x4 matrix (identity when
 * it has no keys), interpolated as the renderer does (render/scene.h). */
void sd_key_matrix(const struct sd_scene *s, int c, int frame, double k[12]);
/* The view and lights at frame (their keys interpolated as the renderer
 * does, render/prepare.c: the fov through its tangent, a spot's angles
 * through their cosines), in double. */
void sd_view_at(const struct sd_scene *s, int frame, struct sd_view *view,
                struct sd_light lights[SCN_MAX_LIGHTS]);
/* 1 when the triangle v0 v1 v2 (9 values) has its vertices on one line
 * (twice its area below 1e-12) or is a sliver (a height under
 * SCN_MIN_TRIANGLE_HEIGHT); the parser refuses it, an import drops it. */
int sd_triangle_degenerate(const double v[9]);
/* What is wrong with cone values v (SCN_CONE_VALUES: base, its radius,
 * apex, its radius), as the text form and NFF say it, or NULL: a negative
 * radius, both radii 0, or ends nearer than SCN_MIN_TRIANGLE_HEIGHT. */
const char *sd_cone_invalid(const double v[SCN_CONE_VALUES]);
/* The smallest height of a triangle (a vertex's distance from the opposite
 * edge); a triangle under SCN_MIN_TRIANGLE_HEIGHT is degenerate (a sliver). */
double sd_triangle_min_height(const double v[9]);
/* The 3x4 product a * b (apply b, then a). */
void sd_mat_mul(const double a[12], const double b[12], double out[12]);
/* Unit quaternion (w, x, y, z) of rotations about x, then y, then z (degrees). */
void sd_euler_quat(const double deg[3], double q[4]);
/* 3x4 rotation matrix of a unit quaternion. */
void sd_quat_matrix(const double q[4], double m[12]);

#endif
