/* spd_main.c: links1-spd, the Standard Procedural Databases as scenes.
 *
 *   links1-spd NAME SIZE -o OUT.scn [--size WxH]
 *
 * NAME: balls, tetra, mount, rings, tree, gears (spd_dbs.c) or teapot
 * (spd_teapot.c); SIZE from 1 to each database's largest, the last whose
 * scene the compiler accepts for the board (its prepared frame within an
 * IMSU block; checked: tetra 8 = 262,144 triangles, rings 15 = 345,602
 * triangles and 14,400 spheres, gears 38 = 369,666 triangles, teapot 16 =
 * 261,760 triangles; balls stops at 5 = 66,430 spheres, mount at 8).
 * The default image is 512x512, as in the originals.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenes/spd/spd.h"

struct spd_db {
    const char *name;
    void (*make)(struct spd_out *o, int size, int width, int height);
    int max_size;
};

static const struct spd_db spd_dbs[] = {
    {"balls", spd_balls, 5}, {"tetra", spd_tetra, 8}, {"mount", spd_mount, 8},
    {"rings", spd_rings, 15}, {"tree", spd_tree, 14}, {"gears", spd_gears, 38},
    {"teapot", spd_teapot, 16},
};
#define SPD_DB_COUNT (sizeof spd_dbs / sizeof spd_dbs[0])

static int spd_usage(void)
{
    fprintf(stderr, "usage: links1-spd NAME SIZE -o OUT.scn [--size WxH]\n  NAME and largest SIZE:");
    for (size_t i = 0; i < SPD_DB_COUNT; i++)
        fprintf(stderr, " %s %d%s", spd_dbs[i].name, spd_dbs[i].max_size,
                i + 1 < SPD_DB_COUNT ? "," : "\n");
    return 2;
}

int main(int argc, char **argv)
{
    const char *name = NULL, *size_arg = NULL, *out = NULL;
    int width = 512, height = 512;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) {
            out = argv[++i];
        } else if (strcmp(argv[i], "--size") == 0 && i + 1 < argc) {
            char tail;
            if (sscanf(argv[++i], "%dx%d%c", &width, &height, &tail) != 2 || width < 1 ||
                height < 1 || width > 1024 || height > 1024) {
                fprintf(stderr, "links1-spd: --size wants WxH, each 1..1024, not '%s'\n", argv[i]);
                return 2;
            }
        } else if (argv[i][0] != '-' && !name) {
            name = argv[i];
        } else if (argv[i][0] != '-' && !size_arg) {
            size_arg = argv[i];
        } else {
            fprintf(stderr, "links1-spd: unknown argument '%s'\n", argv[i]);
            return spd_usage();
        }
    }
    if (!name || !size_arg || !out)
        return spd_usage();
    const struct spd_db *db = NULL;
    for (size_t i = 0; i < SPD_DB_COUNT; i++)
        if (strcmp(name, spd_dbs[i].name) == 0)
            db = &spd_dbs[i];
    char *end;
    long size = strtol(size_arg, &end, 10);
    if (!db) {
        fprintf(stderr, "links1-spd: no database named '%s'\n", name);
        return spd_usage();
    }
    if (*end || size < 1 || size > db->max_size) {
        fprintf(stderr, "links1-spd: %s: SIZE must be 1..%d, not '%s'\n", name, db->max_size,
                size_arg);
        return 2;
    }
    struct spd_out o = {fopen(out, "w"), 0, 0, 0};
    if (!o.f) {
        perror(out);
        return 1;
    }
    fprintf(o.f, "# SPD %s, size %ld: written by links1-spd (scenes/spd/)\n", name, size);
    db->make(&o, (int)size, width, height);
    fprintf(o.f, "# %ld spheres, %ld triangles\n", o.spheres, o.triangles);
    if (fclose(o.f) != 0) {
        perror(out);
        return 1;
    }
    fprintf(stderr, "links1-spd: %s %ld -> %s: %ld spheres, %ld triangles", name, size, out,
            o.spheres, o.triangles);
    if (o.dropped)
        fprintf(stderr, " (%ld degenerate ones left out)", o.dropped);
    fprintf(stderr, "\n");
    return 0;
}
