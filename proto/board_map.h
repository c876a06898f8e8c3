/* board_map.h: addresses of the virt board that the host tools must know
 * too (the an521 boards': board_map_an521.h).  Plain #defines only:
 * boot/virt/start.S includes this through drivers/virt/virt_map.h. */
#ifndef LINKS1_PROTO_BOARD_MAP_H
#define LINKS1_PROTO_BOARD_MAP_H

/* The 1 GiB block at this virtual address is left unmapped on purpose: any
 * access faults.  CMD_FAULT_INJECT's data and prefetch aborts touch it, so a
 * fault report from them names this address. */
#define UNMAPPED_VIRT 0x80000000u

/* The board's RAM starts here (physical = virtual).  The host tool backs
 * the whole RAM with a shared file (QEMU's memory-backend-file, share=on)
 * and maps it too: byte k of that file is guest address BOARD_RAM_BASE + k,
 * which is what a LINK_BULK offset (proto/hostlink.h) counts from. */
#define BOARD_RAM_BASE 0x40000000u
/* The board's RAM and the blocks carved from it that the host must know
 * too: the host compiler refuses a scene whose prepared frame would not fit
 * an IMSU block (host-tools/scene/scene_board.c) before any upload.  The
 * linker script (linker/virt-memory.ld) carves them from these values. */
#define BOARD_RAM_MB 1024 /* -m: the whole 1 GiB Normal-memory block of the
                             MMU map (drivers/virt/virt_map.h) */
/* Each of the two DM<->RC blocks and the RC->NC broadcast block: the most a
 * scene's blob (render/blob.h: loaded scene + prepared frame + scratch)
 * may take.  QEMU backs only the pages a scene writes, so a small scene
 * costs the host no more than before.  184 MiB since the scene index (the
 * loader's, in the blob's scene part) took SPD teapot 64 (269,824 smooth
 * triangles) to 188 MB; the NC pool gave up the 24 MiB. */
#define BOARD_IMSU_BLOCK_BYTES (184 * 1024 * 1024)
#define BOARD_IMSU_BLOCK_NAME "LINKS1_IMSU_PAIR_BLOCK"
/* The DM's private memory: the compiled scene as uploaded, the host frame
 * queue and its tasks' stacks (at least SCN_MAX_SIZE plus 16 MiB). */
#define BOARD_DM_PRIVATE_BYTES (96 * 1024 * 1024)

#endif
