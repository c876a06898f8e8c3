/* insn_report.c: per-core guest instruction counts (see insn_report.h). */
#define _GNU_SOURCE /* O_NOFOLLOW, O_CLOEXEC */
#include "host-tools/insn/insn_report.h"

#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "host-tools/link/board.h"

/* "vcpu K INSNS\n" for each of at most UNITS_MAX_CORES cores, with room. */
#define INSN_REPORT_MAX_BYTES (UNITS_MAX_CORES * 64)

int insn_report_print(const char *path, int ncores)
{
    static uint64_t count[UNITS_MAX_CORES];
    static uint8_t seen[UNITS_MAX_CORES];
    /* The plugin's file in the run's private directory: a link is not
     * followed, and a file larger than the plugin writes is refused. */
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) ||
        st.st_size > INSN_REPORT_MAX_BYTES) {
        fprintf(stderr, "links1: instruction counts %s: %s\n", path,
                fd < 0 ? (errno == ENOENT ? "missing (did QEMU exit before the plugin could "
                                            "write them?)" : strerror(errno))
                : !S_ISREG(st.st_mode) ? "not a regular file" : "larger than the plugin writes");
        if (fd >= 0)
            close(fd);
        return -1;
    }
    FILE *f = fdopen(fd, "r");
    if (!f) {
        fprintf(stderr, "links1: instruction counts %s: %s\n", path, strerror(errno));
        close(fd);
        return -1;
    }
    memset(seen, 0, sizeof seen);
    unsigned vcpu;
    uint64_t n;
    int lines = 0;
    while (fscanf(f, " vcpu %u %" SCNu64, &vcpu, &n) == 2) {
        if (vcpu < UNITS_MAX_CORES && (int)vcpu < ncores) {
            count[vcpu] = n;
            seen[vcpu] = 1;
        }
        lines++;
    }
    int bad = !feof(f) || lines > UNITS_MAX_CORES;
    fclose(f);
    if (bad || lines == 0) {
        fprintf(stderr, "links1: instruction counts %s: %s\n", path,
                lines ? "a line is not 'vcpu K INSNS'" : "no counts in the file");
        return -1;
    }
    uint64_t nc_sum = 0, nc_min = UINT64_MAX, nc_max = 0;
    printf("guest instructions per core:\n");
    for (int k = 0; k < ncores; k++) {
        uint64_t c = seen[k] ? count[k] : 0;
        printf("  core %3d %s %14" PRIu64 "\n", k, board_role_name(k), c);
        if (k >= ROLE_NC) {
            nc_sum += c;
            nc_min = c < nc_min ? c : nc_min;
            nc_max = c > nc_max ? c : nc_max;
        }
    }
    printf("  DM %" PRIu64 ", RC %" PRIu64 ", NCs total %" PRIu64 " (min %" PRIu64
           ", max %" PRIu64 ", %d NCs)\n", count[0], count[1], nc_sum, nc_min, nc_max,
           ncores - ROLE_NC);
    return 0;
}
