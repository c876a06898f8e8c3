/* self_path.c: the running program's directory (see self_path.h). */
#include "host-tools/opts/self_path.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

int self_dir(char *out, size_t cap)
{
    if (cap == 0)
        return -1;
    ssize_t n = readlink("/proc/self/exe", out, cap - 1);
    if (n <= 0 || (size_t)n >= cap - 1) {
        out[0] = 0;
        return -1;
    }
    out[n] = 0;
    char *slash = strrchr(out, '/');
    if (!slash) {
        out[0] = 0;
        return -1;
    }
    *slash = 0;
    return 0;
}

int self_sibling(const char *name, char *out, size_t cap)
{
    if (self_dir(out, cap) < 0)
        return -1;
    size_t have = strlen(out);
    int n = snprintf(out + have, cap - have, "/%s", name);
    if (n < 0 || (size_t)n >= cap - have) {
        out[0] = 0;
        return -1;
    }
    return 0;
}
