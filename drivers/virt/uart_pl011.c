/* uart_pl011.c: the virt board's host-link UART, a PL011 (uart_hw.h). */
#include "drivers/serial/uart_hw.h"

#include "drivers/virt/gic.h"
#include "drivers/virt/virt_map.h"

#include <stddef.h>

#include "kernel/arch.h"
#include "kernel/irq.h"

/* PL011 registers and bits. */
#define UART_DR(b) ((b) + 0x000u)
#define UART_FR(b) ((b) + 0x018u)
#define UART_FR_BUSY (1u << 3)
#define UART_FR_RXFE (1u << 4)
#define UART_FR_TXFF (1u << 5)
#define UART_FR_TXFE (1u << 7)
#define UART_FIFO_DEPTH 16u
#define UART_LCR_H(b) ((b) + 0x02Cu)
#define UART_LCR_H_FEN (1u << 4)
#define UART_LCR_H_WLEN_8 (3u << 5)
#define UART_CR(b) ((b) + 0x030u)
#define UART_CR_UARTEN (1u << 0)
#define UART_CR_TXE (1u << 8)
#define UART_CR_RXE (1u << 9)
#define UART_IMSC(b) ((b) + 0x038u)
#define UART_ICR(b) ((b) + 0x044u)
#define UART_INT_RX (1u << 4)
#define UART_INT_RT (1u << 6) /* receive timeout: FIFO not empty, line idle */
#define UART_INT_ALL 0x7FFu
#define UART_DR_DATA_MASK 0xFFu

#define UART_RX_INTS (UART_INT_RX | UART_INT_RT)

void uart_hw_init(void)
{
    uintptr_t b = UART0_BASE;
    mmio_write32(UART_CR(b), 0);
    mmio_write32(UART_ICR(b), UART_INT_ALL);
    mmio_write32(UART_LCR_H(b), UART_LCR_H_FEN | UART_LCR_H_WLEN_8);
    mmio_write32(UART_IMSC(b), UART_RX_INTS);
    mmio_write32(UART_CR(b), UART_CR_UARTEN | UART_CR_TXE | UART_CR_RXE);
}

void uart_hw_rx_irq_start(void (*fn)(void *))
{
    irq_register(UART0_INTID, fn, NULL);
    gic_route_spi(UART0_INTID, UART_RX_CORE);
}

int uart_hw_rx_ready(void)
{
    return !(mmio_read32(UART_FR(UART0_BASE)) & UART_FR_RXFE);
}

uint8_t uart_hw_rx_byte(void)
{
    return (uint8_t)(mmio_read32(UART_DR(UART0_BASE)) & UART_DR_DATA_MASK);
}

void uart_hw_rx_irq_enable(int on)
{
    mmio_write32(UART_IMSC(UART0_BASE), on ? UART_RX_INTS : 0);
}

void uart_hw_rx_irq_clear(void)
{
    mmio_write32(UART_ICR(UART0_BASE), UART_RX_INTS);
}

void uart_hw_write(const uint8_t *p, size_t n)
{
    /* Once the FIFO reads empty it takes UART_FIFO_DEPTH bytes without
     * further polling: one status read per 16 bytes instead of per byte
     * (each register access is a trip into the emulator). */
    while (n) {
        while (!(mmio_read32(UART_FR(UART0_BASE)) & UART_FR_TXFE))
            ;
        size_t k = n < UART_FIFO_DEPTH ? n : UART_FIFO_DEPTH;
        for (size_t i = 0; i < k; i++)
            mmio_write32(UART_DR(UART0_BASE), p[i]);
        p += k;
        n -= k;
    }
}

void uart_hw_tx_drain(void)
{
    while (mmio_read32(UART_FR(UART0_BASE)) & UART_FR_BUSY)
        ;
}
