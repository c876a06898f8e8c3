/* selftest.h: the board checks behind `links1 selftest`.  Each runs on a
 * board whose unit computers have all reported in, writes a one-line verdict
 * (what it saw, or why it failed) into why, and returns 0 or -1. */
#ifndef LINKS1_HOST_SELFTEST_H
#define LINKS1_HOST_SELFTEST_H

#include <stddef.h>
#include <stdint.h>

#include "host-tools/link/board.h"

/* Long commands (the inter-unit stress run) get this many ms per MiB. */
#define BOARD_STRESS_MS_PER_MIB 4000
/* Link tests: bytes each way through the host link, MiB through the
 * inter-unit lines (issue minimums: 8 MiB and 64 MiB). */
#define SELFTEST_LINK_BYTES (8u << 20)
#define SELFTEST_STRESS_MIB 64u
/* Most a selftest run accepts, so a typo cannot start an hours-long run. */
#define SELFTEST_MAX_STRESS_MIB 4096u
#define SELFTEST_MAX_LINK_BYTES (1024u << 20)
/* Checks named in one selftest run, and the size of a check's one-line verdict. */
#define SELFTEST_MAX_RUN 16
#define SELFTEST_WHY_SIZE 512
/* Idle test: settle after report-in, then count each core's guest
 * instructions over a span (samples from the counting plugin every
 * SAMPLE_MS; the sample after the span may come this much LATE at most).
 * An idle core sleeps in WFI and retires nothing; a spinning one retires
 * millions per second even on a loaded host. */
#define SELFTEST_IDLE_SETTLE_MS 1000
#define SELFTEST_IDLE_SECONDS 5
#define SELFTEST_IDLE_SAMPLE_MS 200
#define SELFTEST_IDLE_LATE_MS 20000
#define SELFTEST_IDLE_MAX_INSNS 10000u /* per idle core per second */
#define SELFTEST_MAX_IDLE_INSNS 1000000000u /* most --max-insns accepts */
/* Latency: round trips timed by default, and the default far end (the
 * first NC: on the an521 boards, on board 1, another process). */
#define SELFTEST_LATENCY_ROUNDS 200u
#define SELFTEST_LATENCY_ROUND_MS 2000 /* the host's wait, per round */

struct selftest_args {
    uint32_t stress_mib;  /* stress: MiB through the inter-unit lines */
    uint32_t link_bytes;  /* link-sink / link-source: bytes each way */
    uint32_t max_insns;   /* idle: most instructions per second an idle core
                             may retire */
    int fault_core;       /* fault: the core that executes the fault */
    uint32_t rounds;      /* latency: round trips timed */
    int latency_core;     /* latency: the line's far end (1: DM<->RC; an NC: RC<->NC) */
};

typedef int selftest_fn(struct board *b, const struct selftest_args *a, char *why,
                        size_t cap);

struct selftest {
    const char *name;
    const char *help;
    selftest_fn *fn;
};

/* Sends cmd with args, waits up to timeout_ms for its result and needs at
 * least min_fields result bytes.  A negative status fails with the board's
 * text in why.  On success *r holds the frame, *fields points into it. */
int selftest_command(struct board *b, uint16_t cmd, const void *args, size_t len,
                     int timeout_ms, size_t min_fields, struct board_frame *r,
                     const uint8_t **fields, char *why, size_t cap);

/* The waiting half of selftest_command, for a command already sent (the
 * bulk transfers move their data between the command and its result). */
int selftest_result(struct board *b, uint16_t cmd, int timeout_ms, size_t min_fields,
                    struct board_frame *r, const uint8_t **fields, char *why, size_t cap);

/* The idle check needs the board started with the counting plugin's
 * series: sets o to write it to path, a name in a private directory of
 * the caller's that the plugin makes new (the caller removes it). */
void selftest_idle_prepare(struct board_opts *o, const char *path);

selftest_fn selftest_status, selftest_ping, selftest_imsu, selftest_stress,
    selftest_link_sink, selftest_link_source, selftest_fault, selftest_idle,
    selftest_latency;

#endif
