/* uart_cmsdk.c: the an521 board's host-link UART, a CMSDK APB UART
 * (uart_hw.h).  It holds one byte each way: the receive interrupt comes
 * per byte. */
#include "drivers/serial/uart_hw.h"

#include "drivers/an521/an521_map.h"
#include "drivers/an521/an521_nvic.h"
#include "kernel/arch.h"
#include "kernel/irq.h"

#define UART_DATA(b) ((b) + 0x00u)
#define UART_STATE(b) ((b) + 0x04u)
#define UART_CTRL(b) ((b) + 0x08u)
#define UART_INT(b) ((b) + 0x0Cu) /* status on read, clear on write */
#define UART_BAUDDIV(b) ((b) + 0x10u)
#define UART_STATE_TXFULL (1u << 0)
#define UART_STATE_RXFULL (1u << 1)
#define UART_CTRL_TXEN (1u << 0)
#define UART_CTRL_RXEN (1u << 1)
#define UART_CTRL_RXINT (1u << 3)
#define UART_INT_RX (1u << 1)
/* The smallest divider the device accepts (QEMU checks it): the fastest
 * line. */
#define UART_BAUDDIV_MIN 16u

void uart_hw_init(void)
{
    uintptr_t b = AN521_UART0;
    mmio_write32(UART_CTRL(b), 0);
    mmio_write32(UART_BAUDDIV(b), UART_BAUDDIV_MIN);
    mmio_write32(UART_INT(b), 0xFu);
    mmio_write32(UART_CTRL(b), UART_CTRL_TXEN | UART_CTRL_RXEN | UART_CTRL_RXINT);
}

void uart_hw_rx_irq_start(void (*fn)(void *))
{
    irq_register(AN521_INTID_IRQ(AN521_UART0_RX_IRQN), fn, 0);
    an521_nvic_enable(AN521_UART0_RX_IRQN);
}

int uart_hw_rx_ready(void)
{
    return (mmio_read32(UART_STATE(AN521_UART0)) & UART_STATE_RXFULL) != 0;
}

uint8_t uart_hw_rx_byte(void)
{
    return (uint8_t)mmio_read32(UART_DATA(AN521_UART0));
}

void uart_hw_rx_irq_enable(int on)
{
    uint32_t c = mmio_read32(UART_CTRL(AN521_UART0));
    mmio_write32(UART_CTRL(AN521_UART0), on ? c | UART_CTRL_RXINT : c & ~UART_CTRL_RXINT);
}

void uart_hw_rx_irq_clear(void)
{
    mmio_write32(UART_INT(AN521_UART0), UART_INT_RX);
}

void uart_hw_write(const uint8_t *p, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        while (mmio_read32(UART_STATE(AN521_UART0)) & UART_STATE_TXFULL)
            ;
        mmio_write32(UART_DATA(AN521_UART0), p[i]);
    }
}

void uart_hw_tx_drain(void)
{
    while (mmio_read32(UART_STATE(AN521_UART0)) & UART_STATE_TXFULL)
        ;
}
