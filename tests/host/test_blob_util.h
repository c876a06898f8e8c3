/* test_blob_util.h: what the blob and clipping tests share: the scenes of
 * scenes/ compiled in memory, blocks aligned like the board's, and whole
 * images rendered the plain way (render_span) for reference. */
#ifndef LINKS1_TEST_BLOB_UTIL_H
#define LINKS1_TEST_BLOB_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_desc.h"
#include "render/blob.h"
#include "render/clip.h"

/* The scenes every test here runs over: the demo and the paper-like ones
 * (city is written by `make` into build/scenes/: tb_scene_path), and the
 * cones and cylinders of cones.scn. */
static const char *const tb_scenes[] = {"demo", "city", "glass", "molecule", "anim",
                                        "cones"};
#define TB_SCENE_COUNT (sizeof tb_scenes / sizeof tb_scenes[0])

/* Where scene NAME is: build/scenes/ for those `make` writes from
 * host-tools/gen/ (city, fig9), scenes/ for the others. */
static inline void tb_scene_path(char *path, size_t size, const char *name)
{
    int made = strcmp(name, "city") == 0 || strcmp(name, "fig9") == 0;
    snprintf(path, size, "%s/%s.scn", made ? "build/scenes" : "scenes", name);
}

/* Scene NAME (tb_scene_path) compiled at its resolution divided by div (1: as
 * written); NULL (and a line saying why) on failure. */
static inline uint8_t *tb_compile_flags(const char *name, int div, uint32_t flags, size_t *len);

static inline uint8_t *tb_compile_div(const char *name, int div, size_t *len)
{
    return tb_compile_flags(name, div, 0, len);
}

/* The same with these SCN_OPT_ flags set besides the scene's own. */
static inline uint8_t *tb_compile_flags(const char *name, int div, uint32_t flags, size_t *len)
{
    char path[128], err[SD_ERR_MAX];
    struct sd_scene s;
    uint8_t *buf = NULL;
    tb_scene_path(path, sizeof path, name);
    if (sd_parse_file(path, &s, err, sizeof err) != 0) {
        printf("cannot parse %s: %s\n", path, err);
        return NULL;
    }
    s.view.width /= div;
    s.view.height /= div;
    s.view.flags |= flags;
    if (sd_compile(&s, &buf, len, err, sizeof err) != 0)
        printf("cannot compile %s: %s\n", path, err);
    sd_free(&s);
    return buf;
}

static inline uint8_t *tb_compile(const char *name, size_t *len)
{
    return tb_compile_div(name, 1, len);
}

/* A zeroed block of at least size bytes, aligned like an IMSU block. */
static inline void *tb_block(size_t size)
{
    size_t rounded = (size + RENDER_RELOCATE_ALIGN - 1) / RENDER_RELOCATE_ALIGN * RENDER_RELOCATE_ALIGN;
    void *p = aligned_alloc(RENDER_RELOCATE_ALIGN, rounded ? rounded : RENDER_RELOCATE_ALIGN);
    if (p)
        memset(p, 0, rounded);
    return p;
}

/* Compiled scene buf (len bytes, freed here; NULL: none) as a blob of
 * frame_index in a new block of exactly render_blob_bytes; NULL on any
 * failure (printed, naming the scene name). */
static inline render_blob_t *tb_blob_bytes(const char *name, uint8_t *buf, size_t len,
                                           uint32_t frame_index, size_t *block_size)
{
    size_t need = 0;
    render_blob_error_t err;
    render_blob_t *blob = NULL;
    if (!buf)
        return NULL;
    if (render_blob_bytes(buf, len, &need, &err) == RENDER_BLOB_OK) {
        void *block = tb_block(need);
        if (render_blob_build(buf, len, frame_index, block, need, "the test block", &blob, &err) !=
            RENDER_BLOB_OK) {
            printf("%s: %s\n", name, err.message);
            free(block);
        }
    } else {
        printf("%s: %s\n", name, err.message);
    }
    free(buf);
    *block_size = need;
    return blob;
}

/* Scene NAME (its resolution divided by div) as a blob of frame_index
 * (tb_blob_bytes). */
static inline render_blob_t *tb_blob_div(const char *name, uint32_t frame_index, int div,
                                         size_t *block_size)
{
    size_t len = 0;
    uint8_t *buf = tb_compile_div(name, div, &len);
    return tb_blob_bytes(name, buf, len, frame_index, block_size);
}

/* The scene of text (named name) as a blob of its frame 0 (tb_blob_bytes). */
static inline render_blob_t *tb_blob_text(const char *name, const char *text, size_t *block_size)
{
    char err[SD_ERR_MAX];
    struct sd_scene s;
    uint8_t *buf = NULL;
    size_t len = 0;
    if (sd_parse_text(name, text, &s, err, sizeof err) != 0) {
        printf("cannot parse %s: %s\n", name, err);
        return NULL;
    }
    if (sd_compile(&s, &buf, &len, err, sizeof err) != 0)
        printf("cannot compile %s: %s\n", name, err);
    sd_free(&s);
    return tb_blob_bytes(name, buf, len, 0, block_size);
}

static inline render_blob_t *tb_blob(const char *name, uint32_t frame_index, size_t *block_size)
{
    return tb_blob_div(name, frame_index, 1, block_size);
}

/* Every pixel of the frame through render_span (full tree walk). */
static inline rgb8_t *tb_render_plain(const render_frame_t *f, render_stats_t *stats)
{
    rgb8_t *img = calloc((size_t)f->width * f->height, sizeof *img);
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    for (uint32_t y = 0; y < f->height; y++)
        render_span(&ctx, y, 0, f->width, img + (size_t)y * f->width);
    if (stats)
        *stats = ctx.stats;
    return img;
}

static inline int tb_same(const rgb8_t *a, const rgb8_t *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (a[i].r != b[i].r || a[i].g != b[i].g || a[i].b != b[i].b)
            return 0;
    return 1;
}

#endif
