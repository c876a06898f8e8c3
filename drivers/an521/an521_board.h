/* an521_board.h: which board of the joined an521 boards this is, and the
 * header of the shared file (proto/board_map_an521.h). */
#ifndef LINKS1_DRIVERS_AN521_AN521_BOARD_H
#define LINKS1_DRIVERS_AN521_AN521_BOARD_H

#include <stdint.h>

/* Core 0 of each board, first thing after .bss is cleared: reads the
 * board's number (AN521_BOARD_ID_ADDR) and the boards joined (the shared
 * file's header).  Returns NULL, or a text naming what is wrong. */
const char *an521_board_probe(void);
/* This board's number (0: the DM and RC's board) and the boards joined. */
uint32_t an521_board(void);
uint32_t an521_boards(void);
/* This core on its board: 0 or 1 (the SSE-200's CPUID). */
uint32_t an521_local_core(void);

/* Board 0, once the shared blocks are set up: tells the other boards. */
void an521_shared_ready(void);
/* Other boards: 1 once board 0 said the shared blocks are set up. */
int an521_shared_is_ready(void);

#endif
