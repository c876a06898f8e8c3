/* selftest.h: the board checks behind `links1 selftest`.  Each runs on a
 * board whose unit computers have all reported in, writes a one-line verdict
 * (what it saw, or why it failed) into why, and returns 0 or -1. */
#ifndef LINKS1_HOST_SELFTEST_H
#define LINKS1_HOST_SELFTEST_H

#include <stddef.h>
#include <stdint.h>

#include "host-tools/board.h"

struct selftest_args {
    uint32_t stress_mib;  /* stress: MiB through the inter-unit lines */
    uint32_t link_bytes;  /* link-sink / link-source: bytes each way */
    uint32_t max_insns;   /* idle: most instructions per second an idle core
                             may retire */
    int fault_core;       /* fault: the core that executes the fault */
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
 * series: sets o to write it to a new temporary file named in path (the
 * caller unlinks it).  Returns 0, or -1 after printing why. */
int selftest_idle_prepare(struct board_opts *o, char *path, size_t cap);

selftest_fn selftest_status, selftest_ping, selftest_imsu, selftest_stress,
    selftest_link_sink, selftest_link_source, selftest_fault, selftest_idle;

#endif
