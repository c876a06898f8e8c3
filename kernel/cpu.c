/* cpu.c: per-core state. */
#include "kernel/cpu.h"

#include <string.h>

#include "kernel/machine.h"
#include "kernel/memlayout.h"
#include "proto/hostlink.h"

UNIT_SHARED struct cpu cpus[UNITS_MAX_CORES];
volatile uint32_t board_ncores;

void cpu_init(uint32_t core)
{
    struct cpu *c = &cpus[core];
    memset(c, 0, sizeof *c);
    c->core = core;
    c->hwid = machine_core_hwid();
    c->role = unit_role_of_core(core);
    c->current = -1;
    arch_set_cpu_ptr(c);
}

void cpu_boot_done(void)
{
    struct cpu *c = mycpu();
    c->boot_done = 1;
    if (c->core != UNITS_DM_CORE)
        machine_doorbell(UNITS_DM_CORE); /* announces the store above */
}
