/* scene_parse.h: the parser's state and the pieces its files share
 * (scene_parse.c: helpers, global statements, clusters, entry points;
 * scene_parse_looks.c: maps and materials; scene_parse_objects.c:
 * transforms, keys and primitives; scene_parse_model.c: the model
 * statement; scene_parse_view.c: the camera and the lights with their
 * keys).  Private to the parser.
 */
#ifndef LINKS1_HOST_SCENE_PARSE_H
#define LINKS1_HOST_SCENE_PARSE_H

#include <stddef.h>

#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_lex.h"

#define PARSE_MAX_FILE (64u * 1024u * 1024u) /* text scenes larger are refused */
#define PARSE_DEFAULT_WIDTH 320
#define PARSE_DEFAULT_HEIGHT 240
#define PARSE_DEFAULT_FOV 45.0
#define PARSE_DEFAULT_DEPTH 5
#define PARSE_DEFAULT_FALLOFF 5.0 /* degrees of a spotlight's soft edge */
#define PARSE_DIR_MAX 1024        /* directory part of a scene file's path */

struct parser {
    struct lex lx;
    struct sd_scene *s;
    char dir[PARSE_DIR_MAX]; /* directory of the scene file, for map images */
    const char *const *textures_from; /* NULL-ended: more directories map images
                                         may come from (sd_parse_text_from) */
    int cap_materials, cap_clusters, cap_prims, cap_components, cap_keys, cap_view_keys;
    int seen_camera, seen_resolution, seen_options, seen_animation, seen_haze;
    int fresnel_off; /* options { fresnel off }: materials that set neither
                        fresnel nor constant keep src and trc constant */
};

/* A material's fresnel until the end of the file decides it
 * (parse_resolve_fresnel). */
#define PARSE_FRESNEL_UNSET (-1.0)

/* helpers (scene_parse.c); each fails through lex_error */
void *parse_grow(struct parser *p, void *arr, int *cap, int n, size_t elem, int limit,
                 const char *what);
void parse_coord3(struct parser *p, const char *what, double v[3]); /* lengths */
void parse_factor3(struct parser *p, const char *what, double v[3]); /* no unit */
void parse_unit3(struct parser *p, const char *what, double v[3]);
int parse_on_off(struct parser *p, const char *what);
void parse_open(struct parser *p, const char *stmt);
void parse_unknown(struct parser *p, const char *block) __attribute__((noreturn));
int parse_len3_zero(const double v[3]);
int parse_find_material(const struct sd_scene *s, const char *name);
int parse_find_map(const struct sd_scene *s, const char *name);
int parse_material_ref(struct parser *p);

/* statements: each starts at its keyword and consumes through its '}' */
void parse_camera(struct parser *p);               /* scene_parse_view.c, with */
void parse_light(struct parser *p);                /* their keys */
void parse_map(struct parser *p);                  /* scene_parse_looks.c */
void parse_material(struct parser *p);
int parse_transform(struct parser *p, double m[12]); /* scene_parse_objects.c;
                                                       0 if not a transform */
void parse_key(struct parser *p, int cluster);
void parse_prim(struct parser *p, int cluster, int material);
void parse_model(struct parser *p, int cluster, int nesting); /* scene_parse_model.c */

#endif
