/* param.h: every limit of the firmware in one place.
 *
 * Memory sizes that the linker carves (stacks, line rings, IMSU blocks,
 * private memory) are defined once in linker/virt-memory.ld and reached
 * through kernel/memlayout.h; the values here are the ones C needs at
 * compile time, and the linker script includes this file for them (so it
 * must hold #defines only). */
#ifndef LINKS1_KERNEL_PARAM_H
#define LINKS1_KERNEL_PARAM_H

/* Cores (= unit computers) and their roles: proto/units.h, shared with the
 * linker script and the host tools. */
#include "proto/units.h"

/* Interrupt ids the handler table covers (kernel/irq.h); on the virt
 * board the 16 SGIs, 16 PPIs (the timer is 30) and the first 32 SPIs (the
 * UART is 33). */
#define IRQ_MAX 64

/* Spinlocks one core may hold at once (nesting depth). */
#define LOCKS_HELD_MAX 8

/* Cooperative tasks per core, and the stack each task gets from its unit
 * computer's private memory. */
#define TASKS_PER_CORE 4
/* 24 KiB: the double renderer (the double firmware's, and the wide one an
 * escalating NC runs) needs about 20 KiB at max_depth 16 (render/limits.h);
 * with 16 KiB the DM refused a max_depth over 12 there. */
#define TASK_STACK_SIZE (24 * 1024)
#define TASK_NAME_MAX 16

/* Host UART receive ring: must hold a full window of host DATA frames
 * (LINK_DATA_WINDOW frames of LINK_DATA_CHUNK bytes) plus a command. */
#define UART_RX_RING_SIZE (16 * 1024)

/* While the UART is polled (bulk uploads), how often the reader looks;
 * the 16-byte FIFO must not sit full for long. */
#define UART_RX_POLL_US 50

/* Frames the DM's link receiver may queue for the command task (bytes of
 * queued frame records, power of two). */
#define DM_FRAME_QUEUE_SIZE (32 * 1024)

/* Inter-unit serial lines: one ring per direction per line, power of two.
 * The linker script carves the rings with this size. */
#define LINE_RING_SIZE (8 * 1024)
/* Largest payload of one inter-unit message. */
#define LINE_MAX_PAYLOAD 1024

/* Log text of one LINK_LOG frame / one panic message. */
#define KLOG_MAX 288

/* Timeouts (milliseconds of the generic timer). */
#define BOOT_CORE_WAIT_MS 2000    /* core 0 waiting for one core to boot */
#define PING_TIMEOUT_MS 2000      /* one ping-pong round over all lines */
#define REPLY_TIMEOUT_MS 10000    /* a unit computer answering a request */
#define STRESS_STALL_MS 10000     /* a stress run making no progress at all */
#define LINK_ACK_TIMEOUT_MS 20000 /* the host acknowledging DATA */

/* IMSU self-test sizes: the pair test moves this much each way, the
 * broadcast test this much to every NC (a slice of the carved blocks, so a
 * 254-NC board finishes in seconds). */
#define IMSU_TEST_PAIR_BYTES (1024 * 1024)
#define IMSU_TEST_BCAST_BYTES (256 * 1024)

/* Largest CMD_LINE_STRESS run the DM accepts (MiB). */
#define STRESS_MAX_MIB 4096

/* Rendering pipeline (roles/gigs.h).  The RC tells the DM (and the DM the
 * host) how far a frame is at most this often. */
#define GIGS_PROGRESS_MS 200
/* How often a waiting RC looks whether an NC halted (a fault), and how
 * often its collector looks whether the frame was abandoned. */
#define GIGS_WATCH_MS 1000
/* Stack the NC's rendering needs besides RENDER_STACK_BYTES(max_depth):
 * render_area's frame and the NC's own calls. */
#define GIGS_NC_STACK_MARGIN 1024
/* The RC's watchdog over each NC (roles/rc_nc.c): an NC that holds an
 * area longer than GIGS_WATCH_FACTOR times the area's expected time (its
 * pixels times the slowest time per pixel of an area finished this frame)
 * plus GIGS_WATCH_FLOOR_MS, or that does not answer a start or stop within
 * GIGS_WATCH_FLOOR_MS, and whose progress word (+1 per pixel) has stood
 * still for GIGS_WATCH_FLOOR_MS, has failed; its area goes to another NC.
 * The floor covers an emulated core that the host did not run for a while. */
#define GIGS_WATCH_FACTOR 4
#define GIGS_WATCH_FLOOR_MS 3000
/* ... and while its word stood still, the others' words moved on by this
 * many pixels: the guest ran, so a loaded host (every core slow alike) is
 * never taken for a failure.  An NC whose peers are all idle (the frame's
 * last area) is judged by time alone after GIGS_WATCH_ALONE_MS. */
#define GIGS_WATCH_PEER_PIXELS 1024
#define GIGS_WATCH_ALONE_MS 20000
#define GIGS_WATCH_FIRST_MS 20000 /* an area before any area finished */
#endif
