/* chart.c: a PNG chart drawn by gnuplot (chart.h). */
#define _GNU_SOURCE /* posix_spawn_file_actions_addclosefrom_np, pipe2 */
#include "host-tools/image/chart.h"

#include "host-tools/opts/exit_clean.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

static int chart_wait(struct chart *c)
{
    int status = -1;
    if (c->pid > 0) {
        while (waitpid(c->pid, &status, 0) < 0 && errno == EINTR)
            ;
        exit_clean_drop_child(c->pid);
        c->pid = 0;
    }
    return status;
}

void chart_abort(struct chart *c)
{
    if (c->script) {
        fclose(c->script);
        c->script = NULL;
    }
    if (c->pid > 0) {
        kill(c->pid, SIGTERM);
        chart_wait(c);
    }
    out_file_abort(&c->out);
}

/* gnuplot spawned with stdin from in and stdout into out.  0, or the
 * posix_spawn error. */
static int chart_spawn(struct chart *c, int in, int out)
{
    char *const argv[] = {CHART_PROGRAM, NULL};
    posix_spawn_file_actions_t fa;
    int rc = posix_spawn_file_actions_init(&fa);
    if (rc == 0)
        rc = posix_spawn_file_actions_adddup2(&fa, in, STDIN_FILENO);
    if (rc == 0)
        rc = posix_spawn_file_actions_adddup2(&fa, out, STDOUT_FILENO);
    if (rc == 0) /* nothing else of ours goes with it */
        rc = posix_spawn_file_actions_addclosefrom_np(&fa, STDERR_FILENO + 1);
    sigset_t held;
    exit_clean_hold(&held); /* started and registered before a signal can end us */
    if (rc == 0)
        rc = posix_spawnp(&c->pid, CHART_PROGRAM, &fa, NULL, argv, environ);
    if (rc == 0)
        exit_clean_add_child(c->pid);
    exit_clean_release(&held);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0)
        c->pid = 0;
    return rc;
}

int chart_open(struct chart *c, const char *path, char *err, size_t cap)
{
    memset(c, 0, sizeof *c);
    if (out_file_open(&c->out, path, err, cap) != 0)
        return -1;
    int p[2];
    if (pipe2(p, O_CLOEXEC) != 0) {
        snprintf(err, cap, "%s: a pipe to %s: %s", path, CHART_PROGRAM, strerror(errno));
        chart_abort(c);
        return -1;
    }
    signal(SIGPIPE, SIG_IGN); /* a write to a gnuplot that stopped fails with EPIPE */
    int rc = chart_spawn(c, p[0], fileno(c->out.f));
    close(p[0]);
    if (rc != 0) {
        close(p[1]);
        if (rc == ENOENT)
            snprintf(err, cap, "%s: a chart needs the %s command, which is not in PATH (the "
                     "Debian package gnuplot-nox)", path, CHART_PROGRAM);
        else
            snprintf(err, cap, "%s: cannot start %s: %s", path, CHART_PROGRAM, strerror(rc));
        chart_abort(c);
        return -1;
    }
    c->script = fdopen(p[1], "w");
    if (!c->script) {
        snprintf(err, cap, "%s: a pipe to %s: %s", path, CHART_PROGRAM, strerror(errno));
        close(p[1]);
        chart_abort(c);
        return -1;
    }
    return 0;
}

int chart_close(struct chart *c, char *err, size_t cap)
{
    int closed = c->script ? fclose(c->script) : EOF;
    c->script = NULL;
    int status = chart_wait(c);
    if (closed != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        snprintf(err, cap, "%s: %s did not draw the chart (exit status %d; its message above)",
                 c->out.path, CHART_PROGRAM, WIFEXITED(status) ? WEXITSTATUS(status) : -1);
        chart_abort(c);
        return -1;
    }
    struct stat st;
    if (fflush(c->out.f) != 0 || fstat(fileno(c->out.f), &st) != 0 || st.st_size == 0) {
        snprintf(err, cap, "%s: %s ended well but wrote no picture", c->out.path,
                 CHART_PROGRAM);
        chart_abort(c);
        return -1;
    }
    return out_file_commit(&c->out, err, cap) == 0 ? 0 : (chart_abort(c), -1);
}
