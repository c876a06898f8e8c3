/* unit.h: start-up of a unit computer: report in, then run the program of
 * its role (DM roles/dm.c, RC roles/rc.c, NC roles/nc.c). */
#ifndef LINKS1_ROLES_UNIT_H
#define LINKS1_ROLES_UNIT_H

#include <stdint.h>

/* Called by boot code on every core once its kernel state is ready. */
void unit_start(void) __attribute__((noreturn));

/* Counts over the board's cores (read from any core). */
uint32_t unit_reported_count(void);
uint32_t unit_halted_count(void);
/* 1 if core has halted after a fault. */
int unit_is_halted(uint32_t core);

/* The role programs' main tasks. */
void dm_start(void);
void rc_main(void *arg);
void nc_main(void *arg);

#endif
