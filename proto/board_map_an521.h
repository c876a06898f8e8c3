/* board_map_an521.h: the an521 boards (QEMU's mps2-an521: two Cortex-M33
 * cores, private SRAMs and 16 MiB of PSRAM) as links1 joins them, what
 * the firmware's memory map (linker/an521-memory.ld) and the host's
 * launcher both know.  Plain #defines only: the linker script includes it.
 *
 * Every board is one QEMU process.  Board 0 carries the DM (core 0) and the
 * RC (core 1), board b > 0 the NCs 2b and 2b + 1.  All boards map one
 * memory file as their PSRAM (memory-backend-file, share=on): it holds
 * what unit computers of different boards share (the IMSU blocks, the
 * serial lines' rings, the data collector's FIFO, the units' status and
 * the relay of the NC boards' host-link messages).  Code, stacks and each
 * unit's private memory stay in its board's own SRAMs. */
#ifndef LINKS1_PROTO_BOARD_MAP_AN521_H
#define LINKS1_PROTO_BOARD_MAP_AN521_H

#define AN521_CORES_PER_BOARD 2
/* Board 0 (DM, RC) and up to 32 NC boards: 64 NCs. */
#define AN521_MAX_BOARDS 33

/* The shared file = the PSRAM: guest address AN521_SHARED_BASE + k is
 * byte k of the file. */
#define AN521_SHARED_BASE 0x80000000u
#define AN521_SHARED_MB 16

/* The file's first page is its header, written by the host before any
 * board starts (all fields little-endian u32 at these offsets). */
#define AN521_HDR_MAGIC_OFF 0   /* AN521_HDR_MAGIC */
#define AN521_HDR_BOARDS_OFF 4  /* boards joined, 2..AN521_MAX_BOARDS */
#define AN521_HDR_READY_OFF 8   /* 0; board 0 writes AN521_HDR_READY once
                                 * the shared blocks are set up */
#define AN521_HDR_BYTES 4096
#define AN521_HDR_MAGIC 0x3135414Cu /* "LA51" */
#define AN521_HDR_READY 0x59444552u /* "REDY" */

/* Where each board finds its own number: the host puts it in the board's
 * SRAM with QEMU's generic loader (-device loader,addr=...,data=B,
 * data-len=4), a word the firmware's image leaves alone. */
#define AN521_BOARD_ID_ADDR 0x103FFFF0 /* no suffix: the linker script uses it */

/* The blocks carved from the shared file after its header and the units'
 * shared state: the serial lines' rings (linker/an521-memory.ld), the two
 * DM<->RC IMSU blocks and the RC->NC broadcast block, each this big, the
 * RC's memory (its frame memory: the host pulls frames from it) and the
 * rest the DM's (where the host link's bulk bytes land). */
#define AN521_SHARED_STATE_BYTES (1024 * 1024)
#define AN521_IMSU_BLOCK_BYTES (3072 * 1024)
#define AN521_RC_MEMORY_BYTES (2048 * 1024)
/* Each NC's private memory, half of its board's SSRAM2 and SSRAM3 (what
 * the two cores' stacks leave, linker/an521-memory.ld). */
#define AN521_NC_MEMORY_BYTES (1984 * 1024)
#define AN521_IMSU_BLOCK_NAME "AN521_IMSU_BLOCK_BYTES"

/* An address where nothing answers: a bus fault (the fault tests). */
#define AN521_UNMAPPED 0x70000000u

#endif
