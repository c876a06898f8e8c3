/* uart_hw.h: the registers of the machine's host-link UART, behind the
 * few calls the machine-free receive ring (drivers/serial/uart.c) and the
 * transmitter need.  One implementation per machine: drivers/virt/
 * uart_pl011.c, drivers/an521/uart_cmsdk.c.  All but uart_hw_init run on
 * the UART's core with interrupts masked where they touch receive state. */
#ifndef LINKS1_DRIVERS_SERIAL_UART_HW_H
#define LINKS1_DRIVERS_SERIAL_UART_HW_H

#include <stddef.h>
#include <stdint.h>

/* The UART's own core: its receive interrupt goes there and only it reads. */
#define UART_RX_CORE 0

/* Line settings, transmit and receive on, receive interrupt enabled at the
 * device (not yet routed). */
void uart_hw_init(void);
/* Registers fn as the receive interrupt's handler (kernel/irq.h) and
 * routes the interrupt to UART_RX_CORE. */
void uart_hw_rx_irq_start(void (*fn)(void *));
/* 1 while a received byte waits in the device. */
int uart_hw_rx_ready(void);
/* Takes one received byte (uart_hw_rx_ready said there is one). */
uint8_t uart_hw_rx_byte(void);
/* Receive interrupt at the device: on (1) or off (0). */
void uart_hw_rx_irq_enable(int on);
/* Clears a pending receive interrupt at the device. */
void uart_hw_rx_irq_clear(void);
/* Sends n bytes as fast as the device takes them. */
void uart_hw_write(const uint8_t *p, size_t n);
/* Waits until everything written has left the transmitter. */
void uart_hw_tx_drain(void);

#endif
