/* uart.c: the host link's receive ring and transmit (see uart.h), over
 * the machine's UART registers (uart_hw.h). */
#include "drivers/serial/uart.h"

#include "drivers/serial/uart_hw.h"
#include "kernel/param.h"
#include "kernel/ringbuf.h"
#include "kernel/spinlock.h"

static uint8_t uart_rx_storage[UART_RX_RING_SIZE];
static struct ringbuf uart_rx_ring;
static volatile int uart_rx_masked;  /* 1 while receive is paused (ring full) */
static uint32_t uart_rx_pause_count; /* times it was paused */
static volatile int uart_rx_polling; /* 1: interrupts off, uart_rx_read polls */

void uart_init(void)
{
    ringbuf_init(&uart_rx_ring, uart_rx_storage, sizeof uart_rx_storage);
    uart_hw_init();
}

static void uart_irq(void *arg);

void uart_rx_start(void)
{
    uart_hw_rx_irq_start(uart_irq);
}

/* Moves received bytes from the device into the ring until it has none or
 * the ring is full (then the receive interrupt is turned off).  Runs with
 * interrupts masked on the UART's core. */
static void uart_rx_drain(void)
{
    while (uart_hw_rx_ready()) {
        if (ringbuf_free(&uart_rx_ring) == 0) {
            /* Full: leave the rest in the device (and QEMU's chardev) and
             * stop interrupting until the reader makes room. */
            uart_hw_rx_irq_enable(0);
            uart_rx_masked = 1;
            uart_rx_pause_count++;
            break;
        }
        ringbuf_put_byte(&uart_rx_ring, uart_hw_rx_byte());
    }
}

/* The receive interrupt (registered by uart_rx_start). */
static void uart_irq(void *arg)
{
    (void)arg;
    /* Clear first, then drain: a byte that arrives after the device reads
     * empty raises the interrupt again.  Clearing after the drain could
     * swallow the interrupt of a byte that came in between (QEMU's PL011
     * raises it only when its FIFO goes from empty to non-empty). */
    uart_hw_rx_irq_clear();
    uart_rx_drain();
}

void uart_rx_set_polling(int on)
{
    irq_push_off();
    uart_rx_polling = on;
    if (on) {
        uart_hw_rx_irq_enable(0);
    } else {
        uart_hw_rx_irq_clear();
        uart_rx_drain();
        if (!uart_rx_masked)
            uart_hw_rx_irq_enable(1);
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
         * against it.  Bytes left in the device while paused raise no new
         * interrupt, so take them here before turning it back on. */
        irq_push_off();
        uart_rx_masked = 0;
        uart_hw_rx_irq_clear();
        uart_rx_drain();
        if (!uart_rx_masked && !uart_rx_polling)
            uart_hw_rx_irq_enable(1);
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

void uart_write(const uint8_t *p, size_t n)
{
    uart_hw_write(p, n);
}

void uart_tx_drain(void)
{
    uart_hw_tx_drain();
}
