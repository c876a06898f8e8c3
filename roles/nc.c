/* nc.c: the node computer (NC) program.  For this stage: answer the RC's
 * pings, read the broadcast block, take part in the line stress run, and
 * fault on request. */
#include <stdint.h>

#include "drivers/imsu/imsu.h"
#include "drivers/serial/line.h"
#include "kernel/cpu.h"
#include "kernel/klog.h"
#include "proto/crc32.h"
#include "proto/wire.h"
#include "roles/gigs.h"
#include "roles/selftest.h"
#include "roles/unit.h"
#include "proto/unitmsg.h"


static void nc_send(struct line_msg *m)
{
    int r = line_send(UNITS_RC_CORE, m, 0);
    if (r != LINE_OK)
        klog("send to RC failed: %s", line_strerror(r));
}

static void nc_bcast_read(struct line_msg *m)
{
    uint32_t me = mycpu()->core;
    uint32_t bytes = wire_get_u32(m->payload);
    const uint8_t *blk;
    uint32_t gen = 0, crc = 0;
    int st = imsu_bcast_read_begin(&imsu_rc_ncs, me, &blk, &gen);
    if (st == IMSU_OK) {
        if (bytes > imsu_rc_ncs.size)
            bytes = (uint32_t)imsu_rc_ncs.size;
        crc = crc32(blk, bytes);
        st = imsu_bcast_read_end(&imsu_rc_ncs, me);
    }
    /* A reader must not be able to write the broadcast block. */
    uint8_t *w;
    int forbidden = imsu_bcast_write_begin(&imsu_rc_ncs, me, &w);
    if (forbidden == IMSU_OK)
        imsu_bcast_write_end(&imsu_rc_ncs, me);
    selftest_msg_set(m, MSG_BCAST_READ_DONE, 16);
    wire_put_u32(m->payload, (uint32_t)st);
    wire_put_u32(m->payload + 4, crc);
    wire_put_u32(m->payload + 8, gen);
    wire_put_u32(m->payload + 12, (uint32_t)forbidden);
    nc_send(m);
}

static void nc_stress(struct line_msg *m)
{
    uint32_t msgs = wire_get_u32(m->payload);
    struct selftest_stream s[2];
    selftest_stream_init(&s[0], UNITS_RC_CORE, 0, msgs);
    selftest_stream_init(&s[1], UNITS_RC_CORE, 1, msgs);
    if (selftest_stress_run(s, 2) != 0)
        klog("stress: stalled with %u to receive, %u to send", (unsigned)s[0].left,
             (unsigned)s[1].left);
    selftest_msg_set(m, MSG_STRESS_REPORT, 16);
    wire_put_u64(m->payload, s[0].bytes);
    wire_put_u32(m->payload + 8, s[0].errors + s[0].left);
    wire_put_u32(m->payload + 12, 0);
    nc_send(m);
}

void nc_main(void *arg)
{
    (void)arg;
    static struct line_msg msgs[UNITS_MAX_CORES];
    struct line_msg *m = &msgs[mycpu()->core];
    for (;;) {
        int r = line_recv(UNITS_RC_CORE, m, 0);
        if (r != LINE_OK) {
            klog("line from RC: %s", line_strerror(r));
            continue;
        }
        switch (m->type) {
        case MSG_PING:
            m->type = MSG_PONG;
            nc_send(m);
            break;
        case MSG_BCAST_READ:
            nc_bcast_read(m);
            break;
        case MSG_STRESS:
            nc_stress(m);
            break;
        case MSG_NC_START:
            nc_render_frame(m);
            break;
        case MSG_FAULT: {
            uint8_t kind = wire_get_u8(m->payload + 2);
            selftest_msg_set(m, MSG_FAULT_ACK, 4);
            wire_put_u32(m->payload, 0);
            nc_send(m);
            selftest_fault_now(kind);
            break;
        }
        default:
            klog("unexpected message type %u from the RC", (unsigned)m->type);
            break;
        }
    }
}
