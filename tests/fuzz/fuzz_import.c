/* fuzz_import.c: libFuzzer harness of the model importer: the input's
 * first byte picks a format and the options, the rest is a model file that
 * libassimp reads from memory with that format as its hint
 * (model_load_memory), then the project's own import code takes it as
 * `links1 import` does: scene_import_model into a fresh scene (the model's
 * materials and textures, or one scene material, `fit` and `smooth` on or
 * off), scene_import_view (the camera, or `--camera auto`), the
 * scene written as text and read back (sd_write_text, sd_parse_text), then
 * compiled, loaded and prepared as the DM does, and a few pixels traced.
 *
 * First byte: bits 0-2 the format (FUZZ_FORMATS), bit 3 fit, bit 4 one
 * scene material instead of the model's, bit 5 smooth, bit 6 camera auto
 * (always taken for a model without a camera, to reach the tracing).
 * Textures are looked for in tests/models/ (run from the repository's top);
 * inputs naming "..", "/dev/" or "/proc/" are skipped, so the fuzzer reads
 * no file outside the tree and never a device. */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_import.h"
#include "render/blob.h"

#define FUZZ_BLOCK (16u * 1024u * 1024u)
#define FUZZ_MAX_INPUT (256u * 1024u)

static const char *const fuzz_formats[8] = {"obj", "ply", "stl", "gltf",
                                            "dae", "3ds", "glb", "off"};

/* The input names something outside the tree or a device. */
static int fuzz_names_outside(const uint8_t *data, size_t size)
{
    static const char *const bad[] = {"..", "/dev/", "/proc/", "/sys/"};
    for (size_t b = 0; b < sizeof bad / sizeof bad[0]; b++)
        if (memmem(data, size, bad[b], strlen(bad[b])))
            return 1;
    return 0;
}

/* The scene s written as text, read back and compiled; aborts when the
 * text does not read back (the writer and the parser disagree). */
static int fuzz_round_trip(const struct sd_scene *s, const struct import_result *r,
                           uint8_t **buf, size_t *len)
{
    char *text = NULL;
    size_t tlen = 0;
    FILE *f = open_memstream(&text, &tlen);
    if (!f)
        abort();
    const char *maps[SCN_MAX_MAPS];
    for (int i = 0; i < s->n_maps; i++)
        maps[i] = r->map_image[i];
    int rc = sd_write_text(s, maps, f);
    if (fclose(f) != 0 || rc != 0)
        abort();
    struct sd_scene back;
    char err[SD_ERR_MAX];
    if (sd_parse_text("tests/models/fuzz.scn", text, &back, err, sizeof err) != 0) {
        fprintf(stderr, "the written scene does not read back: %s\n%s\n", err, text);
        abort();
    }
    free(text);
    rc = sd_compile(&back, buf, len, err, sizeof err);
    sd_free(&back);
    if (rc != 0 && err[0] == 0)
        abort(); /* a refusal names the problem */
    return rc;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t *mem;
    static FILE *notes; /* the import's warnings, not wanted here */
    if (size < 2 || size > FUZZ_MAX_INPUT || fuzz_names_outside(data, size))
        return 0;
    if (!mem && !(mem = aligned_alloc(RENDER_RELOCATE_ALIGN, FUZZ_BLOCK)))
        abort();
    if (!notes && !(notes = fopen("/dev/null", "w")))
        abort();
    unsigned opt = data[0];
    struct model m;
    char err[SD_ERR_MAX];
    err[0] = 0;
    int verbose = getenv("FUZZ_VERBOSE") != NULL; /* say why an input is refused */
    if (model_load_memory(data + 1, size - 1, fuzz_formats[opt & 7], &m, err, sizeof err) !=
        0) {
        if (verbose)
            fprintf(stderr, "refused: %s\n", err);
        if (err[0] == 0)
            abort();
        return 0;
    }
    struct sd_scene s;
    memset(&s, 0, sizeof s);
    sd_view_defaults(&s.view);
    s.clusters = calloc(1, sizeof *s.clusters);
    s.materials = calloc(1, sizeof *s.materials);
    struct import_result *r = calloc(1, sizeof *r);
    if (!s.clusters || !s.materials || !r)
        abort();
    snprintf(s.clusters[0].name, sizeof s.clusters[0].name, "root");
    s.clusters[0].parent = -1;
    s.clusters[0].m[0] = s.clusters[0].m[5] = s.clusters[0].m[10] = 1;
    s.n_clusters = 1;
    int one_material = (opt & 0x10) != 0;
    if (one_material) { /* the scene's own material, as `model { material m }` */
        snprintf(s.materials[0].name, sizeof s.materials[0].name, "m");
        s.materials[0].colour[0] = s.materials[0].colour[1] = s.materials[0].colour[2] = 1;
        s.materials[0].dic = 0.1, s.materials[0].drc = 0.9, s.materials[0].ior = 1;
        sd_material_no_maps(&s.materials[0]);
        s.n_materials = 1;
    }
    struct import_opts o = {(opt & 8) != 0, one_material ? 0 : -1, 0, "fit", (opt & 0x20) != 0,
                            NULL};
    int rc = scene_import_model(&s, 0, &m, "tests/models/", &o, r, err, sizeof err);
    if (rc == 0)
        rc = scene_import_view(&s, &m, r, (opt & 0x40) || !m.have_camera, notes, err,
                               sizeof err);
    model_free(&m);
    if (rc != 0 && err[0] == 0)
        abort();
    uint8_t *buf = NULL;
    size_t len = 0;
    if (rc == 0)
        rc = fuzz_round_trip(&s, r, &buf, &len);
    sd_free(&s);
    free(r);
    if (rc != 0) {
        if (verbose)
            fprintf(stderr, "refused: %s\n", err);
        return 0;
    }
    render_blob_t *blob;
    render_blob_error_t berr;
    render_blob_status_t bst = render_blob_build(buf, len, 0, mem, FUZZ_BLOCK, NULL, &blob, &berr);
    free(buf);
    if (bst != RENDER_BLOB_OK) {
        if (verbose)
            fprintf(stderr, "not built: %s\n", berr.message);
        return 0; /* a big model may not fit the block: the loader said so */
    }
    render_ctx_t ctx;
    render_ctx_init(&ctx, blob->frame);
    uint32_t w = blob->frame->width, h = blob->frame->height;
    for (uint32_t k = 0; k < 16; k++)
        render_pixel(&ctx, (w * (2 * (k % 4) + 1)) / 8, (h * (2 * (k / 4) + 1)) / 8);
    return 0;
}
