/* links1_params.h: every limit and default of the host tool in one place. */
#ifndef LINKS1_HOST_PARAMS_H
#define LINKS1_HOST_PARAMS_H

/* The board's core counts (UNITS_MIN_CORES..UNITS_MAX_CORES) are the
 * firmware's own, in proto/units.h. */
#include "proto/board_map.h"
#include "proto/units.h"
#define BOARD_DEFAULT_CORES 10
#define BOARD_DEFAULT_RAM_MB BOARD_RAM_MB /* what the firmware carves */
#define BOARD_MIN_RAM_MB 64
#define BOARD_MAX_RAM_MB 2048 /* the virt board's 32-bit RAM window below 4 GiB */

/* Default seconds to wait for every unit computer to report in.  256 cores
 * start one after another under emulation on two host cores, so this is
 * generous. */
#define BOARD_DEFAULT_TIMEOUT_S 60
#define BOARD_MAX_TIMEOUT_S 3600

/* Milliseconds to wait for one answer frame (a command's result, a DATA or
 * ACK frame of a transfer) before calling the board unresponsive. */
#define BOARD_FRAME_TIMEOUT_MS 20000
/* Long commands (the inter-unit stress run) get this many ms per MiB. */
#define BOARD_STRESS_MS_PER_MIB 4000

/* A session on a named board waits this long for the board's first answer
 * (it may be finishing a command of a session that went away). */
#define BOARD_SESSION_WAIT_MS 60000

/* Clean stop: wait this long for QEMU to exit after CMD_SHUTDOWN, then send
 * SIGTERM and wait again, and only then SIGKILL. */
#define BOARD_SHUTDOWN_WAIT_MS 5000
#define BOARD_TERM_WAIT_MS 3000

/* Frames other than LOG/HELLO/FAULT wait here until someone asks for them;
 * a transfer keeps at most LINK_DATA_WINDOW DATA frames in flight, so a
 * full queue means the board broke the window. */
#define BOARD_FRAME_QUEUE 32
/* Faults remembered for the caller to check (all are printed). */
#define BOARD_MAX_FAULTS 64
/* Bytes of each remembered fault's text kept (with the terminator). */
#define BOARD_FAULT_TEXT 256
/* Bytes read from the link per read() call, and the pause (microseconds)
 * after a wake-up that lets bytes gather before reading. */
#define BOARD_READ_CHUNK 4096
/* --link-noise: the send buffer of each socket towards the board around the
 * relay (the kernel doubles it). */
#define BOARD_RELAY_SNDBUF 4096
#define BOARD_READ_BATCH_US 200

/* Link tests: bytes each way through the host link, MiB through the
 * inter-unit lines (issue minimums: 8 MiB and 64 MiB). */
#define SELFTEST_LINK_BYTES (8u << 20)
#define SELFTEST_STRESS_MIB 64u
/* Most a selftest run accepts, so a typo cannot start an hours-long run. */
#define SELFTEST_MAX_STRESS_MIB 4096u
#define SELFTEST_MAX_LINK_BYTES (1024u << 20)
/* Checks named in one selftest run, and the size of a check's one-line verdict. */
#define SELFTEST_MAX_RUN 16
#define SELFTEST_WHY_SIZE 512
/* Idle test: settle after report-in, then count each core's guest
 * instructions over a span (samples from the counting plugin every
 * SAMPLE_MS; the sample after the span may come this much LATE at most).
 * An idle core sleeps in WFI and retires nothing; a spinning one retires
 * millions per second even on a loaded host. */
#define SELFTEST_IDLE_SETTLE_MS 1000
#define SELFTEST_IDLE_SECONDS 5
#define SELFTEST_IDLE_SAMPLE_MS 200
#define SELFTEST_IDLE_LATE_MS 20000
#define SELFTEST_IDLE_MAX_INSNS 10000u /* per idle core per second */
#define SELFTEST_MAX_IDLE_INSNS 1000000000u /* most --max-insns accepts */

/* links1 render: NCs when --ncs is not given (a 10-core board), and the
 * most milliseconds the board may stay silent while a frame renders (no
 * progress frame, no result) before the host gives up: one area of a big
 * scene on one NC can take minutes under emulation. */
#define RENDER_DEFAULT_NCS 8
#define RENDER_SILENCE_MS (20 * 60 * 1000)
/* How often the terminal's progress line is redrawn at most. */
#define RENDER_PROGRESS_REDRAW_MS 250
/* Characters of the progress line's bar. */
#define RENDER_PROGRESS_BAR 30

/* The instruction-counting plugin's per-vCPU table. */
#define INSN_COUNT_MAX_VCPUS UNITS_MAX_CORES

#endif
