/* boot.c: an an521 board's first C code.
 *
 * Core 0 of every board learns which board it is and how many are joined,
 * then brings up its own board: the UART, the timer, this core's tick.
 * Board 0 sets up the blocks every board shares (the lines, the IMSU) and
 * says so in the shared file's header; the other boards wait for that
 * before their units start.  Core 0 then lets core 1 go, and both start
 * their unit computers: the DM and the RC on board 0, two NCs elsewhere. */
#include <stdint.h>

#include "drivers/an521/an521_board.h"
#include "drivers/an521/an521_map.h"
#include "drivers/an521/an521_nvic.h"
#include "drivers/an521/an521_relay.h"
#include "drivers/an521/an521_timer.h"
#include "drivers/imsu/imsu.h"
#include "drivers/serial/hostlink_tx.h"
#include "drivers/serial/line.h"
#include "drivers/serial/uart.h"
#include "kernel/arch.h"
#include "kernel/cpu.h"
#include "kernel/klog.h"
#include "kernel/kmem.h"
#include "kernel/ktime.h"
#include "kernel/machine.h"
#include "kernel/memlayout.h"
#include "kernel/panic.h"
#include "kernel/param.h"
#include "kernel/task.h"
#include "roles/unit.h"

/* linker/an521-memory.ld: where the cores' private memory starts, and
 * how much each core has (an absolute symbol). */
extern char __an521_private_start[], AN521_PRIVATE_EACH[];
extern char __an521_dm_start[], AN521_DM_PRIVATE[];
extern char __an521_rc_start[], AN521_RC_PRIVATE[];

void boot_main(void) __attribute__((noreturn));
void boot_secondary(void) __attribute__((noreturn));

/* A board that cannot join stops here: with no per-core state yet there is
 * no way to report, and the host sees its HELLO never come. */
static void boot_stop(void) __attribute__((noreturn));
static void boot_stop(void)
{
    cpu_halt_forever();
}

/* The other boards: sleeps, a tick at a time, until board 0 has set up the
 * shared blocks. */
static void boot_wait_shared(void)
{
    while (!an521_shared_is_ready()) {
        uint32_t mark = task_event_mark();
        task_wait(mark, ktime_deadline_ms(1));
    }
}

void boot_main(void)
{
    if (an521_board_probe())
        boot_stop();
    uint32_t core = machine_core_id();
    cpu_init(core);
    an521_faults_enable();
    uart_init();          // board 0's carries the host link; the others' goes nowhere
    hostlink_tx_init();   // log sink: klog, panics, faults (relayed off board 0)
    ktime_init();         // the board's counter and the tick's handler
    an521_tick_start();
    an521_mhu_start();
    cpu_of(core)->wake_ready = 1;
    uint32_t n = an521_boards() * AN521_CORES_PER_BOARD;
    board_ncores = n;
    kmem_init(core, n);
    if (an521_board() == 0) {
        uart_rx_start();  // host link receive interrupt
        line_init_all(n); // serial line rings DM<->RC, RC<->NCs, in the shared file
        imsu_init_all(n); // IMSU block pair and broadcast block, likewise
        an521_shared_ready();
        an521_relay_start();
    } else {
        boot_wait_shared();
    }
    arch_dsb();
    /* Core 1: its vector table is this image's (INITSVTOR1's reset value),
     * and clearing CPUWAIT lets it run. */
    mmio_write32(AN521_SYSCTL_CPUWAIT, 0);
    unit_start();
}

void boot_secondary(void)
{
    uint32_t core = machine_core_id();
    cpu_init(core);
    an521_faults_enable();
    an521_tick_start();
    an521_mhu_start();
    cpu_of(core)->wake_ready = 1;
    kmem_init(core, board_ncores);
    unit_start();
}

/* The Application Interrupt and Reset Control Register: a system reset
 * request, which QEMU run with -no-reboot (as links1 starts every board)
 * takes as the end of the run. */
#define SCB_AIRCR 0xE000ED0Cu
#define AIRCR_VECTKEY (0x05FAu << 16)
#define AIRCR_SYSRESETREQ (1u << 2)

void machine_power_off(void)
{
    /* Board 0 ends its own process; the host ends the NC boards'. */
    arch_dsb();
    mmio_write32(SCB_AIRCR, AIRCR_VECTKEY | AIRCR_SYSRESETREQ);
    arch_dsb();
    for (int i = 0; i < 1000; i++)
        arch_wfi(); /* the request takes effect between instructions */
}

void machine_private_memory(uint32_t core, uint32_t ncores, uint8_t **base, size_t *size)
{
    (void)ncores;
    if (core == UNITS_DM_CORE) {
        /* In the shared file: the host link's bulk bytes land there. */
        *base = (uint8_t *)__an521_dm_start;
        *size = LINKER_VALUE(AN521_DM_PRIVATE);
        return;
    }
    if (core == UNITS_RC_CORE) {
        /* Likewise: the host pulls frames from the RC's frame memory. */
        *base = (uint8_t *)__an521_rc_start;
        *size = LINKER_VALUE(AN521_RC_PRIVATE);
        return;
    }
    size_t each = LINKER_VALUE(AN521_PRIVATE_EACH);
    *base = (uint8_t *)__an521_private_start + each * (core % AN521_CORES_PER_BOARD);
    *size = each;
}
