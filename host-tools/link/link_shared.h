/* link_shared.h: the host's side of the shared-memory path of the host link
 * (LINK_BULK, proto/hostlink.h): bulk bytes copied straight into or out of
 * the board's RAM that board_start mapped (b->ram), their place and word
 * sum (proto/wordsum.h) told over the serial link. */
#ifndef LINKS1_HOST_LINK_SHARED_H
#define LINKS1_HOST_LINK_SHARED_H

#include <stddef.h>
#include <stdint.h>

#include "host-tools/link/board.h"

/* After a command that takes bulk bytes on the shared path: waits for the
 * board's offer, writes the len bytes there, tells the board where they are
 * and their word sum, and waits for its ACK.  Returns 0 once the board has them;
 * 1 when the board answered the command instead of offering (its RESULT is
 * left queued for the caller, who prints the board's reason); -1 after
 * printing why.  When the board offers the memory again (the bytes it found
 * did not have our sum) the bytes are copied again, up to LINK_BULK_TRIES. */
int link_shared_send(struct board *b, const void *data, size_t len);

/* After a command that sends bulk bytes on the shared path: waits for the
 * board's LINK_BULK, checks that it lies in the board's RAM and that the
 * bytes there have its word sum.  Returns 0 with *k filled and *data pointing at
 * the bytes (in the mapping, valid until the next command); 1 when the
 * board answered with its RESULT instead (left queued); -2 after printing
 * that the bytes do not have the sum (the caller may send its command again,
 * LINK_BULK_TRIES); -1 after printing why. */
int link_shared_receive(struct board *b, struct link_bulk *k, const uint8_t **data);

#endif
