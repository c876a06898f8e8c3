/* spd_scn.c: a scene read from an SPD database's NFF written back as a text
 * scene (docs/scene-format.md), every number so that it reads back to the
 * same double: the text scene compiles to the same bytes as the NFF. */
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_desc.h"
#include "scenes/spd/spd.h"

/* the shortest of %.15g, %.16g, %.17g that reads back as x */
static void scn_num(FILE *f, double x)
{
    char b[40];
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(b, sizeof b, "%.*g", prec, x);
        if (strtod(b, NULL) == x)
            break;
    }
    fprintf(f, " %s", b);
}

static void scn_vec(FILE *f, const char *word, const double *v, int n)
{
    fprintf(f, " %s", word);
    for (int i = 0; i < n; i++)
        scn_num(f, v[i]);
}

int spd_write_scn(FILE *f, const struct sd_scene *s, const char *title)
{
    const struct sd_view *v = &s->view;
    fprintf(f, "# %s\n", title);
    fprintf(f, "camera {");
    scn_vec(f, "eye", v->eye, 3);
    scn_vec(f, " look_at", v->look_at, 3);
    scn_vec(f, " up", v->up, 3);
    scn_vec(f, " fov", &v->fov, 1);
    fprintf(f, " }\nresolution %d %d\n", v->width, v->height);
    fprintf(f, "background");
    for (int i = 0; i < 3; i++)
        scn_num(f, v->background[i]);
    fprintf(f, "\n");
    for (int i = 0; i < s->n_lights; i++) {
        fprintf(f, "light point {");
        scn_vec(f, "colour", s->lights[i].colour, 3);
        scn_vec(f, " position", s->lights[i].position, 3);
        fprintf(f, " }\n");
    }
    for (int i = 0; i < s->n_materials; i++) {
        const struct sd_material *m = &s->materials[i];
        fprintf(f, "material %s {", m->name);
        scn_vec(f, "colour", m->colour, 3);
        scn_vec(f, " dic", &m->dic, 1);
        scn_vec(f, " drc", &m->drc, 1);
        scn_vec(f, " src", &m->src, 1);
        scn_vec(f, " trc", &m->trc, 1);
        scn_vec(f, " fresnel", &m->fresnel, 1);
        scn_vec(f, " ior", &m->ior, 1);
        fprintf(f, "  phong %d }\n", m->phong);
    }
    int used = -1;
    for (int i = 0; i < s->n_prims; i++) {
        const struct sd_prim *p = &s->prims[i];
        if (p->material != used) {
            used = p->material;
            fprintf(f, "use %s\n", s->materials[used].name);
        }
        if (p->kind == SCN_PRIM_ELLIPSOID) {
            fprintf(f, "sphere {");
            scn_vec(f, "centre", p->v, 3);
            scn_vec(f, " radius", p->v + 3, 1);
        } else {
            fprintf(f, "triangle {");
            for (int k = 0; k < 3; k++)
                scn_vec(f, k ? " v" : "v", p->v + 3 * k, 3);
            for (int k = 0; p->smooth && k < 3; k++)
                scn_vec(f, " n", p->n + 3 * k, 3);
        }
        fprintf(f, " }\n");
    }
    return ferror(f) ? -1 : 0;
}
