/* board_frames.c: what the host does with each frame from the board: LOG
 * text printed, HELLO (report-in) checked and recorded, FAULT printed and
 * recorded, everything else queued for board_wait_frame (see board.h). */
#include <stdio.h>
#include <string.h>

#include "host-tools/link/board.h"
#include "host-tools/link/board_text.h"
#include "proto/wire.h"

static void board_print_log(const uint8_t *p, size_t n)
{
    /* One output line per board line, so board text never runs into ours;
     * its control characters escaped (board_text.h). */
    static char text[BOARD_TEXT_CAP(LINK_MAX_PAYLOAD)];
    size_t start = 0;
    for (size_t i = 0; i <= n; i++) {
        if (i == n || p[i] == '\n') {
            if (i > start || i < n)
                printf("board: %s\n", board_text(p + start, i - start, text, sizeof text));
            start = i + 1;
        }
    }
}

static void board_on_hello(struct board *b, const struct link_frame *f)
{
    struct link_hello h;
    if (f->length < LINK_HELLO_SIZE) {
        fprintf(stderr, "links1: HELLO frame of %u bytes, want %d\n", f->length,
                LINK_HELLO_SIZE);
        b->hello_errors++;
        return;
    }
    link_hello_get(f->payload, &h);
    int expect_role = h.core >= ROLE_NC ? ROLE_NC : h.core;
    const char *problem = NULL;
    char why[160];
    if (h.core >= b->opts.ncores) {
        snprintf(why, sizeof why, "core number out of range (board has %d cores)",
                 b->opts.ncores);
        problem = why;
    } else if (h.role != expect_role) {
        snprintf(why, sizeof why, "role %u, want %d (%s)", h.role, expect_role,
                 board_role_name(h.core));
        problem = why;
    } else if (h.ncores != b->opts.ncores) {
        snprintf(why, sizeof why, "says the board has %u cores, QEMU was given %d",
                 h.ncores, b->opts.ncores);
        problem = why;
    } else if (h.variant != board_arith_code(b->opts.arith)) {
        snprintf(why, sizeof why, "runs arithmetic variant %u, want %d (%s)", h.variant,
                 board_arith_code(b->opts.arith), b->opts.arith);
        problem = why;
    } else if (b->reported[h.core]) {
        problem = "reported in twice";
    }
    if (problem) {
        fprintf(stderr, "links1: bad report-in from core %u: %s\n", h.core, problem);
        b->hello_errors++;
        return;
    }
    b->reported[h.core] = 1;
    b->reported_count++;
    if (b->opts.verbose)
        printf("core %u %s reported in (mpidr 0x%08x)\n", h.core, board_role_name(h.core),
               h.mpidr);
}

static const char *board_fault_kind_name(unsigned kind)
{
    switch (kind) {
    case FAULT_UNDEF: return "undefined instruction";
    case FAULT_PREFETCH_ABORT: return "prefetch abort";
    case FAULT_DATA_ABORT: return "data abort";
    case FAULT_PANIC: return "panic";
    default: return "unknown fault kind";
    }
}

static void board_on_fault(struct board *b, const struct link_frame *f)
{
    struct link_fault ft;
    if (f->length < LINK_FAULT_FIXED_SIZE) {
        fprintf(stderr, "links1: FAULT frame of %u bytes, want at least %d\n", f->length,
                LINK_FAULT_FIXED_SIZE);
        memset(&ft, 0, sizeof ft);
        ft.core = UINT16_MAX;
    } else {
        link_fault_get(f->payload, &ft);
    }
    int textlen = f->length > LINK_FAULT_FIXED_SIZE ? f->length - LINK_FAULT_FIXED_SIZE : 0;
    static char text[BOARD_TEXT_CAP(LINK_MAX_PAYLOAD)];
    board_text(f->payload + LINK_FAULT_FIXED_SIZE, (size_t)textlen, text, sizeof text);
    if (b->nfaults < BOARD_MAX_FAULTS) {
        b->faults[b->nfaults] = ft;
        board_text(f->payload + LINK_FAULT_FIXED_SIZE, (size_t)textlen,
                   b->fault_text[b->nfaults], BOARD_FAULT_TEXT);
    }
    b->nfaults++;
    printf("core %u %s FAULT: %s at 0x%08x (pc 0x%08x, status 0x%08x)%s%s\n", ft.core,
           unit_role_name(ft.role),
           board_fault_kind_name(ft.kind), ft.addr, ft.pc, ft.status, textlen ? ": " : "", text);
}

int board_handle_frame(struct board *b, const struct link_frame *f)
{
    switch (f->type) {
    case LINK_LOG:
        if (!b->opts.quiet)
            board_print_log(f->payload, f->length);
        return 0;
    case LINK_HELLO:
        board_on_hello(b, f);
        return 0;
    case LINK_FAULT:
        board_on_fault(b, f);
        return 0;
    default:
        break;
    }
    if (f->type == LINK_RESULT && f->length >= LINK_RESULT_FIXED_SIZE &&
        wire_get_u16(f->payload) == 0) {
        /* Not an answer: the board reports at once a frame from us it had to
         * drop (cmd 0, LINK_ERR_BAD_FRAME). */
        b->host_frames_dropped++;
        b->host_drop_status = (int16_t)wire_get_u16(f->payload + 2);
        board_text(f->payload + LINK_RESULT_FIXED_SIZE, f->length - LINK_RESULT_FIXED_SIZE,
                   b->host_drop_text, sizeof b->host_drop_text);
        fprintf(stderr, "links1: the board dropped a frame from the host (status %d, %s): "
                "%s\n", b->host_drop_status, board_status_name(b->host_drop_status),
                b->host_drop_text);
        return 0;
    }
    if (b->queued >= BOARD_FRAME_QUEUE) {
        fprintf(stderr, "links1: %d frames from the board wait unread (frame type %u "
                "arrived): more than a transfer window, the board is not waiting for ACKs\n",
                BOARD_FRAME_QUEUE, f->type);
        return -1;
    }
    struct board_frame *q = &b->queue[b->queued++];
    q->type = f->type;
    q->flags = f->flags;
    q->seq = f->seq;
    q->length = f->length;
    memcpy(q->payload, f->payload, f->length);
    return 0;
}

const char *board_status_name(int status)
{
    switch (status) {
    case LINK_OK: return "ok";
    case LINK_ERR_UNKNOWN_CMD: return "unknown command";
    case LINK_ERR_BAD_ARGS: return "bad arguments";
    case LINK_ERR_BAD_FRAME: return "dropped frame";
    case LINK_ERR_TIMEOUT: return "timeout";
    case LINK_ERR_CHECK: return "check failed";
    case LINK_ERR_PROTOCOL: return "protocol error";
    default: return "unknown status";
    }
}
