/* relay.c: the NC boards' host-link messages, carried through the shared
 * file to board 0, which sends them (hostlink_relay.h, an521_relay.h).
 *
 * One ring per core, written by that core only and read by board 0's
 * relay task only: the writer fills a record, then moves head; the reader
 * takes it, then moves tail (a barrier before each move).  A record is a
 * u16 payload length, the frame type and flags, the payload, padded to 4
 * bytes. */
#include "drivers/serial/hostlink_relay.h"

#include <string.h>

#include "drivers/an521/an521_board.h"
#include "drivers/an521/an521_relay.h"
#include "drivers/serial/hostlink_tx.h"
#include "kernel/arch.h"
#include "kernel/ktime.h"
#include "kernel/machine.h"
#include "kernel/memlayout.h"
#include "kernel/task.h"
#include "proto/hostlink.h"
#include "proto/units.h"
#include "proto/wire.h"

#define RELAY_RING_BYTES 4096u
#define RELAY_HEADER 4u
#define RELAY_WAIT_MS 2000u /* a writer waits this long for room */
#define RELAY_LOOK_MS 1u    /* the relay task looks this often */

struct relay_ring {
    volatile uint32_t head; /* bytes written (the writer's) */
    volatile uint32_t tail; /* bytes taken (the reader's) */
    volatile uint32_t dropped;
    uint32_t pad;
    uint8_t buf[RELAY_RING_BYTES];
};

UNIT_SHARED static struct relay_ring relay_rings[AN521_CORES_PER_BOARD * AN521_MAX_BOARDS];

static uint32_t relay_record_bytes(size_t len)
{
    return (RELAY_HEADER + (uint32_t)len + 3u) & ~3u;
}

int hostlink_relay_here(void)
{
    return an521_board() != 0;
}

void hostlink_relay_put(uint8_t type, uint8_t flags, const void *payload, size_t len)
{
    struct relay_ring *r = &relay_rings[machine_core_id()];
    uint32_t need = relay_record_bytes(len);
    uint64_t deadline = 0;
    for (;;) {
        uint32_t mark = task_event_mark();
        uint32_t used = r->head - r->tail;
        if (RELAY_RING_BYTES - used >= need)
            break;
        if (arch_irqs_masked() || (deadline && ktime_passed(deadline))) {
            r->dropped++;
            return;
        }
        if (!deadline)
            deadline = ktime_deadline_ms(RELAY_WAIT_MS);
        task_wait(mark, deadline);
    }
    uint8_t rec[RELAY_HEADER + LINK_MAX_PAYLOAD];
    wire_put_u16(rec, (uint16_t)len);
    rec[2] = type;
    rec[3] = flags;
    memcpy(rec + RELAY_HEADER, payload, len);
    uint32_t h = r->head;
    for (uint32_t i = 0; i < RELAY_HEADER + len; i++)
        r->buf[(h + i) % RELAY_RING_BYTES] = rec[i];
    arch_dmb();
    r->head = h + need;
}

/* Board 0: sends what one ring holds; returns the records sent. */
static uint32_t relay_drain(struct relay_ring *r)
{
    uint32_t sent = 0;
    uint8_t rec[RELAY_HEADER + LINK_MAX_PAYLOAD];
    for (;;) {
        uint32_t t = r->tail, h = r->head;
        arch_dmb();
        if (h == t)
            return sent;
        uint32_t used = h - t;
        for (uint32_t i = 0; i < RELAY_HEADER; i++)
            rec[i] = r->buf[(t + i) % RELAY_RING_BYTES];
        uint32_t len = wire_get_u16(rec);
        if (used > RELAY_RING_BYTES || len > LINK_MAX_PAYLOAD ||
            relay_record_bytes(len) > used) {
            /* A ring its writer broke (it faulted mid-record?): drop what
             * it holds rather than send garbage. */
            r->dropped++;
            r->tail = h;
            return sent;
        }
        for (uint32_t i = 0; i < len; i++)
            rec[RELAY_HEADER + i] = r->buf[(t + RELAY_HEADER + i) % RELAY_RING_BYTES];
        arch_dmb();
        r->tail = t + relay_record_bytes(len);
        hostlink_send(rec[2], rec[3], rec + RELAY_HEADER, len);
        sent++;
    }
}

static void relay_task(void *arg)
{
    (void)arg;
    uint32_t cores = an521_boards() * AN521_CORES_PER_BOARD;
    for (;;) {
        uint32_t mark = task_event_mark();
        for (uint32_t k = AN521_CORES_PER_BOARD; k < cores; k++)
            relay_drain(&relay_rings[k]);
        task_wait(mark, ktime_deadline_ms(RELAY_LOOK_MS));
    }
}

void an521_relay_start(void)
{
    task_create("relay", relay_task, 0);
}
