/* render/layout.c: the record sizes of this build and of the board (see
 * layout.h). */
#include "render/layout.h"

#include <stdint.h>

#include "render/blob.h"

const render_layout_t render_layout_native = {
    sizeof(render_blob_t),    sizeof(scene_light_t),   sizeof(scene_material_t),
    sizeof(scene_map_t),      sizeof(scene_cluster_t), sizeof(scene_prim_t),
    sizeof(scene_density_component_t), sizeof(scene_key_t), sizeof(render_frame_t),
    sizeof(render_cluster_t), sizeof(render_prim_t),   sizeof(num_t),
    sizeof(xform_t),          sizeof(scene_normals_t), sizeof(scene_view_key_t),
};

const render_layout_t render_layout_board = {
    RENDER_BOARD_BLOB,    RENDER_BOARD_LIGHT,   RENDER_BOARD_MATERIAL,
    RENDER_BOARD_MAP,     RENDER_BOARD_CLUSTER, RENDER_BOARD_PRIM,
    RENDER_BOARD_COMPONENT, RENDER_BOARD_KEY,   RENDER_BOARD_FRAME,
    RENDER_BOARD_FRAME_CLUSTER, RENDER_BOARD_FRAME_PRIM, RENDER_BOARD_NUM,
    RENDER_BOARD_XFORM,   RENDER_BOARD_NORMALS, RENDER_BOARD_VIEW_KEY,
};

/* On the board (and any 32-bit build of a 4-byte num_t) the records must
 * have the sizes the host assumes for the board. */
#if UINTPTR_MAX == 0xffffffffu && !defined(LINKS1_NUM_DOUBLE)
#define LAYOUT_IS(type, n) _Static_assert(sizeof(type) == (n), #type " is not " #n " bytes: update render/layout.h")
LAYOUT_IS(render_blob_t, RENDER_BOARD_BLOB);
LAYOUT_IS(scene_light_t, RENDER_BOARD_LIGHT);
LAYOUT_IS(scene_material_t, RENDER_BOARD_MATERIAL);
LAYOUT_IS(scene_map_t, RENDER_BOARD_MAP);
LAYOUT_IS(scene_cluster_t, RENDER_BOARD_CLUSTER);
LAYOUT_IS(scene_prim_t, RENDER_BOARD_PRIM);
LAYOUT_IS(scene_density_component_t, RENDER_BOARD_COMPONENT);
LAYOUT_IS(scene_key_t, RENDER_BOARD_KEY);
LAYOUT_IS(render_frame_t, RENDER_BOARD_FRAME);
LAYOUT_IS(render_cluster_t, RENDER_BOARD_FRAME_CLUSTER);
LAYOUT_IS(render_prim_t, RENDER_BOARD_FRAME_PRIM);
LAYOUT_IS(num_t, RENDER_BOARD_NUM);
LAYOUT_IS(xform_t, RENDER_BOARD_XFORM);
LAYOUT_IS(scene_normals_t, RENDER_BOARD_NORMALS);
LAYOUT_IS(scene_view_key_t, RENDER_BOARD_VIEW_KEY);
#endif
