/* test_fwcfg.c: fw_cfg DMA records, file directory search and the ramfb
 * configuration, byte for byte as QEMU's fw_cfg spec lays them out. */
#include <stdint.h>
#include <string.h>

#include "drivers/framemem/fm_param.h"
#include "drivers/virt/fwcfg_format.h"
#include "tests/check.h"

static void test_dma_record_is_big_endian(void)
{
    uint8_t rec[FWCFG_DMA_RECORD_SIZE];
    uint32_t control = fwcfg_dma_control(0x0123, FWCFG_DMA_SELECT | FWCFG_DMA_WRITE);
    CHECK_EQ_INT(control, 0x01230018u);
    fwcfg_dma_encode(rec, control, 28, 0x0000000140001000ull);
    static const uint8_t want[FWCFG_DMA_RECORD_SIZE] = {
        0x01, 0x23, 0x00, 0x18, 0x00, 0x00, 0x00, 0x1c,
        0x00, 0x00, 0x00, 0x01, 0x40, 0x00, 0x10, 0x00,
    };
    CHECK(memcmp(rec, want, sizeof want) == 0);
}

static void test_ramfb_config_layout(void)
{
    uint8_t cfg[RAMFB_CONFIG_SIZE];
    memset(cfg, 0xAA, sizeof cfg);
    ramfb_config_encode(cfg, 0x43800000ull, RAMFB_FOURCC_XR24, 512, 480, 2048);
    static const uint8_t want[RAMFB_CONFIG_SIZE] = {
        0x00, 0x00, 0x00, 0x00, 0x43, 0x80, 0x00, 0x00, /* be64 address */
        0x34, 0x32, 0x52, 0x58,                         /* fourcc, be32 */
        0x00, 0x00, 0x00, 0x00,                         /* flags */
        0x00, 0x00, 0x02, 0x00,                         /* width 512 */
        0x00, 0x00, 0x01, 0xe0,                         /* height 480 */
        0x00, 0x00, 0x08, 0x00,                         /* stride 2048 */
    };
    CHECK(memcmp(cfg, want, sizeof want) == 0);
    /* XR24 is the characters 'X','R','2','4' read as a little-endian word. */
    CHECK(memcmp(&(uint32_t){RAMFB_FOURCC_XR24}, "XR24", 4) == 0 ||
          __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__);
}

/* A directory image in memory, read front to back like the device. */
struct mem_reader {
    const uint8_t *data;
    size_t len, pos;
    int reads;
};

static int mem_read(void *ctx, void *buf, uint32_t len)
{
    struct mem_reader *m = ctx;
    m->reads++;
    if (len > m->len - m->pos)
        return -1;
    memcpy(buf, m->data + m->pos, len);
    m->pos += len;
    return 0;
}

static size_t dir_build(uint8_t *dir, uint32_t count, const char *const *names)
{
    fwcfg_put_be32(dir, count);
    for (uint32_t i = 0; i < count; i++) {
        uint8_t *e = dir + 4 + i * FWCFG_DIR_ENTRY_SIZE;
        memset(e, 0, FWCFG_DIR_ENTRY_SIZE);
        fwcfg_put_be32(e, 100 + i);
        e[4] = 0x00;
        e[5] = (uint8_t)(0x20 + i);
        strncpy((char *)e + 8, names[i], FWCFG_FILE_NAME_SIZE);
    }
    return 4 + (size_t)count * FWCFG_DIR_ENTRY_SIZE;
}

static void test_dir_finds_ramfb(void)
{
    static const char *const names[] = {"bootorder", "etc/ramfb-old", "etc/ramfb",
                                        "etc/table-loader"};
    uint8_t dir[4 + 4 * FWCFG_DIR_ENTRY_SIZE];
    size_t len = dir_build(dir, 4, names);
    struct mem_reader m = {dir, len, 0, 0};
    struct fwcfg_file f;
    CHECK_EQ_INT(fwcfg_dir_search(mem_read, &m, RAMFB_FILE_NAME, &f), FWCFG_OK);
    CHECK_EQ_INT(f.select, 0x22);
    CHECK_EQ_INT(f.size, 102);
    CHECK(strcmp(f.name, "etc/ramfb") == 0);
    CHECK_EQ_INT(m.reads, 4); /* count, then entries up to the match only */
}

static void test_dir_reports_missing_file(void)
{
    static const char *const names[] = {"bootorder", "etc/ramfbX"};
    uint8_t dir[4 + 2 * FWCFG_DIR_ENTRY_SIZE];
    size_t len = dir_build(dir, 2, names);
    struct mem_reader m = {dir, len, 0, 0};
    struct fwcfg_file f;
    CHECK_EQ_INT(fwcfg_dir_search(mem_read, &m, RAMFB_FILE_NAME, &f), FWCFG_ERR_NOT_FOUND);
    CHECK(f.name[0] == '\0');
    uint8_t empty[4] = {0, 0, 0, 0};
    struct mem_reader e = {empty, 4, 0, 0};
    CHECK_EQ_INT(fwcfg_dir_search(mem_read, &e, RAMFB_FILE_NAME, &f), FWCFG_ERR_NOT_FOUND);
}

static void test_dir_refuses_bad_directories(void)
{
    static const char *const names[] = {"a", "b", "etc/ramfb"};
    uint8_t dir[4 + 3 * FWCFG_DIR_ENTRY_SIZE];
    size_t len = dir_build(dir, 3, names);
    struct fwcfg_file f;
    /* Cut short before the match: a read error, not "not found". */
    struct mem_reader cut = {dir, len - 1, 0, 0};
    CHECK_EQ_INT(fwcfg_dir_search(mem_read, &cut, RAMFB_FILE_NAME, &f), FWCFG_ERR_READ);
    /* An absurd count is refused before any entry is read. */
    fwcfg_put_be32(dir, FWCFG_MAX_FILES + 1);
    struct mem_reader big = {dir, len, 0, 0};
    CHECK_EQ_INT(fwcfg_dir_search(mem_read, &big, RAMFB_FILE_NAME, &f), FWCFG_ERR_DIR);
    CHECK_EQ_INT(big.reads, 1);
    struct mem_reader none = {dir, 2, 0, 0};
    CHECK_EQ_INT(fwcfg_dir_search(mem_read, &none, RAMFB_FILE_NAME, &f), FWCFG_ERR_READ);
}

/* A 56-byte name with no NUL is cut, never read past. */
static void test_entry_name_always_terminated(void)
{
    uint8_t e[FWCFG_DIR_ENTRY_SIZE];
    memset(e, 'x', sizeof e);
    fwcfg_put_be32(e, 7);
    e[4] = 0x12;
    e[5] = 0x34;
    struct fwcfg_file f;
    fwcfg_file_decode(e, &f);
    CHECK_EQ_INT(f.size, 7);
    CHECK_EQ_INT(f.select, 0x1234);
    CHECK_EQ_INT(strlen(f.name), FWCFG_FILE_NAME_SIZE - 1);
}

static void test_errors_have_messages(void)
{
    CHECK(strstr(fwcfg_strerror(FWCFG_ERR_NOT_FOUND), "ramfb") != NULL);
    CHECK(strstr(fwcfg_strerror(-99), "unknown") != NULL);
}

int main(void)
{
    RUN(test_dma_record_is_big_endian);
    RUN(test_ramfb_config_layout);
    RUN(test_dir_finds_ramfb);
    RUN(test_dir_reports_missing_file);
    RUN(test_dir_refuses_bad_directories);
    RUN(test_entry_name_always_terminated);
    RUN(test_errors_have_messages);
    return check_exit();
}
