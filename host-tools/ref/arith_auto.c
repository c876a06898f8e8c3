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
#define AUTO_SCENE_STEPS (-1) /* a model's steps: the scene's own model (no knob words) */

/* A candidate's life in auto_choose, one stage at a time:
 *
 *   NOT_RUN -> REFUSED                  its host build refused the scene
 *           -> MEASURED                 its host build's images measured
 *   MEASURED -> DEARER                  --auto: soft beside a float that keeps the target
 *            -> BOARD_REFUSED           keeps the goal; the board refused its pre-render
 *            -> COUNTED                 keeps the goal; its cost counted on the board
 *   COUNTED -> CONFIRM_TRIED            --auto on a render larger than its pre-render:
 *                                       auto_confirm_cheapest took it; then, judged at the
 *                                       render's size, it may miss (back to MEASURED) or
 *                                       its new steps be counted (BOARD_REFUSED, or it
 *                                       stays CONFIRM_TRIED)
 *
 * A candidate not counted (MEASURED) misses the goal; COUNTED and
 * CONFIRM_TRIED are the ones with a cost, the pick among them. */
enum auto_cand_state {
    CAND_NOT_RUN,       /* not rendered yet */
    CAND_REFUSED,       /* the host build refused the scene (why): it misses the target */
    CAND_MEASURED,      /* the host build ran: psnr, psnr_flagged, lost hold; not counted */
    CAND_DEARER,        /* --auto: soft beside a float that keeps the target, not
                           counted (float's code, each VFP instruction a call) */
    CAND_BOARD_REFUSED, /* the board refused its pre-render (why): out */
    CAND_COUNTED,       /* cost holds its NC instructions per pixel on the board */
    CAND_CONFIRM_TRIED, /* counted, and auto_confirm_cheapest has taken it */
};

/* The kind of a candidate, and of a host or board render: --escalate
 * (lost pixels traced again in double; the board's -esc firmware) or not */
enum auto_escalation { AUTO_PLAIN, AUTO_ESCALATED };

/* Where a candidate's measures were taken: on the pre-render (the whole
 * image must keep the goal), or at the render's own size
 * (auto_confirm_steps: the target is its goal, without the margin) */
enum auto_judged { AUTO_JUDGED_PRE_RENDER, AUTO_JUDGED_RENDER_SIZE };

/* How a candidate's flagged pixels are judged (--auto): on their own
 * against the target, or, when under ARITH_AUTO_MIN_FLAGGED of the pixels
 * are flagged, with the whole image */
enum auto_flagged_judge { AUTO_FLAGGED_ON_THEIR_OWN, AUTO_FLAGGED_FEW };

/* The pixels a PSNR is over: the whole image, or the flagged ones */
enum auto_psnr_over { AUTO_PSNR_WHOLE, AUTO_PSNR_FLAGGED };

struct auto_cand {
    char label[24], build[24], arith[8];
    enum auto_escalation escalation;
    enum auto_cand_state state;
    char why[200];       /* REFUSED, BOARD_REFUSED: the reason */
    double psnr, psnr_flagged;
    unsigned lost;       /* pixels flagged */
    enum auto_judged judged;
    enum auto_flagged_judge flagged_judge;
    double cost;         /* COUNTED, CONFIRM_TRIED: NC instructions per pixel on the board */
    /* --auto: the model of this candidate (AUTO_SCENE_STEPS: the scene's), and the PSNR
     * one rung cheaper in each knob would give (< 0: none tried) */
    int steps;
    double weight;
    double looser_steps_db, looser_weight_db;
    int looser_steps;
    double looser_weight;
    enum auto_psnr_over looser_weight_over; /* the pixels looser_weight_db is over */
};

/* Its host build's images measured (psnr, psnr_flagged, lost hold) */
static int auto_has_images(const struct auto_cand *c)
{
    return c->state != CAND_NOT_RUN && c->state != CAND_REFUSED;
}

/* Its cost on the board counted (cost holds) */
static int auto_counted(const struct auto_cand *c)
{
    return c->state == CAND_COUNTED || c->state == CAND_CONFIRM_TRIED;
}

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

/* The words of a model (--auto): its density steps when the scene has a
 * density sphere, its min_weight (scene_opts_words); none for steps < 0,
 * the scene's own model. */
static void auto_knobs(const struct auto_run *r, int steps, double weight,
                       struct scene_opts_words *k)
{
    struct scene_file_opts so;
    scene_file_opts_init(&so);
    if (steps >= 0) {
        so.min_weight = weight;
        so.density_steps = r->density ? steps : -1;
    }
    scene_opts_words(&so, SCENE_OPTS_ALL, k);
}

/* --mark-lost: the pixels that lost precision painted, or not */
enum auto_marking { AUTO_UNMARKED, AUTO_MARKED };

/* One host pre-render: links1-ref-<build>, plain or --escalate, marked or
 * not, with the model steps, weight (density steps and min_weight; none
 * for AUTO_SCENE_STEPS) */
struct auto_render {
    const char *build;
    enum auto_escalation escalation;
    enum auto_marking marking;
    int steps;
    double weight;
};

/* The pre-render how asks for at the pre-render size into
 * DIR/<build>[-esc][-marked].png.  Its exit status (log in
 * DIR/<build>[-esc][-marked].log). */
static int auto_host_render(const struct auto_run *r, const struct auto_render *how, char *img,
                            char *log, size_t cap)
{
    char prog[PATH_MAX + 32], size[32];
    if (ref_program_path(how->build, prog, sizeof prog) != 0)
        return -1;
    const char *esc = how->escalation == AUTO_ESCALATED ? "-esc" : "";
    const char *marked = how->marking == AUTO_MARKED ? "-marked" : "";
    snprintf(img, cap, "%s/%s%s%s.png", r->tmp, how->build, esc, marked);
    snprintf(log, cap, "%s/%s%s%s.log", r->tmp, how->build, esc, marked);
    struct scene_opts_words k;
    auto_knobs(r, how->steps, how->weight, &k);
    const char *extra[12]; /* the knobs (at most 4), -o IMG, --mark-lost, the escalation, NULL */
    int e = 0;
    for (const char *const *w = k.w; *w; w++)
        extra[e++] = *w;
    extra[e++] = "-o";
    extra[e++] = img;
    if (how->marking == AUTO_MARKED)
        extra[e++] = "--mark-lost";
    extra[e++] = how->escalation == AUTO_ESCALATED ? "--escalate" : "--no-escalate";
    extra[e] = NULL;
    char *argv[AUTO_MAX_ARGS];
    if (auto_argv(r, 0, prog, argv, size, sizeof size, extra) != 0)
        return -1;
    return auto_exec(argv, log);
}

/* The double build's pre-render the candidates are judged against: with
 * --auto at the most accurate model, else at the scene's.  As
 * auto_host_render. */
static int auto_ref_render(const struct auto_run *r, char *img, char *log, size_t cap)
{
    struct auto_render ref = {.build = "double", .escalation = AUTO_PLAIN,
                              .marking = AUTO_UNMARKED, .steps = AUTO_SCENE_STEPS, .weight = 0};
    if (r->o->model) {
        ref.steps = SCN_MAX_DENSITY_STEPS;
        ref.weight = ARITH_AUTO_REF_WEIGHT;
    }
    return auto_host_render(r, &ref, img, log, cap);
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

/* --auto: the flagged pixels (marked in m) hold the arithmetic's error,
 * not the model's: c's PSNR over them (its image a) against double with
 * c's model, and whether they are few enough for the whole image to judge
 * them.  0, or -1 after a failed render. */
static int auto_flagged_model(const struct auto_run *r, struct auto_cand *c,
                              const struct image *a, const struct image *m)
{
    struct auto_render model = {.build = "double", .escalation = AUTO_PLAIN,
                                .marking = AUTO_UNMARKED, .steps = c->steps, .weight = c->weight};
    char dimg[PATH_MAX], dlog[PATH_MAX];
    struct image same;
    if (auto_host_render(r, &model, dimg, dlog, sizeof dimg) != 0 ||
        auto_read(dimg, &same, &r->ref) != 0)
        return -1;
    double all;
    long flagged;
    image_error_flagged(&same, a, m, &all, &c->psnr_flagged, &flagged);
    image_free(&same);
    c->flagged_judge = (double)flagged < ARITH_AUTO_MIN_FLAGGED * a->width * a->height
                           ? AUTO_FLAGGED_FEW
                           : AUTO_FLAGGED_ON_THEIR_OWN;
    return 0;
}

/* The host build's pre-render of candidate c (plain and marked): c
 * MEASURED, or REFUSED (why) when the build refused the scene.  0, or -1
 * after a failed render. */
static int auto_measure_image(const struct auto_run *r, struct auto_cand *c)
{
    char img[PATH_MAX], log[PATH_MAX], mimg[PATH_MAX], mlog[PATH_MAX];
    struct auto_render how = {.build = c->build, .escalation = c->escalation,
                              .marking = AUTO_UNMARKED, .steps = c->steps, .weight = c->weight};
    int st = auto_host_render(r, &how, img, log, sizeof img);
    if (st != 0) {
        c->state = CAND_REFUSED;
        auto_last_line(log, c->why, sizeof c->why);
        return st > 0 ? 0 : -1;
    }
    /* a compiled scene cannot be marked: its flagged pixels go unchecked
     * and count as missing the target */
    int compiled = scene_file_ends_with(r->path, ".l1s");
    how.marking = AUTO_MARKED;
    if (!compiled && auto_host_render(r, &how, mimg, mlog, sizeof mimg) != 0) {
        auto_last_line(mlog, c->why, sizeof c->why);
        fprintf(stderr, "%s: %s: %s\n", r->prog, auto_name(r->o), c->why);
        return -1;
    }
    double lost = auto_log_number(log, " pixels in doubt", 0);
    struct image a, m;
    if (lost < 0 || auto_read(img, &a, &r->ref) != 0)
        return -1;
    if (auto_read(compiled ? img : mimg, &m, &r->ref) != 0) {
        image_free(&a);
        return -1;
    }
    auto_error(&r->ref, &a, &m, c);
    st = r->o->model && !compiled ? auto_flagged_model(r, c, &a, &m) : 0;
    image_free(&a);
    image_free(&m);
    if (st != 0)
        return -1;
    if (compiled && lost > 0)
        c->psnr_flagged = 0;
    c->lost = (unsigned)lost;
    c->state = CAND_MEASURED;
    return 0;
}

/* The board's refusal of a pre-render (a limit of its firmware, named
 * after "the board says: ") in its log, into why.  0, or -1 for none. */
static int auto_board_refusal(const char *log, char *why, size_t cap)
{
    const char says[] = "the board says: ";
    char line[300] = "";
    FILE *f = fopen(log, "r");
    while (f && fgets(line, sizeof line, f) && !strstr(line, says))
        line[0] = 0;
    if (f)
        fclose(f);
    if (!strstr(line, says))
        return -1;
    line[strcspn(line, "\n")] = 0;
    snprintf(why, cap, "%s", strstr(line, says) + sizeof says - 1);
    return 0;
}

/* Candidate c counted: NC instructions per pixel of the pre-render on the
 * board with its firmware and model (links1 render --count-insns), the one
 * cost of --arith auto and --auto, into c->cost, and c in state counted;
 * or c BOARD_REFUSED with c->why the board's reason (a limit of its
 * firmware: the candidate is out).  0, or -1 after printing why. */
static int auto_board_cost(const struct auto_run *r, struct auto_cand *c,
                           enum auto_cand_state counted)
{
    const char *esc = c->escalation == AUTO_ESCALATED ? "-esc" : "";
    char self[PATH_MAX], size[32], img[PATH_MAX], log[PATH_MAX], ncs[8];
    if (self_sibling("links1", self, sizeof self) < 0)
        return -1;
    const struct machine_limits *m = machine_limits(r->o->machine);
    if (!m) {
        fprintf(stderr, "%s: %s: machine %d unknown\n", r->prog, auto_name(r->o), r->o->machine);
        return -1;
    }
    snprintf(img, sizeof img, "%s/board-%s%s.png", r->tmp, c->arith, esc);
    snprintf(log, sizeof log, "%s/board-%s%s.log", r->tmp, c->arith, esc);
    snprintf(ncs, sizeof ncs, "%d", ARITH_AUTO_NCS);
    struct scene_opts_words k;
    auto_knobs(r, c->steps, c->weight, &k);
    const char *extra[16] = {"-o", img, "--arith", c->arith, "--ncs", ncs, "--machine", m->name,
                             "--count-insns", "--quiet"};
    int e = 10;
    extra[e++] = c->escalation == AUTO_ESCALATED ? "--escalate" : "--no-escalate";
    for (const char *const *w = k.w; *w; w++) /* the model's words, NULL-ended */
        extra[e++] = *w;
    extra[e] = NULL;
    char *argv[AUTO_MAX_ARGS + 1];
    if (auto_argv(r, 1, "render", argv + 1, size, sizeof size, extra) != 0)
        return -1;
    argv[0] = self; /* links1 render SCENE ... */
    if (auto_exec(argv, log) != 0) {
        /* the board's refusal: the candidate is out; anything else ends the choice */
        if (auto_board_refusal(log, c->why, sizeof c->why) == 0) {
            c->state = CAND_BOARD_REFUSED;
            return 0;
        }
        char why[300];
        auto_last_line(log, why, sizeof why);
        fprintf(stderr, "%s: %s: the board pre-render with %s failed: %s\n", r->prog,
                auto_name(r->o), c->label, why);
        return -1;
    }
    double total = auto_log_number(log, "NCs total ", 1);
    struct image a;
    if (total < 0 || auto_read(img, &a, NULL) != 0) {
        fprintf(stderr, "%s: %s: no instruction count in the board pre-render (%s)\n",
                r->prog, auto_name(r->o), log);
        return -1;
    }
    c->cost = total / ((double)a.width * a.height);
    c->state = counted;
    image_free(&a);
    return 0;
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
    /* the same two traced again in double where a pixel lost precision
     * (render/wide.h), on a unit with an FPU: the -esc firmware (the virt
     * board's double in its VFP, the an521 boards' in software: the cost
     * on the board says which pays), every host build */
    if (o->fpu) {
        c[n++] = (struct auto_cand){.label = "float escalated", .build = "float",
                                    .arith = "float", .escalation = AUTO_ESCALATED};
        c[n] = (struct auto_cand){.build = "fixed", .arith = "fixed",
                                  .escalation = AUTO_ESCALATED};
        snprintf(c[n++].label, sizeof c[0].label, "fixed Q%d.%d escalated",
                 31 - AUTO_FIXED_BITS_BOARD, AUTO_FIXED_BITS_BOARD);
    }
    for (int i = 0; i < n; i++) {
        c[i].state = CAND_NOT_RUN;
        c[i].judged = AUTO_JUDGED_PRE_RENDER;
        c[i].flagged_judge = AUTO_FLAGGED_ON_THEIR_OWN;
        c[i].steps = AUTO_SCENE_STEPS;
        c[i].looser_steps_db = c[i].looser_weight_db = -1;
    }
    return n;
}

/* PSNR of candidate c's pre-render (its build, escalated or not) with the
 * model steps, weight against the reference into *db: 0, 1 (the build
 * refused the scene: *db = 0), -1. */
static int auto_model_psnr(const struct auto_run *r, const struct auto_cand *c, int steps,
                           double weight, double *db)
{
    char img[PATH_MAX], log[PATH_MAX];
    *db = 0;
    struct auto_render how = {.build = c->build, .escalation = c->escalation,
                              .marking = AUTO_UNMARKED, .steps = steps, .weight = weight};
    int st = auto_host_render(r, &how, img, log, sizeof img);
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
    if ((st = auto_model_psnr(r, c, r->density ? auto_steps[i] : top,
                              auto_weight(auto_rung(weight0, wl, AUTO_N_WEIGHTS)), &db)) < 0)
        return -1;
    if ((st != 0 || db < target) &&
        (st = auto_model_psnr(r, c, top, wl[0], &db)) <= 0 && (st < 0 || db < target)) {
        c->steps = top;
        c->weight = wl[0];
        return st < 0 ? -1 : 0;
    }
    if (r->density) {
        /* steps first, at the most accurate weight */
        if ((st = auto_model_psnr(r, c, auto_steps[i], wl[0], &db)) < 0)
            return -1;
        if (st == 0 && db >= target) {
            while (i > 0) {
                double d;
                if ((st = auto_model_psnr(r, c, auto_steps[i - 1], wl[0], &d)) < 0)
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
                if ((st = auto_model_psnr(r, c, auto_steps[i], wl[0], &db)) < 0)
                    return -1;
            }
        }
    }
    c->steps = auto_steps[i];
    if (!r->density)
        c->steps = r->steps0;
    int j = auto_rung(weight0, wl, AUTO_N_WEIGHTS);
    if ((st = auto_model_psnr(r, c, c->steps, wl[j], &db)) < 0)
        return -1;
    if (st == 0 && db >= target) {
        while (j < AUTO_N_WEIGHTS - 1) {
            double d;
            if ((st = auto_model_psnr(r, c, c->steps, wl[j + 1], &d)) < 0)
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
            if ((st = auto_model_psnr(r, c, c->steps, wl[j], &db)) < 0)
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

/* c's images keep goal over the whole image (target, judged at the
 * render's size) and target over its flagged pixels (unless few) */
static int auto_meets_goal(const struct auto_cand *c, double goal, double target)
{
    if (c->judged == AUTO_JUDGED_RENDER_SIZE)
        goal = target;
    return auto_has_images(c) && c->psnr >= goal &&
           (c->psnr_flagged >= target || c->flagged_judge == AUTO_FLAGGED_FEW);
}

/* The run at the render's own size (auto_confirm_steps), against the
 * double build's render there (made once, into r->full_ref).  0, or -1
 * after a failed render. */
static int auto_full_run(struct auto_run *r, struct auto_run *full)
{
    *full = *r;
    full->w = r->fw;
    full->h = r->fh;
    full->margin = 0;
    if (!r->full_ref.width) {
        char img[PATH_MAX], log[PATH_MAX];
        if (auto_ref_render(full, img, log, sizeof img) != 0 ||
            auto_read(img, &r->full_ref, NULL) != 0)
            return -1;
    }
    full->ref = r->full_ref;
    return 0;
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
 * measures (c->judged AUTO_JUDGED_RENDER_SIZE: against the target, no
 * margin), and keeps its state.  0, or -1 after a failed render. */
static int auto_confirm_steps(struct auto_run *r, struct auto_cand *c)
{
    struct auto_run full;
    if (auto_full_run(r, &full) != 0)
        return -1;
    double target = r->o->target_db;
    int i = 0;
    while (i < AUTO_N_STEPS - 1 && auto_steps[i] < c->steps)
        i++;
    struct auto_cand t = *c;
    t.steps = auto_steps[i];
    t.judged = AUTO_JUDGED_RENDER_SIZE;
    if (auto_measure_image(&full, &t) != 0)
        return -1;
    if (t.state == CAND_REFUSED)
        return 0; /* the render's size refused: the pre-render's judgement stands */
    if (auto_meets_goal(&t, target, target)) {
        for (int j = i - 1, missed = 0; j >= 0 && missed < 2; j--) {
            struct auto_cand d = t;
            d.steps = auto_steps[j];
            if (auto_measure_image(&full, &d) != 0)
                return -1;
            if (d.state == CAND_REFUSED || !auto_meets_goal(&d, target, target)) {
                if (!missed++) { /* the rung below the steps kept */
                    t.looser_steps = d.steps;
                    t.looser_steps_db = d.state == CAND_REFUSED ? 0 : d.psnr;
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
            if (t.state == CAND_REFUSED)
                return 0;
        }
    }
    t.state = c->state; /* measured at the render's size: the stage it was in */
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
     * the render's size (to the target itself) */
    double t = auto_goal(r), ts = p->judged == AUTO_JUDGED_RENDER_SIZE ? r->o->target_db : t;
    int steps = r->density && p->looser_steps_db >= 0 && p->looser_steps_db < ts;
    int weight = p->looser_weight_db >= 0 && p->looser_weight_db < t;
    char wn[40];
    char s_why[96], w_why[96];
    snprintf(s_why, sizeof s_why, "density steps (%d give %.1f dB)", p->looser_steps,
             p->looser_steps_db);
    snprintf(w_why, sizeof w_why,
             p->looser_weight_over == AUTO_PSNR_FLAGGED
                 ? "min_weight (%s leaves flagged pixels at %.1f dB)"
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
                   c[i].state == CAND_REFUSED ? "refuses the scene" : "misses the target");
}

/* The first line's opening: the machine, the target, the pre-render */
static void auto_print_head(const struct auto_run *r)
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
}

/* One candidate of the first line: " LABEL[ MODEL]: PSNR, COST" */
static void auto_print_cand(const struct auto_run *r, const struct auto_cand *c)
{
    const struct arith_auto_opts *o = r->o;
    int refused = c->state == CAND_REFUSED;
    printf(" %s", c->label);
    if (o->model && !refused)
        auto_print_model(r, c);
    printf(o->model && !refused ? ": " : " ");
    if (refused)
        printf("refused (misses the target)");
    else if (c->psnr < (c->judged == AUTO_JUDGED_RENDER_SIZE ? o->target_db : auto_goal(r)))
        printf("%.1f dB", c->psnr);
    else if (c->psnr_flagged < o->target_db && c->flagged_judge == AUTO_FLAGGED_FEW)
        printf("%.1f dB (%u flagged pixels at %.1f dB, under %g%%: judged with the whole image)",
               c->psnr, c->lost, c->psnr_flagged, 100 * ARITH_AUTO_MIN_FLAGGED);
    else if (c->psnr_flagged < o->target_db)
        printf(c->psnr_flagged > 0 ? "%.1f dB, %u flagged pixels at %.1f dB"
                                   : "%.1f dB, %u flagged pixels (unchecked in a compiled scene)",
               c->psnr, c->lost, c->psnr_flagged);
    else
        printf("%.1f dB%s", c->psnr, c->lost ? " (flagged pixels within target)" : "");
    if (auto_counted(c))
        printf(", %.0f insns/pixel", c->cost);
    else if (c->state == CAND_DEARER)
        printf(", not counted (float's code with each VFP instruction a call: dearer)");
    else if (c->state == CAND_BOARD_REFUSED)
        printf(", refused by the board: %s", c->why);
}

static void auto_print(const struct auto_run *r, const struct auto_cand *c, int n, int pick)
{
    const struct arith_auto_opts *o = r->o;
    auto_print_head(r);
    for (int i = 0; i < n; i++) {
        printf("%s", i ? ";" : "");
        auto_print_cand(r, &c[i]);
    }
    printf("\n");
    for (int i = 0; i < n; i++)
        if (c[i].state == CAND_REFUSED)
            printf("%s: %s: %s refused the scene: %s\n", r->prog, auto_name(r->o), c[i].label,
                   auto_refusal(r, c[i].why));
    if (pick < 0)
        return;
    double next = -1;
    for (int i = 0; i < n; i++)
        if (i != pick && auto_counted(&c[i]) && strcmp(c[i].arith, c[pick].arith) != 0 &&
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
            if (c[i].state == CAND_COUNTED && (k < 0 || c[i].cost < c[k].cost))
                k = i;
        if (k < 0 || (best >= 0 && c[k].cost > ARITH_AUTO_CONFIRM_REACH * best))
            return 0;
        int steps = c[k].steps;
        c[k].state = CAND_CONFIRM_TRIED;
        if (auto_confirm_steps(r, &c[k]) != 0) {
            fprintf(stderr, "%s: %s: the %s render at %dx%d failed\n", r->prog, auto_name(o),
                    c[k].label, r->fw, r->fh);
            return -1;
        }
        /* judged at the pre-render only: the render's size refused it, the
         * pre-render's judgement stands */
        int full = c[k].judged == AUTO_JUDGED_RENDER_SIZE;
        if (full && !auto_meets_goal(&c[k], auto_goal(r), o->target_db))
            c[k].state = CAND_MEASURED; /* misses at the render's size, at every rung */
        else if (full && c[k].steps != steps &&
                 auto_board_cost(r, &c[k], CAND_CONFIRM_TRIED) != 0)
            return -1;
        if (auto_counted(&c[k]) && (best < 0 || c[k].cost < best))
            best = c[k].cost;
    }
}

/* --auto: pixels of candidate c flagged beyond the target at the weight
 * found (the search looked at the whole image): min_weight down until they
 * keep it.  0, or -1 after a failed render. */
static int auto_flagged_weight(const struct auto_run *r, struct auto_cand *c)
{
    for (int j = auto_rung_weight(c->weight);
         j > 0 && auto_has_images(c) && c->psnr >= auto_goal(r) &&
         c->psnr_flagged < r->o->target_db && c->flagged_judge == AUTO_FLAGGED_ON_THEIR_OWN;
         j--) {
        c->looser_weight = c->weight;
        c->looser_weight_db = c->psnr_flagged;
        c->looser_weight_over = AUTO_PSNR_FLAGGED;
        c->weight = auto_weight(j - 1);
        if (auto_measure_image(r, c) != 0)
            return -1;
    }
    return 0;
}

/* Every candidate NOT_RUN to MEASURED or REFUSED by its host build (with
 * --auto its model searched first).  0, or -1 after a failed render. */
static int auto_measure_all(const struct auto_run *r, struct auto_cand *c, int n)
{
    const struct arith_auto_opts *o = r->o;
    int steps0 = r->steps0;
    double weight0 = r->weight0;
    for (int i = 0; i < n; i++) {
        /* soft has float's bits: one host render serves both */
        int same = -1;
        for (int j = 0; j < i; j++)
            if (strcmp(c[j].build, c[i].build) == 0 && c[j].escalation == c[i].escalation)
                same = j;
        if (same >= 0) {
            struct auto_cand keep = c[i];
            c[i] = c[same];
            memcpy(c[i].label, keep.label, sizeof keep.label);
            memcpy(c[i].arith, keep.arith, sizeof keep.arith);
        } else if ((o->model &&
                    auto_model_search(r, &c[i], auto_goal(r), steps0, weight0) != 0) ||
                   auto_measure_image(r, &c[i]) != 0) {
            fprintf(stderr, "%s: %s: the %s pre-render failed\n", r->prog, auto_name(r->o),
                    c[i].label);
            return -1;
        }
        if (o->model && auto_flagged_weight(r, &c[i]) != 0)
            return -1;
        if (o->model && auto_meets_goal(&c[i], auto_goal(r), o->target_db)) {
            steps0 = c[i].steps; /* the next candidate starts from here */
            weight0 = c[i].weight;
        }
    }
    return 0;
}

/* The MEASURED candidates that keep the goal COUNTED on the board (or
 * BOARD_REFUSED); one of the same firmware and model counted before gives
 * its cost.  0, or -1 after printing why. */
static int auto_count_all(const struct auto_run *r, struct auto_cand *c, int n)
{
    for (int i = 0; i < n; i++) {
        if (c[i].state != CAND_MEASURED ||
            !auto_meets_goal(&c[i], auto_goal(r), r->o->target_db))
            continue;
        for (int j = 0; j < i; j++)
            if (strcmp(c[j].arith, c[i].arith) == 0 && c[j].escalation == c[i].escalation &&
                auto_counted(&c[j]) && c[j].steps == c[i].steps && c[j].weight == c[i].weight) {
                c[i].cost = c[j].cost;
                c[i].state = CAND_COUNTED;
            }
        if (!auto_counted(&c[i]) && auto_board_cost(r, &c[i], CAND_COUNTED) != 0)
            return -1;
    }
    return 0;
}

/* The cheapest counted candidate; among those within ARITH_AUTO_TIE of
 * it, the most accurate.  -1: none. */
static int auto_cheapest(const struct auto_cand *c, int n)
{
    int pick = -1;
    for (int i = 0; i < n; i++)
        if (auto_counted(&c[i]) && (pick < 0 || c[i].cost < c[pick].cost))
            pick = i;
    for (int i = 0; pick >= 0 && i < n; i++)
        if (auto_counted(&c[i]) && c[i].cost <= c[pick].cost * (1 + ARITH_AUTO_TIE) &&
            c[i].psnr > c[pick].psnr)
            pick = i;
    return pick;
}

/* Candidate c's life (enum auto_cand_state) for each of the n: the pick,
 * -1 for none, or -2 after a failed render (printed). */
static int auto_choose(struct auto_run *r, struct auto_cand *c, int n)
{
    const struct arith_auto_opts *o = r->o;
    if (auto_measure_all(r, c, n) != 0)
        return -2;
    /* --auto: soft beside a float of the same model that keeps the target */
    for (int i = 0; o->model && i < n; i++)
        for (int j = 0; j < n; j++)
            if (c[i].state == CAND_MEASURED && strcmp(c[i].arith, "soft") == 0 &&
                strcmp(c[j].arith, "float") == 0 &&
                auto_meets_goal(&c[j], auto_goal(r), o->target_db) && c[j].steps == c[i].steps &&
                c[j].weight == c[i].weight)
                c[i].state = CAND_DEARER;
    if (auto_count_all(r, c, n) != 0)
        return -2;
    if (o->model && r->density && r->margin > 0 && auto_confirm_cheapest(r, c, n) != 0)
        return -2;
    return auto_cheapest(c, n);
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
    if (auto_ref_render(&r, img, log, sizeof img) != 0 || auto_read(img, &r.ref, NULL) != 0) {
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
        out->escalate = c[pick].escalation == AUTO_ESCALATED;
    }
    image_free(&r.ref);
    if (r.full_ref.width)
        image_free(&r.full_ref);
    auto_cleanup(tmp);
    return pick >= 0 ? 0 : -1;
}
