/* dm.h: what the parts of the DM program share (roles/dm.c: tasks and
 * command dispatch; roles/dm_checks.c: line and IMSU checks;
 * roles/dm_transfer.c: host-link bulk transfers). */
#ifndef LINKS1_ROLES_DM_H
#define LINKS1_ROLES_DM_H

#include <stdint.h>

#include "drivers/serial/linemsg.h"
#include "proto/hostlink.h"

/* A host frame taken from the queue. */
struct dm_frame {
    uint8_t type, flags;
    uint16_t seq, length;
    uint8_t payload[LINK_MAX_PAYLOAD];
};

extern struct dm_frame dm_frame;  /* the frame the command task works on */
extern struct line_msg dm_msg;    /* the DM's line message buffer */
extern uint32_t dm_link_errors;   /* host -> board frames dropped so far */

/* Takes the next queued host frame into dm_frame; 0, or -1 at deadline. */
int dm_next_frame(uint64_t deadline);
/* Sends m to the RC and waits for its answer of answer_type into m. */
int dm_rc_request(struct line_msg *m, uint16_t answer_type, uint32_t timeout_ms);

/* Command handlers: each answers with one LINK_RESULT. */
void dm_cmd_line_ping(uint16_t cmd);
void dm_cmd_imsu_test(uint16_t cmd);
void dm_cmd_line_stress(uint16_t cmd);
void dm_cmd_link_sink(uint16_t cmd);
void dm_cmd_link_source(uint16_t cmd);

#endif
