/* render_fixture.c: the scene, clipping and area helpers test_clip.c and
 * test_aa.c share (render_fixture.h). */
#include "tests/host/render_fixture.h"

#include "tests/host/test_blob_util.h"

int rf_load(rf_scene_t *t, const char *name, uint32_t frame_index, int div)
{
    size_t size;
    memset(t, 0, sizeof *t);
    t->blob = tb_blob_div(name, frame_index, div, &size);
    if (!t->blob)
        return 0;
    t->f = t->blob->frame;
    return 1;
}

int rf_clip(rf_scene_t *t)
{
    free(t->clip_mem);
    size_t bytes = render_clip_bytes(t->f);
    t->clip_mem = malloc(bytes);
    return render_clip_init(&t->clip, t->f, t->clip_mem, bytes) == RENDER_OK;
}

int rf_open(rf_scene_t *t, const char *name, uint32_t frame_index, int div)
{
    return rf_load(t, name, frame_index, div) && rf_clip(t);
}

void rf_close(rf_scene_t *t)
{
    free(t->blob);
    free(t->clip_mem);
}

rgb8_t *rf_render_areas(rf_scene_t *t, uint32_t tw, uint32_t th, const render_options_t *options,
                        const render_clip_options_t *opt, render_stats_t *stats,
                        render_status_t *status)
{
    const render_frame_t *f = t->f;
    rgb8_t *img = calloc((size_t)f->width * f->height, sizeof *img);
    rgb8_t *tile = calloc((size_t)tw * th, sizeof *tile);
    render_ctx_t ctx;
    render_ctx_init(&ctx, f);
    if (options)
        ctx.options = *options;
    *status = RENDER_OK;
    for (uint32_t y = 0; y < f->height; y += th)
        for (uint32_t x = 0; x < f->width; x += tw) {
            render_area_t a = {x, y, f->width - x < tw ? f->width - x : tw,
                               f->height - y < th ? f->height - y : th};
            render_status_t st = render_area(&ctx, &t->clip, &a, opt, tile);
            if (st != RENDER_OK && *status == RENDER_OK)
                *status = st;
            for (uint32_t r = 0; r < a.h; r++)
                memcpy(img + (size_t)(y + r) * f->width + x, tile + r * a.w, a.w * sizeof *tile);
        }
    free(tile);
    *stats = ctx.stats;
    return img;
}

int rf_same_rays(const render_stats_t *a, const render_stats_t *b)
{
    return a->primary == b->primary && a->primary_hit == b->primary_hit &&
           a->shadow == b->shadow && a->reflection == b->reflection &&
           a->refraction == b->refraction;
}
