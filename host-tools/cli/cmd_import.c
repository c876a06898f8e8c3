/* cmd_import.c: `links1 import MODEL -o SCENE.scn [--fit] [--camera auto] [--smooth]
 * [--textures-from DIR]`:
 * a model made elsewhere into a text scene (docs/import.md).  The scene is
 * written to a temporary file, read back and compiled before it takes
 * SCENE's name, so a refused model leaves no output at all. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/opts/cli_opt.h"
#include "host-tools/opts/out_file.h"
#include "host-tools/cli/scene_cmds.h"
#include "host-tools/scene/scene_import.h"

enum import_opt_code {
    IMPORT_OPT_FIT = CLI_OWN_CODES,
    IMPORT_OPT_CAMERA,
    IMPORT_OPT_SMOOTH,
    IMPORT_OPT_TEXTURES_FROM
};

/* --textures-from is the model statement's textures_from (one directory
 * for the model's textures), not the scene option of the same name (up to
 * four for a scene's map images). */
static const struct cli_optdef import_optdefs[] = {
    {"fit", NULL, IMPORT_OPT_FIT,
     "scale a model beyond +-1e8 so its largest coordinate is 100"},
    {"camera", "auto", IMPORT_OPT_CAMERA,
     "a model without a camera gets one that frames its bounding box,\n"
     "one without lights a white parallel light"},
    {"smooth", NULL, IMPORT_OPT_SMOOTH, "triangles carry the model's vertex normals"},
    {"textures-from", "DIR", IMPORT_OPT_TEXTURES_FROM,
     "the model's textures may also come from below DIR (once; not /,\n"
     "a directory just under / or your home)"},
    CLI_OPTDEF_END,
};

static void import_usage(FILE *out)
{
    fprintf(out, "usage: links1 import MODEL -o SCENE.scn [options]\n"
                 "Writes a model (OBJ, glTF, PLY, STL, Collada, 3DS, ...) as a text scene with\n"
                 "its camera, lights, materials, maps, clusters and triangles; a model the\n"
                 "scene does not read back and compile leaves no file.\n");
    cli_optdefs_help(out, import_optdefs);
}

struct import_args {
    const char *model, *out;
    int fit, camera_auto, smooth;
    const char *textures_from; /* one more directory textures may come from */
};

static int import_args(int argc, char **argv, struct import_args *a)
{
    static const struct cli_optdef *const lists[] = {import_optdefs, NULL};
    struct option longs[8];
    struct cli c;
    if (cli_optdefs_table(lists, longs, 8) != 0)
        return -1;
    cli_init(&c, "links1 import", argc, argv, "o:h", longs);
    for (int code; (code = cli_next(&c)) != -1;) {
        if (code == 'h') {
            import_usage(stdout);
            return 1;
        } else if (code == 'o') {
            a->out = c.arg;
        } else if (code == IMPORT_OPT_FIT) {
            a->fit = 1;
        } else if (code == IMPORT_OPT_SMOOTH) {
            a->smooth = 1;
        } else if (code == IMPORT_OPT_TEXTURES_FROM) {
            char why[SD_ERR_MAX];
            if (a->textures_from || sd_textures_from_ok(c.arg, "--textures-from", why,
                                                        sizeof why) != 0) {
                cli_usage_error("links1 import", "%s",
                                a->textures_from ? "--textures-from: give it once" : why);
                return -1;
            }
            a->textures_from = c.arg;
        } else if (code == IMPORT_OPT_CAMERA && strcmp(c.arg, "auto") == 0) {
            a->camera_auto = 1;
        } else if (code == IMPORT_OPT_CAMERA) {
            cli_bad_value(&c, "auto");
            return -1;
        } else if (code == CLI_OPERAND && !a->model) {
            a->model = c.arg;
        } else {
            if (code == CLI_OPERAND)
                cli_usage_error("links1 import", "one model at a time, not also '%s'", c.arg);
            return -1;
        }
    }
    if (!a->model || !a->out) {
        cli_usage_error("links1 import", "%s", !a->model ? "no MODEL given" : "no -o SCENE.scn given");
        return -1;
    }
    return 0;
}

/* Copies src into dst of n bytes, cut short if it must be. */
static void import_copy(char *dst, size_t n, const char *src)
{
    size_t k = strlen(src);
    if (k >= n)
        k = n - 1;
    memcpy(dst, src, k);
    dst[k] = 0;
}

/* path's directory with a trailing '/', or "" (the current one). */
static void import_dir(const char *path, char *dir, size_t n)
{
    snprintf(dir, n, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash)
        slash[1] = 0;
    else
        dir[0] = 0;
}

/* Texture paths as the written scene names them: relative to the scene's
 * directory when the file lies below it, absolute otherwise. */
static void import_map_names(const struct import_result *r, int n_maps, const char *out,
                             char names[][IMPORT_PATH_MAX], const char **ptrs)
{
    char odir[IMPORT_PATH_MAX], oreal[PATH_MAX];
    import_dir(out, odir, sizeof odir);
    int have_out = realpath(odir[0] ? odir : ".", oreal) != NULL;
    size_t olen = strlen(oreal);
    for (int i = 0; i < n_maps; i++) {
        char real[PATH_MAX];
        ptrs[i] = names[i];
        if (!r->map_image[i][0] || !realpath(r->map_image[i], real)) {
            import_copy(names[i], IMPORT_PATH_MAX, r->map_image[i]);
        } else if (have_out && strncmp(real, oreal, olen) == 0 && real[olen] == '/') {
            import_copy(names[i], IMPORT_PATH_MAX, real + olen + 1);
        } else {
            import_copy(names[i], IMPORT_PATH_MAX, real);
        }
    }
}

/* A map image the scene names by an absolute path lies outside its
 * directory: reading the scene takes --textures-from, said on stderr with
 * the directories (of from, NULL-ended) that hold such images. */
static void import_outside_note(const char *out, int n_maps, const char *const *names,
                                const char *const *from)
{
    int need[2] = {0, 0};
    for (int i = 0; i < n_maps; i++) {
        char real[PATH_MAX];
        if (names[i][0] != '/' || !realpath(names[i], real))
            continue;
        for (int k = 0; k < 2 && from[k]; k++)
            if (sd_image_below(from[k], real)) {
                need[k] = 1;
                break;
            }
    }
    if (!need[0] && !need[1])
        return;
    fprintf(stderr, "links1 import: %s names map images outside its directory: compile, "
            "render or ref it with", out);
    for (int k = 0; k < 2; k++)
        if (need[k])
            fprintf(stderr, " --textures-from %s", from[k]);
    fprintf(stderr, " (a map's image is read only from below the scene's directory and "
            "those)\n");
}

/* Writes s as text to the output file's temporary file, reads it back
 * from there (beside OUT, so map paths read as they will, their images
 * also from below the directories of the NULL-ended list from: where the
 * import took them) and compiles it. */
static int import_write(const struct sd_scene *s, const char *const *maps,
                        const char *const *from, const struct out_file *of, char *err,
                        size_t errlen)
{
    int rc = sd_write_text(s, maps, of->f);
    if (rc != 0 || fflush(of->f) != 0 || ferror(of->f)) {
        snprintf(err, errlen, "writing %.300s: %s", of->path, strerror(errno));
        return -1;
    }
    struct sd_scene back;
    char why[SD_ERR_MAX];
    if (sd_parse_file_from(of->tmp, from, &back, why, sizeof why) != 0) {
        snprintf(err, errlen, "the written scene does not read back: %.400s", why);
        return -1;
    }
    uint8_t *buf;
    size_t len;
    rc = sd_compile(&back, &buf, &len, why, sizeof why);
    sd_free(&back);
    if (rc != 0) {
        snprintf(err, errlen, "the written scene does not compile: %.400s", why);
        return -1;
    }
    free(buf);
    return 0;
}

int scene_cmd_import(int argc, char **argv)
{
    struct import_args a = {NULL, NULL, 0, 0, 0, NULL};
    int r0 = import_args(argc, argv, &a);
    if (r0 != 0)
        return r0 > 0 ? 0 : 2;
    struct model m;
    char err[SD_ERR_MAX];
    if (out_file_check(a.out, err, sizeof err) != 0) { /* before the model is read */
        fprintf(stderr, "links1 import: -o %s\n", err);
        return 1;
    }
    if (model_load(a.model, &m, err, sizeof err) != 0) {
        fprintf(stderr, "links1 import: %s\n", err);
        return 1;
    }
    struct sd_scene s;
    memset(&s, 0, sizeof s);
    sd_view_defaults(&s.view);
    struct import_result *r = calloc(1, sizeof *r);
    s.clusters = calloc(1, sizeof *s.clusters);
    if (!r || !s.clusters) {
        fprintf(stderr, "links1 import: out of memory\n");
        model_free(&m);
        free(r);
        sd_free(&s);
        return 1;
    }
    snprintf(s.clusters[0].name, sizeof s.clusters[0].name, "root");
    s.clusters[0].parent = -1;
    s.clusters[0].m[0] = s.clusters[0].m[5] = s.clusters[0].m[10] = 1;
    s.n_clusters = 1;
    char dir[IMPORT_PATH_MAX];
    import_dir(a.model, dir, sizeof dir);
    struct import_opts o = {a.fit, -1, 0, "--fit", a.smooth, a.textures_from};
    int rc = scene_import_model(&s, 0, &m, dir, &o, r, err, sizeof err);
    if (rc == 0)
        rc = scene_import_view(&s, &m, r, a.camera_auto, stderr, err, sizeof err);
    model_free(&m);
    if (rc == 0) {
        static char names[SCN_MAX_MAPS][IMPORT_PATH_MAX];
        const char *ptrs[SCN_MAX_MAPS];
        import_map_names(r, s.n_maps, a.out, names, ptrs);
        struct out_file of;
        const char *from[3] = {dir[0] ? dir : ".", a.textures_from, NULL};
        rc = out_file_open(&of, a.out, err, sizeof err);
        if (rc == 0 && import_write(&s, ptrs, from, &of, err, sizeof err) != 0) {
            out_file_abort(&of);
            rc = -1;
        } else if (rc == 0) {
            rc = out_file_commit(&of, err, sizeof err);
        }
        if (rc == 0)
            import_outside_note(a.out, s.n_maps, ptrs, from);
    }
    if (rc != 0) {
        fprintf(stderr, "links1 import: %s: %s\n", a.model, err);
    } else {
        if (r->degenerate || r->other)
            fprintf(stderr, "links1 import: %s: %d degenerate triangle%s dropped, %d points "
                            "or lines left out\n",
                    a.model, r->degenerate, r->degenerate == 1 ? "" : "s", r->other);
        if (r->flat)
            fprintf(stderr, "links1 import: %s: --smooth, but %d of its %d triangles have no "
                            "vertex normals in the file: they are flat\n",
                    a.model, r->flat, r->triangles);
        printf("%s: %d triangles in %d clusters, %d materials, %d maps", a.out, r->triangles,
               r->clusters, r->materials, r->maps);
        if (r->scale != 1)
            printf(", scaled by %g", r->scale);
        printf("\n");
    }
    free(r);
    sd_free(&s);
    return rc ? 1 : 0;
}
