/* ref_program.c: links1-ref-<build> beside this program (ref_program.h). */
#include "host-tools/ref/ref_program.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "host-tools/opts/self_path.h"

int ref_program_path(const char *build, char *out, size_t cap)
{
    char name[64];
    snprintf(name, sizeof name, "links1-ref-%s", build);
    if (self_sibling(name, out, cap) < 0) {
        fprintf(stderr, "links1: cannot find my own directory: %s\n", strerror(errno));
        return -1;
    }
    return 0;
}
