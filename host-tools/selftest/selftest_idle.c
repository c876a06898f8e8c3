/* selftest_idle.c: `links1 selftest idle`: after report-in every unit
 * computer is idle and must sleep, so each core retires (almost) no guest
 * instructions.
 *
 * The counting plugin (insn_count_plugin.c) appends a line of every core's
 * count every SELFTEST_IDLE_SAMPLE_MS while the board runs; the check takes
 * the lines at the start and end of an idle span and divides each core's
 * difference by the span.  A count of guest instructions does not depend
 * on how busy the host is: a core asleep in WFI retires nothing however fast
 * or slow QEMU runs, while a core that spins retires millions per second
 * even on a loaded host. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/selftest/selftest.h"

void selftest_idle_prepare(struct board_opts *o, const char *path)
{
    o->insn_series_out = path;
    o->insn_series_ms = SELFTEST_IDLE_SAMPLE_MS;
}

/* One line of the series: its time and every core's count. */
struct idle_sample {
    long long at_ms;
    uint64_t count[UNITS_MAX_CORES];
};

/* Parses "at T C0 ... CN-1"; 0, or -1 for a line that is not whole. */
static int idle_parse(const char *line, int ncores, struct idle_sample *s)
{
    char *end;
    if (strncmp(line, "at ", 3) != 0)
        return -1;
    s->at_ms = strtoll(line + 3, &end, 10);
    for (int k = 0; k < ncores; k++) {
        const char *p = end;
        s->count[k] = strtoull(p, &end, 10);
        if (end == p)
            return -1;
    }
    return *end == '\n' ? 0 : -1;
}

/* Reads the series file: *first the first sample at or after from_ms, *last
 * the first at or after to_ms.  Returns 1 when both were found, 0 when the
 * file has not got that far yet, -1 when it cannot be read. */
static int idle_find(const char *path, int ncores, long long from_ms, long long to_ms,
                     struct idle_sample *first, struct idle_sample *last)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char *line = NULL;
    size_t cap = 0;
    int have_first = 0, found = 0;
    static struct idle_sample s;
    while (!found && getline(&line, &cap, f) > 0) {
        if (idle_parse(line, ncores, &s) < 0)
            continue;
        if (!have_first && s.at_ms >= from_ms) {
            *first = s;
            have_first = 1;
        }
        if (have_first && s.at_ms >= to_ms) {
            *last = s;
            found = 1;
        }
    }
    free(line);
    fclose(f);
    return found;
}

int selftest_idle(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    const char *path = b->opts.insn_series_out;
    if (!path) {
        snprintf(why, cap, "the board was started without the instruction series");
        return -1;
    }
    long long t0 = board_now_ms() + SELFTEST_IDLE_SETTLE_MS;
    long long t1 = t0 + SELFTEST_IDLE_SECONDS * 1000;
    long long give_up = t1 + SELFTEST_IDLE_LATE_MS;
    static struct idle_sample s0, s1;
    int r = 0;
    while (r == 0) {
        /* Keep reading the link (logs, faults) meanwhile; send nothing. */
        if (board_pump(b, SELFTEST_IDLE_SAMPLE_MS) < 0) {
            snprintf(why, cap, "the board stopped during the idle span");
            return -1;
        }
        if (board_now_ms() < t1)
            continue;
        r = idle_find(path, b->opts.ncores, t0, t1, &s0, &s1);
        if (r == 0 && board_now_ms() > give_up) {
            snprintf(why, cap, "the counting plugin wrote no sample after the idle span "
                     "in %d ms (%s)", SELFTEST_IDLE_LATE_MS, path);
            return -1;
        }
    }
    if (r < 0) {
        snprintf(why, cap, "cannot read the instruction series %s: %s", path, strerror(errno));
        return -1;
    }
    double span_s = (double)(s1.at_ms - s0.at_ms) / 1000.0;
    if (span_s < SELFTEST_IDLE_SECONDS / 2.0) {
        snprintf(why, cap, "the samples span only %.2f s", span_s);
        return -1;
    }
    /* Every core ran its boot: a count of 0 means the counts are not real. */
    for (int k = 0; k < b->opts.ncores; k++) {
        if (s1.count[k] == 0) {
            snprintf(why, cap, "core %d has counted no instruction since boot: the "
                     "counting plugin's samples are not the board's", k);
            return -1;
        }
    }
    int worst = 0, busy = 0;
    double worst_rate = -1, total = 0;
    for (int k = 0; k < b->opts.ncores; k++) {
        /* A count below the first means the core ran the count-from-here
         * marker: all of the second was retired in the span. */
        uint64_t d = s1.count[k] >= s0.count[k] ? s1.count[k] - s0.count[k] : s1.count[k];
        double rate = (double)d / span_s;
        total += (double)d;
        if (rate > worst_rate) {
            worst_rate = rate;
            worst = k;
        }
        busy += rate > a->max_insns;
    }
    snprintf(why, cap, "%d idle cores retired %.0f guest instructions in %.1f s (%.0f "
             "since boot on core %d); most core %d %s: %.0f per second (limit %u)%s",
             b->opts.ncores, total, span_s, (double)s1.count[b->opts.ncores - 1],
             b->opts.ncores - 1, worst, board_role_name(worst), worst_rate, a->max_insns,
             busy ? "; a core that should sleep keeps running" : "");
    if (busy)
        snprintf(why + strlen(why), cap - strlen(why), " (%d cores over the limit)", busy);
    return busy ? -1 : 0;
}
