/* render_faults.c: the fault plan of `links1 render --inject-faults` and
 * the failure summary (see render_faults.h). */
#include "host-tools/gigs/render_faults.h"

#include <stdlib.h>
#include <string.h>

#include "proto/units.h"

/* Areas into its share an NC may fail at (0 = its first). */
#define RENDER_FAULTS_AREA_SPAN 4u

static const char *const render_faults_names[LINK_INJECT_KINDS + 1] = {
    "mixed", "undef", "abort", "hang", "silent",
};

int render_faults_parse(const char *arg, unsigned *k, unsigned *seed)
{
    char *end;
    unsigned long v = strtoul(arg, &end, 10);
    if (end == arg || v > LINK_INJECT_MAX)
        return -1;
    *k = (unsigned)v;
    *seed = 1;
    if (*end == 0)
        return 0;
    if (*end != ':' || end[1] == 0)
        return -1;
    const char *s = end + 1;
    unsigned long sv = strtoul(s, &end, 10);
    if (*end != 0 || sv > 0xFFFFFFFFul)
        return -1;
    *seed = (unsigned)sv;
    return 0;
}

int render_faults_kind_parse(const char *name, uint8_t *kind)
{
    for (uint8_t i = 0; i <= LINK_INJECT_KINDS; i++) {
        if (strcmp(name, render_faults_names[i]) == 0) {
            *kind = i;
            return 0;
        }
    }
    return -1;
}

const char *render_faults_kind_name(uint8_t kind)
{
    return kind <= LINK_INJECT_KINDS ? render_faults_names[kind] : "unknown";
}

/* xorshift32: the plan is the same for the same seed everywhere. */
static uint32_t render_faults_next(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *s = x;
}

uint32_t render_faults_plan(unsigned k, unsigned seed, uint8_t kind, unsigned ncs,
                            uint8_t taken[LINK_CORE_MAP_SIZE],
                            uint8_t out[LINK_INJECT_SIZE(LINK_INJECT_MAX)])
{
    uint16_t cores[UNITS_MAX_CORES];
    uint32_t s = seed * 2654435761u + 0x9E3779B9u;
    if (s == 0)
        s = 1;
    unsigned left = 0;
    for (unsigned i = 0; i < ncs && i < UNITS_MAX_CORES - UNITS_FIRST_NC; i++)
        if (!link_core_map_has(taken, UNITS_FIRST_NC + i))
            cores[left++] = (uint16_t)(UNITS_FIRST_NC + i);
    if (k > LINK_INJECT_MAX)
        k = LINK_INJECT_MAX;
    if (k + 1 > left)
        k = left ? left - 1 : 0;
    ncs = left;
    out[0] = (uint8_t)k;
    out[1] = 0;
    for (unsigned i = 0; i < k; i++) {
        unsigned j = i + render_faults_next(&s) % (ncs - i); /* Fisher-Yates */
        uint16_t c = cores[j];
        cores[j] = cores[i];
        cores[i] = c;
        link_core_map_set(taken, c);
        struct link_inject e;
        e.core = c;
        e.kind = kind != RENDER_FAULTS_MIXED ? kind
                                             : (uint8_t)(1 + render_faults_next(&s) % LINK_INJECT_KINDS);
        e.row = (uint8_t)(render_faults_next(&s) & 0xFF);
        e.area = (uint16_t)(render_faults_next(&s) % RENDER_FAULTS_AREA_SPAN);
        link_inject_put(out + LINK_INJECT_FIXED_SIZE + i * LINK_INJECT_ENTRY_SIZE, &e);
    }
    return LINK_INJECT_SIZE(k);
}

void render_faults_print_plan(FILE *out, const uint8_t *plan)
{
    fprintf(out, "links1 render: fault plan:");
    for (unsigned i = 0; i < plan[0]; i++) {
        struct link_inject e;
        link_inject_get(plan + LINK_INJECT_FIXED_SIZE + i * LINK_INJECT_ENTRY_SIZE, &e);
        fprintf(out, "%s NC %u %s in its area %u at %u/256", i ? ";" : "", e.core,
                render_faults_kind_name(e.kind), e.area, e.row);
    }
    fprintf(out, "\n");
}

void render_faults_print(FILE *out, uint32_t frame, const struct link_render_fails *f)
{
    if (f->failed == 0 && f->failed_before == 0)
        return;
    fprintf(out, "links1 render: frame %u: %u NC(s) failed during the frame", frame, f->failed);
    const char *sep = ": ";
    for (uint32_t c = 0; c < UNITS_MAX_CORES; c++) {
        if (!link_core_map_has(f->failed_map, c))
            continue;
        fprintf(out, "%sNC %u (%s)", sep, c,
                link_core_map_has(f->watchdog_map, c) ? "watchdog" : "fault");
        sep = ", ";
    }
    fprintf(out, "; %u area(s) re-issued", f->reissued);
    uint32_t n = f->reissued < LINK_REISSUE_LIST_MAX ? f->reissued : LINK_REISSUE_LIST_MAX;
    sep = ": ";
    for (uint32_t i = 0; i < n; i++) {
        const struct link_reissue *a = &f->area[i];
        fprintf(out, "%s%ux%u at (%u,%u) from NC %u", sep, a->w, a->h, a->x, a->y, a->core);
        sep = ", ";
    }
    if (n < f->reissued)
        fprintf(out, ", ...");
    if (f->failed_before)
        fprintf(out, "; %u NC(s) out since earlier frames", f->failed_before);
    fprintf(out, "\n");
}

int render_faults_unit_down(const struct link_fault *faults, int n)
{
    for (int i = 0; i < n; i++)
        if (faults[i].role == ROLE_DM || faults[i].role == ROLE_RC)
            return i;
    return -1;
}
