/* klog.c: LINK_LOG lines and the log sink (see klog.h). */
#include "kernel/klog.h"

#include <stdarg.h>

#include "kernel/cpu.h"
#include "proto/hostlink.h"
#include "proto/textfmt.h"

static klog_sink_fn klog_sink;
static volatile uint32_t klog_dropped; /* frames emitted before the sink */

void klog_emit(uint8_t type, const void *payload, size_t len)
{
    klog_sink_fn sink = klog_sink;
    if (!sink) {
        __atomic_fetch_add(&klog_dropped, 1u, __ATOMIC_RELAXED);
        return;
    }
    sink(type, payload, len);
}

void klog_set_sink(klog_sink_fn fn)
{
    klog_sink = fn;
    if (klog_dropped)
        klog("%u log frame(s) dropped before the log sink was registered",
             (unsigned)klog_dropped);
}

void klog(const char *fmt, ...)
{
    struct cpu *c = mycpu();
    /* Formatted in the core's own buffer: klog is never called from an
     * interrupt handler, so one buffer per core suffices. */
    int n = fmt_snprintf(c->logbuf, sizeof c->logbuf, "core %u %s: ",
                         (unsigned)c->core, unit_role_name(c->role));
    va_list ap;
    va_start(ap, fmt);
    int m = fmt_vsnprintf(c->logbuf + n, sizeof c->logbuf - (size_t)n, fmt, ap);
    va_end(ap);
    size_t len = (size_t)n + (size_t)m;
    if (len >= sizeof c->logbuf)
        len = sizeof c->logbuf - 1;
    klog_emit(LINK_LOG, c->logbuf, len);
}
