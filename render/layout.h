/* render/layout.h: the bytes of each record the renderer keeps in memory,
 * so that one formula (render_blob_bytes_layout, render/blob.h) gives a
 * scene's memory both for the machine it runs on and for the board.
 *
 * render_layout_native is this build's sizeof of each record;
 * render_layout_board the board's (every firmware build, float, soft float
 * and fixed point, has num_t of 4 bytes and 4-byte pointers, so the three
 * agree).  A 32-bit build checks at compile time that its records have the
 * board's sizes (render/layout.c), so the host's figure for the board is
 * exact: the host compiler uses it to refuse a scene too big for the board
 * before anything is uploaded.
 */
#ifndef LINKS1_RENDER_LAYOUT_H
#define LINKS1_RENDER_LAYOUT_H

#include <stddef.h>

typedef struct {
    size_t blob;          /* render_blob_t */
    size_t light;         /* scene_light_t */
    size_t material;      /* scene_material_t */
    size_t map;           /* scene_map_t */
    size_t cluster;       /* scene_cluster_t */
    size_t prim;          /* scene_prim_t */
    size_t component;     /* scene_density_component_t */
    size_t key;           /* scene_key_t */
    size_t frame;         /* render_frame_t */
    size_t frame_cluster; /* render_cluster_t */
    size_t frame_prim;    /* render_prim_t */
    size_t num;           /* num_t */
    size_t xform;         /* xform_t */
    size_t normals;       /* scene_normals_t */
    size_t view_key;      /* scene_view_key_t */
} render_layout_t;

/* The board's record sizes, in the order of render_layout_t. */
#define RENDER_BOARD_BLOB 276
#define RENDER_BOARD_LIGHT 48
#define RENDER_BOARD_MATERIAL 52
#define RENDER_BOARD_MAP 24
#define RENDER_BOARD_CLUSTER 60
#define RENDER_BOARD_PRIM 72
#define RENDER_BOARD_COMPONENT 20
#define RENDER_BOARD_KEY 44
#define RENDER_BOARD_FRAME 1168
#define RENDER_BOARD_FRAME_CLUSTER 96
#define RENDER_BOARD_FRAME_PRIM 228
#define RENDER_BOARD_NUM 4
#define RENDER_BOARD_XFORM 48
#define RENDER_BOARD_NORMALS 36
#define RENDER_BOARD_VIEW_KEY 56

extern const render_layout_t render_layout_native;
extern const render_layout_t render_layout_board;

#endif
