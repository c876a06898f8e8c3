/* hostlink_tx.c: board -> host frames (see hostlink_tx.h). */
#include "drivers/serial/hostlink_tx.h"

#include <stdarg.h>

#include "drivers/serial/hostlink_relay.h"
#include "drivers/serial/uart.h"
#include "kernel/klog.h"
#include "kernel/param.h"
#include "kernel/panic.h"
#include "kernel/spinlock.h"
#include "proto/crc32.h"
#include "proto/hostlink.h"
#include "proto/link_arq.h"
#include "proto/textfmt.h"
#include "proto/wire.h"

static struct spinlock hostlink_tx_lock = SPINLOCK_INIT("hostlink_tx");
/* Guarded by the lock: the frames kept for resending (their seqs number
 * every frame, from 0 at boot), the frame being written, the resend count. */
static struct link_arq_store hostlink_store;
static uint8_t hostlink_frame[LINK_MAX_FRAME];
static uint32_t hostlink_resent;

uint16_t hostlink_send(uint8_t type, uint8_t flags, const void *payload, size_t len)
{
    if (len > LINK_MAX_PAYLOAD)
        panic("hostlink_send: payload of %u bytes exceeds LINK_MAX_PAYLOAD %u",
              (unsigned)len, (unsigned)LINK_MAX_PAYLOAD);
    if (hostlink_relay_here()) {
        /* Numbered by the board with the link, when it sends it. */
        hostlink_relay_put(type, flags, payload, len);
        return 0;
    }
    spin_lock(&hostlink_tx_lock);
    uint16_t seq = hostlink_store.next_seq;
    size_t n = link_arq_store_frame(&hostlink_store, hostlink_frame, sizeof hostlink_frame,
                                    type, flags, payload, len);
    uart_write(hostlink_frame, n);
    spin_unlock(&hostlink_tx_lock);
    return seq;
}

void hostlink_send_nak(uint8_t flags, uint16_t expect)
{
    uint8_t f[LINK_HEADER_SIZE + LINK_ACK_SIZE + LINK_CRC_SIZE];
    size_t n = link_arq_nak_encode(f, sizeof f, flags, expect);
    spin_lock(&hostlink_tx_lock);
    uart_write(f, n);
    spin_unlock(&hostlink_tx_lock);
}

int hostlink_resend_from(uint16_t from)
{
    spin_lock(&hostlink_tx_lock);
    int span = link_arq_store_span(&hostlink_store, from);
    if (span > 0)
        span = link_arq_store_resend_count(&hostlink_store, from, span);
    for (int i = 0; i < span; i++) {
        size_t n = link_arq_store_get(&hostlink_store, (uint16_t)(from + i), hostlink_frame,
                                      sizeof hostlink_frame);
        uart_write(hostlink_frame, n);
    }
    if (span > 0)
        hostlink_resent += (uint32_t)span;
    spin_unlock(&hostlink_tx_lock);
    if (span < 0)
        hostlink_send_nak(LINK_FLAG_GONE, from);
    return span;
}

uint32_t hostlink_resends(void)
{
    return hostlink_resent;
}

void hostlink_result(uint16_t cmd, int16_t status, const void *fields, size_t n)
{
    uint8_t p[LINK_MAX_PAYLOAD];
    if (n > sizeof p - 4)
        n = sizeof p - 4;
    wire_put_u16(p, cmd);
    wire_put_u16(p + 2, (uint16_t)status);
    const uint8_t *f = fields;
    for (size_t i = 0; i < n; i++)
        p[4 + i] = f[i];
    hostlink_send(LINK_RESULT, 0, p, 4 + n);
}

void hostlink_error(uint16_t cmd, int16_t status, const char *fmt, ...)
{
    char text[KLOG_MAX];
    va_list ap;
    va_start(ap, fmt);
    int n = fmt_vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (n >= (int)sizeof text)
        n = (int)sizeof text - 1;
    hostlink_result(cmd, status, text, (size_t)n);
}

/* The kernel's log sink: klog lines and fault reports. */
static void hostlink_log_sink(uint8_t type, const void *payload, size_t len)
{
    hostlink_send(type, 0, payload, len);
}

void hostlink_tx_init(void)
{
    klog_set_sink(hostlink_log_sink);
}
