/* arq_bench_main.c: build/bench-link-arq, the host link's stop-and-wait
 * retransmission (proto/link_arq.h) through --link-noise's damage
 * (host-tools/link_noise.h), simulated (host-tools/link_arq_sim.h): for each
 * noise rate from 1e-5 to 1e-2 and each DATA frame size, how many runs
 * delivered everything bit-exact, how many gave up (an error, never wrong
 * data), and the median goodput: payload bytes taken per byte on the line. */
#include <stdio.h>
#include <stdlib.h>

#include "host-tools/link_arq_sim.h"

#define BENCH_SEEDS 9
#define BENCH_BYTES (256u * 1024u)

static int bench_cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(void)
{
    static const double rates[] = {1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2};
    static const unsigned sizes[] = {1024, 256, 64};
    int wrong = 0;
    printf("%-8s %6s %8s %8s %8s %10s\n", "rate", "frame", "exact", "gave_up", "goodput",
           "resends/fr");
    for (size_t i = 0; i < sizeof rates / sizeof rates[0]; i++) {
        for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
            double good[BENCH_SEEDS], resend = 0;
            int exact = 0, gave_up = 0;
            unsigned msgs = BENCH_BYTES / sizes[k];
            for (int s = 0; s < BENCH_SEEDS; s++) {
                struct link_arq_sim_result r =
                    link_arq_sim_run(rates[i], (uint64_t)s + 1, msgs, sizes[k], 0);
                wrong += !r.exact_prefix;
                exact += r.completed && r.exact_prefix;
                gave_up += !r.completed;
                good[s] = r.wire_bytes ? (double)r.taken_bytes / (double)r.wire_bytes : 0;
                resend += (double)r.resends / msgs;
            }
            qsort(good, BENCH_SEEDS, sizeof good[0], bench_cmp);
            printf("%-8.0e %6u %5d/%-2d %5d/%-2d %8.3f %10.3f\n", rates[i], sizes[k], exact,
                   BENCH_SEEDS, gave_up, BENCH_SEEDS, good[BENCH_SEEDS / 2],
                   resend / BENCH_SEEDS);
        }
    }
    printf("runs that delivered wrong data: %d\n", wrong);
    return wrong ? 1 : 0;
}
