/* imsu.c: memory swapping unit (see imsu.h for the rules and ordering).
 * No hardware access beyond the spinlock: the host tests build it. */
#include "drivers/imsu/imsu.h"

#include <string.h>

void imsu_pair_init(struct imsu_pair *p, const char *name, uint32_t core_a,
                    uint32_t core_b, uint8_t *block_a, uint8_t *block_b, size_t size)
{
    spin_init(&p->lock, "imsu_pair");
    p->name = name;
    p->block[IMSU_BLOCK_A] = block_a;
    p->block[IMSU_BLOCK_B] = block_b;
    p->size = size;
    p->side[0] = core_a;
    p->side[1] = core_b;
    p->holds[0] = IMSU_BLOCK_A;
    p->holds[1] = IMSU_BLOCK_B;
    p->writing[0] = p->writing[1] = 0;
    p->swaps = 0;
}

static int imsu_side_of(const struct imsu_pair *p, uint32_t core)
{
    if (core == p->side[0])
        return 0;
    if (core == p->side[1])
        return 1;
    return IMSU_ERR_NOT_SIDE;
}

int imsu_held(struct imsu_pair *p, uint32_t core)
{
    spin_lock(&p->lock);
    int s = imsu_side_of(p, core);
    int r = s < 0 ? s : p->holds[s];
    spin_unlock(&p->lock);
    return r;
}

int imsu_write_begin(struct imsu_pair *p, uint32_t core, int blk, uint8_t **out)
{
    spin_lock(&p->lock);
    int s = imsu_side_of(p, core);
    int r = IMSU_OK;
    if (s < 0)
        r = s;
    else if (p->writing[s])
        r = IMSU_ERR_SELF_WRITING;
    else if (blk != p->holds[s])
        r = IMSU_ERR_NOT_HOLDER;
    else {
        p->writing[s] = 1;
        *out = p->block[blk];
    }
    spin_unlock(&p->lock);
    return r;
}

int imsu_write_end(struct imsu_pair *p, uint32_t core)
{
    spin_lock(&p->lock);
    int s = imsu_side_of(p, core);
    int r = IMSU_OK;
    if (s < 0)
        r = s;
    else if (!p->writing[s])
        r = IMSU_ERR_NOT_WRITING;
    else
        p->writing[s] = 0; /* the unlock's release publishes the block */
    spin_unlock(&p->lock);
    return r;
}

const uint8_t *imsu_read_block(struct imsu_pair *p, uint32_t core)
{
    int b = imsu_held(p, core);
    return b < 0 ? NULL : p->block[b];
}

int imsu_swap(struct imsu_pair *p, uint32_t core)
{
    spin_lock(&p->lock);
    int s = imsu_side_of(p, core);
    int r = IMSU_OK;
    if (s < 0)
        r = s;
    else if (p->writing[s])
        r = IMSU_ERR_SELF_WRITING;
    else if (p->writing[1 - s])
        r = IMSU_ERR_PEER_WRITING;
    else {
        uint8_t t = p->holds[0];
        p->holds[0] = p->holds[1];
        p->holds[1] = t;
        p->swaps++;
    }
    spin_unlock(&p->lock);
    return r;
}

void imsu_bcast_init(struct imsu_bcast *b, uint32_t writer, uint8_t *block, size_t size)
{
    spin_init(&b->lock, "imsu_bcast");
    b->block = block;
    b->size = size;
    b->writer = writer;
    b->writing = 0;
    b->readers = 0;
    memset(b->reads, 0, sizeof b->reads);
    b->generation = 0;
}

int imsu_bcast_write_begin(struct imsu_bcast *b, uint32_t core, uint8_t **out)
{
    spin_lock(&b->lock);
    int r = IMSU_OK;
    if (core != b->writer)
        r = IMSU_ERR_NOT_HOLDER;
    else if (b->writing)
        r = IMSU_ERR_SELF_WRITING;
    else if (b->readers)
        r = IMSU_ERR_READERS_ACTIVE;
    else {
        b->writing = 1;
        *out = b->block;
    }
    spin_unlock(&b->lock);
    return r;
}

int imsu_bcast_write_end(struct imsu_bcast *b, uint32_t core)
{
    spin_lock(&b->lock);
    int r = IMSU_OK;
    if (core != b->writer)
        r = IMSU_ERR_NOT_HOLDER;
    else if (!b->writing)
        r = IMSU_ERR_NOT_WRITING;
    else {
        b->writing = 0;
        b->generation++;
    }
    spin_unlock(&b->lock);
    return r;
}

int imsu_bcast_read_begin(struct imsu_bcast *b, uint32_t core, const uint8_t **out,
                          uint32_t *generation)
{
    spin_lock(&b->lock);
    int r = IMSU_OK;
    if (core >= UNITS_MAX_CORES)
        r = IMSU_ERR_NOT_SIDE;
    else if (b->writing)
        r = IMSU_ERR_WRITER_ACTIVE;
    else {
        b->readers++;
        b->reads[core]++;
        *out = b->block;
        *generation = b->generation;
    }
    spin_unlock(&b->lock);
    return r;
}

int imsu_bcast_read_end(struct imsu_bcast *b, uint32_t core)
{
    spin_lock(&b->lock);
    int r = IMSU_OK;
    if (core >= UNITS_MAX_CORES || b->reads[core] == 0)
        r = IMSU_ERR_NOT_READING;
    else {
        b->readers--;
        b->reads[core]--;
    }
    spin_unlock(&b->lock);
    return r;
}

uint32_t imsu_bcast_read_abandon(struct imsu_bcast *b, uint32_t core)
{
    if (core >= UNITS_MAX_CORES)
        return 0;
    spin_lock(&b->lock);
    uint32_t n = b->reads[core];
    b->readers -= n;
    b->reads[core] = 0;
    spin_unlock(&b->lock);
    return n;
}

const char *imsu_strerror(int status)
{
    switch (status) {
    case IMSU_OK: return "ok";
    case IMSU_ERR_NOT_SIDE: return "core is not a side of this IMSU pair";
    case IMSU_ERR_NOT_HOLDER: return "write to a block this core does not hold";
    case IMSU_ERR_PEER_WRITING: return "swap while the other side is writing its block";
    case IMSU_ERR_SELF_WRITING: return "swap or new write while this core is still writing";
    case IMSU_ERR_NOT_WRITING: return "write end without a write begin";
    case IMSU_ERR_READERS_ACTIVE: return "broadcast write while readers are reading";
    case IMSU_ERR_WRITER_ACTIVE: return "broadcast read while the writer is writing";
    case IMSU_ERR_NOT_READING: return "broadcast read end without a read begin";
    }
    return "unknown IMSU status";
}
