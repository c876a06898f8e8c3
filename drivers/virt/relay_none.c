/* relay_none.c: on the virt board every core reaches the host link's UART
 * itself (hostlink_relay.h). */
#include "drivers/serial/hostlink_relay.h"

#include "kernel/panic.h"

int hostlink_relay_here(void)
{
    return 0;
}

void hostlink_relay_put(uint8_t type, uint8_t flags, const void *payload, size_t len)
{
    (void)flags;
    (void)payload;
    panic("hostlink_relay_put: the virt board relays nothing (message type %u, %u bytes)",
          (unsigned)type, (unsigned)len);
}
