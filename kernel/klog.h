/* klog.h: readable log lines to the host (LINK_LOG frames), prefixed with
 * the core number and role so lines from many cores can be told apart. */
#ifndef LINKS1_KERNEL_KLOG_H
#define LINKS1_KERNEL_KLOG_H

void klog(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

#endif
