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

#include "host-tools/opts/cli_args.h"
#include "host-tools/opts/cli_opt.h"
#include "host-tools/opts/exit_clean.h"
#include "host-tools/opts/out_file.h"
#include "host-tools/scene/nff_read.h"
#include "host-tools/scene/scene_import.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/spd/spd.h"

#define SPD_MAX_SCENE_TEXT (64u * 1024u * 1024u) /* PARSE_MAX_FILE, scene_parse.h */

/* What the command line asks for. */
struct spd_opts {
    const struct spd_db *db;
    long size;
    const char *out;
    int width, height;
};

/* One database's NFF and its scene, in memory. */
struct spd_made {
    char title[160];
    char *nff, *text; /* text is nff for an .nff output */
    size_t nff_len, text_len;
    struct sd_scene s;
    struct nff_info info;
};

enum spd_opt_code { SPD_OPT_SIZE = CLI_OWN_CODES };

static const struct cli_optdef spd_optdefs[] = {
    {"size", "WxH", SPD_OPT_SIZE, "the NFF's resolution (default 512x512, the SPD's)"},
    CLI_OPTDEF_END,
};

static void spd_usage(FILE *f)
{
    fprintf(f, "usage: links1-spd NAME SIZE -o OUT.scn|OUT.nff [options]\n"
               "Writes one of Eric Haines's Standard Procedural Databases as the SPD's own\n"
               "program writes it (NFF, OUT.nff) or as a links1 text scene (OUT.scn).\n"
               "NAME and SIZE: a database and its size (the SPD's default, the largest):");
    for (int i = 0; i < spd_db_count; i++)
        fprintf(f, "%s %s (%d, %d)%s", i % 4 ? "" : "\n ", spd_dbs[i].name,
                spd_dbs[i].default_size, spd_dbs[i].max_size, i + 1 < spd_db_count ? "," : "\n");
    fprintf(f, "options:\n");
    cli_optdefs_help(f, spd_optdefs);
}

static int spd_ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

/* NAME or SIZE, in the order given. */
static int spd_operand(const char **name, const char **size, const char *arg)
{
    if (!*name)
        *name = arg;
    else if (!*size)
        *size = arg;
    else
        return cli_usage_error("links1-spd", "'%s': one NAME and one SIZE", arg);
    return 0;
}

/* NAME and SIZE into o.  0, or -1 (a usage error, said). */
static int spd_database(const char *name, const char *size, struct spd_opts *o)
{
    if (!(o->db = spd_find(name)))
        return cli_usage_error("links1-spd", "no database named '%s'", name);
    char *end;
    o->size = strtol(size, &end, 10);
    if (*end || end == size || o->size < 1 || o->size > o->db->max_size)
        return cli_usage_error("links1-spd", "%s: SIZE must be 1..%d, not '%s'", name,
                               o->db->max_size, size);
    return 0;
}

/* 0, 1 (--help shown) or -1 (a usage error, said). */
static int spd_parse(int argc, char **argv, struct spd_opts *o)
{
    static const struct cli_optdef *const lists[] = {spd_optdefs, NULL};
    struct option longs[4];
    if (cli_optdefs_table(lists, longs, 4) != 0)
        return -1;
    const char *name = NULL, *size = NULL;
    struct cli c;
    cli_init(&c, "links1-spd", argc, argv, "o:h", longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        int bad = 0;
        if (code == 'h') {
            spd_usage(stdout);
            return 1;
        } else if (code == 'o') {
            o->out = c.arg;
        } else if (code == SPD_OPT_SIZE) {
            bad = cli_parse_size(c.arg, &o->width, &o->height) != 0 &&
                  cli_bad_value(&c, cli_size_want());
        } else if (code == CLI_OPERAND) {
            bad = spd_operand(&name, &size, c.arg) != 0;
        } else {
            bad = 1;
        }
        if (bad)
            return -1;
    }
    if (!name || !size || !o->out)
        return cli_usage_error("links1-spd", "want NAME SIZE -o OUT");
    return spd_database(name, size, o);
}

/* The database's NFF and the scene read from it.  0, or -1 after saying why. */
static int spd_make(const struct spd_opts *o, struct spd_made *m)
{
    FILE *f = open_memstream(&m->nff, &m->nff_len);
    if (!f) {
        perror("links1-spd");
        return -1;
    }
    spd_write_nff(o->db, (int)o->size, o->width, o->height, f);
    if (fclose(f) != 0 || !m->nff) {
        fprintf(stderr, "links1-spd: out of memory writing %s %ld\n", o->db->name, o->size);
        return -1;
    }
    char err[SD_ERR_MAX];
    snprintf(m->title, sizeof m->title, "SPD %s %ld (Eric Haines's Standard Procedural "
             "Databases), written by links1-spd (host-tools/spd/)", o->db->name, o->size);
    if (nff_read_text(m->title, m->nff, &m->s, &m->info, err, sizeof err) != 0) {
        fprintf(stderr, "links1-spd: %s\n", err); /* a bug: the reader refuses our NFF */
        return -1;
    }
    m->text = m->nff;
    m->text_len = m->nff_len;
    return 0;
}

/* The text scene, in memory: the text form takes at most 64 MiB
 * (scene_parse.h).  0, or -1 after saying why. */
static int spd_text(const struct spd_opts *o, struct spd_made *m)
{
    m->text = NULL;
    FILE *f = open_memstream(&m->text, &m->text_len);
    if (!f || sd_write_text_titled(&m->s, NULL, m->title, f) != 0 || fclose(f) != 0 ||
        !m->text) {
        fprintf(stderr, "links1-spd: out of memory writing %s %ld\n", o->db->name, o->size);
        return -1;
    }
    if (m->text_len > SPD_MAX_SCENE_TEXT) {
        fprintf(stderr, "links1-spd: %s %ld as a text scene is %zu bytes, more than the %u a "
                "scene text may be: write its NFF (-o FILE.nff), which links1 reads as it is\n",
                o->db->name, o->size, m->text_len, SPD_MAX_SCENE_TEXT);
        return -1;
    }
    return 0;
}

/* OUT written whole or not at all (host-tools/opts/out_file.h).  0, or -1
 * after saying why. */
static int spd_write(const char *out, const char *text, size_t len)
{
    char why[PATH_MAX + 256];
    int rc = out_file_write(out, text, len, why, sizeof why);
    if (rc != 0)
        fprintf(stderr, "links1-spd: %s\n", why);
    return rc;
}

static void spd_say(const struct spd_opts *o, const struct spd_made *m)
{
    long spheres = 0, cones = 0;
    for (int i = 0; i < m->s.n_prims; i++) {
        spheres += m->s.prims[i].kind == SCN_PRIM_ELLIPSOID;
        cones += m->s.prims[i].kind == SCN_PRIM_CONE;
    }
    fprintf(stderr, "links1-spd: %s %ld -> %s: %ld spheres, %ld triangles", o->db->name,
            o->size, o->out, spheres, (long)m->s.n_prims - spheres - cones);
    if (cones)
        fprintf(stderr, ", %ld cones and cylinders", cones);
    fprintf(stderr, "\n");
    fprintf(stderr, "links1-spd: its NFF: %d lights, %ld spheres, %ld polygons, %ld patches, "
            "%ld cones", m->info.lights, m->info.spheres, m->info.polygons, m->info.patches,
            m->info.cones);
    if (m->info.lights_merged)
        fprintf(stderr, "; the lights merged into %d", m->s.n_lights);
    if (m->info.dropped)
        fprintf(stderr, "; %ld degenerate triangles left out", m->info.dropped);
    fprintf(stderr, "\n");
}

int main(int argc, char **argv)
{
    exit_clean_install(); /* a signal leaves no temporary file */
    struct spd_opts o = {NULL, 0, NULL, 512, 512};
    int r = spd_parse(argc, argv, &o);
    if (r != 0)
        return r > 0 ? 0 : 2;
    struct spd_made m;
    memset(&m, 0, sizeof m);
    int rc = spd_make(&o, &m);
    if (rc == 0 && !spd_ends_with(o.out, ".nff"))
        rc = spd_text(&o, &m);
    if (rc == 0)
        rc = spd_write(o.out, m.text, m.text_len);
    if (rc == 0)
        spd_say(&o, &m);
    if (m.text != m.nff)
        free(m.text);
    free(m.nff);
    sd_free(&m.s);
    return rc == 0 ? 0 : 1;
}
