/* render_fixture.h: what the clipping and anti-aliasing tests (test_clip.c,
 * test_aa.c) share: a scene of scenes/ loaded as a blob with its clipping
 * set up, the whole image rendered by areas through render_area, and the
 * ray counts two renders must agree on.  tests/check.h counts failures in
 * each test file's own statics, so render_fixture.c checks nothing: the
 * inline rf_areas checks in the calling test. */
#ifndef LINKS1_TESTS_HOST_RENDER_FIXTURE_H
#define LINKS1_TESTS_HOST_RENDER_FIXTURE_H

#include "render/blob.h"
#include "render/clip.h"
#include "tests/check.h"

typedef struct {
    render_blob_t *blob;
    render_frame_t *f; /* in the test's own block: its options may be changed */
    void *clip_mem;
    render_clip_t clip;
} rf_scene_t;

/* Scene NAME's frame_index as a blob at its resolution divided by div, no
 * clipping yet (rf_clip); 0 (and a line saying why) on failure. */
int rf_load(rf_scene_t *t, const char *name, uint32_t frame_index, int div);
/* Clipping set up (again) for the frame's options as they are now. */
int rf_clip(rf_scene_t *t);
/* rf_load and rf_clip. */
int rf_open(rf_scene_t *t, const char *name, uint32_t frame_index, int div);
void rf_close(rf_scene_t *t);

/* The whole image by areas of tw x th through render_area, the context's
 * options *options (NULL: the frame's); *stats the context's counts,
 * *status RENDER_OK or the first area's failure. */
rgb8_t *rf_render_areas(rf_scene_t *t, uint32_t tw, uint32_t th, const render_options_t *options,
                        const render_clip_options_t *opt, render_stats_t *stats,
                        render_status_t *status);

/* rf_render_areas, its status checked in the calling test. */
static inline rgb8_t *rf_areas(rf_scene_t *t, uint32_t tw, uint32_t th,
                               const render_options_t *options, const render_clip_options_t *opt,
                               render_stats_t *stats)
{
    render_status_t status;
    rgb8_t *img = rf_render_areas(t, tw, th, options, opt, stats, &status);
    CHECK_EQ_INT(status, RENDER_OK);
    return img;
}

/* Two renders trace the same rays: camera rays, hits and the rays they spawn. */
int rf_same_rays(const render_stats_t *a, const render_stats_t *b);

#endif
