/* virt_cpu.h: where the virt board puts its cores in the GICv3 affinity
 * layout.  QEMU groups them in clusters of VIRT_CORES_PER_CLUSTER: core k
 * has MPIDR.Aff0 = k % 16 and Aff1 = k / 16 (using Aff0 alone would give
 * cores 0 and 16 the same number). */
#ifndef LINKS1_DRIVERS_VIRT_VIRT_CPU_H
#define LINKS1_DRIVERS_VIRT_VIRT_CPU_H

#include <stdint.h>

#define VIRT_CORES_PER_CLUSTER 16

uint32_t virt_core_from_mpidr(uint32_t mpidr);
uint32_t virt_mpidr_of_core(uint32_t core);

#endif
