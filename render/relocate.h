/* render/relocate.h: moving a scene and its prepared frame to another
 * address after a byte copy.
 *
 * On the board the DM builds a scene and one prepared frame in one memory
 * block (render/blob.h); the IMSU hands that block to the RC at the same
 * address, but the RC's broadcast copies it to another block, where every
 * pointer inside it (scene arrays, frame arrays, frame->scene, each density
 * primitive's component pointers, each map's texels) still names the old
 * block.  render_relocate rewrites each of them by the distance between the
 * two blocks.
 *
 * The list of pointer fields lives in relocate.c, next to nothing else; each
 * pointer field of scene.h and render.h is marked "reloc" in its comment.
 */
#ifndef LINKS1_RENDER_RELOCATE_H
#define LINKS1_RENDER_RELOCATE_H

#include <stddef.h>
#include <stdint.h>

#include "render/render.h"

/* Both bases must be aligned to this (the arena's largest alignment), so
 * every structure stays as aligned in the copy as in the original. */
#define RENDER_RELOCATE_ALIGN ARENA_MAX_ALIGN

/* After memcpy(new_base, (void *)old_base, size): rewrites the pointers of
 * the scene *scene and the frame *frame (old addresses, either may be NULL;
 * the frame's scene is moved with it and must be *scene when both are
 * given), which must lie in the copy, and sets *scene / *frame to their new
 * addresses.
 *
 * Every pointer must point, with the whole array it stands for, into
 * [old_base, old_base + size); NULL is accepted only for an array of zero
 * elements (e.g. the components of a non-density primitive).  Otherwise
 * RENDER_ERR_RELOCATE, *bad_field (if bad_field is not NULL) names the
 * first offending field, and the copy is left untouched: every pointer is
 * checked before any is rewritten.  Also RENDER_ERR_RELOCATE when a base is
 * not aligned to RENDER_RELOCATE_ALIGN.  Reads nothing outside the copy,
 * whatever it holds.  new_base == old_base is allowed (checks only). */
render_status_t render_relocate(void *new_base, size_t size, uintptr_t old_base,
                                const scene_t **scene, render_frame_t **frame,
                                const char **bad_field);

/* As render_relocate for the frame alone, over a copy whose scene (the
 * one frame->scene names) is already relocated in it: the frame's pointers
 * (into the frame or the scene) are checked and moved, the scene's are not
 * touched. */
render_status_t render_relocate_frame(void *new_base, size_t size, uintptr_t old_base,
                                      render_frame_t **frame, const char **bad_field);

/* As render_relocate_frame over a copy whose frame arrays (clusters,
 * primitives and the rest) are relocated in it already: the frame
 * header's own pointers alone are checked and moved (a world-space frame
 * whose world part the copy holds, render_blob_copy_frame). */
render_status_t render_relocate_frame_header(void *new_base, size_t size, uintptr_t old_base,
                                             render_frame_t **frame, const char **bad_field);

#endif
