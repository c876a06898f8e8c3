/* selftest_link.c: the host-link checks of `links1 selftest` (pattern
 * transfers both ways) and the idle-CPU check. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/link_transfer.h"
#include "host-tools/selftest.h"
#include "proto/wire.h"

int selftest_link_sink(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    uint32_t crc;
    struct board_frame r;
    const uint8_t *f;
    long long t0 = board_now_ms();
    if (board_send_cmd(b, CMD_LINK_SINK, NULL, 0) < 0 ||
        link_transfer_send_pattern(b, a->link_bytes, &crc) < 0) {
        snprintf(why, cap, "sending %u bytes to the board failed", a->link_bytes);
        return -1;
    }
    if (selftest_result(b, CMD_LINK_SINK, BOARD_FRAME_TIMEOUT_MS, LINK_TRANSFER_RESULT_SIZE,
                        &r, &f, why, cap) < 0)
        return -1;
    struct link_transfer_result res;
    link_transfer_result_get(f, &res);
    uint64_t got = res.bytes;
    uint32_t got_crc = res.crc;
    double secs = (double)(board_now_ms() - t0) / 1000.0;
    snprintf(why, cap, "sent %u bytes crc 0x%08x; board took %llu bytes crc 0x%08x "
             "(%.0f KiB/s)", a->link_bytes, crc, (unsigned long long)got, got_crc,
             secs > 0 ? a->link_bytes / 1024.0 / secs : 0.0);
    return got == a->link_bytes && got_crc == crc && res.differ == 0 ? 0 : -1;
}

int selftest_link_source(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    uint8_t arg[4];
    uint64_t bytes;
    uint32_t crc;
    struct board_frame r;
    const uint8_t *f;
    long long t0 = board_now_ms();
    wire_put_u32(arg, a->link_bytes);
    if (board_send_cmd(b, CMD_LINK_SOURCE, arg, sizeof arg) < 0 ||
        link_transfer_receive_pattern(b, &bytes, &crc) < 0) {
        snprintf(why, cap, "receiving %u pattern bytes from the board failed", a->link_bytes);
        return -1;
    }
    double secs = (double)(board_now_ms() - t0) / 1000.0;
    if (selftest_result(b, CMD_LINK_SOURCE, BOARD_FRAME_TIMEOUT_MS, LINK_TRANSFER_RESULT_SIZE,
                        &r, &f, why, cap) < 0)
        return -1;
    struct link_transfer_result res;
    link_transfer_result_get(f, &res);
    uint64_t said = res.bytes;
    uint32_t said_crc = res.crc;
    snprintf(why, cap, "received %llu bytes crc 0x%08x, all the pattern in order; board "
             "says it sent %llu bytes crc 0x%08x (%.0f KiB/s)", (unsigned long long)bytes,
             crc, (unsigned long long)said, said_crc, secs > 0 ? bytes / 1024.0 / secs : 0.0);
    return bytes == a->link_bytes && said == bytes && said_crc == crc ? 0 : -1;
}

/* QEMU's user+system CPU time in clock ticks, from /proc/PID/stat. */
static long long selftest_qemu_cpu_ticks(pid_t pid)
{
    char path[64], buf[4096];
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    FILE *fp = fopen(path, "r");
    if (!fp)
        return -1;
    size_t n = fread(buf, 1, sizeof buf - 1, fp);
    fclose(fp);
    buf[n] = 0;
    /* The command name (field 2) may hold spaces; fields count from its ')'. */
    char *p = strrchr(buf, ')');
    unsigned long long utime, stime;
    if (!p || sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu", &utime,
                     &stime) != 2)
        return -1;
    return (long long)(utime + stime);
}

/* Keeps reading the link (logs, faults) for ms milliseconds. */
static int selftest_pump_for(struct board *b, int ms)
{
    long long end = board_now_ms() + ms;
    for (long long left = ms; left > 0; left = end - board_now_ms())
        if (board_pump(b, (int)left) < 0)
            return -1;
    return 0;
}

int selftest_idle(struct board *b, const struct selftest_args *a, char *why, size_t cap)
{
    if (selftest_pump_for(b, SELFTEST_IDLE_SETTLE_MS) < 0) {
        snprintf(why, cap, "the board stopped while settling");
        return -1;
    }
    long long t0 = board_now_ms(), c0 = selftest_qemu_cpu_ticks(b->qemu_pid);
    if (c0 < 0 || selftest_pump_for(b, SELFTEST_IDLE_SECONDS * 1000) < 0) {
        snprintf(why, cap, "cannot read QEMU's CPU time (pid %d)", (int)b->qemu_pid);
        return -1;
    }
    long long t1 = board_now_ms(), c1 = selftest_qemu_cpu_ticks(b->qemu_pid);
    if (c1 < 0) {
        snprintf(why, cap, "cannot read QEMU's CPU time (pid %d)", (int)b->qemu_pid);
        return -1;
    }
    double cpu_s = (double)(c1 - c0) / (double)sysconf(_SC_CLK_TCK);
    double wall_s = (double)(t1 - t0) / 1000.0;
    double pct = 100.0 * cpu_s / wall_s;
    snprintf(why, cap, "%d idle cores: QEMU used %.1f%% of one host core over %.1f s "
             "(limit %.0f%%)", b->opts.ncores, pct, wall_s, a->max_percent);
    return pct < a->max_percent ? 0 : -1;
}
