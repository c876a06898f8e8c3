/* scene_paper.c: paper mode (scene_paper.h, scene_desc.h). */
#include "host-tools/scene/scene_paper.h"

#include <stdio.h>

#include "host-tools/scene/scene_desc.h"
#include "proto/areas.h"
#include "proto/scene_format.h"
#include "proto/wire.h"

void sd_paper_apply(struct sd_scene *s)
{
    s->paper = 1;
    s->view.flags |= SCN_OPT_PAPER;
    if (!(s->written & SD_WROTE_MIN_WEIGHT))
        s->view.min_weight = 0;
    if (!(s->written & SD_WROTE_AUTO_HIERARCHY))
        s->no_auto_hierarchy = s->n_clusters > 1;
}

/* The section of kind: its offset and record count, or -1. */
static int paper_section(const uint8_t *buf, size_t len, uint32_t kind, uint32_t size,
                         uint32_t *off, uint32_t *count)
{
    uint32_t n = wire_get_u16(buf + SCN_HDR_SECTIONS);
    for (uint32_t i = 0; i < n; i++) {
        size_t e = SCN_HEADER_SIZE + (size_t)i * SCN_SECENT_SIZE;
        if (e + SCN_SECENT_SIZE > len)
            return -1;
        if (wire_get_u32(buf + e + SCN_SECENT_KIND) != kind)
            continue;
        *off = wire_get_u32(buf + e + SCN_SECENT_OFFSET);
        *count = wire_get_u32(buf + e + SCN_SECENT_COUNT);
        uint64_t bytes = (uint64_t)*count * size;
        return *off <= len && bytes <= len - *off ? 0 : -1;
    }
    return -1;
}

int scene_paper_read(const uint8_t *buf, size_t len, struct scene_paper *p, char *err,
                     size_t errlen)
{
    uint32_t voff, vn, moff, mn, coff, cn;
    if (len < SCN_HEADER_SIZE || buf[0] != SCN_MAGIC_0 || buf[1] != SCN_MAGIC_1 ||
        buf[2] != SCN_MAGIC_2 || buf[3] != SCN_MAGIC_3 ||
        paper_section(buf, len, SCN_SEC_VIEW, SCN_VIEW_SIZE, &voff, &vn) != 0 || vn != 1 ||
        paper_section(buf, len, SCN_SEC_MATERIALS, SCN_MAT_SIZE, &moff, &mn) != 0 ||
        paper_section(buf, len, SCN_SEC_CLUSTERS, SCN_CLUSTER_SIZE, &coff, &cn) != 0) {
        snprintf(err, errlen, "not a compiled scene with a view, materials and clusters");
        return -1;
    }
    const uint8_t *v = buf + voff;
    p->paper = (wire_get_u16(v + SCN_VIEW_FLAGS) & SCN_OPT_PAPER) != 0;
    p->width = wire_get_u16(v + SCN_VIEW_WIDTH);
    p->height = wire_get_u16(v + SCN_VIEW_HEIGHT);
    p->frames = wire_get_u32(v + SCN_VIEW_FRAMES);
    p->max_depth = wire_get_u16(v + SCN_VIEW_MAX_DEPTH);
    p->min_weight = wire_get_f32(v + SCN_VIEW_MIN_WEIGHT);
    p->materials = (int)mn;
    p->mirror_or_clear = p->by_angle = 0;
    for (uint32_t i = 0; i < mn; i++) {
        const uint8_t *m = buf + moff + (size_t)i * SCN_MAT_SIZE;
        if (wire_get_f32(m + SCN_MAT_SRC) > 0 || wire_get_f32(m + SCN_MAT_TRC) > 0) {
            p->mirror_or_clear++;
            p->by_angle += wire_get_f32(m + SCN_MAT_FRESNEL) > 0;
        }
    }
    p->clusters = cn;
    return 0;
}

void scene_paper_args(const struct scene_paper *p, unsigned given, struct link_render_args *a)
{
    if (!(given & SCENE_PAPER_GAVE_BALANCE))
        a->balance = LINK_BALANCE_LINES;
    if (!(given & SCENE_PAPER_GAVE_AREAS))
        a->areas = (uint32_t)p->height;
    if (!(given & SCENE_PAPER_GAVE_ASK))
        a->flags |= LINK_RENDER_ASK_WHEN_DONE;
    if (!(given & SCENE_PAPER_GAVE_CLIP))
        a->clip = LINK_CLIP_LISTS;
    if (!(given & SCENE_PAPER_GAVE_ESCALATE))
        a->flags &= (uint8_t)~LINK_RENDER_ESCALATE;
}

void scene_paper_line(const struct scene_paper *p, const struct link_render_args *a,
                      int auto_hierarchy, int own, char *out, size_t cap)
{
    static const char *const clip[] = {"auto", "lists", "tree"};
    enum areas_mode m = (enum areas_mode)a->balance;
    uint32_t k, factor;
    areas_settings(m, 1, a->areas, a->guided, &k, &factor);
    const char *unit = m != AREAS_LINES ? "not scanlines"
                       : k < (uint32_t)p->height ? "bands of whole scanlines"
                       : k == (uint32_t)p->height ? "whole scanlines"
                                                  : "parts of scanlines";
    char hier[96];
    if (auto_hierarchy < 0)
        snprintf(hier, sizeof hier, "as compiled");
    else if (auto_hierarchy)
        snprintf(hier, sizeof hier, "auto_hierarchy on: the scene has %d of its own", own);
    else
        snprintf(hier, sizeof hier, "auto_hierarchy off: the scene's own");
    snprintf(out, cap,
             "paper mode: src/trc %s (%d of %d materials that reflect or transmit), depth "
             "%s %d (min_weight %g), areas %s K %u (%s), ask %s, clip %s, clusters %u "
             "(%s), escalation %s",
             p->by_angle == p->mirror_or_clear ? "by angle" : "partly constant", p->by_angle,
             p->mirror_or_clear, p->min_weight > 0 ? "up to" : "fixed at", p->max_depth, p->min_weight, areas_mode_name(m), (unsigned)k,
             unit, a->flags & LINK_RENDER_ASK_WHEN_DONE ? "finished" : "ahead",
             a->clip < LINK_CLIP_MODES ? clip[a->clip] : "?", (unsigned)p->clusters, hier,
             a->flags & LINK_RENDER_ESCALATE ? "on" : "off");
}
