/* test_scene_image.c: image files (PNG through libpng, PPM by hand) keep
 * every byte, PNG values are read as stored (no gamma conversion), and
 * `links1 compare` counts differences and the silhouette mask correctly. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/image/image_io.h"
#include "host-tools/image/image_save.h"
#include "host-tools/cli/scene_cmds.h"
#include "tests/check.h"

#define W 23
#define H 17

static void make_image(struct image *img)
{
    img->width = W;
    img->height = H;
    img->rgb = malloc(W * H * 3);
    for (int i = 0; i < W * H * 3; i++)
        img->rgb[i] = (uint8_t)(i * 37 + i / 7);
}

static void tmp_path(char *buf, size_t n, const char *ext)
{
    snprintf(buf, n, "/tmp/test_scene_image_%ld%s", (long)getpid(), ext);
}

static void test_round_trips(void)
{
    struct image a, b;
    char err[256], path[128];
    make_image(&a);
    const char *exts[] = {".png", ".ppm"};
    for (int k = 0; k < 2; k++) {
        tmp_path(path, sizeof path, exts[k]);
        int rc = image_save(path, &a, k, err, sizeof err);
        CHECK_EQ_INT(rc, 0);
        CHECK_EQ_INT(image_read(path, &b, err, sizeof err), 0);
        CHECK_EQ_INT(b.width, W);
        CHECK_EQ_INT(b.height, H);
        CHECK(b.rgb && memcmp(a.rgb, b.rgb, W * H * 3) == 0);
        image_free(&b);
        remove(path);
    }
    image_free(&a);
}

static void test_bad_files_named(void)
{
    struct image b;
    char err[256], path[128];
    tmp_path(path, sizeof path, ".bad");
    FILE *f = fopen(path, "wb");
    fputs("P6\n4 4\n255\nabc", f); /* 3 of 48 pixel bytes */
    fclose(f);
    CHECK_EQ_INT(image_read(path, &b, err, sizeof err), -1);
    CHECK(strstr(err, "truncated") != NULL && strstr(err, path) != NULL);
    f = fopen(path, "wb");
    fputs("not an image at all", f);
    fclose(f);
    CHECK_EQ_INT(image_read(path, &b, err, sizeof err), -1);
    CHECK(strstr(err, "not a readable PNG") != NULL);
    remove(path);
    CHECK_EQ_INT(image_read("/nonexistent/x.png", &b, err, sizeof err), -1);
}

static int run_compare(const char *a, const char *b, const char *within, const char *frac,
                       int silhouette)
{
    char *argv[] = {"compare", (char *)a, (char *)b, "--within", (char *)within,
                    "--min-fraction", (char *)frac, silhouette ? "--silhouette" : NULL, NULL};
    int argc = silhouette ? 8 : 7;
    fflush(stdout);
    FILE *saved = stdout; /* keep the report out of the PASS/FAIL lines */
    stdout = fopen("/dev/null", "w");
    int rc = scene_cmd_compare(argc, argv);
    fclose(stdout);
    stdout = saved;
    return rc;
}

static void test_compare_counts(void)
{
    struct image a, b;
    char err[256], pa[128], pb[128];
    a.width = b.width = 10;
    a.height = b.height = 10;
    a.rgb = calloc(300, 1);
    b.rgb = calloc(300, 1);
    for (int i = 0; i < 300; i++)
        a.rgb[i] = b.rgb[i] = 100;
    b.rgb[3 * 55 + 1] = 103; /* one pixel 3 levels off: 99% within 2 */
    tmp_path(pa, sizeof pa, "_a.ppm");
    tmp_path(pb, sizeof pb, "_b.ppm");
    image_save(pa, &a, 1, err, sizeof err);
    image_save(pb, &b, 1, err, sizeof err);
    CHECK_EQ_INT(run_compare(pa, pb, "3", "1", 0), 0);
    CHECK_EQ_INT(run_compare(pa, pb, "2", "0.99", 0), 0);
    CHECK_EQ_INT(run_compare(pa, pb, "2", "0.995", 0), 1);
    /* An edge in A next to the odd pixel: the silhouette mask leaves it out. */
    a.rgb[3 * 56] = 200;
    image_save(pa, &a, 1, err, sizeof err);
    CHECK_EQ_INT(run_compare(pa, pb, "2", "1", 0), 1);
    CHECK_EQ_INT(run_compare(pa, pb, "2", "1", 1), 0);
    remove(pa);
    remove(pb);
    image_free(&a);
    image_free(&b);
}

int main(void)
{
    RUN(test_round_trips);
    RUN(test_bad_files_named);
    RUN(test_compare_counts);
    return check_exit();
}
