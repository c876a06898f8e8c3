/* test_framemem.c: the frame memory (fm.c) and the data collector's FIFO
 * (dc_ring.c): pixel packing, bounds, order, nothing dropped or duplicated
 * when many producers fill a small FIFO, and no lost wake-up. */
#include <pthread.h>
#include <sched.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "drivers/framemem/dc_ring.h"
#include "drivers/framemem/dc_selftest.h"
#include "drivers/framemem/fm.h"
#include "tests/check.h"

static void test_pack_round_trip(void)
{
    uint32_t px = fm_pack(0x12, 0x34, 0x56);
    CHECK_EQ_INT(px, 0x00123456u);
    CHECK_EQ_INT(fm_red(px), 0x12);
    CHECK_EQ_INT(fm_green(px), 0x34);
    CHECK_EQ_INT(fm_blue(px), 0x56);
    CHECK_EQ_INT(fm_pack(255, 255, 255), 0x00ffffffu);
}

static void test_fm_init_checks_size_and_storage(void)
{
    struct fm fm;
    static uint32_t buf[16 * 8];
    CHECK_EQ_INT(fm_init(&fm, buf, sizeof buf, 16, 8), FM_OK);
    CHECK_EQ_INT(fm_stride(&fm), 64);
    CHECK_EQ_INT(fm_bytes(&fm), sizeof buf);
    CHECK_EQ_INT(fm_init(&fm, buf, sizeof buf - 1, 16, 8), FM_ERR_STORAGE);
    CHECK_EQ_INT(fm_init(&fm, NULL, sizeof buf, 16, 8), FM_ERR_STORAGE);
    CHECK_EQ_INT(fm_init(&fm, (uint8_t *)buf + 2, sizeof buf - 4, 4, 4), FM_ERR_STORAGE);
    CHECK_EQ_INT(fm_init(&fm, buf, sizeof buf, 0, 8), FM_ERR_SIZE);
    CHECK_EQ_INT(fm_init(&fm, buf, sizeof buf, FM_MAX_WIDTH + 1, 1), FM_ERR_SIZE);
    CHECK_EQ_INT(fm_init(&fm, buf, sizeof buf, 1, FM_MAX_HEIGHT + 1), FM_ERR_SIZE);
}

/* The largest frame, 1024x1024: runs at its corners land where they should
 * and a run one pixel too long is refused without touching memory. */
static void test_fm_runs_and_bounds(void)
{
    size_t bytes = FM_BYTES(FM_MAX_WIDTH, FM_MAX_HEIGHT);
    uint32_t *mem = malloc(bytes);
    memset(mem, 0x5a, bytes);
    struct fm fm;
    CHECK_EQ_INT(fm_init(&fm, mem, bytes, FM_MAX_WIDTH, FM_MAX_HEIGHT), FM_OK);
    CHECK_EQ_INT(fm_get(&fm, 1023, 1023), 0); /* cleared to black */
    uint32_t run[4] = {fm_pack(1, 2, 3), fm_pack(4, 5, 6), fm_pack(7, 8, 9),
                       fm_pack(10, 11, 12)};
    CHECK_EQ_INT(fm_write_run(&fm, 1020, 1023, run, 4), FM_OK);
    CHECK_EQ_INT(fm_write_run(&fm, 0, 0, run, 1), FM_OK);
    CHECK_EQ_INT(fm_get(&fm, 1023, 1023), fm_pack(10, 11, 12));
    CHECK_EQ_INT(fm_get(&fm, 1020, 1023), fm_pack(1, 2, 3));
    CHECK_EQ_INT(fm_get(&fm, 0, 0), fm_pack(1, 2, 3));
    CHECK_EQ_INT(fm_get(&fm, 1, 0), 0);
    CHECK_EQ_INT(fm_write_run(&fm, 1021, 5, run, 4), FM_ERR_BOUNDS);
    CHECK_EQ_INT(fm_get(&fm, 1021, 5), 0);
    CHECK_EQ_INT(fm_write_run(&fm, 0, 1024, run, 1), FM_ERR_BOUNDS);
    CHECK_EQ_INT(fm_write_run(&fm, UINT32_MAX, 0, run, 2), FM_ERR_BOUNDS);
    CHECK_EQ_INT(fm.runs_written, 2);
    CHECK_EQ_INT(fm.pixels_written, 5);
    CHECK_EQ_INT(fm.runs_refused, 3);
    uint8_t rgb[12];
    CHECK_EQ_INT(fm_read_rgb(&fm, 1020, 1023, 4, rgb), FM_OK);
    for (int i = 0; i < 12; i++)
        CHECK_EQ_INT(rgb[i], i + 1);
    CHECK_EQ_INT(fm_read_rgb(&fm, 1020, 1023, 5, rgb), FM_ERR_BOUNDS);
    fm_clear(&fm);
    CHECK_EQ_INT(fm_get(&fm, 1023, 1023), 0);
    CHECK_EQ_INT(fm.runs_written, 0);
    CHECK_EQ_INT(fm.pixels_written, 0);
    free(mem);
}

static void test_run_pack_from_rgb_bytes(void)
{
    struct dc_run run;
    uint8_t rgb[DC_RUN_MAX_PIXELS * 3 + 3];
    for (size_t i = 0; i < sizeof rgb; i++)
        rgb[i] = (uint8_t)i;
    CHECK_EQ_INT(dc_run_pack(&run, 7, 9, rgb, 2), DC_OK);
    CHECK(run.x == 7 && run.y == 9 && run.n == 2);
    CHECK_EQ_INT(run.px[0], 0x00000102u);
    CHECK_EQ_INT(run.px[1], 0x00030405u);
    CHECK_EQ_INT(dc_run_pack(&run, 0, 0, rgb, 0), DC_ERR_RUN);
    CHECK_EQ_INT(dc_run_pack(&run, 0, 0, rgb, DC_RUN_MAX_PIXELS + 1), DC_ERR_RUN);
    CHECK_EQ_INT(dc_run_pack(&run, FM_MAX_WIDTH, 0, rgb, 1), DC_ERR_RUN);
    CHECK_EQ_INT(dc_run_pack(&run, 0, FM_MAX_HEIGHT, rgb, 1), DC_ERR_RUN);
}

static struct dc_run make_run(uint32_t producer, uint32_t seq, uint32_t n)
{
    struct dc_run r;
    memset(&r, 0, sizeof r);
    r.x = (uint16_t)seq;
    r.y = (uint16_t)producer;
    r.n = (uint16_t)n;
    r.producer = (uint16_t)producer;
    for (uint32_t i = 0; i < n; i++)
        r.px[i] = (producer << 24) ^ (seq << 8) ^ i;
    return r;
}

/* One thread: FIFO order, full at exactly the slot count, empty after. */
static void test_ring_order_full_empty(void)
{
    struct dc_slot slots[4];
    struct dc_ring r;
    struct dc_run in, out;
    int wake;
    CHECK_EQ_INT(dc_ring_init(&r, slots, 3), DC_ERR_SLOTS);
    CHECK_EQ_INT(dc_ring_init(&r, slots, 4), DC_OK);
    CHECK_EQ_INT(dc_ring_try_pop(&r, &out), DC_ERR_EMPTY);
    for (uint32_t lap = 0; lap < 3; lap++) {
        for (uint32_t i = 0; i < 4; i++) {
            in = make_run(1, lap * 4 + i, 1 + i);
            CHECK_EQ_INT(dc_ring_try_push(&r, &in, &wake), DC_OK);
            CHECK_EQ_INT(wake, 0);
        }
        in = make_run(1, 99, 1);
        CHECK_EQ_INT(dc_ring_try_push(&r, &in, &wake), DC_ERR_FULL);
        for (uint32_t i = 0; i < 4; i++) {
            CHECK_EQ_INT(dc_ring_try_pop(&r, &out), DC_OK);
            in = make_run(1, lap * 4 + i, 1 + i);
            CHECK_EQ_INT(out.x, lap * 4 + i);
            CHECK_EQ_INT(out.n, 1 + i);
            CHECK(memcmp(out.px, in.px, out.n * sizeof(uint32_t)) == 0);
        }
        CHECK_EQ_INT(dc_ring_try_pop(&r, &out), DC_ERR_EMPTY);
    }
    in = make_run(1, 0, 0);
    CHECK_EQ_INT(dc_ring_try_push(&r, &in, &wake), DC_ERR_RUN);
}

/* A producer that failed between claiming a position and publishing it:
 * the consumer stops there until it gives the position up, then takes the
 * runs after it; nothing is given up while the oldest run is published. */
static void test_ring_skip_abandoned(void)
{
    struct dc_slot slots[4];
    struct dc_ring r;
    struct dc_run a = make_run(2, 0, 3), c = make_run(4, 2, 5), out;
    int wake;
    dc_ring_init(&r, slots, 4);
    CHECK_EQ_INT(dc_ring_skip_abandoned(&r), 0); /* empty */
    CHECK_EQ_INT(dc_ring_try_push(&r, &a, &wake), DC_OK);
    CHECK_EQ_INT(dc_ring_skip_abandoned(&r), 0); /* published */
    r.head++; /* producer 3 claims position 1 and fails */
    CHECK_EQ_INT(dc_ring_try_push(&r, &c, &wake), DC_OK);
    CHECK_EQ_INT(dc_ring_try_pop(&r, &out), DC_OK);
    CHECK_EQ_INT(out.producer, 2);
    CHECK_EQ_INT(dc_ring_try_pop(&r, &out), DC_ERR_EMPTY);
    CHECK_EQ_INT(dc_ring_skip_abandoned(&r), 1);
    CHECK_EQ_INT(dc_ring_try_pop(&r, &out), DC_OK);
    CHECK_EQ_INT(out.producer, 4);
    CHECK(memcmp(out.px, c.px, c.n * sizeof(uint32_t)) == 0);
    CHECK_EQ_INT(dc_ring_skip_abandoned(&r), 0);
    /* The given-up slot is free for the next lap: four more pushes fit. */
    for (uint32_t i = 0; i < 4; i++)
        CHECK_EQ_INT(dc_ring_try_push(&r, &a, &wake), DC_OK);
    CHECK_EQ_INT(dc_ring_try_push(&r, &a, &wake), DC_ERR_FULL);
}

static void count_wake(uint32_t id, void *ctx)
{
    ((uint32_t *)ctx)[id]++;
}

/* The waiting flags: an armed consumer is reported by the next push; an
 * armed producer is woken by the next pop, and only once. */
static void test_ring_wait_flags(void)
{
    struct dc_slot slots[2];
    struct dc_ring r;
    struct dc_run in = make_run(3, 0, 1), out;
    int wake;
    uint32_t woken[DC_MAX_PRODUCERS] = {0};
    dc_ring_init(&r, slots, 2);
    CHECK_EQ_INT(dc_ring_consumer_arm(&r), 0);
    CHECK_EQ_INT(dc_ring_try_push(&r, &in, &wake), DC_OK);
    CHECK_EQ_INT(wake, 1);
    CHECK_EQ_INT(dc_ring_try_push(&r, &in, &wake), DC_OK);
    CHECK_EQ_INT(wake, 0); /* flag taken by the first push */
    CHECK_EQ_INT(dc_ring_consumer_arm(&r), 1); /* runs are there */
    CHECK_EQ_INT(dc_ring_producer_arm(&r, 3), 0);   /* full: sleep */
    CHECK_EQ_INT(dc_ring_producer_arm(&r, 200), 0);
    CHECK_EQ_INT(dc_ring_producer_arm(&r, DC_MAX_PRODUCERS), DC_ERR_PRODUCER);
    CHECK_EQ_INT(dc_ring_try_pop(&r, &out), DC_OK);
    CHECK_EQ_INT(dc_ring_wake_producers(&r, count_wake, woken), 2);
    CHECK(woken[3] == 1 && woken[200] == 1);
    CHECK_EQ_INT(dc_ring_wake_producers(&r, count_wake, woken), 0);
    CHECK_EQ_INT(dc_ring_producer_arm(&r, 5), 1); /* room now: no sleep */
    CHECK_EQ_INT(dc_ring_wake_producers(&r, count_wake, woken), 0);
    CHECK(r.full_waits == 3);
}

/* ---- many producers, one consumer, a FIFO much smaller than the work ---- */
#define STRESS_PRODUCERS 6
#define STRESS_RUNS 20000
#define STRESS_SLOTS 8
#define WAIT_GIVE_UP_S 20 /* a lost wake-up shows as a waiter stuck this long */

struct stress {
    struct dc_ring ring;
    struct dc_slot slots[STRESS_SLOTS];
    uint32_t producer_wakes[DC_MAX_PRODUCERS]; /* bumped by wake callbacks */
    uint32_t consumer_wakes;
    int stuck; /* a waiter gave up: a wake-up was lost */
};

static int wait_for_change(const uint32_t *counter, uint32_t mark)
{
    time_t start = time(NULL);
    while (__atomic_load_n(counter, __ATOMIC_ACQUIRE) == mark) {
        if (time(NULL) - start > WAIT_GIVE_UP_S)
            return -1;
        sched_yield();
    }
    return 0;
}

struct producer_arg {
    struct stress *st;
    uint32_t id;
};

static void *stress_producer(void *p)
{
    struct producer_arg *a = p;
    struct stress *st = a->st;
    for (uint32_t seq = 0; seq < STRESS_RUNS; seq++) {
        struct dc_run run = make_run(a->id, seq, 1 + (seq % DC_RUN_MAX_PIXELS));
        for (;;) {
            uint32_t mark = __atomic_load_n(&st->producer_wakes[a->id], __ATOMIC_ACQUIRE);
            int wake;
            if (dc_ring_try_push(&st->ring, &run, &wake) == DC_OK) {
                if (wake)
                    __atomic_fetch_add(&st->consumer_wakes, 1, __ATOMIC_RELEASE);
                break;
            }
            if (dc_ring_producer_arm(&st->ring, a->id))
                continue;
            if (wait_for_change(&st->producer_wakes[a->id], mark) != 0) {
                st->stuck = 1;
                return NULL;
            }
        }
    }
    return NULL;
}

static void wake_producer(uint32_t id, void *ctx)
{
    __atomic_fetch_add(&((struct stress *)ctx)->producer_wakes[id], 1, __ATOMIC_RELEASE);
}

/* Every producer's runs arrive exactly once, in its own order, with their
 * pixels intact; a full FIFO made producers wait (never dropped). */
static void test_ring_many_producers(void)
{
    static struct stress st;
    memset(&st, 0, sizeof st);
    CHECK_EQ_INT(dc_ring_init(&st.ring, st.slots, STRESS_SLOTS), DC_OK);
    pthread_t th[STRESS_PRODUCERS];
    struct producer_arg args[STRESS_PRODUCERS];
    /* Ids spread over the bitmap words, as core numbers would be. */
    static const uint32_t ids[STRESS_PRODUCERS] = {2, 3, 31, 32, 100, 255};
    for (int i = 0; i < STRESS_PRODUCERS; i++) {
        args[i].st = &st;
        args[i].id = ids[i];
        pthread_create(&th[i], NULL, stress_producer, &args[i]);
    }
    /* The consumer takes nothing until a producer has found the FIFO full
     * and armed its wait, so the full-FIFO path (wait, then be woken by a
     * pop) runs every time, not only when thread scheduling happens to let
     * the producers get ahead. */
    int filled = wait_for_change(&st.ring.full_waits, 0);
    CHECK_EQ_INT(filled, 0);
    st.stuck = filled != 0;
    uint32_t next[DC_MAX_PRODUCERS] = {0};
    uint32_t got = 0, bad = 0;
    while (got < STRESS_PRODUCERS * STRESS_RUNS && !st.stuck) {
        uint32_t mark = __atomic_load_n(&st.consumer_wakes, __ATOMIC_ACQUIRE);
        struct dc_run out;
        if (dc_ring_try_pop(&st.ring, &out) == DC_OK) {
            dc_ring_wake_producers(&st.ring, wake_producer, &st);
            struct dc_run want = make_run(out.producer, next[out.producer],
                            1 + (next[out.producer] % DC_RUN_MAX_PIXELS));
            if (out.y != out.producer || out.x != (uint16_t)next[out.producer] ||
                out.n != want.n || memcmp(out.px, want.px, out.n * sizeof(uint32_t)) != 0)
                bad++;
            next[out.producer]++;
            got++;
            continue;
        }
        if (dc_ring_consumer_arm(&st.ring))
            continue;
        if (wait_for_change(&st.consumer_wakes, mark) != 0) {
            st.stuck = 1;
            break;
        }
    }
    for (int i = 0; i < STRESS_PRODUCERS; i++)
        pthread_join(th[i], NULL);
    CHECK_EQ_INT(st.stuck, 0);
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(got, STRESS_PRODUCERS * STRESS_RUNS);
    for (int i = 0; i < STRESS_PRODUCERS; i++)
        CHECK_EQ_INT(next[ids[i]], STRESS_RUNS);
    struct dc_run extra;
    CHECK_EQ_INT(dc_ring_try_pop(&st.ring, &extra), DC_ERR_EMPTY);
    CHECK(st.ring.full_waits > 0); /* the small FIFO filled and producers waited */
}

/* The board self-test's pattern: 24-bit pixels, no two alike in the
 * largest frame (so a run stored anywhere but its place would show). */
static void test_selftest_pattern_is_unique(void)
{
    uint8_t *seen = calloc(1u << 21, 1); /* one bit per 24-bit colour */
    uint32_t dup = 0, wide = 0;
    for (uint32_t y = 0; y < FM_MAX_HEIGHT; y++)
        for (uint32_t x = 0; x < FM_MAX_WIDTH; x++) {
            uint32_t p = dc_selftest_pixel(x, y);
            if (p > 0x00FFFFFFu) {
                wide++;
                continue;
            }
            if (seen[p >> 3] & (1u << (p & 7)))
                dup++;
            seen[p >> 3] |= (uint8_t)(1u << (p & 7));
        }
    free(seen);
    CHECK_EQ_INT(wide, 0);
    CHECK_EQ_INT(dup, 0);
}

int main(void)
{
    RUN(test_pack_round_trip);
    RUN(test_fm_init_checks_size_and_storage);
    RUN(test_fm_runs_and_bounds);
    RUN(test_run_pack_from_rgb_bytes);
    RUN(test_ring_order_full_empty);
    RUN(test_ring_wait_flags);
    RUN(test_ring_skip_abandoned);
    RUN(test_ring_many_producers);
    RUN(test_selftest_pattern_is_unique);
    return check_exit();
}
