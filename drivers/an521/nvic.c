/* nvic.c: interrupts on an an521 board.  Each M33 core has its own NVIC;
 * every exception the vector table (boot/an521/start.S) sends here is
 * handed to the kernel as its exception number (an521_map.h).
 *
 * Doorbells: the two cores of one board ring each other through the
 * SSE-200's message handling unit (MHU0: bit 0 a doorbell, bit 1 a lock's
 * turn).  No interrupt crosses from one board's QEMU process to another's,
 * so a unit waiting on a unit of another board is woken by its own SysTick
 * (AN521_TICK_US) and looks again. */
#include "drivers/an521/an521_nvic.h"

#include "drivers/an521/an521_board.h"
#include "drivers/an521/an521_map.h"
#include "kernel/arch.h"
#include "kernel/irq.h"
#include "kernel/machine.h"

#define NVIC_ISER(n) (0xE000E100u + 4u * (n))
#define SCB_SHCSR 0xE000ED24u
/* MemManage, BusFault and UsageFault taken as themselves, not HardFault. */
#define SHCSR_FAULTS ((1u << 16) | (1u << 17) | (1u << 18))

#define MHU_DOORBELL (1u << 0)
#define MHU_LOCK_TURN (1u << 1)

void an521_irq_entry(void)
{
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    uint32_t id = ipsr & 0x1FFu;
    int is_event = 1;
    if (id == AN521_INTID_IRQ(AN521_MHU_IRQN)) {
        /* Taken: a lock's turn alone is for the lock waiter, not the tasks
         * (it is cleared when the waiter sees its turn). */
        uint32_t k = an521_local_core();
        uint32_t stat = mmio_read32(AN521_MHU_CPU_STAT(k));
        mmio_write32(AN521_MHU_CPU_CLR(k), stat & MHU_DOORBELL);
        is_event = (stat & MHU_DOORBELL) != 0;
        if (!is_event)
            mmio_write32(AN521_MHU_CPU_CLR(k), MHU_LOCK_TURN);
    }
    irq_handle(id, is_event);
}

void an521_mhu_start(void)
{
    mmio_write32(AN521_MHU_CPU_CLR(an521_local_core()), MHU_DOORBELL | MHU_LOCK_TURN);
    an521_nvic_enable(AN521_MHU_IRQN);
}

/* Rings core (a unit of this board, not this core) with bits. */
static void mhu_ring(uint32_t core, uint32_t bits)
{
    if (core / AN521_CORES_PER_BOARD != an521_board() || core == machine_core_id())
        return; /* another board's: its tick wakes it */
    arch_dsb(); /* the writes it announces, before the other core can wake */
    mmio_write32(AN521_MHU_CPU_SET(core % AN521_CORES_PER_BOARD), bits);
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
    mhu_ring(core, MHU_DOORBELL);
}

void machine_lock_turn(uint32_t core)
{
    mhu_ring(core, MHU_LOCK_TURN);
}

void machine_lock_turn_seen(void)
{
    mmio_write32(AN521_MHU_CPU_CLR(an521_local_core()), MHU_LOCK_TURN);
}
