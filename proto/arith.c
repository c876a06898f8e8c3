/* arith.c: names of the arithmetic codes (see arith.h). */
#include "proto/arith.h"

#include <stddef.h>

static const char *const arith_names[ARITH_COUNT] = {
    [ARITH_FLOAT] = "float",
    [ARITH_SOFT] = "soft",
    [ARITH_FIXED] = "fixed",
    [ARITH_DOUBLE] = "double",
};

const char *arith_name(int arith)
{
    return arith >= 0 && arith < ARITH_COUNT ? arith_names[arith] : NULL;
}

int arith_from_name(const char *name)
{
    for (int a = 0; a < ARITH_COUNT; a++) {
        const char *s = arith_names[a], *t = name;
        while (*s && *s == *t)
            s++, t++;
        if (!*s && !*t)
            return a;
    }
    return -1;
}
