/* model_wire.c: a struct model as bytes and back (model_wire.h).
 *
 * Layout, in the machine's own byte order: the magic "L1MW", the version,
 * the counts (nodes, node mesh references, meshes, materials, lights,
 * lights left out, have_camera), then the nodes (each a struct model_node),
 * the node mesh references (int each), each mesh (name, material,
 * n_vertices, n_triangles, n_other, has_uv, has_nrm, then its positions,
 * uvs, normals as doubles and its indices as ints), the materials (each a
 * struct model_material), the camera (a struct model_camera), the lights
 * (each a struct model_light), and the end mark "END.". */
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/model/model_wire.h"

#define WIRE_MAGIC "L1MW"
#define WIRE_END "END."
#define WIRE_VERSION 1u
#define WIRE_BUF 65536

/* ------------------------------------------------------------- writing */

struct wire_out {
    int fd, bad;
    size_t n;
    unsigned char buf[WIRE_BUF];
};

static void wire_flush(struct wire_out *o)
{
    for (size_t at = 0; at < o->n && !o->bad;) {
        ssize_t k = write(o->fd, o->buf + at, o->n - at);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            o->bad = 1;
        else
            at += (size_t)k;
    }
    o->n = 0;
}

static void wire_put(struct wire_out *o, const void *p, size_t len)
{
    const unsigned char *b = p;
    while (len > 0 && !o->bad) {
        size_t k = WIRE_BUF - o->n < len ? WIRE_BUF - o->n : len;
        memcpy(o->buf + o->n, b, k);
        o->n += k, b += k, len -= k;
        if (o->n == WIRE_BUF)
            wire_flush(o);
    }
}

static void wire_put_int(struct wire_out *o, int v)
{
    int32_t x = v;
    wire_put(o, &x, sizeof x);
}

int model_wire_send(int fd, const struct model *m)
{
    static struct wire_out o; /* large; one writer per process */
    o.fd = fd, o.bad = 0, o.n = 0;
    wire_put(&o, WIRE_MAGIC, 4);
    wire_put_int(&o, (int)WIRE_VERSION);
    const int counts[7] = {m->n_nodes,     m->n_node_meshes, m->n_meshes,      m->n_materials,
                           m->n_lights,    m->n_lights_other, m->have_camera};
    for (int i = 0; i < 7; i++)
        wire_put_int(&o, counts[i]);
    wire_put(&o, m->nodes, sizeof *m->nodes * (size_t)m->n_nodes);
    for (int i = 0; i < m->n_node_meshes; i++)
        wire_put_int(&o, m->node_meshes[i]);
    for (int i = 0; i < m->n_meshes; i++) {
        const struct model_mesh *me = &m->meshes[i];
        wire_put(&o, me->name, sizeof me->name);
        const int head[6] = {me->material, me->n_vertices, me->n_triangles, me->n_other,
                             me->uv != NULL, me->nrm != NULL};
        for (int j = 0; j < 6; j++)
            wire_put_int(&o, head[j]);
        size_t nv = (size_t)me->n_vertices;
        wire_put(&o, me->pos, sizeof *me->pos * 3 * nv);
        if (me->uv)
            wire_put(&o, me->uv, sizeof *me->uv * 2 * nv);
        if (me->nrm)
            wire_put(&o, me->nrm, sizeof *me->nrm * 3 * nv);
        for (int t = 0; t < 3 * me->n_triangles; t++)
            wire_put_int(&o, me->idx[t]);
    }
    wire_put(&o, m->materials, sizeof *m->materials * (size_t)m->n_materials);
    wire_put(&o, &m->camera, sizeof m->camera);
    wire_put(&o, m->lights, sizeof *m->lights * (size_t)m->n_lights);
    wire_put(&o, WIRE_END, 4);
    wire_flush(&o);
    return o.bad ? -1 : 0;
}

/* ------------------------------------------------------------- reading */

struct wire_in {
    const unsigned char *p;
    size_t left;
    char *why;
    size_t whylen;
    int bad;
};

static int wire_fail(struct wire_in *in, const char *fmt, ...)
{
    if (!in->bad) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(in->why, in->whylen, fmt, ap);
        va_end(ap);
    }
    in->bad = 1;
    return -1;
}

/* Takes len bytes into dst; fails, naming what, when they are not there. */
static int wire_get(struct wire_in *in, void *dst, size_t len, const char *what)
{
    if (in->bad)
        return -1;
    if (len > in->left)
        return wire_fail(in, "cut short in %s", what);
    memcpy(dst, in->p, len);
    in->p += len, in->left -= len;
    return 0;
}

/* A count of items of size bytes each: 0..INT_MAX/4 and no more items than
 * the bytes left could hold.  -1 when it is not. */
static int wire_count(struct wire_in *in, size_t size, const char *what)
{
    int32_t n = 0;
    if (wire_get(in, &n, sizeof n, what) != 0)
        return -1;
    if (n < 0 || n > INT_MAX / 4 || (size > 0 && (size_t)n > in->left / size)) {
        wire_fail(in, "%s: %ld, more than the %zu bytes left could hold", what, (long)n,
                  in->left);
        return -1;
    }
    return (int)n;
}

static int wire_int(struct wire_in *in, const char *what)
{
    int32_t v = 0;
    wire_get(in, &v, sizeof v, what);
    return (int)v;
}

/* An array of n items of size bytes (+1 item, so never 0 bytes). */
static void *wire_array(struct wire_in *in, size_t n, size_t size, const char *what)
{
    if (in->bad)
        return NULL;
    if (n > in->left / size) {
        wire_fail(in, "cut short in %s", what);
        return NULL;
    }
    void *a = calloc(n + 1, size);
    if (!a) {
        wire_fail(in, "out of memory for %s", what);
        return NULL;
    }
    if (wire_get(in, a, n * size, what) != 0) {
        free(a);
        return NULL;
    }
    return a;
}

static int wire_name_ok(struct wire_in *in, const char *name, size_t size, const char *what,
                        int k)
{
    if (!memchr(name, 0, size))
        return wire_fail(in, "%s %d: a name without its end", what, k);
    return 0;
}

static int wire_nodes(struct wire_in *in, struct model *m)
{
    for (int k = 0; k < m->n_nodes && !in->bad; k++) {
        const struct model_node *n = &m->nodes[k];
        wire_name_ok(in, n->name, sizeof n->name, "node", k);
        if (n->parent < -1 || n->parent >= k)
            return wire_fail(in, "node %d: parent %d, not -1 to %d", k, n->parent, k - 1);
        if (n->first_mesh < 0 || n->n_meshes < 0 || n->first_mesh > m->n_node_meshes ||
            n->n_meshes > m->n_node_meshes - n->first_mesh)
            return wire_fail(in, "node %d: meshes %d+%d beyond the %d references", k,
                             n->first_mesh, n->n_meshes, m->n_node_meshes);
    }
    for (int i = 0; i < m->n_node_meshes && !in->bad; i++)
        if (m->node_meshes[i] < 0 || m->node_meshes[i] >= m->n_meshes)
            return wire_fail(in, "mesh reference %d: mesh %d of %d", i, m->node_meshes[i],
                             m->n_meshes);
    return in->bad ? -1 : 0;
}

static int wire_mesh(struct wire_in *in, struct model_mesh *me, int k)
{
    if (wire_get(in, me->name, sizeof me->name, "a mesh's name") != 0 ||
        wire_name_ok(in, me->name, sizeof me->name, "mesh", k) != 0)
        return -1;
    me->material = wire_int(in, "a mesh's material");
    int nv = wire_count(in, 3 * sizeof(double), "a mesh's vertex count");
    int nt = wire_count(in, 3 * sizeof(int32_t), "a mesh's triangle count");
    int no = wire_count(in, 0, "a mesh's count of points and lines");
    int has_uv = wire_int(in, "a mesh's uv flag"), has_nrm = wire_int(in, "a mesh's normal flag");
    if (in->bad)
        return -1;
    if ((has_uv != 0 && has_uv != 1) || (has_nrm != 0 && has_nrm != 1))
        return wire_fail(in, "mesh %d: uv and normal flags %d %d, not 0 or 1", k, has_uv,
                         has_nrm);
    me->n_vertices = nv, me->n_other = no;
    me->pos = wire_array(in, 3 * (size_t)nv, sizeof *me->pos, "a mesh's positions");
    if (has_uv)
        me->uv = wire_array(in, 2 * (size_t)nv, sizeof *me->uv, "a mesh's uvs");
    if (has_nrm)
        me->nrm = wire_array(in, 3 * (size_t)nv, sizeof *me->nrm, "a mesh's normals");
    int32_t *idx = wire_array(in, 3 * (size_t)nt, sizeof *idx, "a mesh's triangles");
    if (in->bad) {
        free(idx);
        return -1;
    }
    me->idx = (int *)idx;
    me->n_triangles = nt;
    for (int t = 0; t < 3 * nt; t++)
        if (idx[t] < 0 || idx[t] >= nv)
            return wire_fail(in, "mesh %d: triangle %d names vertex %ld of %d", k, t / 3,
                             (long)idx[t], nv);
    return 0;
}

static int wire_looks(struct wire_in *in, struct model *m)
{
    for (int i = 0; i < m->n_materials && !in->bad; i++) {
        const struct model_material *mm = &m->materials[i];
        wire_name_ok(in, mm->name, sizeof mm->name, "material", i);
        wire_name_ok(in, mm->diffuse_tex, sizeof mm->diffuse_tex, "material texture", i);
        wire_name_ok(in, mm->bump_tex, sizeof mm->bump_tex, "material bump texture", i);
    }
    for (int i = 0; i < m->n_lights && !in->bad; i++) {
        const struct model_light *l = &m->lights[i];
        wire_name_ok(in, l->name, sizeof l->name, "light", i);
        if (l->kind != MODEL_LIGHT_PARALLEL && l->kind != MODEL_LIGHT_POINT &&
            l->kind != MODEL_LIGHT_SPOT)
            return wire_fail(in, "light %d: kind %d", i, l->kind);
    }
    return in->bad ? -1 : 0;
}

int model_wire_take(const void *buf, size_t len, struct model *m, char *why, size_t whylen)
{
    memset(m, 0, sizeof *m);
    struct wire_in in = {buf, len, why, whylen, 0};
    char magic[4] = "", end[4] = "";
    wire_get(&in, magic, 4, "the magic");
    if (!in.bad && memcmp(magic, WIRE_MAGIC, 4) != 0)
        wire_fail(&in, "not a model (magic)");
    int version = wire_int(&in, "the version");
    if (!in.bad && version != (int)WIRE_VERSION)
        wire_fail(&in, "version %d, not %u", version, WIRE_VERSION);
    int n_nodes = wire_count(&in, sizeof *m->nodes, "the node count");
    int n_refs = wire_count(&in, sizeof(int32_t), "the mesh reference count");
    int n_meshes = wire_count(&in, 6 * sizeof(int32_t), "the mesh count");
    int n_materials = wire_count(&in, sizeof *m->materials, "the material count");
    int n_lights = wire_count(&in, sizeof *m->lights, "the light count");
    int n_other = wire_count(&in, 0, "the count of lights left out");
    int have_camera = wire_int(&in, "the camera flag");
    if (!in.bad && (have_camera != 0 && have_camera != 1))
        wire_fail(&in, "camera flag %d, not 0 or 1", have_camera);
    if (!in.bad && n_nodes < 1)
        wire_fail(&in, "no nodes");
    if (in.bad)
        return -1;
    m->have_camera = have_camera, m->n_lights_other = n_other;
    m->nodes = wire_array(&in, (size_t)n_nodes, sizeof *m->nodes, "the nodes");
    m->node_meshes = wire_array(&in, (size_t)n_refs, sizeof *m->node_meshes, "the references");
    m->meshes = in.bad ? NULL : calloc((size_t)n_meshes + 1, sizeof *m->meshes);
    if (!in.bad && !m->meshes)
        wire_fail(&in, "out of memory for the meshes");
    if (!in.bad) {
        m->n_nodes = n_nodes, m->n_node_meshes = n_refs;
        for (int i = 0; i < n_meshes && !in.bad; i++) {
            m->n_meshes = i + 1; /* model_free frees what the mesh got */
            wire_mesh(&in, &m->meshes[i], i);
        }
        m->n_meshes = n_meshes;
    }
    wire_nodes(&in, m);
    m->materials = wire_array(&in, (size_t)n_materials, sizeof *m->materials, "the materials");
    if (!in.bad)
        m->n_materials = n_materials;
    wire_get(&in, &m->camera, sizeof m->camera, "the camera");
    m->lights = wire_array(&in, (size_t)n_lights, sizeof *m->lights, "the lights");
    if (!in.bad)
        m->n_lights = n_lights;
    wire_looks(&in, m);
    wire_get(&in, end, 4, "the end mark");
    if (!in.bad && memcmp(end, WIRE_END, 4) != 0)
        wire_fail(&in, "no end mark where it belongs");
    if (!in.bad && in.left != 0)
        wire_fail(&in, "%zu bytes after the end mark", in.left);
    if (in.bad) {
        model_free(m);
        return -1;
    }
    return 0;
}
