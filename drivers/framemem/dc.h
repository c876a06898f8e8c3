/* dc.h: the data collector (DC) of LINKS-1 on the board: the one FIFO
 * every NC pushes its finished pixels into, emptied by one unit computer
 * (the consumer) into the frame memory (fm.h).
 *
 * The FIFO is dc_ring.h (lock-free, many producers, one consumer, nothing
 * dropped: see there for the memory ordering).  This file adds sleeping:
 * a producer that finds the FIFO full, or the consumer that finds it empty,
 * sleeps in task_wait() (WFI, never spinning) and is woken by the other
 * side with an SGI_DOORBELL, sent only when the sleeper raised its waiting
 * flag first.
 *
 * Use: dc_init(consumer) once while no one pushes (core 0 before waking the
 * others, or the consumer between frames).  NCs: dc_push_span() per
 * finished span.  Consumer: dc_collect_wait() in a loop until
 * fm->pixels_written says the frame is complete. */
#ifndef LINKS1_DRIVERS_FRAMEMEM_DC_H
#define LINKS1_DRIVERS_FRAMEMEM_DC_H

#include <stdint.h>

#include "drivers/framemem/dc_ring.h"
#include "drivers/framemem/fm.h"

/* Empties the FIFO and names the core that will collect. */
void dc_init(uint32_t consumer_core);

/* Producer (any core but the consumer): pushes one run, sleeping while the
 * FIFO is full.  Sets run->producer to the calling core. */
void dc_push(struct dc_run *run);
/* Producer: n pixels of row y from x on, as r,g,b bytes (the renderer's
 * rgb8_t array), cut into runs of DC_RUN_MAX_PIXELS.  DC_OK, or DC_ERR_RUN
 * (nothing pushed) if the span starts outside the largest frame or n = 0. */
int dc_push_span(uint32_t x, uint32_t y, const uint8_t *rgb, uint32_t n);

/* Consumer: moves up to max_runs waiting runs into fm without sleeping;
 * returns how many it took.  Runs outside fm are refused and counted in
 * fm->runs_refused. */
uint32_t dc_collect(struct fm *fm, uint32_t max_runs);
/* Consumer: like dc_collect with no bound, but sleeps until at least one
 * run came or deadline (ticks, 0 = none) passed; 0 = deadline passed. */
uint32_t dc_collect_wait(struct fm *fm, uint64_t deadline);

/* Consumer: like dc_collect_wait, but also returns (0) once *stop is
 * nonzero, checked whenever the core wakes (the setter signals it). */
uint32_t dc_collect_until(struct fm *fm, uint64_t deadline, const volatile int *stop);
/* Consumer, once no producer will push again: takes every published run
 * and gives up positions a failed producer claimed but never published;
 * returns how many it gave up. */
uint32_t dc_collect_final(struct fm *fm);
/* From now on runs that producer pushes are dropped by the consumer (a
 * producer given up for failed: its area is drawn again by another). */
void dc_ignore_producer(uint32_t producer);

/* Times a producer found the FIFO full and had to wait (statistics). */
uint32_t dc_full_waits(void);

#endif
