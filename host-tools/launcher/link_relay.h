/* link_relay.h: the relay of `--link-noise RATE[:SEED]` (a test hook): a
 * thread of the tool that sits between the tool's end of the UART socket and
 * QEMU's, passing every byte both ways through struct link_noise. */
#ifndef LINKS1_HOST_LINK_RELAY_H
#define LINKS1_HOST_LINK_RELAY_H

#include <stdint.h>

/* Starts the relay between tool_fd and qemu_fd (it owns both from now on
 * and closes both when either side ends).  Returns 0, or -1 after printing
 * why. */
int link_relay_start(int tool_fd, int qemu_fd, double rate, uint64_t seed);

#endif
