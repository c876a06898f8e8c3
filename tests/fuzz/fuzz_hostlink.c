/* fuzz_hostlink.c: libFuzzer harness of the host link (proto/hostlink.c):
 * the streaming frame decoder both sides run (the DM's hostrx task and the
 * host tool), the host's handling of each decoded frame
 * (board_handle_frame: LOG, HELLO, FAULT, dropped-frame reports, the
 * queue), and the payload getters of proto/hostlink.h and
 * proto/render_link.h, each called as their users do: only on a payload
 * at least the record's size.
 *
 * Checked besides memory safety: every delivered frame re-encodes to a
 * frame a fresh decoder delivers unchanged, and every getter followed by
 * its put gives back the bytes it read (where the record has no reserved
 * or padding bytes).  The retransmission (proto/link_arq.c) sees each
 * frame too: the receiver's verdict takes seqs in order only, and each
 * frame kept for resending reads back byte for byte while it is held. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/launcher/launcher.h"
#include "proto/hostlink.h"
#include "proto/link_arq.h"
#include "proto/render_link.h"

static struct link_decoder dec;
static struct board board;

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    /* The host prints every fault it is told of; the fuzzer need not see them. */
    if (!freopen("/dev/null", "w", stdout))
        abort();
    return 0;
}

#define ROUND_TRIP(TYPE, SIZE, GET, PUT)                                                   \
    do {                                                                                   \
        if (f->length >= (SIZE)) {                                                         \
            TYPE v_;                                                                       \
            uint8_t again_[SIZE];                                                          \
            GET(f->payload, &v_);                                                          \
            PUT(again_, &v_);                                                              \
            if (exact && memcmp(again_, f->payload, (SIZE)) != 0)                          \
                abort();                                                                   \
        }                                                                                  \
    } while (0)

static void fuzz_getters(const struct link_frame *f)
{
    int exact = 1;
    ROUND_TRIP(struct link_hello, LINK_HELLO_SIZE, link_hello_get, link_hello_put);
    ROUND_TRIP(struct link_fault, LINK_FAULT_FIXED_SIZE, link_fault_get, link_fault_put);
    ROUND_TRIP(struct link_status_result, LINK_STATUS_RESULT_SIZE, link_status_result_get,
               link_status_result_put);
    ROUND_TRIP(struct link_count_result, LINK_COUNT_RESULT_SIZE, link_count_result_get,
               link_count_result_put);
    ROUND_TRIP(struct link_stress_result, LINK_STRESS_RESULT_SIZE, link_stress_result_get,
               link_stress_result_put);
    ROUND_TRIP(struct link_transfer_result, LINK_TRANSFER_RESULT_SIZE,
               link_transfer_result_get, link_transfer_result_put);
    ROUND_TRIP(struct link_scene_info, LINK_SCENE_INFO_SIZE, link_scene_info_get,
               link_scene_info_put);
    ROUND_TRIP(struct link_progress, LINK_PROGRESS_SIZE, link_progress_get, link_progress_put);
    ROUND_TRIP(struct link_render_stats, LINK_RENDER_STATS_SIZE, link_render_stats_get,
               link_render_stats_put);
    exact = 0; /* render args: bytes 6..7 are reserved, written as 0 */
    ROUND_TRIP(struct link_render_args, LINK_RENDER_ARGS_SIZE, link_render_args_get,
               link_render_args_put);
}

static void fuzz_reencode(const struct link_frame *f)
{
    static uint8_t out[LINK_MAX_FRAME];
    static struct link_decoder again;
    size_t n = link_frame_encode(out, sizeof out, f->type, f->flags, f->seq, f->payload,
                                 f->length);
    if (n != (size_t)LINK_HEADER_SIZE + f->length + LINK_CRC_SIZE)
        abort();
    link_decoder_init(&again);
    struct link_frame g;
    int got = 0;
    for (size_t i = 0; i < n; i++)
        if (link_decoder_push(&again, out[i], &g)) {
            if (i != n - 1 || got)
                abort();
            got = 1;
        }
    if (!got || g.type != f->type || g.flags != f->flags || g.seq != f->seq ||
        g.length != f->length || memcmp(g.payload, f->payload, f->length) != 0)
        abort();
}

static struct link_arq_store store;
static struct link_arq_rx rx;

/* The frame as the retransmission sees it: the verdict, and a copy kept. */
static void fuzz_arq(const struct link_frame *f)
{
    uint16_t expect = rx.expect;
    int known = rx.known;
    enum link_arq_verdict v = link_arq_rx_take(&rx, f);
    if (v == LINK_ARQ_NEW && known && !(f->flags & LINK_FLAG_SESSION) && f->seq != expect)
        abort(); /* taken out of order */
    if (v != LINK_ARQ_NEW && rx.expect != expect)
        abort();
    static uint8_t out[LINK_MAX_FRAME], back[LINK_MAX_FRAME];
    uint16_t seq = store.next_seq;
    size_t n = link_arq_store_frame(&store, out, sizeof out, f->type, f->flags, f->payload,
                                    f->length);
    if (n == 0 || link_arq_store_get(&store, seq, back, sizeof back) != n ||
        memcmp(out, back, n) != 0 || link_arq_store_span(&store, seq) != 1)
        abort();
    int span = link_arq_store_span(&store, f->seq);
    if (span > 0 && link_arq_store_resend_count(&store, f->seq, span) < 1)
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    link_arq_store_init(&store, size > 1 ? (uint16_t)(data[1] << 8) : 0);
    link_arq_rx_init(&rx);
    link_decoder_init(&dec);
    memset(&board, 0, sizeof board);
    board_opts_init(&board.opts);
    board.opts.quiet = 1;
    board.opts.ncores = size ? 3 + data[0] % 64 : 3;
    for (size_t i = 0; i < size; i++) {
        struct link_frame f;
        if (!link_decoder_push(&dec, data[i], &f))
            continue;
        if (f.length > LINK_MAX_PAYLOAD)
            abort();
        fuzz_reencode(&f);
        fuzz_getters(&f);
        fuzz_arq(&f);
        if (board_handle_frame(&board, &f) != 0)
            board.queued = 0; /* the queue is full: the host gives up; start again */
    }
    return 0;
}
