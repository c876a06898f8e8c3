/* klog.c: LINK_LOG lines (see klog.h). */
#include "kernel/klog.h"

#include <stdarg.h>

#include "drivers/serial/hostlink_tx.h"
#include "kernel/cpu.h"
#include "proto/textfmt.h"
#include "proto/hostlink.h"

void klog(const char *fmt, ...)
{
    struct cpu *c = mycpu();
    /* Formatted in the core's own buffer: klog is never called from an
     * interrupt handler, so one buffer per core suffices. */
    int n = fmt_snprintf(c->logbuf, sizeof c->logbuf, "core %u %s: ",
                         (unsigned)c->core, cpu_role_name(c->role));
    va_list ap;
    va_start(ap, fmt);
    int m = fmt_vsnprintf(c->logbuf + n, sizeof c->logbuf - (size_t)n, fmt, ap);
    va_end(ap);
    size_t len = (size_t)n + (size_t)m;
    if (len >= sizeof c->logbuf)
        len = sizeof c->logbuf - 1;
    hostlink_send(LINK_LOG, 0, c->logbuf, len);
}
