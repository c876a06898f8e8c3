/* hostlink_tx.h: frames from the board to the host (proto/hostlink.h).
 *
 * Any core may send; one spinlock keeps each frame whole on the line and
 * numbers the frames in the order they go out.  Every numbered frame is kept
 * (proto/link_arq.h, go-back-N) until newer ones push it out, so the DM can
 * send it again when the host asks (hostlink_resend_from).  A core that
 * faults in the middle of a frame drops the lock (kernel/fault.c); the
 * host's decoder counts the cut frame, resynchronises on the next one and
 * asks for the cut one again. */
#ifndef LINKS1_DRIVERS_SERIAL_HOSTLINK_TX_H
#define LINKS1_DRIVERS_SERIAL_HOSTLINK_TX_H

#include <stddef.h>
#include <stdint.h>

/* Core 0 at boot, once the UART transmits (uart_init): registers the host
 * link as the kernel's log sink (kernel/klog.h), so klog lines, panics and
 * faults go out as LINK_LOG and LINK_FAULT frames. */
void hostlink_tx_init(void);
/* Sends one frame; returns its seq (0 for a message relayed by another
 * board: hostlink_relay.h).  Panics if len > LINK_MAX_PAYLOAD. */
uint16_t hostlink_send(uint8_t type, uint8_t flags, const void *payload, size_t len);
/* A LINK_NAK (unnumbered, not kept) naming the host frame expected next. */
void hostlink_send_nak(uint8_t flags, uint16_t expect);
/* The host's LINK_NAK for seq from: the kept frames from it on, sent again
 * (up to LINK_ARQ_RESEND_BYTES);
 * a LINK_NAK flagged LINK_FLAG_GONE when frame from is no longer kept.
 * Returns the frames sent again, or -1 for gone. */
int hostlink_resend_from(uint16_t from);
/* Frames sent again so far. */
uint32_t hostlink_resends(void);
/* LINK_RESULT: u16 cmd, i16 status, then n bytes of fields. */
void hostlink_result(uint16_t cmd, int16_t status, const void *fields, size_t n);
/* LINK_RESULT with a negative status and text naming the problem. */
void hostlink_error(uint16_t cmd, int16_t status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
