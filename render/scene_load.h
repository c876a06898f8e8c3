/* render/scene_load.h: the compiled scene (proto/scene_format.h) into the
 * renderer's scene_t (render/scene.h).
 *
 * Runs on the board's DM and on the host, in every arithmetic: no malloc,
 * no stdio, no mutable globals.  Everything it builds comes from the arena
 * the caller gives; the input buffer is not referenced afterwards.  Nothing
 * is trusted: sizes, the word sum, section bounds, every count against its limit,
 * every index, every real (finite, within range), the cluster tree.  On
 * failure the arena is left as it was and the error names the problem.
 */
#ifndef LINKS1_RENDER_SCENE_LOAD_H
#define LINKS1_RENDER_SCENE_LOAD_H

#include <stddef.h>
#include <stdint.h>

#include "render/arena.h"
#include "render/layout.h"
#include "render/scene.h"

typedef enum {
    SCENE_LOAD_OK = 0,
    SCENE_LOAD_ERR_TRUNCATED,   /* buffer shorter than the header or its total size */
    SCENE_LOAD_ERR_MAGIC,       /* not "L1SC" */
    SCENE_LOAD_ERR_VERSION,     /* a version this loader does not read */
    SCENE_LOAD_ERR_SIZE,        /* total size wrong, too small or over SCN_MAX_SIZE */
    SCENE_LOAD_ERR_CRC,         /* body checksum mismatch */
    SCENE_LOAD_ERR_SECTION,     /* bad section table: kind, duplicate, bounds,
                                   alignment, overlap, size vs count */
    SCENE_LOAD_ERR_MISSING,     /* a required section is absent */
    SCENE_LOAD_ERR_LIMIT,       /* a count or size over its SCN_MAX_* limit */
    SCENE_LOAD_ERR_INDEX,       /* an index out of range or of the wrong kind */
    SCENE_LOAD_ERR_VALUE,       /* a real not finite or out of range, a bad
                                   enum, a non-zero reserved field */
    SCENE_LOAD_ERR_TREE,        /* cluster tree: parent order, nesting, keys */
    SCENE_LOAD_ERR_ARENA,       /* the arena cannot hold the scene */
} scene_load_status_t;

#define SCENE_LOAD_MSG_MAX 120

typedef struct {
    scene_load_status_t status;
    char message[SCENE_LOAD_MSG_MAX]; /* e.g. "prim 12: material 9 of 4" */
} scene_load_error_t;

/* Checks buf[0..len) and builds *out from arena memory.  len must be the
 * exact size of the compiled scene. */
scene_load_status_t scene_load(const uint8_t *buf, size_t len, arena_t *arena,
                               scene_t *out, scene_load_error_t *err);
/* What the caller knows of buf already, so that scene_load_summed does not
 * work it out again: the body's word sum (proto/wordsum.h, bytes
 * SCN_SUM_START .. len - 1), read once to check the upload, and, when a
 * load of the same bytes in another arithmetic passed (the DM's narrow load
 * before its wide one), that load's scaling (its exponents are integer
 * work on the same bits, the same in every arithmetic) and the checks it
 * made of the values. */
typedef struct {
    uint32_t body_sum; /* compared with the header's instead of the bytes summed */
    int passed;        /* 1: a load of these bytes passed.  unit_exp and
                          tol_exp below are its scene's (scene_t's), so
                          load_scale does not look at the values, and a
                          triangle's values and vertex normals are not
                          checked again (in range, no sliver, unit
                          length); the records' indices and kinds are */
    int32_t unit_exp, tol_exp;
    scene_index_ints_t index; /* when passed, that load's index's integer
                                 part (render_scene_index_same) when its
                                 values widen exactly to this load's (an
                                 IEEE load's: groups NULL otherwise) */
} scene_load_known_t;

/* What a load of bytes whose body sums to body_sum found: s, loaded from
 * them (its index too, which must stay where it is until the other load
 * is done), for another arithmetic's load of the same bytes. */
scene_load_known_t scene_load_known_of(const scene_t *s, uint32_t body_sum);

/* The triangles' extent of buf[0..len) as scene_load works it out when
 * the scene does not state it: the bits of the EXTENT section's value
 * (proto/scene_format.h), which the compiler writes.  The header and the
 * section table are checked, not the word sum nor the records; scratch of
 * 8 bytes a cluster from arena, given back. */
scene_load_status_t scene_load_triangle_exp(const uint8_t *buf, size_t len, arena_t *arena,
                                            uint32_t *bits, scene_load_error_t *err);

/* scene_load with what the caller knows (known, or NULL: nothing). */
scene_load_status_t scene_load_summed(const uint8_t *buf, size_t len,
                                      const scene_load_known_t *known, arena_t *arena,
                                      scene_t *out, scene_load_error_t *err);

/* Checks the header and section table of buf[0..len) (word sum included, not
 * the records) and fills the counts of *shape (every pointer NULL, every
 * other field 0) and the texel bytes of all maps, so memory can be sized
 * before loading: scene_load_bytes and render_prepare_bytes (render.h). */
scene_load_status_t scene_load_shape(const uint8_t *buf, size_t len, scene_t *shape,
                                     uint32_t *texel_bytes, scene_load_error_t *err);
/* The same without the body's word sum: for a caller that runs scene_load
 * on the same bytes next, which checks it (render_blob_load).  The sum costs
 * about an instruction a byte of the scene: once per load is enough. */
scene_load_status_t scene_load_shape_before_load(const uint8_t *buf, size_t len, scene_t *shape,
                                                 uint32_t *texel_bytes, scene_load_error_t *err);
/* Either of those (crc_later: the second) and the maps the scene's index
 * keeps at most in shape->index.parent_map_count, from the cluster records
 * (two for the root and each cluster that is not plain: three
 * instructions a word of each cluster record), so that a scene of many plain clusters (the
 * automatic hierarchy's) is not bounded by two maps a cluster
 * (render_scene_index_bytes). */
scene_load_status_t scene_load_shape_maps(const uint8_t *buf, size_t len, int crc_later,
                                          scene_t *shape, uint32_t *texel_bytes,
                                          scene_load_error_t *err);

/* Arena bytes scene_load needs at most for a scene of this shape; the
 * _layout form with another machine's record sizes (render/layout.h). */
size_t scene_load_bytes(const scene_t *shape, uint32_t texel_bytes);
size_t scene_load_bytes_layout(const scene_t *shape, uint32_t texel_bytes,
                               const render_layout_t *layout);

/* A constant string naming the status. */
const char *scene_load_status_name(scene_load_status_t status);

#endif
