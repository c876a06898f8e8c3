/* test_imsu.c: the IMSU rules (drivers/imsu/imsu.c) on the host: swaps
 * exchange blocks without copying, and every misuse is refused.  One
 * thread plays both sides, so the spinlocks are stand-ins that check
 * balanced use. */
#include <string.h>

#include "drivers/imsu/imsu.h"
#include "tests/check.h"

/* ---- stand-ins for kernel/spinlock.c ---- */
static int test_locks_held; /* must be back to 0 after every IMSU call */

void spin_init(struct spinlock *l, const char *name)
{
    l->name = name;
    l->owner = SPIN_NO_OWNER;
}

void spin_lock(struct spinlock *l)
{
    if (l->owner != SPIN_NO_OWNER)
        check_fail(__FILE__, __LINE__, "spin_lock of a held lock");
    l->owner = 0;
    test_locks_held++;
}

void spin_unlock(struct spinlock *l)
{
    if (l->owner == SPIN_NO_OWNER)
        check_fail(__FILE__, __LINE__, "spin_unlock of a free lock");
    l->owner = SPIN_NO_OWNER;
    test_locks_held--;
}

enum { DM = 0, RC = 1, NC = 2, BLOCK = 64 };
static uint8_t mem_a[BLOCK], mem_b[BLOCK], mem_bcast[BLOCK];

static void test_swap_exchanges_without_copying(void)
{
    struct imsu_pair p;
    imsu_pair_init(&p, "DM-RC", DM, RC, mem_a, mem_b, BLOCK);
    CHECK_EQ_INT(imsu_held(&p, DM), IMSU_BLOCK_A);
    CHECK_EQ_INT(imsu_held(&p, RC), IMSU_BLOCK_B);
    uint8_t *w = NULL;
    CHECK_EQ_INT(imsu_write_begin(&p, DM, IMSU_BLOCK_A, &w), IMSU_OK);
    CHECK(w == mem_a);
    memcpy(w, "frame 1", 8);
    CHECK_EQ_INT(imsu_write_end(&p, DM), IMSU_OK);
    CHECK_EQ_INT(imsu_swap(&p, DM), IMSU_OK);
    /* The RC now reads the very bytes the DM wrote, at the same place. */
    CHECK(imsu_read_block(&p, RC) == mem_a);
    CHECK(memcmp(imsu_read_block(&p, RC), "frame 1", 8) == 0);
    CHECK(imsu_read_block(&p, DM) == mem_b);
    CHECK(imsu_read_block(&p, NC) == NULL);
    CHECK_EQ_INT(p.swaps, 1);
    CHECK_EQ_INT(test_locks_held, 0);
}

static void test_misuse_is_refused(void)
{
    struct imsu_pair p;
    imsu_pair_init(&p, "DM-RC", DM, RC, mem_a, mem_b, BLOCK);
    uint8_t *w = NULL;
    /* Writing the block the other side holds. */
    CHECK_EQ_INT(imsu_write_begin(&p, DM, IMSU_BLOCK_B, &w), IMSU_ERR_NOT_HOLDER);
    /* A core that is not a side. */
    CHECK_EQ_INT(imsu_write_begin(&p, NC, IMSU_BLOCK_A, &w), IMSU_ERR_NOT_SIDE);
    CHECK_EQ_INT(imsu_swap(&p, NC), IMSU_ERR_NOT_SIDE);
    /* Swapping while the peer is mid-write, or while writing oneself. */
    CHECK_EQ_INT(imsu_write_begin(&p, RC, IMSU_BLOCK_B, &w), IMSU_OK);
    CHECK_EQ_INT(imsu_swap(&p, DM), IMSU_ERR_PEER_WRITING);
    CHECK_EQ_INT(imsu_swap(&p, RC), IMSU_ERR_SELF_WRITING);
    CHECK_EQ_INT(imsu_write_begin(&p, RC, IMSU_BLOCK_B, &w), IMSU_ERR_SELF_WRITING);
    CHECK_EQ_INT(imsu_held(&p, DM), IMSU_BLOCK_A); /* nothing moved */
    CHECK_EQ_INT(imsu_write_end(&p, RC), IMSU_OK);
    CHECK_EQ_INT(imsu_write_end(&p, RC), IMSU_ERR_NOT_WRITING);
    CHECK_EQ_INT(imsu_swap(&p, DM), IMSU_OK);
    /* After the swap the old block is the peer's. */
    CHECK_EQ_INT(imsu_write_begin(&p, DM, IMSU_BLOCK_A, &w), IMSU_ERR_NOT_HOLDER);
    CHECK_EQ_INT(test_locks_held, 0);
    CHECK(strlen(imsu_strerror(IMSU_ERR_PEER_WRITING)) > 0);
}

static void test_broadcast_rules(void)
{
    struct imsu_bcast b;
    imsu_bcast_init(&b, RC, mem_bcast, BLOCK);
    uint8_t *w = NULL;
    const uint8_t *r = NULL;
    uint32_t gen = 99;
    CHECK_EQ_INT(imsu_bcast_write_begin(&b, NC, &w), IMSU_ERR_NOT_HOLDER);
    CHECK_EQ_INT(imsu_bcast_write_begin(&b, RC, &w), IMSU_OK);
    memcpy(w, "scene", 6);
    CHECK_EQ_INT(imsu_bcast_read_begin(&b, NC, &r, &gen), IMSU_ERR_WRITER_ACTIVE);
    CHECK_EQ_INT(imsu_bcast_write_end(&b, RC), IMSU_OK);
    CHECK_EQ_INT(imsu_bcast_read_begin(&b, NC, &r, &gen), IMSU_OK);
    CHECK_EQ_INT(imsu_bcast_read_begin(&b, NC + 1, &r, &gen), IMSU_OK);
    CHECK(r == mem_bcast && memcmp(r, "scene", 6) == 0);
    CHECK_EQ_INT(gen, 1);
    CHECK_EQ_INT(imsu_bcast_write_begin(&b, RC, &w), IMSU_ERR_READERS_ACTIVE);
    CHECK_EQ_INT(imsu_bcast_read_end(&b, NC), IMSU_OK);
    CHECK_EQ_INT(imsu_bcast_read_end(&b, NC + 1), IMSU_OK);
    CHECK_EQ_INT(imsu_bcast_read_end(&b, NC), IMSU_ERR_NOT_READING);
    CHECK_EQ_INT(imsu_bcast_write_begin(&b, RC, &w), IMSU_OK);
    CHECK_EQ_INT(imsu_bcast_write_end(&b, RC), IMSU_OK);
    CHECK_EQ_INT(b.generation, 2);
    CHECK_EQ_INT(imsu_bcast_write_end(&b, RC), IMSU_ERR_NOT_WRITING);
    /* A reader that failed mid-read: the RC ends its read, and only its. */
    CHECK_EQ_INT(imsu_bcast_read_begin(&b, NC, &r, &gen), IMSU_OK);
    CHECK_EQ_INT(imsu_bcast_read_begin(&b, NC + 1, &r, &gen), IMSU_OK);
    CHECK_EQ_INT(imsu_bcast_read_abandon(&b, NC), 1);
    CHECK_EQ_INT(imsu_bcast_read_abandon(&b, NC), 0);
    CHECK_EQ_INT(imsu_bcast_read_end(&b, NC), IMSU_ERR_NOT_READING);
    CHECK_EQ_INT(imsu_bcast_write_begin(&b, RC, &w), IMSU_ERR_READERS_ACTIVE);
    CHECK_EQ_INT(imsu_bcast_read_end(&b, NC + 1), IMSU_OK);
    CHECK_EQ_INT(imsu_bcast_write_begin(&b, RC, &w), IMSU_OK);
    CHECK_EQ_INT(imsu_bcast_write_end(&b, RC), IMSU_OK);
    CHECK_EQ_INT(test_locks_held, 0);
}

int main(void)
{
    RUN(test_swap_exchanges_without_copying);
    RUN(test_misuse_is_refused);
    RUN(test_broadcast_rules);
    return check_exit();
}
