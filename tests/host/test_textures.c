/* Host tests of a model's texture paths (scene_import.c, scene_texture.c):
 * a texture is read only from the model's own directory (and below), or
 * from a directory the user allows (`model { ... textures_from "DIR" }`,
 * `links1 import --textures-from DIR`); an absolute path, ../ or a link
 * that leads out of it is refused, and so is anything but a regular file
 * (a directory, a device, a FIFO, which never blocks the read).  Each
 * refusal names the texture and the problem.  Models are written at run
 * time in a directory of the test's own. */
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include "host-tools/model/model.h"
#include "host-tools/opts/tmp_dir.h"
#include "host-tools/scene/scene_import.h"
#include "tests/check.h"
#include "tests/host/empty_scene.h"

static char root[64];
static char model_dir[128]; /* root/model/ */

static void at(char *out, size_t cap, const char *rel)
{
    snprintf(out, cap, "%s/%s", root, rel);
}

static void put(const char *rel, const char *text)
{
    char path[256];
    at(path, sizeof path, rel);
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* A 2x2 binary PPM. */
static void put_ppm(const char *rel)
{
    char path[256];
    at(path, sizeof path, rel);
    FILE *f = fopen(path, "wb");
    if (f) {
        fputs("P6\n2 2\n255\n", f);
        for (int i = 0; i < 12; i++)
            fputc(40 * (i % 6), f);
        fclose(f);
    }
}

/* The model's material names tex as its diffuse texture. */
static void model_with(const char *tex)
{
    char mtl[512];
    snprintf(mtl, sizeof mtl, "newmtl painted\nKd 1 1 1\nmap_Kd %s\n", tex);
    put("model/x.mtl", mtl);
}


static struct import_result res;

/* The model imported with texture tex: 0, or -1 with err. */
static int import_with(const char *tex, char *err, size_t cap)
{
    char obj[256];
    at(obj, sizeof obj, "model/x.obj");
    model_with(tex);
    struct model m;
    if (model_load(obj, &m, err, cap) != 0)
        return -1;
    struct sd_scene s;
    empty_scene(&s);
    struct import_opts o = {.fit = 0, .material = -1, .fit_hint = "--fit"};
    int rc = scene_import_model(&s, 0, &m, model_dir, &o, &res, err, cap);
    model_free(&m);
    sd_free(&s);
    return rc;
}

static void expect_loads(const char *tex)
{
    char err[2048] = "";
    int rc = import_with(tex, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc != 0)
        printf("    %s: %s\n", tex, err);
}

static void expect_refused(const char *tex, const char *want)
{
    char err[2048] = "";
    int rc = import_with(tex, err, sizeof err);
    CHECK_EQ_INT(rc, -1);
    CHECK(strstr(err, want) != NULL);
    if (rc == 0 || !strstr(err, want))
        printf("    %s: rc %d, '%s'\n", tex, rc, err);
}

static void textures_inside_load(void)
{
    expect_loads("t.ppm");
    expect_loads("sub/t2.ppm");
    expect_loads("in_link.ppm"); /* a link that stays inside */
    char abs[256];
    at(abs, sizeof abs, "model/t.ppm");
    expect_loads(abs); /* absolute, but inside */
}

static void textures_outside_refused(void)
{
    char abs[256];
    at(abs, sizeof abs, "outside/o.ppm");
    expect_refused("../outside/o.ppm", "outside the model's directory");
    expect_refused(abs, "outside the model's directory");
    expect_refused("out_link.ppm", "outside the model's directory");
    expect_refused("sub/../../outside/o.ppm", "outside the model's directory");
    expect_refused("/dev/zero", "outside the model's directory");
}

static void textures_not_regular_refused(void)
{
    expect_refused("dir.ppm", "not a regular file");
    char dev[256];
    at(dev, sizeof dev, "model/zero.ppm");
    if (mknod(dev, S_IFCHR | 0600, makedev(1, 5)) == 0)
        expect_refused("zero.ppm", "not a regular file");
    else
        printf("    (no device node can be made here: not root)\n");
}

/* The model statement: textures_from allows one more directory. */
static void textures_from_allows(void)
{
    char scn[256], err[2048] = "";
    at(scn, sizeof scn, "scene.scn");
    model_with("../outside/o.ppm");
    struct sd_scene s;
    const char *plain = "light point { position 0 5 -5 }\nmodel { file \"model/x.obj\" }\n";
    int rc = sd_parse_text(scn, plain, &s, err, sizeof err);
    CHECK(rc != 0 && strstr(err, "outside the model's directory"));
    if (rc == 0)
        sd_free(&s);
    const char *allowed = "light point { position 0 5 -5 }\n"
                          "model { file \"model/x.obj\"  textures_from \"outside\" }\n";
    rc = sd_parse_text(scn, allowed, &s, err, sizeof err);
    CHECK_EQ_INT(rc, 0);
    if (rc == 0)
        sd_free(&s);
    else
        printf("    textures_from: %s\n", err);
    /* what it allows is that directory only */
    model_with("../elsewhere/e.ppm");
    rc = sd_parse_text(scn, allowed, &s, err, sizeof err);
    CHECK(rc != 0 && strstr(err, "outside the model's directory"));
    if (rc == 0)
        sd_free(&s);
}

/* Last: on a FIFO the old reader blocked for ever (the alarm ends it). */
static void textures_fifo_refused(void)
{
    expect_refused("fifo.ppm", "not a regular file");
}

int main(void)
{
    alarm(60);
    snprintf(root, sizeof root, "/tmp/links1-tex-XXXXXX");
    if (!mkdtemp(root)) {
        printf("FAIL test_textures: mkdtemp\n");
        return 1;
    }
    snprintf(model_dir, sizeof model_dir, "%s/model/", root);
    char p[256], q[256];
    at(p, sizeof p, "model");
    mkdir(p, 0700);
    at(p, sizeof p, "model/sub");
    mkdir(p, 0700);
    at(p, sizeof p, "model/dir.ppm");
    mkdir(p, 0700);
    at(p, sizeof p, "outside");
    mkdir(p, 0700);
    at(p, sizeof p, "elsewhere");
    mkdir(p, 0700);
    put("model/x.obj", "mtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                       "usemtl painted\nf 1/1 2/2 3/3\n");
    put_ppm("model/t.ppm");
    put_ppm("model/sub/t2.ppm");
    put_ppm("outside/o.ppm");
    put_ppm("elsewhere/e.ppm");
    at(p, sizeof p, "model/in_link.ppm");
    CHECK(symlink("t.ppm", p) == 0);
    at(p, sizeof p, "model/out_link.ppm");
    at(q, sizeof q, "outside/o.ppm");
    CHECK(symlink(q, p) == 0);
    at(p, sizeof p, "model/fifo.ppm");
    CHECK(mkfifo(p, 0600) == 0);
    RUN(textures_inside_load);
    RUN(textures_outside_refused);
    RUN(textures_not_regular_refused);
    RUN(textures_from_allows);
    RUN(textures_fifo_refused);
    tmp_dir_remove(root);
    return check_exit();
}
