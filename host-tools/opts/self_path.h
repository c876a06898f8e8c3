/* self_path.h: where this program lives, for finding the programs and
 * files installed beside it (the firmware, links1-ref-*, insn-count.so). */
#ifndef LINKS1_HOST_OPTS_SELF_PATH_H
#define LINKS1_HOST_OPTS_SELF_PATH_H

#include <stddef.h>

/* The directory of the running program (/proc/self/exe) into out.
 * 0, or -1 with out empty when it cannot be read or does not fit. */
int self_dir(char *out, size_t cap);

/* out = "<self_dir>/name".  0, or -1 (out empty) when that does not fit. */
int self_sibling(const char *name, char *out, size_t cap);

#endif
