/* scene_parse_model.c: the `model` statement of the text scene format
 * (docs/scene-format.md): a model file's nodes, triangles and materials
 * placed in the cluster the statement stands in (scene_import.h).
 *
 *   model { file "bison.obj"  material m  fit on  smooth on  textures_from "maps" }
 *
 * A model's textures are read from its own directory (and below) only,
 * unless textures_from names one more (relative to the scene's directory,
 * like file; not / nor a system root: sd_textures_from_ok): scene_import.h,
 * sd_texture_open.
 */
#include <stdio.h>
#include <string.h>

#include "host-tools/scene/scene_import.h"
#include "host-tools/scene/scene_parse.h"

void parse_model(struct parser *p, int cluster, int nesting)
{
    int line = p->lx.tok_line, col = p->lx.tok_col;
    char file[LEX_TOKEN_MAX] = "", textures[LEX_TOKEN_MAX] = "";
    struct import_opts o = {0, -1, nesting, "'fit on'", 0, NULL};
    lex_next(&p->lx);
    parse_open(p, "model");
    while (p->lx.kind != LEX_CLOSE) {
        if (lex_is_word(&p->lx, "file")) {
            lex_next(&p->lx);
            if (p->lx.kind != LEX_STRING)
                lex_error(&p->lx, "expected a file name in quotes, found '%s'", p->lx.tok);
            snprintf(file, sizeof file, "%s", p->lx.tok);
            lex_next(&p->lx);
        } else if (lex_is_word(&p->lx, "material")) {
            lex_next(&p->lx);
            o.material = parse_material_ref(p);
        } else if (lex_is_word(&p->lx, "fit")) {
            lex_next(&p->lx);
            o.fit = parse_on_off(p, "fit");
        } else if (lex_is_word(&p->lx, "textures_from")) {
            lex_next(&p->lx);
            if (p->lx.kind != LEX_STRING)
                lex_error(&p->lx, "expected a directory name in quotes, found '%s'", p->lx.tok);
            snprintf(textures, sizeof textures, "%s", p->lx.tok);
            lex_next(&p->lx);
        } else if (lex_is_word(&p->lx, "smooth")) {
            lex_next(&p->lx);
            o.smooth = parse_on_off(p, "smooth");
        } else {
            parse_unknown(p, "model");
        }
    }
    p->lx.tok_line = line, p->lx.tok_col = col; /* errors below name the statement */
    if (!file[0])
        lex_error(&p->lx, "model needs a file \"NAME\"");
    char path[IMPORT_PATH_MAX], dir[IMPORT_PATH_MAX];
    snprintf(path, sizeof path, "%s%s", file[0] == '/' ? "" : p->dir, file);
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash)
        slash[1] = 0;
    else
        dir[0] = 0;
    char allow[IMPORT_PATH_MAX];
    if (textures[0]) {
        snprintf(allow, sizeof allow, "%s%s", textures[0] == '/' ? "" : p->dir, textures);
        char why[SD_ERR_MAX];
        if (sd_textures_from_ok(allow, "textures_from", why, sizeof why) != 0)
            lex_error(&p->lx, "model: %s", why);
        o.textures_from = allow;
    }
    struct model m;
    char why[SD_ERR_MAX];
    if (model_load(path, &m, why, sizeof why) != 0)
        lex_error(&p->lx, "model: %s", why);
    struct import_result r;
    int rc = scene_import_model(p->s, cluster, &m, dir, &o, &r, why, sizeof why);
    model_free(&m);
    if (rc != 0)
        lex_error(&p->lx, "model %s: %s", path, why);
    /* the arrays were grown to their exact sizes */
    p->cap_clusters = p->s->n_clusters;
    p->cap_prims = p->s->n_prims;
    p->cap_materials = p->s->n_materials;
    if (r.degenerate || r.other)
        fprintf(stderr, "%s:%d:%d: model %s: %d degenerate triangle%s dropped, %d points or "
                        "lines left out\n",
                p->lx.file, line, col, path, r.degenerate, r.degenerate == 1 ? "" : "s",
                r.other);
    if (r.flat)
        fprintf(stderr, "%s:%d:%d: model %s: smooth on, but %d of its %d triangles have no "
                        "vertex normals in the file: they are flat\n",
                p->lx.file, line, col, path, r.flat, r.triangles);
    lex_next(&p->lx);
}
