/* render_faults.h: `links1 render --inject-faults K[:SEED]` (the test hook
 * of proto/render_link.h): the plan of which NCs fail, how and when, and
 * the summary of what a frame lost and got back. */
#ifndef LINKS1_HOST_RENDER_FAULTS_H
#define LINKS1_HOST_RENDER_FAULTS_H

#include <stdint.h>
#include <stdio.h>

#include "proto/hostlink.h"
#include "proto/render_link.h"

/* --inject-kind: one kind for every failing NC, or 0 for a random one each. */
#define RENDER_FAULTS_MIXED 0

/* Parses "K[:SEED]"; 0, or -1 if it is not that form. */
int render_faults_parse(const char *arg, unsigned *k, unsigned *seed);
/* Parses undef, abort, hang, silent or mixed; 0 or -1. */
int render_faults_kind_parse(const char *name, uint8_t *kind);
const char *render_faults_kind_name(uint8_t kind);

/* The plan for k of the NCs 2..ncs+1 not marked in the core map taken
 * (then marked there): LINK_INJECT_SIZE(k) bytes into out.  Each failing
 * NC, its point in the frame and (for kind RENDER_FAULTS_MIXED) its kind
 * are drawn from seed.  Fewer than k when fewer than k + 1 are left (one
 * must stay).  Returns the bytes. */
uint32_t render_faults_plan(unsigned k, unsigned seed, uint8_t kind, unsigned ncs,
                            uint8_t taken[LINK_CORE_MAP_SIZE],
                            uint8_t out[LINK_INJECT_SIZE(LINK_INJECT_MAX)]);
/* Prints the plan, one line. */
void render_faults_print_plan(FILE *out, const uint8_t *plan);

/* The first of n faults the board reported that is the DM's or the RC's
 * (the board cannot render on then), or -1. */
int render_faults_unit_down(const struct link_fault *faults, int n);

/* Prints "NCs failed: ...; areas re-issued: ..." for a frame that lost
 * any NC; nothing otherwise. */
void render_faults_print(FILE *out, uint32_t frame, const struct link_render_fails *f);

#endif
