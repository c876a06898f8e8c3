/* model.h: a 3-D model read from a file made elsewhere (OBJ+MTL, glTF 2,
 * PLY, STL, Collada, 3DS, ...), as plain data.  model_assimp.c fills it
 * through libassimp and is the only file that knows assimp (model_load runs
 * it in a child process: model_child.c, model_wire.c); scene_import.c
 * turns it into scene records.  Everything here is as the file has it:
 * right-handed coordinates, assimp's units, nothing checked yet.
 */
#ifndef LINKS1_HOST_SCENE_MODEL_H
#define LINKS1_HOST_SCENE_MODEL_H

#include <stddef.h>

#define MODEL_NAME_MAX 64
#define MODEL_PATH_MAX 1024

struct model_node {
    char name[MODEL_NAME_MAX];
    int parent;             /* index of the parent node (always lower), -1: the root */
    double m[12];           /* 3x4 row-major, node -> parent */
    int first_mesh, n_meshes; /* into model.node_meshes */
};

struct model_mesh {
    char name[MODEL_NAME_MAX];
    int material;           /* into model.materials */
    int n_vertices;
    double *pos;            /* 3 per vertex */
    double *uv;             /* 2 per vertex, NULL when the mesh has none */
    double *nrm;            /* vertex normals, 3 per vertex, NULL when none */
    int n_triangles;
    int *idx;               /* 3 vertex indices per triangle */
    int n_other;            /* points, lines: not triangles, left out */
};

/* Which material properties the file gave (the rest keep their defaults). */
#define MODEL_HAVE_DIFFUSE 0x01u
#define MODEL_HAVE_AMBIENT 0x02u
#define MODEL_HAVE_SPECULAR 0x04u
#define MODEL_HAVE_SHININESS 0x08u
#define MODEL_HAVE_OPACITY 0x10u
#define MODEL_HAVE_TRANSMISSION 0x20u
#define MODEL_HAVE_IOR 0x40u

struct model_material {
    char name[MODEL_NAME_MAX];
    unsigned have;          /* MODEL_HAVE_* */
    double diffuse[3], ambient[3], specular[3];
    double shininess;       /* exponent */
    double shininess_strength; /* scales specular; 1 when not given */
    double opacity;         /* 1 = opaque */
    double transmission;    /* 0..1 */
    double ior;
    char diffuse_tex[MODEL_PATH_MAX]; /* as written in the file; "" none, "*N" embedded */
    char bump_tex[MODEL_PATH_MAX];    /* a bump (height) or normal texture */
    int bump_is_normal;     /* bump_tex is a normal (tangent-space) texture,
                               imported as a normal map; else a height */
};

struct model_camera {       /* world coordinates */
    double eye[3], look_at[3], up[3];
    double fov;             /* horizontal, degrees */
    double aspect;          /* width / height; 0 when not given */
};

/* The kinds of light a model file can hold. */
enum model_light_kind {
    MODEL_LIGHT_PARALLEL = 1, /* a direction only (the sun); 0 is no kind */
    MODEL_LIGHT_POINT = 2,    /* a position, shining every way */
    MODEL_LIGHT_SPOT = 3,     /* a position, a direction and a cone */
};

struct model_light {        /* world coordinates */
    char name[MODEL_NAME_MAX];
    int kind;               /* enum model_light_kind */
    double colour[3], position[3], direction[3];
    double inner, outer;    /* spot: full cone angles, degrees */
};

struct model {
    struct model_node *nodes;
    int n_nodes;
    int *node_meshes;       /* mesh indices, each node's run */
    int n_node_meshes;
    struct model_mesh *meshes;
    int n_meshes;
    struct model_material *materials;
    int n_materials;
    int have_camera;        /* the first camera of the file, if any */
    struct model_camera camera;
    struct model_light *lights;
    int n_lights;
    int n_lights_other;     /* ambient and area lights, left out */
};

/* Reads the model at path into *m.  0, or -1 with "PATH: why" in err (the
 * library's own message when it refuses the file) and *m empty.  The
 * library reads the file in a child process (model_child.c): a crash,
 * abort or endless loop in it ends in a message naming what happened,
 * never in the end of the program. */
int model_load(const char *path, struct model *m, char *err, size_t errlen);
/* The same in this process (model_assimp.c; what model_load's child runs):
 * the library's crashes are the program's. */
int model_assimp_load(const char *path, struct model *m, char *err, size_t errlen);
/* model_assimp_load from size bytes in memory, in this process (the fuzz
 * harness); hint is the format's file extension ("obj", "ply", "stl",
 * "gltf", ...).  A file an OBJ or glTF names (its MTL, buffers) is still
 * read from the disk. */
#define MODEL_MEMORY_MAX (64u * 1024u * 1024u)
int model_load_memory(const void *data, size_t size, const char *hint, struct model *m,
                      char *err, size_t errlen);
void model_free(struct model *m);

#endif
