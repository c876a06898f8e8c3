/* fake_board.h: a board session with no QEMU for the host tests: the tool's
 * end of a socketpair, the test playing the board on the other end. */
#ifndef LINKS1_TESTS_FAKE_BOARD_H
#define LINKS1_TESTS_FAKE_BOARD_H

#include <sys/socket.h>

#include "host-tools/launcher/launcher.h"

static inline int fake_session(struct board *b, int *peer)
{
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM, 0, sv) < 0)
        return -1;
    struct board_opts o;
    board_opts_init(&o);
    o.quiet = 1;
    board_attach(b, &o, sv[0]);
    *peer = sv[1];
    return 0;
}

#endif
