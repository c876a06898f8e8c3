/* farm_slurm.c: `links1 farm --slurm`: one round of a farm's items (frames,
 * or the bands of one frame) handed to Slurm as one job array, the array
 * index the item.  The batch script is fixed text written into DIR (no data
 * in it); the tool, scene and render arguments reach it as its arguments
 * through sbatch's argument array (fork + execvp, no shell string).  Each
 * task ends its log with one line, "links1-farm-task I RC START END NODE",
 * from which the per-host summary is read back, every field range-checked. */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host-tools/cli/farm.h"
#include "host-tools/opts/exit_clean.h"

#define FARM_SLURM_ARRAY_MAX 65536 /* bytes of --array's list */
#define FARM_SLURM_LOG_MAX (1 << 20) /* bytes of a task's log read back */
#define FARM_SLURM_JOB_MAX 4294967294L /* Slurm's job ids are 32-bit */

static const char farm_slurm_script[] =
    "#!/bin/sh\n"
    "# links1 farm: one task of a Slurm job array, written by links1 farm.\n"
    "# Arguments: TOOL SCENE EXT FRAME BANDS [render arguments...]; the array\n"
    "# index is the frame (BANDS 0) or the band of frame FRAME.\n"
    "tool=$1 scene=$2 ext=$3 frame=$4 bands=$5\n"
    "shift 5\n"
    "i=${SLURM_ARRAY_TASK_ID:?links1 farm: not run as a Slurm array task}\n"
    "n=$(printf %04d \"$i\")\n"
    "start=$(date +%s.%N)\n"
    "if [ \"$bands\" = 0 ]; then\n"
    "    \"$tool\" render \"$scene\" --frames \"$i:$i\" -o \"frame.$ext\" --quiet \"$@\"\n"
    "else\n"
    "    \"$tool\" render \"$scene\" --frame \"$frame\" --band \"$n/$bands\" -o \"band-$n.$ext\" "
    "--quiet \"$@\"\n"
    "fi\n"
    "rc=$?\n"
    "echo \"links1-farm-task $i $rc $start $(date +%s.%N) ${SLURMD_NODENAME:-$(hostname)}\"\n"
    "exit $rc\n";

/* The script written whole into dir/farm-slurm-task.sh (mode 0700, a file
 * of its own: an older one, or anything else of that name, is replaced,
 * never followed).  0, or -1 after saying why. */
static int farm_slurm_write_script(const char *dir, char *path, size_t cap)
{
    snprintf(path, cap, "%s/farm-slurm-task.sh", dir);
    if (unlink(path) != 0 && errno != ENOENT) {
        fprintf(stderr, "links1 farm: %s: cannot replace it: %s\n", path, strerror(errno));
        return -1;
    }
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0700);
    if (fd < 0) {
        fprintf(stderr, "links1 farm: %s: %s\n", path, strerror(errno));
        return -1;
    }
    size_t n = sizeof farm_slurm_script - 1;
    ssize_t w = write(fd, farm_slurm_script, n);
    if (close(fd) != 0 || w != (ssize_t)n) {
        fprintf(stderr, "links1 farm: %s: cannot write it\n", path);
        return -1;
    }
    return 0;
}

/* --array's list of the items, runs of consecutive items as A-B.  0, or -1
 * when it would pass FARM_SLURM_ARRAY_MAX bytes. */
static int farm_slurm_array(const long *items, long n, char *out, size_t cap)
{
    size_t len = (size_t)snprintf(out, cap, "--array=");
    for (long i = 0; i < n;) {
        long j = i;
        while (j + 1 < n && items[j + 1] == items[j] + 1)
            j++;
        int w = j > i ? snprintf(out + len, cap - len, "%s%ld-%ld", i ? "," : "", items[i], items[j])
                      : snprintf(out + len, cap - len, "%s%ld", i ? "," : "", items[i]);
        if (w < 0 || (size_t)w >= cap - len)
            return -1;
        len += (size_t)w;
        i = j + 1;
    }
    return 0;
}

/* The task's line in dir/slurm-JOB_ITEM.log added into hosts[]: 1 when the
 * task logged one, 0 when it did not (it never ran, or was killed). */
static int farm_slurm_read_task(const char *dir, long job, long item, struct farm_host *hosts,
                                int *nhosts)
{
    char path[PATH_MAX + 64];
    snprintf(path, sizeof path, "%s/slurm-%ld_%ld.log", dir, job, item);
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    if (fd < 0)
        return 0;
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return 0;
    }
    /* the last FARM_SLURM_LOG_MAX bytes hold the task's own last line */
    off_t from = st.st_size > FARM_SLURM_LOG_MAX ? st.st_size - FARM_SLURM_LOG_MAX : 0;
    static char buf[FARM_SLURM_LOG_MAX + 1];
    ssize_t got = 0, r;
    if (lseek(fd, from, SEEK_SET) == from)
        while (got < FARM_SLURM_LOG_MAX &&
               (r = read(fd, buf + got, (size_t)(FARM_SLURM_LOG_MAX - got))) > 0)
            got += r;
    close(fd);
    buf[got > 0 ? got : 0] = 0;
    char *line = NULL;
    for (char *p = buf; (p = strstr(p, "links1-farm-task ")) != NULL; p++)
        if (p == buf || p[-1] == '\n')
            line = p;
    long i;
    int rc;
    double start, end;
    char node[256];
    if (!line || sscanf(line, "links1-farm-task %ld %d %lf %lf %255s", &i, &rc, &start, &end,
                        node) != 5 || i != item)
        return 0;
    double seconds = end - start;
    if (!(seconds >= 0 && seconds < 1e9))
        seconds = 0;
    int h;
    for (h = 0; h < *nhosts; h++)
        if (strcmp(hosts[h].name, node) == 0)
            break;
    if (h == *nhosts) {
        if (*nhosts == FARM_MAX_HOSTS)
            return 1;
        memset(&hosts[h], 0, sizeof hosts[h]);
        snprintf(hosts[h].name, sizeof hosts[h].name, "%s", node);
        (*nhosts)++;
    }
    if (rc == 0) {
        hosts[h].frames++;
        hosts[h].seconds += seconds;
    } else {
        hosts[h].failed++;
    }
    return 1;
}

/* The words of sbatch's argument array that are made for the round. */
struct farm_slurm_words {
    char script[PATH_MAX + 32], chdir[PATH_MAX + 16], frame[24], bands[16];
    char array[FARM_SLURM_ARRAY_MAX]; /* --array=LIST */
};

/* The task script written and sbatch's words made in w.  0, or -1 after
 * saying why. */
static int farm_slurm_words(const struct farm_slurm_round *r, struct farm_slurm_words *w)
{
    if (farm_slurm_write_script(r->dir, w->script, sizeof w->script) != 0)
        return -1;
    if (farm_slurm_array(r->items, r->nitems, w->array, sizeof w->array) != 0) {
        fprintf(stderr, "links1 farm: --slurm: the list of %ld items to render is longer than "
                "%d bytes of sbatch --array; farm fewer frames at a time\n", r->nitems,
                FARM_SLURM_ARRAY_MAX);
        return -1;
    }
    snprintf(w->chdir, sizeof w->chdir, "--chdir=%s", r->dir);
    snprintf(w->frame, sizeof w->frame, "%ld", r->frame);
    snprintf(w->bands, sizeof w->bands, "%d", r->bands);
    return 0;
}

/* sbatch's argument array (NULL-ended; the caller frees it), or NULL
 * after saying so. */
static const char **farm_slurm_argv(const struct farm_slurm_round *r,
                                    const struct farm_slurm_words *w)
{
    const char **av = calloc((size_t)r->nextra + 24, sizeof *av);
    if (!av) {
        fprintf(stderr, "links1 farm: out of memory\n");
        return NULL;
    }
    size_t k = 0;
    av[k++] = "sbatch";
    av[k++] = "--parsable";
    av[k++] = "--wait";
    av[k++] = w->array;
    av[k++] = w->chdir;
    av[k++] = "--job-name=links1-farm";
    av[k++] = "--output=slurm-%A_%a.log"; /* in --chdir */
    av[k++] = "--ntasks=1";
    av[k++] = w->script;
    av[k++] = r->tool;
    av[k++] = r->scene;
    av[k++] = r->ext;
    av[k++] = w->frame;
    av[k++] = w->bands;
    for (int i = 0; i < r->nextra; i++)
        av[k++] = r->extra[i];
    av[k] = NULL;
    return av;
}

/* How far farm_slurm_read_out reads. */
enum farm_slurm_until {
    FARM_SLURM_UNTIL_LINE, /* a newline is in, or the end */
    FARM_SLURM_UNTIL_END,
};

/* What fd gives appended to out (*got bytes so far) up to cap - 1 bytes
 * (ended by a 0), until a newline or until its end; at the end, what is
 * past cap - 1 bytes is read and dropped. */
static void farm_slurm_read_out(int fd, char *out, size_t cap, size_t *got,
                                enum farm_slurm_until until)
{
    ssize_t n;
    while (*got < cap - 1) {
        if (until == FARM_SLURM_UNTIL_LINE && memchr(out, '\n', *got))
            break;
        n = read(fd, out + *got, cap - 1 - *got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        *got += (size_t)n;
    }
    out[*got] = 0;
    if (until == FARM_SLURM_UNTIL_END && *got == cap - 1) { /* the rest is not the job id */
        char sink[256];
        while ((n = read(fd, sink, sizeof sink)) > 0 || (n < 0 && errno == EINTR))
            ;
    }
}

/* The job id that `sbatch --parsable` prints first, "JOB" or
 * "JOB;CLUSTER" (a number 1 to FARM_SLURM_JOB_MAX), or -1. */
static long farm_slurm_job(const char *out)
{
    if (out[0] < '0' || out[0] > '9')
        return -1;
    char *end;
    errno = 0;
    long job = strtol(out, &end, 10);
    if (errno || job <= 0 || job > FARM_SLURM_JOB_MAX || (*end && *end != ';' && *end != '\n'))
        return -1;
    return job;
}

/* Once sbatch printed the job id: `scancel JOB` registered to run if a
 * signal stops the farm (killing sbatch --wait leaves the job running).
 * Its exit_clean slot, or -1. */
static int farm_slurm_cancel_on_signal(const char *out)
{
    long job = farm_slurm_job(out);
    if (job < 0)
        return -1;
    char id[24], done[96], failed[160];
    snprintf(id, sizeof id, "%ld", job);
    snprintf(done, sizeof done, "links1 farm: stopped: cancelled Slurm job %ld", job);
    snprintf(failed, sizeof failed, "links1 farm: stopped: scancel %ld failed; Slurm job %ld "
             "may still be running", job, job);
    const char *const av[] = {"scancel", id, NULL};
    return exit_clean_add_command(av, done, failed);
}

/* sbatch run with av (av freed) and waited for, its standard output in
 * out (*got bytes), its exit status (waitpid's) in *status; while it
 * waits for the job, a signal that stops the farm cancels the job.  0, or
 * -1 after saying why it could not be started. */
static int farm_slurm_sbatch(const char **av, char *out, size_t cap, size_t *got, int *status)
{
    int fds[2];
    if (pipe(fds) != 0) {
        fprintf(stderr, "links1 farm: pipe: %s\n", strerror(errno));
        free(av);
        return -1;
    }
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "links1 farm: fork: %s\n", strerror(errno));
        close(fds[0]);
        close(fds[1]);
        free(av);
        return -1;
    }
    if (pid == 0) {
        exit_clean_in_child();
        int null = open("/dev/null", O_RDONLY);
        if (null >= 0) {
            dup2(null, 0);
            close(null);
        }
        dup2(fds[1], 1);
        close(fds[0]);
        close(fds[1]);
        execvp("sbatch", (char *const *)av);
        fprintf(stderr, "links1 farm: cannot start sbatch: %s\n", strerror(errno));
        _exit(127);
    }
    free(av);
    exit_clean_add_child(pid);
    close(fds[1]);
    *got = 0;
    farm_slurm_read_out(fds[0], out, cap, got, FARM_SLURM_UNTIL_LINE);
    int cancel = farm_slurm_cancel_on_signal(out);
    farm_slurm_read_out(fds[0], out, cap, got, FARM_SLURM_UNTIL_END);
    close(fds[0]);
    while (waitpid(pid, status, 0) < 0 && errno == EINTR)
        ;
    exit_clean_drop_child(pid);
    exit_clean_drop_command(cancel); /* the job has ended */
    return 0;
}

int farm_slurm_run(const struct farm_slurm_round *r, struct farm_host *hosts, int *nhosts,
                   long *njobs)
{
    *njobs = 0;
    static struct farm_slurm_words w;
    if (farm_slurm_words(r, &w) != 0)
        return -1;
    const char **av = farm_slurm_argv(r, &w);
    char out[256];
    size_t got = 0;
    int status;
    if (!av || farm_slurm_sbatch(av, out, sizeof out, &got, &status) != 0)
        return -1;
    long job = farm_slurm_job(out);
    if (job < 0) {
        fprintf(stderr, "links1 farm: --slurm: sbatch did not submit the job array (exit %d%s%.*s)\n",
                WIFEXITED(status) ? WEXITSTATUS(status) : -1, got ? "; it printed: " : "",
                (int)strcspn(out, "\n"), out);
        return -1;
    }
    printf("links1 farm: Slurm job %ld ended (sbatch exit %d): %ld task(s)\n", job,
           WIFEXITED(status) ? WEXITSTATUS(status) : -1, r->nitems);
    for (long i = 0; i < r->nitems; i++)
        *njobs += farm_slurm_read_task(r->dir, job, r->items[i], hosts, nhosts);
    return 0;
}
