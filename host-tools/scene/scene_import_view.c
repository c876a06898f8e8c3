/* scene_import_view.c: a model's camera and lights into a scene made from
 * the model alone (scene_import.h, docs/import.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_import.h"

#define VIEW_AUTO_DIR_X -0.35 /* --camera auto looks from the front, left and above */
#define VIEW_AUTO_DIR_Y 0.45
#define VIEW_AUTO_DIR_Z -1.0
#define VIEW_AUTO_MARGIN 1.1  /* the model's bounding sphere fills 1/1.1 of the view */
#define VIEW_AUTO_LIGHT_X 0.5 /* the added light travels right, down and away */
#define VIEW_AUTO_LIGHT_Y -1.0
#define VIEW_AUTO_LIGHT_Z 0.7

/* Model (right-handed) to scene (left-handed): negate z, scale positions. */
static void view_flip(const double in[3], double scale, double out[3])
{
    out[0] = in[0] * scale, out[1] = in[1] * scale, out[2] = -in[2] * scale;
}

static int view_in_range(const double v[3])
{
    for (int i = 0; i < 3; i++)
        if (!(fabs(v[i]) <= SCN_MAX_COORD))
            return 0;
    return 1;
}

static int view_camera(struct sd_scene *s, const struct model *m, const struct import_result *r,
                       int camera_auto, FILE *warn, char *err, size_t errlen)
{
    struct sd_view *v = &s->view;
    if (m->have_camera) {
        const struct model_camera *c = &m->camera;
        view_flip(c->eye, r->scale, v->eye);
        view_flip(c->look_at, r->scale, v->look_at);
        view_flip(c->up, 1, v->up);
        if (!isfinite(c->fov) || !view_in_range(v->eye) || !view_in_range(v->look_at) ||
            !isfinite(v->up[0] + v->up[1] + v->up[2])) {
            snprintf(err, errlen, "the model's camera (eye %g %g %g) is not finite or beyond "
                                  "+-%g",
                     v->eye[0], v->eye[1], v->eye[2], (double)SCN_MAX_COORD);
            return -1;
        }
        v->fov = c->fov;
        if (!(v->fov >= SCN_MIN_FOV && v->fov <= SCN_MAX_FOV)) {
            v->fov = v->fov < SCN_MIN_FOV ? SCN_MIN_FOV : SCN_MAX_FOV;
            fprintf(warn, "the camera's field of view %g degrees is taken as %g\n", c->fov,
                    v->fov);
        }
        if (c->aspect > 0 && isfinite(c->aspect)) {
            long h = lround(v->width / c->aspect);
            v->height = (int)(h < 1 ? 1 : h > SCN_MAX_HEIGHT ? SCN_MAX_HEIGHT : h);
        }
        return 0;
    }
    if (!camera_auto) {
        snprintf(err, errlen, "the model has no camera (--camera auto frames it)");
        return -1;
    }
    double c[3], d[3] = {VIEW_AUTO_DIR_X, VIEW_AUTO_DIR_Y, VIEW_AUTO_DIR_Z}, radius = 0;
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int i = 0; i < 3; i++) {
        c[i] = (r->lo[i] + r->hi[i]) / 2;
        radius += (r->hi[i] - r->lo[i]) * (r->hi[i] - r->lo[i]) / 4;
    }
    radius = fmax(sqrt(radius), 1e-3);
    /* the smaller of the two half-angles of the view must hold the sphere */
    double tan_h = tan(v->fov * M_PI / 360);
    double tan_min = fmin(tan_h, tan_h * v->height / v->width);
    double dist = VIEW_AUTO_MARGIN * radius / sin(atan(tan_min));
    for (int i = 0; i < 3; i++) {
        v->eye[i] = c[i] + dist * d[i] / len;
        v->look_at[i] = c[i];
    }
    v->up[0] = v->up[2] = 0, v->up[1] = 1;
    if (!view_in_range(v->eye)) {
        snprintf(err, errlen, "--camera auto would put the eye at %g %g %g, beyond +-%g "
                              "(--fit makes the model smaller)",
                 v->eye[0], v->eye[1], v->eye[2], (double)SCN_MAX_COORD);
        return -1;
    }
    return 0;
}

static double view_strength(const struct model_light *l)
{
    return l->colour[0] + l->colour[1] + l->colour[2];
}

static int view_by_strength(const void *a, const void *b)
{
    double sa = view_strength(a), sb = view_strength(b);
    return sa < sb ? 1 : sa > sb ? -1 : 0;
}

static int view_light(const struct model_light *ml, double scale, struct sd_light *l,
                      FILE *warn, char *err, size_t errlen)
{
    memset(l, 0, sizeof *l);
    l->kind = ml->kind == MODEL_LIGHT_PARALLEL ? SCN_LIGHT_PARALLEL
              : ml->kind == MODEL_LIGHT_POINT  ? SCN_LIGHT_POINT
                                               : SCN_LIGHT_SPOT;
    int clamped = 0;
    for (int i = 0; i < 3; i++) {
        double c = ml->colour[i];
        l->colour[i] = c < 0 ? 0 : c > SCN_MAX_INTENSITY ? SCN_MAX_INTENSITY : c;
        clamped |= l->colour[i] != c;
    }
    if (clamped)
        fprintf(warn, "light '%s': colour %g %g %g is clamped to 0..%g\n", ml->name,
                ml->colour[0], ml->colour[1], ml->colour[2], (double)SCN_MAX_INTENSITY);
    view_flip(ml->position, scale, l->position);
    view_flip(ml->direction, 1, l->direction);
    if (!view_in_range(l->position) || !isfinite(l->colour[0] + l->colour[1] + l->colour[2])) {
        snprintf(err, errlen, "light '%s' at %g %g %g is not finite or beyond +-%g", ml->name,
                 l->position[0], l->position[1], l->position[2], (double)SCN_MAX_COORD);
        return -1;
    }
    double len = sqrt(l->direction[0] * l->direction[0] + l->direction[1] * l->direction[1] +
                      l->direction[2] * l->direction[2]);
    if (l->kind != SCN_LIGHT_POINT && !(len > 0 && isfinite(len))) {
        snprintf(err, errlen, "light '%s' has no direction", ml->name);
        return -1;
    }
    if (len > 0 && isfinite(len))
        for (int i = 0; i < 3; i++) /* unit, so the text form's range holds */
            l->direction[i] /= len;
    else
        memset(l->direction, 0, sizeof l->direction);
    if (l->kind == SCN_LIGHT_SPOT) {
        double inner = isfinite(ml->inner) ? ml->inner / 2 : 0;
        double outer = isfinite(ml->outer) ? ml->outer / 2 : inner;
        l->cone = fmin(fmax(inner, 0), SCN_MAX_SPOT_ANGLE - 0.01);
        l->falloff = fmax(outer - l->cone, 0.01);
        if (l->cone + l->falloff > SCN_MAX_SPOT_ANGLE)
            l->falloff = SCN_MAX_SPOT_ANGLE - l->cone;
    }
    return 0;
}

int scene_import_view(struct sd_scene *s, const struct model *m, const struct import_result *r,
                      int camera_auto, FILE *warn, char *err, size_t errlen)
{
    if (view_camera(s, m, r, camera_auto, warn, err, errlen) != 0)
        return -1;
    if (m->n_lights_other)
        fprintf(warn, "%d ambient or area light%s left out (the scene has point, parallel and "
                      "spot lights)\n",
                m->n_lights_other, m->n_lights_other > 1 ? "s" : "");
    if (m->n_lights == 0) {
        if (!camera_auto) {
            snprintf(err, errlen, "the model has no light (--camera auto adds one)");
            return -1;
        }
        struct sd_light *l = &s->lights[s->n_lights++];
        memset(l, 0, sizeof *l);
        l->kind = SCN_LIGHT_PARALLEL;
        l->colour[0] = l->colour[1] = l->colour[2] = 1;
        l->direction[0] = VIEW_AUTO_LIGHT_X;
        l->direction[1] = VIEW_AUTO_LIGHT_Y;
        l->direction[2] = VIEW_AUTO_LIGHT_Z;
        return 0;
    }
    struct model_light *sorted = malloc((size_t)m->n_lights * sizeof *sorted);
    if (!sorted) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    memcpy(sorted, m->lights, (size_t)m->n_lights * sizeof *sorted);
    qsort(sorted, (size_t)m->n_lights, sizeof *sorted, view_by_strength);
    int keep = m->n_lights < SCN_MAX_LIGHTS ? m->n_lights : SCN_MAX_LIGHTS;
    if (m->n_lights > keep) {
        fprintf(warn, "the model has %d lights; the scene keeps the %d strongest (", m->n_lights,
                keep);
        for (int i = 0; i < keep; i++)
            fprintf(warn, "%s'%s'", i ? ", " : "", sorted[i].name);
        fprintf(warn, ") and leaves out %d\n", m->n_lights - keep);
    }
    int rc = 0;
    for (int i = 0; i < keep && rc == 0; i++)
        rc = view_light(&sorted[i], r->scale, &s->lights[s->n_lights++], warn, err, errlen);
    free(sorted);
    return rc;
}
