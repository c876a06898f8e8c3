/* an521_relay.h: board 0's side of the host-link relay (drivers/an521/
 * relay.c). */
#ifndef LINKS1_DRIVERS_AN521_AN521_RELAY_H
#define LINKS1_DRIVERS_AN521_AN521_RELAY_H

/* Board 0, core 0: starts the task that sends the other boards' messages. */
void an521_relay_start(void);

#endif
