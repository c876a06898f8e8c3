/* nvic.c: interrupts on an an521 board.  Each M33 core has its own NVIC;
 * every exception the vector table (boot/an521/start.S) sends here is
 * handed to the kernel as its exception number (an521_map.h).
 *
 * Doorbells: no interrupt crosses from one board's QEMU process to
 * another's, so a unit waiting on a unit of another board is woken by its
 * own SysTick (AN521_TICK_US) and looks again; the two cores of one board
 * are woken the same way. */
#include "drivers/an521/an521_nvic.h"

#include "drivers/an521/an521_map.h"
#include "kernel/arch.h"
#include "kernel/irq.h"
#include "kernel/machine.h"

#define NVIC_ISER(n) (0xE000E100u + 4u * (n))
#define SCB_SHCSR 0xE000ED24u
/* MemManage, BusFault and UsageFault taken as themselves, not HardFault. */
#define SHCSR_FAULTS ((1u << 16) | (1u << 17) | (1u << 18))

void an521_irq_entry(void)
{
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    irq_handle(ipsr & 0x1FFu, 1);
}

void an521_nvic_enable(uint32_t irqn)
{
    mmio_write32(NVIC_ISER(irqn / 32u), 1u << (irqn % 32u));
}

void an521_faults_enable(void)
{
    mmio_write32(SCB_SHCSR, mmio_read32(SCB_SHCSR) | SHCSR_FAULTS);
}

void machine_doorbell(uint32_t core)
{
    (void)core;
    arch_dsb(); /* the writes it announces, seen at the next look */
}

void machine_lock_turn(uint32_t core)
{
    (void)core;
}

void machine_lock_turn_seen(void)
{
}
