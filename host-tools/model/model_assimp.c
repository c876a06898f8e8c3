/* model_assimp.c: model_assimp_load and model_load_memory through
 * libassimp (model.h); model_load runs model_assimp_load in a child
 * (model_child.c).  With assimp_lib.c, the only file of links1 that
 * includes assimp: it gives the library its own file I/O (regular files
 * only, model_io_open), copies what the library read into plain arrays
 * and checks nothing beyond what it must to copy safely. */
#include <assimp/cfileio.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "host-tools/model/assimp_lib.h"
#include "host-tools/model/model.h"
#include "host-tools/model/model_child.h"

/* Triangulate polygons, put points and lines in meshes of their own, and
 * let the library refuse a file whose structure is broken. */
#define MODEL_AI_FLAGS \
    (aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure)

/* The library's functions (assimp_lib.h), set by the two entries below. */
static const struct assimp_lib *ai;

static void model_name(char *out, const struct aiString *s)
{
    snprintf(out, MODEL_NAME_MAX, "%.*s", (int)s->length, s->data);
}

static void model_mat34(const struct aiMatrix4x4 *a, double m[12])
{
    const double r[12] = {a->a1, a->a2, a->a3, a->a4, a->b1, a->b2,
                          a->b3, a->b4, a->c1, a->c2, a->c3, a->c4};
    memcpy(m, r, sizeof r);
}

/* The node's placement in the world (product of its and its parents'). */
static void model_world(const struct aiNode *n, struct aiMatrix4x4 *w)
{
    struct aiMatrix4x4 acc = n->mTransformation, t;
    for (const struct aiNode *p = n->mParent; p; p = p->mParent) {
        t = p->mTransformation;
        ai->multiply_matrix4(&t, &acc);
        acc = t;
    }
    *w = acc;
}

static void model_xform(const struct aiMatrix4x4 *w, const struct aiVector3D *v, int point,
                        double out[3])
{
    double x = v->x, y = v->y, z = v->z, p = point ? 1 : 0;
    out[0] = w->a1 * x + w->a2 * y + w->a3 * z + w->a4 * p;
    out[1] = w->b1 * x + w->b2 * y + w->b3 * z + w->b4 * p;
    out[2] = w->c1 * x + w->c2 * y + w->c3 * z + w->c4 * p;
}

/* The node named name, or NULL (cameras and lights are placed by the node
 * of their name). */
static const struct aiNode *model_find_node(const struct aiNode *n, const struct aiString *name)
{
    if (n->mName.length == name->length && memcmp(n->mName.data, name->data, name->length) == 0)
        return n;
    for (unsigned i = 0; i < n->mNumChildren; i++) {
        const struct aiNode *f = model_find_node(n->mChildren[i], name);
        if (f)
            return f;
    }
    return NULL;
}

/* Counts nodes and their mesh references, depth first. */
static void model_count(const struct aiNode *n, int *nodes, int *refs)
{
    (*nodes)++;
    *refs += (int)n->mNumMeshes;
    for (unsigned i = 0; i < n->mNumChildren; i++)
        model_count(n->mChildren[i], nodes, refs);
}

/* Copies the nodes depth first, so a parent's index is below its children's. */
static void model_copy_nodes(struct model *m, const struct aiNode *n, int parent)
{
    int k = m->n_nodes++;
    struct model_node *d = &m->nodes[k];
    model_name(d->name, &n->mName);
    d->parent = parent;
    model_mat34(&n->mTransformation, d->m);
    d->first_mesh = m->n_node_meshes;
    d->n_meshes = (int)n->mNumMeshes;
    for (unsigned i = 0; i < n->mNumMeshes; i++)
        m->node_meshes[m->n_node_meshes++] = (int)n->mMeshes[i];
    for (unsigned i = 0; i < n->mNumChildren; i++)
        model_copy_nodes(m, n->mChildren[i], k);
}

static int model_copy_mesh(struct model_mesh *d, const struct aiMesh *a)
{
    model_name(d->name, &a->mName);
    d->material = (int)a->mMaterialIndex;
    d->n_vertices = (int)a->mNumVertices;
    d->pos = malloc(sizeof *d->pos * 3 * (a->mNumVertices + 1));
    d->uv = a->mTextureCoords[0] ? malloc(sizeof *d->uv * 2 * (a->mNumVertices + 1)) : NULL;
    d->nrm = a->mNormals ? malloc(sizeof *d->nrm * 3 * (a->mNumVertices + 1)) : NULL;
    int n_tri = 0;
    for (unsigned f = 0; f < a->mNumFaces; f++)
        n_tri += a->mFaces[f].mNumIndices == 3;
    d->idx = malloc(sizeof *d->idx * 3 * (size_t)(n_tri + 1));
    if (!d->pos || !d->idx || (a->mTextureCoords[0] && !d->uv) || (a->mNormals && !d->nrm))
        return -1;
    for (unsigned v = 0; v < a->mNumVertices; v++) {
        d->pos[3 * v] = a->mVertices[v].x;
        d->pos[3 * v + 1] = a->mVertices[v].y;
        d->pos[3 * v + 2] = a->mVertices[v].z;
        if (d->uv) {
            d->uv[2 * v] = a->mTextureCoords[0][v].x;
            d->uv[2 * v + 1] = a->mTextureCoords[0][v].y;
        }
        if (d->nrm) {
            d->nrm[3 * v] = a->mNormals[v].x;
            d->nrm[3 * v + 1] = a->mNormals[v].y;
            d->nrm[3 * v + 2] = a->mNormals[v].z;
        }
    }
    for (unsigned f = 0; f < a->mNumFaces; f++) {
        const struct aiFace *face = &a->mFaces[f];
        if (face->mNumIndices != 3) {
            d->n_other++;
            continue;
        }
        for (int j = 0; j < 3; j++)
            d->idx[3 * d->n_triangles + j] = (int)face->mIndices[j];
        d->n_triangles++;
    }
    return 0;
}

static void model_tex(const struct aiMaterial *a, enum aiTextureType t, char *out)
{
    struct aiString s;
    if (ai->material_texture_count(a, t) > 0 &&
        ai->material_texture(a, t, 0, &s, NULL, NULL, NULL, NULL, NULL, NULL) == aiReturn_SUCCESS)
        snprintf(out, MODEL_PATH_MAX, "%.*s", (int)s.length, s.data);
}

static int model_colour(const struct aiMaterial *a, const char *key, unsigned type,
                        unsigned index, double out[3])
{
    struct aiColor4D c;
    if (ai->material_color(a, key, type, index, &c) != aiReturn_SUCCESS)
        return 0;
    out[0] = c.r, out[1] = c.g, out[2] = c.b;
    return 1;
}

static int model_float(const struct aiMaterial *a, const char *key, unsigned type,
                       unsigned index, double *out)
{
    ai_real f;
    unsigned max = 1;
    if (ai->material_float_array(a, key, type, index, &f, &max) != aiReturn_SUCCESS || max != 1)
        return 0;
    *out = f;
    return 1;
}

static void model_copy_material(struct model_material *d, const struct aiMaterial *a)
{
    struct aiString s;
    if (ai->material_string(a, AI_MATKEY_NAME, &s) == aiReturn_SUCCESS)
        model_name(d->name, &s);
    d->shininess_strength = 1;
    d->opacity = 1;
    /* A material the library made up for a file without one (STL, PLY,
     * OBJ without MTL): white and fully specular there; the scene's
     * defaults here. */
    if (!d->name[0] || strcmp(d->name, AI_DEFAULT_MATERIAL_NAME) == 0) {
        snprintf(d->name, sizeof d->name, "default");
        return;
    }
    if (model_colour(a, AI_MATKEY_COLOR_DIFFUSE, d->diffuse) ||
        model_colour(a, AI_MATKEY_BASE_COLOR, d->diffuse))
        d->have |= MODEL_HAVE_DIFFUSE;
    if (model_colour(a, AI_MATKEY_COLOR_AMBIENT, d->ambient))
        d->have |= MODEL_HAVE_AMBIENT;
    if (model_colour(a, AI_MATKEY_COLOR_SPECULAR, d->specular))
        d->have |= MODEL_HAVE_SPECULAR;
    if (model_float(a, AI_MATKEY_SHININESS, &d->shininess))
        d->have |= MODEL_HAVE_SHININESS;
    model_float(a, AI_MATKEY_SHININESS_STRENGTH, &d->shininess_strength);
    if (model_float(a, AI_MATKEY_OPACITY, &d->opacity))
        d->have |= MODEL_HAVE_OPACITY;
    if (model_float(a, AI_MATKEY_TRANSMISSION_FACTOR, &d->transmission))
        d->have |= MODEL_HAVE_TRANSMISSION;
    if (model_float(a, AI_MATKEY_REFRACTI, &d->ior))
        d->have |= MODEL_HAVE_IOR;
    model_tex(a, aiTextureType_DIFFUSE, d->diffuse_tex);
    if (!d->diffuse_tex[0])
        model_tex(a, aiTextureType_BASE_COLOR, d->diffuse_tex);
    model_tex(a, aiTextureType_HEIGHT, d->bump_tex);
    if (!d->bump_tex[0]) {
        model_tex(a, aiTextureType_NORMALS, d->bump_tex);
        d->bump_is_normal = d->bump_tex[0] != 0;
    }
}

/* The first camera.  Its position is relative to the node of its name;
 * the glTF 2 reader also copies that node's translation into it, where the
 * format puts a camera at its node's origin, so there it is left out.
 * mHorizontalFOV is taken as the full angle, as the readers fill it. */
static void model_copy_camera(struct model *m, const struct aiScene *sc, int gltf)
{
    const struct aiCamera *c = sc->mCameras[0];
    struct aiVector3D pos = c->mPosition;
    if (gltf)
        pos.x = pos.y = pos.z = 0;
    const struct aiNode *n = model_find_node(sc->mRootNode, &c->mName);
    struct aiMatrix4x4 w = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    if (n)
        model_world(n, &w);
    struct aiVector3D at = {pos.x + c->mLookAt.x, pos.y + c->mLookAt.y, pos.z + c->mLookAt.z};
    model_xform(&w, &pos, 1, m->camera.eye);
    model_xform(&w, &at, 1, m->camera.look_at);
    model_xform(&w, &c->mUp, 0, m->camera.up);
    m->camera.fov = c->mHorizontalFOV * 180 / M_PI;
    m->camera.aspect = c->mAspect;
    m->have_camera = 1;
}

static void model_copy_lights(struct model *m, const struct aiScene *sc)
{
    for (unsigned i = 0; i < sc->mNumLights; i++) {
        const struct aiLight *a = sc->mLights[i];
        int kind = a->mType == aiLightSource_DIRECTIONAL ? MODEL_LIGHT_PARALLEL
                   : a->mType == aiLightSource_POINT     ? MODEL_LIGHT_POINT
                   : a->mType == aiLightSource_SPOT      ? MODEL_LIGHT_SPOT
                                                         : 0;
        if (!kind) {
            m->n_lights_other++;
            continue;
        }
        struct model_light *d = &m->lights[m->n_lights++];
        const struct aiNode *n = model_find_node(sc->mRootNode, &a->mName);
        struct aiMatrix4x4 w = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        if (n)
            model_world(n, &w);
        model_name(d->name, &a->mName);
        d->kind = kind;
        d->colour[0] = a->mColorDiffuse.r;
        d->colour[1] = a->mColorDiffuse.g;
        d->colour[2] = a->mColorDiffuse.b;
        model_xform(&w, &a->mPosition, 1, d->position);
        model_xform(&w, &a->mDirection, 0, d->direction);
        d->inner = a->mAngleInnerCone * 180 / M_PI;
        d->outer = a->mAngleOuterCone * 180 / M_PI;
    }
}

static int model_copy(struct model *m, const struct aiScene *sc, int gltf)
{
    int nodes = 0, refs = 0;
    model_count(sc->mRootNode, &nodes, &refs);
    m->nodes = calloc((size_t)nodes, sizeof *m->nodes);
    m->node_meshes = calloc((size_t)refs + 1, sizeof *m->node_meshes);
    m->meshes = calloc(sc->mNumMeshes + 1, sizeof *m->meshes);
    m->materials = calloc(sc->mNumMaterials + 1, sizeof *m->materials);
    m->lights = calloc(sc->mNumLights + 1, sizeof *m->lights);
    if (!m->nodes || !m->node_meshes || !m->meshes || !m->materials || !m->lights)
        return -1;
    model_copy_nodes(m, sc->mRootNode, -1);
    for (unsigned i = 0; i < sc->mNumMeshes; i++)
        if (model_copy_mesh(&m->meshes[m->n_meshes++], sc->mMeshes[i]) != 0)
            return -1;
    for (unsigned i = 0; i < sc->mNumMaterials; i++, m->n_materials++)
        model_copy_material(&m->materials[i], sc->mMaterials[i]);
    if (sc->mNumCameras > 0)
        model_copy_camera(m, sc, gltf);
    model_copy_lights(m, sc);
    return 0;
}

static int model_is_gltf(const char *path)
{
    const char *dot = strrchr(path, '.');
    return dot && (strcasecmp(dot, ".gltf") == 0 || strcasecmp(dot, ".glb") == 0);
}

/* libassimp 5.2's PLY reader loops without end (allocating) on a header
 * line it does not expect, e.g. `property float x outer loop` or a word
 * that is no keyword (tests/fuzz/corpus/fuzz_import/regress-assimp-ply-*),
 * so a PLY header is checked first: it ends in `end_header` within 64 KiB,
 * and every line before is `format ascii|binary_little_endian|
 * binary_big_endian V`, `comment ...`, `obj_info ...`, `element NAME COUNT`,
 * `property TYPE NAME` or `property list COUNT_TYPE ITEM_TYPE NAME`.
 * Words are split at blanks (space, tab, CR, VT, FF), of any length. */
#define MODEL_PLY_HEADER_MAX 65536
#define MODEL_PLY_WORDS 6 /* the most a line keeps; more are counted */

struct model_ply_line {
    const char *w[MODEL_PLY_WORDS];
    size_t len[MODEL_PLY_WORDS];
    int n; /* every word on the line, kept or not */
};

static int model_ply_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* The words of the n bytes at s (a line without its newline) into l. */
static void model_ply_split(const char *s, size_t n, struct model_ply_line *l)
{
    l->n = 0;
    for (size_t i = 0; i < n;) {
        while (i < n && model_ply_blank(s[i]))
            i++;
        if (i == n)
            break;
        size_t b = i;
        while (i < n && !model_ply_blank(s[i]))
            i++;
        if (l->n < MODEL_PLY_WORDS) {
            l->w[l->n] = s + b;
            l->len[l->n] = i - b;
        }
        l->n++;
    }
}

/* Word k of l is word. */
static int model_ply_is(const struct model_ply_line *l, int k, const char *word)
{
    return k < l->n && k < MODEL_PLY_WORDS && l->len[k] == strlen(word) &&
           memcmp(l->w[k], word, l->len[k]) == 0;
}

/* A header line the reader takes (one before end_header). */
static int model_ply_line_ok(const struct model_ply_line *l)
{
    if (l->n == 0 || model_ply_is(l, 0, "comment") || model_ply_is(l, 0, "obj_info"))
        return 1;
    if (model_ply_is(l, 0, "format"))
        return l->n == 3 && (model_ply_is(l, 1, "ascii") ||
                             model_ply_is(l, 1, "binary_little_endian") ||
                             model_ply_is(l, 1, "binary_big_endian"));
    if (model_ply_is(l, 0, "element"))
        return l->n == 3;
    if (model_ply_is(l, 0, "property"))
        return l->n == (model_ply_is(l, 1, "list") ? 5 : 3);
    return 0;
}

/* 0, or -1 with the first line the reader cannot take in err. */
static int model_ply_header_ok(const char *data, size_t size, const char *name, char *err,
                               size_t errlen)
{
    if (size < 3 || strncasecmp(data, "ply", 3) != 0)
        return 0; /* the reader takes a file that begins so as PLY */
    if (size > MODEL_PLY_HEADER_MAX)
        size = MODEL_PLY_HEADER_MAX;
    const char *nl = memchr(data, '\n', size);
    size_t at = nl ? (size_t)(nl - data) + 1 : size; /* past the magic line */
    while (at < size) {
        nl = memchr(data + at, '\n', size - at);
        size_t end = nl ? (size_t)(nl - data) : size;
        struct model_ply_line l;
        model_ply_split(data + at, end - at, &l);
        if (model_ply_is(&l, 0, "end_header"))
            return 0;
        if (!model_ply_line_ok(&l)) {
            char line[64];
            size_t n = end - at < sizeof line - 1 ? end - at : sizeof line - 1;
            for (size_t k = 0; k < n; k++) {
                unsigned char c = (unsigned char)data[at + k];
                line[k] = c < ' ' || c > '~' ? '?' : (char)c;
            }
            line[n] = 0;
            snprintf(err, errlen, "%s: a PLY header line the model library cannot take, "
                                  "refused before it reads the file: '%s'",
                     name, line);
            return -1;
        }
        at = end + 1;
    }
    snprintf(err, errlen, "%s: a PLY header without end_header in its first %d bytes", name,
             MODEL_PLY_HEADER_MAX);
    return -1;
}

/* ------------------------------------------------ the library's files */

/* Every file the library opens for a model read from the disk (the model,
 * its MTL, glTF buffers, ...) goes through model_io_open: opened without
 * blocking and taken only as a regular file of at most
 * MODEL_CHILD_MAX_BYTES, so a FIFO or a device named by the model neither
 * hangs the import nor is read as it is.  The first file refused is kept
 * (model_io.refused) and the import fails naming it; a file that is not
 * there is only not found, as with the library's own files. */
struct model_io {
    char refused[MODEL_PATH_MAX + 128]; /* "PATH: why", "" none */
};

struct model_io_file {
    int fd;
    size_t size;
};

static struct model_io_file *model_io_of(struct aiFile *f)
{
    return (struct model_io_file *)(void *)f->UserData;
}

static size_t model_io_read(struct aiFile *f, char *buf, size_t size, size_t count)
{
    if (size == 0 || count > SIZE_MAX / size)
        return 0;
    size_t want = size * count, got = 0;
    while (got < want) {
        ssize_t n = read(model_io_of(f)->fd, buf + got, want - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        got += (size_t)n;
    }
    return got / size;
}

static size_t model_io_write(struct aiFile *f, const char *buf, size_t size, size_t count)
{
    (void)f, (void)buf, (void)size, (void)count;
    return 0; /* opened for reading only */
}

static size_t model_io_tell(struct aiFile *f)
{
    off_t at = lseek(model_io_of(f)->fd, 0, SEEK_CUR);
    return at < 0 ? 0 : (size_t)at;
}

static size_t model_io_size(struct aiFile *f)
{
    return model_io_of(f)->size;
}

/* As fseek: offset is signed (a step back from here or the end comes as
 * a wrapped size_t); the place must stay within the file. */
static enum aiReturn model_io_seek(struct aiFile *f, size_t offset, enum aiOrigin origin)
{
    long long base = origin == aiOrigin_SET ? 0
                     : origin == aiOrigin_CUR ? (long long)model_io_tell(f)
                                              : (long long)model_io_of(f)->size;
    long long to = base + (long long)(ptrdiff_t)offset;
    if (to < 0 || to > (long long)model_io_of(f)->size ||
        lseek(model_io_of(f)->fd, (off_t)to, SEEK_SET) < 0)
        return aiReturn_FAILURE;
    return aiReturn_SUCCESS;
}

static void model_io_flush(struct aiFile *f)
{
    (void)f;
}

static struct aiFile *model_io_open(struct aiFileIO *io, const char *path, const char *mode)
{
    struct model_io *ctx = (struct model_io *)(void *)io->UserData;
    if (strpbrk(mode, "wa+"))
        return NULL;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0)
        return NULL; /* not there (or not ours): the library goes on without it */
    char why[sizeof ctx->refused];
    struct stat st;
    struct aiFile *f = calloc(1, sizeof *f);
    struct model_io_file *mf = calloc(1, sizeof *mf);
    if (model_file_check(fd, path, MODEL_CHILD_MAX_BYTES, why, sizeof why) != 0 ||
        fstat(fd, &st) != 0 || !f || !mf) {
        if (!ctx->refused[0])
            snprintf(ctx->refused, sizeof ctx->refused, "%s", f && mf ? why : "out of memory");
        free(f);
        free(mf);
        close(fd);
        return NULL;
    }
    mf->fd = fd;
    mf->size = (size_t)st.st_size;
    *f = (struct aiFile){model_io_read, model_io_write, model_io_tell, model_io_size,
                         model_io_seek, model_io_flush, (aiUserData)(void *)mf};
    return f;
}

static void model_io_close(struct aiFileIO *io, struct aiFile *f)
{
    (void)io;
    if (!f)
        return;
    close(model_io_of(f)->fd);
    free(model_io_of(f));
    free(f);
}

/* What the library read (sc, or NULL when it refused: its message) into *m;
 * name names the model in err. */
static int model_take(const struct aiScene *sc, const char *name, int gltf, struct model *m,
                      char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    if (!sc) {
        const char *why = ai->error_string();
        snprintf(err, errlen, "%s: the model library cannot read it: %s", name,
                 why && why[0] ? why : "no reason given");
        return -1;
    }
    int rc = 0;
    if (!sc->mRootNode || (sc->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
        snprintf(err, errlen, "%s: the model library read it only in part (incomplete scene)",
                 name);
        rc = -1;
    } else if (model_copy(m, sc, gltf) != 0) {
        snprintf(err, errlen, "%s: out of memory copying the model", name);
        rc = -1;
    }
    ai->release_import(sc);
    if (rc != 0)
        model_free(m);
    return rc;
}

/* ai opened; 0, or -1 with "NAME: why not" in err. */
static int model_lib_open(const char *name, char *err, size_t errlen)
{
    char why[512];
    ai = assimp_lib(why, sizeof why);
    if (!ai)
        snprintf(err, errlen, "%s: %s", name, why);
    return ai ? 0 : -1;
}

int model_assimp_load(const char *path, struct model *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    if (model_lib_open(path, err, errlen) != 0)
        return -1;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd >= 0) {
        static char head[MODEL_PLY_HEADER_MAX];
        int refused = model_file_check(fd, path, MODEL_CHILD_MAX_BYTES, err, errlen) != 0;
        ssize_t n = refused ? 0 : read(fd, head, sizeof head);
        close(fd);
        if (refused || model_ply_header_ok(head, n > 0 ? (size_t)n : 0, path, err, errlen) != 0)
            return -1;
    }
    struct model_io ctx = {""};
    struct aiFileIO io = {model_io_open, model_io_close, (aiUserData)(void *)&ctx};
    const struct aiScene *sc = ai->import_file_ex(path, MODEL_AI_FLAGS, &io);
    if (ctx.refused[0]) {
        ai->release_import(sc);
        if (strncmp(ctx.refused, path, strlen(path)) == 0 && ctx.refused[strlen(path)] == ':')
            snprintf(err, errlen, "%s", ctx.refused);
        else
            snprintf(err, errlen, "%s: a file it refers to, %s", path, ctx.refused);
        return -1;
    }
    return model_take(sc, path, model_is_gltf(path), m, err, errlen);
}

int model_load_memory(const void *data, size_t size, const char *hint, struct model *m,
                      char *err, size_t errlen)
{
    char name[32];
    snprintf(name, sizeof name, "(memory).%s", hint);
    memset(m, 0, sizeof *m);
    if (size == 0 || size > MODEL_MEMORY_MAX) {
        snprintf(err, errlen, "%s: %zu bytes, not 1 to %u", name, size, MODEL_MEMORY_MAX);
        return -1;
    }
    if (model_ply_header_ok(data, size, name, err, errlen) != 0 ||
        model_lib_open(name, err, errlen) != 0)
        return -1;
    const struct aiScene *sc =
        ai->import_file_from_memory(data, (unsigned)size, MODEL_AI_FLAGS, hint);
    return model_take(sc, name, model_is_gltf(name), m, err, errlen);
}

void model_free(struct model *m)
{
    for (int i = 0; i < m->n_meshes; i++) {
        free(m->meshes[i].pos);
        free(m->meshes[i].uv);
        free(m->meshes[i].nrm);
        free(m->meshes[i].idx);
    }
    free(m->nodes);
    free(m->node_meshes);
    free(m->meshes);
    free(m->materials);
    free(m->lights);
    memset(m, 0, sizeof *m);
}
