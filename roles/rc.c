/* rc.c: the root computer (RC) program.  For this stage it carries out the
 * DM's bring-up requests over its lines to the NCs and the IMSUs. */
#include <stdint.h>

#include "drivers/imsu/imsu.h"
#include "drivers/serial/line.h"
#include "kernel/cpu.h"
#include "kernel/klog.h"
#include "kernel/ktime.h"
#include "kernel/panic.h"
#include "kernel/task.h"
#include "proto/crc32.h"
#include "proto/wire.h"
#include "roles/gigs.h"
#include "roles/selftest.h"
#include "roles/unit.h"
#include "proto/unitmsg.h"


static void rc_send(uint32_t peer, struct line_msg *m)
{
    int r = line_send(peer, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
    if (r != LINE_OK)
        klog("send of message type %u to core %u failed: %s", (unsigned)m->type,
             (unsigned)peer, line_strerror(r));
}

static void rc_ping_ncs(struct line_msg *m)
{
    uint32_t n = board_ncores, ok = 0, first_bad = 0xFFFFFFFFu;
    uint64_t deadline = ktime_deadline_ms(PING_TIMEOUT_MS);
    for (uint32_t k = UNITS_FIRST_NC; k < n; k++) {
        selftest_msg_set(m, MSG_PING, 4);
        wire_put_u32(m->payload, k);
        line_send(k, m, deadline);
    }
    for (uint32_t k = UNITS_FIRST_NC; k < n; k++) {
        int r = selftest_recv_type(k, MSG_PONG, m, deadline);
        if (r == LINE_OK && wire_get_u32(m->payload) == k)
            ok++;
        else if (first_bad == 0xFFFFFFFFu)
            first_bad = k;
    }
    selftest_msg_set(m, MSG_PING_NCS_DONE, 12);
    wire_put_u32(m->payload, ok);
    wire_put_u32(m->payload + 4, n - UNITS_FIRST_NC);
    wire_put_u32(m->payload + 8, first_bad);
    rc_send(UNITS_DM_CORE, m);
}

/* The DM asks for timed round trips with one NC (MSG_LATENCY). */
static void rc_latency(struct line_msg *m)
{
    uint32_t rounds = wire_get_u32(m->payload);
    uint32_t core = wire_get_u16(m->payload + 4), done = 0, mmm[3] = {0, 0, 0};
    int r = m->len < 6 || core < UNITS_FIRST_NC || core >= board_ncores
                ? LINE_ERR_NO_LINE
                : selftest_latency(core, rounds, m, &done, mmm);
    selftest_msg_set(m, MSG_LATENCY_DONE, 20);
    wire_put_u32(m->payload, (uint32_t)r);
    wire_put_u32(m->payload + 4, done);
    for (int i = 0; i < 3; i++)
        wire_put_u32(m->payload + 8 + 4 * i, mmm[i]);
    rc_send(UNITS_DM_CORE, m);
}

/* The DM swapped a block to us: check it, show that misuse is refused,
 * write our answer into it and swap it back. */
static void rc_imsu_pair(struct line_msg *m)
{
    struct imsu_pair *p = &imsu_dm_rc;
    uint32_t bytes = wire_get_u32(m->payload);
    uint32_t want = wire_get_u32(m->payload + 4);
    uint32_t seed = wire_get_u32(m->payload + 8);
    uint32_t misuse_failed = 0;
    int status = 0;
    if (bytes > p->size)
        bytes = (uint32_t)p->size;
    int held = imsu_held(p, UNITS_RC_CORE);
    uint32_t got = crc32(imsu_read_block(p, UNITS_RC_CORE), bytes);
    uint8_t *w;
    if (imsu_write_begin(p, UNITS_RC_CORE, 1 - held, &w) != IMSU_ERR_NOT_HOLDER) {
        misuse_failed++;
        imsu_write_end(p, UNITS_RC_CORE);
    }
    int r = imsu_write_begin(p, UNITS_RC_CORE, held, &w);
    uint32_t mine = 0;
    if (r != IMSU_OK) {
        status = r;
    } else {
        selftest_fill(w, bytes, seed, 0);
        mine = crc32(w, bytes);
        /* Still inside the write: the DM's swap must be refused now. */
        selftest_msg_set(m, MSG_IMSU_MIDWRITE, 0);
        rc_send(UNITS_DM_CORE, m);
        r = selftest_recv_type(UNITS_DM_CORE, MSG_IMSU_MIDWRITE_SEEN, m,
                               ktime_deadline_ms(REPLY_TIMEOUT_MS));
        if (r != LINE_OK || (int32_t)wire_get_u32(m->payload) != IMSU_ERR_PEER_WRITING)
            misuse_failed++;
        imsu_write_end(p, UNITS_RC_CORE);
        r = imsu_swap(p, UNITS_RC_CORE);
        if (r != IMSU_OK)
            status = r;
    }
    selftest_msg_set(m, MSG_IMSU_PAIR_DONE, 16);
    wire_put_u32(m->payload, (uint32_t)status);
    wire_put_u32(m->payload + 4, mine);
    wire_put_u32(m->payload + 8, misuse_failed);
    wire_put_u32(m->payload + 12, got == want);
    rc_send(UNITS_DM_CORE, m);
}

static void rc_imsu_bcast(struct line_msg *m)
{
    struct imsu_bcast *b = &imsu_rc_ncs;
    uint32_t bytes = wire_get_u32(m->payload);
    uint32_t seed = wire_get_u32(m->payload + 4);
    uint32_t misuse_failed = 0, ok = 0, n = board_ncores;
    if (bytes > b->size)
        bytes = (uint32_t)b->size;
    uint8_t *w;
    int r = imsu_bcast_write_begin(b, UNITS_RC_CORE, &w);
    if (r != IMSU_OK)
        panic("IMSU broadcast: the RC cannot write its own block: %s", imsu_strerror(r));
    selftest_fill(w, bytes, seed, 0);
    uint32_t crc = crc32(w, bytes);
    imsu_bcast_write_end(b, UNITS_RC_CORE);
    uint32_t gen = b->generation;
    /* A write while someone reads must be refused. */
    const uint8_t *rd;
    uint32_t g;
    if (imsu_bcast_read_begin(b, UNITS_RC_CORE, &rd, &g) == IMSU_OK) {
        if (imsu_bcast_write_begin(b, UNITS_RC_CORE, &w) != IMSU_ERR_READERS_ACTIVE) {
            misuse_failed++;
            imsu_bcast_write_end(b, UNITS_RC_CORE);
        }
        imsu_bcast_read_end(b, UNITS_RC_CORE);
    } else {
        misuse_failed++;
    }
    uint64_t deadline = ktime_deadline_ms(REPLY_TIMEOUT_MS);
    for (uint32_t k = UNITS_FIRST_NC; k < n; k++) {
        selftest_msg_set(m, MSG_BCAST_READ, 4);
        wire_put_u32(m->payload, bytes);
        line_send(k, m, deadline);
    }
    for (uint32_t k = UNITS_FIRST_NC; k < n; k++) {
        if (selftest_recv_type(k, MSG_BCAST_READ_DONE, m, deadline) != LINE_OK)
            continue;
        if (wire_get_u32(m->payload) == IMSU_OK && wire_get_u32(m->payload + 4) == crc &&
            wire_get_u32(m->payload + 8) == gen)
            ok++;
        if ((int32_t)wire_get_u32(m->payload + 12) != IMSU_ERR_NOT_HOLDER)
            misuse_failed++;
    }
    selftest_msg_set(m, MSG_IMSU_BCAST_DONE, 12);
    wire_put_u32(m->payload, ok);
    wire_put_u32(m->payload + 4, n - UNITS_FIRST_NC);
    wire_put_u32(m->payload + 8, misuse_failed);
    rc_send(UNITS_DM_CORE, m);
}

static void rc_stress(struct line_msg *m)
{
    static struct selftest_stream s[2 * UNITS_MAX_CORES];
    uint32_t msgs = wire_get_u32(m->payload);
    uint32_t n = 0, skipped = 0;
    selftest_stream_init(&s[n++], UNITS_DM_CORE, 0, msgs);
    selftest_stream_init(&s[n++], UNITS_DM_CORE, 1, msgs);
    for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++) {
        if (unit_is_halted(k)) {
            skipped++;
            continue;
        }
        selftest_msg_set(m, MSG_STRESS, 4);
        wire_put_u32(m->payload, msgs);
        rc_send(k, m);
        selftest_stream_init(&s[n++], k, 0, msgs);
        selftest_stream_init(&s[n++], k, 1, msgs);
    }
    if (selftest_stress_run(s, n) != 0)
        klog("stress: stalled: some line stopped moving");
    uint64_t bytes = 0;
    uint32_t errors = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (!s[i].sending) {
            bytes += s[i].bytes;
            errors += s[i].errors + s[i].left;
        }
    }
    uint64_t deadline = ktime_deadline_ms(REPLY_TIMEOUT_MS);
    for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++) {
        if (unit_is_halted(k))
            continue;
        if (selftest_recv_type(k, MSG_STRESS_REPORT, m, deadline) != LINE_OK) {
            errors++;
            continue;
        }
        bytes += wire_get_u64(m->payload);
        errors += wire_get_u32(m->payload + 8);
    }
    selftest_msg_set(m, MSG_STRESS_REPORT, 16);
    wire_put_u64(m->payload, bytes);
    wire_put_u32(m->payload + 8, errors);
    wire_put_u32(m->payload + 12, skipped);
    rc_send(UNITS_DM_CORE, m);
}

static void rc_fault(struct line_msg *m)
{
    uint16_t core = wire_get_u16(m->payload);
    uint8_t kind = wire_get_u8(m->payload + 2);
    if (core == UNITS_RC_CORE) {
        selftest_msg_set(m, MSG_FAULT_ACK, 4);
        wire_put_u32(m->payload, 0);
        rc_send(UNITS_DM_CORE, m);
        selftest_fault_now(kind);
        return;
    }
    int r = line_send(core, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
    if (r == LINE_OK)
        r = selftest_recv_type(core, MSG_FAULT_ACK, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
    selftest_msg_set(m, MSG_FAULT_ACK, 4);
    wire_put_u32(m->payload, (uint32_t)r);
    rc_send(UNITS_DM_CORE, m);
}

void rc_main(void *arg)
{
    (void)arg;
    static struct line_msg msg;
    struct line_msg *m = &msg;
    task_create("rcdc", rc_collect_task, NULL); /* the data collector */
    for (;;) {
        int r = line_recv(UNITS_DM_CORE, m, 0);
        if (r != LINE_OK) {
            klog("line from DM: %s", line_strerror(r));
            continue;
        }
        switch (m->type) {
        case MSG_PING:
            m->type = MSG_PONG;
            rc_send(UNITS_DM_CORE, m);
            break;
        case MSG_PING_NCS:
            rc_ping_ncs(m);
            break;
        case MSG_LATENCY:
            rc_latency(m);
            break;
        case MSG_IMSU_PAIR:
            rc_imsu_pair(m);
            break;
        case MSG_IMSU_BCAST:
            rc_imsu_bcast(m);
            break;
        case MSG_STRESS:
            rc_stress(m);
            break;
        case MSG_FAULT:
            rc_fault(m);
            break;
        case MSG_RENDER_FRAME:
            rc_render_frame(m);
            break;
        default:
            klog("unexpected message type %u from the DM", (unsigned)m->type);
            break;
        }
    }
}
