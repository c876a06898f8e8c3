/* fuzz_scene_text.c: libFuzzer harness of the text scene format: the
 * tokenizer and parser (sd_parse_text), the compiler (sd_compile), and the
 * compiled form back through the loader, which must take everything the
 * compiler writes.
 *
 * The scene is named scenes/fuzz.scn (run from the repository's top), so
 * a map's `image "maps/checker.png"` reads the maps of scenes/maps/.
 * Inputs with `"/` or `..` are skipped: a map's image is a path, and the
 * fuzzer must read nothing outside scenes/ (fuzz_image_map fuzzes the
 * image files themselves). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_desc.h"
#include "render/scene_load.h"

#define FUZZ_ARENA (16u * 1024u * 1024u)

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t *arena_mem;
    if (size > 256 * 1024)
        return 0;
    char *text = malloc(size + 1);
    if (!text)
        abort();
    memcpy(text, data, size);
    text[size] = 0;
    if (strstr(text, "\"/") || strstr(text, "..")) {
        free(text);
        return 0;
    }
    struct sd_scene s;
    char err[SD_ERR_MAX];
    err[0] = 0;
    int verbose = getenv("FUZZ_VERBOSE") != NULL; /* say why an input is refused */
    if (sd_parse_text("scenes/fuzz.scn", text, &s, err, sizeof err) != 0) {
        if (verbose)
            fprintf(stderr, "refused: %s\n", err);
        free(text);
        if (err[0] == 0)
            abort(); /* a refusal names the problem */
        return 0;
    }
    free(text);
    uint8_t *buf = NULL;
    size_t len = 0;
    int rc = sd_compile(&s, &buf, &len, err, sizeof err);
    sd_free(&s);
    if (rc != 0) {
        if (err[0] == 0)
            abort();
        return 0;
    }
    if (!arena_mem && !(arena_mem = malloc(FUZZ_ARENA)))
        abort();
    arena_t arena;
    arena_init(&arena, arena_mem, FUZZ_ARENA);
    scene_t scene;
    scene_load_error_t lerr;
    scene_load_status_t st = scene_load(buf, len, &arena, &scene, &lerr);
    if (st != SCENE_LOAD_OK && st != SCENE_LOAD_ERR_ARENA) {
        fprintf(stderr, "the loader refuses what the compiler wrote: %s\n", lerr.message);
        abort();
    }
    free(buf);
    return 0;
}
