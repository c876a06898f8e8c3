/* Host tests of the rendering commands' encodings (proto/render_link.h)
 * and of the NC statistics the RC sums (roles/gigs.h). */
#include <string.h>

#include "host-tools/gigs/render_faults.h"
#include "proto/render_link.h"
#include "roles/gigs.h"
#include "tests/check.h"

/* Every field round-trips at its own offset: distinct values per field, so
 * two fields swapped or overlapping would not come back equal. */
static void render_link_stats_round_trip(void)
{
    /* 5 u32, 8 u64, 8 u32, 1 u64, 1 u32 */
    CHECK_EQ_INT(LINK_RENDER_STATS_SIZE, 5 * 4 + 8 * 8 + 8 * 4 + 8 + 4);
    struct link_render_stats s = {1, 64, 368, 20, 3230, 1ull << 40, 2, 3, 4, 5, 6, 7, 8,
                                  9, 10, 11, 12, 13, 14, 15, 16, (1ull << 33) + 17, 0x8021};
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
    CHECK(t.escalated_pixels == 16);
    CHECK(t.primary_hit == (1ull << 33) + 17 && t.flags == 0x8021);
}

static void render_link_args_round_trip(void)
{
    struct link_render_args a = {.frame = 7, .balance = LINK_BALANCE_DECREASING,
                                 .flags = LINK_RENDER_NO_XCLIP | LINK_RENDER_ASK_WHEN_DONE,
                                 .guided = 5, .areas = 1024, .row0 = 300, .rows = 180};
    uint8_t buf[LINK_RENDER_ARGS_SIZE];
    link_render_args_put(buf, &a);
    struct link_render_args b;
    link_render_args_get(buf, &b);
    CHECK_EQ_INT(b.frame, 7);
    CHECK_EQ_INT(b.balance, LINK_BALANCE_DECREASING);
    CHECK_EQ_INT(b.flags, LINK_RENDER_NO_XCLIP | LINK_RENDER_ASK_WHEN_DONE);
    CHECK_EQ_INT(b.guided, 5);
    CHECK_EQ_INT(b.areas, 1024);
    CHECK_EQ_INT(b.row0, 300);
    CHECK_EQ_INT(b.rows, 180);
    CHECK_EQ_INT(wire_get_u16(buf + 14), 180); /* the band last */
    CHECK_EQ_INT(buf[7], 0); /* the reserved byte is zero */
}

static void render_link_info_and_progress_round_trip(void)
{
    struct link_scene_info i = {320, 240, 4, 17868, 21632, 8388608, 3, 41, 27, 1024}, j;
    uint8_t buf[LINK_SCENE_INFO_SIZE];
    link_scene_info_put(buf, &i);
    link_scene_info_get(buf, &j);
    CHECK(i.width == j.width && i.height == j.height && i.frames == j.frames &&
          i.compiled_bytes == j.compiled_bytes && i.blob_bytes == j.blob_bytes &&
          i.blob_limit == j.blob_limit && i.check_ms == j.check_ms && i.load_ms == j.load_ms &&
          i.prepare_ms == j.prepare_ms && i.prims == j.prims);
    struct link_progress g = {3, 17, 368, 70000, 76800}, h;
    uint8_t pb[LINK_PROGRESS_SIZE];
    link_progress_put(pb, &g);
    link_progress_get(pb, &h);
    CHECK(g.frame == h.frame && g.areas_done == h.areas_done && g.areas_total == h.areas_total);
    CHECK(g.pixels_done == h.pixels_done && g.pixels_total == h.pixels_total);
    CHECK_EQ_INT(wire_get_u32(pb + 12), 70000); /* pixels after the areas */
}

/* The RC sums each NC's statistics: two NCs' messages add field by field. */
static void gigs_stats_sum_of_two(void)
{
    /* weight_cut, self_blocked, screen_tests: host only */
    render_stats_t a = {.primary = 1, .shadow = 2, .reflection = 3, .refraction = 4,
                        .transmission = 5, .box_tests = 6, .prim_tests = 7,
                        .primary_box_tests = 8, .primary_prim_tests = 9,
                        .precision_lost_pixels = 10, .escalated_pixels = 11, .primary_hit = 12};
    render_stats_t b = {.primary = 100, .shadow = 200, .reflection = 300, .refraction = 400,
                        .transmission = 500, .box_tests = 600, .prim_tests = 700,
                        .primary_box_tests = 800, .primary_prim_tests = 900,
                        .precision_lost_pixels = 1000, .escalated_pixels = 1100,
                        .primary_hit = 1200};
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
          sum.primary_prim_tests == 909 && sum.precision_lost_pixels == 1010 &&
          sum.escalated_pixels == 1111 && sum.primary_hit == 1212);
}

/* The failure report: counts, both maps and the listed areas come back;
 * a report cut short is refused; the list stops at LINK_REISSUE_LIST_MAX
 * while the count goes on. */
static void render_link_fails_round_trip(void)
{
    struct link_render_fails f, g;
    memset(&f, 0, sizeof f);
    f.failed = 2;
    f.reissued = 1;
    f.failed_before = 3;
    link_core_map_set(f.failed_map, 2);
    link_core_map_set(f.failed_map, 255);
    link_core_map_set(f.watchdog_map, 255);
    link_core_map_set(f.watchdog_map, 256); /* out of range: ignored */
    f.area[0] = (struct link_reissue){255, 10, 20, 30, 40};
    uint8_t buf[LINK_RENDER_FAILS_SIZE(LINK_REISSUE_LIST_MAX) + 1];
    uint32_t n = link_render_fails_put(buf, &f);
    CHECK_EQ_INT(n, LINK_RENDER_FAILS_SIZE(1));
    CHECK_EQ_INT(n, link_render_fails_size(&f));
    memset(&g, 0xEE, sizeof g);
    CHECK_EQ_INT(link_render_fails_get(buf, n, &g), 0);
    CHECK(g.failed == 2 && g.reissued == 1 && g.failed_before == 3);
    CHECK(link_core_map_has(g.failed_map, 2) && link_core_map_has(g.failed_map, 255));
    CHECK(!link_core_map_has(g.failed_map, 3) && !link_core_map_has(g.watchdog_map, 2));
    CHECK(link_core_map_has(g.watchdog_map, 255) && !link_core_map_has(g.watchdog_map, 256));
    CHECK(g.area[0].core == 255 && g.area[0].x == 10 && g.area[0].y == 20 &&
          g.area[0].w == 30 && g.area[0].h == 40);
    CHECK_EQ_INT(link_render_fails_get(buf, n - 1, &g), -1);
    CHECK_EQ_INT(link_render_fails_get(buf, LINK_RENDER_FAILS_FIXED - 1, &g), -1);
    f.reissued = LINK_REISSUE_LIST_MAX + 5;
    CHECK_EQ_INT(link_render_fails_put(buf, &f), LINK_RENDER_FAILS_SIZE(LINK_REISSUE_LIST_MAX));
    CHECK_EQ_INT(link_render_fails_get(buf, sizeof buf - 1, &g), 0);
    CHECK_EQ_INT(g.reissued, LINK_REISSUE_LIST_MAX + 5);
}

static void render_link_inject_round_trip(void)
{
    struct link_inject e = {253, LINK_INJECT_SILENT, 200, 0x1234}, d;
    uint8_t buf[LINK_INJECT_ENTRY_SIZE + 1];
    buf[LINK_INJECT_ENTRY_SIZE] = 0x5A;
    link_inject_put(buf, &e);
    CHECK_EQ_INT(buf[LINK_INJECT_ENTRY_SIZE], 0x5A);
    link_inject_get(buf, &d);
    CHECK(d.core == 253 && d.kind == LINK_INJECT_SILENT && d.row == 200 && d.area == 0x1234);
}

/* The host's plan: K distinct NCs of the board, kinds in range, the same
 * plan for the same seed, another for another seed. */
static void render_faults_plan_distinct(void)
{
    uint8_t p[LINK_INJECT_SIZE(LINK_INJECT_MAX)], q[sizeof p];
    uint8_t taken[LINK_CORE_MAP_SIZE] = {0}, none[LINK_CORE_MAP_SIZE];
    unsigned ncs = 64, k = 63;
    CHECK_EQ_INT(render_faults_plan(k, 5, RENDER_FAULTS_MIXED, ncs, taken, p),
                 LINK_INJECT_SIZE(k));
    CHECK_EQ_INT(p[0], k);
    int seen[UNITS_MAX_CORES] = {0}, kinds[LINK_INJECT_KINDS + 1] = {0};
    for (unsigned i = 0; i < k; i++) {
        struct link_inject e;
        link_inject_get(p + LINK_INJECT_FIXED_SIZE + i * LINK_INJECT_ENTRY_SIZE, &e);
        CHECK(e.core >= UNITS_FIRST_NC && e.core < UNITS_FIRST_NC + ncs);
        CHECK(e.kind >= 1 && e.kind <= LINK_INJECT_KINDS);
        seen[e.core]++;
        kinds[e.kind]++;
    }
    for (unsigned c = 0; c < UNITS_MAX_CORES; c++)
        CHECK(seen[c] <= 1);
    for (unsigned kd = 1; kd <= LINK_INJECT_KINDS; kd++)
        CHECK(kinds[kd] > 0); /* 63 draws: every kind comes up */
    /* All but one are taken now: no more may fail. */
    CHECK_EQ_INT(render_faults_plan(1, 5, RENDER_FAULTS_MIXED, ncs, taken, q),
                 LINK_INJECT_SIZE(0));
    memset(none, 0, sizeof none);
    render_faults_plan(k, 5, RENDER_FAULTS_MIXED, ncs, none, q);
    CHECK(memcmp(p, q, LINK_INJECT_SIZE(k)) == 0);
    memset(none, 0, sizeof none);
    render_faults_plan(k, 6, RENDER_FAULTS_MIXED, ncs, none, q);
    CHECK(memcmp(p, q, LINK_INJECT_SIZE(k)) != 0);
    memset(none, 0, sizeof none);
    render_faults_plan(1, 9, LINK_INJECT_HANG, 2, none, q);
    CHECK_EQ_INT(q[LINK_INJECT_FIXED_SIZE + 2], LINK_INJECT_HANG);
    /* Taken NCs are not planned again: 10 NCs, 3 then 3 then 3, all apart. */
    memset(none, 0, sizeof none);
    int hit[UNITS_MAX_CORES] = {0};
    for (unsigned round = 0; round < 4; round++) {
        uint32_t bytes = render_faults_plan(3, round, RENDER_FAULTS_MIXED, 10, none, q);
        CHECK_EQ_INT(bytes, LINK_INJECT_SIZE(round < 3 ? 3 : 0));
        for (unsigned i = 0; i < q[0]; i++)
            hit[wire_get_u16(q + LINK_INJECT_FIXED_SIZE + i * LINK_INJECT_ENTRY_SIZE)]++;
    }
    for (unsigned c = 0; c < UNITS_MAX_CORES; c++)
        CHECK(hit[c] <= 1);
    unsigned kk, seed;
    CHECK_EQ_INT(render_faults_parse("3:17", &kk, &seed), 0);
    CHECK(kk == 3 && seed == 17);
    CHECK_EQ_INT(render_faults_parse("2", &kk, &seed), 0);
    CHECK(kk == 2);
    CHECK_EQ_INT(render_faults_parse("2:", &kk, &seed), -1);
    CHECK_EQ_INT(render_faults_parse("x", &kk, &seed), -1);
    CHECK_EQ_INT(render_faults_parse("999", &kk, &seed), -1);
    uint8_t kind;
    CHECK_EQ_INT(render_faults_kind_parse("silent", &kind), 0);
    CHECK_EQ_INT(kind, LINK_INJECT_SILENT);
    CHECK_EQ_INT(render_faults_kind_parse("mixed", &kind), 0);
    CHECK_EQ_INT(kind, RENDER_FAULTS_MIXED);
    CHECK_EQ_INT(render_faults_kind_parse("boom", &kind), -1);
}

int main(void)
{
    RUN(render_link_stats_round_trip);
    RUN(render_link_args_round_trip);
    RUN(render_link_info_and_progress_round_trip);
    RUN(gigs_stats_sum_of_two);
    RUN(render_link_fails_round_trip);
    RUN(render_link_inject_round_trip);
    RUN(render_faults_plan_distinct);
    return check_exit();
}
