/* fake_qemu.h: the board's side of the UART as the host tests that start
 * a fake QEMU play it (the test program run again as $QEMU): frames in the
 * board's own encoding, one report-in per core. */
#ifndef LINKS1_TESTS_FAKE_QEMU_H
#define LINKS1_TESTS_FAKE_QEMU_H

#include <stddef.h>
#include <stdint.h>
#include <unistd.h>

#include "proto/hostlink.h"

static int fake_fd;       /* the board's end of the UART */
static uint16_t fake_seq; /* the board's frame counter */

/* Sends one frame; 0, or -1 when the tool's end is gone. */
static int fake_send(uint8_t type, const void *p, size_t n)
{
    uint8_t frame[LINK_MAX_FRAME];
    size_t len = link_frame_encode(frame, sizeof frame, type, 0, fake_seq++, p, n);
    return write(fake_fd, frame, len) == (ssize_t)len ? 0 : -1;
}

/* Core core of ncores reports in (LINK_HELLO); 0, or -1 as fake_send. */
static int fake_hello(int core, int ncores)
{
    struct link_hello h = {.core = (uint16_t)core, .role = unit_role_of_core((uint32_t)core),
                           .variant = 0, .mpidr = 0x80000000u | (uint32_t)core,
                           .ncores = (uint16_t)ncores};
    uint8_t p[LINK_HELLO_SIZE];
    link_hello_put(p, &h);
    return fake_send(LINK_HELLO, p, sizeof p);
}

#endif
