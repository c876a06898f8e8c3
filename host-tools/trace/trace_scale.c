/* trace_scale.c: a trace priced at a larger size (trace_file.h). */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/trace/trace_file.h"
#include "proto/areas.h"

int trace_scale(struct trace *t, uint32_t f, char *err, size_t cap)
{
    if (f == 1)
        return 0;
    if (f == 0 || t->width > AREAS_MAX_DIM / f || t->height > AREAS_MAX_DIM / f) {
        snprintf(err, cap, "scale %" PRIu32 ": the %" PRIu32 "x%" PRIu32 " trace would exceed %u pixels a side",
                 f, t->width, t->height, (unsigned)AREAS_MAX_DIM);
        return -1;
    }
    uint32_t w = t->width * f, h = t->height * f;
    uint32_t *pixel = malloc(sizeof *pixel * (size_t)w * h);
    if (!pixel) {
        snprintf(err, cap, "scale %" PRIu32 ": out of memory for %" PRIu32 "x%" PRIu32 " pixels", f, w, h);
        return -1;
    }
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++)
            pixel[(size_t)y * w + x] = t->pixel[(size_t)(y / f) * t->width + x / f];
    free(t->pixel);
    t->pixel = pixel;
    t->width = w;
    t->height = h;
    for (uint32_t i = 0; i < t->nareas; i++) {
        struct trace_area *a = &t->areas[i];
        a->x *= f;
        a->y *= f;
        a->w *= f;
        a->h *= f;
        a->push *= (uint64_t)f * f;
        a->total = a->setup + trace_pixels_sum(t, a->x, a->y, a->w, a->h) + a->push;
    }
    return trace_check(t, err, cap);
}
