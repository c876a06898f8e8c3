/* virt_cpu.c: core numbers from MPIDR (see virt_cpu.h), and the machine's
 * names of this core (kernel/machine.h). */
#include "drivers/virt/virt_cpu.h"

#include "drivers/virt/virt_sysreg.h"
#include "kernel/machine.h"

uint32_t virt_core_from_mpidr(uint32_t mpidr)
{
    uint32_t aff0 = mpidr & 0xFFu;
    uint32_t aff1 = (mpidr >> 8) & 0xFFu;
    return aff1 * VIRT_CORES_PER_CLUSTER + aff0;
}

uint32_t virt_mpidr_of_core(uint32_t core)
{
    return ((core / VIRT_CORES_PER_CLUSTER) << 8) | (core % VIRT_CORES_PER_CLUSTER);
}

uint32_t machine_core_id(void)
{
    return virt_core_from_mpidr(arch_read_mpidr());
}

uint32_t machine_core_hwid(void)
{
    return arch_read_mpidr();
}
