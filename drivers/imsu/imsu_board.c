/* imsu_board.c: the board's IMSUs, in the memory linker/virt-memory.ld
 * carved for them: the DM<->RC block pair and the RC->NCs broadcast block. */
#include "drivers/imsu/imsu.h"

#include "kernel/memlayout.h"
#include "kernel/param.h"

UNIT_SHARED struct imsu_pair imsu_dm_rc;
UNIT_SHARED struct imsu_bcast imsu_rc_ncs;

void imsu_init_all(uint32_t ncores)
{
    (void)ncores;
    size_t pair = LINKER_VALUE(LINKS1_IMSU_PAIR_BLOCK);
    imsu_pair_init(&imsu_dm_rc, "DM-RC", UNITS_DM_CORE, UNITS_RC_CORE, (uint8_t *)__imsu_pair_start,
                   (uint8_t *)__imsu_pair_start + pair, pair);
    imsu_bcast_init(&imsu_rc_ncs, UNITS_RC_CORE, (uint8_t *)__imsu_bcast_start,
                    LINKER_VALUE(LINKS1_IMSU_BCAST_BLOCK));
}

