/* arith_auto.c: `--arith auto` (arith_auto.h). */
#include "host-tools/ref/arith_auto.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host-tools/image/image_compare.h"
#include "host-tools/image/image_io.h"
#include "host-tools/opts/self_path.h"
#include "host-tools/opts/tmp_dir.h"
#include "host-tools/ref/ref_program.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_file.h"
#include "proto/machines.h"
#include "render/render.h"

/* The fixed formats: fixed/num.h takes NUM_FRAC_BITS 8..24 (those that
 * keep NUM_FAR in range build); the firmware is built with its default. */
#define AUTO_FIXED_BITS_BOARD 19
#define AUTO_FIXED_BITS_MIN 8
#define AUTO_FIXED_BITS_MAX 24
#define AUTO_MAX_CANDS (3 + AUTO_FIXED_BITS_MAX - AUTO_FIXED_BITS_MIN)
#define AUTO_MAX_ARGS 48

struct auto_cand {
    char label[24], build[24], arith[8];
    int measured;        /* the host build ran (images below valid) */
    int refused;         /* the host build refused the scene (why): it
                            misses the target */
    char why[200];
    double psnr, psnr_flagged;
    unsigned lost;       /* pixels flagged */
    double cost;         /* NC instructions per pixel on the board; < 0: not measured */
};

struct auto_run {
    const char *prog, *path, *tmp;
    const struct arith_auto_opts *o;
    int w, h;            /* pre-render size; 0: the scene's (a compiled .l1s) */
    struct image ref;    /* the double build's pre-render */
};

int arith_auto_fpu(const char *word)
{
    return strcmp(word, "vfp") == 0 ? 1 : strcmp(word, "none") == 0 ? 0 : -1;
}

void arith_auto_scene_words(const struct scene_file_opts *so, long frame,
                            struct arith_auto_words *w)
{
    int n = 0;
    if (so->max_depth >= 0) {
        snprintf(w->depth, sizeof w->depth, "%d", so->max_depth);
        w->words[n++] = "--max-depth";
        w->words[n++] = w->depth;
    }
    if (so->min_weight >= 0) {
        snprintf(w->weight, sizeof w->weight, "%.17g", so->min_weight);
        w->words[n++] = "--min-weight";
        w->words[n++] = w->weight;
    }
    if (so->density_steps >= 0) {
        snprintf(w->steps, sizeof w->steps, "%d", so->density_steps);
        w->words[n++] = "--density-steps";
        w->words[n++] = w->steps;
    }
    if (so->refraction >= 0) {
        w->words[n++] = "--refraction";
        w->words[n++] = so->refraction ? "on" : "off";
    }
    if (so->refractionless >= 0) {
        w->words[n++] = "--refractionless";
        w->words[n++] = so->refractionless ? "on" : "off";
    }
    if (so->no_auto_hierarchy)
        w->words[n++] = "--no-auto-hierarchy";
    if (so->paper)
        w->words[n++] = "--paper";
    snprintf(w->frame, sizeof w->frame, "%ld", frame);
    w->words[n++] = "--frame";
    w->words[n++] = w->frame;
    w->words[n] = NULL;
}

/* Runs argv with stdout and stderr into log; its exit status, or -1. */
static int auto_exec(char *const *argv, const char *log)
{
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
        }
        execv(argv[0], argv);
        fprintf(stderr, "cannot run %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* The last non-empty line of a log, for a refusal. */
static void auto_last_line(const char *log, char *out, size_t cap)
{
    snprintf(out, cap, "no message");
    FILE *f = fopen(log, "r");
    if (!f)
        return;
    char line[1024];
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = 0;
        if (line[0]) {
            size_t n = strlen(line) < cap - 1 ? strlen(line) : cap - 1;
            memcpy(out, line, n);
            out[n] = 0;
        }
    }
    fclose(f);
}

/* The number before (or, after_key: after) key in a log, or -1. */
static double auto_log_number(const char *log, const char *key, int after_key)
{
    FILE *f = fopen(log, "r");
    if (!f)
        return -1;
    char buf[8192];
    double v = -1;
    while (v < 0 && fgets(buf, sizeof buf, f)) {
        const char *k = strstr(buf, key);
        if (!k)
            continue;
        if (after_key) {
            v = strtod(k + strlen(key), NULL);
        } else {
            const char *p = k;
            while (p > buf && p[-1] >= '0' && p[-1] <= '9')
                p--;
            if (p < k)
                v = strtod(p, NULL);
        }
    }
    fclose(f);
    return v;
}

/* argv of one pre-render: prog SCENE [--size WxH] WORDS... extra... NULL. */
static int auto_argv(const struct auto_run *r, char *prog, char **argv, char *size, size_t cap,
                     const char *const *extra)
{
    int n = 0;
    argv[n++] = prog;
    argv[n++] = (char *)r->path;
    if (r->w) {
        snprintf(size, cap, "%dx%d", r->w, r->h);
        argv[n++] = "--size";
        argv[n++] = size;
    }
    for (const char *const *w = r->o->words; w && *w; w++) {
        if (n >= AUTO_MAX_ARGS - 16)
            return -1;
        argv[n++] = (char *)*w;
    }
    for (; *extra; extra++)
        argv[n++] = (char *)*extra;
    argv[n] = NULL;
    return 0;
}

/* links1-ref-<build> at the pre-render size into DIR/<build>[-marked].png.
 * Its exit status (log in DIR/<build>[-marked].log). */
static int auto_host_render(const struct auto_run *r, const char *build, int marked,
                            char *img, char *log, size_t cap)
{
    char prog[PATH_MAX + 32], size[32];
    if (ref_program_path(build, prog, sizeof prog) != 0)
        return -1;
    snprintf(img, cap, "%s/%s%s.png", r->tmp, build, marked ? "-marked" : "");
    snprintf(log, cap, "%s/%s%s.log", r->tmp, build, marked ? "-marked" : "");
    const char *extra[] = {"-o", img, marked ? "--mark-lost" : NULL, NULL};
    char *argv[AUTO_MAX_ARGS];
    if (auto_argv(r, prog, argv, size, sizeof size, extra) != 0)
        return -1;
    return auto_exec(argv, log);
}

/* PSNR of img against the reference, over every pixel and over the pixels
 * painted as lost in marked. */
static void auto_error(const struct image *ref, const struct image *img,
                       const struct image *marked, struct auto_cand *c)
{
    long flagged;
    image_error_flagged(ref, img, marked, &c->psnr, &c->psnr_flagged, &flagged);
}

static int auto_read(const char *path, struct image *img, const struct image *like)
{
    char err[512];
    if (image_read(path, img, err, sizeof err) != 0)
        return -1;
    if (like && (img->width != like->width || img->height != like->height)) {
        image_free(img);
        return -1;
    }
    return 0;
}

/* The host build's pre-render of candidate c (plain and marked). */
static int auto_measure_image(const struct auto_run *r, struct auto_cand *c)
{
    char img[PATH_MAX], log[PATH_MAX], mimg[PATH_MAX], mlog[PATH_MAX];
    int st = auto_host_render(r, c->build, 0, img, log, sizeof img);
    if (st != 0) {
        c->refused = 1;
        auto_last_line(log, c->why, sizeof c->why);
        return st > 0 ? 0 : -1;
    }
    /* a compiled scene cannot be marked: its flagged pixels go unchecked
     * and count as missing the target */
    int compiled = scene_file_ends_with(r->path, ".l1s");
    if (!compiled && auto_host_render(r, c->build, 1, mimg, mlog, sizeof mimg) != 0) {
        auto_last_line(mlog, c->why, sizeof c->why);
        fprintf(stderr, "%s: --arith auto: %s\n", r->prog, c->why);
        return -1;
    }
    double lost = auto_log_number(log, " pixels lost precision", 0);
    struct image a, m;
    if (lost < 0 || auto_read(img, &a, &r->ref) != 0)
        return -1;
    if (auto_read(compiled ? img : mimg, &m, &r->ref) != 0) {
        image_free(&a);
        return -1;
    }
    auto_error(&r->ref, &a, &m, c);
    if (compiled && lost > 0)
        c->psnr_flagged = 0;
    c->lost = (unsigned)lost;
    c->measured = 1;
    image_free(&a);
    image_free(&m);
    return 0;
}

/* NC instructions per pixel of the pre-render on the board with firmware
 * arith (links1 render --count-insns), or -1 after printing why. */
static double auto_board_cost(const struct auto_run *r, const char *arith)
{
    char self[PATH_MAX], size[32], img[PATH_MAX], log[PATH_MAX], ncs[8];
    if (self_sibling("links1", self, sizeof self) < 0)
        return -1;
    const struct machine_limits *m = machine_limits(r->o->machine);
    if (!m) {
        fprintf(stderr, "%s: --arith auto: machine %d unknown\n", r->prog, r->o->machine);
        return -1;
    }
    snprintf(img, sizeof img, "%s/board-%s.png", r->tmp, arith);
    snprintf(log, sizeof log, "%s/board-%s.log", r->tmp, arith);
    snprintf(ncs, sizeof ncs, "%d", ARITH_AUTO_NCS);
    const char *extra[] = {"-o", img, "--arith", arith, "--ncs", ncs, "--machine", m->name,
                           "--count-insns", "--quiet", NULL};
    char *argv[AUTO_MAX_ARGS + 1];
    if (auto_argv(r, "render", argv + 1, size, sizeof size, extra) != 0)
        return -1;
    argv[0] = self; /* links1 render SCENE ... */
    if (auto_exec(argv, log) != 0) {
        char why[300];
        auto_last_line(log, why, sizeof why);
        fprintf(stderr, "%s: --arith auto: the board pre-render with %s failed: %s\n", r->prog,
                arith, why);
        return -1;
    }
    double total = auto_log_number(log, "NCs total ", 1);
    struct image a;
    if (total < 0 || auto_read(img, &a, NULL) != 0) {
        fprintf(stderr, "%s: --arith auto: no instruction count in the board pre-render (%s)\n",
                r->prog, log);
        return -1;
    }
    double pixels = (double)a.width * a.height;
    image_free(&a);
    return total / pixels;
}

/* The candidates for the unit computer: float (with VFP), soft, fixed
 * Q12.19 (the firmware), and on the host every other fixed format built
 * (links1-ref-fixedN next to this program). */
static int auto_candidates(const struct arith_auto_opts *o, struct auto_cand *c)
{
    int n = 0;
    if (o->fpu)
        c[n++] = (struct auto_cand){.label = "float", .build = "float", .arith = "float"};
    c[n++] = (struct auto_cand){.label = "soft", .build = "float", .arith = "soft"};
    snprintf(c[n].label, sizeof c[n].label, "fixed Q%d.%d", 31 - AUTO_FIXED_BITS_BOARD,
             AUTO_FIXED_BITS_BOARD);
    snprintf(c[n].build, sizeof c[n].build, "fixed");
    snprintf(c[n++].arith, sizeof c[0].arith, "fixed");
    for (int f = AUTO_FIXED_BITS_MAX; o->target == ARITH_AUTO_HOST && f >= AUTO_FIXED_BITS_MIN;
         f--) {
        char build[24], prog[PATH_MAX + 32];
        snprintf(build, sizeof build, "fixed%d", f);
        if (f == AUTO_FIXED_BITS_BOARD || ref_program_path(build, prog, sizeof prog) != 0 ||
            access(prog, X_OK) != 0)
            continue;
        c[n] = (struct auto_cand){.arith = "fixed"};
        snprintf(c[n].label, sizeof c[n].label, "fixed Q%d.%d", 31 - f, f);
        snprintf(c[n++].build, sizeof c[0].build, "%s", build);
    }
    for (int i = 0; i < n; i++)
        c[i].cost = -1;
    return n;
}

static int auto_meets(const struct auto_cand *c, double target)
{
    return c->measured && c->psnr >= target && c->psnr_flagged >= target;
}

/* The pre-render size: the render's size scaled to at most
 * ARITH_AUTO_PIXELS, keeping its shape; 0x0 for a compiled scene. */
static int auto_size(struct auto_run *r)
{
    r->w = r->h = 0;
    if (scene_file_ends_with(r->path, ".l1s"))
        return 0;
    int w = r->o->width, h = r->o->height;
    if (!w) {
        struct sd_scene s;
        char err[SD_ERR_MAX];
        if (scene_file_parse(r->path, &s, err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            return -1;
        }
        w = s.view.width;
        h = s.view.height;
        sd_free(&s);
    }
    double k = sqrt((double)ARITH_AUTO_PIXELS / ((double)w * h));
    if (k > 1)
        k = 1;
    r->w = (int)(w * k) > 0 ? (int)(w * k) : 1;
    r->h = (int)(h * k) > 0 ? (int)(h * k) : 1;
    return 0;
}

/* A host build's refusal without its "links1 ref: SCENE: " prefix. */
static const char *auto_refusal(const struct auto_run *r, const char *why)
{
    static const char tool[] = "links1 ref: ";
    size_t n = strlen(r->path);
    if (strncmp(why, tool, sizeof tool - 1) == 0 && strncmp(why + sizeof tool - 1, r->path, n) == 0 &&
        strncmp(why + sizeof tool - 1 + n, ": ", 2) == 0)
        return why + sizeof tool - 1 + n + 2;
    return why;
}

static void auto_print(const struct auto_run *r, const struct auto_cand *c, int n, int pick)
{
    const struct arith_auto_opts *o = r->o;
    const struct machine_limits *m = machine_limits(o->machine);
    printf("%s: --arith auto (%s%s%s, target %.1f dB; pre-render %dx%d against double):",
           r->prog, o->target == ARITH_AUTO_BOARD && m ? m->name : "",
           o->target == ARITH_AUTO_BOARD && m ? " " : "", o->fpu ? "VFP" : "no FPU",
           o->target_db, r->ref.width, r->ref.height);
    for (int i = 0; i < n; i++) {
        printf("%s %s ", i ? ";" : "", c[i].label);
        if (c[i].refused)
            printf("refused (misses the target)");
        else if (c[i].psnr < o->target_db)
            printf("%.1f dB", c[i].psnr);
        else if (c[i].psnr_flagged < o->target_db)
            printf(c[i].psnr_flagged > 0 ? "%.1f dB, %u flagged pixels at %.1f dB"
                                         : "%.1f dB, %u flagged pixels (unchecked in a compiled scene)",
                   c[i].psnr, c[i].lost, c[i].psnr_flagged);
        else
            printf("%.1f dB%s", c[i].psnr, c[i].lost ? " (flagged pixels within target)" : "");
        if (c[i].cost >= 0)
            printf(", %.0f insns/pixel", c[i].cost);
    }
    printf("\n");
    for (int i = 0; i < n; i++)
        if (c[i].refused)
            printf("%s: --arith auto: %s refused the scene: %s\n", r->prog, c[i].label,
                   auto_refusal(r, c[i].why));
    if (pick < 0)
        return;
    double next = -1;
    for (int i = 0; i < n; i++)
        if (i != pick && c[i].cost >= 0 && strcmp(c[i].arith, c[pick].arith) != 0 &&
            (next < 0 || c[i].cost < next))
            next = c[i].cost;
    printf("%s: --arith auto picks %s: the cheapest that keeps %.1f dB (%.1f dB, %.0f NC "
           "instructions per pixel on the board", r->prog, c[pick].label, o->target_db,
           c[pick].psnr, c[pick].cost);
    if (next > 0)
        printf("; the next arithmetic that keeps it costs %.2fx", next / c[pick].cost);
    printf(")\n");
    fflush(stdout);
}

static int auto_choose(struct auto_run *r, struct auto_cand *c, int n)
{
    const struct arith_auto_opts *o = r->o;
    for (int i = 0; i < n; i++) {
        /* soft has float's bits: one host render serves both */
        int same = -1;
        for (int j = 0; j < i; j++)
            if (strcmp(c[j].build, c[i].build) == 0)
                same = j;
        if (same >= 0) {
            struct auto_cand keep = c[i];
            c[i] = c[same];
            memcpy(c[i].label, keep.label, sizeof keep.label);
            memcpy(c[i].arith, keep.arith, sizeof keep.arith);
            c[i].cost = -1;
        } else if (auto_measure_image(r, &c[i]) != 0) {
            fprintf(stderr, "%s: --arith auto: the %s pre-render failed\n", r->prog,
                    c[i].label);
            return -2;
        }
    }
    for (int i = 0; i < n; i++) {
        if (!auto_meets(&c[i], o->target_db))
            continue;
        for (int j = 0; j < i; j++)
            if (strcmp(c[j].arith, c[i].arith) == 0 && c[j].cost >= 0)
                c[i].cost = c[j].cost;
        if (c[i].cost < 0 && (c[i].cost = auto_board_cost(r, c[i].arith)) < 0)
            return -2;
    }
    int pick = -1;
    for (int i = 0; i < n; i++)
        if (c[i].cost >= 0 && (pick < 0 || c[i].cost < c[pick].cost))
            pick = i;
    for (int i = 0; pick >= 0 && i < n; i++)
        if (c[i].cost >= 0 && c[i].cost <= c[pick].cost * (1 + ARITH_AUTO_TIE) &&
            c[i].psnr > c[pick].psnr)
            pick = i;
    return pick;
}

static void auto_cleanup(const char *tmp)
{
    if (tmp_dir_remove(tmp) != 0)
        fprintf(stderr, "links1: could not remove %s: %s\n", tmp, strerror(errno));
}

int arith_auto_pick(const char *prog, const char *path, const struct arith_auto_opts *o,
                    struct arith_auto_choice *out)
{
    char tmp[] = "/tmp/links1-auto-XXXXXX";
    if (!mkdtemp(tmp)) {
        fprintf(stderr, "%s: --arith auto: a temporary directory: %s\n", prog, strerror(errno));
        return -1;
    }
    struct auto_run r = {.prog = prog, .path = path, .tmp = tmp, .o = o};
    struct auto_cand c[AUTO_MAX_CANDS];
    int n = auto_candidates(o, c), pick = -2;
    char img[PATH_MAX], log[PATH_MAX];
    if (auto_size(&r) != 0) {
        auto_cleanup(tmp);
        return -1;
    }
    int st = auto_host_render(&r, "double", 0, img, log, sizeof img);
    if (st != 0 || auto_read(img, &r.ref, NULL) != 0) {
        char why[300];
        auto_last_line(log, why, sizeof why);
        fprintf(stderr, "%s: --arith auto: the double build's pre-render failed: %s\n", prog,
                why);
        auto_cleanup(tmp);
        return -1;
    }
    pick = auto_choose(&r, c, n);
    if (pick > -2)
        auto_print(&r, c, n, pick);
    if (pick == -1)
        fprintf(stderr, "%s: --arith auto: no arithmetic of a unit computer %s keeps %.1f dB "
                "on %s (lower --target-db%s)\n", prog, o->fpu ? "with VFP" : "without an FPU",
                o->target_db, path, o->fpu ? "" : ", or allow --fpu vfp");
    if (pick >= 0) {
        snprintf(out->build, sizeof out->build, "%s", c[pick].build);
        snprintf(out->arith, sizeof out->arith, "%s", c[pick].arith);
        snprintf(out->label, sizeof out->label, "%s", c[pick].label);
    }
    image_free(&r.ref);
    auto_cleanup(tmp);
    return pick >= 0 ? 0 : -1;
}
