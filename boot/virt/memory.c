/* memory.c: the private memory of each unit computer on the virt board
 * (kernel/machine.h): the DM's and the RC's carved blocks, and the NC pool
 * shared out by the number of NCs booted (linker/virt-memory.ld). */
#include <stddef.h>
#include <stdint.h>

#include "kernel/machine.h"
#include "kernel/memlayout.h"
#include "proto/units.h"

/* NC shares are whole multiples of this, so each starts page aligned. */
#define KMEM_NC_SHARE_ALIGN (64u * 1024u)

void machine_private_memory(uint32_t core, uint32_t ncores, uint8_t **base, size_t *size)
{
    if (core == 0) {
        *base = (uint8_t *)__dm_private_start;
        *size = LINKER_VALUE(LINKS1_DM_PRIVATE);
    } else if (core == 1) {
        *base = (uint8_t *)__rc_private_start;
        *size = LINKER_VALUE(LINKS1_RC_PRIVATE);
    } else {
        uint32_t ncs = ncores - UNITS_FIRST_NC;
        size_t pool = (size_t)(__nc_pool_end - __nc_pool_start);
        size_t share = (pool / ncs) & ~(size_t)(KMEM_NC_SHARE_ALIGN - 1);
        *base = (uint8_t *)__nc_pool_start + share * (core - UNITS_FIRST_NC);
        *size = share;
    }
}

