/* uart.c: PL011 driver (see uart.h). */
#include "drivers/serial/uart.h"

#include "drivers/virt/gic.h"
#include "drivers/virt/virt_map.h"

#include <stddef.h>

#include "kernel/arch.h"
#include "kernel/irq.h"
#include "kernel/param.h"
#include "kernel/ringbuf.h"
#include "kernel/spinlock.h"

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

/* The UART's own core: its interrupt goes there and only it reads. */
#define UART_RX_CORE 0

static uint8_t uart_rx_storage[UART_RX_RING_SIZE];
static struct ringbuf uart_rx_ring;
static volatile int uart_rx_masked;  /* 1 while receive is paused (ring full) */
static uint32_t uart_rx_pause_count; /* times it was paused */
static volatile int uart_rx_polling; /* 1: interrupts off, uart_rx_read polls */

void uart_init(void)
{
    uintptr_t b = UART0_BASE;
    ringbuf_init(&uart_rx_ring, uart_rx_storage, sizeof uart_rx_storage);
    mmio_write32(UART_CR(b), 0);
    mmio_write32(UART_ICR(b), UART_INT_ALL);
    mmio_write32(UART_LCR_H(b), UART_LCR_H_FEN | UART_LCR_H_WLEN_8);
    mmio_write32(UART_IMSC(b), UART_INT_RX | UART_INT_RT);
    mmio_write32(UART_CR(b), UART_CR_UARTEN | UART_CR_TXE | UART_CR_RXE);
}

static void uart_irq(void *arg);

void uart_rx_start(void)
{
    irq_register(UART0_INTID, uart_irq, NULL);
    gic_route_spi(UART0_INTID, UART_RX_CORE);
}

/* Moves received bytes from the FIFO into the ring until the FIFO is empty
 * or the ring is full (then receive interrupts are masked).  Runs with
 * interrupts masked on the UART's core. */
static void uart_rx_drain(void)
{
    uintptr_t b = UART0_BASE;
    while (!(mmio_read32(UART_FR(b)) & UART_FR_RXFE)) {
        if (ringbuf_free(&uart_rx_ring) == 0) {
            /* Full: leave the rest in the FIFO (and QEMU's chardev) and
             * stop interrupting until the reader makes room. */
            mmio_write32(UART_IMSC(b), 0);
            uart_rx_masked = 1;
            uart_rx_pause_count++;
            break;
        }
        ringbuf_put_byte(&uart_rx_ring,
                         (uint8_t)(mmio_read32(UART_DR(b)) & UART_DR_DATA_MASK));
    }
}

/* The receive interrupt (registered by uart_rx_start). */
static void uart_irq(void *arg)
{
    (void)arg;
    /* Clear first, then drain: a byte that arrives after the FIFO reads
     * empty raises the interrupt again.  Clearing after the drain could
     * swallow the interrupt of a byte that came in between, and QEMU's
     * PL011 raises it only when the FIFO goes from empty to non-empty. */
    mmio_write32(UART_ICR(UART0_BASE), UART_INT_RX | UART_INT_RT);
    uart_rx_drain();
}

void uart_rx_set_polling(int on)
{
    irq_push_off();
    uart_rx_polling = on;
    if (on) {
        mmio_write32(UART_IMSC(UART0_BASE), 0);
    } else {
        mmio_write32(UART_ICR(UART0_BASE), UART_INT_RX | UART_INT_RT);
        uart_rx_drain();
        if (!uart_rx_masked)
            mmio_write32(UART_IMSC(UART0_BASE), UART_INT_RX | UART_INT_RT);
    }
    irq_pop_off();
}

uint32_t uart_rx_read(uint8_t *out, uint32_t max)
{
    if (uart_rx_polling && !uart_rx_masked) {
        irq_push_off();
        uart_rx_drain();
        irq_pop_off();
    }
    uint32_t n = ringbuf_get_some(&uart_rx_ring, out, max);
    if (n && uart_rx_masked) {
        /* The handler runs on this core: masking interrupts orders us
         * against it.  Bytes left in the FIFO while paused raise no new
         * interrupt, so take them here before unmasking. */
        irq_push_off();
        uart_rx_masked = 0;
        mmio_write32(UART_ICR(UART0_BASE), UART_INT_RX | UART_INT_RT);
        uart_rx_drain();
        if (!uart_rx_masked && !uart_rx_polling)
            mmio_write32(UART_IMSC(UART0_BASE), UART_INT_RX | UART_INT_RT);
        irq_pop_off();
    }
    return n;
}

int uart_rx_is_polling(void)
{
    return uart_rx_polling;
}

uint32_t uart_rx_pending(void)
{
    return ringbuf_used(&uart_rx_ring);
}

uint32_t uart_rx_pauses(void)
{
    return uart_rx_pause_count;
}

void uart_putc(uint8_t c)
{
    while (mmio_read32(UART_FR(UART0_BASE)) & UART_FR_TXFF)
        ;
    mmio_write32(UART_DR(UART0_BASE), c);
}

void uart_write(const uint8_t *p, size_t n)
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

void uart_tx_drain(void)
{
    while (mmio_read32(UART_FR(UART0_BASE)) & UART_FR_BUSY)
        ;
}
