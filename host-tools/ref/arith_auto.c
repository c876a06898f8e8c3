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
#include "host-tools/opts/exit_clean.h"
#include "host-tools/opts/tmp_dir.h"
#include "host-tools/ref/ref_program.h"
#include "host-tools/scene/scene_desc.h"
#include "host-tools/scene/scene_file.h"
#include "host-tools/scene/scene_opts.h"
#include "proto/machines.h"
#include "render/render.h"

/* The fixed formats: fixed/num.h takes NUM_FRAC_BITS 8..24 (those that
 * keep NUM_FAR in range build); the firmware is built with its default. */
#define AUTO_FIXED_BITS_BOARD 19
#define AUTO_FIXED_BITS_MIN 8
#define AUTO_FIXED_BITS_MAX 24
#define AUTO_MAX_CANDS (5 + AUTO_FIXED_BITS_MAX - AUTO_FIXED_BITS_MIN) /* 2 escalated */
#define AUTO_MAX_ARGS 48

struct auto_cand {
    char label[24], build[24], arith[8];
    int escalate;        /* --escalate: lost pixels traced again in double */
    int measured;        /* the host build ran (images below valid) */
    int refused;         /* the host build refused the scene (why): it
                            misses the target */
    char why[200];
    double psnr, psnr_flagged;
    unsigned lost;       /* pixels flagged */
    double cost;         /* NC instructions per pixel on the board; < 0: not measured */
    /* --auto: the model of this candidate (-1: the scene's), and the PSNR
     * one rung cheaper in each knob would give (< 0: none tried) */
    int steps;
    double weight;
    double looser_steps_db, looser_weight_db;
    int looser_steps;
    double looser_weight;
    int looser_flagged;  /* looser_weight_db is the PSNR of the flagged pixels there */
    int few_flagged;     /* --auto: under ARITH_AUTO_MIN_FLAGGED of the pixels
                            flagged: judged with the whole image */
    int confirm_tried;   /* --auto: auto_confirm_cheapest took it */
    int confirmed;       /* --auto: its density steps and its images judged at
                            the render's size (auto_confirm_steps): the target
                            is its goal, without the margin */
    int board_refused;   /* the board refused its pre-render (why): out */
    int dearer;          /* --auto: soft beside a float that keeps the target, not
                            counted (float's code, each VFP instruction a call) */
};

struct auto_run {
    const char *prog, *path, *tmp;
    const struct arith_auto_opts *o;
    int w, h;            /* pre-render size; 0: the scene's (a compiled .l1s) */
    int fw, fh;          /* the render's size */
    struct image full_ref; /* --auto: the double build's render at fw x fh (once
                              auto_confirm_steps needs it; width 0 before) */
    int bw, bh;          /* the board pre-render's (the cost): w, h but for --auto */
    struct image ref;    /* the double build's pre-render */
    /* --auto: the scene's density steps and min_weight, and whether it has
     * a density sphere (without one the steps change nothing) */
    int steps0, density;
    double weight0;
    double margin;       /* dB over the target the whole pre-render must reach */
};

/* --auto's rungs: density steps about 1.2x apart, min_weight 2x apart
 * from ARITH_AUTO_REF_WEIGHT to ARITH_AUTO_MAX_WEIGHT. */
static const int auto_steps[] = {2,  3,  4,  5,  6,  8,  10,  12,  14,  16,  18,  20,  24, 28,
                                 32, 36, 40, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256};
#define AUTO_N_STEPS ((int)(sizeof auto_steps / sizeof auto_steps[0]))
#define AUTO_N_WEIGHTS 11 /* 2^-12 .. 2^-2 */

static double auto_weight(int j)
{
    return ldexp(ARITH_AUTO_REF_WEIGHT, j);
}

/* "1/128" for a power of two, else %g */
static const char *auto_weight_name(double w, char *buf, size_t cap)
{
    int e;
    double m = frexp(w, &e);
    if (w > 0 && m == 0.5 && e <= 0)
        snprintf(buf, cap, "1/%.0f", ldexp(1, 1 - e));
    else
        snprintf(buf, cap, "%g", w);
    return buf;
}

/* "--auto" or "--arith auto", for messages */
static const char *auto_name(const struct arith_auto_opts *o)
{
    return o->model ? "--auto" : "--arith auto";
}

int arith_auto_fpu(const char *word)
{
    return strcmp(word, "vfp") == 0 ? 1 : strcmp(word, "none") == 0 ? 0 : -1;
}

void arith_auto_scene_words(const struct scene_file_opts *so, long frame,
                            struct arith_auto_words *w)
{
    int n = scene_opts_words(so, SCENE_OPTS_PRE_RENDER, &w->given);
    memcpy(w->words, w->given.w, (size_t)n * sizeof *w->words);
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
        exit_clean_in_child(); /* it ends with us, even after SIGKILL */
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
        }
        execv(argv[0], argv);
        fprintf(stderr, "cannot run %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    exit_clean_add_child(pid); /* a signal stops it (it cleans up after itself) */
    int st;
    pid_t r;
    while ((r = waitpid(pid, &st, 0)) < 0 && errno == EINTR)
        ;
    exit_clean_drop_child(pid);
    if (r < 0)
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
static int auto_argv(const struct auto_run *r, int board, char *prog, char **argv, char *size,
                     size_t cap, const char *const *extra)
{
    int n = 0;
    argv[n++] = prog;
    argv[n++] = (char *)r->path;
    if (r->w) {
        snprintf(size, cap, "%dx%d", board ? r->bw : r->w, board ? r->bh : r->h);
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

/* The words of a model (--auto): "--density-steps N" when the scene has a
 * density sphere, "--min-weight W"; none for steps < 0. */
struct auto_knob_words {
    const char *w[5];
    char steps[16], weight[40];
};

static void auto_knobs(const struct auto_run *r, int steps, double weight,
                       struct auto_knob_words *k)
{
    int n = 0;
    memset(k->w, 0, sizeof k->w);
    if (steps >= 0 && r->density) {
        snprintf(k->steps, sizeof k->steps, "%d", steps);
        k->w[n++] = "--density-steps";
        k->w[n++] = k->steps;
    }
    if (steps >= 0) {
        snprintf(k->weight, sizeof k->weight, "%.17g", weight);
        k->w[n++] = "--min-weight";
        k->w[n++] = k->weight;
    }
    k->w[n] = NULL;
}

/* links1-ref-<build> at the pre-render size (with the model steps, weight
 * when steps >= 0) into DIR/<build>[-marked].png.  Its exit status (log in
 * DIR/<build>[-marked].log). */
static int auto_host_render_model(const struct auto_run *r, const char *build, int escalate,
                                  int marked, int steps, double weight, char *img, char *log,
                                  size_t cap)
{
    char prog[PATH_MAX + 32], size[32];
    if (ref_program_path(build, prog, sizeof prog) != 0)
        return -1;
    const char *esc = escalate ? "-esc" : "";
    snprintf(img, cap, "%s/%s%s%s.png", r->tmp, build, esc, marked ? "-marked" : "");
    snprintf(log, cap, "%s/%s%s%s.log", r->tmp, build, esc, marked ? "-marked" : "");
    struct auto_knob_words k;
    auto_knobs(r, steps, weight, &k);
    const char *extra[8];
    int e = 0;
    for (const char *const *w = k.w; *w; w++)
        extra[e++] = *w;
    extra[e++] = "-o";
    extra[e++] = img;
    if (marked)
        extra[e++] = "--mark-lost";
    if (escalate)
        extra[e++] = "--escalate";
    extra[e] = NULL;
    char *argv[AUTO_MAX_ARGS];
    if (auto_argv(r, 0, prog, argv, size, sizeof size, extra) != 0)
        return -1;
    return auto_exec(argv, log);
}

static int auto_host_render(const struct auto_run *r, const char *build, int marked,
                            char *img, char *log, size_t cap)
{
    return auto_host_render_model(r, build, 0, marked, -1, 0, img, log, cap);
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
    int st = auto_host_render_model(r, c->build, c->escalate, 0, c->steps, c->weight, img, log,
                                    sizeof img);
    if (st != 0) {
        c->refused = 1;
        auto_last_line(log, c->why, sizeof c->why);
        return st > 0 ? 0 : -1;
    }
    /* a compiled scene cannot be marked: its flagged pixels go unchecked
     * and count as missing the target */
    int compiled = scene_file_ends_with(r->path, ".l1s");
    if (!compiled &&
        auto_host_render_model(r, c->build, c->escalate, 1, c->steps, c->weight, mimg, mlog,
                               sizeof mimg) != 0) {
        auto_last_line(mlog, c->why, sizeof c->why);
        fprintf(stderr, "%s: %s: %s\n", r->prog, auto_name(r->o), c->why);
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
    /* --auto: the flagged pixels hold the arithmetic's error, not the
     * model's: against double with the candidate's model */
    struct image same;
    char dimg[PATH_MAX], dlog[PATH_MAX];
    if (r->o->model && !compiled) {
        double all;
        long flagged;
        if (auto_host_render_model(r, "double", 0, 0, c->steps, c->weight, dimg, dlog,
                                   sizeof dimg) != 0 ||
            auto_read(dimg, &same, &r->ref) != 0) {
            image_free(&a);
            image_free(&m);
            return -1;
        }
        image_error_flagged(&same, &a, &m, &all, &c->psnr_flagged, &flagged);
        image_free(&same);
        c->few_flagged = (double)flagged < ARITH_AUTO_MIN_FLAGGED * a.width * a.height;
    }
    if (compiled && lost > 0)
        c->psnr_flagged = 0;
    c->lost = (unsigned)lost;
    c->measured = 1;
    image_free(&a);
    image_free(&m);
    return 0;
}

/* NC instructions per pixel of the pre-render on the board with firmware
 * arith and the model steps, weight (steps < 0: the scene's) (links1
 * render --count-insns): the one cost of --arith auto and --auto; or -1,
 * after printing why, or with c->board_refused set and c->why the board's
 * reason (a limit of its firmware: the candidate is out). */
static double auto_board_cost(const struct auto_run *r, struct auto_cand *c, int steps,
                              double weight)
{
    const char *arith = c->arith;
    int escalate = c->escalate;
    char self[PATH_MAX], size[32], img[PATH_MAX], log[PATH_MAX], ncs[8];
    if (self_sibling("links1", self, sizeof self) < 0)
        return -1;
    const struct machine_limits *m = machine_limits(r->o->machine);
    if (!m) {
        fprintf(stderr, "%s: %s: machine %d unknown\n", r->prog, auto_name(r->o), r->o->machine);
        return -1;
    }
    snprintf(img, sizeof img, "%s/board-%s%s.png", r->tmp, arith, escalate ? "-esc" : "");
    snprintf(log, sizeof log, "%s/board-%s%s.log", r->tmp, arith, escalate ? "-esc" : "");
    snprintf(ncs, sizeof ncs, "%d", ARITH_AUTO_NCS);
    struct auto_knob_words k;
    auto_knobs(r, steps, weight, &k);
    const char *extra[16] = {"-o", img, "--arith", arith, "--ncs", ncs, "--machine", m->name,
                             "--count-insns", "--quiet"};
    int e = 10;
    if (escalate)
        extra[e++] = "--escalate";
    for (const char *const *w = k.w; *w; w++) /* the model's words, NULL-ended */
        extra[e++] = *w;
    extra[e] = NULL;
    char *argv[AUTO_MAX_ARGS + 1];
    if (auto_argv(r, 1, "render", argv + 1, size, sizeof size, extra) != 0)
        return -1;
    argv[0] = self; /* links1 render SCENE ... */
    if (auto_exec(argv, log) != 0) {
        /* the board's refusal (a limit of its firmware, named): the
         * candidate is out; anything else ends the choice */
        const char says[] = "the board says: ";
        char line[300] = "";
        FILE *f = fopen(log, "r");
        while (f && fgets(line, sizeof line, f) && !strstr(line, says))
            line[0] = 0;
        if (f)
            fclose(f);
        if (strstr(line, says)) {
            line[strcspn(line, "\n")] = 0;
            snprintf(c->why, sizeof c->why, "%s", strstr(line, says) + sizeof says - 1);
            c->board_refused = 1;
            return -1;
        }
        char why[300];
        auto_last_line(log, why, sizeof why);
        fprintf(stderr, "%s: %s: the board pre-render with %s failed: %s\n", r->prog, auto_name(r->o),
                c->label, why);
        return -1;
    }
    double total = auto_log_number(log, "NCs total ", 1);
    struct image a;
    if (total < 0 || auto_read(img, &a, NULL) != 0) {
        fprintf(stderr, "%s: %s: no instruction count in the board pre-render (%s)\n",
                r->prog, auto_name(r->o), log);
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
    c[n] = (struct auto_cand){.build = "fixed", .arith = "fixed"};
    snprintf(c[n++].label, sizeof c[n].label, "fixed Q%d.%d", 31 - AUTO_FIXED_BITS_BOARD,
             AUTO_FIXED_BITS_BOARD);
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
    /* --arith auto: the same two traced again in double where a pixel lost
     * precision (render/wide.h), on a unit with an FPU: the -esc firmware
     * (the virt board's double in its VFP, the an521 boards' in software:
     * the cost on the board says which pays), every host build */
    if (o->fpu && !o->model) {
        c[n++] = (struct auto_cand){.label = "float escalated", .build = "float",
                                    .arith = "float", .escalate = 1};
        c[n] = (struct auto_cand){.build = "fixed", .arith = "fixed", .escalate = 1};
        snprintf(c[n++].label, sizeof c[0].label, "fixed Q%d.%d escalated",
                 31 - AUTO_FIXED_BITS_BOARD, AUTO_FIXED_BITS_BOARD);
    }
    for (int i = 0; i < n; i++) {
        c[i].cost = -1;
        c[i].steps = -1;
        c[i].looser_steps_db = c[i].looser_weight_db = -1;
    }
    return n;
}

/* PSNR of build's pre-render with the model steps, weight against the
 * reference into *db: 0, 1 (the build refused the scene: *db = 0), -1. */
static int auto_model_psnr(const struct auto_run *r, const char *build, int steps, double weight,
                           double *db)
{
    char img[PATH_MAX], log[PATH_MAX];
    *db = 0;
    int st = auto_host_render_model(r, build, 0, 0, steps, weight, img, log, sizeof img);
    if (st != 0)
        return st > 0 ? 1 : -1;
    struct image a;
    if (auto_read(img, &a, &r->ref) != 0)
        return -1;
    struct image_compare_opts co = {0};
    struct image_compare_result cr;
    image_compare(&r->ref, &a, &co, &cr);
    image_free(&a);
    *db = cr.psnr;
    return 0;
}

/* The rung of v in a ladder of n rising values: the first at or above it
 * (the last when none). */
static int auto_rung(double v, const double *ladder, int n)
{
    int i = 0;
    while (i < n - 1 && ladder[i] < v)
        i++;
    return i;
}

/* The rung of min_weight w */
static int auto_rung_weight(double w)
{
    int j = 0;
    while (j < AUTO_N_WEIGHTS - 1 && auto_weight(j) < w)
        j++;
    return j;
}

/* --auto for one candidate: from a model (steps0, weight0: the scene's,
 * or the last candidate's that kept the target), density steps down while
 * the pre-render keeps the target (up until it does), at the lowest
 * min_weight rung; then min_weight up while it keeps it (down until it
 * does).  Sets c->steps, c->weight and the PSNR one rung cheaper in each;
 * a candidate that misses the target at every rung keeps its most
 * accurate model (and misses).  0, or -1 after a failed render. */
static int auto_model_search(const struct auto_run *r, struct auto_cand *c, double target,
                             int steps0, double weight0)
{
    double sl[AUTO_N_STEPS], wl[AUTO_N_WEIGHTS], db = 0;
    for (int i = 0; i < AUTO_N_STEPS; i++)
        sl[i] = auto_steps[i];
    for (int j = 0; j < AUTO_N_WEIGHTS; j++)
        wl[j] = auto_weight(j);
    int i = auto_rung(steps0, sl, AUTO_N_STEPS), st;
    c->looser_steps_db = c->looser_weight_db = -1;
    /* missing the target at the start and at the most accurate model: out */
    int top = r->density ? SCN_MAX_DENSITY_STEPS : r->steps0;
    if ((st = auto_model_psnr(r, c->build, r->density ? auto_steps[i] : top,
                              auto_weight(auto_rung(weight0, wl, AUTO_N_WEIGHTS)), &db)) < 0)
        return -1;
    if ((st != 0 || db < target) &&
        (st = auto_model_psnr(r, c->build, top, wl[0], &db)) <= 0 && (st < 0 || db < target)) {
        c->steps = top;
        c->weight = wl[0];
        return st < 0 ? -1 : 0;
    }
    if (r->density) {
        /* steps first, at the most accurate weight */
        if ((st = auto_model_psnr(r, c->build, auto_steps[i], wl[0], &db)) < 0)
            return -1;
        if (st == 0 && db >= target) {
            while (i > 0) {
                double d;
                if ((st = auto_model_psnr(r, c->build, auto_steps[i - 1], wl[0], &d)) < 0)
                    return -1;
                c->looser_steps = auto_steps[i - 1];
                c->looser_steps_db = d;
                if (st != 0 || d < target)
                    break;
                i--;
            }
        } else {
            while (i < AUTO_N_STEPS - 1 && (st != 0 || db < target)) {
                c->looser_steps = auto_steps[i];
                c->looser_steps_db = db;
                i++;
                if ((st = auto_model_psnr(r, c->build, auto_steps[i], wl[0], &db)) < 0)
                    return -1;
            }
        }
    }
    c->steps = auto_steps[i];
    if (!r->density)
        c->steps = r->steps0;
    int j = auto_rung(weight0, wl, AUTO_N_WEIGHTS);
    if ((st = auto_model_psnr(r, c->build, c->steps, wl[j], &db)) < 0)
        return -1;
    if (st == 0 && db >= target) {
        while (j < AUTO_N_WEIGHTS - 1) {
            double d;
            if ((st = auto_model_psnr(r, c->build, c->steps, wl[j + 1], &d)) < 0)
                return -1;
            c->looser_weight = wl[j + 1];
            c->looser_weight_db = d;
            if (st != 0 || d < target)
                break;
            j++;
        }
    } else {
        while (j > 0 && (st != 0 || db < target)) {
            c->looser_weight = wl[j];
            c->looser_weight_db = db;
            j--;
            if ((st = auto_model_psnr(r, c->build, c->steps, wl[j], &db)) < 0)
                return -1;
        }
    }
    c->weight = wl[j];
    return 0;
}

/* The PSNR the whole pre-render must reach: the target, and with --auto
 * on a pre-render smaller than the render ARITH_AUTO_MARGIN_DB more */
static double auto_goal(const struct auto_run *r)
{
    return r->o->target_db + r->margin;
}

static int auto_meets_goal(const struct auto_cand *c, double goal, double target)
{
    if (c->confirmed)
        goal = target; /* judged at the render's size */
    return c->measured && c->psnr >= goal && (c->psnr_flagged >= target || c->few_flagged);
}

/* --auto on a render larger than its pre-render, with a density sphere:
 * candidate c's density steps judged again at the render's own size, where
 * thin features decide which steps keep the target (their PSNR moves by 1
 * to 2.5 dB between 160x120, 200x150 and 320x240, so the pre-render's
 * margin alone buys up to 1.28x the steps needed: docs/results/
 * arith-auto.md), against the double build's render at that size (made
 * once): from the steps the pre-render found, down the rungs while the
 * render keeps the target (past one rung that misses it: the PSNR of a
 * step count is not monotone), up until it does.  c then holds the render's
 * measures (c->confirmed: judged against the target, no margin).  0, or
 * -1 after a failed render. */
static int auto_confirm_steps(struct auto_run *r, struct auto_cand *c)
{
    struct auto_run full = *r;
    full.w = r->fw;
    full.h = r->fh;
    full.margin = 0;
    if (!r->full_ref.width) {
        char img[PATH_MAX], log[PATH_MAX];
        if (auto_host_render_model(&full, "double", 0, 0, SCN_MAX_DENSITY_STEPS,
                                   ARITH_AUTO_REF_WEIGHT, img, log, sizeof img) != 0 ||
            auto_read(img, &r->full_ref, NULL) != 0)
            return -1;
    }
    full.ref = r->full_ref;
    double target = r->o->target_db;
    int i = 0;
    while (i < AUTO_N_STEPS - 1 && auto_steps[i] < c->steps)
        i++;
    struct auto_cand t = *c;
    t.steps = auto_steps[i];
    t.confirmed = 1;
    if (auto_measure_image(&full, &t) != 0)
        return -1;
    if (t.refused)
        return 0; /* the render's size refused: the pre-render's judgement stands */
    if (auto_meets_goal(&t, target, target)) {
        for (int j = i - 1, missed = 0; j >= 0 && missed < 2; j--) {
            struct auto_cand d = t;
            d.steps = auto_steps[j];
            if (auto_measure_image(&full, &d) != 0)
                return -1;
            if (d.refused || !auto_meets_goal(&d, target, target)) {
                if (!missed++) { /* the rung below the steps kept */
                    t.looser_steps = d.steps;
                    t.looser_steps_db = d.refused ? 0 : d.psnr;
                }
                continue;
            }
            d.looser_steps_db = -1;
            t = d;
            missed = 0;
        }
    } else {
        while (i < AUTO_N_STEPS - 1 && !auto_meets_goal(&t, target, target)) {
            struct auto_cand u = t;
            u.steps = auto_steps[++i];
            if (auto_measure_image(&full, &u) != 0)
                return -1;
            u.looser_steps = t.steps;
            u.looser_steps_db = t.psnr;
            t = u;
            if (t.refused)
                return 0;
        }
    }
    *c = t;
    return 0;
}

/* The scene at r->path parsed, its map images also from below each
 * --textures-from DIR of the words (as the pre-renders read it). */
static int auto_parse(const struct auto_run *r, struct sd_scene *s, char *err, size_t errlen)
{
    const char *from[SD_TEXTURES_FROM_MAX + 1] = {NULL};
    int n = 0;
    for (const char *const *w = r->o->words; w && w[0] && w[1]; w++)
        if (strcmp(w[0], "--textures-from") == 0 && n < SD_TEXTURES_FROM_MAX)
            from[n++] = *++w;
    return scene_file_parse_from(r->path, from, s, err, errlen);
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
        if (auto_parse(r, &s, err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            return -1;
        }
        w = s.view.width;
        h = s.view.height;
        sd_free(&s);
    }
    if (r->o->model) {
        struct sd_scene s;
        char err[SD_ERR_MAX];
        if (auto_parse(r, &s, err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            return -1;
        }
        r->steps0 = s.view.density_steps;
        r->weight0 = s.view.min_weight;
        r->density = 0;
        for (int i = 0; i < s.n_prims; i++)
            r->density |= s.prims[i].kind == SCN_PRIM_DENSITY;
        sd_free(&s);
    }
    for (int board = 0; board < 2; board++) {
        double px = board || !r->o->model ? ARITH_AUTO_PIXELS : ARITH_AUTO_MODEL_PIXELS;
        double k = sqrt(px / ((double)w * h));
        if (k > 1)
            k = 1;
        int kw = (int)(w * k) > 0 ? (int)(w * k) : 1, kh = (int)(h * k) > 0 ? (int)(h * k) : 1;
        *(board ? &r->bw : &r->w) = kw;
        *(board ? &r->bh : &r->h) = kh;
    }
    r->fw = w;
    r->fh = h;
    r->margin = r->o->model && (double)r->w * r->h < (double)w * h ? ARITH_AUTO_MARGIN_DB : 0;
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

/* --auto: " with N density steps, min_weight W" of a candidate */
static void auto_print_model(const struct auto_run *r, const struct auto_cand *c)
{
    char wn[40];
    if (r->density)
        printf(" with %d density steps, min_weight %s", c->steps,
               auto_weight_name(c->weight, wn, sizeof wn));
    else
        printf(" with min_weight %s", auto_weight_name(c->weight, wn, sizeof wn));
}

/* --auto: "; binding: ..." of the pick: the knobs one rung cheaper in
 * which misses the target, the one that misses most first. */
static void auto_print_binding(const struct auto_run *r, const struct auto_cand *p, int n,
                               const struct auto_cand *c)
{
    /* min_weight was judged on the pre-render; density steps too, or at
     * the render's size (confirmed: to the target itself) */
    double t = auto_goal(r), ts = p->confirmed ? r->o->target_db : t;
    int steps = r->density && p->looser_steps_db >= 0 && p->looser_steps_db < ts;
    int weight = p->looser_weight_db >= 0 && p->looser_weight_db < t;
    char wn[40];
    char s_why[96], w_why[96];
    snprintf(s_why, sizeof s_why, "density steps (%d give %.1f dB)", p->looser_steps,
             p->looser_steps_db);
    snprintf(w_why, sizeof w_why,
             p->looser_flagged ? "min_weight (%s leaves flagged pixels at %.1f dB)"
                               : "min_weight (%s gives %.1f dB)",
             auto_weight_name(p->looser_weight, wn, sizeof wn), p->looser_weight_db);
    if (steps && weight) {
        int sf = p->looser_steps_db <= p->looser_weight_db;
        printf("; binding: %s, then %s", sf ? s_why : w_why, sf ? w_why : s_why);
    } else if (steps || weight) {
        printf("; binding: %s", steps ? s_why : w_why);
    } else {
        printf("; binding: no model knob (%s)",
               r->density ? "density steps and min_weight at their cheapest rungs"
                          : "no density sphere; min_weight at its highest rung");
    }
    int missed = 0;
    for (int i = 0; i < n; i++)
        if (strcmp(c[i].arith, p->arith) != 0 &&
            !auto_meets_goal(&c[i], auto_goal(r), r->o->target_db))
            printf("%s%s %s", missed++ ? ", " : "; arithmetic: ", c[i].label,
                   c[i].refused ? "refuses the scene" : "misses the target");
}

static void auto_print(const struct auto_run *r, const struct auto_cand *c, int n, int pick)
{
    const struct arith_auto_opts *o = r->o;
    const struct machine_limits *m = machine_limits(o->machine);
    char wn[40];
    printf("%s: %s (%s%s%s, target %.1f dB", r->prog, auto_name(o),
           o->target == ARITH_AUTO_BOARD && m ? m->name : "",
           o->target == ARITH_AUTO_BOARD && m ? " " : "", o->fpu ? "VFP" : "no FPU",
           o->target_db);
    if (r->margin > 0)
        printf(", %.1f over the whole pre-render, smaller than the render", auto_goal(r));
    printf("; pre-render %dx%d against double", r->ref.width, r->ref.height);
    if (o->model && r->density)
        printf(" at %d density steps, min_weight %s", SCN_MAX_DENSITY_STEPS,
               auto_weight_name(ARITH_AUTO_REF_WEIGHT, wn, sizeof wn));
    else if (o->model)
        printf(" at min_weight %s", auto_weight_name(ARITH_AUTO_REF_WEIGHT, wn, sizeof wn));
    if (r->full_ref.width)
        printf("; density steps judged again at the render's %dx%d against double there, "
               "to the target", r->fw, r->fh);
    printf("):");
    for (int i = 0; i < n; i++) {
        printf("%s %s", i ? ";" : "", c[i].label);
        if (o->model && !c[i].refused)
            auto_print_model(r, &c[i]);
        printf(o->model && !c[i].refused ? ": " : " ");
        if (c[i].refused)
            printf("refused (misses the target)");
        else if (c[i].psnr < (c[i].confirmed ? o->target_db : auto_goal(r)))
            printf("%.1f dB", c[i].psnr);
        else if (c[i].psnr_flagged < o->target_db && c[i].few_flagged)
            printf("%.1f dB (%u flagged pixels at %.1f dB, under %g%%: judged with the whole image)",
                   c[i].psnr, c[i].lost, c[i].psnr_flagged, 100 * ARITH_AUTO_MIN_FLAGGED);
        else if (c[i].psnr_flagged < o->target_db)
            printf(c[i].psnr_flagged > 0 ? "%.1f dB, %u flagged pixels at %.1f dB"
                                         : "%.1f dB, %u flagged pixels (unchecked in a compiled scene)",
                   c[i].psnr, c[i].lost, c[i].psnr_flagged);
        else
            printf("%.1f dB%s", c[i].psnr, c[i].lost ? " (flagged pixels within target)" : "");
        if (c[i].cost >= 0)
            printf(", %.0f insns/pixel", c[i].cost);
        else if (c[i].dearer)
            printf(", not counted (float's code with each VFP instruction a call: dearer)");
        else if (c[i].board_refused)
            printf(", refused by the board: %s", c[i].why);
    }
    printf("\n");
    for (int i = 0; i < n; i++)
        if (c[i].refused)
            printf("%s: %s: %s refused the scene: %s\n", r->prog, auto_name(r->o), c[i].label,
                   auto_refusal(r, c[i].why));
    if (pick < 0)
        return;
    double next = -1;
    for (int i = 0; i < n; i++)
        if (i != pick && c[i].cost >= 0 && strcmp(c[i].arith, c[pick].arith) != 0 &&
            (next < 0 || c[i].cost < next))
            next = c[i].cost;
    printf("%s: %s picks %s", r->prog, auto_name(o), c[pick].label);
    if (o->model)
        auto_print_model(r, &c[pick]);
    printf(": the cheapest that keeps %.1f dB (%.1f dB, %.0f NC "
           "instructions per pixel on the board", o->target_db, c[pick].psnr, c[pick].cost);
    if (next > 0)
        printf("; the next arithmetic that keeps it costs %.2fx", next / c[pick].cost);
    if (o->model)
        auto_print_binding(r, &c[pick], n, c);
    printf(")\n");
    fflush(stdout);
}

/* --auto on a render larger than its pre-render, with a density sphere:
 * the candidates costed on the board, cheapest first, have their steps
 * judged again at the render's size (auto_confirm_steps) and are costed
 * again when they changed, until the next costs more than
 * ARITH_AUTO_CONFIRM_REACH times the cheapest judged so far: the
 * pre-render's margin costs at most a few rungs of steps (1.33x on the
 * density_steps scene), so one that far behind cannot become the
 * cheapest, and it keeps its pre-render judgement.  0, or -1 after a
 * failed render (printed). */
static int auto_confirm_cheapest(struct auto_run *r, struct auto_cand *c, int n)
{
    const struct arith_auto_opts *o = r->o;
    double best = -1;
    for (;;) {
        int k = -1;
        for (int i = 0; i < n; i++)
            if (c[i].cost >= 0 && !c[i].confirm_tried && (k < 0 || c[i].cost < c[k].cost))
                k = i;
        if (k < 0 || (best >= 0 && c[k].cost > ARITH_AUTO_CONFIRM_REACH * best))
            return 0;
        int steps = c[k].steps;
        c[k].confirm_tried = 1;
        if (auto_confirm_steps(r, &c[k]) != 0) {
            fprintf(stderr, "%s: %s: the %s render at %dx%d failed\n", r->prog, auto_name(o),
                    c[k].label, r->fw, r->fh);
            return -1;
        }
        /* not confirmed: the render's size refused it, the pre-render's
         * judgement stands */
        if (c[k].confirmed && !auto_meets_goal(&c[k], auto_goal(r), o->target_db))
            c[k].cost = -1; /* misses at the render's size, at every rung */
        else if (c[k].confirmed && c[k].steps != steps &&
                 (c[k].cost = auto_board_cost(r, &c[k], c[k].steps, c[k].weight)) < 0 &&
                 !c[k].board_refused)
            return -1;
        if (c[k].cost >= 0 && (best < 0 || c[k].cost < best))
            best = c[k].cost;
    }
}

static int auto_choose(struct auto_run *r, struct auto_cand *c, int n)
{
    const struct arith_auto_opts *o = r->o;
    int steps0 = r->steps0;
    double weight0 = r->weight0;
    for (int i = 0; i < n; i++) {
        /* soft has float's bits: one host render serves both */
        int same = -1;
        for (int j = 0; j < i; j++)
            if (strcmp(c[j].build, c[i].build) == 0 && c[j].escalate == c[i].escalate)
                same = j;
        if (same >= 0) {
            struct auto_cand keep = c[i];
            c[i] = c[same];
            memcpy(c[i].label, keep.label, sizeof keep.label);
            memcpy(c[i].arith, keep.arith, sizeof keep.arith);
            c[i].cost = -1;
        } else if ((o->model &&
                    auto_model_search(r, &c[i], auto_goal(r), steps0, weight0) != 0) ||
                   auto_measure_image(r, &c[i]) != 0) {
            fprintf(stderr, "%s: %s: the %s pre-render failed\n", r->prog, auto_name(r->o),
                    c[i].label);
            return -2;
        }
        /* --auto: pixels flagged beyond the target at the weight found (the
         * search looked at the whole image): min_weight down until they
         * keep it */
        for (int j = auto_rung_weight(c[i].weight);
             o->model && j > 0 && c[i].measured && c[i].psnr >= auto_goal(r) &&
             c[i].psnr_flagged < o->target_db && !c[i].few_flagged;
             j--) {
            c[i].looser_weight = c[i].weight;
            c[i].looser_weight_db = c[i].psnr_flagged;
            c[i].looser_flagged = 1;
            c[i].weight = auto_weight(j - 1);
            if (auto_measure_image(r, &c[i]) != 0)
                return -2;
        }
        if (o->model && auto_meets_goal(&c[i], auto_goal(r), o->target_db)) {
            steps0 = c[i].steps; /* the next candidate starts from here */
            weight0 = c[i].weight;
        }
    }
    for (int i = 0; o->model && i < n; i++)
        for (int j = 0; j < n; j++)
            if (strcmp(c[i].arith, "soft") == 0 && strcmp(c[j].arith, "float") == 0 &&
                auto_meets_goal(&c[j], auto_goal(r), o->target_db) && c[j].steps == c[i].steps &&
                c[j].weight == c[i].weight)
                c[i].dearer = 1;
    for (int i = 0; i < n; i++) {
        if (!auto_meets_goal(&c[i], auto_goal(r), o->target_db) || c[i].dearer)
            continue;
        for (int j = 0; j < i; j++)
            if (strcmp(c[j].arith, c[i].arith) == 0 && c[j].escalate == c[i].escalate &&
                c[j].cost >= 0 && c[j].steps == c[i].steps && c[j].weight == c[i].weight)
                c[i].cost = c[j].cost;
        if (c[i].cost < 0 &&
            (c[i].cost = auto_board_cost(r, &c[i], c[i].steps, c[i].weight)) < 0 &&
            !c[i].board_refused)
            return -2;
    }
    if (o->model && r->density && r->margin > 0 && auto_confirm_cheapest(r, c, n) != 0)
        return -2;
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
    char tmp[PATH_MAX];
    if (tmp_dir_make("auto", tmp, sizeof tmp) != 0) {
        fprintf(stderr, "%s: %s: a temporary directory: %s\n", prog, auto_name(o), strerror(errno));
        return -1;
    }
    if (o->model && scene_file_ends_with(path, ".l1s")) {
        fprintf(stderr, "%s: --auto: %s: --auto sets density steps and min_weight, so it needs "
                "a text scene, not a compiled one (or use --arith auto)\n", prog, path);
        auto_cleanup(tmp);
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
    int st = o->model ? auto_host_render_model(&r, "double", 0, 0, SCN_MAX_DENSITY_STEPS,
                                               ARITH_AUTO_REF_WEIGHT, img, log, sizeof img)
                      : auto_host_render(&r, "double", 0, img, log, sizeof img);
    if (st != 0 || auto_read(img, &r.ref, NULL) != 0) {
        char why[300];
        auto_last_line(log, why, sizeof why);
        fprintf(stderr, "%s: %s: the double build's pre-render failed: %s\n", prog, auto_name(o),
                why);
        auto_cleanup(tmp);
        return -1;
    }
    pick = auto_choose(&r, c, n);
    if (pick > -2)
        auto_print(&r, c, n, pick);
    if (pick == -1)
        fprintf(stderr, "%s: %s: no %sarithmetic of a unit computer %s keeps %.1f dB "
                "on %s (lower --target-db%s)\n", prog, auto_name(o), o->model ? "model and " : "",
                o->fpu ? "with VFP" : "without an FPU", o->target_db, path,
                o->fpu ? "" : ", or allow --fpu vfp");
    if (pick >= 0) {
        snprintf(out->build, sizeof out->build, "%s", c[pick].build);
        snprintf(out->arith, sizeof out->arith, "%s", c[pick].arith);
        snprintf(out->label, sizeof out->label, "%s", c[pick].label);
        out->density_steps = o->model && r.density ? c[pick].steps : -1;
        out->min_weight = o->model ? c[pick].weight : -1;
        out->escalate = c[pick].escalate;
    }
    image_free(&r.ref);
    if (r.full_ref.width)
        image_free(&r.full_ref);
    auto_cleanup(tmp);
    return pick >= 0 ? 0 : -1;
}
