/* Host tests of the host link's go-back-N pieces (proto/link_arq.h: the
 * receiver's verdict, the store of frames kept for resending, the NAK's
 * rate limit) and of `--link-noise` (host-tools/launcher/link_noise.h,
 * link_relay.h): the damage it does and the relay that does it. */
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "host-tools/launcher/link_noise.h"
#include "host-tools/launcher/link_relay.h"
#include "proto/link_arq.h"
#include "proto/wire.h"
#include "tests/check.h"

/* Byte i of the bytes sent through the relay. */
static uint8_t pattern_byte(uint32_t i)
{
    return (uint8_t)(i * 2654435761u >> 24);
}

static struct link_frame arq_frame(uint8_t type, uint8_t flags, uint16_t seq, const uint8_t *p,
                                   uint16_t len)
{
    struct link_frame f = {type, flags, seq, len, p};
    return f;
}

static void arq_receiver_takes_once_and_naks_others(void)
{
    struct link_arq_rx rx;
    link_arq_rx_init(&rx);
    uint8_t p[1] = {0};
    struct link_frame f = arq_frame(LINK_CMD, 0, 7, p, 1);
    CHECK_EQ_INT(link_arq_rx_take(&rx, &f), LINK_ARQ_NEW);
    CHECK_EQ_INT(link_arq_rx_take(&rx, &f), LINK_ARQ_DUP);
    f.seq = 9;
    CHECK_EQ_INT(link_arq_rx_take(&rx, &f), LINK_ARQ_OTHER);
    CHECK_EQ_INT(rx.expect, 8);
    f.seq = 8;
    CHECK_EQ_INT(link_arq_rx_take(&rx, &f), LINK_ARQ_NEW);
    f.seq = 3;
    f.flags = LINK_FLAG_SESSION; /* a new session numbers from anywhere */
    CHECK_EQ_INT(link_arq_rx_take(&rx, &f), LINK_ARQ_NEW);
    CHECK_EQ_INT(rx.expect, 4);
}

static void noise_counts_each_kind_near_rate(void)
{
    static uint8_t in[1 << 20], out[2 << 20];
    for (size_t i = 0; i < sizeof in; i++)
        in[i] = (uint8_t)i;
    struct link_noise z;
    link_noise_init(&z, 1e-2, 42);
    size_t k = link_noise_apply(&z, in, sizeof in, out);
    uint64_t hits = z.flipped + z.dropped + z.duplicated + z.inserted;
    CHECK_NEAR((double)hits / (double)sizeof in, 1e-2, 1e-3);
    CHECK(z.flipped > 0 && z.dropped > 0 && z.duplicated > 0 && z.inserted > 0);
    CHECK_EQ_INT(k, sizeof in - z.dropped + z.duplicated + z.inserted);
    link_noise_init(&z, 0, 42);
    CHECK_EQ_INT(link_noise_apply(&z, in, 4096, out), 4096);
    CHECK(memcmp(in, out, 4096) == 0);
}

static void noise_parse_rate_and_seed(void)
{
    double rate;
    uint64_t seed;
    char why[160];
    CHECK_EQ_INT(link_noise_parse("1e-3", &rate, &seed, why, sizeof why), 0);
    CHECK_NEAR(rate, 1e-3, 1e-12);
    CHECK_EQ_INT(seed, 1);
    CHECK_EQ_INT(link_noise_parse("0.01:77", &rate, &seed, why, sizeof why), 0);
    CHECK_EQ_INT(seed, 77);
    CHECK_EQ_INT(link_noise_parse("2", &rate, &seed, why, sizeof why), -1);
    CHECK(strstr(why, "RATE") != NULL);
    CHECK_EQ_INT(link_noise_parse("nan", &rate, &seed, why, sizeof why), -1);
    CHECK_EQ_INT(link_noise_parse("1e-3:x", &rate, &seed, why, sizeof why), -1);
    CHECK(strstr(why, "SEED") != NULL);
}

/* A relay that moves no byte for this long has stalled (the test fails on
 * the bytes missing); it is not how a pass ends. */
#define RELAY_STALL_MS 20000

/* Writes n pattern bytes into a and reads what arrives at b, until cap
 * bytes came or b reads end-of-file; with end, a's sending side is shut
 * once all n are written, so the relay ends b after handing on what it
 * holds (the end of a damaged pass, whose length the noise changes).
 * Returns the bytes read into got. */
static size_t relay_pass(int a, int b, size_t n, uint8_t *got, size_t cap, int end)
{
    size_t put = 0, have = 0;
    int shut = 0;
    while (have < cap) {
        if (end && put == n && !shut) {
            shutdown(a, SHUT_WR);
            shut = 1;
        }
        struct pollfd p[2] = {{a, put < n ? POLLOUT : 0, 0}, {b, POLLIN, 0}};
        if (poll(p, 2, RELAY_STALL_MS) <= 0)
            break;
        if (p[0].revents & POLLOUT) {
            uint8_t chunk[4096];
            size_t k = n - put < sizeof chunk ? n - put : sizeof chunk;
            for (size_t i = 0; i < k; i++)
                chunk[i] = pattern_byte((uint32_t)(put + i));
            ssize_t w = write(a, chunk, k);
            if (w > 0)
                put += (size_t)w;
        }
        if (p[1].revents & (POLLIN | POLLHUP)) {
            ssize_t r = read(b, got + have, cap - have);
            if (r <= 0)
                break;
            have += (size_t)r;
        }
    }
    return have;
}

static void relay_passes_bytes_and_ends_with_either_side(void)
{
    int tool[2], qemu[2];
    CHECK(socketpair(AF_UNIX, SOCK_STREAM, 0, tool) == 0);
    CHECK(socketpair(AF_UNIX, SOCK_STREAM, 0, qemu) == 0);
    CHECK_EQ_INT(link_relay_start(tool[1], qemu[0], 0, 1), 0);
    size_t n = 1u << 20;
    uint8_t *got = malloc(n);
    CHECK_EQ_INT(relay_pass(tool[0], qemu[1], n, got, n, 0), n);
    int same = 1;
    for (size_t i = 0; i < n; i++)
        same &= got[i] == pattern_byte((uint32_t)i);
    CHECK(same);
    CHECK_EQ_INT(relay_pass(qemu[1], tool[0], n, got, n, 0), n);
    close(qemu[1]); /* QEMU ends: the tool reads end-of-file */
    uint8_t c;
    struct pollfd p = {tool[0], POLLIN, 0};
    CHECK(poll(&p, 1, 2000) == 1);
    CHECK_EQ_INT(read(tool[0], &c, 1), 0);
    close(tool[0]);
    free(got);
}

static void relay_damages_at_its_rate(void)
{
    int tool[2], qemu[2];
    CHECK(socketpair(AF_UNIX, SOCK_STREAM, 0, tool) == 0);
    CHECK(socketpair(AF_UNIX, SOCK_STREAM, 0, qemu) == 0);
    CHECK_EQ_INT(link_relay_start(tool[1], qemu[0], 1e-2, 7), 0);
    size_t n = 1u << 18;
    uint8_t *got = malloc(2 * n);
    size_t k = relay_pass(tool[0], qemu[1], n, got, 2 * n, 1);
    /* Drops and additions nearly balance; count the bytes that differ in
     * place up to the first length change instead: some must. */
    size_t differ = 0;
    for (size_t i = 0; i < k && i < n; i++)
        differ += got[i] != pattern_byte((uint32_t)i);
    CHECK(k > n - n / 50 && k < n + n / 50);
    CHECK(differ > 0);
    close(qemu[1]);
    close(tool[0]);
    free(got);
}


/* ---- go-back-N: the store of frames kept for resending, the NAK limit ---- */

static void arq_store_keeps_frames_until_pushed_out(void)
{
    static struct link_arq_store st;
    link_arq_store_init(&st, 65530); /* seqs wrap on the way */
    uint8_t out[LINK_MAX_FRAME], got[LINK_MAX_FRAME], payload[1000];
    for (int k = 0; k < 300; k++) {
        memset(payload, k, sizeof payload);
        size_t len = (size_t)(k % 7) * 150 + 1;
        size_t n = link_arq_store_frame(&st, out, sizeof out, LINK_DATA, 0, payload, len);
        CHECK_EQ_INT(n, LINK_HEADER_SIZE + len + LINK_CRC_SIZE);
        /* The newest frame reads back byte for byte. */
        CHECK_EQ_INT(link_arq_store_get(&st, (uint16_t)(65530 + k), got, sizeof got), n);
        CHECK(memcmp(got, out, n) == 0);
    }
    uint16_t next = (uint16_t)(65530 + 300);
    CHECK_EQ_INT(st.next_seq, next);
    CHECK_EQ_INT(link_arq_store_span(&st, next), 0);      /* nothing to resend */
    CHECK_EQ_INT(link_arq_store_span(&st, (uint16_t)(next - 5)), 5);
    CHECK_EQ_INT(link_arq_store_span(&st, (uint16_t)(next + 3)), -1); /* never sent */
    CHECK_EQ_INT(link_arq_store_span(&st, 65530), -1);   /* pushed out (256 frames kept) */
    /* Bytes: 64 KiB hold only the newest ~140 of these frames. */
    int held = 0;
    for (int k = 1; k <= 256; k++)
        held += link_arq_store_get(&st, (uint16_t)(next - k), got, sizeof got) > 0;
    CHECK(held > 100 && held < 256);
    CHECK_EQ_INT(link_arq_store_span(&st, (uint16_t)(next - held)), held);
    CHECK_EQ_INT(link_arq_store_span(&st, (uint16_t)(next - held - 1)), -1);
    /* A resend stops after the frame that reaches LINK_ARQ_RESEND_BYTES. */
    int k = link_arq_store_resend_count(&st, (uint16_t)(next - held), held);
    CHECK(k > 0 && k < held);
    size_t bytes = 0;
    for (int i = 0; i < k; i++)
        bytes += link_arq_store_get(&st, (uint16_t)(next - held + i), got, sizeof got);
    CHECK(bytes >= LINK_ARQ_RESEND_BYTES);
    CHECK(bytes - link_arq_store_get(&st, (uint16_t)(next - held + k - 1), got, sizeof got) <
          LINK_ARQ_RESEND_BYTES);
}

static void arq_nak_is_rate_limited_and_counted(void)
{
    struct link_arq_nak n = {0};
    CHECK_EQ_INT(link_arq_nak_due(&n, 7, 1000, LINK_ARQ_NAK_MS), 1);
    CHECK_EQ_INT(link_arq_nak_due(&n, 7, 1000 + LINK_ARQ_NAK_MS - 1, LINK_ARQ_NAK_MS), 0);
    CHECK_EQ_INT(link_arq_nak_due(&n, 7, 1000 + LINK_ARQ_NAK_MS, LINK_ARQ_NAK_MS), 1);
    CHECK_EQ_INT(n.tries, 2);
    CHECK_EQ_INT(link_arq_nak_due(&n, 8, 1000 + LINK_ARQ_NAK_MS, LINK_ARQ_NAK_MS), 1);
    CHECK_EQ_INT(n.tries, 1); /* a new seq: counted afresh */
    uint8_t f[32];
    size_t len = link_arq_nak_encode(f, sizeof f, LINK_FLAG_POLL, 0x1234);
    struct link_decoder d;
    link_decoder_init(&d);
    struct link_frame fr;
    int got = 0;
    for (size_t i = 0; i < len; i++)
        got |= link_decoder_push(&d, f[i], &fr);
    CHECK(got);
    CHECK_EQ_INT(fr.type, LINK_NAK);
    CHECK_EQ_INT(fr.flags, LINK_FLAG_POLL);
    CHECK_EQ_INT(wire_get_u16(fr.payload), 0x1234);
}

static void arq_rx_drops_everything_behind(void)
{
    struct link_arq_rx r;
    link_arq_rx_init(&r);
    struct link_frame f = {.type = LINK_DATA, .seq = 100};
    CHECK_EQ_INT(link_arq_rx_take(&r, &f), LINK_ARQ_NEW);
    f.seq = 101;
    CHECK_EQ_INT(link_arq_rx_take(&r, &f), LINK_ARQ_NEW);
    f.seq = 90; /* an old frame sent again */
    CHECK_EQ_INT(link_arq_rx_take(&r, &f), LINK_ARQ_DUP);
    f.seq = 104; /* after a gap */
    CHECK_EQ_INT(link_arq_rx_take(&r, &f), LINK_ARQ_OTHER);
    CHECK_EQ_INT(r.expect, 102);
}

int main(void)
{
    RUN(arq_receiver_takes_once_and_naks_others);
    RUN(noise_counts_each_kind_near_rate);
    RUN(noise_parse_rate_and_seed);
    RUN(relay_passes_bytes_and_ends_with_either_side);
    RUN(relay_damages_at_its_rate);
    RUN(arq_store_keeps_frames_until_pushed_out);
    RUN(arq_nak_is_rate_limited_and_counted);
    RUN(arq_rx_drops_everything_behind);
    return check_exit();
}
