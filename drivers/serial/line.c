/* line.c: inter-unit serial lines (see line.h). */
#include "drivers/serial/line.h"

#include "kernel/arch.h"
#include "kernel/cpu.h"
#include "kernel/machine.h"
#include "kernel/ktime.h"
#include "kernel/memlayout.h"
#include "kernel/panic.h"
#include "kernel/ringbuf.h"
#include "kernel/task.h"
#include "proto/crc32.h"

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

UNIT_SHARED static struct line lines[UNITS_MAX_CORES - 1];
UNIT_SHARED static uint32_t lines_used;

/* The RC's, one bit per sending core: set by the sender after each
 * message to the RC, taken by the RC, which serves many lines, so that it
 * looks only at the lines that sent.  The other cores have one line each:
 * no map. */
UNIT_SHARED static uint32_t line_pending[LINE_PENDING_WORDS];

/* Bytes a message of len payload bytes takes in the ring: header and
 * payload padded to whole words (ringbuf_put_words), so every message
 * starts word-aligned and the ring copies it a word at a time; the header's
 * words as linemsg_header_words makes them, whose bytes on these
 * little-endian cores are linemsg.h's layout.  The padding is whatever follows
 * the payload in the sender's struct line_msg (payload[] holds
 * LINE_MAX_PAYLOAD bytes, a multiple of 4). */
#define LINE_PADDED(len) (((uint32_t)(len) + 3u) & ~3u)
#define LINE_RECORD_SIZE(len) (LINEMSG_HEADER_SIZE + LINE_PADDED(len))
_Static_assert(LINEMSG_HEADER_SIZE % 4 == 0 && LINE_MAX_PAYLOAD % 4 == 0 &&
                   LINE_RING_SIZE % 4 == 0,
               "line records are whole words");
_Static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
               "a ring's header words are linemsg.h's little-endian bytes");

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

int line_end_of(uint32_t peer, struct line_end *e)
{
    _Static_assert(UNITS_DM_CORE == 0 && UNITS_RC_CORE == 1 && UNITS_FIRST_NC == 2,
                   "line i joins the RC and core i + 1, line 0 the DM");
    uint32_t me = mycpu()->core;
    /* Every line has the RC at one end; x is the other end. */
    uint32_t x = me == UNITS_RC_CORE ? peer : (peer == UNITS_RC_CORE ? me : UNITS_RC_CORE);
    if (x == UNITS_RC_CORE || x >= board_ncores)
        return LINE_ERR_NO_LINE;
    struct line *l = &lines[x == UNITS_DM_CORE ? 0 : x - 1];
    int mine = l->end[0] == me ? 0 : 1;
    e->out = &l->dir[mine];
    e->in = &l->dir[1 - mine];
    e->me = me;
    e->peer = peer;
    return LINE_OK;
}

int line_end_try_send(const struct line_end *e, struct line_msg *m)
{
    struct line_dir *out = e->out;
    if (m->len > LINE_MAX_PAYLOAD)
        return LINE_ERR_TOO_LONG;
    uint32_t hdr[LINEMSG_HEADER_WORDS];
    m->seq = out->send_seq;
    linemsg_header_words(hdr, m, linemsg_payload_crc(m));
    /* The payload goes into the ring from m itself: one copy. */
    if (ringbuf_put_words(&out->ring, hdr, LINEMSG_HEADER_WORDS, m->payload,
                          LINE_PADDED(m->len) / 4u) != 0)
        return LINE_ERR_FULL;
    out->send_seq++;
    if (e->peer == UNITS_RC_CORE)
        __atomic_fetch_or(&line_pending[e->me / 32u], 1u << (e->me % 32u), __ATOMIC_RELEASE);
    /* Full barrier: the new head is visible before we read the flag (the
     * receiver raises its flag, barriers, then re-reads head). */
    arch_dmb();
    if (out->reader_waiting) {
        out->reader_waiting = 0;
        machine_doorbell(e->peer);
    }
    return LINE_OK;
}

int line_try_send(uint32_t peer, struct line_msg *m)
{
    struct line_end e;
    if (line_end_of(peer, &e) != LINE_OK)
        return LINE_ERR_NO_LINE;
    return line_end_try_send(&e, m);
}

/* line_try_recv on the direction in, looked up already. */
static inline __attribute__((always_inline)) int line_take(struct line_dir *in, uint32_t peer,
                                                           struct line_msg *m)
{
    uint32_t hdr[LINEMSG_HEADER_WORDS], words = ringbuf_words_in(&in->ring);
    if (words < LINEMSG_HEADER_WORDS)
        return LINE_ERR_EMPTY;
    ringbuf_read_words(&in->ring, 0, hdr, LINEMSG_HEADER_WORDS);
    uint32_t check = linemsg_header_from_words(hdr, m);
    if (m->len > LINE_MAX_PAYLOAD)
        panic("line from core %u: header announces a message longer than %u bytes",
              (unsigned)peer, (unsigned)LINE_MAX_PAYLOAD);
    /* The sender puts whole messages, so the rest is there already; the
     * payload comes out of the ring straight into m. */
    uint32_t n = LINE_PADDED(m->len) / 4u;
    if (words < LINEMSG_HEADER_WORDS + n)
        panic("line from core %u: half a message in the ring", (unsigned)peer);
    ringbuf_read_words(&in->ring, LINEMSG_HEADER_WORDS, m->payload, n);
    ringbuf_take_words(&in->ring, LINEMSG_HEADER_WORDS + n);
    int st = linemsg_check_payload(m, check);
    arch_dmb(); /* our tail is visible before we read the sender's flag */
    if (in->writer_waiting) {
        in->writer_waiting = 0;
        machine_doorbell(peer);
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

/* line_recv_ready_arm on the direction in, looked up already. */
static int line_arm(struct line_dir *in)
{
    in->reader_waiting = 1;
    arch_dmb(); /* flag visible before we look at head again */
    return ringbuf_used(&in->ring) >= LINEMSG_HEADER_SIZE;
}

int line_try_recv(uint32_t peer, struct line_msg *m)
{
    struct line_end e;
    if (line_end_of(peer, &e) != LINE_OK)
        return LINE_ERR_NO_LINE;
    return line_take(e.in, peer, m);
}

int line_end_try_recv_arm(const struct line_end *e, struct line_msg *m, int *ready)
{
    int r = line_take(e->in, e->peer, m);
    *ready = line_arm(e->in);
    return r;
}

int line_try_recv_arm(uint32_t peer, struct line_msg *m, int *ready)
{
    struct line_end e;
    *ready = 0;
    if (line_end_of(peer, &e) != LINE_OK)
        return LINE_ERR_NO_LINE;
    return line_end_try_recv_arm(&e, m, ready);
}

int line_recv_ready(uint32_t peer)
{
    struct line_end e;
    if (line_end_of(peer, &e) != LINE_OK)
        return 0;
    return ringbuf_used(&e.in->ring) >= LINEMSG_HEADER_SIZE;
}

int line_end_recv_ready_arm(const struct line_end *e)
{
    return line_arm(e->in);
}

int line_recv_ready_arm(uint32_t peer)
{
    struct line_end e;
    if (line_end_of(peer, &e) != LINE_OK)
        return 0;
    return line_end_recv_ready_arm(&e);
}

int line_send_ready_arm(uint32_t peer, uint32_t len)
{
    struct line_end e;
    if (line_end_of(peer, &e) != LINE_OK)
        return 0;
    e.out->writer_waiting = 1;
    arch_dmb(); /* flag visible before we look at tail again */
    return ringbuf_free(&e.out->ring) >= LINE_RECORD_SIZE(len);
}

uint32_t line_pending_take(uint32_t word)
{
    if (word >= LINE_PENDING_WORDS || mycpu()->core != UNITS_RC_CORE)
        return 0;
    return __atomic_exchange_n(&line_pending[word], 0, __ATOMIC_ACQUIRE);
}

void line_pending_mark(uint32_t peer)
{
    if (peer < UNITS_MAX_CORES && mycpu()->core == UNITS_RC_CORE)
        __atomic_fetch_or(&line_pending[peer / 32u], 1u << (peer % 32u), __ATOMIC_RELAXED);
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
