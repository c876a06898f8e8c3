/* unit.c: a unit computer reports in and starts its role's tasks. */
#include "roles/unit.h"

#include "drivers/serial/hostlink_tx.h"
#include "kernel/cpu.h"
#include "kernel/task.h"
#include "proto/arith.h"
#include "proto/hostlink.h"

#ifndef LINKS1_ARITH
#error "the Makefile names the firmware's arithmetic: -DLINKS1_ARITH=ARITH_..."
#endif

static void unit_report_in(void)
{
    struct cpu *c = mycpu();
    struct link_hello h = {(uint16_t)c->core, c->role, LINKS1_ARITH, c->hwid,
                           (uint16_t)board_ncores, 0};
    uint8_t p[LINK_HELLO_SIZE];
    link_hello_put(p, &h);
    /* Marked before sending: a host that has the HELLO may ask CMD_STATUS
     * at once, and must find this core counted. */
    c->reported = 1;
    hostlink_send(LINK_HELLO, 0, p, sizeof p);
}

void unit_start(void)
{
    struct cpu *c = mycpu();
    c->started = 1;
    unit_report_in();
    switch (c->role) {
    case ROLE_DM:
        dm_start();
        break;
    case ROLE_RC:
        task_create("rc", rc_main, NULL);
        break;
    default:
        task_create("nc", nc_main, NULL);
        break;
    }
    task_schedule_forever();
}

uint32_t unit_reported_count(void)
{
    uint32_t n = 0;
    for (uint32_t k = 0; k < board_ncores; k++)
        n += cpu_of(k)->reported;
    return n;
}

uint32_t unit_halted_count(void)
{
    uint32_t n = 0;
    for (uint32_t k = 0; k < board_ncores; k++)
        n += cpu_of(k)->halted;
    return n;
}

int unit_is_halted(uint32_t core)
{
    return cpu_of(core)->halted;
}
