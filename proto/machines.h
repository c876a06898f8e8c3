/* machines.h: the machines links1 runs on, and what each gives a scene;
 * the host compiler refuses a scene a machine cannot hold before anything
 * is uploaded (host-tools/scene/scene_board.h), the launcher starts each
 * (host-tools/launcher/). */
#ifndef LINKS1_PROTO_MACHINES_H
#define LINKS1_PROTO_MACHINES_H

#include <stddef.h>

enum machine_id {
    MACHINE_VIRT = 0,  /* one virt board, a Cortex-A15 core per unit computer */
    MACHINE_AN521 = 1, /* dual Cortex-M33 an521 boards, one QEMU each, joined
                          by a shared file (proto/board_map_an521.h) */
    MACHINE_COUNT
};

struct machine_limits {
    const char *name;      /* as --machine takes it */
    size_t blob_bytes;     /* an IMSU block: the prepared frame's blob */
    const char *blob_name; /* ... the definition that sets it */
    size_t nc_bytes;       /* an NC's private memory (its working set); 0
                              when it depends on the NCs booted */
    const char *nc_name;   /* ... the definition that sets it */
};

/* The limits of machine id (an enum machine_id), or NULL when there is no
 * such machine. */
const struct machine_limits *machine_limits(int id);
/* The machine named name (virt, an521), or -1. */
int machine_by_name(const char *name);

#endif
