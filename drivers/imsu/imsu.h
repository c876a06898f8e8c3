/* imsu.h: the intercomputer memory swapping unit (IMSU) of LINKS-1.
 *
 * Pair: two memory blocks, A and B, between two unit computers.  At any
 * time each side holds one block and may read and write only that one.
 * imsu_swap() exchanges which side holds which block: no byte is copied,
 * the "sending" is the change of holder (as the hardware switched which
 * block answered each computer's addresses).  Rules, all checked:
 *   - a side writes only inside imsu_write_begin/imsu_write_end, and only
 *     the block it holds (IMSU_ERR_NOT_HOLDER otherwise);
 *   - a swap is refused while either side is inside a write
 *     (IMSU_ERR_PEER_WRITING / IMSU_ERR_SELF_WRITING);
 *   - only the pair's two cores may use it (IMSU_ERR_NOT_SIDE).
 *
 * Broadcast block: one writer (the RC), many readers (the NCs).  The writer
 * writes inside imsu_bcast_write_begin/end, refused while any reader is
 * inside imsu_bcast_read_begin/end, and readers are refused while the
 * writer is writing.  Each finished write bumps the block's generation, so
 * a reader can tell which version it read.
 *
 * Memory ordering: every begin/end/swap takes the IMSU's spinlock, whose
 * acquire/release barriers order the block's contents with the holder and
 * writer state.  So the bytes a side wrote before imsu_write_end (or the RC
 * before imsu_bcast_write_end) are visible to the other side once it sees
 * itself as holder after the swap (or starts a read of that generation).
 * The swap itself does not tell the peer: the sides say so over their
 * serial line, which orders its own messages (drivers/serial/line.h).
 *
 * Errors are returned, not fatal, so the self-test can show that misuse is
 * caught; callers that do not expect an error panic with imsu_strerror(). */
#ifndef LINKS1_DRIVERS_IMSU_IMSU_H
#define LINKS1_DRIVERS_IMSU_IMSU_H

#include <stddef.h>
#include <stdint.h>

#include "kernel/param.h"
#include "kernel/spinlock.h"

enum imsu_status {
    IMSU_OK = 0,
    IMSU_ERR_NOT_SIDE = -1,      /* caller is not one of the pair's cores */
    IMSU_ERR_NOT_HOLDER = -2,    /* writing a block the caller does not hold */
    IMSU_ERR_PEER_WRITING = -3,  /* swap while the other side is mid-write */
    IMSU_ERR_SELF_WRITING = -4,  /* swap or second begin while mid-write */
    IMSU_ERR_NOT_WRITING = -5,   /* write_end without write_begin */
    IMSU_ERR_READERS_ACTIVE = -6,/* broadcast write while readers read */
    IMSU_ERR_WRITER_ACTIVE = -7, /* broadcast read while the writer writes */
    IMSU_ERR_NOT_READING = -8,   /* read_end without read_begin */
};

enum imsu_block_id { IMSU_BLOCK_A = 0, IMSU_BLOCK_B = 1 };

struct imsu_pair {
    struct spinlock lock;
    const char *name;       /* e.g. "DM-RC", for messages */
    uint8_t *block[2];      /* blocks A and B */
    size_t size;            /* bytes of each block */
    uint32_t side[2];       /* the two cores */
    uint8_t holds[2];       /* block held by side i */
    uint8_t writing[2];     /* side i is inside a write */
    uint32_t swaps;         /* swaps done */
};

struct imsu_bcast {
    struct spinlock lock;
    uint8_t *block;         /* the broadcast block */
    size_t size;
    uint32_t writer;        /* the one core that writes */
    uint8_t writing;        /* writer inside a write */
    uint32_t readers;       /* reads in progress */
    uint8_t reads[UNITS_MAX_CORES]; /* of them, by each core */
    uint32_t generation;    /* finished writes */
};

/* The board's IMSUs (set up by core 0 before the others wake). */
extern struct imsu_pair imsu_dm_rc;
extern struct imsu_bcast imsu_rc_ncs;
void imsu_init_all(uint32_t ncores);

void imsu_pair_init(struct imsu_pair *p, const char *name, uint32_t core_a,
                    uint32_t core_b, uint8_t *block_a, uint8_t *block_b, size_t size);
/* Which block (enum imsu_block_id) core holds, or IMSU_ERR_NOT_SIDE. */
int imsu_held(struct imsu_pair *p, uint32_t core);
/* Opens block blk for writing by core; *out is its address.  Reading the
 * held block needs no call: the holder reads it between swaps. */
int imsu_write_begin(struct imsu_pair *p, uint32_t core, int blk, uint8_t **out);
int imsu_write_end(struct imsu_pair *p, uint32_t core);
/* The held block's address for reading (NULL if core is not a side). */
const uint8_t *imsu_read_block(struct imsu_pair *p, uint32_t core);
int imsu_swap(struct imsu_pair *p, uint32_t core);

void imsu_bcast_init(struct imsu_bcast *b, uint32_t writer, uint8_t *block, size_t size);
int imsu_bcast_write_begin(struct imsu_bcast *b, uint32_t core, uint8_t **out);
int imsu_bcast_write_end(struct imsu_bcast *b, uint32_t core);
int imsu_bcast_read_begin(struct imsu_bcast *b, uint32_t core, const uint8_t **out,
                          uint32_t *generation);
int imsu_bcast_read_end(struct imsu_bcast *b, uint32_t core);
/* Ends every read a core left open because it failed (the RC, for an NC
 * it gave up on): the next broadcast write is not refused for it.
 * Returns how many reads it ended. */
uint32_t imsu_bcast_read_abandon(struct imsu_bcast *b, uint32_t core);

const char *imsu_strerror(int status);

#endif
