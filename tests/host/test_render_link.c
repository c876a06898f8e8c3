/* Host tests of the rendering commands' encodings (proto/render_link.h)
 * and of the NC statistics the RC sums (roles/gigs.h). */
#include <string.h>

#include "proto/render_link.h"
#include "roles/gigs.h"
#include "tests/check.h"

/* Every field round-trips at its own offset: distinct values per field, so
 * two fields swapped or overlapping would not come back equal. */
static void render_link_stats_round_trip(void)
{
    /* 5 u32, 8 u64, 7 u32 */
    CHECK_EQ_INT(LINK_RENDER_STATS_SIZE, 5 * 4 + 8 * 8 + 7 * 4);
    struct link_render_stats s = {1, 64, 368, 20, 3230, 1ull << 40, 2, 3, 4, 5, 6, 7, 8,
                                  9, 10, 11, 12, 13, 14, 15};
    uint8_t buf[LINK_RENDER_STATS_SIZE + 1];
    buf[LINK_RENDER_STATS_SIZE] = 0xA5;
    link_render_stats_put(buf, &s);
    CHECK_EQ_INT(buf[LINK_RENDER_STATS_SIZE], 0xA5); /* nothing past the size */
    struct link_render_stats t;
    memset(&t, 0xFF, sizeof t);
    link_render_stats_get(buf, &t);
    uint8_t again[LINK_RENDER_STATS_SIZE];
    link_render_stats_put(again, &t);
    CHECK(memcmp(buf, again, sizeof again) == 0);
    CHECK(t.frame == 1 && t.ncs == 64 && t.areas == 368 && t.prepare_ms == 20);
    CHECK(t.shadow == 2 && t.primary_prim_tests == 8 && t.precision_lost_pixels == 9);
    CHECK(t.dm_high == 10 && t.rc_high == 11 && t.nc_high_max == 12 && t.nc_private == 13);
    CHECK(t.blob_bytes == 14);
    CHECK(t.primary == 1ull << 40 && t.dc_full_waits == 15 && t.render_ms == 3230);
}

static void render_link_args_round_trip(void)
{
    struct link_render_args a = {7, LINK_BALANCE_DECREASING,
                                 LINK_RENDER_NO_XCLIP | LINK_RENDER_PREPARE_NEXT, 1024};
    uint8_t buf[LINK_RENDER_ARGS_SIZE];
    link_render_args_put(buf, &a);
    struct link_render_args b;
    link_render_args_get(buf, &b);
    CHECK_EQ_INT(b.frame, 7);
    CHECK_EQ_INT(b.balance, LINK_BALANCE_DECREASING);
    CHECK_EQ_INT(b.flags, LINK_RENDER_NO_XCLIP | LINK_RENDER_PREPARE_NEXT);
    CHECK_EQ_INT(b.areas, 1024);
    CHECK_EQ_INT(buf[6] | buf[7], 0); /* the reserved field is zero */
}

static void render_link_info_and_progress_round_trip(void)
{
    struct link_scene_info i = {320, 240, 4, 17868, 21632, 8388608}, j;
    uint8_t buf[LINK_SCENE_INFO_SIZE];
    link_scene_info_put(buf, &i);
    link_scene_info_get(buf, &j);
    CHECK(i.width == j.width && i.height == j.height && i.frames == j.frames &&
          i.compiled_bytes == j.compiled_bytes && i.blob_bytes == j.blob_bytes &&
          i.blob_limit == j.blob_limit);
    struct link_progress g = {3, 17, 368}, h;
    uint8_t pb[LINK_PROGRESS_SIZE];
    link_progress_put(pb, &g);
    link_progress_get(pb, &h);
    CHECK(g.frame == h.frame && g.areas_done == h.areas_done && g.areas_total == h.areas_total);
}

/* The RC sums each NC's statistics: two NCs' messages add field by field. */
static void gigs_stats_sum_of_two(void)
{
    render_stats_t a = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 0}; /* weight_cut: host only */
    render_stats_t b = {100, 200, 300, 400, 500, 600, 700, 800, 900, 1000, 0};
    uint8_t pa[GIGS_STATS_SIZE], pb[GIGS_STATS_SIZE];
    gigs_stats_put(pa, &a);
    gigs_stats_put(pb, &b);
    render_stats_t sum;
    memset(&sum, 0, sizeof sum);
    gigs_stats_add(&sum, pa);
    gigs_stats_add(&sum, pb);
    CHECK(sum.primary == 101 && sum.shadow == 202 && sum.reflection == 303 &&
          sum.refraction == 404 && sum.transmission == 505 && sum.box_tests == 606 &&
          sum.prim_tests == 707 && sum.primary_box_tests == 808 &&
          sum.primary_prim_tests == 909 && sum.precision_lost_pixels == 1010);
}

int main(void)
{
    RUN(render_link_stats_round_trip);
    RUN(render_link_args_round_trip);
    RUN(render_link_info_and_progress_round_trip);
    RUN(gigs_stats_sum_of_two);
    return check_exit();
}
