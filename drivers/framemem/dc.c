/* dc.c: the board's data collector (see dc.h). */
#include "drivers/framemem/dc.h"

#include "kernel/cpu.h"
#include "kernel/machine.h"
#include "kernel/memlayout.h"
#include "kernel/ktime.h"
#include "kernel/panic.h"
#include "kernel/task.h"

/* One DC on the board, shared by every core: the FIFO's slots live in the
 * image, not in any unit computer's private memory. */
UNIT_SHARED static struct dc_slot dc_slots[DC_RING_SLOTS];
UNIT_SHARED static struct dc_ring dc_ring;
UNIT_SHARED static uint32_t dc_consumer;
/* Producers whose runs the consumer drops (set by the consumer only). */
UNIT_SHARED static uint8_t dc_ignored[DC_MAX_PRODUCERS];

void dc_init(uint32_t consumer_core)
{
    int rc = dc_ring_init(&dc_ring, dc_slots, DC_RING_SLOTS);
    if (rc != DC_OK)
        panic("dc_init: %s", dc_strerror(rc));
    dc_consumer = consumer_core;
}

void dc_push(struct dc_run *run)
{
    struct cpu *c = mycpu();
    if (c->core == dc_consumer)
        panic("dc_push on the collecting core %u: it would wait for itself",
              (unsigned)c->core);
    run->producer = (uint16_t)c->core;
    for (;;) {
        uint32_t mark = task_event_mark(); /* before looking: no lost wake-up */
        int wake;
        int rc = dc_ring_try_push(&dc_ring, run, &wake);
        if (rc == DC_OK) {
            if (wake)
                machine_doorbell(dc_consumer);
            return;
        }
        if (rc != DC_ERR_FULL)
            panic("dc_push from core %u: %s", (unsigned)c->core, dc_strerror(rc));
        if (dc_ring_producer_arm(&dc_ring, c->core))
            continue; /* a slot came free meanwhile */
        task_wait(mark, 0);
    }
}

int dc_push_span(uint32_t x, uint32_t y, const uint8_t *rgb, uint32_t n)
{
    struct dc_run run;
    if (n == 0 || x >= FM_MAX_WIDTH || y >= FM_MAX_HEIGHT)
        return DC_ERR_RUN;
    while (n > 0) {
        uint32_t take = n < DC_RUN_MAX_PIXELS ? n : DC_RUN_MAX_PIXELS;
        int rc = dc_run_pack(&run, x, y, rgb, take);
        if (rc != DC_OK)
            return rc; /* x ran past FM_MAX_WIDTH: the rest is refused */
        dc_push(&run);
        x += take;
        rgb += 3 * take;
        n -= take;
    }
    return DC_OK;
}

static void dc_wake_producer(uint32_t core, void *ctx)
{
    (void)ctx;
    machine_doorbell(core);
}

uint32_t dc_collect(struct fm *fm, uint32_t max_runs)
{
    static struct dc_run run; /* consumer only; keeps 264 bytes off the stack */
    uint32_t taken = 0;
    while (taken < max_runs && dc_ring_try_pop(&dc_ring, &run) == DC_OK) {
        if (run.producer >= DC_MAX_PRODUCERS || !dc_ignored[run.producer])
            (void)fm_write_run(fm, run.x, run.y, run.px, run.n); /* refusals counted */
        taken++;
    }
    if (taken)
        dc_ring_wake_producers(&dc_ring, dc_wake_producer, NULL);
    return taken;
}

uint32_t dc_collect_wait(struct fm *fm, uint64_t deadline)
{
    for (;;) {
        uint32_t mark = task_event_mark();
        uint32_t n = dc_collect(fm, UINT32_MAX);
        if (n)
            return n;
        if (dc_ring_consumer_arm(&dc_ring))
            continue;
        if (ktime_passed(deadline))
            return 0;
        task_wait(mark, deadline);
    }
}

uint32_t dc_collect_until(struct fm *fm, uint64_t deadline, const volatile int *stop)
{
    for (;;) {
        uint32_t mark = task_event_mark();
        uint32_t n = dc_collect(fm, UINT32_MAX);
        if (n)
            return n;
        if (*stop)
            return 0;
        if (dc_ring_consumer_arm(&dc_ring))
            continue;
        if (ktime_passed(deadline))
            return 0;
        task_wait(mark, deadline);
    }
}

uint32_t dc_collect_final(struct fm *fm)
{
    uint32_t skipped = 0;
    for (;;) {
        dc_collect(fm, UINT32_MAX);
        if (!dc_ring_skip_abandoned(&dc_ring))
            return skipped;
        skipped++;
    }
}

void dc_ignore_producer(uint32_t producer)
{
    if (producer < DC_MAX_PRODUCERS)
        dc_ignored[producer] = 1;
}

uint32_t dc_full_waits(void)
{
    return __atomic_load_n(&dc_ring.full_waits, __ATOMIC_RELAXED);
}
