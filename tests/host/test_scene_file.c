/* test_scene_file.c: a scene file as `links1 ref` and `links1 render` both
 * read it (host-tools/scene/scene_file.c): a text scene is compiled with the
 * changes asked for, a compiled one read as is, an empty or oversized
 * compiled file and a change asked of a compiled one refused by name, and
 * per-frame output names. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_file.h"
#include "tests/check.h"

static const char *scene_text =
    "camera { eye 0 1 -5 look_at 0 0 0 up 0 1 0 fov 60 }\n"
    "resolution 64 48\n"
    "light point { position 1 2 3 }\n"
    "material m { colour 1 1 1 }\n"
    "sphere { material m radius 1 }\n";

static char dir[] = "/tmp/links1-test-scene-file-XXXXXX";

static void write_file(const char *path, const void *data, size_t len)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fwrite(data, 1, len, f);
        fclose(f);
    }
}

static void test_text_compiled_with_changes(void)
{
    char scn[128], err[SD_ERR_MAX];
    snprintf(scn, sizeof scn, "%s/a.scn", dir);
    write_file(scn, scene_text, strlen(scene_text));
    struct scene_file_opts o;
    scene_file_opts_init(&o);
    uint8_t *plain, *sized;
    size_t plain_len, sized_len;
    CHECK_EQ_INT(scene_file_bytes(scn, &o, &plain, &plain_len, err, sizeof err), 0);
    o.width = 32;
    o.height = 24;
    CHECK_EQ_INT(scene_file_bytes(scn, &o, &sized, &sized_len, err, sizeof err), 0);
    CHECK(plain_len > 0 && plain_len == sized_len);
    CHECK(plain_len == sized_len && memcmp(plain, sized, plain_len) != 0);
    /* The compiled form read back as is. */
    char l1s[128];
    snprintf(l1s, sizeof l1s, "%s/a.l1s", dir);
    write_file(l1s, plain, plain_len);
    uint8_t *read;
    size_t read_len;
    scene_file_opts_init(&o);
    CHECK_EQ_INT(scene_file_bytes(l1s, &o, &read, &read_len, err, sizeof err), 0);
    CHECK(read_len == plain_len && memcmp(read, plain, plain_len) == 0);
    free(plain);
    free(sized);
    free(read);
    /* A change asked of a compiled scene is refused by name. */
    o.max_depth = 2;
    CHECK_EQ_INT(scene_file_bytes(l1s, &o, &read, &read_len, err, sizeof err), -1);
    CHECK(strstr(err, l1s) && strstr(err, "--max-depth needs a text scene"));
    remove(scn);
    remove(l1s);
}

static void test_bad_files_refused(void)
{
    char path[128], err[SD_ERR_MAX];
    struct scene_file_opts o;
    scene_file_opts_init(&o);
    uint8_t *buf = (uint8_t *)1;
    size_t len = 1;
    snprintf(path, sizeof path, "%s/empty.l1s", dir);
    write_file(path, "", 0);
    CHECK_EQ_INT(scene_file_bytes(path, &o, &buf, &len, err, sizeof err), -1);
    CHECK(strstr(err, path) && strstr(err, ": empty file, not a compiled scene"));
    CHECK(buf == NULL);
    remove(path);
    snprintf(path, sizeof path, "%s/missing.l1s", dir);
    CHECK_EQ_INT(scene_file_bytes(path, &o, &buf, &len, err, sizeof err), -1);
    CHECK(strstr(err, path) && strstr(err, "No such file"));
    snprintf(path, sizeof path, "%s/broken.scn", dir);
    write_file(path, "sphere { radius -1 }\n", 21);
    CHECK_EQ_INT(scene_file_bytes(path, &o, &buf, &len, err, sizeof err), -1);
    CHECK(strncmp(err, path, strlen(path)) == 0);
    remove(path);
}

static void test_frame_paths(void)
{
    char buf[64];
    scene_file_frame_path("a.png", 7, buf, sizeof buf);
    CHECK(strcmp(buf, "a-0007.png") == 0);
    scene_file_frame_path("out/x.y/anim", 12, buf, sizeof buf);
    CHECK(strcmp(buf, "out/x.y/anim-0012") == 0);
    scene_file_frame_path("d.x/f.ppm", 0, buf, sizeof buf);
    CHECK(strcmp(buf, "d.x/f-0000.ppm") == 0);
    CHECK(scene_file_ends_with("a.l1s", ".l1s") && !scene_file_ends_with("l1s", ".l1s"));
}

int main(void)
{
    if (!mkdtemp(dir)) {
        printf("FAIL test_scene_file: cannot make %s\n", dir);
        return 1;
    }
    RUN(test_text_compiled_with_changes);
    RUN(test_bad_files_refused);
    RUN(test_frame_paths);
    rmdir(dir);
    return check_exit();
}
