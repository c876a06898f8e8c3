/* link_transfer.h: bulk transfers over the host link (LINK_DATA frames with
 * LINK_ACK flow control, see proto/hostlink.h): bytes up, and the link
 * tests' known pattern both ways. */
#ifndef LINKS1_HOST_LINK_TRANSFER_H
#define LINKS1_HOST_LINK_TRANSFER_H

#include <stddef.h>
#include <stdint.h>

#include "host-tools/link/board.h"

/* len bytes of data as one transfer, never more than LINK_DATA_WINDOW DATA
 * frames ahead of the board's ACKs, waiting for the last ACK (the serial
 * path of a bulk upload).  0, or -1 after printing why. */
int link_transfer_send(struct board *b, const void *data, size_t len);

/* The same with total (>= 1) bytes of the link tests' pattern.  *crc gets
 * the CRC-32 of what was sent.  Returns 0, or -1 after printing why. */
int link_transfer_send_pattern(struct board *b, uint32_t total, uint32_t *crc);

/* Receives one transfer from the board, ACKing each DATA frame, and checks
 * that its bytes are the pattern from offset 0, in order, with no DATA frame
 * repeated or out of order.  *bytes and *crc get what arrived.  Returns 0,
 * or -1 after printing the first problem (with its byte offset). */
int link_transfer_receive_pattern(struct board *b, uint64_t *bytes, uint32_t *crc);

#endif
