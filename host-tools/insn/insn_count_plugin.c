/* insn_count_plugin.c: a QEMU TCG plugin that counts the guest instructions
 * each emulated core executes, for deterministic cost figures (wall-clock
 * time on a shared host cannot show a many-core speed-up).
 *
 *   qemu-system-arm ... -plugin build/insn-count.so,out=FILE
 *
 * At exit it writes one line "vcpu K INSNS" per vCPU to FILE (or to QEMU's
 * log when out= is not given).  Counting is per translated block: when a
 * block runs, its instruction count is added to the running vCPU's total.  A
 * block left early by an exception is counted whole, so counts of faulting
 * code are a slight over-estimate; a core asleep in WFI counts nothing.
 * A core that executes the marker of proto/insn_mark.h starts again from
 * zero (the rest of that block goes uncounted: a few instructions).
 *
 * With series=FILE,every=MS a thread of the plugin also appends, every MS
 * milliseconds while QEMU runs, one line "at T C0 C1 ... CN-1": T the
 * host's CLOCK_MONOTONIC in milliseconds, Ck vCPU k's count then.  Without
 * icount QEMU runs the guest's generic timer from that same clock, so the
 * difference of two lines is what each core retired over that span of guest
 * time (links1 selftest idle reads it while the board runs).
 *
 * With trace=FILE every trace mark of proto/insn_mark.h a core executes is
 * kept, in order, with the core's count then; at exit FILE gets one line
 * "K KIND COUNT" per mark (vCPU K, enum insn_mark_trace_kind), vCPU by
 * vCPU.  Counts are taken at block entry, so a mark's count includes the
 * rest of its block; the difference of two marks' counts is exact to
 * within the blocks they sit in, and differences of successive marks add
 * up to the difference of the first and last (links1 render --trace).
 *
 * With profile=FILE (and profile_from=K, and profile_to=L) the
 * instructions of vCPUs K to L (from K on when no L; none when L < K)
 * are also counted per translated block: at exit FILE gets one line
 * "ADDR COUNT" per block start address that ran (hexadecimal guest address,
 * instructions executed in blocks starting there, retranslations summed),
 * which the firmware's symbol table attributes to functions (links1 render
 * --insn-profile, tests/bench/bench_insn_funcs.sh).
 *
 * Every FILE is made new (O_CREAT | O_EXCL | O_NOFOLLOW, mode 0600): a file
 * or a link already at that name is refused, never written through.  links1
 * names files in a private directory it made for the run (tmp_dir_make).
 */
#include <fcntl.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "proto/units.h"
#include "proto/insn_mark.h"

/* The per-vCPU table: one entry per core the board can have. */
#define INSN_COUNT_MAX_VCPUS UNITS_MAX_CORES

/* ---- QEMU 7.2 plugin API, version 1 ----
 * Debian ships no qemu-plugin.h, so the few types and functions used here
 * are declared from the documented API.  QEMU resolves the functions when it
 * loads the plugin. */
#define PLUGIN_EXPORT __attribute__((visibility("default")))
typedef uint64_t qemu_plugin_id_t;
struct qemu_plugin_tb;
typedef struct qemu_info_t {
    const char *target_name;
    struct {
        int min;
        int cur;
    } version;
    bool system_emulation;
    union {
        struct {
            int smp_vcpus;
            int max_vcpus;
        } system;
    };
} qemu_info_t;
enum qemu_plugin_cb_flags {
    QEMU_PLUGIN_CB_NO_REGS,
    QEMU_PLUGIN_CB_R_REGS,
    QEMU_PLUGIN_CB_RW_REGS,
};
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void *userdata);
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id,
                                           qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_cb(struct qemu_plugin_tb *tb,
                                          qemu_plugin_vcpu_udata_cb_t cb,
                                          enum qemu_plugin_cb_flags flags, void *userdata);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
uint64_t qemu_plugin_tb_vaddr(const struct qemu_plugin_tb *tb);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb,
                                    void *userdata);
void qemu_plugin_outs(const char *string);
struct qemu_plugin_insn;
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb, size_t idx);
const void *qemu_plugin_insn_data(const struct qemu_plugin_insn *insn);
size_t qemu_plugin_insn_size(const struct qemu_plugin_insn *insn);
void qemu_plugin_register_vcpu_insn_exec_cb(struct qemu_plugin_insn *insn,
                                            qemu_plugin_vcpu_udata_cb_t cb,
                                            enum qemu_plugin_cb_flags flags, void *userdata);

PLUGIN_EXPORT int qemu_plugin_version = 1;

/* ---- the counter ---- */

static uint64_t insn_count[INSN_COUNT_MAX_VCPUS]; /* per vCPU index */
static int insn_count_vcpus;                       /* vCPUs on the board */
static char insn_count_out[4096];                  /* output file, or "" */

/* Runs on the vCPU's own thread.  Each slot has one writer, but the add is
 * atomic anyway so a reader at exit never sees a torn value. */
static void insn_count_tb_exec(unsigned int vcpu, void *n_insns)
{
    if (vcpu < INSN_COUNT_MAX_VCPUS)
        __atomic_fetch_add(&insn_count[vcpu], (uint64_t)(uintptr_t)n_insns, __ATOMIC_RELAXED);
}

/* The "count from here" marker (proto/insn_mark.h) ran on this vCPU. */
static void insn_count_mark(unsigned int vcpu, void *userdata)
{
    (void)userdata;
    if (vcpu < INSN_COUNT_MAX_VCPUS)
        __atomic_store_n(&insn_count[vcpu], 0, __ATOMIC_RELAXED);
}

/* The halfword after 0xF3AF of a 4-byte hint, or 0 for any other insn. */
static unsigned insn_count_hint_hw1(const struct qemu_plugin_insn *insn)
{
    const uint8_t *b = qemu_plugin_insn_data(insn);
    if (qemu_plugin_insn_size(insn) != 4 || (unsigned)(b[0] | b[1] << 8) != INSN_MARK_THUMB_HW0)
        return 0;
    return (unsigned)(b[2] | b[3] << 8);
}

/* ---- the trace ---- */

struct insn_trace_event {
    uint64_t count;
    uint8_t kind;
};
struct insn_trace_log {
    struct insn_trace_event *ev;
    size_t n, cap;
};
static struct insn_trace_log insn_trace[INSN_COUNT_MAX_VCPUS]; /* each written by its vCPU's thread only */
static char insn_trace_out[4096];   /* trace file, or "" */
static int insn_trace_oom;          /* an append found no memory */

static void insn_count_trace(unsigned int vcpu, void *kind)
{
    if (vcpu >= INSN_COUNT_MAX_VCPUS)
        return;
    struct insn_trace_log *t = &insn_trace[vcpu];
    if (t->n == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 4096;
        struct insn_trace_event *ev = realloc(t->ev, cap * sizeof *ev);
        if (!ev) {
            __atomic_store_n(&insn_trace_oom, 1, __ATOMIC_RELAXED);
            return;
        }
        t->ev = ev;
        t->cap = cap;
    }
    t->ev[t->n].count = __atomic_load_n(&insn_count[vcpu], __ATOMIC_RELAXED);
    t->ev[t->n].kind = (uint8_t)(uintptr_t)kind;
    t->n++;
}

/* path made new for writing: never an existing file, never through a link. */
static FILE *insn_open_out(const char *path)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0)
        return NULL;
    FILE *f = fdopen(fd, "w");
    if (!f)
        close(fd);
    return f;
}

static void insn_trace_write(void)
{
    FILE *f = insn_open_out(insn_trace_out);
    if (!f) {
        qemu_plugin_outs("insn-count: cannot make the trace= file (it exists, or a link is there)\n");
        return;
    }
    if (insn_trace_oom)
        fputs("oom\n", f); /* the reader refuses the trace */
    for (int k = 0; k < insn_count_vcpus; k++)
        for (size_t i = 0; i < insn_trace[k].n; i++)
            fprintf(f, "%d %u %llu\n", k, (unsigned)insn_trace[k].ev[i].kind,
                    (unsigned long long)insn_trace[k].ev[i].count);
    fclose(f);
}

/* ---- the profile ---- */

struct insn_prof_tb {
    uint64_t vaddr, count;
    uint32_t n;
    struct insn_prof_tb *next;
};
static char insn_prof_out[4096];      /* profile file, or "" */
static unsigned insn_prof_from;       /* the first vCPU profiled */
static unsigned insn_prof_to = ~0u;   /* the last */
static struct insn_prof_tb *insn_prof_list; /* every block translated */
static pthread_mutex_t insn_prof_lock = PTHREAD_MUTEX_INITIALIZER;
static int insn_prof_oom;

static void insn_prof_exec(unsigned int vcpu, void *rec)
{
    struct insn_prof_tb *t = rec;
    if (vcpu >= insn_prof_from && vcpu <= insn_prof_to)
        __atomic_fetch_add(&t->count, (uint64_t)t->n, __ATOMIC_RELAXED);
}

static void insn_prof_trans(struct qemu_plugin_tb *tb, size_t n)
{
    struct insn_prof_tb *t = calloc(1, sizeof *t);
    if (!t) {
        __atomic_store_n(&insn_prof_oom, 1, __ATOMIC_RELAXED);
        return;
    }
    t->vaddr = qemu_plugin_tb_vaddr(tb);
    t->n = (uint32_t)n;
    pthread_mutex_lock(&insn_prof_lock);
    t->next = insn_prof_list;
    insn_prof_list = t;
    pthread_mutex_unlock(&insn_prof_lock);
    qemu_plugin_register_vcpu_tb_exec_cb(tb, insn_prof_exec, QEMU_PLUGIN_CB_NO_REGS, t);
}

static int insn_prof_by_addr(const void *a, const void *b)
{
    const struct insn_prof_tb *x = *(struct insn_prof_tb *const *)a;
    const struct insn_prof_tb *y = *(struct insn_prof_tb *const *)b;
    return x->vaddr < y->vaddr ? -1 : x->vaddr > y->vaddr;
}

static void insn_prof_write(void)
{
    FILE *f = insn_open_out(insn_prof_out);
    if (!f) {
        qemu_plugin_outs("insn-count: cannot make the profile= file (it exists, or a link is there)\n");
        return;
    }
    pthread_mutex_lock(&insn_prof_lock);
    size_t n = 0;
    for (struct insn_prof_tb *t = insn_prof_list; t; t = t->next)
        n++;
    struct insn_prof_tb **v = malloc((n ? n : 1) * sizeof *v);
    if (insn_prof_oom || !v) {
        fputs("oom\n", f); /* the reader refuses the profile */
    } else {
        size_t i = 0;
        for (struct insn_prof_tb *t = insn_prof_list; t; t = t->next)
            v[i++] = t;
        qsort(v, n, sizeof *v, insn_prof_by_addr);
        for (i = 0; i < n;) {
            uint64_t addr = v[i]->vaddr, sum = 0;
            for (; i < n && v[i]->vaddr == addr; i++)
                sum += __atomic_load_n(&v[i]->count, __ATOMIC_RELAXED);
            if (sum)
                fprintf(f, "%08llx %llu\n", (unsigned long long)addr, (unsigned long long)sum);
        }
    }
    pthread_mutex_unlock(&insn_prof_lock);
    free(v);
    fclose(f);
}

static void insn_count_tb_trans(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    size_t n = qemu_plugin_tb_n_insns(tb);
    if (insn_prof_out[0])
        insn_prof_trans(tb, n);
    for (size_t i = 0; i < n; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        unsigned hw1 = insn_count_hint_hw1(insn);
        if (hw1 == INSN_MARK_THUMB_HW1)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, insn_count_mark,
                                                   QEMU_PLUGIN_CB_NO_REGS, NULL);
        else if (insn_trace_out[0] && hw1 >= INSN_MARK_TRACE_HW1_BASE &&
                 hw1 < INSN_MARK_TRACE_HW1_BASE + INSN_TRACE_KINDS)
            qemu_plugin_register_vcpu_insn_exec_cb(
                insn, insn_count_trace, QEMU_PLUGIN_CB_NO_REGS,
                (void *)(uintptr_t)(hw1 - INSN_MARK_TRACE_HW1_BASE));
    }
    qemu_plugin_register_vcpu_tb_exec_cb(tb, insn_count_tb_exec, QEMU_PLUGIN_CB_NO_REGS,
                                         (void *)(uintptr_t)n);
}

static void insn_count_atexit(qemu_plugin_id_t id, void *userdata)
{
    (void)id;
    (void)userdata;
    if (insn_trace_out[0])
        insn_trace_write();
    if (insn_prof_out[0])
        insn_prof_write();
    if (!insn_count_out[0] && (insn_trace_out[0] || insn_prof_out[0]))
        return;
    char line[64];
    FILE *f = insn_count_out[0] ? insn_open_out(insn_count_out) : NULL;
    if (insn_count_out[0] && !f) {
        qemu_plugin_outs("insn-count: cannot make the out= file (it exists, or a link is there)\n");
        return;
    }
    for (int k = 0; k < insn_count_vcpus; k++) {
        snprintf(line, sizeof line, "vcpu %d %llu\n", k,
                 (unsigned long long)__atomic_load_n(&insn_count[k], __ATOMIC_RELAXED));
        if (f)
            fputs(line, f);
        else
            qemu_plugin_outs(line);
    }
    if (f)
        fclose(f);
}

/* ---- the series thread ---- */

static char insn_series_out[4096]; /* series file, or "" */
static long insn_series_ms;        /* its period */

static void *insn_series_thread(void *arg)
{
    (void)arg;
    static char line[INSN_COUNT_MAX_VCPUS * 22 + 32];
    FILE *f = insn_open_out(insn_series_out);
    if (!f) {
        qemu_plugin_outs("insn-count: cannot make the series= file (it exists, or a link is there)\n");
        return NULL;
    }
    struct timespec period = {insn_series_ms / 1000, (insn_series_ms % 1000) * 1000000L};
    for (;;) {
        struct timespec now;
        clock_gettime(CLOCK_MONOTONIC, &now);
        size_t n = (size_t)snprintf(line, sizeof line, "at %lld",
                                    (long long)now.tv_sec * 1000 + now.tv_nsec / 1000000);
        for (int k = 0; k < insn_count_vcpus && n < sizeof line; k++)
            n += (size_t)snprintf(line + n, sizeof line - n, " %llu",
                                  (unsigned long long)__atomic_load_n(&insn_count[k],
                                                                      __ATOMIC_RELAXED));
        if (n < sizeof line - 1) {
            line[n++] = '\n';
            fwrite(line, 1, n, f);
            fflush(f); /* a reader sees whole lines only */
        }
        nanosleep(&period, NULL);
    }
    return NULL;
}

PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info,
                                      int argc, char **argv)
{
    if (!info->system_emulation) {
        qemu_plugin_outs("insn-count: only system emulation is supported\n");
        return -1;
    }
    insn_count_vcpus = info->system.max_vcpus;
    if (insn_count_vcpus > INSN_COUNT_MAX_VCPUS) {
        qemu_plugin_outs("insn-count: more vCPUs than INSN_COUNT_MAX_VCPUS\n");
        return -1;
    }
    for (int i = 0; i < argc; i++) {
        if (strncmp(argv[i], "out=", 4) == 0 && strlen(argv[i] + 4) < sizeof insn_count_out) {
            strcpy(insn_count_out, argv[i] + 4);
        } else if (strncmp(argv[i], "series=", 7) == 0 &&
                   strlen(argv[i] + 7) < sizeof insn_series_out) {
            strcpy(insn_series_out, argv[i] + 7);
        } else if (strncmp(argv[i], "trace=", 6) == 0 &&
                   strlen(argv[i] + 6) < sizeof insn_trace_out) {
            strcpy(insn_trace_out, argv[i] + 6);
        } else if (strncmp(argv[i], "every=", 6) == 0 && atol(argv[i] + 6) > 0) {
            insn_series_ms = atol(argv[i] + 6);
        } else if (strncmp(argv[i], "profile=", 8) == 0 &&
                   strlen(argv[i] + 8) < sizeof insn_prof_out) {
            strcpy(insn_prof_out, argv[i] + 8);
        } else if (strncmp(argv[i], "profile_to=", 11) == 0 && atol(argv[i] + 11) >= 0 &&
                   atol(argv[i] + 11) < INSN_COUNT_MAX_VCPUS) {
            insn_prof_to = (unsigned)atol(argv[i] + 11); /* below profile_from: none */
        } else if (strncmp(argv[i], "profile_from=", 13) == 0 && atol(argv[i] + 13) >= 0 &&
                   atol(argv[i] + 13) <= INSN_COUNT_MAX_VCPUS) {
            insn_prof_from = (unsigned)atol(argv[i] + 13);
        } else {
            qemu_plugin_outs("insn-count: arguments are out=FILE, series=FILE, every=MS, "
                             "trace=FILE, profile=FILE, profile_from=K, profile_to=L\n");
            return -1;
        }
    }
    if (insn_series_out[0]) {
        pthread_t th;
        if (insn_series_ms <= 0 ||
            pthread_create(&th, NULL, insn_series_thread, NULL) != 0) {
            qemu_plugin_outs("insn-count: series=FILE needs every=MS, and a thread\n");
            return -1;
        }
        pthread_detach(th);
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, insn_count_tb_trans);
    qemu_plugin_register_atexit_cb(id, insn_count_atexit, NULL);
    return 0;
}
