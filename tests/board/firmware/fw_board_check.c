/* fw_board_check.c: firmware board checks that need frames the links1 tool
 * never sends on purpose: damaged frames, unknown commands, malformed
 * payloads, frames out of place, and every kind of injected fault.
 *
 * The board is started by the one launcher (host-tools/link/board.c) and spoken
 * to with the one framing (proto/hostlink.c); a damaged frame is a good one
 * from link_frame_encode with a byte spoilt.  Prints one "PASS name" or
 * "FAIL name: why" line per check (counted by tests/run.sh).
 *
 * usage: fw_board_check ELF SMP   (tests/board/firmware/fw_board.sh runs it)
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/launcher/launcher.h"
#include "proto/board_map.h"
#include "proto/wire.h"

/* A command the firmware answers slowly (a ping with silent lines waits for
 * each of them) gets this long. */
#define FW_CHECK_WAIT_MS 30000
#define FW_CHECK_PING_WAIT_MS 60000
#define FW_CHECK_SMALL_RAM_MB 256

static int fw_failed;

static void verdict(const char *name, int ok, const char *fmt, ...)
{
    if (ok) {
        printf("PASS %s\n", name);
    } else {
        char why[512];
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(why, sizeof why, fmt, ap);
        va_end(ap);
        printf("FAIL %s: %s\n", name, why);
        fw_failed++;
    }
    fflush(stdout);
}

/* One command and its answer; on a missing answer status is 1 and text
 * says so. */
struct answer {
    int status;
    size_t n;
    const uint8_t *fields;
    char text[LINK_MAX_PAYLOAD + 1];
    struct board_frame frame;
};

static void take_result(struct board *b, uint16_t cmd, int timeout_ms, struct answer *a)
{
    if (board_wait_result(b, cmd, timeout_ms, &a->frame, &a->status, &a->fields, &a->n) < 0) {
        a->status = 1;
        a->n = 0;
        snprintf(a->text, sizeof a->text, "(no result for command %u)", cmd);
        return;
    }
    snprintf(a->text, sizeof a->text, "%.*s", (int)a->n, (const char *)a->fields);
}

static void command(struct board *b, uint16_t cmd, const void *args, size_t len,
                    int timeout_ms, struct answer *a)
{
    if (board_send_cmd(b, cmd, args, len) < 0) {
        a->status = 1;
        a->n = 0;
        snprintf(a->text, sizeof a->text, "(could not send command %u)", cmd);
        return;
    }
    take_result(b, cmd, timeout_ms, a);
}

/* Waits for the board's report (a RESULT for cmd 0) of one more frame from
 * the host it could not take; fills a with its status and text. */
static void take_drop_report(struct board *b, uint32_t before, struct answer *a)
{
    long long end = board_now_ms() + FW_CHECK_WAIT_MS;
    while (b->host_frames_dropped <= before) {
        long long left = end - board_now_ms();
        if (left <= 0 || board_pump(b, (int)left) < 0) {
            a->status = 1;
            snprintf(a->text, sizeof a->text, "(no report of a dropped frame)");
            return;
        }
    }
    a->status = b->host_drop_status;
    snprintf(a->text, sizeof a->text, "%s", b->host_drop_text);
}

/* Waits until at least n faults have been reported; 0, or -1. */
static int wait_faults(struct board *b, int n, int timeout_ms)
{
    long long end = board_now_ms() + timeout_ms;
    while (b->nfaults < n) {
        long long left = end - board_now_ms();
        if (left <= 0 || board_pump(b, (int)left) < 0)
            return -1;
    }
    return 0;
}

static int has(const struct answer *a, const char *s)
{
    return strstr(a->text, s) != NULL;
}

static void bad_input_checks(struct board *b, int smp)
{
    struct answer a;
    uint8_t frame[LINK_MAX_FRAME], args[8];
    uint32_t before;

    /* A frame whose CRC is wrong: dropped and reported at once (and asked
     * for again: its seq stays the next one, proto/link_arq.h). */
    wire_put_u16(args, CMD_STATUS);
    size_t n = link_frame_encode(frame, sizeof frame, LINK_CMD, 0, b->tx_seq, args,
                                 LINK_CMD_FIXED_SIZE);
    frame[n - 1] ^= 1;
    before = b->host_frames_dropped;
    board_send_raw(b, frame, n);
    take_drop_report(b, before, &a);
    verdict("fw_bad_crc_reported", a.status == LINK_ERR_BAD_FRAME && has(&a, "bad CRC 1"),
            "got status %d '%s'", a.status, a.text);

    /* A header announcing more than LINK_MAX_PAYLOAD, then junk. */
    n = link_frame_encode(frame, sizeof frame, LINK_CMD, 0, b->tx_seq, args,
                          LINK_CMD_FIXED_SIZE);
    wire_put_u16(frame + LINK_HEADER_SIZE - 2, 0xFFFF); /* the length field */
    memset(frame + LINK_HEADER_SIZE, 0, 16);
    before = b->host_frames_dropped;
    board_send_raw(b, frame, LINK_HEADER_SIZE + 16);
    take_drop_report(b, before, &a);
    verdict("fw_bad_length_reported", a.status == LINK_ERR_BAD_FRAME && has(&a, "bad length 1"),
            "got status %d '%s'", a.status, a.text);

    command(b, 99, NULL, 0, FW_CHECK_WAIT_MS, &a);
    verdict("fw_unknown_command", a.status == LINK_ERR_UNKNOWN_CMD &&
            has(&a, "unknown command 99"), "got status %d '%s'", a.status, a.text);

    before = b->host_frames_dropped;
    board_send(b, LINK_CMD, 0, "\x01", 1);
    take_drop_report(b, before, &a);
    verdict("fw_cmd_without_number", a.status == LINK_ERR_BAD_ARGS &&
            has(&a, "no command number"), "got status %d '%s'", a.status, a.text);

    command(b, CMD_LINE_STRESS, "\x01", 1, FW_CHECK_WAIT_MS, &a);
    verdict("fw_stress_short_args", a.status == LINK_ERR_BAD_ARGS && has(&a, "needs u32"),
            "got status %d '%s'", a.status, a.text);

    wire_put_u32(args, 0);
    command(b, CMD_LINE_STRESS, args, 4, FW_CHECK_WAIT_MS, &a);
    verdict("fw_stress_zero_mib", a.status == LINK_ERR_BAD_ARGS && has(&a, "outside"),
            "got status %d '%s'", a.status, a.text);

    wire_put_u16(args, (uint16_t)smp);
    wire_put_u8(args + 2, FAULT_UNDEF);
    command(b, CMD_FAULT_INJECT, args, 3, FW_CHECK_WAIT_MS, &a);
    verdict("fw_fault_core_out_of_range", a.status == LINK_ERR_BAD_ARGS &&
            has(&a, "out of range"), "got status %d '%s'", a.status, a.text);

    before = b->host_frames_dropped;
    board_send(b, LINK_DATA, 0, "stray", 5);
    take_drop_report(b, before, &a);
    verdict("fw_data_outside_transfer", a.status == LINK_ERR_PROTOCOL &&
            has(&a, "outside a transfer"), "got status %d '%s'", a.status, a.text);

    /* The same command frame twice (a resend whose first copy got
     * through): carried out once, the repeat dropped by its seq
     * (proto/link_arq.h). */
    wire_put_u16(args, CMD_STATUS);
    int seq = board_send(b, LINK_CMD, 0, args, LINK_CMD_FIXED_SIZE);
    n = link_frame_encode(frame, sizeof frame, LINK_CMD, 0, (uint16_t)seq, args,
                          LINK_CMD_FIXED_SIZE);
    board_send_raw(b, frame, n);
    struct board_frame r;
    int status = -1;
    const uint8_t *fields;
    size_t nf;
    int first = board_wait_result(b, CMD_STATUS, FW_CHECK_WAIT_MS, &r, &status, &fields, &nf);
    board_pump(b, 500); /* a second answer would be here by now */
    int more = 0;
    for (int i = 0; i < b->queued; i++)
        more += b->queue[i].type == LINK_RESULT;
    verdict("fw_duplicate_command_once", seq >= 0 && first == 0 && status == 0 && more == 0,
            "first answer %d (status %d), %d more results", first, status, more);

    command(b, CMD_STATUS, NULL, 0, FW_CHECK_WAIT_MS, &a);
    struct link_status_result st = {0, 0, 0};
    int ok = a.status == 0 && a.n >= LINK_STATUS_RESULT_SIZE;
    if (ok)
        link_status_result_get(a.fields, &st);
    verdict("fw_runs_after_bad_input", ok && st.ncores == smp && st.reported == smp &&
            st.halted == 0, "status %d, %u cores, %u reported, %u halted", a.status,
            st.ncores, st.reported, st.halted);
}

struct fault_case {
    int core;
    uint8_t inject;     /* CMD_FAULT_INJECT kind */
    uint8_t reported;   /* enum link_fault_kind in the report */
    const char *label;
    const char *text;   /* what the report's text must hold */
};

/* Data abort, prefetch abort, panic and both spinlock misuses on five NCs,
 * each reported as what it is; then the rest still answer. */
static void fault_checks(struct board *b, int smp)
{
    static const struct fault_case cases[] = {
        {2, FAULT_DATA_ABORT, FAULT_DATA_ABORT, "data", "data abort"},
        {3, FAULT_PREFETCH_ABORT, FAULT_PREFETCH_ABORT, "prefetch", "prefetch abort"},
        {4, FAULT_PANIC, FAULT_PANIC, "panic", "injected by the host"},
        {5, FAULT_INJECT_LOCK_TWICE, FAULT_PANIC, "lock_twice", "'selftest_twice' already held"},
        {6, FAULT_INJECT_UNLOCK_FREE, FAULT_PANIC, "unlock_free", "'selftest_free' not held"},
    };
    const int ncases = (int)(sizeof cases / sizeof cases[0]);
    struct link_status_result st;
    struct answer a;
    uint8_t args[3];
    char name[64];
    for (int i = 0; i < ncases; i++) {
        const struct fault_case *c = &cases[i];
        int before = b->nfaults;
        wire_put_u16(args, (uint16_t)c->core);
        wire_put_u8(args + 2, c->inject);
        command(b, CMD_FAULT_INJECT, args, sizeof args, FW_CHECK_WAIT_MS, &a);
        snprintf(name, sizeof name, "fw_fault_%s_reported", c->label);
        if (wait_faults(b, before + 1, FW_CHECK_WAIT_MS) < 0 || before >= BOARD_MAX_FAULTS) {
            verdict(name, 0, "result %d '%s', no fault report from core %d", a.status, a.text,
                    c->core);
            continue;
        }
        const struct link_fault *f = &b->faults[before];
        const char *text = b->fault_text[before];
        int ok = a.status == 0 && f->core == c->core && f->role == ROLE_NC &&
                 f->kind == c->reported && strstr(text, c->text);
        if (c->inject == FAULT_DATA_ABORT || c->inject == FAULT_PREFETCH_ABORT)
            ok = ok && (f->addr & ~1u) == UNMAPPED_VIRT; /* bit 0: Thumb */
        verdict(name, ok, "result %d, fault core %u role %u kind %u addr 0x%x '%s'", a.status,
                f->core, f->role, f->kind, f->addr, text);
    }

    command(b, CMD_STATUS, NULL, 0, FW_CHECK_WAIT_MS, &a);
    int halted = -1;
    if (a.status == 0 && a.n >= LINK_STATUS_RESULT_SIZE) {
        link_status_result_get(a.fields, &st);
        halted = st.halted;
    }
    verdict("fw_fault_status_counts_halted", halted == ncases, "status %d, %d halted",
            a.status, halted);

    char lines[64];
    snprintf(lines, sizeof lines, "%d of %d serial lines", smp - 1 - ncases, smp - 1);
    command(b, CMD_LINE_PING, NULL, 0, FW_CHECK_PING_WAIT_MS, &a);
    verdict("fw_fault_others_answer", a.status == LINK_ERR_TIMEOUT && has(&a, lines),
            "got status %d '%s', want '%s'", a.status, a.text, lines);

    wire_put_u16(args, (uint16_t)cases[0].core);
    wire_put_u8(args + 2, FAULT_UNDEF);
    command(b, CMD_FAULT_INJECT, args, sizeof args, FW_CHECK_WAIT_MS, &a);
    verdict("fw_fault_halted_core_refused", a.status == LINK_ERR_BAD_ARGS &&
            has(&a, "already halted"), "got status %d '%s'", a.status, a.text);
}

/* A board with less RAM than the linker script carved is refused at boot
 * with a fault naming both sizes, not left to crash later. */
static void small_ram_check(const struct board_opts *base)
{
    struct board_opts o = *base;
    struct board b;
    o.ncores = UNITS_MIN_CORES;
    o.ram_mb = FW_CHECK_SMALL_RAM_MB;
    if (board_start(&b, &o) < 0) {
        verdict("fw_small_ram_refused", 0, "the board did not start");
        return;
    }
    if (wait_faults(&b, 1, o.timeout_s * 1000) < 0) {
        verdict("fw_small_ram_refused", 0, "no fault report in %d s, %d cores reported in",
                o.timeout_s, b.reported_count);
    } else {
        char have[32], need[32];
        snprintf(have, sizeof have, "%d MiB", FW_CHECK_SMALL_RAM_MB);
        snprintf(need, sizeof need, "needs %d MiB", BOARD_DEFAULT_RAM_MB);
        const struct link_fault *f = &b.faults[0];
        verdict("fw_small_ram_refused", f->core == 0 && f->kind == FAULT_PANIC &&
                strstr(b.fault_text[0], have) && strstr(b.fault_text[0], need) &&
                b.reported_count == 0, "fault core %u kind %u '%s', %d cores reported in",
                f->core, f->kind, b.fault_text[0], b.reported_count);
    }
    board_stop(&b); /* the halted DM cannot power off: QEMU is signalled */
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: fw_board_check ELF SMP\n");
        return 2;
    }
    struct board_opts o;
    board_opts_init(&o);
    o.firmware = argv[1];
    o.ncores = atoi(argv[2]);
    /* Five NCs fault: cores 2..6, and one more must be left to answer. */
    if (o.ncores < 8 || o.ncores > UNITS_MAX_CORES) {
        fprintf(stderr, "fw_board_check: SMP %s: want 8..%d cores\n", argv[2], UNITS_MAX_CORES);
        return 2;
    }
    small_ram_check(&o);

    struct board b;
    if (board_start(&b, &o) < 0) {
        printf("FAIL fw_board: the board did not start\n");
        return 1;
    }
    int r = board_wait_reported(&b, o.timeout_s * 1000);
    verdict("fw_all_reported", r == 0 && b.hello_errors == 0, "%d of %d cores reported in, "
            "%d bad report-ins", b.reported_count, o.ncores, b.hello_errors);
    if (r == 0) {
        bad_input_checks(&b, o.ncores);
        fault_checks(&b, o.ncores);
    }
    if (b.fd < 0) {
        printf("FAIL fw_board: the board stopped talking (see above)\n");
        fw_failed++;
    }
    board_stop(&b);
    return fw_failed ? 1 : 0;
}
