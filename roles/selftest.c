/* selftest.c: test patterns, stress streams, faults on purpose. */
#include "roles/selftest.h"

#include <string.h>

#include "drivers/serial/line.h"
#include "kernel/cpu.h"
#include "kernel/klog.h"
#include "kernel/ktime.h"
#include "kernel/param.h"
#include "kernel/memlayout.h"
#include "kernel/panic.h"
#include "kernel/spinlock.h"
#include "kernel/task.h"
#include "proto/hostlink.h"
#include "proto/render_link.h"
#include "proto/textfmt.h"
#include "proto/unitmsg.h"
#include "proto/wire.h"

/* A cheap mix of (seed, seq, word index): every word of every message of
 * every stream differs, so a lost, repeated or misplaced message shows. */
static uint32_t selftest_word(uint32_t seed, uint32_t seq, uint32_t j)
{
    uint32_t x = seed * 0x9E3779B1u ^ seq * 0x85EBCA77u ^ j * 0x27D4EB2Fu;
    return x ^ (x >> 15);
}

void selftest_fill(uint8_t *p, size_t n, uint32_t seed, uint32_t seq)
{
    for (uint32_t j = 0; j < n / 4; j++) {
        uint32_t w = selftest_word(seed, seq, j);
        memcpy(p + 4u * j, &w, 4);
    }
}

uint32_t selftest_check(const uint8_t *p, size_t n, uint32_t seed, uint32_t seq)
{
    uint32_t bad = 0;
    for (uint32_t j = 0; j < n / 4; j++) {
        uint32_t w;
        memcpy(&w, p + 4u * j, 4);
        bad += w != selftest_word(seed, seq, j);
    }
    return bad;
}

/* The byte of a pattern at i: not a constant, not a copy of another
 * buffer, so gcc does not turn the loops below into memset or memcpy. */
static uint8_t selftest_mem_byte(uint32_t i, uint32_t seed)
{
    return (uint8_t)((i * 131u + seed) ^ (i >> 7));
}

/* One copy (fill < 0) or fill (of fill's byte) of len bytes at offsets
 * od, os into buffers of len + 32 patterned bytes; 1 when a byte is wrong.
 * A byte at a time throughout: gcc makes no call of the functions under
 * test here. */
__attribute__((optimize("no-tree-loop-distribute-patterns")))
static int selftest_mem_case(uint8_t *dst, uint8_t *src, uint32_t len, uint32_t od, uint32_t os,
                             int fill)
{
    uint32_t span = len + 32;
    for (uint32_t i = 0; i < span; i++) {
        src[i] = selftest_mem_byte(i, 0x5Au);
        dst[i] = selftest_mem_byte(i, 0xC3u);
    }
    if (fill < 0)
        memcpy(dst + od, src + os, len);
    else
        memset(dst + od, fill, len);
    for (uint32_t i = 0; i < span; i++) {
        uint8_t want = selftest_mem_byte(i, 0xC3u);
        if (i >= od && i - od < len)
            want = fill < 0 ? selftest_mem_byte(i - od + os, 0x5Au) : (uint8_t)fill;
        if (dst[i] != want)
            return 1;
    }
    return 0;
}

/* The length after len: every one to 300, every seventh to 1,100, then
 * (long) 4,101 and SELFTEST_MEM_LONG; 0 after the last. */
static uint32_t selftest_mem_next_len(uint32_t len, int long_too)
{
    if (len < 300)
        return len + 1;
    if (len + 7 <= 1100)
        return len + 7;
    if (!long_too || len >= SELFTEST_MEM_LONG)
        return 0;
    return len < 4101 ? 4101 : SELFTEST_MEM_LONG;
}

uint32_t selftest_mem(uint8_t *scratch, uint32_t *cases, char *first, size_t cap)
{
    /* destination and source offsets: both aligned (the long ones too),
     * word-aligned apart, and not word-aligned */
    static const uint8_t offsets[][2] = {{0, 0}, {4, 0}, {0, 4}, {1, 0}, {0, 3}, {2, 2}, {7, 5}};
    static const int fills[] = {-1, 0, 0xA5}; /* a copy, then fills of 0 and of 0xA5 */
    uint8_t *src = scratch, *dst = scratch + SELFTEST_MEM_BUFFER;
    uint32_t wrong = 0;
    *cases = 0;
    first[0] = 0;
    for (uint32_t k = 0; k < sizeof offsets / sizeof offsets[0]; k++) {
        uint32_t od = offsets[k][0], os = offsets[k][1], len = 0;
        do {
            for (uint32_t f = 0; f < sizeof fills / sizeof fills[0]; f++) {
                int fill = fills[f];
                (*cases)++;
                if (selftest_mem_case(dst, src, len, od, os, fill) && !wrong++)
                    fmt_snprintf(first, cap, "%s %u bytes, offsets %u and %u",
                                 fill < 0 ? "memcpy" : "memset", (unsigned)len, (unsigned)od,
                                 (unsigned)os);
            }
            len = selftest_mem_next_len(len, k < 2);
        } while (len);
    }
    return wrong;
}

void selftest_msg_set(struct line_msg *m, uint16_t type, uint16_t len)
{
    m->type = type;
    m->len = len;
}

void selftest_stream_init(struct selftest_stream *s, uint32_t peer, int sending,
                        uint32_t msgs)
{
    s->peer = peer;
    s->sending = sending;
    s->left = msgs;
    s->seq = 0;
    s->bytes = 0;
    s->errors = 0;
}

/* The seed of the stream from core a to core b. */
static uint32_t selftest_stress_seed(uint32_t from, uint32_t to)
{
    return (from << 16) ^ to ^ 0x5EED0000u;
}

/* One step of one stream; returns 1 if a message moved. */
static int selftest_stress_step(struct selftest_stream *s, struct line_msg *m)
{
    uint32_t me = mycpu()->core;
    if (s->sending) {
        if (!line_send_ready_arm(s->peer, LINE_MAX_PAYLOAD))
            return 0;
        selftest_msg_set(m, MSG_STRESS_DATA, LINE_MAX_PAYLOAD);
        selftest_fill(m->payload, LINE_MAX_PAYLOAD, selftest_stress_seed(me, s->peer), s->seq);
        if (line_try_send(s->peer, m) != LINE_OK)
            return 0;
    } else {
        int r = line_try_recv(s->peer, m);
        if (r == LINE_ERR_EMPTY)
            return 0;
        if (r != LINE_OK || m->type != MSG_STRESS_DATA || m->len != LINE_MAX_PAYLOAD ||
            selftest_check(m->payload, m->len, selftest_stress_seed(s->peer, me), s->seq) != 0)
            s->errors++;
    }
    s->seq++;
    s->left--;
    s->bytes += LINE_MAX_PAYLOAD;
    return 1;
}

int selftest_stress_run(struct selftest_stream *s, uint32_t n)
{
    static struct line_msg msg[UNITS_MAX_CORES]; /* one scratch message per core */
    struct line_msg *m = &msg[mycpu()->core];
    uint64_t stall = ktime_ms_to_ticks(STRESS_STALL_MS);
    uint64_t last = ktime_now();
    for (;;) {
        uint32_t active = 0, moved = 0;
        for (uint32_t i = 0; i < n; i++) {
            if (!s[i].left)
                continue;
            active++;
            /* A few messages per stream per pass keeps every line busy. */
            for (int k = 0; k < 4 && s[i].left; k++) {
                if (!selftest_stress_step(&s[i], m))
                    break;
                moved++;
            }
        }
        if (!active)
            return 0;
        if (moved) {
            last = ktime_now();
            task_yield(); /* let this core's other tasks (the DM's link) run */
            continue;
        }
        uint32_t mark = task_event_mark();
        int ready = 0;
        for (uint32_t i = 0; i < n && !ready; i++) {
            if (!s[i].left)
                continue;
            ready = s[i].sending ? line_send_ready_arm(s[i].peer, LINE_MAX_PAYLOAD)
                                 : line_recv_ready_arm(s[i].peer);
        }
        if (ready)
            continue;
        if (ktime_now() - last >= stall)
            return -1;
        task_wait(mark, last + stall);
    }
}

int selftest_fault_kind_valid(uint8_t kind)
{
    return (kind >= FAULT_UNDEF && kind <= FAULT_PANIC) || kind == FAULT_INJECT_LOCK_TWICE ||
           kind == FAULT_INJECT_UNLOCK_FREE;
}

void selftest_fault_now(uint8_t kind)
{
    switch (kind) {
    case FAULT_UNDEF:
        __asm__ volatile("udf #0");
        break;
    case FAULT_DATA_ABORT:
        (void)*(volatile uint32_t *)MACHINE_UNMAPPED;
        break;
    case FAULT_PREFETCH_ABORT: {
        /* Thumb bit set so the branch itself is legal; the fetch faults. */
        void (*fn)(void) = (void (*)(void))(uintptr_t)(MACHINE_UNMAPPED | 1u);
        fn();
        break;
    }
    case FAULT_PANIC:
        panic("fault injected by the host (CMD_FAULT_INJECT)");
    case FAULT_INJECT_LOCK_TWICE: {
        struct spinlock l;
        spin_init(&l, "selftest_twice");
        spin_lock(&l);
        spin_lock(&l); /* must panic: this core holds it */
        break;
    }
    case FAULT_INJECT_UNLOCK_FREE: {
        struct spinlock l;
        spin_init(&l, "selftest_free");
        spin_unlock(&l); /* must panic: nobody holds it */
        break;
    }
    }
    panic("selftest_fault_now: kind %u did not fault", (unsigned)kind);
}

void selftest_fail_on_purpose(uint8_t kind)
{
    switch (kind) {
    case LINK_INJECT_UNDEF:
        selftest_fault_now(FAULT_UNDEF);
    case LINK_INJECT_DATA_ABORT:
        selftest_fault_now(FAULT_DATA_ABORT);
    case LINK_INJECT_HANG:
        cpu_halt_forever(); /* interrupts off, halted word not set */
    case LINK_INJECT_SILENT:
        for (;;)
            task_wait(task_event_mark(), 0);
    }
    klog("unknown failure kind %u injected: ignored", (unsigned)kind);
}

int selftest_recv_type(uint32_t peer, uint16_t type, struct line_msg *m,
                       uint64_t deadline)
{
    for (;;) {
        int r = line_recv(peer, m, deadline);
        if (r == LINE_ERR_TIMEOUT || r == LINE_ERR_NO_LINE)
            return r;
        if (r != LINE_OK) {
            klog("line from core %u: %s", (unsigned)peer, line_strerror(r));
            return r;
        }
        if (m->type == type)
            return LINE_OK;
        klog("dropped message type %u from core %u while waiting for type %u",
             (unsigned)m->type, (unsigned)peer, (unsigned)type);
    }
}

int selftest_latency(uint32_t peer, uint32_t rounds, struct line_msg *m, uint32_t *done,
                     uint32_t mmm[3])
{
    static uint32_t rtt[LINK_LATENCY_MAX_ROUNDS];
    *done = 0;
    mmm[0] = mmm[1] = mmm[2] = 0;
    if (rounds == 0 || rounds > LINK_LATENCY_MAX_ROUNDS)
        return LINE_ERR_TOO_LONG;
    for (uint32_t i = 0; i < rounds; i++) {
        uint64_t deadline = ktime_deadline_ms(PING_TIMEOUT_MS);
        selftest_msg_set(m, MSG_PING, 4);
        wire_put_u32(m->payload, 0x1A7E0000u + i);
        uint64_t t0 = ktime_now();
        int r = line_send(peer, m, deadline);
        if (r == LINE_OK)
            r = selftest_recv_type(peer, MSG_PONG, m, deadline);
        uint64_t t1 = ktime_now();
        if (r == LINE_OK && wire_get_u32(m->payload) != 0x1A7E0000u + i)
            r = LINE_ERR_CHECK;
        if (r != LINE_OK)
            return r;
        uint64_t d = t1 - t0;
        /* insertion: rtt[0..i] stays sorted */
        uint32_t v = d > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)d, j = i;
        for (; j > 0 && rtt[j - 1] > v; j--)
            rtt[j] = rtt[j - 1];
        rtt[j] = v;
        *done = i + 1;
    }
    mmm[0] = rtt[0];
    mmm[1] = rtt[rounds / 2];
    mmm[2] = rtt[rounds - 1];
    return LINE_OK;
}
