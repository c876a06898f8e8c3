/* Host tests of the shared-memory path's host side (host-tools/link/link_shared.c)
 * against a fake board on the other end of a socketpair and a buffer
 * standing for the board's RAM: bytes land where the board offered and are
 * told with their CRC; an offer outside the RAM is cancelled with no bytes;
 * a refusal instead of an offer is left for the caller; bytes from the board
 * whose CRC does not match are refused. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/link/link_shared.h"
#include "proto/wordsum.h"
#include "proto/wire.h"
#include "tests/check.h"
#include "tests/host/fake_board.h"

#define RAM_SIZE (1u << 20)

static uint16_t peer_seq; /* the fake board's frame counter */

static void peer_send(int fd, uint8_t type, const void *payload, size_t len)
{
    uint8_t frame[LINK_MAX_FRAME];
    size_t n = link_frame_encode(frame, sizeof frame, type, 0, peer_seq++, payload, len);
    CHECK(write(fd, frame, n) == (ssize_t)n);
}

static void peer_bulk(int fd, uint32_t offset, uint32_t length, uint32_t crc)
{
    struct link_bulk k = {offset, length, crc};
    uint8_t p[LINK_BULK_SIZE];
    link_bulk_put(p, &k);
    peer_send(fd, LINK_BULK, p, sizeof p);
}

/* The next frame the host sent, decoded into *k when it is a LINK_BULK. */
static int peer_read_bulk(int fd, struct link_bulk *k)
{
    struct link_decoder d;
    link_decoder_init(&d);
    uint8_t byte;
    while (read(fd, &byte, 1) == 1) {
        struct link_frame f;
        if (link_decoder_push(&d, byte, &f)) {
            if (f.type != LINK_BULK || f.length != LINK_BULK_SIZE)
                return -1;
            link_bulk_get(f.payload, k);
            return 0;
        }
    }
    return -1;
}

static void session(struct board *b, int *peer, uint8_t *ram)
{
    CHECK(fake_session(b, peer) == 0);
    b->ram = ram;
    b->ram_size = RAM_SIZE;
    peer_seq = 0;
}

static void shared_send_lands_where_offered(void)
{
    static uint8_t ram[RAM_SIZE];
    struct board b;
    int peer;
    session(&b, &peer, ram);
    uint8_t data[3000];
    for (size_t i = 0; i < sizeof data; i++)
        data[i] = link_pattern_byte((uint32_t)i);
    peer_bulk(peer, 0x4000, 4096, 0); /* the offer */
    uint8_t ack[LINK_ACK_SIZE];
    wire_put_u16(ack, 0); /* the host's first frame is its BULK, seq 0 */
    peer_send(peer, LINK_ACK, ack, sizeof ack);
    CHECK_EQ_INT(link_shared_send(&b, data, sizeof data), 0);
    CHECK(memcmp(ram + 0x4000, data, sizeof data) == 0);
    struct link_bulk k;
    CHECK_EQ_INT(peer_read_bulk(peer, &k), 0);
    CHECK_EQ_INT(k.offset, 0x4000);
    CHECK_EQ_INT(k.length, sizeof data);
    CHECK_EQ_INT(k.sum, wordsum(data, sizeof data));
    b.ram = NULL;
    board_stop(&b);
    close(peer);
}

static void shared_send_cancels_offer_outside_ram(void)
{
    static uint8_t ram[RAM_SIZE];
    struct board b;
    int peer;
    session(&b, &peer, ram);
    peer_bulk(peer, RAM_SIZE - 16, 64, 0); /* runs past the end of the RAM */
    uint8_t res[LINK_RESULT_FIXED_SIZE + 4];
    wire_put_u16(res, CMD_SCENE_LOAD);
    wire_put_u16(res + 2, (uint16_t)LINK_ERR_BAD_ARGS);
    memcpy(res + LINK_RESULT_FIXED_SIZE, "none", 4);
    peer_send(peer, LINK_RESULT, res, sizeof res);
    uint8_t data[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    CHECK_EQ_INT(link_shared_send(&b, data, sizeof data), -1);
    struct link_bulk k;
    CHECK_EQ_INT(peer_read_bulk(peer, &k), 0);
    CHECK_EQ_INT(k.length, 0); /* answered with no bytes */
    CHECK_EQ_INT(board_queued(&b), 0); /* and the board's result taken */
    b.ram = NULL;
    board_stop(&b);
    close(peer);
}

static void shared_send_leaves_refusal_for_caller(void)
{
    static uint8_t ram[RAM_SIZE];
    struct board b;
    int peer;
    session(&b, &peer, ram);
    uint8_t res[LINK_RESULT_FIXED_SIZE + 7];
    wire_put_u16(res, CMD_SCENE_LOAD);
    wire_put_u16(res + 2, (uint16_t)LINK_ERR_BAD_ARGS);
    memcpy(res + LINK_RESULT_FIXED_SIZE, "too big", 7);
    peer_send(peer, LINK_RESULT, res, sizeof res);
    uint8_t data[8] = {0};
    CHECK_EQ_INT(link_shared_send(&b, data, sizeof data), 1);
    struct board_frame f;
    const uint8_t *fields;
    size_t nf;
    int status;
    CHECK_EQ_INT(board_wait_result(&b, CMD_SCENE_LOAD, 1000, &f, &status, &fields, &nf), 0);
    CHECK_EQ_INT(status, LINK_ERR_BAD_ARGS);
    CHECK(nf == 7 && memcmp(fields, "too big", 7) == 0);
    b.ram = NULL;
    board_stop(&b);
    close(peer);
}

static void shared_receive_checks_crc(void)
{
    static uint8_t ram[RAM_SIZE];
    struct board b;
    int peer;
    session(&b, &peer, ram);
    for (uint32_t i = 0; i < 5000; i++)
        ram[0x100 + i] = link_pattern_byte(i);
    uint32_t good = wordsum(ram + 0x100, 5000);
    peer_bulk(peer, 0x100, 5000, good);
    peer_bulk(peer, 0x100, 5000, good ^ 1);
    peer_bulk(peer, RAM_SIZE, 1, 0);
    struct link_bulk k;
    const uint8_t *data = NULL;
    CHECK_EQ_INT(link_shared_receive(&b, &k, &data), 0);
    CHECK(data == ram + 0x100 && k.length == 5000 && k.sum == good);
    CHECK_EQ_INT(link_shared_receive(&b, &k, &data), -2); /* wrong CRC: the pull again */
    CHECK_EQ_INT(link_shared_receive(&b, &k, &data), -1); /* outside the RAM */
    b.ram = NULL;
    board_stop(&b);
    close(peer);
}

/* The board found other bytes than the host's CRC says and offers the same
 * memory again: the host copies them again and sends a new LINK_BULK. */
static void shared_send_copies_again_on_a_new_offer(void)
{
    static uint8_t ram[RAM_SIZE];
    struct board b;
    int peer;
    session(&b, &peer, ram);
    uint8_t data[2000];
    for (size_t i = 0; i < sizeof data; i++)
        data[i] = link_pattern_byte((uint32_t)i + 5);
    peer_bulk(peer, 0x8000, 4096, 0); /* the offer */
    peer_bulk(peer, 0x8000, 4096, 0); /* and again: the CRC failed */
    uint8_t ack[LINK_ACK_SIZE];
    wire_put_u16(ack, 1); /* the host's second BULK */
    peer_send(peer, LINK_ACK, ack, sizeof ack);
    CHECK_EQ_INT(link_shared_send(&b, data, sizeof data), 0);
    CHECK(memcmp(ram + 0x8000, data, sizeof data) == 0);
    struct link_bulk k1, k2;
    CHECK_EQ_INT(peer_read_bulk(peer, &k1), 0);
    CHECK_EQ_INT(peer_read_bulk(peer, &k2), 0);
    CHECK_EQ_INT(k2.offset, 0x8000);
    CHECK_EQ_INT(k2.length, sizeof data);
    CHECK_EQ_INT(k2.sum, wordsum(data, sizeof data));
    close(peer);
    board_session_close(&b);
}

int main(void)
{
    RUN(shared_send_lands_where_offered);
    RUN(shared_send_cancels_offer_outside_ram);
    RUN(shared_send_leaves_refusal_for_caller);
    RUN(shared_receive_checks_crc);
    RUN(shared_send_copies_again_on_a_new_offer);
    return check_exit();
}
