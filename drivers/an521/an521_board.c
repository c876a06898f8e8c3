/* an521_board.c: the board's number, the boards joined, this core's
 * number (kernel/machine.h). */
#include "drivers/an521/an521_board.h"

#include "drivers/an521/an521_map.h"
#include "kernel/arch.h"
#include "kernel/machine.h"
#include "proto/units.h"

static uint32_t an521_board_no;  /* this board: 0 .. boards - 1 */
static uint32_t an521_boards_no; /* boards joined */

static volatile uint32_t *an521_hdr(uint32_t off)
{
    return (volatile uint32_t *)(uintptr_t)(AN521_SHARED_BASE + off);
}

const char *an521_board_probe(void)
{
    if (*an521_hdr(AN521_HDR_MAGIC_OFF) != AN521_HDR_MAGIC)
        return "the shared file has no an521 header (start the boards with links1)";
    uint32_t boards = *an521_hdr(AN521_HDR_BOARDS_OFF);
    uint32_t board = *(volatile uint32_t *)(uintptr_t)AN521_BOARD_ID_ADDR;
    if (boards < 2 || boards > AN521_MAX_BOARDS)
        return "the shared file's header names a number of boards out of range";
    if (board >= boards)
        return "this board's number is beyond the boards joined";
    an521_board_no = board;
    an521_boards_no = boards;
    return 0;
}

uint32_t an521_board(void)
{
    return an521_board_no;
}

uint32_t an521_boards(void)
{
    return an521_boards_no;
}

uint32_t an521_local_core(void)
{
    return mmio_read32(AN521_CPUID) & 1u;
}

void an521_shared_ready(void)
{
    arch_dmb(); /* every shared block written before the word that says so */
    *an521_hdr(AN521_HDR_READY_OFF) = AN521_HDR_READY;
}

int an521_shared_is_ready(void)
{
    int ready = *an521_hdr(AN521_HDR_READY_OFF) == AN521_HDR_READY;
    arch_dmb();
    return ready;
}

uint32_t machine_core_id(void)
{
    return an521_board_no * AN521_CORES_PER_BOARD + an521_local_core();
}

uint32_t machine_core_hwid(void)
{
    /* Board number in the high half, the SSE-200's CPUID in the low. */
    return (an521_board_no << 16) | an521_local_core();
}
