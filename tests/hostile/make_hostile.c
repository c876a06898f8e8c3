/* make_hostile.c: writes each hostile class (hostile.c) as DIR/NAME.l1s,
 * the good base scene they are made from as DIR/base.l1s, and prints one line per class, "NAME<TAB>EXPECTED", the words the
 * board's refusal must contain (tests/board/render/render_hostile.sh).
 * Usage: make_hostile DIR */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/scene/scene_desc.h"
#include "tests/hostile/hostile.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: make_hostile DIR\n");
        return 2;
    }
    struct hostile_scene base;
    char err[SD_ERR_MAX];
    if (hostile_base(&base, err, sizeof err) != 0) {
        fprintf(stderr, "make_hostile: the base scene: %s\n", err);
        return 1;
    }
    char path[1024];
    snprintf(path, sizeof path, "%s/base.l1s", argv[1]);
    FILE *bf = fopen(path, "wb");
    if (!bf || fwrite(base.buf, 1, base.len, bf) != base.len || fclose(bf) != 0) {
        fprintf(stderr, "make_hostile: cannot write %s\n", path);
        return 1;
    }
    for (int i = 0; i < hostile_class_count; i++) {
        const struct hostile_class *c = &hostile_classes[i];
        struct hostile_scene h = {malloc(base.len), base.len};
        if (!h.buf)
            return 1;
        memcpy(h.buf, base.buf, base.len);
        snprintf(path, sizeof path, "%s/%s.l1s", argv[1], c->name);
        FILE *f = NULL;
        if (c->make(&h) != 0 || !(f = fopen(path, "wb")) ||
            fwrite(h.buf, 1, h.len, f) != h.len || fclose(f) != 0) {
            fprintf(stderr, "make_hostile: %s: cannot make or write it\n", path);
            return 1;
        }
        printf("%s\t%s\n", c->name, c->expect);
        free(h.buf);
    }
    free(base.buf);
    return 0;
}
