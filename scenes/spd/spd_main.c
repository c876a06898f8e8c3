/* spd_main.c: links1-spd, the Standard Procedural Databases.
 *
 *   links1-spd NAME SIZE -o OUT.scn [--size WxH]    a text scene
 *   links1-spd NAME SIZE -o OUT.nff [--size WxH]    the SPD's own NFF
 *
 * NAME: balls, gears, mount, rings, teapot, tetra, tree (spd_dbs.c,
 * spd_teapot.c); SIZE from 1 to each database's largest, the last whose
 * scene the compiler accepts for the board (its prepared frame within an
 * IMSU block: docs/scene-format.md).  The database is written as NFF, as
 * the SPD's program writes it with `-r 1`, and a text scene is made from
 * that NFF by the reader `links1 ref FILE.nff` uses (nff_read.h), so the
 * two compile to the same bytes.  --size changes the NFF's resolution
 * (512 x 512 in the SPD).  The largest sizes of rings and teapot are over
 * the 64 MiB a text scene may be: those are written as NFF only.
 */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host-tools/opts/out_file.h"
#include "host-tools/opts/exit_clean.h"
#include "host-tools/scene/nff_read.h"
#include "host-tools/scene/scene_import.h"
#include "host-tools/scene/scene_desc.h"
#include "scenes/spd/spd.h"

#define SPD_MAX_SCENE_TEXT (64u * 1024u * 1024u) /* PARSE_MAX_FILE, scene_parse.h */

static int spd_usage(void)
{
    fprintf(stderr, "usage: links1-spd NAME SIZE -o OUT.scn|OUT.nff [--size WxH]\n"
                    "  NAME (SPD's default size, largest size):");
    for (int i = 0; i < spd_db_count; i++)
        fprintf(stderr, " %s (%d, %d)%s", spd_dbs[i].name, spd_dbs[i].default_size,
                spd_dbs[i].max_size, i + 1 < spd_db_count ? "," : "\n");
    return 2;
}

static int spd_ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

int main(int argc, char **argv)
{
    exit_clean_install(); /* a signal leaves no temporary file */
    const char *name = NULL, *size_arg = NULL, *out = NULL;
    int width = 512, height = 512;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) {
            out = argv[++i];
        } else if (strcmp(argv[i], "--size") == 0 && i + 1 < argc) {
            char tail;
            if (sscanf(argv[++i], "%dx%d%c", &width, &height, &tail) != 2 || width < 1 ||
                height < 1 || width > SCN_MAX_WIDTH || height > SCN_MAX_HEIGHT) {
                fprintf(stderr, "links1-spd: --size wants WxH, each 1..%d, not '%s'\n",
                        SCN_MAX_WIDTH, argv[i]);
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
    const struct spd_db *db = spd_find(name);
    if (!db) {
        fprintf(stderr, "links1-spd: no database named '%s'\n", name);
        return spd_usage();
    }
    char *end;
    long size = strtol(size_arg, &end, 10);
    if (*end || end == size_arg || size < 1 || size > db->max_size) {
        fprintf(stderr, "links1-spd: %s: SIZE must be 1..%d, not '%s'\n", name, db->max_size,
                size_arg);
        return 2;
    }
    /* the NFF, in memory */
    char *nff = NULL;
    size_t nff_len = 0;
    FILE *m = open_memstream(&nff, &nff_len);
    if (!m) {
        perror("links1-spd");
        return 1;
    }
    spd_write_nff(db, (int)size, width, height, m);
    if (fclose(m) != 0 || !nff) {
        fprintf(stderr, "links1-spd: out of memory writing %s %ld\n", name, size);
        free(nff);
        return 1;
    }
    char title[160], err[SD_ERR_MAX];
    snprintf(title, sizeof title, "SPD %s %ld (Eric Haines's Standard Procedural Databases), "
             "written by links1-spd (scenes/spd/)", name, size);
    struct sd_scene s;
    struct nff_info info;
    if (nff_read_text(title, nff, &s, &info, err, sizeof err) != 0) {
        fprintf(stderr, "links1-spd: %s\n", err); /* a bug: the reader refuses our NFF */
        free(nff);
        return 1;
    }
    /* the text scene, in memory: the text form takes at most 64 MiB
     * (scene_parse.h), which the largest sizes' numbers pass */
    char *text = nff;
    size_t text_len = nff_len;
    if (!spd_ends_with(out, ".nff")) {
        text = NULL;
        m = open_memstream(&text, &text_len);
        if (!m || sd_write_text_titled(&s, NULL, title, m) != 0 || fclose(m) != 0 || !text) {
            fprintf(stderr, "links1-spd: out of memory writing %s %ld\n", name, size);
            sd_free(&s);
            free(nff);
            free(text);
            return 1;
        }
        if (text_len > SPD_MAX_SCENE_TEXT) {
            fprintf(stderr, "links1-spd: %s %ld as a text scene is %zu bytes, more than the "
                    "%u a scene text may be: write its NFF (-o FILE.nff), which links1 reads "
                    "as it is\n", name, size, text_len, SPD_MAX_SCENE_TEXT);
            sd_free(&s);
            free(nff);
            free(text);
            return 1;
        }
    }
    /* written whole or not at all (host-tools/opts/out_file.h) */
    char why[PATH_MAX + 256];
    struct out_file of;
    int rc = out_file_open(&of, out, why, sizeof why);
    if (rc == 0 && fwrite(text, 1, text_len, of.f) != text_len) {
        snprintf(why, sizeof why, "%s: write failed", out);
        out_file_abort(&of);
        rc = -1;
    } else if (rc == 0) {
        rc = out_file_commit(&of, why, sizeof why);
    }
    if (text != nff)
        free(text);
    if (rc) {
        fprintf(stderr, "links1-spd: %s\n", why);
        sd_free(&s);
        free(nff);
        return 1;
    }
    long spheres = 0;
    for (int i = 0; i < s.n_prims; i++)
        spheres += s.prims[i].kind == SCN_PRIM_ELLIPSOID;
    fprintf(stderr, "links1-spd: %s %ld -> %s: %ld spheres, %ld triangles\n", name, size, out,
            spheres, (long)s.n_prims - spheres);
    fprintf(stderr, "links1-spd: its NFF: %d lights, %ld spheres, %ld polygons, %ld patches, "
            "%ld cones", info.lights, info.spheres, info.polygons, info.patches, info.cones);
    if (info.lights_merged)
        fprintf(stderr, "; the lights merged into %d", s.n_lights);
    if (info.dropped)
        fprintf(stderr, "; %ld degenerate triangles left out", info.dropped);
    fprintf(stderr, "\n");
    sd_free(&s);
    free(nff);
    return 0;
}
