/* fuzz_image_map.c: libFuzzer harness of the image-map loader: the input is
 * an image file (PNG through libpng, or binary PPM) that a scene's colour
 * map and bump map both read (`map ... { image "FILE" }`, parse_map_image
 * over image_read), and then another scene's normal map and attribute map.
 * A scene that parses is compiled, loaded and prepared as the DM does, and
 * a few pixels of a sphere wearing the maps are traced, so the texels
 * reach the map lookups (render/maps.c).  A map's image is read only from
 * below the scene's directory (sd_image_open_below), so the input is
 * written to in.img in a directory of the harness's own (mkdtemp), beside
 * the scene it names. */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <unistd.h>

#include "host-tools/scene/scene_desc.h"
#include "render/blob.h"

#define FUZZ_BLOCK (8u * 1024u * 1024u)

static int fuzz_fd = -1;
static uint8_t *fuzz_mem;
static char fuzz_dir[] = "/tmp/links1-fuzz-map.XXXXXX";
static char fuzz_scn[64]; /* fuzz_dir/fuzz.scn: the image in.img beside it */
static char fuzz_img[64];

/* The directory and its image removed when the fuzzer exits. */
static void fuzz_cleanup(void)
{
    unlink(fuzz_img);
    rmdir(fuzz_dir);
}

/* text parsed, compiled, loaded and prepared, and a few pixels traced. */
static void fuzz_scene(const char *text)
{
    struct sd_scene s;
    char err[SD_ERR_MAX];
    err[0] = 0;
    int verbose = getenv("FUZZ_VERBOSE") != NULL; /* say why an input is refused */
    if (sd_parse_text(fuzz_scn, text, &s, err, sizeof err) != 0) {
        if (verbose)
            fprintf(stderr, "refused: %s\n", err);
        if (err[0] == 0)
            abort(); /* a refused image is named */
        return;
    }
    uint8_t *buf;
    size_t len;
    int rc = sd_compile(&s, &buf, &len, err, sizeof err);
    sd_free(&s);
    if (rc != 0)
        return;
    render_blob_t *blob;
    render_blob_error_t berr;
    if (render_blob_build(buf, len, 0, fuzz_mem, FUZZ_BLOCK, NULL, &blob, &berr) !=
        RENDER_BLOB_OK)
        abort(); /* a map that parsed must load and prepare */
    render_ctx_t ctx;
    render_ctx_init(&ctx, blob->frame);
    for (uint32_t y = 2; y < 6; y++)
        for (uint32_t x = 2; x < 6; x++)
            render_pixel(&ctx, x, y);
    free(buf);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (fuzz_fd < 0) {
        if (!mkdtemp(fuzz_dir))
            abort();
        snprintf(fuzz_scn, sizeof fuzz_scn, "%s/fuzz.scn", fuzz_dir);
        snprintf(fuzz_img, sizeof fuzz_img, "%s/in.img", fuzz_dir);
        atexit(fuzz_cleanup);
        fuzz_fd = open(fuzz_img, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        fuzz_mem = aligned_alloc(RENDER_RELOCATE_ALIGN, FUZZ_BLOCK);
        if (fuzz_fd < 0 || !fuzz_mem)
            abort();
    }
    if (ftruncate(fuzz_fd, 0) != 0 || pwrite(fuzz_fd, data, size, 0) != (ssize_t)size)
        abort();
    char text[1024];
    snprintf(text, sizeof text,
             "camera { eye 0 0 -4 look_at 0 0 0 up 0 1 0 fov 40 }\n"
             "resolution 8 8\n"
             "light parallel { direction 0.3 -0.5 1 }\n"
             "map c colour { image \"in.img\" repeat 2 3 }\n"
             "map b bump { image \"in.img\" repeat 3 2 depth 0.8 }\n"
             "material m { colour_map c bump_map b phong 10 }\n"
             "sphere { material m radius 1.2 }\n");
    fuzz_scene(text);
    snprintf(text, sizeof text,
             "camera { eye 0 0 -4 look_at 0 0 0 up 0 1 0 fov 40 }\n"
             "resolution 8 8\n"
             "light parallel { direction 0.3 -0.5 1 }\n"
             "map n normal { image \"in.img\" repeat 2 3 }\n"
             "map a attribute { image \"in.img\" repeat 3 2 }\n"
             "material m { normal_map n src 0.5 trc 0.4 src_map a trc_map a drc_map a }\n"
             "sphere { material m radius 1.2 }\n");
    fuzz_scene(text);
    return 0;
}
