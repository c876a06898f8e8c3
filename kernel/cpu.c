/* cpu.c: per-core state and the core-number <-> MPIDR mapping. */
#include "kernel/cpu.h"

#include <string.h>

#include "kernel/gic.h"
#include "proto/hostlink.h"

struct cpu cpus[UNITS_MAX_CORES];
volatile uint32_t board_ncores;

/* The virt board puts 16 cores in each GICv3 cluster: Aff0 = k % 16,
 * Aff1 = k / 16.  Using Aff0 alone would give cores 0 and 16 the same id. */
uint32_t cpu_core_from_mpidr(uint32_t mpidr)
{
    uint32_t aff0 = mpidr & 0xFFu;
    uint32_t aff1 = (mpidr >> 8) & 0xFFu;
    return aff1 * CORES_PER_CLUSTER + aff0;
}

uint32_t cpu_mpidr_of_core(uint32_t core)
{
    return ((core / CORES_PER_CLUSTER) << 8) | (core % CORES_PER_CLUSTER);
}

void cpu_init(uint32_t core)
{
    struct cpu *c = &cpus[core];
    memset(c, 0, sizeof *c);
    c->core = core;
    c->mpidr = arch_read_mpidr();
    c->role = unit_role_of_core(core);
    c->current = -1;
    arch_write_tpidrprw((uintptr_t)c);
}

void cpu_boot_done(void)
{
    struct cpu *c = mycpu();
    c->boot_done = 1;
    if (c->core != UNITS_DM_CORE)
        gic_send_sgi(UNITS_DM_CORE, SGI_DOORBELL); /* after the store: the DSB in it */
}
