/* hostlink_relay.h: host-link messages of unit computers that do not
 * reach the host link's UART themselves.  On the virt board every core
 * does (drivers/virt/relay_none.c); on the an521 boards only board 0 has
 * the link, and the NC boards' cores put their messages in the shared file
 * for board 0 to send (drivers/an521/relay.c). */
#ifndef LINKS1_DRIVERS_SERIAL_HOSTLINK_RELAY_H
#define LINKS1_DRIVERS_SERIAL_HOSTLINK_RELAY_H

#include <stddef.h>
#include <stdint.h>

/* 1 when this core's messages go through the relay. */
int hostlink_relay_here(void);
/* Queues one message for the board with the link.  Waits (sleeping) for
 * room up to a bound; with interrupts masked (a fault) it does not wait,
 * and a message that finds no room is dropped and counted. */
void hostlink_relay_put(uint8_t type, uint8_t flags, const void *payload, size_t len);

#endif
