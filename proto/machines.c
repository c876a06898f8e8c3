/* machines.c: each machine's limits (machines.h), from the definitions
 * their memory maps use. */
#include "proto/machines.h"

#include <string.h>

#include "proto/board_map.h"
#include "proto/board_map_an521.h"

static const struct machine_limits machine_table[MACHINE_COUNT] = {
    [MACHINE_VIRT] = {"virt", BOARD_IMSU_BLOCK_BYTES, BOARD_IMSU_BLOCK_NAME,
                      0, NULL}, /* the NC pool shared by the NCs booted: no
                                   one size to check a scene against */
    [MACHINE_AN521] = {"an521", AN521_IMSU_BLOCK_BYTES, AN521_IMSU_BLOCK_NAME,
                       AN521_NC_MEMORY_BYTES, "AN521_NC_MEMORY_BYTES"},
};

const struct machine_limits *machine_limits(int id)
{
    if (id < 0 || id >= MACHINE_COUNT)
        return NULL;
    return &machine_table[id];
}

int machine_by_name(const char *name)
{
    for (int i = 0; i < MACHINE_COUNT; i++)
        if (strcmp(machine_table[i].name, name) == 0)
            return i;
    return -1;
}
