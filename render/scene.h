/* render/scene.h: the in-memory scene the renderer works on.
 *
 * The loader (render/scene_load.c) fills a scene_t from the compiled binary
 * scene; render_prepare() (render/render.h) turns it into a prepared frame in
 * eye coordinates.  Every array is a pointer into memory the caller provides
 * (an arena); the renderer never writes to a scene_t.
 *
 * Conventions used by every field below:
 * - Coordinates are left-handed, as in POV-Ray: x right, y up, z forward.
 *   Lengths are the scene text's times 2^unit_exp (below: the largest is
 *   8..16); the fixed-point build requires every world and eye coordinate
 *   to stay within +-NUM_COORD_LIMIT (fixed/num.h) as stored.
 * - Colours and intensities are linear RGB in num_t, 1 = full scale; the
 *   final pixel is clamped to [0,1] and scaled to 0..255.
 * - Indices are 0-based; "none" is the constant SCENE_NONE.
 */
#ifndef LINKS1_RENDER_SCENE_H
#define LINKS1_RENDER_SCENE_H

#include <stdint.h>

#include "fixed/num.h"
#include "render/limits.h"

#define SCENE_NONE 0xffffu /* "no map" in 16-bit index fields */
#define SCENE_NO_CLUSTER 0xffffffffu /* "no parent": cluster 0 only */

typedef struct {
    num_t x, y, z;
} vec3_t;

typedef struct {
    num_t r, g, b;
} rgb_t;

/* Affine map p' = m[.][0..2] * p + m[.][3], row-major (3 rows of 4). */
typedef struct {
    num_t m[3][4];
} xform_t;

/* Pinhole camera (its keys, scene_view_key_t, move it).  Pixel (x, y), with y = 0
 * the top row, looks through the point at screen coordinates
 *   sx = (2(x + 1/2)/width  - 1) * tan_half_fov_y * width/height
 *   sy = (1 - 2(y + 1/2)/height) * tan_half_fov_y
 * i.e. the eye-space direction (sx, sy, 1). */
typedef struct {
    vec3_t eye;           /* world position of the eye */
    vec3_t look_at;       /* world point seen at the image centre; != eye */
    vec3_t up;            /* world "up" hint; not parallel to look_at - eye */
    num_t tan_half_fov_y; /* tan(vertical field of view / 2), > 0; the host
                             compiler computes it (no tan() on the board) */
} scene_camera_t;

enum scene_light_kind {
    SCENE_LIGHT_PARALLEL = 0, /* directional: no position, no falloff */
    SCENE_LIGHT_POINT = 1,    /* point: no distance falloff (Fig. 5 has none) */
    SCENE_LIGHT_SPOT = 2,     /* point with a cone and a smooth edge */
};

/* Lights live in world coordinates (their keys, scene_view_key_t, move
 * them). */
typedef struct {
    uint8_t kind;      /* enum scene_light_kind */
    rgb_t intensity;   /* L_i per channel, >= 0, 1 = full */
    vec3_t position;   /* POINT, SPOT: world position */
    vec3_t direction;  /* PARALLEL: direction the light travels (from the
                          light into the scene); SPOT: cone axis, pointing
                          away from the light.  Need not be unit length. */
    num_t cos_inner;   /* SPOT: cos of the half-angle of full intensity */
    num_t cos_outer;   /* SPOT: cos of the half-angle where it reaches 0;
                          cos_outer < cos_inner; smoothstep in between */
} scene_light_t;

/* Surface properties, the parameters of the paper's Fig. 5. */
typedef struct {
    rgb_t colour;      /* F: object colour, 0..1 per channel; multiplies
                          ambient, diffuse and transmitted light */
    num_t dic;         /* ambient coefficient (per light; shadowed or not
                          by options.ambient_shadowed), 0..1 */
    num_t drc;         /* diffuse coefficient (shadowed light), 0..1 */
    num_t src;         /* reflection coefficient at normal incidence, 0..1 */
    num_t trc;         /* transmissivity at normal incidence, 0..1;
                          src + trc <= 1 keeps energy */
    num_t fresnel;     /* 0..1: weight of the angle dependence of src/trc
                          (render/shade.h); 0 = constant src/trc */
    num_t ior;         /* index of refraction, >= 1; 1 = no bending */
    uint16_t phong_n;  /* highlight sharpness n of cos^n, 0..RENDER_MAX_PHONG_N;
                          0 = no highlight */
    uint16_t colour_map; /* index into scene maps (kind COLOUR) or SCENE_NONE */
    uint16_t bump_map;   /* index into scene maps (kind BUMP) or SCENE_NONE */
    uint16_t normal_map; /* index into scene maps (kind NORMAL) or SCENE_NONE;
                            never together with bump_map */
    /* attribute maps (kind ATTRIBUTE) or SCENE_NONE: the map's value 0..1
     * at the hit multiplies dic, drc, src, trc there */
    uint16_t dic_map, drc_map, src_map, trc_map;
} scene_material_t;

/* Every map index of m set to SCENE_NONE (a material built in code). */
static inline void scene_material_no_maps(scene_material_t *m)
{
    m->colour_map = m->bump_map = m->normal_map = SCENE_NONE;
    m->dic_map = m->drc_map = m->src_map = m->trc_map = SCENE_NONE;
}

enum scene_map_kind {
    SCENE_MAP_COLOUR = 0,   /* texels: 3 bytes R,G,B per texel, 0..255 */
    SCENE_MAP_BUMP = 1,     /* texels: 1 byte height per texel, 0..255; the
                               normal is tilted by the height gradient */
    SCENE_MAP_NORMAL = 2,   /* texels: 3 signed bytes per texel, the
                               tangent-space normal times
                               SCN_MAP_NORMAL_ONE (proto/scene_format.h), z >= 1 */
    SCENE_MAP_ATTRIBUTE = 3 /* texels: 1 byte per texel, 0..255 = 0..1 */
};

/* Bytes per texel of a map of that kind. */
static inline unsigned scene_map_texel_bytes(uint8_t kind)
{
    return kind == SCENE_MAP_COLOUR || kind == SCENE_MAP_NORMAL ? 3u : 1u;
}

/* A 2-D array mapped onto surfaces through (u, v) in [0,1) (repeated). */
typedef struct {
    uint8_t kind;          /* enum scene_map_kind */
    uint16_t width;        /* texels, 1..RENDER_MAX_MAP_SIZE */
    uint16_t height;       /* texels, 1..RENDER_MAX_MAP_SIZE */
    const uint8_t *texels; /* reloc (render/relocate.c); row-major, row 0 at v = 0, width*height*bpp */
    num_t repeat_u;        /* tiles across u in [0,1), > 0 (1 = once) */
    num_t repeat_v;        /* tiles across v in [0,1), > 0 */
    num_t bump_depth;      /* BUMP: >= 0; the normal n becomes
                              normalize(n - bump_depth*(su*T + sv*B)) with
                              su, sv = (difference of the two neighbouring
                              texels' heights) / (2*255) along u and v */
} scene_map_t;

/* One animation key of a cluster: translation, rotation (unit quaternion,
 * computed by the host compiler since the board has no trig) and scale.
 * Between keys, translate/scale interpolate linearly and the quaternion by
 * normalised linear interpolation; before the first/after the last key the
 * end key holds. */
typedef struct {
    uint32_t frame;     /* frame number of this key; keys sorted ascending */
    vec3_t translate;
    num_t rot_w, rot_x, rot_y, rot_z; /* unit quaternion */
    vec3_t scale;       /* per-axis scale, non-zero */
} scene_key_t;

/* One key of the camera or of a light: its values at a frame.  Between a
 * target's keys render_prepare interpolates every value linearly with the
 * cluster keys' weight (the camera's tan_half_fov_y and a spot's cosines
 * are what interpolate); before the first/after the last the end key
 * holds.  Keys are grouped by target, the camera's first, then by rising
 * light index, frames rising within a target (the loader checks it). */
#define SCENE_VIEW_KEY_CAMERA SCENE_NONE /* target of the camera's keys */
typedef struct {
    uint32_t frame;     /* frame number of this key */
    uint16_t target;    /* SCENE_VIEW_KEY_CAMERA or the light's index */
    union {
        scene_camera_t camera; /* the camera's key */
        scene_light_t light;   /* a light's key: its kind is the light's */
    } v;
} scene_view_key_t;

/* A node of the object hierarchy.  cluster 0 is the root (the scene).
 * child -> parent transform for frame f = K(f) * local, where K(f) is the
 * keyframed TRS (translate * rotate * scale) or identity without keys. */
typedef struct {
    uint32_t parent;    /* index of the parent cluster, < own index;
                           SCENE_NO_CLUSTER for cluster 0 only */
    xform_t local;      /* child -> parent affine map, invertible */
    uint32_t first_key; /* first key in scene keys */
    uint32_t key_count; /* 0 = static */
} scene_cluster_t;

/* What render_prepare needs of a cluster's static place in the scene,
 * worked out once a load (render_scene_index, render/render.h) rather
 * than every frame: its children and primitives grouped (ascending index),
 * and whose maps its primitives use. */
typedef struct {
    uint32_t first_child, child_count; /* into the index's child_list */
    uint32_t first_prim, prim_count;   /* into the index's prim_list */
    uint32_t maps_of; /* the cluster whose maps its primitives use: itself,
                         or for a plain cluster (no keys, the identity: a
                         node of the automatic hierarchy) its parent's */
} scene_group_t;

/* The scene's static structure (render_scene_index): arrays in the
 * scene's memory, NULL when the scene has none (render_prepare then
 * works it out into the frame's). */
typedef struct {
    const scene_group_t *groups; /* reloc; cluster_count */
    const uint32_t *child_list;  /* reloc; cluster_count: cluster indices, grouped by parent */
    const uint32_t *prim_list;   /* reloc; prim_count: prim indices, grouped by cluster */
    const uint32_t *normal_src;  /* reloc; 3 per normals record: for vertex k
                                    of record j, (j' << 2 | k') of the first
                                    (in prim order) vertex normal with the
                                    same bits and cluster maps, (j << 2 | k)
                                    when it is the first: the frame maps
                                    each distinct one once and copies it */
    const num_t *uv_spread;      /* reloc; prim_count: a triangle's spread of
                                    map coordinates, the sum over k = 1, 2
                                    of max(|u_k - u_0|, |v_k - v_0|)
                                    (precision_check); 0 for other kinds,
                                    and for all in a scene without maps */
    const xform_t *parent_maps;  /* reloc; 2 per cluster with maps of its
                                    own, in rising cluster index: what of
                                    its map to its parent and back stays
                                    from frame to frame: without keys both
                                    maps (the key the identity), with keys
                                    [1] its local map's inverse */
    uint32_t parent_map_count;   /* of parent_maps */
    const uint32_t *own_list;    /* reloc; own_count: the clusters with maps
                                    of their own (parent_maps' order) */
    uint32_t own_count;
    uint32_t pointer_lo, pointer_hi; /* the primitives that are not
                                        triangles lie in [pointer_lo,
                                        pointer_hi) (0, 0: none) */
    uint32_t keyed_lo, keyed_hi; /* the clusters with keys lie in
                                    [keyed_lo, keyed_hi) (0, 0: none) */
} scene_index_t;

/* What of a scene_index_t is the same in every arithmetic: integers
 * worked out from the same bytes by the same decisions (a plain cluster,
 * a vertex normal equal to another, bit for bit, in both).  Another
 * arithmetic's load of the same bytes takes them over
 * (scene_load_known_t.index) instead of working them out again. */
typedef struct {
    uint32_t cluster_count, prim_count, normals_count; /* the scene's */
    const scene_group_t *groups;  /* cluster_count */
    const uint32_t *child_list;   /* cluster_count */
    const uint32_t *prim_list;    /* prim_count */
    const uint32_t *normal_src;   /* 3 per normals record */
    uint32_t own_count;
    uint32_t pointer_lo, pointer_hi, keyed_lo, keyed_hi;
} scene_index_ints_t;

enum scene_prim_kind {
    SCENE_PRIM_TRIANGLE = 0,
    SCENE_PRIM_ELLIPSOID = 1,
    SCENE_PRIM_BOX = 2,
    SCENE_PRIM_DENSITY = 3,
    SCENE_PRIM_CONE = 4,   /* a cone frustum or cylinder (render/prim_cone.c) */
};

/* One LINKS-1 density field component: weight b, radius d.  Field at
 * distance r: b(1 - 3r^2/d^2) for r <= d/3; (3b/2)(1 - r/d)^2 for
 * d/3 <= r <= d; 0 beyond. */
typedef struct {
    vec3_t centre;      /* in the cluster's coordinates */
    num_t radius;       /* d > 0 */
    num_t weight;       /* b; may be negative (a component that carves) */
} scene_density_component_t;

/* The unit normals at a smooth triangle's vertices, in its cluster's
 * coordinates. */
typedef struct {
    vec3_t n[3];
} scene_normals_t;

/* A primitive, in the coordinates of its cluster. */
typedef struct {
    uint8_t kind;       /* enum scene_prim_kind */
    uint16_t material;  /* index into scene materials */
    uint32_t cluster;   /* owning cluster */
    union {
        struct {
            vec3_t v[3];   /* vertices; front face is either side */
            num_t tex_u[3]; /* map coordinate u per vertex */
            num_t tex_v[3]; /* map coordinate v per vertex */
            uint32_t smooth; /* 0: flat (the paper's); k > 0: a smooth
                                triangle (beyond the paper), its vertex
                                normals are scene normals[k - 1] */
        } triangle;
        struct {
            vec3_t centre;
            vec3_t radius; /* semi-axes along the cluster's x, y, z, > 0;
                              rotate it with the cluster transform */
        } ellipsoid;
        struct {
            vec3_t centre;
            vec3_t half;   /* half edge lengths along x, y, z, > 0 */
        } box;
        struct {
            uint32_t first;    /* first component in density_components */
            uint16_t count;    /* 1..RENDER_MAX_DENSITY_COMPONENTS */
            num_t threshold;   /* surface: sum of fields == threshold, > 0 */
        } density;
        struct {
            vec3_t end[2];     /* the centres of its end discs (base, apex), apart */
            num_t radius[2];   /* their radii, >= 0, not both 0 */
            uint8_t capped;    /* 1: both ends closed by flat discs; 0: open */
        } cone;
    } shape;
} scene_prim_t;

/* An ellipsoid's or a box's centre and semi-axes (radius or half edges):
 * the two shapes that are a unit cube or sphere scaled and moved. */
static inline void scene_prim_centre_axes(const scene_prim_t *sp, vec3_t *centre, vec3_t *axes)
{
    int round = sp->kind == SCENE_PRIM_ELLIPSOID;
    *centre = round ? sp->shape.ellipsoid.centre : sp->shape.box.centre;
    *axes = round ? sp->shape.ellipsoid.radius : sp->shape.box.half;
}

/* Switches for measurement; every combination gives a correct image and the
 * speed-ups (hierarchy, bounds) give the same image on or off. */
typedef struct {
    uint8_t max_depth;      /* reflection/refraction depth, 0..RENDER_MAX_DEPTH;
                               primary ray = depth 0 */
    uint8_t refractionless; /* 1: past max_depth, transmission goes straight
                               through the remaining transparent objects */
    uint8_t use_bounds;     /* 1: test bounding boxes before contents */
    uint8_t use_hierarchy;  /* 1: walk the cluster tree; 0: flat list */
    uint8_t shadows;        /* 1: shadow rays; 0: every light unshadowed */
    uint8_t refraction;     /* 1: transmitted rays bend (Snell) within
                               max_depth; 0: they never bend, at any depth:
                               transmission goes straight through */
    uint8_t mark_lost;      /* 1: a pixel that lost precision is painted
                               RENDER_LOST_COLOUR instead */
    uint8_t ambient_shadowed; /* 1: light i's ambient term dic F S_i takes
                               the light as shadows leave it (Fig. 5 read
                               literally: the text form's default); 0: the
                               unshadowed L_i (SCN_OPT_AMBIENT_SHADOWED) */
    uint8_t shadow_tint;    /* 1: a transparent object between a point and
                               a light passes trc(th) F of it (tinted); 0:
                               trc(th) alone, its transmissivity (the text
                               form's default; SCN_OPT_UNTINTED_SHADOWS) */
    uint8_t check_lost;     /* 1: a pixel that lost precision is checked in
                               the wide arithmetic (render/wide.h) and
                               counts as lost only when it is more than
                               RENDER_CHECK_LOST_STEPS/255 off there; it
                               keeps its colour (SCN_OPT_CHECK_LOST) */
    uint8_t world_space;    /* 1: render_prepare leaves the scene in world
                               coordinates and the camera moves the rays
                               instead; a frame whose cluster maps did not
                               change keeps the frame before's primitives
                               (SCN_OPT_WORLD_SPACE, render/render.h) */
    uint8_t spd_rules;      /* 1: Haines's SPD rules (SCN_OPT_SPD_RULES): a
                               pixel is the mean of the camera rays through
                               its four corners (render_area traces each
                               corner once), and a transmitting surface
                               spawns a reflected ray whatever its src */
    uint8_t antialias;      /* 1: Whitted's adaptive anti-aliasing
                               (SCN_OPT_ANTIALIAS): corner rays shared as
                               spd_rules shares them, and a pixel cut into
                               four where its corners differ by more than
                               aa_threshold, down to aa_depth (render/trace.c) */
    uint8_t aa_depth;       /* 0..SCN_MAX_AA_DEPTH: cuts at most; 0 = the
                               mean of the corners */
    uint16_t density_steps; /* equal steps of a density sphere's root finder,
                               SCN_MIN_DENSITY_STEPS..SCN_MAX_DENSITY_STEPS
                               (render/prim.c; render_prim_t.density_steps) */
    num_t min_weight;       /* adaptive depth, 0..1: a reflected or refracted
                               ray whose weight (the product of src and trc
                               along its path) falls below it is not traced;
                               0 = max_depth alone decides */
    num_t aa_threshold;     /* antialias: 0..1, the largest difference of a
                               channel between a quad's four corners (max -
                               min, before clamping) that is not cut */
} render_options_t;

/* The arrays (marked "reloc") are the scene's pointer fields:
 * render_relocate (render/relocate.c) moves each one when a blob is copied
 * to another address; a new pointer field must be added there too. */
typedef struct {
    uint16_t width, height;    /* image size, 1..RENDER_MAX_WIDTH/HEIGHT */
    uint32_t frame_count;      /* frames of the animation, >= 1 */
    scene_camera_t camera;
    rgb_t background;          /* colour of rays that hit nothing */
    render_options_t options;
    /* Haze (SCN_SEC_HAZE, render/haze.h): when haze is 1 a ray's colour c
     * at distance t becomes haze_colour + (c - haze_colour) exp(-haze_k t)
     * and a ray that hits nothing takes haze_colour. */
    uint8_t haze;
    rgb_t haze_colour;
    num_t haze_k;              /* 1/D per stored unit of length */

    const scene_light_t *lights;         uint16_t light_count;    /* reloc */
    const scene_material_t *materials;   uint16_t material_count; /* reloc */
    const scene_map_t *maps;             uint16_t map_count;      /* reloc */
    const scene_cluster_t *clusters;     uint32_t cluster_count;  /* reloc */
    const scene_key_t *keys;             uint32_t key_count;      /* reloc */
    const scene_prim_t *prims;           uint32_t prim_count;     /* reloc */
    const scene_density_component_t *density_components;          /* reloc */
    uint32_t density_component_count;
    const scene_normals_t *normals;      uint32_t normals_count;  /* reloc */
    const scene_view_key_t *view_keys;   uint32_t view_key_count; /* reloc */
    int32_t unit_exp;  /* every length above (positions, radii, half edges,
                          translations, component centres and radii) is the
                          scene text's times 2^unit_exp (render/limits.h,
                          RENDER_NORM_EXP): exact in the IEEE builds; a
                          so a scene scaled by 2^k renders the same */
    int32_t tol_exp;   /* the tolerances of render/limits.h apply times
                          2^tol_exp in these units: 0 unless the geometry's
                          largest |length| (primitives, density components,
                          cluster and key translations; not the eye or the
                          lights) is under 2^-RENDER_TOL_SLACK_EXP of the
                          scene's, so a far light or eye does not widen them
                          beyond 8 times the geometry's norm.  In
                          RENDER_TOL_EXP_MIN..0 */
    scene_index_t index;   /* reloc; scene_load's render_scene_index */
} scene_t;

/* A tolerance of render/limits.h (NUM_C of a ..._VALUE) in the units the
 * scene is stored in. */
static inline num_t scene_tolerance(const scene_t *s, num_t value)
{
    return num_scale2(value, s->tol_exp);
}

#endif
