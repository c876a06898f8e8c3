/* ref_program.h: where the host reference renderer of each build lives. */
#ifndef LINKS1_HOST_REF_PROGRAM_H
#define LINKS1_HOST_REF_PROGRAM_H

#include <stddef.h>

/* The path of links1-ref-<build> next to this program into out; 0, or -1
 * after printing why. */
int ref_program_path(const char *build, char *out, size_t cap);

#endif
