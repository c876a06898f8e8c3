/* empty_scene.h: an empty scene description for the host tests that build
 * one up (the scene's default view and its root cluster). */
#ifndef LINKS1_TESTS_EMPTY_SCENE_H
#define LINKS1_TESTS_EMPTY_SCENE_H

#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_desc.h"

static void empty_scene(struct sd_scene *s)
{
    memset(s, 0, sizeof *s);
    sd_view_defaults(&s->view);
    s->clusters = calloc(1, sizeof *s->clusters);
    s->clusters[0].parent = -1;
    s->clusters[0].m[0] = s->clusters[0].m[5] = s->clusters[0].m[10] = 1;
    s->n_clusters = 1;
}

#endif
