/* test_scene_paper.c: paper mode (host-tools/scene/scene_paper.h): what
 * `options { paper on }` and --paper set in the scene (min_weight 0, no
 * automatic hierarchy where the scene has clusters of its own, the PAPER
 * flag), that options written beside it win, that the compiled bytes carry
 * what the printed line says, and the render arguments it sets. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_file.h"
#include "host-tools/scene/scene_paper.h"
#include "proto/scene_format.h"
#include "tests/check.h"

/* %s: the options block's contents.  Two clusters of the author's (the
 * root besides), six primitives, a mirror and a clear material. */
static const char *clustered =
    "camera { eye 0 1 -5 look_at 0 0 0 up 0 1 0 fov 60 }\n"
    "resolution 64 48\n"
    "options { max_depth 4 %s }\n"
    "light point { position 1 2 3 }\n"
    "material m { colour 1 1 1 }\n"
    "material mirror { colour 1 1 1 src 0.7 }\n"
    "material glass { colour 1 1 1 trc 0.8 ior 1.5 }\n"
    "cluster a { translate -1 0 0\n"
    "  sphere { material m centre 0 0 0 radius 0.3 }\n"
    "  sphere { material m centre 0 1 0 radius 0.3 }\n"
    "  sphere { material mirror centre 0 2 0 radius 0.3 } }\n"
    "cluster b { translate 1 0 0\n"
    "  sphere { material glass centre 0 0 0 radius 0.3 }\n"
    "  sphere { material m centre 0 1 0 radius 0.3 }\n"
    "  sphere { material m centre 0 2 0 radius 0.3 } }\n";

/* Six spheres at the root: only an automatic hierarchy can group them. */
static const char *flat =
    "camera { eye 0 1 -5 look_at 0 0 0 up 0 1 0 fov 60 }\n"
    "resolution 64 48\n"
    "options { paper on }\n"
    "light point { position 1 2 3 }\n"
    "material m { colour 1 1 1 }\n"
    "sphere { material m centre -2 0 0 radius 0.3 }\n"
    "sphere { material m centre -1 0 0 radius 0.3 }\n"
    "sphere { material m centre 0 0 0 radius 0.3 }\n"
    "sphere { material m centre 1 0 0 radius 0.3 }\n"
    "sphere { material m centre 2 0 0 radius 0.3 }\n"
    "sphere { material m centre 3 0 0 radius 0.3 }\n";

static char dir[] = "/tmp/links1-test-scene-paper-XXXXXX";

static int parse_with(const char *options, struct sd_scene *s)
{
    char text[2048], err[SD_ERR_MAX];
    snprintf(text, sizeof text, clustered, options);
    int rc = sd_parse_text("t.scn", text, s, err, sizeof err);
    if (rc != 0)
        fprintf(stderr, "%s\n", err);
    return rc;
}

static void test_paper_on_sets_the_scene(void)
{
    struct sd_scene s;
    if (parse_with("", &s) == 0) { /* not in paper mode */
        CHECK(s.view.min_weight > 0);
        CHECK_EQ_INT(s.no_auto_hierarchy, 0);
        CHECK_EQ_INT(s.view.flags & SCN_OPT_PAPER, 0);
        sd_free(&s);
    }
    if (parse_with("paper on", &s) == 0) {
        CHECK(s.view.min_weight == 0);
        CHECK_EQ_INT(s.no_auto_hierarchy, 1); /* the scene has clusters a and b */
        CHECK(s.view.flags & SCN_OPT_PAPER);
        CHECK_EQ_INT(s.view.max_depth, 4);    /* the depth is the scene's, fixed */
        sd_free(&s);
    }
    if (parse_with("paper off", &s) == 0) {
        CHECK(s.view.min_weight > 0 && !(s.view.flags & SCN_OPT_PAPER));
        sd_free(&s);
    }
    char err[SD_ERR_MAX];
    CHECK_EQ_INT(sd_parse_text("flat.scn", flat, &s, err, sizeof err), 0);
    CHECK_EQ_INT(s.no_auto_hierarchy, 0); /* no clusters of its own: the automatic one */
    CHECK(s.view.min_weight == 0);
    sd_free(&s);
}

static void test_written_options_win(void)
{
    struct sd_scene s;
    if (parse_with("min_weight 0.01 paper on auto_hierarchy on", &s) == 0) {
        CHECK(s.view.min_weight == 0.01);
        CHECK_EQ_INT(s.no_auto_hierarchy, 0);
        CHECK(s.view.flags & SCN_OPT_PAPER);
        sd_free(&s);
    }
    if (parse_with("paper on fresnel off", &s) == 0) { /* constant src/trc as written */
        int by_angle = 0;
        for (int i = 0; i < s.n_materials; i++)
            by_angle += s.materials[i].fresnel > 0;
        CHECK_EQ_INT(by_angle, 0);
        sd_free(&s);
    }
}

/* What the compiled bytes hold is what the line says. */
static void test_compiled_bytes_and_line(void)
{
    struct sd_scene s;
    if (parse_with("paper on", &s) != 0)
        return;
    uint8_t *buf;
    size_t len;
    char err[SD_ERR_MAX];
    CHECK_EQ_INT(sd_compile(&s, &buf, &len, err, sizeof err), 0);
    struct scene_paper p;
    CHECK_EQ_INT(scene_paper_read(buf, len, &p, err, sizeof err), 0);
    CHECK_EQ_INT(p.paper, 1);
    CHECK(p.min_weight == 0);
    CHECK_EQ_INT(p.max_depth, 4);
    CHECK_EQ_INT(p.height, 48);
    CHECK_EQ_INT((int)p.clusters, s.n_clusters); /* no automatic hierarchy added */
    CHECK_EQ_INT(p.mirror_or_clear, 2);
    CHECK_EQ_INT(p.by_angle, 2);
    struct link_render_args a = {0};
    a.balance = LINK_BALANCE_DECREASING;
    scene_paper_args(&p, 0, &a);
    CHECK_EQ_INT(a.balance, LINK_BALANCE_LINES);
    CHECK_EQ_INT(a.areas, 48);
    CHECK(a.flags & LINK_RENDER_ASK_WHEN_DONE);
    CHECK_EQ_INT(a.clip, LINK_CLIP_LISTS);
    char line[512];
    scene_paper_line(&p, &a, 0, s.n_clusters, line, sizeof line);
    CHECK(strstr(line, "src/trc by angle (2 of 2 ") != NULL);
    CHECK(strstr(line, "depth fixed at 4 (min_weight 0)") != NULL);
    CHECK(strstr(line, "areas lines K 48 (whole scanlines)") != NULL);
    CHECK(strstr(line, "ask finished, clip lists, clusters 3 (auto_hierarchy off") != NULL);
    /* options given beside paper mode stay */
    struct link_render_args g = {0};
    g.balance = LINK_BALANCE_DYNAMIC;
    g.areas = 96;
    g.clip = LINK_CLIP_TREE;
    scene_paper_args(&p, SCENE_PAPER_GAVE_BALANCE | SCENE_PAPER_GAVE_AREAS |
                             SCENE_PAPER_GAVE_CLIP, &g);
    CHECK_EQ_INT(g.balance, LINK_BALANCE_DYNAMIC);
    CHECK_EQ_INT(g.areas, 96);
    CHECK_EQ_INT(g.clip, LINK_CLIP_TREE);
    CHECK(g.flags & LINK_RENDER_ASK_WHEN_DONE);
    a.areas = 240; /* five pieces of each scanline */
    scene_paper_line(&p, &a, 0, s.n_clusters, line, sizeof line);
    CHECK(strstr(line, "areas lines K 240 (parts of scanlines)") != NULL);
    free(buf);
    sd_free(&s);
    /* without paper mode the compiled scene carries no flag, and the
     * automatic hierarchy adds clusters */
    if (parse_with("", &s) == 0) {
        CHECK_EQ_INT(sd_compile(&s, &buf, &len, err, sizeof err), 0);
        CHECK_EQ_INT(scene_paper_read(buf, len, &p, err, sizeof err), 0);
        CHECK_EQ_INT(p.paper, 0);
        CHECK(p.min_weight > 0);
        free(buf);
        sd_free(&s);
    }
    CHECK_EQ_INT(scene_paper_read((const uint8_t *)"L1SC", 4, &p, err, sizeof err), -1);
}

/* --paper on the command line (scene_file_opts.paper) does what the
 * options block does; --min-weight beside it wins; a compiled file cannot
 * take it. */
static void test_command_line_paper(void)
{
    char scn[128], l1s[128], err[SD_ERR_MAX], text[2048];
    snprintf(scn, sizeof scn, "%s/c.scn", dir);
    snprintf(l1s, sizeof l1s, "%s/c.l1s", dir);
    snprintf(text, sizeof text, clustered, "");
    FILE *f = fopen(scn, "w");
    if (!f) {
        CHECK(f != NULL);
        return;
    }
    fputs(text, f);
    fclose(f);
    struct scene_file_opts o;
    scene_file_opts_init(&o);
    o.paper = 1;
    uint8_t *buf;
    size_t len;
    struct scene_file_info info;
    struct scene_paper p;
    CHECK_EQ_INT(scene_file_bytes_info(scn, &o, &buf, &len, &info, err, sizeof err), 0);
    CHECK_EQ_INT(info.auto_hierarchy, 0);
    CHECK_EQ_INT(info.own_clusters, 3);
    if (buf && scene_paper_read(buf, len, &p, err, sizeof err) == 0) {
        CHECK_EQ_INT(p.paper, 1);
        CHECK(p.min_weight == 0);
        CHECK_EQ_INT((int)p.clusters, 3);
    }
    f = fopen(l1s, "wb");
    if (f && buf) {
        fwrite(buf, 1, len, f);
        fclose(f);
    }
    free(buf);
    o.min_weight = 0.125;
    CHECK_EQ_INT(scene_file_bytes_info(scn, &o, &buf, &len, &info, err, sizeof err), 0);
    if (buf && scene_paper_read(buf, len, &p, err, sizeof err) == 0)
        CHECK(p.min_weight == 0.125f && p.paper == 1);
    free(buf);
    scene_file_opts_init(&o);
    o.paper = 1;
    CHECK_EQ_INT(scene_file_bytes_info(l1s, &o, &buf, &len, &info, err, sizeof err), -1);
    CHECK(strstr(err, "--paper") != NULL);
    unlink(scn);
    unlink(l1s);
}

int main(void)
{
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    RUN(test_paper_on_sets_the_scene);
    RUN(test_written_options_win);
    RUN(test_compiled_bytes_and_line);
    RUN(test_command_line_paper);
    rmdir(dir);
    return check_exit();
}
