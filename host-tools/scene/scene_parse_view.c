/* scene_parse_view.c: the camera and the lights, and their keys
 * (docs/scene-format.md, "Keys move the camera and the lights").
 *
 * A key gives the camera's or a light's values at a frame; a value a key
 * does not give keeps the one the key before it had (the first key: the
 * block's own, which come before the keys).  The renderer interpolates
 * between keys (render/prepare.c); sd_view_at does the same in double, and
 * every frame between two keys is checked here, so a camera that would
 * look at its own eye or a light whose direction would pass through zero
 * is refused at the key that makes it, not on the board.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_parse.h"

#define VIEW_PI 3.14159265358979323846
/* A light's interpolated direction, or the camera's from eye to look_at,
 * may not shrink below this part of the longer of its two keys' (nearly
 * opposite keys; the renderer normalises it every frame). */
#define VIEW_MIN_DIRECTION_PART (1.0 / 16)

static double view_len3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

static double view_dist3(const double a[3], const double b[3])
{
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    return view_len3(d);
}

/* NULL when the camera is usable, else what is wrong with it (the checks
 * of a still camera). */
static const char *view_camera_problem(const double eye[3], const double look_at[3],
                                       const double up[3])
{
    double d[3], c[3];
    for (int i = 0; i < 3; i++)
        d[i] = look_at[i] - eye[i];
    c[0] = d[1] * up[2] - d[2] * up[1];
    c[1] = d[2] * up[0] - d[0] * up[2];
    c[2] = d[0] * up[1] - d[1] * up[0];
    if (parse_len3_zero(d))
        return "eye and look_at are the same point";
    if (view_len3(c) <= 1e-9 * view_len3(d) * view_len3(up))
        return "up is parallel to the viewing direction (or zero)";
    return NULL;
}

/* ------------------------------------------------ interpolation (double) */

/* The keys of target (-1 the camera, else a light) and the two frame f
 * lies between, with the weight from the first to the second: the rule of
 * render/prepare.c (prep_key_span).  0 when the target has no keys. */
static int view_span(const struct sd_scene *s, int target, int f, const struct sd_view_key **a,
                     const struct sd_view_key **b, double *w)
{
    int first = -1, n = 0;
    for (int i = 0; i < s->n_view_keys; i++)
        if (s->view_keys[i].target == target) {
            if (first < 0)
                first = i;
            n++;
        }
    if (n == 0)
        return 0;
    const struct sd_view_key *k = &s->view_keys[first];
    *w = 0;
    *a = *b = &k[0];
    if (f >= k[n - 1].frame) {
        *a = *b = &k[n - 1];
    } else if (f > k[0].frame) {
        int i = 0;
        while (i + 1 < n && k[i + 1].frame <= f)
            i++;
        *a = &k[i];
        *b = &k[i + 1];
        *w = (double)(f - k[i].frame) / (k[i + 1].frame - k[i].frame);
    }
    return 1;
}

static void view_lerp3(const double a[3], const double b[3], double w, double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = a[i] + (b[i] - a[i]) * w;
}

/* tan(fov / 2) of a horizontal fov in degrees */
static double view_tan(double fov) { return tan(fov * VIEW_PI / 360.0); }

void sd_view_at(const struct sd_scene *s, int frame, struct sd_view *view,
                struct sd_light lights[SCN_MAX_LIGHTS])
{
    const struct sd_view_key *a, *b;
    double w;
    *view = s->view;
    if (view_span(s, -1, frame, &a, &b, &w)) {
        view_lerp3(a->eye, b->eye, w, view->eye);
        view_lerp3(a->look_at, b->look_at, w, view->look_at);
        view_lerp3(a->up, b->up, w, view->up);
        /* the tangent interpolates (the board has no trigonometry) */
        double t = view_tan(a->fov) + (view_tan(b->fov) - view_tan(a->fov)) * w;
        view->fov = atan(t) * 360.0 / VIEW_PI;
    }
    for (int i = 0; i < s->n_lights; i++) {
        struct sd_light *l = &lights[i];
        *l = s->lights[i];
        if (!view_span(s, i, frame, &a, &b, &w))
            continue;
        view_lerp3(a->colour, b->colour, w, l->colour);
        view_lerp3(a->position, b->position, w, l->position);
        view_lerp3(a->direction, b->direction, w, l->direction);
        /* the cosines interpolate */
        double ci = cos(a->cone * VIEW_PI / 180) +
                    (cos(b->cone * VIEW_PI / 180) - cos(a->cone * VIEW_PI / 180)) * w;
        double co = cos((a->cone + a->falloff) * VIEW_PI / 180) +
                    (cos((b->cone + b->falloff) * VIEW_PI / 180) -
                     cos((a->cone + a->falloff) * VIEW_PI / 180)) * w;
        l->cone = acos(ci) * 180 / VIEW_PI;
        l->falloff = acos(co) * 180 / VIEW_PI - l->cone;
    }
}

/* ------------------------------------------------------------- the keys */

/* Appends key k; the previous key of its target, if any, is the one
 * before it (a target's keys are read together). */
static struct sd_view_key *view_add_key(struct parser *p, const struct sd_view_key *k)
{
    struct sd_scene *s = p->s;
    s->view_keys = parse_grow(p, s->view_keys, &p->cap_view_keys, s->n_view_keys,
                              sizeof *s->view_keys, SCN_MAX_VIEW_KEYS,
                              "keys of the camera and lights (SCN_MAX_VIEW_KEYS)");
    s->view_keys[s->n_view_keys] = *k;
    return &s->view_keys[s->n_view_keys++];
}

/* "key FRAME {": the frame, which must rise after prev's (NULL: the
 * target's first key). */
static int view_key_frame(struct parser *p, const struct sd_view_key *prev, const char *whose)
{
    lex_next(&p->lx);
    if (prev && p->lx.kind == LEX_NUMBER && p->lx.num <= prev->frame)
        lex_error(&p->lx, "key frames of %s must rise (frame %s after %d)", whose, p->lx.tok,
                  prev->frame);
    int frame = lex_int(&p->lx, "key frame", 0, SCN_MAX_FRAMES - 1);
    parse_open(p, "key");
    return frame;
}

/* Every frame strictly between keys a and b of the camera: a usable
 * camera (the one rule of a still camera, on the values the renderer
 * interpolates). */
static void view_check_camera_span(struct parser *p, const struct sd_view_key *a,
                                   const struct sd_view_key *b)
{
    for (int f = a->frame + 1; f < b->frame; f++) {
        double w = (double)(f - a->frame) / (b->frame - a->frame), e[3], l[3], u[3];
        view_lerp3(a->eye, b->eye, w, e);
        view_lerp3(a->look_at, b->look_at, w, l);
        view_lerp3(a->up, b->up, w, u);
        const char *bad = view_camera_problem(e, l, u);
        double d[3];
        for (int i = 0; i < 3; i++)
            d[i] = l[i] - e[i];
        if (!bad && view_len3(d) < VIEW_MIN_DIRECTION_PART * fmax(view_dist3(a->eye, a->look_at),
                                                                  view_dist3(b->eye, b->look_at)))
            bad = "eye and look_at are (nearly) the same point";
        if (bad)
            lex_error(&p->lx, "camera keys at frames %d and %d: at frame %d between them %s "
                      "(add a key between them)", a->frame, b->frame, f, bad);
    }
}

static void parse_camera_key(struct parser *p)
{
    struct sd_scene *s = p->s;
    const struct sd_view_key *prev = s->n_view_keys > 0 && s->view_keys[s->n_view_keys - 1].target == -1
                                         ? &s->view_keys[s->n_view_keys - 1]
                                         : NULL;
    struct sd_view_key k;
    memset(&k, 0, sizeof k);
    k.target = -1;
    if (prev) {
        k = *prev;
    } else {
        memcpy(k.eye, s->view.eye, sizeof k.eye);
        memcpy(k.look_at, s->view.look_at, sizeof k.look_at);
        memcpy(k.up, s->view.up, sizeof k.up);
        k.fov = s->view.fov;
    }
    k.frame = view_key_frame(p, prev, "the camera");
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "eye")) {
            lex_next(&p->lx);
            parse_coord3(p, "eye", k.eye);
        } else if (lex_is_word(&p->lx, "look_at")) {
            lex_next(&p->lx);
            parse_coord3(p, "look_at", k.look_at);
        } else if (lex_is_word(&p->lx, "up")) {
            lex_next(&p->lx);
            parse_factor3(p, "up", k.up);
        } else if (lex_is_word(&p->lx, "fov")) {
            lex_next(&p->lx);
            k.fov = lex_number_in(&p->lx, "fov (degrees)", SCN_MIN_FOV, SCN_MAX_FOV);
        } else {
            parse_unknown(p, "camera key");
        }
    }
    const char *bad = view_camera_problem(k.eye, k.look_at, k.up);
    if (bad)
        lex_error(&p->lx, "camera key at frame %d: %s", k.frame, bad);
    if (prev)
        view_check_camera_span(p, prev, &k);
    view_add_key(p, &k);
    lex_next(&p->lx);
}

void parse_camera(struct parser *p)
{
    struct sd_view *v = &p->s->view;
    if (p->seen_camera++)
        lex_error(&p->lx, "a second camera (a scene has one)");
    lex_next(&p->lx);
    parse_open(p, "camera");
    int keys = 0;
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "key")) {
            if (!keys++) { /* the camera's own values, checked before its keys */
                const char *bad = view_camera_problem(v->eye, v->look_at, v->up);
                if (bad)
                    lex_error(&p->lx, "camera: %s", bad);
            }
            parse_camera_key(p);
            continue;
        }
        if (keys)
            lex_error(&p->lx, "the camera's own '%s' must come before its keys", p->lx.tok);
        if (lex_is_word(&p->lx, "eye")) {
            lex_next(&p->lx);
            parse_coord3(p, "eye", v->eye);
        } else if (lex_is_word(&p->lx, "look_at")) {
            lex_next(&p->lx);
            parse_coord3(p, "look_at", v->look_at);
        } else if (lex_is_word(&p->lx, "up")) {
            lex_next(&p->lx);
            parse_factor3(p, "up", v->up);
        } else if (lex_is_word(&p->lx, "fov")) {
            lex_next(&p->lx);
            v->fov = lex_number_in(&p->lx, "fov (degrees)", SCN_MIN_FOV, SCN_MAX_FOV);
        } else {
            parse_unknown(p, "camera");
        }
    }
    int close_line = p->lx.tok_line;
    const char *bad = view_camera_problem(v->eye, v->look_at, v->up);
    if (bad && strstr(bad, "same point"))
        lex_error(&p->lx, "camera ending on line %d: %s", close_line, bad);
    if (bad)
        lex_error(&p->lx, "camera: %s", bad);
    lex_next(&p->lx);
}

/* A light's values as read so far: l, and for a spot aimed with 'at' the
 * point it is aimed at (aim_at), kept when a later key moves it. */
struct view_light_state {
    struct sd_light l;
    int aim_at;
    double at[3];
};

static const char *view_kind_name(int kind)
{
    return kind == SCN_LIGHT_PARALLEL ? "parallel" : kind == SCN_LIGHT_POINT ? "point" : "spot";
}

/* One property of a light or of its key into st; 0 when the token is not
 * one.  have: bits of what was given (VIEW_HAVE_*). */
#define VIEW_HAVE_POS 1
#define VIEW_HAVE_DIR 2
#define VIEW_HAVE_CONE 4
static int view_light_property(struct parser *p, struct view_light_state *st, int *have)
{
    struct sd_light *l = &st->l;
    int k = l->kind;
    if (lex_is_word(&p->lx, "colour") || lex_is_word(&p->lx, "color")) {
        lex_next(&p->lx);
        for (int i = 0; i < 3; i++)
            l->colour[i] = lex_number_in(&p->lx, "light colour", 0, SCN_MAX_INTENSITY);
    } else if (lex_is_word(&p->lx, "position") && k != SCN_LIGHT_PARALLEL) {
        lex_next(&p->lx);
        parse_coord3(p, "position", l->position);
        *have |= VIEW_HAVE_POS;
    } else if (lex_is_word(&p->lx, "direction") && k != SCN_LIGHT_POINT) {
        lex_next(&p->lx);
        parse_factor3(p, "direction", l->direction);
        if (parse_len3_zero(l->direction))
            lex_error(&p->lx, "light direction is zero");
        st->aim_at = 0;
        *have |= VIEW_HAVE_DIR;
    } else if (lex_is_word(&p->lx, "at") && k == SCN_LIGHT_SPOT) {
        lex_next(&p->lx);
        parse_coord3(p, "at", st->at);
        st->aim_at = 1;
        *have |= VIEW_HAVE_DIR;
    } else if (lex_is_word(&p->lx, "cone") && k == SCN_LIGHT_SPOT) {
        lex_next(&p->lx);
        l->cone = lex_number_in(&p->lx, "cone (degrees)", 0, SCN_MAX_SPOT_ANGLE);
        *have |= VIEW_HAVE_CONE;
    } else if (lex_is_word(&p->lx, "falloff") && k == SCN_LIGHT_SPOT) {
        lex_next(&p->lx);
        l->falloff = lex_number_in(&p->lx, "falloff (degrees)", 0.01, SCN_MAX_SPOT_ANGLE);
    } else {
        return 0;
    }
    return 1;
}

/* The checks of a light's values, once its block or key is read (at its
 * closing brace); what names it in a message. */
static void view_light_finish(struct parser *p, struct view_light_state *st, const char *what)
{
    struct sd_light *l = &st->l;
    if (l->kind == SCN_LIGHT_SPOT && st->aim_at) {
        for (int i = 0; i < 3; i++)
            l->direction[i] = st->at[i] - l->position[i];
        if (parse_len3_zero(l->direction))
            lex_error(&p->lx, "%sspotlight 'at' is its own position", what);
    }
    if (l->cone + l->falloff > SCN_MAX_SPOT_ANGLE)
        lex_error(&p->lx, "%scone + falloff is %g degrees, more than %g", what,
                  l->cone + l->falloff, SCN_MAX_SPOT_ANGLE);
}

/* Every frame strictly between keys a and b of a light with a direction:
 * the interpolated direction keeps VIEW_MIN_DIRECTION_PART of its length. */
static void view_check_light_span(struct parser *p, int kind, const struct sd_view_key *a,
                                  const struct sd_view_key *b)
{
    if (kind == SCN_LIGHT_POINT)
        return;
    double least = VIEW_MIN_DIRECTION_PART * fmax(view_len3(a->direction), view_len3(b->direction));
    for (int f = a->frame + 1; f < b->frame; f++) {
        double d[3];
        view_lerp3(a->direction, b->direction, (double)(f - a->frame) / (b->frame - a->frame), d);
        if (view_len3(d) < least)
            lex_error(&p->lx, "light keys at frames %d and %d: their directions are nearly "
                      "opposite, and at frame %d between them the direction shrinks to %g of "
                      "its length (add a key between them)", a->frame, b->frame, f,
                      view_len3(d) / fmax(view_len3(a->direction), view_len3(b->direction)));
    }
}

static void parse_light_key(struct parser *p, struct view_light_state *st, int light)
{
    struct sd_scene *s = p->s;
    const struct sd_view_key *prev = s->n_view_keys > 0 && s->view_keys[s->n_view_keys - 1].target == light
                                         ? &s->view_keys[s->n_view_keys - 1]
                                         : NULL;
    struct sd_view_key k;
    memset(&k, 0, sizeof k);
    k.target = light;
    k.frame = view_key_frame(p, prev, "a light");
    int have = 0;
    while (p->lx.kind != LEX_CLOSE)
        if (!view_light_property(p, st, &have))
            lex_error(&p->lx, "'%s' is not a property of a %s light's key", p->lx.tok,
                      view_kind_name(st->l.kind));
    char what[64];
    snprintf(what, sizeof what, "light key at frame %d: ", k.frame);
    view_light_finish(p, st, what);
    memcpy(k.colour, st->l.colour, sizeof k.colour);
    memcpy(k.position, st->l.position, sizeof k.position);
    memcpy(k.direction, st->l.direction, sizeof k.direction);
    k.cone = st->l.cone;
    k.falloff = st->l.falloff;
    if (prev)
        view_check_light_span(p, st->l.kind, prev, &k);
    view_add_key(p, &k);
    lex_next(&p->lx);
}

void parse_light(struct parser *p)
{
    struct sd_scene *s = p->s;
    if (s->n_lights >= SCN_MAX_LIGHTS)
        lex_error(&p->lx, "more than SCN_MAX_LIGHTS (%d) lights", SCN_MAX_LIGHTS);
    lex_next(&p->lx);
    struct view_light_state st;
    memset(&st, 0, sizeof st);
    struct sd_light *l = &st.l;
    l->colour[0] = l->colour[1] = l->colour[2] = 1;
    l->falloff = PARSE_DEFAULT_FALLOFF;
    if (lex_is_word(&p->lx, "parallel"))
        l->kind = SCN_LIGHT_PARALLEL;
    else if (lex_is_word(&p->lx, "point"))
        l->kind = SCN_LIGHT_POINT;
    else if (lex_is_word(&p->lx, "spot"))
        l->kind = SCN_LIGHT_SPOT;
    else
        lex_error(&p->lx, "light kind must be parallel, point or spot, not '%s'", p->lx.tok);
    lex_next(&p->lx);
    parse_open(p, "light");
    int have = 0, keys = 0, index = s->n_lights;
    while (p->lx.kind != LEX_CLOSE && !lex_is_word(&p->lx, "key"))
        if (!view_light_property(p, &st, &have))
            lex_error(&p->lx, "'%s' is not a property of a %s light", p->lx.tok,
                      view_kind_name(l->kind));
    if (l->kind != SCN_LIGHT_PARALLEL && !(have & VIEW_HAVE_POS))
        lex_error(&p->lx, "this light needs a position");
    if (l->kind != SCN_LIGHT_POINT && !(have & VIEW_HAVE_DIR))
        lex_error(&p->lx, "this light needs a direction%s",
                  l->kind == SCN_LIGHT_SPOT ? " (or 'at')" : "");
    if (l->kind == SCN_LIGHT_SPOT && !(have & VIEW_HAVE_CONE))
        lex_error(&p->lx, "a spotlight needs a cone angle");
    view_light_finish(p, &st, "");
    s->lights[index] = *l; /* its own values: the record, and its first key's defaults */
    while (p->lx.kind != LEX_CLOSE) {
        if (!lex_is_word(&p->lx, "key"))
            lex_error(&p->lx, "the light's own '%s' must come before its keys", p->lx.tok);
        parse_light_key(p, &st, index);
        keys++;
    }
    s->n_lights = index + 1;
    lex_next(&p->lx);
}
