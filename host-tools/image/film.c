/* film.c: frames piped to the ffmpeg command as PNG images (film.h). */
#define _GNU_SOURCE /* posix_spawn_file_actions_addclosefrom_np, pipe2 */
#include "host-tools/image/film.h"
#include "host-tools/opts/exit_clean.h"
#include "host-tools/opts/tmp_dir.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

#define FILM_LOG_TAIL 240 /* bytes of ffmpeg's last message quoted */

static int film_ends(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n > m && strcasecmp(s + n - m, suffix) == 0;
}

enum film_kind film_kind_of(const char *out)
{
    if (film_ends(out, ".mp4"))
        return FILM_MP4;
    if (film_ends(out, ".webm"))
        return FILM_WEBM;
    if (film_ends(out, ".apng"))
        return FILM_APNG;
    return FILM_NONE;
}

int film_padded(enum film_kind kind, int width, int height)
{
    return kind != FILM_APNG && ((width | height) & 1);
}

int film_program_check(char *err, size_t cap)
{
    const char *path = getenv("PATH");
    if (path) {
        const char *p = path;
        for (;;) {
            size_t n = strcspn(p, ":");
            char file[4096];
            struct stat st;
            if (n > 0 && n + sizeof FILM_PROGRAM + 1 < sizeof file) {
                snprintf(file, sizeof file, "%.*s/%s", (int)n, p, FILM_PROGRAM);
                if (stat(file, &st) == 0 && S_ISREG(st.st_mode) && access(file, X_OK) == 0)
                    return 0;
            }
            if (!p[n])
                break;
            p += n + 1;
        }
    }
    snprintf(err, cap, "a film needs the %s command, which is not in PATH (the Debian package "
             "ffmpeg: host-tools/scripts/install-deps.sh installs it)", FILM_PROGRAM);
    return -1;
}

/* The last line ffmpeg wrote to its log, into out (empty when none). */
static void film_last_message(const struct film *fm, char *out, size_t cap)
{
    out[0] = 0;
    int fd = open(fm->log, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return;
    char buf[FILM_LOG_TAIL + 1];
    off_t end = lseek(fd, 0, SEEK_END);
    off_t from = end > FILM_LOG_TAIL ? end - FILM_LOG_TAIL : 0;
    ssize_t n = end > 0 ? pread(fd, buf, (size_t)(end - from), from) : 0;
    close(fd);
    if (n <= 0)
        return;
    buf[n] = 0;
    while (n > 0 && (buf[n - 1] == '\n' || buf[n - 1] == '\r'))
        buf[--n] = 0;
    char *line = strrchr(buf, '\n');
    snprintf(out, cap, "%s", line ? line + 1 : buf);
}

/* Waits for ffmpeg; its exit status as waitpid gives it, or -1. */
static int film_wait(struct film *fm)
{
    int status = -1;
    if (fm->pid > 0) {
        while (waitpid(fm->pid, &status, 0) < 0 && errno == EINTR)
            ;
        exit_clean_drop_child(fm->pid);
        fm->pid = 0;
    }
    return status;
}

static void film_cleanup(struct film *fm)
{
    if (fm->pipe) {
        fclose(fm->pipe);
        fm->pipe = NULL;
    }
    if (fm->pid > 0) {
        kill(fm->pid, SIGTERM);
        film_wait(fm);
    }
    out_file_abort(&fm->out);
    if (fm->log[0]) {
        tmp_file_remove(fm->log);
        fm->log[0] = 0;
    }
}

void film_abort(struct film *fm) { film_cleanup(fm); }

/* ffmpeg's argument array and the words made for it: no shell sees the
 * path or anything else. */
struct film_args {
    const char *v[40];
    char rate[16];
    char target[sizeof ((struct out_file *)0)->tmp + 8];
};

/* The encoder's arguments for kind from v[n] on; the next free index. */
static int film_codec_args(enum film_kind kind, const char **v, int n)
{
    switch (kind) {
    case FILM_MP4:
        v[n++] = "-c:v";
        v[n++] = "libx264";
        v[n++] = "-pix_fmt";
        v[n++] = "yuv420p";
        v[n++] = "-crf";
        v[n++] = "20";
        v[n++] = "-f";
        v[n++] = "mp4";
        break;
    case FILM_WEBM:
        v[n++] = "-c:v";
        v[n++] = "libvpx-vp9";
        v[n++] = "-pix_fmt";
        v[n++] = "yuv420p";
        v[n++] = "-crf";
        v[n++] = "32";
        v[n++] = "-b:v";
        v[n++] = "0";
        v[n++] = "-f";
        v[n++] = "webm";
        break;
    default: /* FILM_APNG */
        v[n++] = "-c:v";
        v[n++] = "apng";
        v[n++] = "-plays";
        v[n++] = "0";
        v[n++] = "-f";
        v[n++] = "apng";
        break;
    }
    return n;
}

/* ffmpeg's argument array for the film (PNG frames on its standard input,
 * the film into the temporary file) in a. */
static void film_argv(const struct film *fm, int fps, struct film_args *a)
{
    snprintf(a->rate, sizeof a->rate, "%d", fps);
    snprintf(a->target, sizeof a->target, "file:%s", fm->out.tmp); /* a name, never a protocol */
    const char **v = a->v;
    int n = 0;
    v[n++] = FILM_PROGRAM;
    v[n++] = "-hide_banner";
    v[n++] = "-nostats";
    v[n++] = "-loglevel";
    v[n++] = "error";
    v[n++] = "-y"; /* the temporary file exists (out_file made it) */
    v[n++] = "-f";
    v[n++] = "image2pipe";
    v[n++] = "-framerate";
    v[n++] = a->rate;
    v[n++] = "-c:v";
    v[n++] = "png";
    v[n++] = "-i";
    v[n++] = "-";
    if (film_padded(fm->kind, fm->width, fm->height)) {
        v[n++] = "-vf";
        v[n++] = "pad=ceil(iw/2)*2:ceil(ih/2)*2"; /* black on the right and bottom */
    }
    n = film_codec_args(fm->kind, v, n);
    v[n++] = a->target;
    v[n] = NULL;
}

/* ffmpeg started (fm->pid) with argv, its standard input the pipe's end
 * in, its standard output /dev/null, its standard error log.  0, or
 * posix_spawn's error (fm->pid 0). */
static int film_spawn(struct film *fm, const char *const *argv, int in, int log)
{
    posix_spawn_file_actions_t fa;
    int rc = posix_spawn_file_actions_init(&fa);
    if (rc == 0)
        rc = posix_spawn_file_actions_adddup2(&fa, in, STDIN_FILENO);
    if (rc == 0)
        rc = posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    if (rc == 0)
        rc = posix_spawn_file_actions_adddup2(&fa, log, STDERR_FILENO);
    if (rc == 0) /* nothing of ours (the board's sockets) goes with it */
        rc = posix_spawn_file_actions_addclosefrom_np(&fa, STDERR_FILENO + 1);
    signal(SIGPIPE, SIG_IGN); /* a write to an ffmpeg that stopped fails with EPIPE */
    if (rc == 0)
        rc = posix_spawnp(&fm->pid, FILM_PROGRAM, &fa, NULL, (char *const *)argv, environ);
    if (rc == 0) /* a signal stops it (its input's end stops it too) */
        exit_clean_add_child(fm->pid);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0)
        fm->pid = 0;
    return rc;
}

/* The film's kind (from path) and fps checked.  0, or -1 with why in err. */
static int film_check(const struct film *fm, const char *path, int fps, char *err, size_t cap)
{
    if (fm->kind == FILM_NONE) {
        snprintf(err, cap, "%s: not a film (.mp4, .webm or .apng)", path);
        return -1;
    }
    if (fps < 1 || fps > FILM_MAX_FPS) {
        snprintf(err, cap, "%s: %d frames a second, not 1..%d", path, fps, FILM_MAX_FPS);
        return -1;
    }
    return 0;
}

/* ffmpeg could not be started (rc, posix_spawn's error): why, in err. */
static void film_spawn_failed(const char *path, int rc, char *err, size_t cap)
{
    if (rc == ENOENT)
        snprintf(err, cap, "%s: the %s command was not found (the Debian package ffmpeg: "
                 "host-tools/scripts/install-deps.sh installs it)", path, FILM_PROGRAM);
    else
        snprintf(err, cap, "%s: cannot start %s: %s", path, FILM_PROGRAM, strerror(rc));
}

int film_open(struct film *fm, const char *path, int width, int height, int fps, char *err,
              size_t cap)
{
    memset(fm, 0, sizeof *fm);
    fm->kind = film_kind_of(path);
    fm->width = width;
    fm->height = height;
    if (film_check(fm, path, fps, err, cap) != 0 || out_file_open(&fm->out, path, err, cap) != 0)
        return -1;
    int log = tmp_file_make("ffmpeg", fm->log, sizeof fm->log);
    if (log < 0) {
        snprintf(err, cap, "%s: ffmpeg's log file: %s", path, strerror(errno));
        fm->log[0] = 0;
        film_cleanup(fm);
        return -1;
    }
    int p[2];
    if (pipe2(p, O_CLOEXEC) != 0) {
        snprintf(err, cap, "%s: a pipe to ffmpeg: %s", path, strerror(errno));
        close(log);
        film_cleanup(fm);
        return -1;
    }
    struct film_args a;
    film_argv(fm, fps, &a);
    int rc = film_spawn(fm, a.v, p[0], log);
    close(p[0]);
    close(log);
    if (rc != 0) {
        close(p[1]);
        film_spawn_failed(path, rc, err, cap);
        film_cleanup(fm);
        return -1;
    }
    fm->pipe = fdopen(p[1], "wb");
    if (!fm->pipe) {
        snprintf(err, cap, "%s: a pipe to ffmpeg: %s", path, strerror(errno));
        close(p[1]);
        film_cleanup(fm);
        return -1;
    }
    return 0;
}

/* "ffmpeg exited 1: <its last message>" for a stopped ffmpeg. */
static void film_stopped(struct film *fm, int status, const char *what, char *err, size_t cap)
{
    char last[FILM_LOG_TAIL + 1];
    film_last_message(fm, last, sizeof last);
    char how[64];
    if (status == -1)
        snprintf(how, sizeof how, "stopped");
    else if (WIFEXITED(status))
        snprintf(how, sizeof how, "exited %d", WEXITSTATUS(status));
    else if (WIFSIGNALED(status))
        snprintf(how, sizeof how, "was killed by signal %d", WTERMSIG(status));
    else
        snprintf(how, sizeof how, "stopped (status %d)", status);
    snprintf(err, cap, "%s: %s %s %s%s%s", fm->out.path, FILM_PROGRAM, how, what,
             last[0] ? ": " : "", last);
}

int film_frame(struct film *fm, const struct image *img, char *err, size_t cap)
{
    if (!fm->pipe) {
        snprintf(err, cap, "%s: the film is not open", fm->out.path);
        return -1;
    }
    if (img->width != fm->width || img->height != fm->height) {
        snprintf(err, cap, "%s: frame %ld is %dx%d, the film's frames %dx%d", fm->out.path,
                 fm->frames, img->width, img->height, fm->width, fm->height);
        return -1;
    }
    char werr[256];
    if (image_write(fm->pipe, "the pipe to ffmpeg", img, 0, werr, sizeof werr) != 0) {
        fclose(fm->pipe);
        fm->pipe = NULL;
        int status = film_wait(fm);
        char what[64];
        snprintf(what, sizeof what, "before frame %ld was taken", fm->frames);
        film_stopped(fm, status, what, err, cap);
        return -1;
    }
    fm->frames++;
    return 0;
}

int film_close(struct film *fm, char *err, size_t cap)
{
    if (!fm->pipe) {
        snprintf(err, cap, "%s: the film is not open", fm->out.path);
        film_cleanup(fm);
        return -1;
    }
    int closed = fclose(fm->pipe);
    fm->pipe = NULL;
    int status = film_wait(fm);
    if (status != 0 || closed != 0) {
        film_stopped(fm, status, "finishing the film", err, cap);
        film_cleanup(fm);
        return -1;
    }
    /* ffmpeg wrote the temporary file by name: its size is the film's */
    struct stat st;
    if (stat(fm->out.tmp, &st) != 0 || st.st_size == 0) {
        snprintf(err, cap, "%s: %s ended well but wrote no film", fm->out.path, FILM_PROGRAM);
        film_cleanup(fm);
        return -1;
    }
    if (out_file_commit(&fm->out, err, cap) != 0) {
        film_cleanup(fm);
        return -1;
    }
    tmp_file_remove(fm->log);
    fm->log[0] = 0;
    return 0;
}
