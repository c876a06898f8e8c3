/* test_areas.c: the RC's area schedules cover the screen exactly once,
 * stay inside it, have the sizes each schedule promises, and decreasing
 * areas never grow (but by a pixel of a scanline's rounding). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "proto/areas.h"
#include "tests/check.h"

/* Summary of one schedule run by areas_walk. */
struct walk {
    uint32_t areas;        /* areas handed out */
    uint32_t min_px, max_px; /* smallest and largest area, pixels */
    uint32_t first_px, last_px;
    int grew;              /* an area larger than the one before by more
                              than a pixel */
    struct area first, last;
};

/* Runs a schedule to its end and checks the invariants every mode keeps:
 * each area non-empty and inside the screen, every pixel covered exactly
 * once, areas_count and areas_handed agreeing with what came out.  Returns
 * 0 if the schedule could not start. */
static int areas_walk(enum areas_mode mode, uint32_t w, uint32_t h, uint32_t ncs,
                      uint32_t k, struct walk *out)
{
    struct areas s;
    struct area a;
    char what[160];
    int rc = areas_init(&s, mode, w, h, ncs, k);
    snprintf(what, sizeof what, "%s %ux%u ncs=%u k=%u: init %s", areas_mode_name(mode), w,
             h, ncs, k, areas_strerror(rc));
    if (rc != AREAS_OK) {
        check_fail(__FILE__, __LINE__, what);
        return 0;
    }
    uint8_t *seen = calloc((size_t)w * h, 1);
    memset(out, 0, sizeof *out);
    out->min_px = UINT32_MAX;
    int bad_rect = 0, overlap = 0;
    uint32_t prev = UINT32_MAX;
    while (areas_next(&s, &a)) {
        uint32_t px = a.w * a.h;
        if (a.w == 0 || a.h == 0 || a.x >= w || a.y >= h || a.w > w - a.x ||
            a.h > h - a.y) {
            bad_rect = 1;
            break;
        }
        for (uint32_t y = a.y; y < a.y + a.h; y++)
            for (uint32_t x = a.x; x < a.x + a.w; x++)
                if (seen[(size_t)y * w + x]++)
                    overlap = 1;
        if (out->areas == 0) {
            out->first = a;
            out->first_px = px;
        }
        out->last = a;
        out->last_px = px;
        if (prev != UINT32_MAX && px > prev + 1)
            out->grew = 1;
        prev = px;
        if (px < out->min_px)
            out->min_px = px;
        if (px > out->max_px)
            out->max_px = px;
        out->areas++;
    }
    int holes = 0;
    for (size_t i = 0; i < (size_t)w * h; i++)
        if (seen[i] == 0)
            holes = 1;
    free(seen);
    if (bad_rect || overlap || holes || areas_count(&s) != out->areas ||
        areas_handed(&s) != out->areas || areas_next(&s, &a) != 0) {
        snprintf(what, sizeof what,
                 "%s %ux%u ncs=%u k=%u: outside=%d overlap=%d holes=%d count=%u walked=%u",
                 areas_mode_name(mode), w, h, ncs, k, bad_rect, overlap, holes,
                 areas_count(&s), out->areas);
        check_fail(__FILE__, __LINE__, what);
    }
    return 1;
}

static const uint32_t sizes[][2] = {
    {1, 1},   {1, 7},    {7, 1},    {2, 2},     {3, 5},    {17, 13},
    {13, 17}, {97, 3},   {3, 97},   {509, 1},   {1, 509},  {64, 64},
    {320, 200}, {511, 479}, {512, 480}, {640, 480}, {1024, 1024}, {4096, 2},
};
#define NSIZES (sizeof sizes / sizeof sizes[0])
static const uint32_t ncs_list[] = {1, 2, 3, 8, 64, 254};
#define NNCS (sizeof ncs_list / sizeof ncs_list[0])
static const uint32_t k_list[] = {0, 1, 7, 64, 1024, 2400, 1u << 22};
#define NK (sizeof k_list / sizeof k_list[0])

/* Static: one area per NC (fewer only when the screen has fewer pixels). */
static void test_static_covers_one_area_per_nc(void)
{
    struct walk wk;
    for (size_t i = 0; i < NSIZES; i++)
        for (size_t j = 0; j < NNCS; j++) {
            uint32_t w = sizes[i][0], h = sizes[i][1], n = ncs_list[j];
            if (!areas_walk(AREAS_STATIC, w, h, n, 0, &wk))
                continue;
            uint32_t want = n < w * h ? n : w * h;
            CHECK_EQ_INT(wk.areas, want);
        }
}

/* Dynamic: exactly k areas (k = 0 is the default), clamped to the pixels. */
static void test_dynamic_covers_k_areas(void)
{
    struct walk wk;
    for (size_t i = 0; i < NSIZES; i++)
        for (size_t j = 0; j < NK; j++) {
            uint32_t w = sizes[i][0], h = sizes[i][1];
            uint32_t k = k_list[j] == 0 ? AREAS_DEFAULT_K : k_list[j];
            if (!areas_walk(AREAS_DYNAMIC, w, h, 8, k_list[j], &wk))
                continue;
            CHECK_EQ_INT(wk.areas, k < w * h ? k : w * h);
        }
}

/* The paper's grids on 512x480: 64 = 8x8 areas of 64x60, 1024 = 32x32 of
 * 16x15, all equal. */
static void test_dynamic_paper_grids_are_equal(void)
{
    struct walk wk;
    if (areas_walk(AREAS_DYNAMIC, 512, 480, 64, 64, &wk)) {
        CHECK_EQ_INT(wk.first.w, 64);
        CHECK_EQ_INT(wk.first.h, 60);
        CHECK_EQ_INT(wk.min_px, wk.max_px);
    }
    if (areas_walk(AREAS_DYNAMIC, 512, 480, 64, 1024, &wk)) {
        CHECK_EQ_INT(wk.first.w, 16);
        CHECK_EQ_INT(wk.first.h, 15);
        CHECK_EQ_INT(wk.min_px, wk.max_px);
        CHECK_EQ_INT(wk.last.x, 496);
        CHECK_EQ_INT(wk.last.y, 465);
    }
}

/* Grid areas are nearly equal: the largest at most twice the smallest once
 * areas are a few pixels each, and raster order (first at the origin). */
static void test_grid_areas_nearly_equal(void)
{
    struct walk wk;
    for (size_t i = 0; i < NSIZES; i++) {
        uint32_t w = sizes[i][0], h = sizes[i][1];
        if (!areas_walk(AREAS_DYNAMIC, w, h, 1, 64, &wk))
            continue;
        CHECK(wk.first.x == 0 && wk.first.y == 0);
        if ((uint64_t)w * h >= 64 * 16 && w >= 8 && h >= 8)
            CHECK(wk.max_px <= 2 * wk.min_px);
    }
}

/* Decreasing: full coverage for every size, NC count and bound; sizes never
 * grow but by the pixel a scanline's pieces round by; no area below the
 * k-grid's area size. */
static void test_decreasing_never_grows(void)
{
    struct walk wk;
    for (size_t i = 0; i < NSIZES; i++)
        for (size_t j = 0; j < NNCS; j++)
            for (size_t m = 0; m < NK; m++) {
                uint32_t w = sizes[i][0], h = sizes[i][1];
                if ((uint64_t)w * h > 300000 && m % 3 != 0)
                    continue; /* big screens: a subset keeps the test quick */
                if (!areas_walk(AREAS_DECREASING, w, h, ncs_list[j], k_list[m], &wk))
                    continue;
                if (wk.grew) {
                    char msg[120];
                    snprintf(msg, sizeof msg, "%ux%u ncs=%u k=%u: an area grew", w, h,
                             ncs_list[j], k_list[m]);
                    check_fail(__FILE__, __LINE__, msg);
                }
                uint32_t k = k_list[m], factor;
                if (k == 0)
                    areas_decreasing_defaults(ncs_list[j], &k, &factor);
                if (k > w * h)
                    k = w * h;
                uint32_t floor_px = (w * h + k - 1) / k;
                /* Pieces of a scanline are at least floor_px wide, and
                 * bands at least a scanline, when a scanline holds
                 * floor_px. */
                if (floor_px <= w)
                    CHECK(wk.min_px >= floor_px);
            }
}

/* The paper's case, 512x480 with 64 NCs and 1024-area bound: starts with
 * bands of whole scanlines, shrinks to pieces of one scanline no smaller
 * than a 16x15 grid area, in more areas than NCs and fewer than the grid. */
static void test_decreasing_paper_case(void)
{
    struct walk wk;
    if (!areas_walk(AREAS_DECREASING, 512, 480, 64, 1024, &wk))
        return;
    /* 245760 px / (2 * 64) = 1920 px = 3.75 scanlines -> 3 whole scanlines */
    CHECK_EQ_INT(wk.first.w, 512);
    CHECK_EQ_INT(wk.first.h, 3);
    /* bound 240 px: 512 / 240 leaves room for two pieces, of 256 px */
    CHECK_EQ_INT(wk.last.w, 256);
    CHECK_EQ_INT(wk.last.h, 1);
    CHECK_EQ_INT(wk.min_px, 256);
    CHECK(wk.areas > 64 && wk.areas < 1024);
}

/* More NCs than scanlines: the schedules still cut the screen (pieces of
 * scanlines), and a single pixel is one area whatever the NC count. */
static void test_more_ncs_than_scanlines(void)
{
    struct walk wk;
    if (areas_walk(AREAS_STATIC, 100, 3, 64, 0, &wk)) {
        CHECK_EQ_INT(wk.areas, 64);
        CHECK(wk.max_px <= 2 * wk.min_px);
    }
    if (areas_walk(AREAS_DECREASING, 100, 3, 254, 1u << 22, &wk)) {
        CHECK_EQ_INT(wk.areas, 300); /* bound 1 px, pieces of 1 px */
        CHECK_EQ_INT(wk.first.h, 1);
    }
    for (int mode = AREAS_STATIC; mode < AREAS_MODES; mode++)
        if (areas_walk((enum areas_mode)mode, 1, 1, 254, 0, &wk))
            CHECK_EQ_INT(wk.areas, 1);
}

/* A prime width cuts as well as any: pieces as equal as whole pixels
 * allow (509 at a bound of 239 px: 254 and 255), no piece below the
 * bound, none a pixel (the divisor the width lacks). */
static void test_decreasing_prime_width_cuts_near_equal_pieces(void)
{
    struct walk wk;
    if (areas_walk(AREAS_DECREASING, 509, 480, 64, 1024, &wk)) {
        CHECK_EQ_INT(wk.min_px, 254);
        CHECK(wk.last.w == 254 || wk.last.w == 255);
        CHECK_EQ_INT(wk.last.x + wk.last.w, 509);
    }
}

static void test_bad_arguments_are_refused(void)
{
    struct areas s;
    CHECK_EQ_INT(areas_init(&s, (enum areas_mode)AREAS_MODES, 10, 10, 1, 0), AREAS_ERR_MODE);
    CHECK_EQ_INT(areas_init(&s, AREAS_DYNAMIC, 0, 10, 1, 0), AREAS_ERR_SIZE);
    CHECK_EQ_INT(areas_init(&s, AREAS_DYNAMIC, 10, 0, 1, 0), AREAS_ERR_SIZE);
    CHECK_EQ_INT(areas_init(&s, AREAS_DYNAMIC, AREAS_MAX_DIM + 1, 10, 1, 0), AREAS_ERR_SIZE);
    CHECK_EQ_INT(areas_init(&s, AREAS_STATIC, 10, 10, 0, 0), AREAS_ERR_NCS);
    CHECK(strstr(areas_strerror(AREAS_ERR_NCS), "NC") != NULL);
}

/* A larger guided factor gives smaller first areas, still covering the
 * screen once; the factor is refused out of range or after the first area. */
static void test_guided_factor(void)
{
    struct areas s;
    struct area a;
    uint32_t first[3] = {0};
    const uint32_t f[3] = {1, 2, 8};
    for (int i = 0; i < 3; i++) {
        CHECK_EQ_INT(areas_init(&s, AREAS_DECREASING, 512, 480, 64, 16384), AREAS_OK);
        CHECK_EQ_INT(areas_set_guided_factor(&s, f[i]), AREAS_OK);
        uint32_t n = areas_count(&s), pixels = 0, walked = 0;
        CHECK(areas_next(&s, &a));
        first[i] = a.w * a.h;
        pixels += a.w * a.h;
        walked++;
        while (areas_next(&s, &a)) {
            pixels += a.w * a.h;
            walked++;
        }
        CHECK_EQ_INT(pixels, 512 * 480);
        CHECK_EQ_INT(walked, n);
    }
    CHECK(first[0] > first[1] && first[1] > first[2]);
    CHECK_EQ_INT(first[1], 3 * 512); /* the default: test_decreasing_paper_case's */
    CHECK_EQ_INT(areas_init(&s, AREAS_DECREASING, 512, 480, 64, 1024), AREAS_OK);
    CHECK_EQ_INT(areas_set_guided_factor(&s, 0), AREAS_ERR_FACTOR);
    CHECK_EQ_INT(areas_set_guided_factor(&s, AREAS_MAX_GUIDED_FACTOR + 1), AREAS_ERR_FACTOR);
    areas_next(&s, &a);
    CHECK_EQ_INT(areas_set_guided_factor(&s, 4), AREAS_ERR_FACTOR);
    CHECK(strstr(areas_strerror(AREAS_ERR_FACTOR), "guided") != NULL);
}

/* k = 0 and no factor: the decreasing schedule takes both from the NC
 * count (the board's default), and is then the schedule of those values. */
static void test_decreasing_defaults_by_ncs(void)
{
    static const uint32_t want[][3] = {
        {1, 16384, 2}, {8, 16384, 2}, {64, 16384, 2}, {65, 7168, 4},
        {128, 7168, 4}, {129, 14336, 3}, {254, 14336, 3}, {4096, 14336, 3},
    };
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        uint32_t k = 0, factor = 0;
        areas_decreasing_defaults(want[i][0], &k, &factor);
        CHECK_EQ_INT(k, want[i][1]);
        CHECK_EQ_INT(factor, want[i][2]);
        struct areas by_rule, given;
        CHECK_EQ_INT(areas_init(&by_rule, AREAS_DECREASING, 512, 480, want[i][0], 0), AREAS_OK);
        CHECK_EQ_INT(areas_init(&given, AREAS_DECREASING, 512, 480, want[i][0], k), AREAS_OK);
        CHECK_EQ_INT(areas_set_guided_factor(&given, factor), AREAS_OK);
        struct area a, b;
        int same = 1, more;
        do {
            more = areas_next(&by_rule, &a);
            if (more != areas_next(&given, &b) ||
                (more && (a.x != b.x || a.y != b.y || a.w != b.w || a.h != b.h)))
                same = 0;
        } while (more && same);
        CHECK(same);
    }
    /* dynamic keeps the paper's grid of AREAS_DEFAULT_K */
    struct areas d;
    CHECK_EQ_INT(areas_init(&d, AREAS_DYNAMIC, 512, 480, 254, 0), AREAS_OK);
    CHECK_EQ_INT(areas_count(&d), AREAS_DEFAULT_K);
}

/* The paper's job unit, "one scanline or part of one": K >= height gives
 * every scanline K/height (rounded) pieces of one row, K < height bands of
 * whole scanlines; every schedule covers the screen once. */
static void test_lines_are_scanlines(void)
{
    struct walk wk;
    if (areas_walk(AREAS_LINES, 512, 480, 16, 480, &wk)) { /* Table 2: 480 areas */
        CHECK_EQ_INT(wk.areas, 480);
        CHECK_EQ_INT(wk.min_px, 512);
        CHECK_EQ_INT(wk.max_px, 512);
    }
    if (areas_walk(AREAS_LINES, 512, 480, 16, 2400, &wk)) { /* Table 2: 2,400 areas */
        CHECK_EQ_INT(wk.areas, 2400);
        CHECK(wk.min_px >= 102 && wk.max_px <= 103);
    }
    /* every area one row high, 5 to a scanline, in raster order */
    struct areas s;
    struct area a;
    CHECK_EQ_INT(areas_init(&s, AREAS_LINES, 512, 480, 16, 2400), AREAS_OK);
    uint32_t per_line[480] = {0}, rows_high = 0, raster = 1, py = 0, px = 0;
    while (areas_next(&s, &a)) {
        rows_high += a.h != 1;
        if (a.y < 480)
            per_line[a.y]++;
        raster &= a.y > py || (a.y == py && a.x >= px);
        py = a.y, px = a.x + a.w;
    }
    CHECK_EQ_INT(rows_high, 0);
    CHECK(raster);
    int five = 1;
    for (int y = 0; y < 480; y++)
        five &= per_line[y] == 5;
    CHECK(five);
    if (areas_walk(AREAS_LINES, 512, 480, 16, 96, &wk)) { /* K < height: whole scanlines */
        CHECK_EQ_INT(wk.areas, 96);
        CHECK_EQ_INT(wk.min_px, 5 * 512);
        CHECK_EQ_INT(wk.max_px, 5 * 512);
    }
    if (areas_walk(AREAS_LINES, 37, 23, 3, 500, &wk)) /* uneven pieces, K > height */
        CHECK_EQ_INT(wk.areas, 500);
    if (areas_walk(AREAS_LINES, 5, 3, 3, 1000, &wk)) /* clamped to the pixels */
        CHECK_EQ_INT(wk.areas, 15);
    if (areas_walk(AREAS_LINES, 640, 7, 2, 0, &wk)) /* k = 0: AREAS_DEFAULT_K */
        CHECK_EQ_INT(wk.areas, AREAS_DEFAULT_K);
}

static void test_mode_names_round_trip(void)
{
    enum areas_mode m;
    for (int i = AREAS_STATIC; i < AREAS_MODES; i++) {
        CHECK_EQ_INT(areas_mode_parse(areas_mode_name((enum areas_mode)i), &m), AREAS_OK);
        CHECK_EQ_INT(m, i);
    }
    CHECK_EQ_INT(areas_mode_parse("guided", &m), AREAS_ERR_MODE);
    CHECK(strcmp(areas_mode_name(AREAS_DECREASING), "decreasing") == 0);
}

/* A band: a schedule of rows scanlines moved down by y0 covers exactly
 * scanlines y0 .. y0+rows-1 of the screen, in every mode, and hands out the
 * areas of the unmoved schedule moved by y0. */
static void test_band_origin(void)
{
    const uint32_t w = 37, h = 50, y0 = 13, rows = 21;
    for (int m = 0; m < AREAS_MODES; m++) {
        struct areas s, plain;
        struct area a, b;
        CHECK(areas_init(&s, (enum areas_mode)m, w, rows, 5, 64) == AREAS_OK);
        CHECK(areas_init(&plain, (enum areas_mode)m, w, rows, 5, 64) == AREAS_OK);
        areas_set_origin(&s, y0);
        uint8_t seen[50][37] = {{0}};
        int moved = 1;
        while (areas_next(&s, &a)) {
            moved &= areas_next(&plain, &b) && a.x == b.x && a.w == b.w && a.h == b.h &&
                     a.y == b.y + y0;
            for (uint32_t y = a.y; y < a.y + a.h && y < h; y++)
                for (uint32_t x = a.x; x < a.x + a.w && x < w; x++)
                    seen[y][x]++;
        }
        CHECK(moved && areas_next(&plain, &b) == 0);
        int exact = 1;
        for (uint32_t y = 0; y < h; y++)
            for (uint32_t x = 0; x < w; x++)
                exact &= seen[y][x] == (y >= y0 && y < y0 + rows);
        CHECK(exact);
    }
}

int main(void)
{
    RUN(test_static_covers_one_area_per_nc);
    RUN(test_dynamic_covers_k_areas);
    RUN(test_dynamic_paper_grids_are_equal);
    RUN(test_grid_areas_nearly_equal);
    RUN(test_decreasing_never_grows);
    RUN(test_decreasing_paper_case);
    RUN(test_more_ncs_than_scanlines);
    RUN(test_decreasing_prime_width_cuts_near_equal_pieces);
    RUN(test_bad_arguments_are_refused);
    RUN(test_guided_factor);
    RUN(test_decreasing_defaults_by_ncs);
    RUN(test_lines_are_scanlines);
    RUN(test_mode_names_round_trip);
    RUN(test_band_origin);
    return check_exit();
}
