/* test_linemsg.c: encoding of inter-unit messages (drivers/serial/linemsg.c). */
#include <string.h>

#include "drivers/serial/linemsg.h"
#include "tests/check.h"

static void test_round_trip(void)
{
    static struct line_msg m, out;
    uint8_t buf[LINEMSG_MAX_SIZE];
    m.type = 0x1234;
    m.len = 5;
    m.seq = 0xA0B0C0D0u;
    memcpy(m.payload, "hello", 5);
    size_t n = linemsg_encode(buf, sizeof buf, &m);
    CHECK_EQ_INT(n, LINEMSG_HEADER_SIZE + 5);
    /* Little-endian fields at fixed offsets, whatever the host is. */
    CHECK(buf[0] == 0x34 && buf[1] == 0x12 && buf[2] == 5 && buf[3] == 0);
    CHECK(buf[4] == 0xD0 && buf[7] == 0xA0);
    CHECK_EQ_INT(linemsg_total_size(buf), LINEMSG_HEADER_SIZE + 5);
    CHECK_EQ_INT(linemsg_decode(buf, n, &out), LINEMSG_OK);
    CHECK_EQ_INT(out.type, 0x1234);
    CHECK_EQ_INT(out.len, 5);
    CHECK(out.seq == 0xA0B0C0D0u);
    CHECK(memcmp(out.payload, "hello", 5) == 0);
}

static void test_full_size_and_empty(void)
{
    static struct line_msg m, out;
    static uint8_t buf[LINEMSG_MAX_SIZE];
    m.type = 1;
    m.len = LINE_MAX_PAYLOAD;
    for (int i = 0; i < LINE_MAX_PAYLOAD; i++)
        m.payload[i] = (uint8_t)(i * 13);
    CHECK_EQ_INT(linemsg_encode(buf, sizeof buf, &m), LINEMSG_MAX_SIZE);
    CHECK_EQ_INT(linemsg_decode(buf, sizeof buf, &out), LINEMSG_OK);
    CHECK(memcmp(out.payload, m.payload, LINE_MAX_PAYLOAD) == 0);
    m.len = 0;
    CHECK_EQ_INT(linemsg_encode(buf, sizeof buf, &m), LINEMSG_HEADER_SIZE);
    CHECK_EQ_INT(linemsg_decode(buf, LINEMSG_HEADER_SIZE, &out), LINEMSG_OK);
    CHECK_EQ_INT(out.len, 0);
}

static void test_rejects_bad_input(void)
{
    static struct line_msg m, out;
    uint8_t buf[LINEMSG_MAX_SIZE];
    m.type = 2;
    m.len = 4;
    m.seq = 9;
    memcpy(m.payload, "data", 4);
    size_t n = linemsg_encode(buf, sizeof buf, &m);
    CHECK_EQ_INT(linemsg_encode(buf, n - 1, &m), 0);          /* no room */
    CHECK_EQ_INT(linemsg_decode(buf, n - 1, &out), LINEMSG_ERR_SHORT);
    CHECK_EQ_INT(linemsg_decode(buf, 3, &out), LINEMSG_ERR_SHORT);
    buf[LINEMSG_HEADER_SIZE + 2] ^= 1; /* one flipped payload bit */
    CHECK_EQ_INT(linemsg_decode(buf, n, &out), LINEMSG_ERR_CHECK);
    buf[LINEMSG_HEADER_SIZE + 2] ^= 1;
    buf[2] = 0xFF; /* length 0x00FF + ... */
    buf[3] = 0xFF; /* 65535 > LINE_MAX_PAYLOAD */
    CHECK_EQ_INT(linemsg_total_size(buf), LINEMSG_ERR_TOO_LONG);
    CHECK_EQ_INT(linemsg_decode(buf, n, &out), LINEMSG_ERR_TOO_LONG);
    m.len = LINE_MAX_PAYLOAD + 1;
    CHECK_EQ_INT(linemsg_encode(buf, sizeof buf, &m), 0);
    CHECK(strlen(linemsg_strerror(LINEMSG_ERR_CHECK)) > 0);
}

int main(void)
{
    RUN(test_round_trip);
    RUN(test_full_size_and_empty);
    RUN(test_rejects_bad_input);
    return check_exit();
}
