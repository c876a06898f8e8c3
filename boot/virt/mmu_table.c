/* mmu_table.c: the first-level LPAE translation table every core uses
 * (see drivers/virt/virt_map.h for why).  Four 1 GiB block entries cover the
 * 32-bit address space; built at compile time, so the MMU can be turned on
 * before any C code runs. */
#include <stdint.h>

#include "drivers/virt/virt_map.h"

/* Long-descriptor block entry fields. */
#define PTE_BLOCK 0x1ull               /* bits[1:0] = 01: block */
#define PTE_ATTR(i) ((uint64_t)(i) << 2) /* MAIR index (boot/virt/start.S) */
#define PTE_ATTR_NORMAL PTE_ATTR(0)
#define PTE_ATTR_DEVICE PTE_ATTR(1)
#define PTE_AP_RW_PL1 (0ull << 6)
#define PTE_SH_INNER (3ull << 8)
#define PTE_AF (1ull << 10)            /* accessed: no access-flag faults */
#define PTE_PXN (1ull << 53)
#define PTE_XN (1ull << 54)
#define PTE_INVALID 0ull

#define PTE_DEVICE(pa) ((uint64_t)(pa) | PTE_BLOCK | PTE_ATTR_DEVICE | PTE_AP_RW_PL1 | \
                        PTE_AF | PTE_PXN | PTE_XN)
#define PTE_RAM(pa) ((uint64_t)(pa) | PTE_BLOCK | PTE_ATTR_NORMAL | PTE_AP_RW_PL1 | \
                     PTE_SH_INNER | PTE_AF)

/* With TTBCR.T0SZ = 0 the first-level table has 4 entries and must be
 * aligned to its 32-byte size. */
const uint64_t mmu_l1_table[4] __attribute__((aligned(32))) = {
    PTE_DEVICE(0x00000000u),      /* 0x00000000: devices (GIC, UART, ...) */
    PTE_RAM(RAM_BASE),            /* 0x40000000: RAM */
    PTE_INVALID,                  /* 0x80000000: unmapped, faults */
    PTE_DEVICE(GICR_HIGH_PHYS),   /* 0xC0000000: high redistributors */
};
