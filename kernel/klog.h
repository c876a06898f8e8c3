/* klog.h: readable log lines to the host (LINK_LOG frames), prefixed with
 * the core number and role so lines from many cores can be told apart,
 * and the log sink they leave the kernel through.
 *
 * The kernel knows no device.  A driver registers the sink, one function
 * that sends a frame of the host link (drivers/serial/hostlink_tx.c does,
 * as xv6's uart serves its console); klog() lines and the panic and fault
 * reports (kernel/fault.c: LINK_FAULT, then LINK_LOG) all go through it.
 *
 * Before a sink is registered output is dropped, not buffered: a core that
 * panics that early halts, so nothing would ever send a buffer.  The drops
 * are counted and reported in one line once the sink registers; the boot
 * code registers it before anything that can panic, so in practice none is
 * lost. */
#ifndef LINKS1_KERNEL_KLOG_H
#define LINKS1_KERNEL_KLOG_H

#include <stddef.h>
#include <stdint.h>

/* Sends one host link frame (type, payload); must be callable from any
 * core, with interrupts masked, and from the fault path. */
typedef void (*klog_sink_fn)(uint8_t type, const void *payload, size_t len);

/* Core 0 at boot, once, before it wakes the other cores. */
void klog_set_sink(klog_sink_fn fn);
/* Hands one frame to the sink (or drops and counts it while none is set). */
void klog_emit(uint8_t type, const void *payload, size_t len);

void klog(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

#endif
