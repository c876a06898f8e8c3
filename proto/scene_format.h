/* scene_format.h: the compiled scene (".l1s"), the form a scene is uploaded
 * in to the board's DM.  One definition for the host compiler
 * (host-tools/scene/) and the loader (render/scene_load.c).
 *
 * Every field is little-endian and read with proto/wire.h, never by casting
 * the buffer to a struct; reals are IEEE 754 binary32 bit patterns.
 *
 *   offset  size  field
 *   0       4     magic   "L1SC"
 *   4       2     version SCN_VERSION; any other value is refused
 *   6       2     section count, 1..SCN_SEC_COUNT
 *   8       4     total size in bytes (header + table + sections)
 *   12      4     word sum (proto/wordsum.h) of bytes 16 .. total size - 1
 *   16      16*n  section table: per section u32 kind, u32 offset (from the
 *                 start of the file, 4-byte aligned), u32 size in bytes,
 *                 u32 record count; size must equal count * record size
 *   ...           section bodies
 *
 * Each kind appears at most once.  VIEW and CLUSTERS are required (cluster 0
 * is the scene's root); the others may be absent, meaning zero records.
 *
 * The hierarchy: every cluster names its parent by index, and a parent's
 * index is always smaller than its child's, so the tree is acyclic by
 * construction and the loader checks it with one comparison per cluster.
 * Primitives name the cluster they belong to and are given in that
 * cluster's coordinates.  A cluster's placement in its parent is
 * K(frame) * M: M is its static 3x4 matrix, K the transform interpolated
 * from its keyframes (identity when it has none).
 */
#ifndef LINKS1_PROTO_SCENE_FORMAT_H
#define LINKS1_PROTO_SCENE_FORMAT_H

/* ------------------------------------------------------------ the limits */
#define SCN_MAX_SIZE (64u * 1024u * 1024u) /* whole compiled scene, bytes; the
                                              DM keeps it in its private memory */
#define SCN_MAX_WIDTH 1024                 /* the frame memory is 1024x1024 */
#define SCN_MAX_HEIGHT 1024
#define SCN_MAX_LIGHTS 16 /* lights of any kinds (parallel, point, spot): the
                             one limit, also the renderer's (render/limits.h
                             RENDER_MAX_LIGHTS); the paper sets none.  Each
                             costs 48 bytes here, 48 in the scene and 60 in
                             the prepared frame (render_frame_t holds them),
                             and a shadow ray per hit */
#define SCN_MAX_MATERIALS 1024
#define SCN_MAX_MAPS 16
#define SCN_MAX_MAP_SIDE 1024              /* texels per map row or column */
#define SCN_MAX_TEXEL_BYTES (4u * 1024u * 1024u) /* over all maps */
#define SCN_MAX_CLUSTERS 1048576           /* 32-bit indices; the board's memory
                                              is the tighter bound (blob.h) */
#define SCN_MAX_CLUSTER_NESTING 32         /* clusters below the root */
#define SCN_MAX_PRIMS 1048576 /* the board's IMSU block is the tighter bound */
#define SCN_MAX_DENSITY_COMPONENTS 64      /* components of one density sphere */
#define SCN_MAX_COMPONENTS 65536           /* density components, all prims */
#define SCN_MAX_KEYS 65536                 /* keyframes over all clusters */
#define SCN_MAX_CLUSTER_KEYS 65535         /* keyframes of one cluster */
#define SCN_MAX_VIEW_KEYS 65536            /* keyframes of the camera and the
                                              lights, all together */
#define SCN_MAX_FRAMES 100000              /* frames of one animation */
#define SCN_MAX_DEPTH 16                   /* ray recursion depth */
#define SCN_MAX_PHONG 1024                 /* highlight exponent n */
#define SCN_MAX_IOR 10.0f                  /* index of refraction */
#define SCN_MAX_COORD 1.0e8f /* |length|: a coordinate, radius, half edge or
                                 translation; the loader scales every length
                                 by a power of two to a largest of 8..16
                                 (render/limits.h, RENDER_NORM_EXP_MIN) */
#define SCN_MAX_FACTOR 1000.0f /* |value without a unit|: a weight or
                                  threshold, a map coordinate, bump depth,
                                  direction, normal (not a cluster's matrix
                                  entry or scale: SCN_MAX_SCALE): taken as
                                  it is, within the fixed build's
                                  NUM_COORD_LIMIT */
#define SCN_MAX_SCALE 1.0e8f /* |a cluster's matrix entry or key scale|: the
                                 loader takes each cluster's power of two
                                 out of them into the lengths it holds, so
                                 they enter num_t near 1 (render/scene_load.c,
                                 load_scale) */
#define SCN_MIN_SIZE 1.0e-12 /* a radius or a component radius, text form:
                                 the loader scales lengths by powers of two
                                 and the renderer refuses what its
                                 arithmetic cannot resolve (RENDER_ERR_DETAIL) */
#define SCN_MAX_REPEAT 1.0e4f              /* map repeats along u or v */
#define SCN_MAX_INTENSITY 100.0f           /* a light's colour channel */
#define SCN_MIN_FOV 0.1                    /* degrees (text form) */
#define SCN_MAX_FOV 170.0
#define SCN_MAX_SPOT_ANGLE 89.0            /* cone + falloff, degrees (text form) */
#define SCN_MAX_NAME 32                    /* names in the text form, with NUL */
#define SCN_MIN_TRIANGLE_HEIGHT 1.0e-4 /* each height of a triangle (distance of a
                                      vertex from the opposite edge), text form;
                                      the loader refuses under 1/8 of it, which
                                      leaves room for rounding to binary32 and
                                      for the fixed build's step (2^-19) */
#define SCN_LOAD_MIN_TRIANGLE_HEIGHT (SCN_MIN_TRIANGLE_HEIGHT / 8)

/* ---------------------------------------------------------------- header */
#define SCN_MAGIC_0 'L'
#define SCN_MAGIC_1 '1'
#define SCN_MAGIC_2 'S'
#define SCN_MAGIC_3 'C'
#define SCN_VERSION 7 /* 2: 32-bit cluster indices; 3: VIEW carries min_weight;
                         4: VIEW carries density_steps; 5: MATERIALS 52
                         bytes (normal and attribute maps), map kinds
                         NORMAL and ATTRIBUTE.  VIEW_KEYS (kind 11),
                         HAZE (kind 12) and EXTENT (kind 13) came later
                         without a new
                         version: a file without
                         it is what it was, and a loader from before it
                         refuses one with it as an unknown section kind.
                         6: the header's check is the word sum, not a
                         CRC-32; 7: VIEW 80 bytes (anti-aliasing) */
#define SCN_HEADER_SIZE 16
#define SCN_HDR_MAGIC 0
#define SCN_HDR_VERSION 4
#define SCN_HDR_SECTIONS 6
#define SCN_HDR_TOTAL 8
#define SCN_HDR_SUM 12
#define SCN_SUM_START 16 /* the word sum covers everything after the header */

#define SCN_SECENT_SIZE 16
#define SCN_SECENT_KIND 0
#define SCN_SECENT_OFFSET 4
#define SCN_SECENT_BYTES 8
#define SCN_SECENT_COUNT 12
#define SCN_SECTION_ALIGN 4

enum scn_section {
    SCN_SEC_VIEW = 1,      /* exactly one record: camera, image, options */
    SCN_SEC_LIGHTS = 2,    /* up to SCN_MAX_LIGHTS records */
    SCN_SEC_MATERIALS = 3,
    SCN_SEC_MAPS = 4,      /* map descriptors; texels live in TEXELS */
    SCN_SEC_TEXELS = 5,    /* bytes, all maps, record size 1 */
    SCN_SEC_CLUSTERS = 6,  /* record 0 is the root */
    SCN_SEC_PRIMS = 7,
    SCN_SEC_COMPONENTS = 8, /* density components, all density spheres */
    SCN_SEC_KEYS = 9,      /* keyframes, grouped per cluster, frames rising */
    SCN_SEC_NORMALS = 10,  /* vertex normals of smooth triangles, prims rising */
    SCN_SEC_VIEW_KEYS = 11, /* keyframes of the camera and the lights */
    SCN_SEC_HAZE = 12,     /* none or one record: the haze */
    SCN_SEC_EXTENT = 13,   /* none or one record: the triangles' extent */
};
#define SCN_SEC_COUNT 13 /* kinds are 1..SCN_SEC_COUNT */

/* The board has no trigonometry: every angle is turned into the cosine,
 * tangent or quaternion the renderer needs by the host compiler. */

/* --------------------------------------------------------- VIEW record */
#define SCN_VIEW_SIZE 80
#define SCN_VIEW_EYE 0          /* 3 x f32 */
#define SCN_VIEW_LOOK_AT 12     /* 3 x f32, != eye */
#define SCN_VIEW_UP 24          /* 3 x f32, not parallel to look_at - eye */
#define SCN_VIEW_TAN_HALF_FOV_Y 36 /* f32 > 0: tan(vertical field of view / 2) */
#define SCN_VIEW_WIDTH 40       /* u16: 1..SCN_MAX_WIDTH pixels */
#define SCN_VIEW_HEIGHT 42      /* u16: 1..SCN_MAX_HEIGHT pixels */
#define SCN_VIEW_BACKGROUND 44  /* 3 x f32 0..1, colour of rays that hit nothing */
#define SCN_VIEW_MAX_DEPTH 56   /* u16: 0..SCN_MAX_DEPTH */
#define SCN_VIEW_FLAGS 58       /* u16: SCN_OPT_* */
#define SCN_VIEW_FRAMES 60      /* u32: frames of the animation, 1 = still */
#define SCN_VIEW_MIN_WEIGHT 64  /* f32 0..1: adaptive depth; a ray whose weight
                                   (product of src and trc along its path) falls
                                   below it is not traced; 0 = depth limit only */
#define SCN_VIEW_DENSITY_STEPS 68 /* u32: SCN_MIN_DENSITY_STEPS..SCN_MAX_DENSITY_STEPS:
                                   equal steps a density sphere's root finder
                                   samples along a ray's span through its
                                   components (render/prim.c); a feature
                                   thinner than a step can be stepped over */
#define SCN_VIEW_AA_DEPTH 72    /* u16: 0..SCN_MAX_AA_DEPTH, with SCN_OPT_ANTIALIAS:
                                   how many times a pixel may be cut into
                                   four (0 = its corner rays only) */
#define SCN_VIEW_AA_ZERO 74     /* u16: 0 */
#define SCN_VIEW_AA_THRESHOLD 76 /* f32 0..1, with SCN_OPT_ANTIALIAS: a quad
                                   whose four corner colours differ by more
                                   than it in a channel (max - min, before
                                   clamping, 1 = full scale) is cut into four */
#define SCN_MAX_TAN_HALF_FOV 100.0f
#define SCN_DEFAULT_MIN_WEIGHT (1.0 / 512) /* text form's default (Hall and Greenberg 1983) */
#define SCN_MIN_DENSITY_STEPS 2
#define SCN_MAX_DENSITY_STEPS 256
#define SCN_MAX_AA_DEPTH 4 /* a pixel side cut into at most 16 */
#define SCN_DEFAULT_AA_THRESHOLD 0.1 /* text form's default */
#define SCN_DEFAULT_DENSITY_STEPS 24 /* text form's default: 16 come within 0.05
                                        dB of it on demo.scn; thin features want
                                        more (docs/results/sweeps.md, the density_steps
                                        sweep) */

/* Render options.  REFRACTIONLESS: past max_depth, transmission continues
 * along the straight ray (the paper's 4.5).  NO_REFRACTION: transmission
 * never bends, at any depth: every transmitted ray goes straight on (the
 * paper's Table 3).  The other NO_* switches turn a speed-up or shadows
 * off, for measurement only. */
#define SCN_OPT_REFRACTIONLESS 0x0001u
#define SCN_OPT_NO_BOUNDS 0x0002u
#define SCN_OPT_NO_HIERARCHY 0x0004u
#define SCN_OPT_NO_SHADOWS 0x0008u
#define SCN_OPT_NO_REFRACTION 0x0010u
#define SCN_OPT_MARK_LOST 0x0020u /* pixels that lost precision painted
                                     RENDER_LOST_COLOUR (--mark-lost) */
/* The two readings of the paper's shadows (docs/renderer.md, "Ambient and
 * shadows"); the text form sets both bits unless told otherwise, a
 * compiled scene without them keeps the earlier readings.
 * AMBIENT_SHADOWED: Fig. 5's ambient term dic F L_i takes light i as the
 * shadow rule leaves it (times what lies between), as its diffuse term
 * does; without it, ambient takes the unshadowed L_i.
 * UNTINTED_SHADOWS: a transparent object between a point and a light
 * multiplies the light by its transmissivity trc(th) alone; without it,
 * by trc(th) F (tinted by the object's colour). */
#define SCN_OPT_AMBIENT_SHADOWED 0x0040u
#define SCN_OPT_UNTINTED_SHADOWS 0x0080u
/* PAPER: the scene asks for the paper's mode (`options { paper on }`,
 * docs/scene-format.md): the host tools set the render's schedule from it
 * (lines areas, asking when finished, the clipping lists); the renderer
 * takes no notice of it, the rest of paper mode is compiled in already. */
#define SCN_OPT_PAPER 0x0100u
/* CHECK_LOST: a pixel that lost precision is traced again in double
 * (render/wide.h) and counts as lost (painted, with MARK_LOST) only when
 * its colour is more than RENDER_CHECK_LOST_STEPS/255 off double's
 * (--check-lost); it keeps its own colour. */
#define SCN_OPT_CHECK_LOST 0x0200u
/* WORLD_SPACE: the DM leaves the scene in world coordinates and the
 * camera turns the rays; a frame whose keyed cluster maps are those of the
 * frame before keeps its primitives (render_frame_t.world, --world-space). */
#define SCN_OPT_WORLD_SPACE 0x0400u
/* SPD_RULES: Eric Haines's rules for timing the Standard Procedural
 * Databases (--spd-rules, docs/results/spd.md): camera rays at the pixel
 * corners, (width+1) x (height+1) of them, each pixel the mean of its
 * four; a transmitting surface spawns a reflected ray too, whatever its
 * specular coefficient.  The host tools set the depth, min_weight and the
 * other rules beside it. */
#define SCN_OPT_SPD_RULES 0x0800u
/* ANTIALIAS: Whitted's adaptive anti-aliasing (1980; --aa, docs/renderer.md,
 * "Anti-aliasing"): camera rays at the pixel corners, shared by
 * neighbours, and a pixel cut into four where its corners differ by more
 * than SCN_VIEW_AA_THRESHOLD, down to SCN_VIEW_AA_DEPTH. */
#define SCN_OPT_ANTIALIAS 0x1000u
#define SCN_OPT_KNOWN 0x1fffu

/* ------------------------------------------------------- LIGHTS record */
#define SCN_LIGHT_SIZE 48
#define SCN_LIGHT_KIND 0        /* u32: enum scn_light_kind */
#define SCN_LIGHT_COLOUR 4      /* 3 x f32, L_i, 0..SCN_MAX_INTENSITY */
#define SCN_LIGHT_POSITION 16   /* 3 x f32, world, point and spot */
#define SCN_LIGHT_DIRECTION 28  /* 3 x f32 non-zero, the way the light travels;
                                   parallel and spot (cone axis) */
#define SCN_LIGHT_COS_INNER 40  /* f32: spot, cos of the full-intensity half-angle */
#define SCN_LIGHT_COS_OUTER 44  /* f32: spot, cos where it reaches 0, < cos_inner */

enum scn_light_kind {
    SCN_LIGHT_PARALLEL = 1,
    SCN_LIGHT_POINT = 2,
    SCN_LIGHT_SPOT = 3,
};

/* ---------------------------------------------------- MATERIALS record */
#define SCN_MAT_SIZE 52
#define SCN_MAT_COLOUR 0        /* 3 x f32, F, each 0..1 */
#define SCN_MAT_DIC 12          /* f32 0..1: ambient coefficient (per light) */
#define SCN_MAT_DRC 16          /* f32 0..1: diffuse coefficient */
#define SCN_MAT_SRC 20          /* f32 0..1: reflection coefficient at normal incidence */
#define SCN_MAT_TRC 24          /* f32 0..1: transmissivity at normal incidence */
#define SCN_MAT_FRESNEL 28      /* f32 0..1: weight of the angle dependence
                                   (Schlick's curve, render/shade.h);
                                   0 = constant src and trc */
#define SCN_MAT_IOR 32          /* f32 1..SCN_MAX_IOR */
#define SCN_MAT_PHONG 36        /* u16: n of cos^n, 0..SCN_MAX_PHONG, 0 = no highlight */
#define SCN_MAT_COLOUR_MAP 38   /* u16: map index (a COLOUR map) or SCN_NO_INDEX */
#define SCN_MAT_BUMP_MAP 40     /* u16: map index (a BUMP map) or SCN_NO_INDEX */
#define SCN_MAT_NORMAL_MAP 42   /* u16: map index (a NORMAL map) or SCN_NO_INDEX;
                                   not with a bump map */
/* u16 each: map index (an ATTRIBUTE map) or SCN_NO_INDEX; the map's value
 * (0..1) multiplies that coefficient where the surface is hit */
#define SCN_MAT_DIC_MAP 44
#define SCN_MAT_DRC_MAP 46
#define SCN_MAT_SRC_MAP 48
#define SCN_MAT_TRC_MAP 50
#define SCN_NO_INDEX 0xffffu    /* "no map" */
#define SCN_NO_CLUSTER 0xffffffffu /* "no parent" (cluster 0 only) */

/* ------------------------------------------------------------ MAPS record */
#define SCN_MAP_SIZE 24
#define SCN_MAP_KIND 0          /* u16: enum scn_map_kind */
#define SCN_MAP_WIDTH 2         /* u16: 1..SCN_MAX_MAP_SIDE */
#define SCN_MAP_HEIGHT 4        /* u16: 1..SCN_MAX_MAP_SIDE */
#define SCN_MAP_RESERVED 6      /* u16: 0 */
#define SCN_MAP_FIRST 8         /* u32: first byte in TEXELS */
#define SCN_MAP_REPEAT_U 12     /* f32 > 0: tiles across u */
#define SCN_MAP_REPEAT_V 16     /* f32 > 0: tiles across v */
#define SCN_MAP_BUMP_DEPTH 20   /* f32 >= 0: bump tilt per unit slope; 0 for
                                   other kinds */

/* COLOUR: 3 bytes per texel (R, G, B).  BUMP: 1 byte per texel, a height
 * whose gradient tilts the normal.  NORMAL: 3 signed bytes per texel (two's
 * complement), the tangent-space normal (x along T, y along B = N x T,
 * z along N) times SCN_MAP_NORMAL_ONE, unit length up to that rounding,
 * z >= 1.  ATTRIBUTE: 1 byte per texel, a value 0..255 standing for 0..1.
 * Row-major, row 0 at v = 0. */
enum scn_map_kind {
    SCN_MAP_COLOUR = 1,
    SCN_MAP_BUMP = 2,
    SCN_MAP_NORMAL = 3,
    SCN_MAP_ATTRIBUTE = 4,
};
#define SCN_MAP_COLOUR_BYTES 3
#define SCN_MAP_BUMP_BYTES 1
#define SCN_MAP_NORMAL_BYTES 3
#define SCN_MAP_ATTRIBUTE_BYTES 1
#define SCN_MAP_NORMAL_ONE 127 /* a NORMAL texel's component 1.0 */

/* ------------------------------------------------------- CLUSTERS record */
#define SCN_CLUSTER_SIZE 60
#define SCN_CLUSTER_PARENT 0    /* u32: parent index, < own; SCN_NO_CLUSTER for 0 only */
#define SCN_CLUSTER_KEY_FIRST 4 /* u32: its first keyframe in KEYS */
#define SCN_CLUSTER_MATRIX 8    /* 12 x f32: rows of the 3x4 child -> parent matrix */
#define SCN_CLUSTER_KEY_COUNT 56 /* u32: its keyframes, 0 = static, at most
                                   SCN_MAX_CLUSTER_KEYS */

/* ---------------------------------------------------------- PRIMS record */
#define SCN_PRIM_SIZE 76
#define SCN_PRIM_KIND 0         /* u16: enum scn_prim_kind */
#define SCN_PRIM_MATERIAL 2     /* u16: material index */
#define SCN_PRIM_CLUSTER 4      /* u32: the cluster it belongs to */
#define SCN_PRIM_FIRST 8        /* u32: DENSITY: first component in COMPONENTS;
                                   CONE: enum scn_cone_caps (SCN_PRIM_CAPS) */
#define SCN_PRIM_CAPS SCN_PRIM_FIRST
#define SCN_PRIM_COUNT 12       /* u32: DENSITY: components, 1..SCN_MAX_DENSITY_COMPONENTS */
#define SCN_PRIM_VALUES 16      /* SCN_PRIM_MAX_VALUES x f32, unused ones 0 */
#define SCN_PRIM_MAX_VALUES 15

/* Values of each kind, in the cluster's coordinates:
 *   TRIANGLE  v0, v1, v2 (3 each), then u0, u1, u2, then v0, v1, v2 (map coords)
 *   ELLIPSOID centre (3), semi-axes (3, each > 0)
 *   BOX       centre (3), half edge lengths (3, each > 0)
 *   DENSITY   threshold (> 0); first/count name its components
 *   CONE      base centre (3), base radius, apex centre (3), apex radius:
 *             a cone frustum or cylinder (radii >= 0, not both 0; base !=
 *             apex), its end discs capped or not by SCN_PRIM_CAPS (count 0).
 *             Kind 5 came without a new version: a loader from before it
 *             refuses the scene as one of an unknown primitive kind
 */
enum scn_prim_kind {
    SCN_PRIM_TRIANGLE = 1,
    SCN_PRIM_ELLIPSOID = 2,
    SCN_PRIM_BOX = 3,
    SCN_PRIM_DENSITY = 4,
    SCN_PRIM_CONE = 5,
};
#define SCN_PRIM_KINDS 5 /* kinds are 1..SCN_PRIM_KINDS */
#define SCN_TRIANGLE_VALUES 15
#define SCN_ELLIPSOID_VALUES 6
#define SCN_BOX_VALUES 6
#define SCN_DENSITY_VALUES 1
#define SCN_CONE_VALUES 8
/* A cone's end discs: open (NFF's `c`: "the surface exists without
 * endcaps") or both capped by flat discs (the text form's default). */
enum scn_cone_caps {
    SCN_CONE_OPEN = 0,
    SCN_CONE_CAPPED = 1,
};

/* ------------------------------------------------- COMPONENTS record */
#define SCN_COMPONENT_SIZE 20
#define SCN_COMPONENT_CENTRE 0  /* 3 x f32 */
#define SCN_COMPONENT_RADIUS 12 /* f32 > 0: d */
#define SCN_COMPONENT_WEIGHT 16 /* f32 != 0: b (negative carves) */

/* -------------------------------------------------------- NORMALS record */
/* A smooth triangle (`model { smooth on }`, beyond the paper, whose
 * triangles are flat): the unit normals at its three vertices, which the
 * renderer interpolates across it.  Only smooth triangles have one, so a
 * flat triangle costs SCN_PRIM_SIZE = 76 bytes and a smooth one
 * 76 + SCN_NORMALS_SIZE = 116.  Records name their triangle, in rising
 * prim order, at most one per triangle. */
#define SCN_NORMALS_SIZE 40
#define SCN_NORMALS_PRIM 0      /* u32: index of a TRIANGLE in PRIMS */
#define SCN_NORMALS_N 4         /* 9 x f32: n0, n1, n2 in the cluster's coordinates */
#define SCN_NORMAL_LENGTH_TOLERANCE 1.0e-3f /* each |n| within 1 +- this */

/* ----------------------------------------------------------- KEYS record */
#define SCN_KEY_SIZE 44
#define SCN_KEY_FRAME 0         /* u32: frame number, rising within a cluster */
#define SCN_KEY_TRANSLATE 4     /* 3 x f32 */
#define SCN_KEY_ROTATION 16     /* 4 x f32: unit quaternion w, x, y, z */
#define SCN_KEY_SCALE 32        /* 3 x f32, each non-zero */
#define SCN_QUAT_NORM_TOLERANCE 1.0e-3f /* |q| must be within 1 +- this */
/* K = translate * rotate * scale; between keys the renderer interpolates
 * (render/scene.h). */

/* ------------------------------------------------------ VIEW_KEYS record */
/* A keyframe of the camera or of one light: at its frame the values it
 * holds replace the VIEW record's camera or the LIGHTS record's values
 * (the light's kind stays).  Records are grouped by target, the camera's
 * first, then light 0's, light 1's, ...; frames rise within a target.
 * Between two keys of a target every value is interpolated linearly,
 * a + (b - a) w with w = (frame - a's) / (b's - a's), the weight the
 * cluster keys use; before its first key and after its last the end key
 * holds (render/prepare.c).  A target without keys keeps its static record. */
#define SCN_VKEY_SIZE 52
#define SCN_VKEY_FRAME 0        /* u32: frame number, rising within a target */
#define SCN_VKEY_TARGET 4       /* u32: SCN_VKEY_CAMERA or a light's index */
/* the camera's key (checked as the VIEW record's camera) */
#define SCN_VKEY_EYE 8          /* 3 x f32 */
#define SCN_VKEY_LOOK_AT 20     /* 3 x f32 */
#define SCN_VKEY_UP 32          /* 3 x f32 */
#define SCN_VKEY_TAN_HALF_FOV_Y 44 /* f32 > 0: its tangent is what interpolates */
#define SCN_VKEY_RESERVED 48    /* u32: 0 in a camera's key */
/* a light's key (checked as its LIGHTS record, by its kind) */
#define SCN_VKEY_COLOUR 8       /* 3 x f32 */
#define SCN_VKEY_POSITION 20    /* 3 x f32 */
#define SCN_VKEY_DIRECTION 32   /* 3 x f32 */
#define SCN_VKEY_COS_INNER 44   /* f32: its cosine is what interpolates */
#define SCN_VKEY_COS_OUTER 48   /* f32 */
#define SCN_VKEY_CAMERA 0xffffffffu

/* ----------------------------------------------------------- HAZE record */
/* haze { colour R G B  distance D } (docs/scene-format.md): a ray's colour
 * c at distance t from its origin becomes h + (c - h) exp(-t / D), and a
 * ray that hits nothing takes h, as POV-Ray's fog_type 1.  The record holds
 * 1/D (the host divides; the board scales it by the scene's power of two):
 * the loader refuses a D that, scaled, is under 1/SCN_MAX_FACTOR. */
#define SCN_HAZE_SIZE 16
#define SCN_HAZE_COLOUR 0       /* 3 x f32 0..1: h */
#define SCN_HAZE_INV_DISTANCE 12 /* f32 > 0, finite: 1/D per unit of the scene's
                                    lengths, D in 0 < D <= SCN_MAX_COORD */

/* ------------------------------------------------------- EXTENT record */
/* The triangles' extent as the loader scales the scene by it
 * (render/scene_load.h, scene_load_triangle_exp): the largest power of two
 * of a triangle coordinate's magnitude, its clusters' powers of two added.
 * The compiler states it; a loader given it does not read every triangle
 * twice, and refuses a triangle beyond it.  Without the section the loader
 * works it out. */
#define SCN_EXTENT_SIZE 4
#define SCN_EXTENT_TRI_EXP 0 /* i32 (two's complement): within
                                +-SCN_EXTENT_EXP_LIMIT, or the bits
                                SCN_EXTENT_NO_TRIANGLE (no triangle) */
#define SCN_EXTENT_EXP_LIMIT 65536
#define SCN_EXTENT_NO_TRIANGLE 0x80000000u

#endif
