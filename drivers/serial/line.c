/* line.c: inter-unit serial lines (see line.h). */
#include "drivers/serial/line.h"

#include "kernel/arch.h"
#include "kernel/cpu.h"
#include "kernel/gic.h"
#include "kernel/ktime.h"
#include "kernel/memlayout.h"
#include "kernel/panic.h"
#include "kernel/ringbuf.h"
#include "kernel/task.h"

/* One direction of one line. */
struct line_dir {
    struct ringbuf ring;              /* encoded messages */
    volatile uint32_t reader_waiting; /* receiver sleeps until a message comes */
    volatile uint32_t writer_waiting; /* sender sleeps until room */
    uint32_t send_seq;                /* next seq to send (sender's) */
    uint32_t recv_seq;                /* next seq expected (receiver's) */
    uint32_t errors;                  /* bad crc or seq seen by the receiver */
};

struct line {
    uint32_t end[2];          /* the two cores */
    struct line_dir dir[2];   /* dir[i] carries end[i] -> end[1 - i] */
};

static struct line lines[UNITS_MAX_CORES - 1];
static uint32_t lines_used;

void line_init_all(uint32_t ncores)
{
    uint32_t n = ncores - 1;
    if ((uintptr_t)(__lines_end - __lines_start) < (uintptr_t)n * 2u * LINE_RING_SIZE)
        panic("line: %u lines need %u bytes of ring memory, the linker carved %u",
              (unsigned)n, (unsigned)(n * 2u * LINE_RING_SIZE),
              (unsigned)(__lines_end - __lines_start));
    for (uint32_t i = 0; i < n; i++) {
        struct line *l = &lines[i];
        /* Line 0: DM<->RC; line i: RC<->NC core i+1. */
        l->end[0] = i == 0 ? UNITS_DM_CORE : UNITS_RC_CORE;
        l->end[1] = i == 0 ? UNITS_RC_CORE : i + 1;
        for (int d = 0; d < 2; d++) {
            uint8_t *mem = (uint8_t *)__lines_start + (2u * i + (uint32_t)d) * LINE_RING_SIZE;
            ringbuf_init(&l->dir[d].ring, mem, LINE_RING_SIZE);
            l->dir[d].reader_waiting = 0;
            l->dir[d].writer_waiting = 0;
            l->dir[d].send_seq = 0;
            l->dir[d].recv_seq = 0;
            l->dir[d].errors = 0;
        }
    }
    lines_used = n;
}

uint32_t line_count(void)
{
    return lines_used;
}

/* The direction this core sends on (out) and receives on (in) towards peer. */
static int line_dirs(uint32_t peer, struct line_dir **out, struct line_dir **in)
{
    uint32_t me = mycpu()->core;
    uint32_t idx;
    if ((me == UNITS_DM_CORE && peer == UNITS_RC_CORE) || (me == UNITS_RC_CORE && peer == UNITS_DM_CORE))
        idx = 0;
    else if (me == UNITS_RC_CORE && peer >= UNITS_FIRST_NC && peer < board_ncores)
        idx = peer - 1;
    else if (peer == UNITS_RC_CORE && me >= UNITS_FIRST_NC)
        idx = me - 1;
    else
        return LINE_ERR_NO_LINE;
    struct line *l = &lines[idx];
    int mine = l->end[0] == me ? 0 : 1;
    *out = &l->dir[mine];
    *in = &l->dir[1 - mine];
    return LINE_OK;
}

int line_try_send(uint32_t peer, struct line_msg *m)
{
    struct line_dir *out, *in;
    if (line_dirs(peer, &out, &in) != LINE_OK)
        return LINE_ERR_NO_LINE;
    if (m->len > LINE_MAX_PAYLOAD)
        return LINE_ERR_TOO_LONG;
    if (ringbuf_free(&out->ring) < LINEMSG_HEADER_SIZE + (uint32_t)m->len)
        return LINE_ERR_FULL;
    uint8_t buf[LINEMSG_MAX_SIZE];
    m->seq = out->send_seq;
    size_t n = linemsg_encode(buf, sizeof buf, m);
    if (ringbuf_put(&out->ring, buf, (uint32_t)n) != 0)
        panic("line_try_send: ring to core %u lost its free space", (unsigned)peer);
    out->send_seq++;
    /* Full barrier: the new head is visible before we read the flag (the
     * receiver raises its flag, barriers, then re-reads head). */
    arch_dmb();
    if (out->reader_waiting) {
        out->reader_waiting = 0;
        gic_send_sgi(peer, SGI_DOORBELL);
    }
    return LINE_OK;
}

int line_try_recv(uint32_t peer, struct line_msg *m)
{
    struct line_dir *out, *in;
    if (line_dirs(peer, &out, &in) != LINE_OK)
        return LINE_ERR_NO_LINE;
    uint8_t buf[LINEMSG_MAX_SIZE];
    if (ringbuf_peek(&in->ring, buf, LINEMSG_HEADER_SIZE) != 0)
        return LINE_ERR_EMPTY;
    int total = linemsg_total_size(buf);
    if (total < 0)
        panic("line from core %u: header announces a message longer than %u bytes",
              (unsigned)peer, (unsigned)LINE_MAX_PAYLOAD);
    /* The sender puts whole messages, so the rest is there already. */
    if (ringbuf_get(&in->ring, buf, (uint32_t)total) != 0)
        panic("line from core %u: half a message in the ring", (unsigned)peer);
    int st = linemsg_decode(buf, (size_t)total, m);
    arch_dmb(); /* our tail is visible before we read the sender's flag */
    if (in->writer_waiting) {
        in->writer_waiting = 0;
        gic_send_sgi(peer, SGI_DOORBELL);
    }
    if (st != LINEMSG_OK) {
        in->errors++;
        in->recv_seq = m->seq + 1;
        return LINE_ERR_CHECK;
    }
    if (m->seq != in->recv_seq) {
        in->errors++;
        in->recv_seq = m->seq + 1;
        return LINE_ERR_SEQ;
    }
    in->recv_seq++;
    return LINE_OK;
}

int line_recv_ready_arm(uint32_t peer)
{
    struct line_dir *out, *in;
    if (line_dirs(peer, &out, &in) != LINE_OK)
        return 0;
    in->reader_waiting = 1;
    arch_dmb(); /* flag visible before we look at head again */
    return ringbuf_used(&in->ring) >= LINEMSG_HEADER_SIZE;
}

int line_send_ready_arm(uint32_t peer, uint32_t len)
{
    struct line_dir *out, *in;
    if (line_dirs(peer, &out, &in) != LINE_OK)
        return 0;
    out->writer_waiting = 1;
    arch_dmb(); /* flag visible before we look at tail again */
    return ringbuf_free(&out->ring) >= LINEMSG_HEADER_SIZE + len;
}

int line_send(uint32_t peer, struct line_msg *m, uint64_t deadline)
{
    for (;;) {
        uint32_t mark = task_event_mark();
        int r = line_try_send(peer, m);
        if (r != LINE_ERR_FULL)
            return r;
        if (line_send_ready_arm(peer, m->len))
            continue;
        if (ktime_passed(deadline))
            return LINE_ERR_TIMEOUT;
        task_wait(mark, deadline);
    }
}

int line_recv(uint32_t peer, struct line_msg *m, uint64_t deadline)
{
    for (;;) {
        uint32_t mark = task_event_mark();
        int r = line_try_recv(peer, m);
        if (r != LINE_ERR_EMPTY)
            return r;
        if (line_recv_ready_arm(peer))
            continue;
        if (ktime_passed(deadline))
            return LINE_ERR_TIMEOUT;
        task_wait(mark, deadline);
    }
}

const char *line_strerror(int status)
{
    switch (status) {
    case LINE_OK: return "ok";
    case LINE_ERR_NO_LINE: return "no serial line to that unit computer";
    case LINE_ERR_FULL: return "line full";
    case LINE_ERR_EMPTY: return "no message";
    case LINE_ERR_TIMEOUT: return "timed out";
    case LINE_ERR_TOO_LONG: return "payload longer than LINE_MAX_PAYLOAD";
    case LINE_ERR_CHECK: return "message failed its crc32";
    case LINE_ERR_SEQ: return "message out of sequence (lost, repeated or reordered)";
    }
    return "unknown line status";
}
