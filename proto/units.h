/* units.h: the unit computers of the board: how many there may be, and
 * which core plays which role.  One definition for the firmware, the
 * linker script (linker/virt-memory.ld is run through the C preprocessor)
 * and the host tools, so it holds #defines only.
 *
 * Core 0 is the DM, core 1 the RC, cores 2.. the NCs: at least one NC, at
 * most the 254 NCs LINKS-1 was designed for. */
#ifndef LINKS1_PROTO_UNITS_H
#define LINKS1_PROTO_UNITS_H

#define UNITS_MAX_CORES 256
#define UNITS_MIN_CORES 3
#define UNITS_DM_CORE 0
#define UNITS_RC_CORE 1
#define UNITS_FIRST_NC 2

#endif
