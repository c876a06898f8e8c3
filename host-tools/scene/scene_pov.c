/* scene_pov.c: a scene in POV-Ray 3.7's language, for an outside check of
 * the renderer (docs/pov-mapping.md has the mapping and its limits).
 *
 * Exact where both renderers mean the same thing: the camera, point and
 * parallel lights without fading, per-light ambient when it is not
 * shadowed (global ambient_light = sum of the light colours, finish
 * ambient = dic), Lambert diffuse (diffuse drc, brilliance 1), hard
 * shadows, mirror reflection constant or on the angle (POV-Ray's variable
 * reflection, min + (max - min)(1 - cos)^falloff, is Schlick's curve of
 * render/shade.h with min src, max src + (1 - src) fresnel, falloff 5),
 * triangles, ellipsoids, boxes, cones and cylinders.  Anything else is approximated and named
 * in a comment at the top of the file, or refused when strict is set.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "host-tools/scene/scene_desc.h"

#define POV_PARALLEL_DISTANCE 1000.0 /* where a parallel light's location goes
                                        (at least; 4 times pov_extent beyond it) */
#define POV_MAX_NOTES 16

/* A bound on the scene's |coordinates| in world space, unless its clusters
 * enlarge it: the camera, the lights, every cluster's and key's translation
 * added up, plus the largest length of a primitive. */
static double pov_extent(const struct sd_scene *s)
{
    double most = 0, moved = 0, prim = 0;
    for (int c = 0; c < 3; c++) {
        most = fmax(most, fmax(fabs(s->view.eye[c]), fabs(s->view.look_at[c])));
        for (int i = 0; i < s->n_lights; i++)
            most = fmax(most, fabs(s->lights[i].position[c]));
        for (int i = 0; i < s->n_clusters; i++)
            moved += fabs(s->clusters[i].m[4 * c + 3]);
        for (int i = 0; i < s->n_keys; i++)
            moved += fabs(s->keys[i].translate[c]);
    }
    for (int i = 0; i < s->n_prims; i++) {
        int kind = s->prims[i].kind;
        int n = kind == SCN_PRIM_TRIANGLE ? 9 : kind == SCN_PRIM_DENSITY ? 0
                : kind == SCN_PRIM_CONE ? SCN_CONE_VALUES : 6;
        for (int k = 0; k < n; k++)
            prim = fmax(prim, fabs(s->prims[i].v[k]));
    }
    for (int i = 0; i < s->n_components; i++)
        for (int c = 0; c < 3; c++)
            prim = fmax(prim, fabs(s->components[i].centre[c]) + s->components[i].radius);
    return fmax(most, moved + 2 * prim);
}

struct pov_notes {
    const char *text[POV_MAX_NOTES];
    int n;
};

static void pov_note(struct pov_notes *n, const char *text)
{
    for (int i = 0; i < n->n; i++)
        if (strcmp(n->text[i], text) == 0)
            return;
    if (n->n < POV_MAX_NOTES)
        n->text[n->n++] = text;
}

/* What this scene has that POV-Ray cannot render the same way. */
static void pov_check(const struct sd_scene *s, struct pov_notes *n)
{
    for (int i = 0; i < s->n_lights; i++)
        if (s->lights[i].kind == SCN_LIGHT_SPOT)
            pov_note(n, "spotlight: POV-Ray's falloff curve between cone and edge differs");
    int ambient_shadowed = (s->view.flags & SCN_OPT_AMBIENT_SHADOWED) &&
                           !(s->view.flags & SCN_OPT_NO_SHADOWS);
    for (int i = 0; i < s->n_materials; i++) {
        const struct sd_material *m = &s->materials[i];
        if (m->dic > 0 && ambient_shadowed)
            pov_note(n, "ambient shadowed per light (ambient_shadowed on): POV-Ray's "
                        "ambient is never shadowed; exported unshadowed");
        if (m->trc > 0)
            pov_note(n, "transmission: POV-Ray's filter also dims the other terms; "
                        "trc is exported as filter");
        if (m->trc > 0 && m->fresnel > 0)
            pov_note(n, "angle-dependent trc (fresnel): POV-Ray's filter is a constant");
        if (m->phong > 0 && (m->src > 0 || m->fresnel > 0))
            pov_note(n, "highlight cos^n * src(th): exported as POV-Ray phong src, not the "
                        "same curve");
        if (m->colour_map >= 0)
            pov_note(n, "colour map: not exported, the pigment is F alone");
        if (m->bump_map >= 0)
            pov_note(n, "bump map: not exported");
        if (m->normal_map >= 0)
            pov_note(n, "normal map: not exported");
        if (m->dic_map >= 0 || m->drc_map >= 0 || m->src_map >= 0 || m->trc_map >= 0)
            pov_note(n, "attribute maps: not exported, the coefficients are the material's");
    }
    for (int i = 0; i < s->n_prims; i++)
        if (s->prims[i].kind == SCN_PRIM_DENSITY)
            pov_note(n, "density sphere: exported as a blob, whose field function differs");
    if (s->view.max_depth == 0)
        pov_note(n, "max_depth 0: POV-Ray always traces at least one level");
    if (s->view.flags & SCN_OPT_ANTIALIAS)
        pov_note(n, "anti-aliasing (aa): not in a POV-Ray scene file; its nearest is the "
                    "command line's adaptive +AM2 +A<threshold> +R<depth>, not the same test");
}

static void pov_vec(FILE *f, const double v[3])
{
    fprintf(f, "<%.9g, %.9g, %.9g>", v[0], v[1], v[2]);
}

/* POV-Ray multiplies row vectors: its matrix is the transpose of ours. */
static void pov_matrix(FILE *f, const double m[12])
{
    fprintf(f, "  matrix <%.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g>\n",
            m[0], m[4], m[8], m[1], m[5], m[9], m[2], m[6], m[10], m[3], m[7], m[11]);
}

static void pov_material(FILE *f, const struct sd_material *m)
{
    fprintf(f, "  pigment { rgb");
    if (m->trc > 0)
        fprintf(f, "f <%.9g, %.9g, %.9g, %.9g>", m->colour[0], m->colour[1], m->colour[2],
                m->trc);
    else
        fprintf(f, " <%.9g, %.9g, %.9g>", m->colour[0], m->colour[1], m->colour[2]);
    fprintf(f, " }\n  finish { ambient %.9g diffuse %.9g brilliance 1 specular 0 ", m->dic,
            m->drc);
    if (m->phong > 0 && m->src > 0)
        fprintf(f, "phong %.9g phong_size %d ", m->src, m->phong);
    else
        fprintf(f, "phong 0 ");
    /* src(th) = src + (1 - src) fresnel (1 - cos)^5: POV-Ray's variable
     * reflection between src (head-on) and its value at grazing */
    if (m->fresnel > 0)
        fprintf(f, "reflection { %.9g, %.9g falloff 5 } }\n", m->src,
                m->src + (1 - m->src) * m->fresnel);
    else
        fprintf(f, "reflection { %.9g } }\n", m->src);
    if (m->trc > 0 && m->ior != 1)
        fprintf(f, "  interior { ior %.9g }\n", m->ior);
}

static void pov_world_matrix(const struct sd_scene *s, int c, int frame, double out[12])
{
    double m[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    for (; c >= 0; c = s->clusters[c].parent) {
        double k[12], km[12], r[12];
        sd_key_matrix(s, c, frame, k);
        sd_mat_mul(k, s->clusters[c].m, km);
        sd_mat_mul(km, m, r);
        memcpy(m, r, sizeof r);
    }
    memcpy(out, m, sizeof m);
}

static void pov_prim(FILE *f, const struct sd_scene *s, const struct sd_prim *p, int frame)
{
    const double *v = p->v;
    switch (p->kind) {
    case SCN_PRIM_TRIANGLE:
        /* a smooth triangle: POV-Ray's smooth_triangle, each vertex with
         * its normal */
        fprintf(f, p->smooth ? "smooth_triangle { " : "triangle { ");
        for (int j = 0; j < 3; j++) {
            pov_vec(f, v + 3 * j);
            if (p->smooth) {
                fprintf(f, ", ");
                pov_vec(f, p->n + 3 * j);
            }
            fprintf(f, j < 2 ? ", " : "\n");
        }
        break;
    case SCN_PRIM_ELLIPSOID:
        fprintf(f, "sphere { <0, 0, 0>, 1 scale ");
        pov_vec(f, v + 3);
        fprintf(f, " translate ");
        pov_vec(f, v);
        fprintf(f, "\n");
        break;
    case SCN_PRIM_BOX: {
        double lo[3], hi[3];
        for (int i = 0; i < 3; i++)
            lo[i] = v[i] - v[3 + i], hi[i] = v[i] + v[3 + i];
        fprintf(f, "box { ");
        pov_vec(f, lo);
        fprintf(f, ", ");
        pov_vec(f, hi);
        fprintf(f, "\n");
        break;
    }
    case SCN_PRIM_CONE:
        /* POV-Ray's cone and cylinder: capped unless open, as ours */
        if (v[3] == v[7]) {
            fprintf(f, "cylinder { ");
            pov_vec(f, v);
            fprintf(f, ", ");
            pov_vec(f, v + 4);
            fprintf(f, ", %.9g%s\n", v[3], p->capped ? "" : " open");
        } else {
            fprintf(f, "cone { ");
            pov_vec(f, v);
            fprintf(f, ", %.9g, ", v[3]);
            pov_vec(f, v + 4);
            fprintf(f, ", %.9g%s\n", v[7], p->capped ? "" : " open");
        }
        break;
    default:
        fprintf(f, "blob { threshold %.9g\n", v[0]);
        for (int i = 0; i < p->count; i++) {
            const struct sd_component *c = &s->components[p->first + i];
            fprintf(f, "  sphere { ");
            pov_vec(f, c->centre);
            fprintf(f, ", %.9g, %.9g }\n", c->radius, c->weight);
        }
        break;
    }
    pov_material(f, &s->materials[p->material]);
    double m[12];
    pov_world_matrix(s, p->cluster, frame, m);
    pov_matrix(f, m);
    fprintf(f, "}\n");
}

int sd_export_pov(const struct sd_scene *s, int frame, int strict, FILE *f, const char *name,
                  char *err, size_t errlen)
{
    struct pov_notes notes = {{0}, 0};
    pov_check(s, &notes);
    if (strict && notes.n > 0) {
        snprintf(err, errlen, "POV-Ray cannot render this scene the same way: %s",
                 notes.text[0]);
        return -1;
    }
    /* the camera and lights of this frame (their keys) */
    struct sd_view view;
    struct sd_light lights[SCN_MAX_LIGHTS];
    sd_view_at(s, frame, &view, lights);
    const struct sd_view *v = &view;
    fprintf(f, "// Written by links1 export-pov (frame %d). Render with\n"
               "//   povray +I<this> +O<out.png> +W%d +H%d -A +WT1 File_Gamma=1.0\n",
            frame, v->width, v->height);
    for (int i = 0; i < notes.n; i++)
        fprintf(f, "// approximated: %s\n", notes.text[i]);
    double amb[3] = {0, 0, 0};
    for (int i = 0; i < s->n_lights; i++)
        for (int c = 0; c < 3; c++)
            amb[c] += lights[i].colour[c];
    fprintf(f, "#version 3.7;\n"
               "global_settings {\n  assumed_gamma 1.0\n  ambient_light rgb ");
    pov_vec(f, amb);
    /* adc_bailout 0: trace every level like the renderer; POV counts the
     * primary ray as level 1. */
    fprintf(f, "\n  max_trace_level %d\n  adc_bailout 0\n}\n", v->max_depth + 1);
    fprintf(f, "background { rgb ");
    pov_vec(f, v->background);
    fprintf(f, " }\n");
    if (v->haze) { /* the same blend: c exp(-d/D) + h (1 - exp(-d/D)), every ray */
        fprintf(f, "fog {\n  fog_type 1\n  distance %.9g\n  color rgb ", v->haze_distance);
        pov_vec(f, v->haze_colour);
        fprintf(f, "\n}\n");
    }
    fprintf(f, "camera {\n  perspective\n  location ");
    pov_vec(f, v->eye);
    fprintf(f, "\n  sky ");
    pov_vec(f, v->up);
    fprintf(f, "\n  up y\n  right x * %d / %d\n  angle %.9g\n  look_at ", v->width, v->height,
            v->fov);
    pov_vec(f, v->look_at);
    fprintf(f, "\n}\n");
    for (int i = 0; i < s->n_lights; i++) {
        const struct sd_light *l = &lights[i];
        double pos[3], at[3];
        double far = fmax(POV_PARALLEL_DISTANCE, 4 * pov_extent(s));
        if (l->kind == SCN_LIGHT_PARALLEL) {
            double len = sqrt(l->direction[0] * l->direction[0] +
                              l->direction[1] * l->direction[1] +
                              l->direction[2] * l->direction[2]);
            for (int c = 0; c < 3; c++) {
                pos[c] = -l->direction[c] / len * far;
                at[c] = 0;
            }
        } else {
            memcpy(pos, l->position, sizeof pos);
            for (int c = 0; c < 3; c++)
                at[c] = l->position[c] + l->direction[c];
        }
        fprintf(f, "light_source {\n  ");
        pov_vec(f, pos);
        fprintf(f, "\n  color rgb ");
        pov_vec(f, l->colour);
        if (l->kind == SCN_LIGHT_PARALLEL) {
            fprintf(f, "\n  parallel\n  point_at ");
            pov_vec(f, at);
        } else if (l->kind == SCN_LIGHT_SPOT) {
            fprintf(f, "\n  spotlight\n  radius %.9g\n  falloff %.9g\n  tightness 0\n  point_at ",
                    l->cone, l->cone + l->falloff);
            pov_vec(f, at);
        }
        fprintf(f, "\n}\n");
    }
    for (int i = 0; i < s->n_prims; i++)
        pov_prim(f, s, &s->prims[i], frame);
    if (ferror(f) || fflush(f) != 0) {
        snprintf(err, errlen, "%s: write failed: %s", name, strerror(errno));
        return -1;
    }
    return 0;
}
