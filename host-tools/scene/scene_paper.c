/* scene_paper.c: paper mode (scene_paper.h, scene_desc.h). */
#include "host-tools/scene/scene_paper.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_desc.h"
#include "proto/areas.h"
#include "proto/scene_format.h"
#include "proto/wire.h"

#define PAPER_PI 3.14159265358979323846
/* the most triangles a cone becomes: its side and two fans */
#define PAPER_CONE_MAX (4 * SD_CONE_SIDES)

/* Unit u, w across the unit axis a. */
static void paper_across(const double a[3], double u[3], double w[3])
{
    int least = fabs(a[0]) <= fabs(a[1]) ? (fabs(a[0]) <= fabs(a[2]) ? 0 : 2)
                                         : (fabs(a[1]) <= fabs(a[2]) ? 1 : 2);
    double any[3] = {0, 0, 0};
    any[least] = 1;
    u[0] = a[1] * any[2] - a[2] * any[1];
    u[1] = a[2] * any[0] - a[0] * any[2];
    u[2] = a[0] * any[1] - a[1] * any[0];
    double ul = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int k = 0; k < 3; k++)
        u[k] /= ul;
    w[0] = a[1] * u[2] - a[2] * u[1];
    w[1] = a[2] * u[0] - a[0] * u[2];
    w[2] = a[0] * u[1] - a[1] * u[0];
}

/* Triangle a b c of cone's material and cluster at out[n], unless
 * degenerate; the new count. */
static int paper_tri(const struct sd_prim *cone, const double *a, const double *b,
                     const double *c, struct sd_prim *out, int n)
{
    struct sd_prim t;
    memset(&t, 0, sizeof t);
    t.kind = SCN_PRIM_TRIANGLE;
    t.material = cone->material;
    t.cluster = cone->cluster;
    memcpy(t.v, a, 3 * sizeof *a);
    memcpy(t.v + 3, b, 3 * sizeof *b);
    memcpy(t.v + 6, c, 3 * sizeof *c);
    t.v[10] = 1; /* map coordinates (0,0), (1,0), (0,1), as the text form's */
    t.v[14] = 1;
    if (sd_triangle_degenerate(t.v))
        return n;
    out[n] = t;
    return n + 1;
}

/* A cone's facets: SD_CONE_SIDES quads round (two triangles each, one
 * where an end is a point) and, capped, a fan over each end disc. */
static int paper_cone_facets(const struct sd_prim *cone, struct sd_prim *out)
{
    const double *v = cone->v;
    double a[3] = {v[4] - v[0], v[5] - v[1], v[6] - v[2]}, u[3], w[3];
    double len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (int k = 0; k < 3; k++)
        a[k] /= len;
    paper_across(a, u, w);
    double ring[2][SD_CONE_SIDES + 1][3];
    for (int i = 0; i <= SD_CONE_SIDES; i++) {
        double t = 2.0 * PAPER_PI * (i % SD_CONE_SIDES) / SD_CONE_SIDES, ca = cos(t), sa = sin(t);
        for (int e = 0; e < 2; e++)
            for (int k = 0; k < 3; k++)
                ring[e][i][k] = v[4 * e + k] + v[4 * e + 3] * (ca * u[k] + sa * w[k]);
    }
    int n = 0;
    for (int i = 0; i < SD_CONE_SIDES; i++) {
        if (v[3] > 0)
            n = paper_tri(cone, ring[0][i], ring[0][i + 1], ring[1][i + 1], out, n);
        if (v[7] > 0)
            n = paper_tri(cone, ring[0][i], ring[1][i + 1], ring[1][i], out, n);
    }
    for (int e = 0; cone->capped && e < 2; e++)
        for (int i = 1; v[4 * e + 3] > 0 && i + 1 < SD_CONE_SIDES; i++)
            n = paper_tri(cone, ring[e][0], ring[e][i], ring[e][i + 1], out, n);
    return n;
}

int sd_paper_facet_cones(struct sd_scene *s, char *err, size_t errlen)
{
    long cones = 0;
    for (int i = 0; i < s->n_prims; i++)
        cones += s->prims[i].kind == SCN_PRIM_CONE;
    if (cones == 0)
        return 0;
    long most = s->n_prims + cones * (PAPER_CONE_MAX - 1);
    struct sd_prim *out = most <= SCN_MAX_PRIMS ? malloc((size_t)most * sizeof *out) : NULL;
    if (!out) {
        snprintf(err, errlen, "paper mode: %ld cones and cylinders faceted would make %s", cones,
                 most <= SCN_MAX_PRIMS ? "more than memory holds"
                                       : "more primitives than SCN_MAX_PRIMS");
        return -1;
    }
    int n = 0;
    for (int i = 0; i < s->n_prims; i++) {
        if (s->prims[i].kind == SCN_PRIM_CONE)
            n += paper_cone_facets(&s->prims[i], out + n);
        else
            out[n++] = s->prims[i];
    }
    free(s->prims);
    s->prims = out;
    s->n_prims = n;
    s->paper_faceted += (int)cones;
    return 0;
}

void sd_paper_apply(struct sd_scene *s)
{
    char err[SD_ERR_MAX];
    (void)sd_paper_facet_cones(s, err, sizeof err); /* failing, sd_compile refuses its cones */
    s->paper = 1;
    s->view.flags |= SCN_OPT_PAPER;
    s->view.flags &= ~SCN_OPT_ANTIALIAS; /* the paper's pixel is one ray */
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
