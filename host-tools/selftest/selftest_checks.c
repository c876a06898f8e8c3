/* selftest_checks.c: the command checks of `links1 selftest`: status,
 * serial-line ping, IMSU, inter-unit stress, fault injection. */
#define _GNU_SOURCE /* memmem */
#include <stdio.h>
#include <string.h>

#include "host-tools/link/board_text.h"
#include "host-tools/selftest/selftest.h"
#include "proto/wire.h"

int selftest_command(struct board *b, uint16_t cmd, const void *args, size_t len,
                     int timeout_ms, size_t min_fields, struct board_frame *r,
                     const uint8_t **fields, char *why, size_t cap)
{
    if (board_send_cmd(b, cmd, args, len) < 0) {
        snprintf(why, cap, "could not send command %u", cmd);
        return -1;
    }
    return selftest_result(b, cmd, timeout_ms, min_fields, r, fields, why, cap);
}

int selftest_result(struct board *b, uint16_t cmd, int timeout_ms, size_t min_fields,
                    struct board_frame *r, const uint8_t **fields, char *why, size_t cap)
{
    size_t n;
    return board_wait_ok(b, cmd, timeout_ms, min_fields, r, fields, &n, why, cap);
}

int selftest_status(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    (void)a;
    struct board_frame r;
    const uint8_t *f;
    if (selftest_command(b, CMD_STATUS, NULL, 0, BOARD_FRAME_TIMEOUT_MS,
                         LINK_STATUS_RESULT_SIZE, &r, &f, why, cap) < 0)
        return -1;
    struct link_status_result st;
    link_status_result_get(f, &st);
    snprintf(why, cap, "board reports %u cores, %u unit computers reported in", st.ncores,
             st.reported);
    return st.ncores == b->opts.ncores && st.reported == st.ncores ? 0 : -1;
}

int selftest_ping(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    (void)a;
    struct board_frame r;
    const uint8_t *f;
    if (selftest_command(b, CMD_LINE_PING, NULL, 0, BOARD_FRAME_TIMEOUT_MS,
                         LINK_COUNT_RESULT_SIZE, &r, &f, why, cap) < 0)
        return -1;
    /* One line DM-RC plus one RC-NC line per NC. */
    struct link_count_result c;
    link_count_result_get(f, &c);
    uint32_t want = (uint32_t)b->opts.ncores - 1;
    snprintf(why, cap, "%u of %u serial lines answered the ping", c.ok, want);
    return c.ok == want && c.total == want ? 0 : -1;
}

int selftest_latency(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    struct board_frame r;
    const uint8_t *f;
    uint8_t args[LINK_LATENCY_ARGS_SIZE];
    wire_put_u32(args, a->rounds);
    wire_put_u16(args + 4, (uint16_t)a->latency_core);
    int timeout = BOARD_FRAME_TIMEOUT_MS + (int)a->rounds * SELFTEST_LATENCY_ROUND_MS;
    if (selftest_command(b, CMD_LINE_LATENCY, args, sizeof args, timeout,
                         LINK_LATENCY_RESULT_SIZE, &r, &f, why, cap) < 0)
        return -1;
    struct link_latency_result l;
    link_latency_result_get(f, &l);
    if (l.rounds != a->rounds || l.freq == 0 || l.min > l.median || l.median > l.max) {
        snprintf(why, cap, "the board's result does not hold together: %u rounds (asked %u), "
                 "%u ticks per second, round trips min %u, median %u, max %u ticks", l.rounds,
                 a->rounds, l.freq, l.min, l.median, l.max);
        return -1;
    }
    double us = 1e6 / l.freq;
    snprintf(why, cap, "%u round trips %s<->core %d: median %.1f us (min %.1f, max %.1f; "
             "%u ticks of a %u Hz counter), one way %.1f us", l.rounds,
             a->latency_core == 1 ? "DM" : "RC", a->latency_core, l.median * us, l.min * us,
             l.max * us, l.median, l.freq, l.median * us / 2);
    return 0;
}

int selftest_imsu(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    (void)a;
    struct board_frame r;
    const uint8_t *f;
    if (selftest_command(b, CMD_IMSU_TEST, NULL, 0, BOARD_FRAME_TIMEOUT_MS,
                         LINK_COUNT_RESULT_SIZE, &r, &f, why, cap) < 0)
        return -1;
    struct link_count_result c;
    link_count_result_get(f, &c);
    snprintf(why, cap,
             "memcpy and memset right; %u of %u IMSU blocks swapped or broadcast with "
             "matching checksums",
             c.ok, c.total);
    return c.ok > 0 && c.ok == c.total ? 0 : -1;
}

int selftest_stress(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    struct board_frame r;
    const uint8_t *f;
    uint8_t arg[4];
    wire_put_u32(arg, a->stress_mib);
    int timeout = BOARD_FRAME_TIMEOUT_MS + (int)a->stress_mib * BOARD_STRESS_MS_PER_MIB;
    if (selftest_command(b, CMD_LINE_STRESS, arg, sizeof arg, timeout,
                         LINK_STRESS_RESULT_SIZE, &r, &f, why, cap) < 0)
        return -1;
    struct link_stress_result st;
    link_stress_result_get(f, &st);
    snprintf(why, cap, "%llu bytes (%.1f MiB) through the inter-unit lines, %u errors",
             (unsigned long long)st.bytes, (double)st.bytes / (1 << 20), st.errors);
    return st.bytes >= ((uint64_t)a->stress_mib << 20) && st.errors == 0 ? 0 : -1;
}

/* Waits for a FAULT frame after the first `before` faults; returns its index. */
static int selftest_wait_new_fault(struct board *b, int before, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    while (b->nfaults <= before) {
        long long left = end - board_now_ms();
        if (left <= 0 || board_pump(b, (int)left) < 0)
            return -1;
    }
    return before;
}

int selftest_fault(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    struct board_frame r;
    const uint8_t *f;
    uint8_t arg[3];
    int before = b->nfaults;
    wire_put_u16(arg, (uint16_t)a->fault_core);
    wire_put_u8(arg + 2, FAULT_UNDEF);
    if (selftest_command(b, CMD_FAULT_INJECT, arg, sizeof arg, BOARD_FRAME_TIMEOUT_MS, 0, &r,
                         &f, why, cap) < 0)
        return -1;
    int k = selftest_wait_new_fault(b, before, BOARD_FRAME_TIMEOUT_MS);
    if (k < 0 || k >= BOARD_MAX_FAULTS) {
        snprintf(why, cap, "no fault report from core %d within %d ms", a->fault_core,
                 BOARD_FRAME_TIMEOUT_MS);
        return -1;
    }
    const struct link_fault *ft = &b->faults[k];
    int want_role = a->fault_core >= ROLE_NC ? ROLE_NC : a->fault_core;
    if (ft->core != a->fault_core || ft->role != want_role || ft->kind != FAULT_UNDEF ||
        ft->addr == 0) {
        snprintf(why, cap, "fault report says core %u role %u kind %u at 0x%08x; want core "
                 "%d role %d kind %d (undefined instruction) at a non-zero address",
                 ft->core, ft->role, ft->kind, ft->addr, a->fault_core, want_role,
                 FAULT_UNDEF);
        return -1;
    }
    /* The rest of the board must still answer: status, then a ping over
     * every serial line but the faulted NC's. */
    char sub[SELFTEST_WHY_SIZE / 2];
    if (selftest_command(b, CMD_STATUS, NULL, 0, BOARD_FRAME_TIMEOUT_MS,
                         LINK_STATUS_RESULT_SIZE, &r, &f, sub, sizeof sub) < 0) {
        snprintf(why, cap, "after the fault, status failed: %s", sub);
        return -1;
    }
    int status;
    size_t n;
    if (board_send_cmd(b, CMD_LINE_PING, NULL, 0) < 0 ||
        board_wait_result(b, CMD_LINE_PING, BOARD_FRAME_TIMEOUT_MS, &r, &status, &f, &n) < 0 ||
        (status >= 0 && n < LINK_COUNT_RESULT_SIZE)) {
        snprintf(why, cap, "after the fault on core %d the board did not answer a ping",
                 a->fault_core);
        return -1;
    }
    /* Every line but the faulted NC's must answer.  The board reports that
     * either as a success with u32 lines ok, or (as a ping with a silent
     * line is an error) as error text "OK of TOTAL serial lines ...". */
    uint32_t want = (uint32_t)b->opts.ncores - 2, ok = 0;
    char counted[48];
    snprintf(counted, sizeof counted, "%u of %u ", want, want + 1);
    if (status >= 0) {
        struct link_count_result c;
        link_count_result_get(f, &c);
        ok = c.ok;
    }
    else if (memmem(f, n, counted, strlen(counted)))
        ok = want;
    if (a->fault_core < ROLE_NC || ok != want) {
        char text[BOARD_TEXT_CAP(LINK_MAX_PAYLOAD)];
        board_text(f, status < 0 ? n : 0, text, sizeof text);
        snprintf(why, cap, "core %d reported the fault at 0x%08x, then the ping answered "
                 "status %d '%s'; want %u lines (all but the faulted NC's)", a->fault_core,
                 ft->addr, status, text, want);
        return -1;
    }
    snprintf(why, cap, "core %d NC reported the undefined instruction at 0x%08x; the other "
             "%d cores still answer (%u lines ok)", a->fault_core, ft->addr,
             b->opts.ncores - 1, ok);
    return 0;
}
