/* link_shared.c: bulk bytes through the board's shared RAM (see
 * link_shared.h). */
#include "host-tools/link/link_shared.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "proto/wordsum.h"
#include "proto/wire.h"

/* Waits for LINK_BULK, or a LINK_RESULT (put back: 1).  0 with *k, or -1. */
static int link_shared_wait(struct board *b, struct link_bulk *k, const char *what)
{
    struct board_frame f;
    if (board_wait_frame_of(b, (1u << LINK_BULK) | (1u << LINK_RESULT), BOARD_FRAME_TIMEOUT_MS,
                            &f, what) < 0)
        return -1;
    if (f.type == LINK_RESULT) {
        board_unget_frame(b, &f);
        return 1;
    }
    if (f.length != LINK_BULK_SIZE) {
        fprintf(stderr, "links1: %s: LINK_BULK frame of %u bytes, want %d\n", what, f.length,
                LINK_BULK_SIZE);
        return -1;
    }
    link_bulk_get(f.payload, k);
    if (!b->ram) {
        fprintf(stderr, "links1: %s: this board's RAM is not shared with the host "
                "(use --link serial)\n", what);
        return -1;
    }
    if (k->offset > b->ram_size || k->length > b->ram_size - k->offset) {
        fprintf(stderr, "links1: %s: the board names %u bytes at offset 0x%x, outside its "
                "%zu bytes of RAM\n", what, k->length, k->offset, b->ram_size);
        return -1;
    }
    return 0;
}

/* Answers an offer the host cannot use with no bytes, so the board ends
 * the command (its result, a refusal, is taken here) instead of waiting. */
static int link_shared_cancel(struct board *b, uint32_t offset)
{
    struct link_bulk none = {offset, 0, 0};
    uint8_t p[LINK_BULK_SIZE];
    link_bulk_put(p, &none);
    struct board_frame f;
    if (board_send(b, LINK_BULK, 0, p, sizeof p) >= 0)
        (void)board_wait_frame(b, LINK_RESULT, BOARD_FRAME_TIMEOUT_MS, &f,
                               "the result of a cancelled transfer");
    return -1;
}

/* The board's RAM at [p, p + len) mapped here before the bytes are
 * copied in: one call instead of a page fault a page (a scene of 27 MB
 * is 6,600 pages).  Only a speed-up: where the kernel lacks it, the copy
 * faults the pages in as before. */
static void link_shared_populate(uint8_t *p, size_t len)
{
#if defined(MADV_POPULATE_WRITE)
    uintptr_t page = (uintptr_t)sysconf(_SC_PAGESIZE);
    uintptr_t lo = (uintptr_t)p & ~(page - 1), hi = ((uintptr_t)p + len + page - 1) & ~(page - 1);
    if (len)
        (void)madvise((void *)lo, hi - lo, MADV_POPULATE_WRITE);
#else
    (void)p;
    (void)len;
#endif
}

int link_shared_send(struct board *b, const void *data, size_t len)
{
    struct link_bulk k = {0, 0, 0};
    int r = link_shared_wait(b, &k, "the board's offer of shared memory");
    if (r < 0 && k.length)
        return link_shared_cancel(b, k.offset);
    if (r != 0)
        return r;
    if (len > k.length) {
        fprintf(stderr, "links1: the board offers %u bytes of shared memory for %zu bytes\n",
                k.length, len);
        return link_shared_cancel(b, k.offset);
    }
    link_shared_populate(b->ram + k.offset, len);
    for (int t = 1;; t++) {
        memcpy(b->ram + k.offset, data, len);
        struct link_bulk done = {k.offset, (uint32_t)len, wordsum(data, len)};
        uint8_t p[LINK_BULK_SIZE];
        link_bulk_put(p, &done);
        int seq = board_send(b, LINK_BULK, 0, p, sizeof p);
        if (seq < 0)
            return -1;
        struct board_frame f;
        if (board_wait_frame_of(b, (1u << LINK_ACK) | (1u << LINK_RESULT) | (1u << LINK_BULK),
                                BOARD_FRAME_TIMEOUT_MS, &f,
                                "ACK of the shared-memory bytes") < 0)
            return -1;
        if (f.type == LINK_RESULT) {
            board_unget_frame(b, &f); /* the board refused them: its reason follows */
            return 1;
        }
        if (f.type == LINK_BULK) {
            /* The bytes the board found did not have our word sum: it offers the
             * same memory again (proto/hostlink.h, LINK_BULK_TRIES). */
            struct link_bulk again;
            link_bulk_get(f.payload, &again);
            if (f.length != LINK_BULK_SIZE || again.offset != k.offset ||
                again.length != k.length || t >= LINK_BULK_TRIES) {
                fprintf(stderr, "links1: the board offered shared memory again (try %d of %d) "
                        "at 0x%x, %u bytes\n", t + 1, LINK_BULK_TRIES, again.offset,
                        again.length);
                return link_shared_cancel(b, again.offset);
            }
            fprintf(stderr, "links1: the board found other bytes than ours in shared memory: "
                    "copying them again (try %d of %d)\n", t + 1, LINK_BULK_TRIES);
            continue;
        }
        if (f.length != LINK_ACK_SIZE || wire_get_u16(f.payload) != (uint16_t)seq) {
            fprintf(stderr, "links1: ACK of the shared-memory bytes: %u bytes naming seq %u, "
                    "want seq %d\n", f.length, f.length >= 2 ? wire_get_u16(f.payload) : 0, seq);
            return -1;
        }
        return 0;
    }
}

int link_shared_receive(struct board *b, struct link_bulk *k, const uint8_t **data)
{
    int r = link_shared_wait(b, k, "the board's shared-memory bytes");
    if (r != 0)
        return r;
    uint32_t c = wordsum(b->ram + k->offset, k->length);
    if (c != k->sum) {
        fprintf(stderr, "links1: %u bytes at offset 0x%x of the board's RAM have word sum 0x%08x, "
                "the board says 0x%08x\n", k->length, k->offset, c, k->sum);
        return -2;
    }
    *data = b->ram + k->offset;
    return 0;
}
