/* test_model_child.c: the model library in a child process (model_child.h,
 * model_wire.h): the same model as read in this process for every file of
 * tests/models/, the wire form cut short or damaged never read as a model
 * that does not hold together, and a child that crashes, aborts, exits
 * badly, runs too long, sends too much or sends a malformed model each
 * named; an OBJ whose MTL is a FIFO or a device refused at once, naming
 * it.  The inputs of tests/fuzz/assimp-crashes/ (on which libassimp
 * itself crashes) go through the child with the fuzz harness's own way of
 * reading them (model_load_memory).  Runs from the repository's top. */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "host-tools/model/model_child.h"
#include "host-tools/model/model_wire.h"
#include "tests/check.h"

#define MODELS "tests/models/"
#define CRASHES "tests/fuzz/assimp-crashes/"
#define TEST_ERR_MAX 1024

static const struct model_child_limits test_lim = {20000, MODEL_CHILD_MAX_BYTES, 0, 0};

static int same_doubles(const double *a, const double *b, size_t n)
{
    return (!a && !b) || (a && b && memcmp(a, b, n * sizeof *a) == 0);
}

/* a and b hold the same model, field by field (doubles bit for bit). */
static int model_same(const struct model *a, const struct model *b)
{
    if (a->n_nodes != b->n_nodes || a->n_node_meshes != b->n_node_meshes ||
        a->n_meshes != b->n_meshes || a->n_materials != b->n_materials ||
        a->n_lights != b->n_lights || a->n_lights_other != b->n_lights_other ||
        a->have_camera != b->have_camera)
        return 0;
    for (int i = 0; i < a->n_nodes; i++) {
        const struct model_node *x = &a->nodes[i], *y = &b->nodes[i];
        if (strcmp(x->name, y->name) || x->parent != y->parent || x->first_mesh != y->first_mesh ||
            x->n_meshes != y->n_meshes || !same_doubles(x->m, y->m, 12))
            return 0;
    }
    if (memcmp(a->node_meshes, b->node_meshes, sizeof(int) * (size_t)a->n_node_meshes))
        return 0;
    for (int i = 0; i < a->n_meshes; i++) {
        const struct model_mesh *x = &a->meshes[i], *y = &b->meshes[i];
        size_t nv = (size_t)x->n_vertices;
        if (strcmp(x->name, y->name) || x->material != y->material ||
            x->n_vertices != y->n_vertices || x->n_triangles != y->n_triangles ||
            x->n_other != y->n_other || !same_doubles(x->pos, y->pos, 3 * nv) ||
            !same_doubles(x->uv, y->uv, 2 * nv) || !same_doubles(x->nrm, y->nrm, 3 * nv) ||
            memcmp(x->idx, y->idx, sizeof(int) * 3 * (size_t)x->n_triangles))
            return 0;
    }
    for (int i = 0; i < a->n_materials; i++) {
        const struct model_material *x = &a->materials[i], *y = &b->materials[i];
        if (strcmp(x->name, y->name) || x->have != y->have ||
            !same_doubles(x->diffuse, y->diffuse, 3) || !same_doubles(x->ambient, y->ambient, 3) ||
            !same_doubles(x->specular, y->specular, 3) ||
            !same_doubles(&x->shininess, &y->shininess, 1) ||
            !same_doubles(&x->shininess_strength, &y->shininess_strength, 1) ||
            !same_doubles(&x->opacity, &y->opacity, 1) ||
            !same_doubles(&x->transmission, &y->transmission, 1) ||
            !same_doubles(&x->ior, &y->ior, 1) || strcmp(x->diffuse_tex, y->diffuse_tex) ||
            strcmp(x->bump_tex, y->bump_tex) || x->bump_is_normal != y->bump_is_normal)
            return 0;
    }
    if (a->have_camera &&
        (!same_doubles(a->camera.eye, b->camera.eye, 3) ||
         !same_doubles(a->camera.look_at, b->camera.look_at, 3) ||
         !same_doubles(a->camera.up, b->camera.up, 3) ||
         !same_doubles(&a->camera.fov, &b->camera.fov, 1) ||
         !same_doubles(&a->camera.aspect, &b->camera.aspect, 1)))
        return 0;
    for (int i = 0; i < a->n_lights; i++) {
        const struct model_light *x = &a->lights[i], *y = &b->lights[i];
        if (strcmp(x->name, y->name) || x->kind != y->kind ||
            !same_doubles(x->colour, y->colour, 3) || !same_doubles(x->position, y->position, 3) ||
            !same_doubles(x->direction, y->direction, 3) || !same_doubles(&x->inner, &y->inner, 1) ||
            !same_doubles(&x->outer, &y->outer, 1))
            return 0;
    }
    return 1;
}

/* Every model file of tests/models/: model_load (the child) gives what
 * model_assimp_load gives in this process, or the same refusal; and each
 * file loads, or is refused, as it is known to (a model neither side could
 * load would otherwise pass). */
static void test_child_same_as_in_process(void)
{
    static const struct {
        const char *file;
        int loads; /* 1: the library reads it (the scene may refuse it later) */
    } files[] = {{"cube.obj", 1},       {"ball.obj", 1},        {"plate.gltf", 1},
                 {"tetra.ply", 1},      {"pyramid.stl", 1},     {"tower.dae", 1},
                 {"tetra.3ds", 1},      {"huge.obj", 1},        {"degenerate.obj", 1},
                 {"nonfinite.obj", 1},  {"missing_tex.obj", 1}, {"bad_syntax.gltf", 0}};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        char path[256], e1[TEST_ERR_MAX] = "", e2[TEST_ERR_MAX] = "";
        snprintf(path, sizeof path, MODELS "%s", files[i].file);
        struct model here, child;
        int r1 = model_assimp_load(path, &here, e1, sizeof e1);
        int r2 = model_load(path, &child, e2, sizeof e2);
        CHECK_EQ_INT(r2, r1);
        if ((r1 == 0) != files[i].loads) {
            printf("  %s: %s\n", path, files[i].loads ? e1 : "read, but it is known bad");
            CHECK(!"the file loads, or is refused, as it is known to");
        }
        if (r1 == 0 && here.n_meshes == 0) {
            printf("  %s: no mesh\n", path);
            CHECK(!"a model read holds a mesh");
        }
        if (r1 == 0 && r2 == 0 && !model_same(&here, &child)) {
            printf("  %s differs\n", path);
            CHECK(!"the child's model equals the one read here");
        }
        if (r1 != 0 && r2 != 0 && strcmp(e1, e2) != 0) {
            printf("  %s: '%s' against '%s'\n", path, e1, e2);
            CHECK(!"the child's refusal equals the one here");
        }
        if (r1 != 0 && e1[0] == 0)
            CHECK(!"a refusal names its reason");
        if (r1 == 0)
            model_free(&here);
        if (r2 == 0)
            model_free(&child);
    }
}

/* cube.obj as wire bytes, in *len (malloc). */
static unsigned char *wire_of_cube(size_t *len, struct model *m)
{
    char err[TEST_ERR_MAX];
    *len = 0;
    if (model_assimp_load(MODELS "cube.obj", m, err, sizeof err) != 0)
        return NULL;
    FILE *f = tmpfile();
    if (!f)
        return NULL;
    unsigned char *b = NULL;
    if (model_wire_send(fileno(f), m) == 0) {
        long n = ftell(f) >= 0 ? lseek(fileno(f), 0, SEEK_END) : -1;
        b = n > 0 ? malloc((size_t)n) : NULL;
        if (b && (lseek(fileno(f), 0, SEEK_SET) != 0 || read(fileno(f), b, (size_t)n) != n)) {
            free(b);
            b = NULL;
        }
        *len = b ? (size_t)n : 0;
    }
    fclose(f);
    return b;
}

/* The wire form reads back equal; every shorter prefix and a byte more are
 * refused; each byte damaged is refused or reads as a model whose
 * indices hold (ASan would see a read outside it). */
static void test_wire_cut_and_damaged(void)
{
    struct model m, back;
    size_t len;
    unsigned char *b = wire_of_cube(&len, &m);
    CHECK(b != NULL && len > 100);
    if (!b)
        return;
    char why[256];
    CHECK(model_wire_take(b, len, &back, why, sizeof why) == 0);
    CHECK(model_same(&m, &back));
    model_free(&back);
    int cut_refused = 0;
    for (size_t n = 0; n < len; n++)
        cut_refused += model_wire_take(b, n, &back, why, sizeof why) != 0;
    CHECK_EQ_INT(cut_refused, len);
    unsigned char *more = malloc(len + 1);
    memcpy(more, b, len);
    more[len] = 0;
    CHECK(model_wire_take(more, len + 1, &back, why, sizeof why) != 0 &&
          strstr(why, "1 bytes after the end mark"));
    free(more);
    int refused = 0, taken = 0, broken = 0;
    for (size_t k = 0; k < len; k++) {
        for (unsigned flip = 1; flip < 256; flip <<= 3) {
            b[k] ^= (unsigned char)flip;
            if (model_wire_take(b, len, &back, why, sizeof why) != 0) {
                refused++;
                broken += why[0] == 0;
            } else {
                taken++;
                for (int i = 0; i < back.n_meshes; i++)
                    for (int t = 0; t < 3 * back.meshes[i].n_triangles; t++)
                        broken += back.meshes[i].idx[t] < 0 ||
                                  back.meshes[i].idx[t] >= back.meshes[i].n_vertices;
                model_free(&back);
            }
            b[k] ^= (unsigned char)flip;
        }
    }
    CHECK(refused > 0 && taken > 0); /* a damaged double still reads */
    CHECK_EQ_INT(broken, 0);
    model_free(&m);
    free(b);
}

/* ---------------------------------------------------- children that fail */

static int load_segv(const char *path, struct model *m, char *err, size_t errlen)
{
    (void)path, (void)m, (void)err, (void)errlen;
    static volatile uintptr_t nowhere = 16;
    return *(volatile int *)nowhere; /* a real invalid read, as the library's */
}

static int load_abort(const char *path, struct model *m, char *err, size_t errlen)
{
    (void)path, (void)m, (void)err, (void)errlen;
    abort();
}

static int load_exit7(const char *path, struct model *m, char *err, size_t errlen)
{
    (void)path, (void)m, (void)err, (void)errlen;
    _exit(7);
}

static int load_hang(const char *path, struct model *m, char *err, size_t errlen)
{
    (void)path, (void)m, (void)err, (void)errlen;
    for (;;)
        pause();
    return -1;
}

static int load_refuse(const char *path, struct model *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    snprintf(err, errlen, "%s: refused \x01 here", path);
    return -1;
}

static int load_refuse_silently(const char *path, struct model *m, char *err, size_t errlen)
{
    (void)path, (void)errlen;
    memset(m, 0, sizeof *m);
    err[0] = 0;
    return -1;
}

/* A model whose second node's parent is itself. */
static int load_forward_parent(const char *path, struct model *m, char *err, size_t errlen)
{
    if (model_assimp_load(path, m, err, errlen) != 0 || m->n_nodes < 2)
        return -1;
    m->nodes[1].parent = 1;
    return 0;
}

/* A model whose triangle names a vertex beyond its mesh. */
static int load_bad_index(const char *path, struct model *m, char *err, size_t errlen)
{
    if (model_assimp_load(path, m, err, errlen) != 0 || m->n_meshes < 1)
        return -1;
    m->meshes[0].idx[4] = m->meshes[0].n_vertices;
    return 0;
}

struct child_case {
    const char *name;
    model_loader_fn load;
    struct model_child_limits lim;
    const char *want;
};

static void test_children_that_fail(void)
{
    static const struct child_case cases[] = {
        {"segv", load_segv, {20000, MODEL_CHILD_MAX_BYTES, 0, 0},
         MODELS "cube.obj: the model library crashed (signal 11, SIGSEGV) while reading it; "
                "the file is malformed or unsupported"},
        {"abort", load_abort, {20000, MODEL_CHILD_MAX_BYTES, 0, 0},
         MODELS "cube.obj: the model library crashed (signal 6, SIGABRT)"},
        {"exit", load_exit7, {20000, MODEL_CHILD_MAX_BYTES, 0, 0},
         MODELS "cube.obj: the model library failed (exit status 7) while reading it"},
        {"hang", load_hang, {300, MODEL_CHILD_MAX_BYTES, 0, 0},
         MODELS "cube.obj: the model library did not finish reading it within 0.3 s (stopped)"},
        {"too big", model_assimp_load, {20000, 1000, 0, 0},
         MODELS "cube.obj: the model library handed back more than 1000 bytes (stopped)"},
        {"refusal", load_refuse, {20000, MODEL_CHILD_MAX_BYTES, 0, 0},
         MODELS "cube.obj: refused ? here"},
        {"silent refusal", load_refuse_silently, {20000, MODEL_CHILD_MAX_BYTES, 0, 0},
         MODELS "cube.obj: the model library refused it without saying why"},
        {"parent", load_forward_parent, {20000, MODEL_CHILD_MAX_BYTES, 0, 0},
         MODELS "cube.obj: the model library handed back malformed data (node 1: parent 1, "
                "not -1 to 0)"},
        {"index", load_bad_index, {20000, MODEL_CHILD_MAX_BYTES, 0, 0},
         MODELS "cube.obj: the model library handed back malformed data (mesh 0: triangle 1 "
                "names vertex"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        struct model m;
        char err[TEST_ERR_MAX] = "";
        int rc = model_child_load(MODELS "cube.obj", cases[i].load, &cases[i].lim, &m, err,
                                  sizeof err);
        if (rc == 0 || strncmp(err, cases[i].want, strlen(cases[i].want)) != 0) {
            printf("  %s: rc %d, '%s'\n", cases[i].name, rc, err);
            CHECK(!"the child's failure is named");
        }
        CHECK(m.n_nodes == 0 && m.nodes == NULL && m.meshes == NULL);
    }
    CHECK(waitpid(-1, NULL, WNOHANG) < 0 && errno == ECHILD); /* every child reaped */
}

/* ------------------------------------------- the child's own limits */

/* Tells the limits the child runs under, as its refusal. */
static int load_tell_limits(const char *path, struct model *m, char *err, size_t errlen)
{
    (void)path;
    memset(m, 0, sizeof *m);
    struct rlimit as, cpu;
    getrlimit(RLIMIT_AS, &as);
    getrlimit(RLIMIT_CPU, &cpu);
    snprintf(err, errlen, "as %llu cpu %llu", (unsigned long long)as.rlim_cur,
             (unsigned long long)cpu.rlim_cur);
    return -1;
}

/* The greedy child's allocations: far more than a child may add. */
#define GREEDY_CHUNK ((size_t)64 << 20)
#define GREEDY_TOTAL (((size_t)MODEL_CHILD_MEMORY_MB + 1024) << 20)

/* Takes GREEDY_TOTAL bytes (untouched) before reading the model. */
static int load_greedy(const char *path, struct model *m, char *err, size_t errlen)
{
    size_t want = GREEDY_TOTAL / GREEDY_CHUNK, got = 0;
    void **p = calloc(want, sizeof *p);
    while (p && got < want && (p[got] = malloc(GREEDY_CHUNK)) != NULL)
        got++;
    for (size_t i = 0; i < got; i++)
        free(p[i]);
    free(p);
    if (got < want) {
        memset(m, 0, sizeof *m);
        snprintf(err, errlen, "%s: out of memory after %zu MiB", path, got * (GREEDY_CHUNK >> 20));
        return -1;
    }
    return model_assimp_load(path, m, err, errlen);
}

/* Spins on the CPU without end. */
static int load_spin(const char *path, struct model *m, char *err, size_t errlen)
{
    (void)path, (void)m, (void)err, (void)errlen;
    for (volatile unsigned long n = 0;; n++) {
    }
    return -1;
}

static long long now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

static void test_child_limits(void)
{
    struct model m;
    char err[TEST_ERR_MAX] = "";
    int rc = model_child_load(MODELS "cube.obj", load_tell_limits, &test_lim, &m, err,
                              sizeof err);
    unsigned long long as = ULLONG_MAX, cpu = ULLONG_MAX;
    sscanf(err, "as %llu cpu %llu", &as, &cpu);
    CHECK_EQ_INT(rc, -1);
    CHECK(as != (unsigned long long)RLIM_INFINITY);
    CHECK(cpu == MODEL_CHILD_CPU_S);
    if (as == (unsigned long long)RLIM_INFINITY || cpu == (unsigned long long)RLIM_INFINITY)
        printf("  the child runs with: %s\n", err);
    /* a child that takes more memory than it may is stopped */
    rc = model_child_load(MODELS "cube.obj", load_greedy, &test_lim, &m, err, sizeof err);
    CHECK_EQ_INT(rc, -1);
    if (rc == 0) {
        printf("  the child took %zu MiB and read the model\n", GREEDY_TOTAL >> 20);
        model_free(&m);
    }
    if (rc != 0 && !strstr(err, "out of memory after") && !strstr(err, "MiB a reader may take"))
        printf("  the greedy child: %s\n", err);
    CHECK(rc != 0 && (strstr(err, "out of memory after") || strstr(err, "MiB a reader may take")));
    /* a child that spins is stopped by its CPU limit, before the deadline */
    static const struct model_child_limits spin_lim = {30000, MODEL_CHILD_MAX_BYTES, 1, 0};
    long long t0 = now_ms();
    rc = model_child_load(MODELS "cube.obj", load_spin, &spin_lim, &m, err, sizeof err);
    CHECK_EQ_INT(rc, -1);
    CHECK(strstr(err, "used more than 1 s of CPU time") != NULL);
    CHECK(now_ms() - t0 < 10000);
    if (!strstr(err, "used more than 1 s of CPU time"))
        printf("  the spinning child: %s\n", err);
    /* the models of tests/models/ still load under the limits */
    CHECK_EQ_INT(model_load(MODELS "cube.obj", &m, err, sizeof err), 0);
    model_free(&m);
}

/* ------------------------------------ libassimp's own crashes, in a child */

static const char *const fuzz_formats[8] = {"obj", "ply", "stl", "gltf",
                                            "dae", "3ds", "glb", "off"};

/* Reads a fuzz_import input (first byte: the format) as the harness does. */
static int load_fuzz_input(const char *path, struct model *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    FILE *f = fopen(path, "rb");
    static unsigned char data[1 << 20];
    size_t n = f ? fread(data, 1, sizeof data, f) : 0;
    if (f)
        fclose(f);
    if (n < 2) {
        snprintf(err, errlen, "%s: cannot read it", path);
        return -1;
    }
    return model_load_memory(data + 1, n - 1, fuzz_formats[data[0] & 7], m, err, errlen);
}

static void test_library_crashes_in_child(void)
{
    DIR *d = opendir(CRASHES);
    CHECK(d != NULL);
    if (!d)
        return;
    int inputs = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.' || strcmp(e->d_name, "README") == 0)
            continue;
        char path[512], err[TEST_ERR_MAX] = "";
        snprintf(path, sizeof path, CRASHES "%s", e->d_name);
        struct model m;
        int rc = model_child_load(path, load_fuzz_input, &test_lim, &m, err, sizeof err);
        inputs++;
        char want[600];
        snprintf(want, sizeof want, "%s: the model library crashed (signal ", path);
        if (rc == 0 || strncmp(err, want, strlen(want)) != 0 ||
            !strstr(err, "; the file is malformed or unsupported")) {
            printf("  %s: rc %d, '%s'\n", path, rc, err);
            CHECK(!"libassimp's crash is named");
        }
        if (rc == 0)
            model_free(&m);
    }
    closedir(d);
    CHECK(inputs >= 3);
}

/* ------------------------------------ files the model names, as they are */

/* An OBJ in dir whose MTL (name) is made by make, read through the child
 * within 5 s: refused naming the MTL and what it is, well before then. */
static void side_file_refused(const char *dir, const char *name, const char *what)
{
    char obj[PATH_MAX], want[PATH_MAX + 64], err[TEST_ERR_MAX] = "";
    snprintf(obj, sizeof obj, "%s/uses_%s.obj", dir, name);
    FILE *f = fopen(obj, "w");
    CHECK(f != NULL);
    if (!f)
        return;
    fprintf(f, "mtllib %s\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", name);
    fclose(f);
    static const struct model_child_limits lim = {5000, MODEL_CHILD_MAX_BYTES, 0, 0};
    struct model m;
    long long t0 = now_ms();
    int rc = model_child_load(obj, model_assimp_load, &lim, &m, err, sizeof err);
    long long ms = now_ms() - t0;
    snprintf(want, sizeof want, "%s/%s: not a regular file (%s): not read", dir, name, what);
    if (rc == 0 || !strstr(err, want) || ms >= 4000) {
        printf("  %s: rc %d after %lld ms, '%s'; want '%s'\n", obj, rc, ms, err, want);
        CHECK(!"a file the model names that is not a regular file is refused, named, at once");
    }
    if (rc == 0)
        model_free(&m);
}

/* An OBJ whose MTL is a FIFO (no writer: opening it to read would wait
 * for ever), or a link to /dev/zero, is refused naming it. */
static void test_side_files_refused(void)
{
    char dir[] = "/tmp/links1-test-model-XXXXXX", p[PATH_MAX];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(p, sizeof p, "%s/fifo.mtl", dir);
    CHECK(mkfifo(p, 0600) == 0);
    side_file_refused(dir, "fifo.mtl", "a FIFO");
    snprintf(p, sizeof p, "%s/zero.mtl", dir);
    CHECK(symlink("/dev/zero", p) == 0);
    side_file_refused(dir, "zero.mtl", "a device");
    static const char *const made[] = {"fifo.mtl", "zero.mtl", "uses_fifo.mtl.obj",
                                       "uses_zero.mtl.obj"};
    for (size_t i = 0; i < sizeof made / sizeof made[0]; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, made[i]);
        unlink(p);
    }
    CHECK(rmdir(dir) == 0);
}

int main(void)
{
    RUN(test_child_same_as_in_process);
    RUN(test_wire_cut_and_damaged);
    RUN(test_children_that_fail);
    RUN(test_library_crashes_in_child);
    RUN(test_child_limits);
    RUN(test_side_files_refused);
    return check_exit();
}
