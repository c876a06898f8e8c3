/* board.c: one link session with a board: frames in and out, the
 * go-back-N retransmission, the queue of frames waiting to be taken (see
 * board.h).  It knows nothing of QEMU: the launcher (host-tools/launcher/)
 * starts the process, hands the session its end of the UART and says what
 * happened to the process when the link ends (board.process_gone). */
#include "host-tools/link/board.h"
#include "host-tools/link/board_arq.h"
#include "host-tools/link/board_text.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "proto/arith.h"
#include "proto/wire.h"

long long board_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

const char *board_role_name(int core)
{
    return unit_role_name(unit_role_of_core((uint32_t)core));
}

int board_arith_code(const char *arith)
{
    int a = arith_from_name(arith);
    return arith_on_board(a) ? a : -1;
}

int board_session_init(struct board *b, const struct board_opts *o)
{
    /* A write to a link whose far end is gone (QEMU exited, a named board
     * stopped) must fail with EPIPE and a message, not kill the tool
     * silently with its temporary files left behind. */
    signal(SIGPIPE, SIG_IGN);
    memset(b, 0, sizeof *b);
    b->opts = *o;
    b->fd = -1;
    b->ram_fd = -1;
    b->lock_fd = -1;
    b->state_fd = -1;
    b->started_ms = board_now_ms();
    link_decoder_init(&b->dec);
    b->arq = calloc(1, sizeof *b->arq);
    if (!b->arq) {
        fprintf(stderr, "links1: no memory for the link's retransmission state\n");
        return -1;
    }
    /* We number our frames from 0; the board's numbering is learnt from its
     * first frame, except on a board we boot (board_session_peer_from_zero). */
    link_arq_store_init(&b->arq->tx, 0);
    link_arq_rx_init(&b->arq->rx);
    b->arq->heard_ms = b->arq->byte_ms = b->started_ms;
    b->arq->naks_heard = 1;
    return 0;
}

void board_session_open(struct board *b, int fd)
{
    b->fd = fd;
    fcntl(b->fd, F_SETFL, fcntl(b->fd, F_GETFL) | O_NONBLOCK);
}

void board_session_peer_from_zero(struct board *b)
{
    b->arq->rx.known = 1;
}

void board_session_naks_ours(struct board *b, int ours)
{
    b->arq->naks_heard = ours;
}

int board_attach(struct board *b, const struct board_opts *o, int fd)
{
    if (board_session_init(b, o) < 0)
        return -1;
    board_session_open(b, fd);
    return 0;
}

void board_session_drain(struct board *b, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    b->stopping = 1;
    while (b->fd >= 0 && board_now_ms() < end) {
        if (board_pump(b, (int)(end - board_now_ms())) < 0)
            break;
        b->queued = 0; /* nothing waits for these any more */
    }
}

void board_session_close(struct board *b)
{
    if (b->fd >= 0)
        close(b->fd);
    b->fd = -1;
    free(b->arq);
    b->arq = NULL;
}

uint32_t board_session_adopt(struct board *b)
{
    const struct link_stats *s = &b->dec.stats;
    uint32_t cut = s->crc_errors + s->bad_length + s->junk_bytes + b->host_frames_dropped;
    memset(&b->dec.stats, 0, sizeof b->dec.stats);
    b->host_frames_dropped = 0;
    b->queued = 0;
    for (int k = 0; k < b->opts.ncores && k < UNITS_MAX_CORES; k++)
        b->reported[k] = 1;
    b->reported_count = b->opts.ncores;
    return cut;
}

int board_queued(const struct board *b)
{
    return b->queued;
}

int board_take_queued(struct board *b, uint32_t mask, struct board_frame *out)
{
    for (int i = 0; i < b->queued; i++) {
        if (b->queue[i].type >= 32 || !(mask & (1u << b->queue[i].type)))
            continue;
        *out = b->queue[i];
        memmove(&b->queue[i], &b->queue[i + 1], (size_t)(b->queued - i - 1) * sizeof b->queue[0]);
        b->queued--;
        return 1;
    }
    return 0;
}

/* ------------------------------------------------------- incoming frames */

/* The socket reached end-of-file or failed: the board is gone. */
static int board_lost(struct board *b, const char *why)
{
    char desc[192];
    if (b->fd >= 0) {
        close(b->fd);
        b->fd = -1;
    }
    if (b->stopping)
        return -1; /* the shutdown we asked for */
    if (b->process_gone)
        b->process_gone(b, desc, sizeof desc);
    else
        snprintf(desc, sizeof desc, "the other end closed the link");
    fprintf(stderr, "links1: the board stopped talking (%s): %s\n", why, desc);
    return -1;
}

/* 1 (after saying so) when the session's link is closed: nothing can be
 * sent any more. */
static int board_closed(const struct board *b)
{
    if (b->arq && b->fd >= 0)
        return 0;
    fprintf(stderr, "links1: the board's link is closed\n");
    return 1;
}

/* ---- the retransmission (proto/link_arq.h, go-back-N) ---- */

static int board_write_all(struct board *b, const uint8_t *p, size_t n, int timeout_ms);

/* The retransmission gives up: every wait from now on fails. */
static int board_arq_give_up(struct board *b, const char *why)
{
    if (!b->link_failed)
        fprintf(stderr, "links1: the host link gave up: %s (noise on the link: %u bad CRC, "
                "%u bad length, %u junk bytes from the board; %u frames from the host "
                "dropped by the board)\n", why, b->dec.stats.crc_errors,
                b->dec.stats.bad_length, b->dec.stats.junk_bytes, b->host_frames_dropped);
    b->link_failed = 1;
    return -1;
}

/* A NAK asked for while a frame is being written (the write reads the board
 * meanwhile) goes out after it, never inside it (board_write_all). */
static int board_send_nak(struct board *b, uint8_t flags)
{
    if (b->arq->writing) {
        b->arq->nak_due = 1;
        b->arq->nak_flags = flags;
        return 0;
    }
    uint8_t f[LINK_HEADER_SIZE + LINK_ACK_SIZE + LINK_CRC_SIZE];
    size_t n = link_arq_nak_encode(f, sizeof f, flags, b->arq->rx.expect);
    return board_write_all(b, f, n, BOARD_FRAME_TIMEOUT_MS);
}

/* The board's frame we expect was lost (a gap, a damaged frame): ask for it,
 * at most once per LINK_ARQ_NAK_MS, and give up after LINK_ARQ_MAX_ASKS
 * asks in a row. */
static int board_arq_lost(struct board *b)
{
    b->arq->armed = b->arq->damage_seen = b->arq->gap = 1;
    if (!b->arq->rx.known)
        return 0; /* the board's numbering is not known yet: nothing to name */
    if (!link_arq_nak_due(&b->arq->nak, b->arq->rx.expect, (uint64_t)board_now_ms(),
                          LINK_ARQ_NAK_MS))
        return 0;
    if (b->arq->nak.tries > LINK_ARQ_MAX_ASKS) {
        char why[96];
        snprintf(why, sizeof why, "frame %u from the board did not come through whole after "
                 "%d requests", b->arq->rx.expect, LINK_ARQ_MAX_ASKS);
        return board_arq_give_up(b, why);
    }
    return board_send_nak(b, 0);
}

static int board_arq_resend(struct board *b, uint16_t from);

/* A LINK_NAK from the board: our frames from the seq it names, sent again.
 * One naming our next frame says the board lacks nothing of ours (its
 * answer to a poll, or to the junk of our poll's zero bytes): the link is
 * back in step when it answers our poll and we lack nothing either, and
 * polling stops. */
static int board_arq_nak_in(struct board *b, const struct link_frame *f, int polled)
{
    if (f->length < LINK_ACK_SIZE || !b->arq->naks_heard) {
        b->arq->armed = 1;
        return 0;
    }
    uint16_t from = wire_get_u16(f->payload);
    if (!(f->flags & LINK_FLAG_GONE) && from == b->arq->tx.next_seq && !b->arq->writing) {
        /* (the decoder still holds this frame: bytes past it are partial) */
        if (polled && !b->arq->gap && b->dec.have <= b->dec.delivered)
            b->arq->armed = 0;
        return 0;
    }
    b->arq->armed = b->arq->damage_seen = 1;
    char why[96];
    if (f->flags & LINK_FLAG_GONE) {
        snprintf(why, sizeof why, "the board no longer holds its frame %u that we asked for",
                 from);
        return board_arq_give_up(b, why);
    }
    if (b->arq->writing) { /* resent after the frame being written */
        b->arq->resend_due = 1;
        b->arq->resend_from = from;
        return 0;
    }
    return board_arq_resend(b, from);
}

/* Our kept frames from seq from on, sent again (up to LINK_ARQ_RESEND_BYTES). */
static int board_arq_resend(struct board *b, uint16_t from)
{
    char why[96];
    int span = link_arq_store_span(&b->arq->tx, from);
    if (span > 0) {
        b->arq->asked = b->arq->asked && b->arq->asked_from == from ? b->arq->asked + 1 : 1;
        b->arq->asked_from = from;
        if (b->arq->asked > LINK_ARQ_MAX_ASKS) {
            snprintf(why, sizeof why, "our frame %u did not reach the board whole after %d "
                     "resends", from, LINK_ARQ_MAX_ASKS);
            return board_arq_give_up(b, why);
        }
    }
    if (span < 0) {
        snprintf(why, sizeof why, "the board asked for our frame %u, no longer held", from);
        board_send_nak(b, LINK_FLAG_GONE);
        return board_arq_give_up(b, why);
    }
    span = link_arq_store_resend_count(&b->arq->tx, from, span);
    for (int i = 0; i < span; i++) {
        uint8_t frame[LINK_MAX_FRAME];
        size_t n = link_arq_store_get(&b->arq->tx, (uint16_t)(from + i), frame, sizeof frame);
        if (board_write_all(b, frame, n, BOARD_FRAME_TIMEOUT_MS) < 0)
            return -1;
        b->frames_resent++;
    }
    return 0;
}

/* A good frame from the board: NAKs answered, numbered frames handled in
 * seq order only, each once. */
static int board_arq_frame(struct board *b, const struct link_frame *f)
{
    int polled = b->arq->polls > 0;
    b->arq->heard_ms = board_now_ms();
    b->arq->polls = 0;
    if (f->type == LINK_NAK)
        return board_arq_nak_in(b, f, polled);
    switch (link_arq_rx_take(&b->arq->rx, f)) {
    case LINK_ARQ_NEW:
        b->arq->gap = 0;
        return board_handle_frame(b, f);
    case LINK_ARQ_DUP:
        b->frames_dropped_dup++;
        return 0;
    default:
        return board_arq_lost(b);
    }
}

/* Nothing heard for LINK_ARQ_POLL_MS on a link seen damaged: our partial
 * frame is given up, the board's is completed by LINK_ARQ_FLUSH_BYTES zero
 * bytes, and a poll asks the board to send again what we lack and to name
 * what it lacks. */
static int board_arq_poll(struct board *b)
{
    struct link_frame f;
    while (b->dec.have) {
        if (link_decoder_unstick(&b->dec, &f) && board_arq_frame(b, &f) < 0)
            return -1;
    }
    b->arq->heard_ms = board_now_ms();
    if (!b->arq->rx.known)
        return 0; /* the first good frame sets the numbering */
    if (++b->arq->polls > LINK_ARQ_MAX_TRIES) {
        char why[96];
        snprintf(why, sizeof why, "%d polls over %d s brought no frame from the board",
                 LINK_ARQ_MAX_TRIES, LINK_ARQ_MAX_TRIES * LINK_ARQ_POLL_MS / 1000);
        return board_arq_give_up(b, why);
    }
    static const uint8_t zeros[LINK_ARQ_FLUSH_BYTES];
    if (board_write_all(b, zeros, sizeof zeros, BOARD_FRAME_TIMEOUT_MS) < 0)
        return -1;
    return board_send_nak(b, LINK_FLAG_POLL);
}

int board_arq_failed(const struct board *b)
{
    return b->link_failed;
}

/* Reads what is available now and handles every completed frame. */
static int board_read_available(struct board *b)
{
    uint8_t buf[BOARD_READ_CHUNK];
    for (;;) {
        ssize_t n = read(b->fd, buf, sizeof buf);
        if (n == 0)
            return board_lost(b, "end of the UART socket");
        if (n < 0) {
            if (errno == EINTR)
                continue;
            if (errno == EAGAIN || errno == EWOULDBLOCK)
                return 0;
            return board_lost(b, strerror(errno));
        }
        b->arq->byte_ms = board_now_ms();
        for (ssize_t i = 0; i < n; i++) {
            struct link_frame f;
            const struct link_stats *s = &b->dec.stats;
            uint32_t damaged = s->crc_errors + s->bad_length, junk = s->junk_bytes;
            int got = link_decoder_push(&b->dec, buf[i], &f);
            if (s->crc_errors + s->bad_length != damaged && board_arq_lost(b) < 0)
                return -1;
            if (s->junk_bytes != junk)
                b->arq->armed = b->arq->damage_seen = 1;
            if (got && board_arq_frame(b, &f) < 0)
                return -1;
        }
        fflush(stdout);
        if ((size_t)n < sizeof buf)
            return 0; /* drained: no need for a read that says EAGAIN */
    }
}

/* How long a partial frame may wait for its next byte before it counts as
 * damage: long on a link never seen damaged. */
static long long board_arq_stall_ms(const struct board *b)
{
    return b->arq->damage_seen ? LINK_ARQ_STALL_MS : LINK_ARQ_STALL_CLEAN_MS;
}

int board_pump(struct board *b, int timeout_ms)
{
    if (b->fd < 0 || b->link_failed)
        return -1;
    int wait = timeout_ms < 0 ? 0 : timeout_ms;
    if (b->arq->armed || b->dec.have) {
        long long due = b->arq->armed ? b->arq->heard_ms + LINK_ARQ_POLL_MS
                                     : b->arq->byte_ms + board_arq_stall_ms(b);
        due -= board_now_ms();
        if (due < wait)
            wait = due < 0 ? 0 : (int)due;
    }
    struct pollfd p = {.fd = b->fd, .events = POLLIN};
    int r = poll(&p, 1, wait);
    if (r < 0 && errno != EINTR) {
        fprintf(stderr, "links1: poll: %s\n", strerror(errno));
        return -1;
    }
    if (r > 0) {
        /* QEMU writes the UART to the socket one byte at a time; a short
         * pause lets a batch gather, so a fast stream costs one read per
         * batch instead of a wake-up per byte (host CPU QEMU needs). */
        struct timespec batch = {0, BOARD_READ_BATCH_US * 1000L};
        nanosleep(&batch, NULL);
        if (board_read_available(b) < 0)
            return -1;
    }
    /* A partial frame that waits long for its bytes is damage no frame
     * showed (its length field spoilt): the link is then polled too. */
    long long quiet = board_now_ms() - b->arq->heard_ms;
    if (!b->arq->armed && b->dec.have && board_now_ms() - b->arq->byte_ms >= board_arq_stall_ms(b))
        b->arq->armed = 1;
    if (b->arq->armed && quiet >= LINK_ARQ_POLL_MS && board_arq_poll(b) < 0)
        return -1;
    return 0;
}

static void board_print_missing(const struct board *b)
{
    fprintf(stderr, "links1: %d of %d unit computers did not report in:",
            b->opts.ncores - b->reported_count, b->opts.ncores);
    const char *sep = "";
    for (int k = 0; k < b->opts.ncores; k++) {
        if (b->reported[k])
            continue;
        /* A run of silent cores, never spanning two roles. */
        int e = k;
        while (k >= ROLE_NC && e + 1 < b->opts.ncores && !b->reported[e + 1])
            e++;
        if (e > k)
            fprintf(stderr, "%s cores %d-%d (NCs)", sep, k, e);
        else
            fprintf(stderr, "%s core %d (%s)", sep, k, board_role_name(k));
        sep = ",";
        k = e;
    }
    fprintf(stderr, "\n");
}

int board_wait_reported(struct board *b, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    while (b->reported_count < b->opts.ncores && b->hello_errors == 0) {
        long long left = end - board_now_ms();
        if (left <= 0) {
            board_print_missing(b);
            fprintf(stderr, "links1: (waited %.1f s; --timeout S waits longer)\n",
                    timeout_ms / 1000.0);
            return -1;
        }
        if (board_pump(b, (int)left) < 0) {
            board_print_missing(b);
            return -1;
        }
    }
    if (b->hello_errors) {
        fprintf(stderr, "links1: %d bad report-in frame(s)\n", b->hello_errors);
        return -1;
    }
    if (!b->opts.quiet)
        printf("links1: board up: %d unit computers in %.1f s\n", b->opts.ncores,
               (double)(board_now_ms() - b->started_ms) / 1000.0);
    return 0;
}

/* ------------------------------------------------------- outgoing frames */

static int board_write_frame(struct board *b, const uint8_t *p, size_t n, int timeout_ms);

/* Writes whole frames: a NAK or a resend the board asks for while the write
 * waits (and reads) goes out after them, so no frame is cut by another. */
static int board_write_all(struct board *b, const uint8_t *p, size_t n, int timeout_ms)
{
    if (board_closed(b))
        return -1;
    b->arq->writing++;
    int r = board_write_frame(b, p, n, timeout_ms);
    b->arq->writing--;
    while (r == 0 && !b->arq->writing && (b->arq->resend_due || b->arq->nak_due)) {
        if (b->arq->resend_due) {
            b->arq->resend_due = 0;
            r = board_arq_resend(b, b->arq->resend_from);
        } else {
            b->arq->nak_due = 0;
            r = board_send_nak(b, b->arq->nak_flags);
        }
    }
    return r;
}

static int board_write_frame(struct board *b, const uint8_t *p, size_t n, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    while (n) {
        if (b->fd < 0)
            return -1;
        ssize_t w = write(b->fd, p, n);
        if (w > 0) {
            p += w;
            n -= (size_t)w;
            continue;
        }
        if (w < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
            return board_lost(b, strerror(errno));
        /* The board is not taking bytes: keep reading what it sends meanwhile,
         * so neither side can block the other. */
        long long left = end - board_now_ms();
        if (left <= 0) {
            fprintf(stderr, "links1: the board took no input for %d ms\n", timeout_ms);
            return -1;
        }
        struct pollfd pf = {.fd = b->fd, .events = POLLIN | POLLOUT};
        if (poll(&pf, 1, (int)left) > 0 && (pf.revents & (POLLIN | POLLHUP)) &&
            board_read_available(b) < 0)
            return -1;
    }
    return 0;
}

int board_send(struct board *b, uint8_t type, uint8_t flags, const void *payload,
               size_t len)
{
    if (board_closed(b))
        return -1;
    uint8_t frame[LINK_MAX_FRAME];
    uint16_t seq = b->tx_seq;
    b->arq->tx.next_seq = seq; /* kept for resending (proto/link_arq.h) */
    size_t n = link_arq_store_frame(&b->arq->tx, frame, sizeof frame, type, flags, payload, len);
    if (n == 0) {
        fprintf(stderr, "links1: frame payload of %zu bytes is over the %d-byte limit\n",
                len, LINK_MAX_PAYLOAD);
        return -1;
    }
    if (board_write_all(b, frame, n, BOARD_FRAME_TIMEOUT_MS) < 0)
        return -1;
    b->tx_seq++;
    return seq;
}

int board_send_raw(struct board *b, const void *bytes, size_t n)
{
    return board_write_all(b, bytes, n, BOARD_FRAME_TIMEOUT_MS);
}

int board_send_cmd(struct board *b, uint16_t cmd, const void *args, size_t len)
{
    uint8_t p[LINK_MAX_PAYLOAD];
    if (len > sizeof p - LINK_CMD_FIXED_SIZE) {
        fprintf(stderr, "links1: command %u: %zu bytes of arguments is too many\n", cmd, len);
        return -1;
    }
    wire_put_u16(p, cmd);
    if (len)
        memcpy(p + LINK_CMD_FIXED_SIZE, args, len);
    return board_send(b, LINK_CMD, 0, p, LINK_CMD_FIXED_SIZE + len) < 0 ? -1 : 0;
}

void board_unget_frame(struct board *b, const struct board_frame *f)
{
    if (b->queued == BOARD_FRAME_QUEUE)
        b->queued--; /* cannot happen: the frame was just taken from it */
    memmove(&b->queue[1], &b->queue[0], (size_t)b->queued * sizeof b->queue[0]);
    b->queue[0] = *f;
    b->queued++;
}

int board_wait_frame(struct board *b, uint8_t type, int timeout_ms,
                     struct board_frame *out, const char *what)
{
    return board_wait_frame_of(b, 1u << type, timeout_ms, out, what);
}

int board_wait_frame_of(struct board *b, uint32_t mask, int timeout_ms,
                        struct board_frame *out, const char *what)
{
    long long end = board_now_ms() + timeout_ms;
    for (;;) {
        if (board_take_queued(b, mask, out))
            return 0;
        long long left = end - board_now_ms();
        if (left <= 0) {
            fprintf(stderr, "links1: no %s from the board within %d ms\n", what, timeout_ms);
            return -1;
        }
        if (board_pump(b, (int)left) < 0) {
            fprintf(stderr, "links1: gave up waiting for %s\n", what);
            return -1;
        }
    }
}

int board_wait_result(struct board *b, uint16_t cmd, int timeout_ms,
                      struct board_frame *out, int *status,
                      const uint8_t **fields, size_t *nfields)
{
    char what[64];
    snprintf(what, sizeof what, "result of command %u", cmd);
    if (board_wait_frame(b, LINK_RESULT, timeout_ms, out, what) < 0)
        return -1;
    if (out->length < LINK_RESULT_FIXED_SIZE) {
        fprintf(stderr, "links1: RESULT frame of %u bytes, want at least %d\n", out->length,
                LINK_RESULT_FIXED_SIZE);
        return -1;
    }
    uint16_t got = wire_get_u16(out->payload);
    if (got != cmd) {
        fprintf(stderr, "links1: waited for the result of command %u, got one for %u\n",
                cmd, got);
        return -1;
    }
    *status = (int16_t)wire_get_u16(out->payload + 2);
    *fields = out->payload + LINK_RESULT_FIXED_SIZE;
    *nfields = out->length - LINK_RESULT_FIXED_SIZE;
    return 0;
}

int board_wait_ok(struct board *b, uint16_t cmd, int timeout_ms, size_t min_fields,
                  struct board_frame *out, const uint8_t **fields, size_t *nfields,
                  char *why, size_t cap)
{
    int status;
    if (board_wait_result(b, cmd, timeout_ms, out, &status, fields, nfields) < 0) {
        snprintf(why, cap, "no valid result for command %u", cmd);
        return -1;
    }
    if (status != LINK_OK) {
        char text[BOARD_TEXT_CAP(LINK_MAX_PAYLOAD)];
        snprintf(why, cap, "the board says: %s (%s)",
                 board_text(*fields, *nfields, text, sizeof text), board_status_name(status));
        return -1;
    }
    if (*nfields < min_fields) {
        snprintf(why, cap, "result of command %u has %zu bytes of fields, want %zu", cmd,
                 *nfields, min_fields);
        return -1;
    }
    return 0;
}

uint32_t board_link_errors(const struct board *b)
{
    const struct link_stats *s = &b->dec.stats;
    return s->crc_errors + s->bad_length + s->junk_bytes + s->seq_gaps +
           b->host_frames_dropped;
}

uint32_t board_report_link_errors(const struct board *b)
{
    const struct link_stats *s = &b->dec.stats;
    uint32_t n = board_link_errors(b);
    if (n)
        fprintf(stderr, "links1: link errors: from the board %u bad CRC, %u bad length, "
                "%u junk bytes, %u seq gaps (in %u good frames); %u frames from the host "
                "dropped by the board; %u of our frames sent again, %u of the board's taken "
                "twice and dropped\n", s->crc_errors, s->bad_length, s->junk_bytes,
                s->seq_gaps, s->frames, b->host_frames_dropped, b->frames_resent, b->frames_dropped_dup);
    return n;
}

