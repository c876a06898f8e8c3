/* hostile.h: hostile scenes, one per class of attack on the compiled form
 * (proto/scene_format.h), each made by editing the fields of a good
 * compiled scene through the format's one definition (the compiler writes
 * the base; nothing here writes the format a second time).
 *
 * Each class names the words its refusal must contain, on the host
 * (scene_load and render_blob_build, tests/hostile/test_hostile.c) and on
 * the board (the DM's "scene refused: ..." answer,
 * tests/board/render/render_hostile.sh, files from make_hostile). */
#ifndef LINKS1_TESTS_HOSTILE_H
#define LINKS1_TESTS_HOSTILE_H

#include <stddef.h>
#include <stdint.h>

struct hostile_scene {
    uint8_t *buf; /* malloc'ed */
    size_t len;
};

struct hostile_class {
    const char *name;   /* file name on the board test, test name on the host */
    const char *expect; /* the refusal contains this */
    int (*make)(struct hostile_scene *h); /* 0, or -1 if the base lacks what it edits */
};

extern const struct hostile_class hostile_classes[];
extern const int hostile_class_count;

/* The good scene every class edits, compiled: 32x24 pixels, 2 frames, a
 * light, two materials, a colour map, clusters nested 32 deep (1..32, each
 * the child of the one before) and cluster 33 a child of the root with a
 * key, and a box, a triangle, a density sphere and two spheres (prims 0..4). */
int hostile_base(struct hostile_scene *h, char *err, size_t errlen);

/* The text of a scene whose prepared frame needs more than the DM's IMSU
 * block (about 32000 triangles): what every NC would have to take in. */
char *hostile_big_text(void);

#endif
