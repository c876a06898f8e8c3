/* dm_checks.c: the DM's side of the bring-up checks over the serial lines
 * and the IMSUs (CMD_LINE_PING, CMD_LINE_LATENCY, CMD_IMSU_TEST,
 * CMD_LINE_STRESS). */
#include <stdint.h>

#include "drivers/imsu/imsu.h"
#include "drivers/serial/hostlink_tx.h"
#include "drivers/serial/line.h"
#include "drivers/serial/uart.h"
#include "kernel/cpu.h"
#include "kernel/ktime.h"
#include "proto/crc32.h"
#include "proto/hostlink.h"
#include "proto/wire.h"
#include "roles/dm.h"
#include "roles/selftest.h"
#include "roles/unit.h"
#include "proto/unitmsg.h"

/* The success result of the ping and IMSU checks: ok of total passed. */
static void dm_count_result(uint16_t cmd, uint32_t ok, uint32_t total)
{
    struct link_count_result r = {ok, total};
    uint8_t f[LINK_COUNT_RESULT_SIZE];
    link_count_result_put(f, &r);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

void dm_cmd_line_ping(uint16_t cmd)
{
    struct line_msg *m = &dm_msg;
    uint32_t total = line_count(), ok = 0;
    selftest_msg_set(m, MSG_PING, 4);
    wire_put_u32(m->payload, 0xD0D0u);
    int r = dm_rc_request(m, MSG_PONG, PING_TIMEOUT_MS);
    if (r != LINE_OK || wire_get_u32(m->payload) != 0xD0D0u) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "line DM<->RC: no pong (%s)", line_strerror(r));
        return;
    }
    ok++;
    selftest_msg_set(m, MSG_PING_NCS, 0);
    r = dm_rc_request(m, MSG_PING_NCS_DONE, PING_TIMEOUT_MS + REPLY_TIMEOUT_MS);
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "RC did not report its NC pings (%s)",
                       line_strerror(r));
        return;
    }
    ok += wire_get_u32(m->payload);
    uint32_t first_bad = wire_get_u32(m->payload + 8);
    if (ok != total) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT,
                       "%u of %u serial lines answered; first silent: RC<->core %u",
                       (unsigned)ok, (unsigned)total, (unsigned)first_bad);
        return;
    }
    dm_count_result(cmd, ok, total);
}

/* Timed round trips on one line: the DM's own with the RC (core 1), or the
 * RC's with an NC, asked of the RC. */
void dm_cmd_line_latency(uint16_t cmd)
{
    if (dm_frame.length < LINK_CMD_FIXED_SIZE + LINK_LATENCY_ARGS_SIZE) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_LINE_LATENCY needs u32 rounds, u16 core "
                       "(%u bytes), got %u", (unsigned)LINK_LATENCY_ARGS_SIZE,
                       (unsigned)(dm_frame.length - LINK_CMD_FIXED_SIZE));
        return;
    }
    uint32_t rounds = wire_get_u32(dm_frame.payload + LINK_CMD_FIXED_SIZE);
    uint16_t core = wire_get_u16(dm_frame.payload + LINK_CMD_FIXED_SIZE + 4);
    if (rounds == 0 || rounds > LINK_LATENCY_MAX_ROUNDS || core == UNITS_DM_CORE ||
        core >= board_ncores || unit_is_halted(core)) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_LINE_LATENCY: %u rounds (1..%u) to core "
                       "%u (the RC, or a running NC of the %u cores)", (unsigned)rounds,
                       (unsigned)LINK_LATENCY_MAX_ROUNDS, (unsigned)core,
                       (unsigned)board_ncores);
        return;
    }
    struct line_msg *m = &dm_msg;
    uint32_t done = 0, mmm[3] = {0, 0, 0};
    int r;
    if (core == UNITS_RC_CORE) {
        r = selftest_latency(UNITS_RC_CORE, rounds, m, &done, mmm);
    } else {
        selftest_msg_set(m, MSG_LATENCY, 6);
        wire_put_u32(m->payload, rounds);
        wire_put_u16(m->payload + 4, core);
        r = dm_rc_request(m, MSG_LATENCY_DONE, REPLY_TIMEOUT_MS + rounds * PING_TIMEOUT_MS);
        if (r == LINE_OK && m->len < 20)
            r = LINE_ERR_CHECK;
        if (r == LINE_OK) {
            r = (int32_t)wire_get_u32(m->payload);
            done = wire_get_u32(m->payload + 4);
            for (int i = 0; i < 3; i++)
                mmm[i] = wire_get_u32(m->payload + 8 + 4 * i);
        }
    }
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "line %s<->core %u: round %u of %u failed (%s)",
                       core == UNITS_RC_CORE ? "DM" : "RC", (unsigned)core,
                       (unsigned)done + 1, (unsigned)rounds, line_strerror(r));
        return;
    }
    struct link_latency_result res = {rounds, ktime_freq(), mmm[0], mmm[1], mmm[2]};
    uint8_t f[LINK_LATENCY_RESULT_SIZE];
    link_latency_result_put(f, &res);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

_Static_assert(SELFTEST_MEM_SCRATCH <= IMSU_TEST_PAIR_BYTES,
               "selftest_mem's scratch beyond the pair test's");

/* The DM's memcpy and memset (selftest_mem), then the IMSU pair both ways
 * (with misuse checks), then the broadcast block. */
void dm_cmd_imsu_test(uint16_t cmd)
{
    struct imsu_pair *p = &imsu_dm_rc;
    struct line_msg *m = &dm_msg;
    const uint32_t bytes = IMSU_TEST_PAIR_BYTES;
    const uint32_t seed_out = 0xA11CE000u + p->swaps, seed_back = 0xB0B00000u + p->swaps;
    uint32_t blocks_ok = 0, misuse_failed = 0;

    int held = imsu_held(p, UNITS_DM_CORE);
    uint8_t *w;
    int r = imsu_write_begin(p, UNITS_DM_CORE, held, &w);
    if (r != IMSU_OK) {
        hostlink_error(cmd, LINK_ERR_CHECK, "IMSU: DM cannot write its own block: %s",
                       imsu_strerror(r));
        return;
    }
    /* first the copies every block move relies on, in the block's bytes */
    uint32_t mem_cases;
    char mem_first[64];
    uint32_t mem_wrong = selftest_mem(w, &mem_cases, mem_first, sizeof mem_first);
    if (mem_wrong) {
        imsu_write_end(p, UNITS_DM_CORE);
        hostlink_error(cmd, LINK_ERR_CHECK,
                       "the firmware's memcpy and memset: %u of %u cases wrong (first: %s)",
                       (unsigned)mem_wrong, (unsigned)mem_cases, mem_first);
        return;
    }
    selftest_fill(w, bytes, seed_out, 0);
    uint32_t crc_out = crc32(w, bytes);
    imsu_write_end(p, UNITS_DM_CORE);
    r = imsu_swap(p, UNITS_DM_CORE);
    if (r != IMSU_OK) {
        hostlink_error(cmd, LINK_ERR_CHECK, "IMSU: swap DM->RC refused: %s", imsu_strerror(r));
        return;
    }
    /* The block went to the RC: writing it now must be refused. */
    if (imsu_write_begin(p, UNITS_DM_CORE, held, &w) != IMSU_ERR_NOT_HOLDER) {
        misuse_failed++;
        imsu_write_end(p, UNITS_DM_CORE);
    }
    selftest_msg_set(m, MSG_IMSU_PAIR, 12);
    wire_put_u32(m->payload, bytes);
    wire_put_u32(m->payload + 4, crc_out);
    wire_put_u32(m->payload + 8, seed_back);
    r = dm_rc_request(m, MSG_IMSU_MIDWRITE, REPLY_TIMEOUT_MS);
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "IMSU: RC did not start its write (%s)",
                       line_strerror(r));
        return;
    }
    /* The RC is inside its write: our swap must be refused. */
    int swap_st = imsu_swap(p, UNITS_DM_CORE);
    selftest_msg_set(m, MSG_IMSU_MIDWRITE_SEEN, 4);
    wire_put_u32(m->payload, (uint32_t)swap_st);
    r = dm_rc_request(m, MSG_IMSU_PAIR_DONE, REPLY_TIMEOUT_MS);
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "IMSU: RC did not finish the pair test (%s)",
                       line_strerror(r));
        return;
    }
    int32_t rc_status = (int32_t)wire_get_u32(m->payload);
    uint32_t crc_back = wire_get_u32(m->payload + 4);
    misuse_failed += wire_get_u32(m->payload + 8);
    blocks_ok += wire_get_u32(m->payload + 12); /* RC saw our block intact */
    if (rc_status != IMSU_OK) {
        hostlink_error(cmd, LINK_ERR_CHECK, "IMSU: RC side failed: %s", imsu_strerror(rc_status));
        return;
    }
    const uint8_t *back = imsu_read_block(p, UNITS_DM_CORE);
    if (imsu_held(p, UNITS_DM_CORE) == held && crc32(back, bytes) == crc_back &&
        selftest_check(back, bytes, seed_back, 0) == 0)
        blocks_ok++;

    selftest_msg_set(m, MSG_IMSU_BCAST, 8);
    wire_put_u32(m->payload, IMSU_TEST_BCAST_BYTES);
    wire_put_u32(m->payload + 4, seed_out ^ 0xCA57u);
    r = dm_rc_request(m, MSG_IMSU_BCAST_DONE, REPLY_TIMEOUT_MS * 2);
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "IMSU: RC did not finish the broadcast (%s)",
                       line_strerror(r));
        return;
    }
    uint32_t ncs_ok = wire_get_u32(m->payload), ncs = wire_get_u32(m->payload + 4);
    misuse_failed += wire_get_u32(m->payload + 8);
    blocks_ok += ncs_ok;
    uint32_t expected = 2 + ncs;
    if (blocks_ok != expected || misuse_failed) {
        hostlink_error(cmd, LINK_ERR_CHECK,
                       "IMSU: %u of %u blocks arrived intact (pair both ways + %u NC reads); "
                       "%u misuse checks not refused",
                       (unsigned)blocks_ok, (unsigned)expected, (unsigned)ncs,
                       (unsigned)misuse_failed);
        return;
    }
    dm_count_result(cmd, blocks_ok, expected);
}

void dm_cmd_line_stress(uint16_t cmd)
{
    if (dm_frame.length < LINK_CMD_FIXED_SIZE + 4) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_LINE_STRESS needs u32 MiB (4 bytes), got %u",
                       (unsigned)(dm_frame.length - LINK_CMD_FIXED_SIZE));
        return;
    }
    uint32_t mib = wire_get_u32(dm_frame.payload + LINK_CMD_FIXED_SIZE);
    if (mib == 0 || mib > STRESS_MAX_MIB) {
        hostlink_error(cmd, LINK_ERR_BAD_ARGS, "CMD_LINE_STRESS: %u MiB is outside 1..%u",
                       (unsigned)mib, (unsigned)STRESS_MAX_MIB);
        return;
    }
    /* Both directions of every live line carry an equal share. */
    uint32_t live = line_count();
    for (uint32_t k = UNITS_FIRST_NC; k < board_ncores; k++)
        live -= (uint32_t)unit_is_halted(k);
    uint64_t total = (uint64_t)mib << 20;
    uint64_t per_stream = (total + 2u * live - 1) / (2u * live);
    uint32_t msgs = (uint32_t)((per_stream + LINE_MAX_PAYLOAD - 1) / LINE_MAX_PAYLOAD);

    struct line_msg *m = &dm_msg;
    selftest_msg_set(m, MSG_STRESS, 4);
    wire_put_u32(m->payload, msgs);
    int r = line_send(UNITS_RC_CORE, m, ktime_deadline_ms(REPLY_TIMEOUT_MS));
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "stress: cannot reach the RC (%s)", line_strerror(r));
        return;
    }
    struct selftest_stream s[2];
    selftest_stream_init(&s[0], UNITS_RC_CORE, 1, msgs);
    selftest_stream_init(&s[1], UNITS_RC_CORE, 0, msgs);
    int stalled = selftest_stress_run(s, 2);
    r = selftest_recv_type(UNITS_RC_CORE, MSG_STRESS_REPORT, m, ktime_deadline_ms(STRESS_STALL_MS * 2));
    if (r != LINE_OK) {
        hostlink_error(cmd, LINK_ERR_TIMEOUT, "stress: no report from the RC (%s)",
                       line_strerror(r));
        return;
    }
    uint64_t bytes = s[1].bytes + wire_get_u64(m->payload);
    uint32_t errors = s[1].errors + s[1].left + wire_get_u32(m->payload + 8);
    uint32_t skipped = wire_get_u32(m->payload + 12);
    if (errors || stalled || bytes < total) {
        hostlink_error(cmd, LINK_ERR_CHECK,
                       "stress: %u errors, %u KiB of %u KiB checked%s",
                       (unsigned)errors, (unsigned)(bytes >> 10), (unsigned)(total >> 10),
                       stalled ? ", a line stalled" : "");
        return;
    }
    struct link_stress_result res = {bytes, errors, skipped};
    uint8_t f[LINK_STRESS_RESULT_SIZE];
    link_stress_result_put(f, &res);
    hostlink_result(cmd, LINK_OK, f, sizeof f);
}

