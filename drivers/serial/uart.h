/* uart.h: the UART that carries the host link (its registers are the
 * machine's: uart_hw.h).
 *
 * Receive is interrupt driven: the handler (on core 0, where the UART's
 * interrupt is routed) moves bytes from the device (the PL011's 16-byte
 * FIFO) into a ring of UART_RX_RING_SIZE bytes.  When the ring is full the handler masks the
 * receive interrupt instead of dropping bytes: the FIFO then fills, QEMU
 * stops taking bytes from the chardev and the host's writes wait.  Taking
 * bytes out of the ring unmasks it again.  Transmit is polled; callers
 * serialise whole frames (drivers/serial/hostlink_tx.h). */
#ifndef LINKS1_DRIVERS_SERIAL_UART_H
#define LINKS1_DRIVERS_SERIAL_UART_H

#include <stddef.h>
#include <stdint.h>

/* Core 0, once, first thing: line settings, FIFOs, transmit and receive
 * on.  Needs no interrupt controller, so the host link can carry the
 * earliest panics. */
void uart_init(void);
/* Core 0, once interrupts are set up: registers the receive interrupt's
 * handler (kernel/irq.h) and routes the interrupt to core 0. */
void uart_rx_start(void);
/* Bulk mode for long host uploads: with on = 1 the receive interrupt stays
 * off and uart_rx_read() moves what the FIFO holds itself; the reader
 * calls it every UART_RX_POLL_US.  Each received byte then costs two
 * register reads instead of an interrupt's six register accesses and two
 * changes of the interrupt line. */
void uart_rx_set_polling(int on);
int uart_rx_is_polling(void);
/* Takes up to max received bytes; returns how many (0 if none yet). */
uint32_t uart_rx_read(uint8_t *out, uint32_t max);
/* Bytes waiting in the receive ring. */
uint32_t uart_rx_pending(void);
/* Times the ring filled and receive was paused (statistics). */
uint32_t uart_rx_pauses(void);
/* Sends n bytes, filling the transmit FIFO a burst at a time. */
void uart_write(const uint8_t *p, size_t n);
/* Waits until everything written has left the transmitter. */
void uart_tx_drain(void);

#endif
