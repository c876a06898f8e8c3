/* scene_import.h: models made elsewhere (model.h) into a scene
 * (scene_desc.h), for `links1 import` and the `model` statement of the text
 * form.  The mapping, field by field, is in docs/import.md.
 *
 * The model's right-handed coordinates become the scene's left-handed ones
 * by negating z (vertices, node transforms, camera and lights), which
 * leaves the picture as the model's author saw it.
 */
#ifndef LINKS1_HOST_SCENE_IMPORT_H
#define LINKS1_HOST_SCENE_IMPORT_H

#include <stdio.h>

#include "host-tools/model/model.h"
#include "host-tools/scene/scene_desc.h"

#define IMPORT_FIT_EXTENT 100.0 /* --fit: the largest |coordinate| becomes this */
#define IMPORT_PATH_MAX 2048

struct import_opts {
    int fit;           /* scale a model beyond +-SCN_MAX_COORD into range */
    int material;      /* every triangle gets this scene material; -1: the model's */
    int nesting;       /* depth of the parent cluster below the root */
    const char *fit_hint; /* how the user asks for fit, for the refusal: "--fit" */
    int smooth;        /* 1: triangles carry the model's vertex normals
                          (beyond the paper); meshes without them stay flat */
    const char *textures_from; /* NULL, or one more directory the model's
                                  textures may come from (sd_texture_open) */
};

struct import_result {
    int triangles;     /* placed */
    int degenerate;    /* dropped: vertices on one line */
    int other;         /* points and lines left out */
    int smooth;        /* placed with vertex normals (opts smooth) */
    int flat;          /* opts smooth, but flat: the mesh has no normals,
                          or one of the three is zero or not finite */
    int clusters, materials, maps;
    double scale;      /* 1, or the --fit factor */
    double lo[3], hi[3]; /* extent of the placed model in its parent cluster */
    char map_image[SCN_MAX_MAPS][IMPORT_PATH_MAX]; /* texture file of each map
                                                      the import added (by scene map index) */
};

/* Adds the model's nodes as clusters under cluster parent of s, its
 * triangles, and (when o->material < 0) its materials and texture maps.
 * model_dir ends in '/' or is "" and locates texture files, which are read
 * only from below it or o->textures_from (sd_texture_open).  0, or -1 with
 * err saying what is wrong with the model (s then as before the call). */
int scene_import_model(struct sd_scene *s, int parent, const struct model *m,
                       const char *model_dir, const struct import_opts *o,
                       struct import_result *r, char *err, size_t errlen);

/* The model's camera and lights into s (a scene being made from the model
 * alone), in scene coordinates scaled as r->scale.  camera_auto frames a
 * model without a camera and adds a light to one without lights.  Notes
 * (lights left out, clamped) go to warn.  0, or -1 with err. */
int scene_import_view(struct sd_scene *s, const struct model *m, const struct import_result *r,
                      int camera_auto, FILE *warn, char *err, size_t errlen);

/* Reads the image open on fd (sd_image_open_below's: a regular file, a FIFO
 * or a device refused, never read; closed here) into map m (its kind set):
 * the RGB bytes of a colour map, the luminance of a bump or attribute map,
 * the normal (2c/255 - 1 per channel, sd_map_normal_texel) of a normal
 * map; path names it in err.  The side limit is checked on the file's
 * header: a small file claiming a huge image costs nothing.  0, or -1 with
 * err. */
int sd_map_read_image_fd(struct sd_map *m, int fd, const char *path, char *err, size_t errlen);

/* A normal map texel of the compiled form (proto/scene_format.h) from the
 * tangent-space normal v (x along T, y along B, z along n): each component
 * of v times SCN_MAP_NORMAL_ONE rounded to a signed byte, v normalized
 * first unless the rounded vector's length is already within sqrt(3)/2 of
 * SCN_MAP_NORMAL_ONE (so texels written as byte/127 read back the same).
 * 0, or -1 when v is not finite, has no length or its z comes out under 1
 * (it does not point out of the surface). */
int sd_map_normal_texel(const double v[3], uint8_t out[3]);

/* Whose image sd_image_open_below opens: it says so in its refusal. */
enum sd_image_owner {
    SD_IMAGE_OF_MODEL, /* a model's texture (the model's directory) */
    SD_IMAGE_OF_SCENE, /* a map statement's image (the scene's directory) */
};

/* The image name (as the file that names it writes it) opened: the path
 * (dir + name, or name when absolute; dir ends in '/' or is "" = ".") into
 * path, and opened only when it resolves (realpath) to a regular file below
 * dir or below one of the directories of the NULL-ended list allow (NULL:
 * none); absolute paths, ../ and links that lead elsewhere are refused,
 * and so are directories, FIFOs and devices (checked without blocking).
 * Its fd, or -1 with "PATH: why" in err (outside: naming dir, allow and
 * how to allow another, as owner says). */
int sd_image_open_below(const char *name, const char *dir, const char *const *allow,
                        enum sd_image_owner owner, char *path, size_t cap, char *err,
                        size_t errlen);

/* real (a resolved path) lies below the directory dir (resolved here; ""
 * is "."; NULL: no directory): 1 or 0.  The one test of "below" that
 * sd_image_open_below makes. */
int sd_image_below(const char *dir, const char *real);

/* A model's texture tex opened: sd_image_open_below below model_dir or
 * allow (NULL: none). */
int sd_texture_open(const char *tex, const char *model_dir, const char *allow, char *path,
                    size_t cap, char *err, size_t errlen);

/* dir, which the user names to allow images from (`--textures-from DIR`,
 * `textures_from "DIR"`; what names it in err), is a directory that may
 * be: it resolves (realpath) to a directory that is not / itself, not a
 * directory directly under / (/etc, /home, /tmp, /usr, /proc, /root, ...:
 * every one) and not the user's home directory.  0, or -1 with err naming
 * dir, what it resolves to and the rule. */
int sd_textures_from_ok(const char *dir, const char *what, char *err, size_t errlen);

/* Writes s as text that sd_parse_text reads back to the same scene.
 * map_image[i], when not NULL or "", is written as map i's image file
 * instead of its texels.  0, or -1 (a write error). */
int sd_write_text(const struct sd_scene *s, const char *const *map_image, FILE *f);
/* The same under another first comment line (title, without its "# "). */
int sd_write_text_titled(const struct sd_scene *s, const char *const *map_image,
                         const char *title, FILE *f);

#endif
