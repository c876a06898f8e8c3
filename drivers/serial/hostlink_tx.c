/* hostlink_tx.c: board -> host frames (see hostlink_tx.h). */
#include "drivers/serial/hostlink_tx.h"

#include <stdarg.h>

#include "drivers/serial/uart.h"
#include "kernel/klog.h"
#include "kernel/param.h"
#include "kernel/panic.h"
#include "kernel/spinlock.h"
#include "proto/crc32.h"
#include "proto/hostlink.h"
#include "proto/textfmt.h"
#include "proto/wire.h"

static struct spinlock hostlink_tx_lock = SPINLOCK_INIT("hostlink_tx");
static uint16_t hostlink_tx_seq; /* next frame's seq; guarded by the lock */

static void hostlink_put_bytes(const uint8_t *p, size_t n)
{
    uart_write(p, n);
}

uint16_t hostlink_send(uint8_t type, uint8_t flags, const void *payload, size_t len)
{
    if (len > LINK_MAX_PAYLOAD)
        panic("hostlink_send: payload of %u bytes exceeds LINK_MAX_PAYLOAD %u",
              (unsigned)len, (unsigned)LINK_MAX_PAYLOAD);
    uint8_t hdr[LINK_HEADER_SIZE];
    hdr[0] = LINK_SYNC0;
    hdr[1] = LINK_SYNC1;
    hdr[2] = type;
    hdr[3] = flags;
    wire_put_u16(hdr + 6, (uint16_t)len);
    spin_lock(&hostlink_tx_lock);
    uint16_t seq = hostlink_tx_seq++;
    wire_put_u16(hdr + 4, seq);
    /* The CRC covers type through payload, computed as the bytes go out
     * so no frame-sized buffer is needed. */
    uint32_t crc = crc32_update(0, hdr + 2, LINK_HEADER_SIZE - 2);
    crc = crc32_update(crc, payload, len);
    uint8_t tail[LINK_CRC_SIZE];
    wire_put_u32(tail, crc);
    hostlink_put_bytes(hdr, sizeof hdr);
    hostlink_put_bytes(payload, len);
    hostlink_put_bytes(tail, sizeof tail);
    spin_unlock(&hostlink_tx_lock);
    return seq;
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
