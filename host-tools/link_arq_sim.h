/* link_arq_sim.h: the host link's stop-and-wait retransmission
 * (proto/link_arq.h) run between a simulated sender and receiver joined by
 * two byte pipes through struct link_noise, on a virtual clock: one step, one
 * round of both ends.  The host tests and bench-link-arq use it. */
#ifndef LINKS1_HOST_LINK_ARQ_SIM_H
#define LINKS1_HOST_LINK_ARQ_SIM_H

#include <stddef.h>
#include <stdint.h>

struct link_arq_sim_result {
    int completed;       /* every message taken */
    int exact_prefix;    /* what was taken equals the start of what was sent */
    size_t sent_bytes, taken_bytes; /* payload bytes offered, taken */
    uint32_t resends;    /* frames the sender sent again */
    uint64_t wire_bytes; /* bytes both ends put on the line (frames, resends, answers) */
    uint64_t steps;      /* virtual clock steps the run took */
};

/* Byte i of the simulated messages. */
uint8_t link_arq_sim_byte(uint32_t i);

/* Sends msgs messages of msg_len bytes (1..LINK_MAX_PAYLOAD) as LINK_DATA
 * frames numbered from first_seq, through noise at rate each way (seeded). */
struct link_arq_sim_result link_arq_sim_run(double rate, uint64_t seed, unsigned msgs,
                                            size_t msg_len, uint16_t first_seq);

#endif
