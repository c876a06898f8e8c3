/* boot.c: the virt board's first C code.  Core 0 brings up the shared pieces, counts
 * the cores, and wakes the others with PSCI CPU_ON; every core then sets up
 * its own state and starts its unit computer's program. */
#include <stdint.h>

#include "drivers/imsu/imsu.h"
#include "drivers/serial/hostlink_tx.h"
#include "drivers/serial/line.h"
#include "drivers/serial/uart.h"
#include "boot/virt/psci.h"
#include "drivers/virt/gic.h"
#include "drivers/virt/virt_cpu.h"
#include "drivers/virt/virt_map.h"
#include "drivers/virt/virt_sysreg.h"
#include "kernel/arch.h"
#include "kernel/cpu.h"
#include "kernel/fdt.h"
#include "kernel/kmem.h"
#include "kernel/klog.h"
#include "kernel/ktime.h"
#include "kernel/machine.h"
#include "kernel/panic.h"
#include "kernel/param.h"
#include "kernel/task.h"
#include "roles/unit.h"

void boot_main(void) __attribute__((noreturn));
void boot_secondary(void) __attribute__((noreturn));

/* boot/virt/start.S: where the other cores begin. */
void secondary_entry(void);

/* The linker script carved memory up to __nc_pool_end: refuse to run on a
 * board given less RAM (QEMU's -m), with the numbers, rather than fault
 * later on a missing address. */
static void boot_check_ram(void)
{
    uint64_t base = 0, size = 0;
    int r = fdt_find_memory((const uint8_t *)DTB_BASE, DTB_MAX_SIZE, &base, &size);
    if (r != FDT_OK) {
        klog("cannot check the board's RAM size: %s at 0x%08x", fdt_strerror(r),
             (unsigned)DTB_BASE);
        return;
    }
    uint64_t need_end = (uintptr_t)__nc_pool_end;
    if (base != RAM_BASE || base + size < need_end)
        panic("the board has %u MiB of RAM at 0x%08x; links1 needs %u MiB from 0x%08x "
              "(qemu -m %u)",
              (unsigned)(size >> 20), (unsigned)base, (unsigned)((need_end - RAM_BASE) >> 20),
              (unsigned)RAM_BASE, (unsigned)((need_end - RAM_BASE) >> 20));
}

/* Cores on the board: PSCI AFFINITY_INFO answers INVALID_PARAMETERS for an
 * MPIDR that does not exist, so the count is known before any core wakes
 * and every core reads the same board_ncores. */
static uint32_t boot_count_cores(void)
{
    uint32_t n = 1;
    while (n < UNITS_MAX_CORES &&
           psci_call(PSCI_AFFINITY_INFO, virt_mpidr_of_core(n), 0, 0) >= 0)
        n++;
    return n;
}

/* Starts core k and sleeps until it has booted (cpu_boot_done rings this
 * core's doorbell) or halted.  One core at a time: the cores report in one
 * after the other, so none waits for the host link, and the work of a boot
 * is the same every time.  The mark is taken before CPU_ON and the first
 * wait is unconditional, so this core does the same whether the doorbell
 * comes before or after it looks.  A core slower than BOOT_CORE_WAIT_MS
 * only loses its turn: the next one starts anyway. */
static void boot_start_core(uint32_t k)
{
    const struct cpu *c = cpu_of(k);
    uint64_t deadline = ktime_deadline_ms(BOOT_CORE_WAIT_MS);
    uint32_t mark = task_event_mark();
    int r = psci_call(PSCI_CPU_ON, virt_mpidr_of_core(k), (uint32_t)(uintptr_t)secondary_entry,
                      k);
    if (r != PSCI_RET_SUCCESS) {
        klog("PSCI CPU_ON of core %u (mpidr 0x%x) failed: %d", (unsigned)k,
             (unsigned)virt_mpidr_of_core(k), r);
        return;
    }
    for (;;) {
        task_wait(mark, deadline);
        mark = task_event_mark();
        if (c->boot_done || c->halted)
            return;
        if (ktime_passed(deadline)) {
            klog("core %u has not booted within %u ms; starting the next core",
                 (unsigned)k, (unsigned)BOOT_CORE_WAIT_MS);
            return;
        }
    }
}

void boot_main(void)
{
    cpu_init(0);
    uart_init();         // PL011 on: the host link transmits from here
    hostlink_tx_init();  // log sink: klog, panics and faults reach the host
    gic_dist_init();     // interrupt distributor
    gic_cpu_init();      // this core's redistributor and CPU interface
    ktime_init();        // timer interrupt handler
    uart_rx_start();     // host link receive interrupt
    boot_check_ram();    // QEMU gave the memory the linker script carved
    uint32_t n = boot_count_cores();
    if (n < UNITS_MIN_CORES)
        panic("the board has %u core(s); links1 needs at least %u (DM, RC, one NC)",
              (unsigned)n, (unsigned)UNITS_MIN_CORES);
    board_ncores = n;
    kmem_init(0, n);     // the DM's private memory
    line_init_all(n);    // serial line rings DM<->RC, RC<->NCs
    imsu_init_all(n);    // IMSU block pair and broadcast block
    /* Everything above is in memory before any other core can look. */
    arch_dsb();
    for (uint32_t k = 1; k < n; k++)
        boot_start_core(k);
    unit_start();
}

void boot_secondary(void)
{
    uint32_t core = virt_core_from_mpidr(arch_read_mpidr());
    cpu_init(core);
    gic_cpu_init();                // redistributor and CPU interface: doorbells
                                   // wake this core from here (spinlock.h)
    kmem_init(core, board_ncores); // this unit computer's private memory
    unit_start();
}

void machine_power_off(void)
{
    psci_call(PSCI_SYSTEM_OFF, 0, 0, 0);
}
