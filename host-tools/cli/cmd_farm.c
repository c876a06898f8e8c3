/* cmd_farm.c: links1 farm SCENE --frames A:B -o DIR --hosts FILE: the frames
 * of an animation handed to hosts through GNU parallel, one job per frame
 * (one at a time on a host, N on a host written N/host, so a faster host
 * takes more), each job a
 * `links1 render SCENE --frames F:F` on its host, the frame brought back into
 * DIR (parallel's --return, rsync over ssh; a local host ":" writes it there
 * itself).  A frame already in DIR is not rendered again.  parallel is started
 * with fork + execvp and an argument array; its command template holds only
 * fixed words and replacement strings ({1} the tool, {2} the scene, {3} the
 * frame, {4}... the extra render arguments), every piece of data reaching it
 * as its own ":::" input, which parallel quotes for the shell (local or
 * remote) itself.  The summary is read back from parallel's --joblog. */
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
#include "host-tools/cli/links1_cmds.h"
#include "host-tools/image/film.h"
#include "host-tools/image/image_io.h"
#include "host-tools/image/image_save.h"
#include "host-tools/opts/cli_args.h"
#include "host-tools/opts/cli_opt.h"
#include "host-tools/opts/exit_clean.h"
#include "host-tools/opts/private_path.h"
#include "host-tools/opts/self_path.h"

#define FARM_MAX_FRAMES 100000 /* frames in one farm */
#define FARM_MAX_EXTRA 64      /* render arguments after "--" */
#define FARM_HOSTS_MAX_BYTES (1 << 20)
#define FARM_MAX_BANDS 1024    /* bands of one still frame */

enum {
    FARM_OPT_FRAMES = CLI_OWN_CODES,
    FARM_OPT_HOSTS,
    FARM_OPT_RETRIES,
    FARM_OPT_EXT,
    FARM_OPT_FILM,
    FARM_OPT_FPS,
    FARM_OPT_BANDS,
    FARM_OPT_SLURM
};

#define FARM_GO (-1) /* a step's "go on" (else it returns the exit status) */

/* Who runs the jobs. */
enum farm_backend { FARM_PARALLEL, FARM_SLURM };

/* What the command line asks. */
struct farm_opts {
    const char *scene, *dir, *hosts_file, *ext, *film;
    const char *extra[FARM_MAX_EXTRA]; /* render arguments after "--" */
    int nextra, retries, fps, fps_given;
    int bands;                         /* 0: frames first..last, a job a frame */
    enum farm_backend backend;
    long first, last;
};

/* A farm's run: the paths resolved, the items, and the rounds' state.
 * The items are frames first..last, or the bands 0..bands-1 of frame
 * first: item0..item0+nitems-1. */
struct farm_run {
    const struct farm_opts *o;
    char scene[PATH_MAX], hosts_path[PATH_MAX], dir[PATH_MAX], tool[PATH_MAX];
    char fw_dir[PATH_MAX];    /* $FW_DIR made absolute, "" when unset */
    int dir_fd, nhosts_file;  /* DIR; the host lines of --hosts */
    const char *slots;        /* the host lines, each with its N/ (1/ when
                                 it had none), one a line: what parallel reads */
    size_t slots_len;
    char slots_path[PATH_MAX + 32]; /* DIR/farm-hosts, written from slots */
    const char *unit;         /* what a job makes: "frame" or "band" */
    long item0, nitems;
    long *todo, ntodo;        /* this round's items, rising */
    char (*todo_s)[24];       /* the same as %04ld: parallel's inputs */
    char *ok;                 /* todo[i]'s job ended well (parallel's joblog) */
    char *again;              /* item item0 + i may go out again */
    struct farm_host *hosts;  /* the summary, nhosts of them */
    int nhosts;
    long kept, refarmed, missing, njobs;
    int status;               /* parallel's last exit status (waitpid's) */
};

/* The words of one parallel round its argument array points at. */
struct farm_words {
    char joblog_name[32], joblog[PATH_MAX + 32];
    char templ[4096], ret[64], retries[16];
};

static const struct cli_optdef farm_optdefs[] = {
    {"frames", "A:B", FARM_OPT_FRAMES,
     "the frames to render (at most " CLI_STR(FARM_MAX_FRAMES) ")"},
    {"hosts", "FILE", FARM_OPT_HOSTS,
     "the hosts, GNU parallel's --sshloginfile: each line ':' (this\n"
     "machine), [N/][user@]host[:port], blank or a # comment; refused\n"
     "unless no one but you (or root) can change it"},
    {"slurm", NULL, FARM_OPT_SLURM,
     "instead of --hosts: the frames (or bands) not in DIR as one Slurm\n"
     "job array (`sbatch --wait --array`, the task id the frame), DIR on\n"
     "a file system the nodes share; sbatch's own SBATCH_* variables\n"
     "(SBATCH_PARTITION, ...) choose where it runs"},
    {"retries", "N", FARM_OPT_RETRIES,
     "tries of a frame (parallel --retries: each on a host where it has\n"
     "not failed yet; Slurm: rounds of the frames still missing),\n"
     "1..100, default 3"},
    {"ext", "png|ppm", FARM_OPT_EXT, "the frames' format (default png)"},
    {"film", "OUT", FARM_OPT_FILM,
     "once every frame is in DIR, frames A..B made into one film by\n"
     "ffmpeg (OUT's ending: .mp4, .webm or .apng), written whole or not"},
    {"fps", "N", FARM_OPT_FPS, "the film's frames a second (1.." CLI_STR(FILM_MAX_FPS) ", default "
     CLI_STR(FILM_DEFAULT_FPS) ")"},
    {"bands", "N", FARM_OPT_BANDS,
     "one still frame (--frames F:F) cut into N bands of scanlines, a\n"
     "job a band (`links1 render --band I/N`), stitched into\n"
     "DIR/frame-FFFF.EXT once all are back (2.." CLI_STR(FARM_MAX_BANDS) ")"},
    CLI_OPTDEF_END,
};

static void farm_usage(FILE *out)
{
    fprintf(out,
            "usage: links1 farm SCENE --frames A:B -o DIR --hosts FILE|--slurm [options]\n"
            "                   [-- links1 render arguments...]\n"
            "Renders frames A..B on the hosts of FILE one frame a job, one job at a time on\n"
            "a host (N at a time on a host written N/host),\n"
            "each job `links1 render SCENE --frames F:F` run there (links1 and SCENE at the\n"
            "same absolute paths on every host); the frames gathered into DIR as\n"
            "frame-NNNN.EXT.  A frame already in DIR is not rendered again (an interrupted\n"
            "farm resumes).  DIR is refused unless no one but you can change it.  The ssh\n"
            "parallel uses: $PARALLEL_SSH (e.g. \"ssh -F CONFIG\"), else ssh; $FW_DIR, when\n"
            "set, is made absolute and passed to every host (--env).\n"
            "options:\n");
    cli_optdefs_help(out, farm_optdefs);
}

int farm_in_path(const char *name)
{
    const char *path = getenv("PATH");
    if (!path || !*path)
        path = "/usr/bin:/bin";
    while (*path) {
        const char *end = strchr(path, ':');
        size_t n = end ? (size_t)(end - path) : strlen(path);
        char full[PATH_MAX];
        size_t len = strlen(name);
        if (n > 0 && n + len + 2 <= sizeof full) {
            memcpy(full, path, n);
            full[n] = '/';
            memcpy(full + n + 1, name, len + 1);
            struct stat st;
            if (stat(full, &st) == 0 && S_ISREG(st.st_mode) && access(full, X_OK) == 0)
                return 1;
        }
        if (!end)
            break;
        path = end + 1;
    }
    return 0;
}

/* Whether `parallel --version` says it is GNU parallel (moreutils has a
 * `parallel` too, with other options).  1, or 0. */
static int farm_is_gnu_parallel(void)
{
    int fds[2];
    if (pipe(fds) != 0)
        return 0;
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return 0;
    }
    if (pid == 0) {
        int null = open("/dev/null", O_RDWR);
        if (null >= 0) {
            dup2(null, 0);
            dup2(null, 2);
            close(null);
        }
        dup2(fds[1], 1);
        close(fds[0]);
        close(fds[1]);
        char *const av[] = {"parallel", "--version", NULL};
        execvp("parallel", av);
        _exit(127);
    }
    close(fds[1]);
    char buf[256];
    size_t got = 0;
    ssize_t r;
    while (got < sizeof buf - 1 && (r = read(fds[0], buf + got, sizeof buf - 1 - got)) > 0)
        got += (size_t)r;
    buf[got] = 0;
    close(fds[0]);
    int status;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    return strncmp(buf, "GNU parallel", 12) == 0;
}

/* Whether s[0..n) is a user or host name: letters, digits, '.', '-' and
 * '_', not starting with '-' (ssh would take it for an option). */
static int farm_name_ok(const char *s, size_t n)
{
    if (n == 0 || n > 253 || s[0] == '-')
        return 0;
    for (size_t i = 0; i < n; i++)
        if (!((s[i] >= 'a' && s[i] <= 'z') || (s[i] >= 'A' && s[i] <= 'Z') ||
              (s[i] >= '0' && s[i] <= '9') || s[i] == '.' || s[i] == '-' || s[i] == '_'))
            return 0;
    return 1;
}

/* Whether s is a number lo..hi in decimal digits alone (no leading 0). */
static int farm_number_ok(const char *s, size_t n, long lo, long hi)
{
    if (n == 0 || n > 6 || s[0] == '0' || strspn(s, "0123456789") < n)
        return 0;
    long v = strtol(s, NULL, 10);
    return v >= lo && v <= hi;
}

/* Whether line is a host line: [N/]: or [N/][user@]host[:port], host a
 * name or a bracketed IPv6 address ([2001:db8::1]). */
static int farm_host_line_ok(const char *p)
{
    size_t d = strspn(p, "0123456789");
    if (d > 0 && p[d] == '/') {
        if (!farm_number_ok(p, d, 1, 9999))
            return 0;
        p += d + 1;
    }
    if (strcmp(p, ":") == 0)
        return 1;
    const char *at = strchr(p, '@');
    if (at) {
        if (!farm_name_ok(p, (size_t)(at - p)))
            return 0;
        p = at + 1;
    }
    const char *end;
    if (*p == '[') {
        end = strchr(p, ']');
        size_t n = end ? (size_t)(end - p - 1) : 0;
        if (n < 2 || strspn(p + 1, "0123456789abcdefABCDEF:") < n || !memchr(p + 1, ':', n))
            return 0;
        end++;
    } else {
        end = p + strcspn(p, ":");
        if (!farm_name_ok(p, (size_t)(end - p)))
            return 0;
    }
    return *end == 0 || (*end == ':' && farm_number_ok(end + 1, strlen(end + 1), 1, 65535));
}

/* s (n bytes) into out, a control character as \n or \xHH. */
static void farm_printable(const char *s, size_t n, char *out, size_t cap)
{
    size_t k = 0;
    for (size_t i = 0; i < n && k + 5 < cap; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '\n')
            k += (size_t)snprintf(out + k, cap - k, "\\n");
        else if (c < 0x20 || c == 0x7f)
            k += (size_t)snprintf(out + k, cap - k, "\\x%02x", c);
        else
            out[k++] = (char)c;
    }
    out[k] = 0;
}

/* The hosts file's lines (buf, n bytes): each a host line, blank, or a #
 * comment.  The host lines' count, or -1 after naming the first other.
 * The host lines go to slots (*slots_len bytes, room for 2n + 1), each
 * with its job slots: N/ as written, or 1/ (one job at a time there). */
static int farm_host_lines(const char *file, char *buf, size_t n, char *slots,
                           size_t *slots_len)
{
    int hosts = 0;
    *slots_len = 0;
    size_t lineno = 0;
    for (char *line = buf; line < buf + n;) {
        char *nl = memchr(line, '\n', (size_t)(buf + n - line));
        char *end = nl ? nl : buf + n, *next = nl ? nl + 1 : buf + n;
        lineno++;
        size_t len = (size_t)(end - line);
        while (len > 0 && line[len - 1] && strchr(" \t\r", line[len - 1]))
            len--;
        size_t lead = strspn(line, " \t");
        if (lead >= len || line[lead] == '#') {
            line = next;
            continue;
        }
        char keep = line[len];
        line[len] = 0;
        int ok = strlen(line) == len && farm_host_line_ok(line);
        line[len] = keep;
        if (!ok) {
            char shown[256];
            farm_printable(line, len < 60 ? len : 60, shown, sizeof shown);
            fprintf(stderr, "links1 farm: --hosts %s: line %zu '%s%s' is not a host line: "
                    "refused (parallel runs each line as an ssh login; a line may be ':' for "
                    "this machine, [N/][user@]host[:port] with host of letters, digits, '.', "
                    "'-' and '_' not starting with '-' or an [IPv6] address, blank, or a # "
                    "comment)\n", file, lineno, shown, len > 60 ? "..." : "");
            return -1;
        }
        hosts++;
        size_t d = strspn(line + lead, "0123456789");
        if (!(d > 0 && line[lead + d] == '/'))
            *slots_len += (size_t)sprintf(slots + *slots_len, "1/");
        memcpy(slots + *slots_len, line + lead, len - lead);
        *slots_len += len - lead;
        slots[(*slots_len)++] = '\n';
        line = next;
    }
    if (hosts == 0)
        fprintf(stderr, "links1 farm: --hosts %s: no host in it (one a line, ':' for this "
                        "machine)\n", file);
    return hosts ? hosts : -1;
}

/* The hosts file: code for parallel, so a regular file that only you (or
 * root) can change (private_path), of host lines.  Returns the number of
 * host lines with the file's resolved path in real and the lines with
 * their job slots in r->slots, or -1 after saying why. */
static int farm_check_hosts(const char *file, char *real, struct farm_run *r)
{
    char err[2 * PATH_MAX + 512];
    int fd = private_path_open(file, PRIVATE_PATH_FILE, real, err, sizeof err);
    if (fd < 0) {
        fprintf(stderr, "links1 farm: --hosts %s\n", err);
        return -1;
    }
    struct stat st;
    if (fstat(fd, &st) != 0 || st.st_size > FARM_HOSTS_MAX_BYTES) {
        fprintf(stderr, "links1 farm: --hosts %s: %lld bytes, more than %d\n", file,
                (long long)st.st_size, FARM_HOSTS_MAX_BYTES);
        close(fd);
        return -1;
    }
    static char buf[FARM_HOSTS_MAX_BYTES + 1];
    ssize_t got = 0, n;
    while (got < FARM_HOSTS_MAX_BYTES &&
           (n = read(fd, buf + got, (size_t)(FARM_HOSTS_MAX_BYTES - got))) > 0)
        got += n;
    close(fd);
    static char slots[2 * FARM_HOSTS_MAX_BYTES + 1];
    r->slots = slots;
    return farm_host_lines(file, buf, (size_t)got, slots, &r->slots_len);
}

/* DIR/farm-hosts: the host lines with their job slots, which parallel
 * reads with -j100% (a host's N/ is its job slots, 1 where none is
 * written: -j1 would hold every host to one).  0, or -1 after saying why. */
static int farm_write_slots(struct farm_run *r)
{
    snprintf(r->slots_path, sizeof r->slots_path, "%s/farm-hosts", r->dir);
    int fd = openat(r->dir_fd, "farm-hosts",
                    O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY, 0600);
    ssize_t put = fd < 0 ? -1 : write(fd, r->slots, r->slots_len);
    if (fd < 0 || put != (ssize_t)r->slots_len || close(fd) != 0) {
        fprintf(stderr, "links1 farm: %s: %s\n", r->slots_path,
                put >= 0 && fd >= 0 ? "short write" : strerror(errno));
        return -1;
    }
    return 0;
}

/* DIR: made when missing (0755 less the umask: others may read the frames);
 * else a directory only you can change (private_path): no one else can
 * plant a link or a frame in it.  Its fd (O_CLOEXEC) with its resolved
 * path in real, or -1 after saying why. */
static int farm_open_dir(const char *dir, char *real)
{
    if (mkdir(dir, 0755) != 0 && errno != EEXIST) {
        fprintf(stderr, "links1 farm: -o %s: cannot make it: %s\n", dir, strerror(errno));
        return -1;
    }
    char err[2 * PATH_MAX + 512];
    int fd = private_path_open(dir, PRIVATE_PATH_DIR, real, err, sizeof err);
    if (fd < 0) {
        fprintf(stderr, "links1 farm: -o %s\n", err);
        return -1;
    }
    if (access(real, W_OK | X_OK) != 0) {
        fprintf(stderr, "links1 farm: -o %s: cannot write into it\n", dir);
        close(fd);
        return -1;
    }
    return fd;
}

/* s (what names it, e.g. "the scene") holds no control character: parallel
 * takes a newline in an input for the end of a job's input.  0, or -1
 * after saying why. */
static int farm_plain(const char *what, const char *s)
{
    size_t i = 0;
    while (s[i] && (unsigned char)s[i] >= 0x20 && s[i] != 0x7f)
        i++;
    if (!s[i])
        return 0;
    char shown[PATH_MAX + 64], which[48];
    farm_printable(s, strlen(s), shown, sizeof shown);
    if (s[i] == '\n')
        snprintf(which, sizeof which, "a newline");
    else
        snprintf(which, sizeof which, "a control character (byte 0x%02x)", (unsigned char)s[i]);
    fprintf(stderr, "links1 farm: %s '%s' holds %s: refused (a farm's paths and arguments "
            "reach parallel as lines of input: this one would become several jobs)\n", what, shown, which);
    return -1;
}

/* The farm's arguments as given hold no control character (farm_plain).
 * 0, or -1 after saying why. */
static int farm_args_plain(const char *scene, const char *dir, const char *hosts,
                           const char *film, const char *const *extra, int nextra)
{
    if (farm_plain("the scene", scene) != 0 || farm_plain("-o", dir) != 0 ||
        (hosts && farm_plain("--hosts", hosts) != 0) || (film && farm_plain("--film", film) != 0))
        return -1;
    for (int i = 0; i < nextra; i++)
        if (farm_plain("the render argument", extra[i]) != 0)
            return -1;
    return 0;
}

/* A piece parallel would read as its own separator instead of an input. */
static int farm_separator_word(const char *s)
{
    return strcmp(s, ":::") == 0 || strcmp(s, "::::") == 0 || strcmp(s, ":::+") == 0 ||
           strcmp(s, "::::+") == 0;
}

/* The joblog's lines (name in DIR, dir_fd; log its path) added into
 * hosts[] (*nhosts of them so far), read without following a link; *njobs the
 * jobs it logs; ok[seq - 1] set for each job (Seq, 1..njobs_max: the inputs'
 * order) that ended well.  0, or -1. */
static int farm_read_joblog(int dir_fd, const char *name, const char *log,
                            struct farm_host *hosts, int *nhosts, long *njobs, char *ok,
                            long njobs_max)
{
    int fd = openat(dir_fd, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    struct stat st;
    FILE *f = fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode) ? fdopen(fd, "r") : NULL;
    if (!f) {
        fprintf(stderr, "links1 farm: parallel's joblog %s: %s\n", log,
                fd < 0 && errno == ENOENT ? "parallel ended without writing it (its own words "
                                            "are above)"
                : fd < 0                  ? strerror(errno)
                                          : "not a regular file");
        if (fd >= 0)
            close(fd);
        return -1;
    }
    char line[8192];
    *njobs = 0;
    int first = 1;
    while (fgets(line, sizeof line, f)) {
        if (first) { /* the header */
            first = 0;
            continue;
        }
        char *field[9] = {0};
        char *p = line;
        for (int i = 0; i < 9 && p; i++) {
            field[i] = p;
            p = i < 8 ? strchr(p, '\t') : NULL;
            if (p)
                *p++ = 0;
        }
        if (!field[7])
            continue;
        long seq = strtol(field[0], NULL, 10);
        double runtime = strtod(field[3], NULL);
        long exitval = strtol(field[6], NULL, 10), sig = strtol(field[7], NULL, 10);
        if (!(runtime >= 0 && runtime < 1e9))
            runtime = 0;
        int h;
        for (h = 0; h < *nhosts; h++)
            if (strcmp(hosts[h].name, field[1]) == 0)
                break;
        if (h == *nhosts) {
            if (*nhosts == FARM_MAX_HOSTS)
                continue;
            memset(&hosts[h], 0, sizeof hosts[h]);
            snprintf(hosts[h].name, sizeof hosts[h].name, "%s", field[1]);
            (*nhosts)++;
        }
        (*njobs)++;
        if (exitval == 0 && sig == 0) {
            if (seq >= 1 && seq <= njobs_max)
                ok[seq - 1] = 1;
            hosts[h].frames++;
            hosts[h].seconds += runtime;
        } else {
            hosts[h].failed++;
        }
    }
    fclose(f);
    return 0;
}

/* Item n's file in DIR: what makes "frame" (frame-NNNN.EXT) or "band". */
static void farm_item_path(const char *dir, const char *what, long n, const char *ext, char *out,
                           size_t cap)
{
    snprintf(out, cap, "%s/%s-%04ld.%s", dir, what, n, ext);
}

/* Whether path is a finished item: a non-empty regular file (frames and
 * bands are written whole, so one that is there is complete). */
static int farm_item_there(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0;
}

/* The bands 0..bands-1 of DIR stitched top to bottom into frame f of DIR
 * (written whole, then the bands removed).  Every band must be as wide as
 * the first.  0, or 1 after saying why (the bands stay). */
static int farm_stitch(const char *dir, long f, long bands, const char *ext)
{
    char err[PATH_MAX + 256], path[PATH_MAX + 32];
    struct image whole = {0, 0, NULL};
    for (long b = 0; b < bands; b++) {
        struct image img;
        farm_item_path(dir, "band", b, ext, path, sizeof path);
        if (image_read(path, &img, err, sizeof err) != 0) {
            fprintf(stderr, "links1 farm: stitching: %s\n", err);
            image_free(&whole);
            return 1;
        }
        if ((b > 0 && img.width != whole.width) || whole.height + img.height > IMAGE_MAX_SIDE) {
            fprintf(stderr, "links1 farm: stitching: %s is %dx%d, the bands before it %d wide "
                    "and %d high in all\n", path, img.width, img.height, whole.width, whole.height);
            image_free(&img);
            image_free(&whole);
            return 1;
        }
        size_t row = (size_t)img.width * 3;
        uint8_t *grown = realloc(whole.rgb, row * (size_t)(whole.height + img.height));
        if (!grown) {
            fprintf(stderr, "links1 farm: stitching: out of memory\n");
            image_free(&img);
            image_free(&whole);
            return 1;
        }
        memcpy(grown + row * (size_t)whole.height, img.rgb, row * (size_t)img.height);
        whole.rgb = grown;
        whole.width = img.width;
        whole.height += img.height;
        image_free(&img);
    }
    farm_item_path(dir, "frame", f, ext, path, sizeof path);
    int rc = image_save(path, &whole, strcmp(ext, "ppm") == 0, err, sizeof err);
    image_free(&whole);
    if (rc != 0) {
        fprintf(stderr, "links1 farm: stitching: %s\n", err);
        return 1;
    }
    for (long b = 0; b < bands; b++) {
        char band[PATH_MAX + 32];
        farm_item_path(dir, "band", b, ext, band, sizeof band);
        unlink(band);
    }
    printf("links1 farm: %ld bands stitched into %s\n", bands, path);
    return 0;
}

/* Frames first..last of DIR, in order, made into the film OUT (every frame
 * the first one's size).  0, or 1 after saying why; nothing is named OUT
 * then. */
static int farm_film(const char *dir, long first, long last, const char *ext, const char *out,
                     int fps)
{
    struct film fm;
    memset(&fm, 0, sizeof fm);
    char err[PATH_MAX + 256];
    for (long f = first; f <= last; f++) {
        char path[PATH_MAX + 32];
        farm_item_path(dir, "frame", f, ext, path, sizeof path);
        struct image img;
        if (image_read(path, &img, err, sizeof err) != 0) {
            fprintf(stderr, "links1 farm: --film %s: %s\n", out, err);
            film_abort(&fm);
            return 1;
        }
        int bad = 0;
        if (f == first) {
            bad = film_open(&fm, out, img.width, img.height, fps, err, sizeof err) != 0;
            if (!bad && film_padded(fm.kind, img.width, img.height))
                printf("links1 farm: %s: %dx%d padded to %dx%d (the film's yuv420p needs even "
                       "sides)\n", out, img.width, img.height, img.width + (img.width & 1),
                       img.height + (img.height & 1));
        } else if (img.width != fm.width || img.height != fm.height) {
            snprintf(err, sizeof err, "%s is %dx%d, frame %ld was %dx%d", path, img.width,
                     img.height, first, fm.width, fm.height);
            bad = 1;
        }
        if (!bad)
            bad = film_frame(&fm, &img, err, sizeof err) != 0;
        image_free(&img);
        if (bad) {
            fprintf(stderr, "links1 farm: --film %s: %s\n", out, err);
            film_abort(&fm);
            return 1;
        }
    }
    if (film_close(&fm, err, sizeof err) != 0) {
        fprintf(stderr, "links1 farm: --film %s: %s\n", out, err);
        return 1;
    }
    printf("links1 farm: wrote %s (%ld frames at %d a second)\n", out, last - first + 1, fps);
    return 0;
}

/* An operand into o: the scene, or after "--" a render argument.
 * FARM_GO, or 2 after saying why. */
static int farm_take_operand(const struct cli *c, struct farm_opts *o)
{
    if (c->rest) {
        if (o->nextra == FARM_MAX_EXTRA) {
            cli_usage_error("links1 farm", "more than %d render arguments after --",
                            FARM_MAX_EXTRA);
            return 2;
        }
        o->extra[o->nextra++] = c->arg;
    } else if (!o->scene) {
        o->scene = c->arg;
    } else {
        cli_usage_error("links1 farm", "'%s': one scene a farm (render arguments go after --)",
                        c->arg);
        return 2;
    }
    return FARM_GO;
}

/* One option (code, from cli_next) into o.  FARM_GO, or an exit status. */
static int farm_take_option(const struct cli *c, int code, struct farm_opts *o)
{
    switch (code) {
    case CLI_OPERAND: return farm_take_operand(c, o);
    case 'o': o->dir = c->arg; return FARM_GO;
    case FARM_OPT_HOSTS: o->hosts_file = c->arg; return FARM_GO;
    case FARM_OPT_FRAMES:
        if (cli_parse_frames(c->arg, &o->first, &o->last) != 0 ||
            o->last - o->first >= FARM_MAX_FRAMES) {
            cli_bad_value(c, "frames A:B, 0 <= A <= B, at most " CLI_STR(FARM_MAX_FRAMES)
                             " of them");
            return 2;
        }
        return FARM_GO;
    case FARM_OPT_RETRIES: return cli_int(c, 1, 100, &o->retries) != 0 ? 2 : FARM_GO;
    case FARM_OPT_EXT:
        if (strcmp(c->arg, "png") != 0 && strcmp(c->arg, "ppm") != 0) {
            cli_bad_value(c, "png or ppm");
            return 2;
        }
        o->ext = c->arg;
        return FARM_GO;
    case FARM_OPT_FILM:
        if (film_kind_of(c->arg) == FILM_NONE) {
            cli_bad_value(c, "a film named .mp4, .webm or .apng");
            return 2;
        }
        o->film = c->arg;
        return FARM_GO;
    case FARM_OPT_FPS:
        o->fps_given = 1;
        return cli_int(c, 1, FILM_MAX_FPS, &o->fps) != 0 ? 2 : FARM_GO;
    case FARM_OPT_BANDS: return cli_int(c, 2, FARM_MAX_BANDS, &o->bands) != 0 ? 2 : FARM_GO;
    case FARM_OPT_SLURM: o->backend = FARM_SLURM; return FARM_GO;
    case 'h': farm_usage(stdout); return 0;
    default: return 2;
    }
}

/* The command line into o (defaults first).  FARM_GO, or an exit status
 * (0 after --help) after saying why. */
static int farm_parse(int argc, char **argv, struct farm_opts *o)
{
    memset(o, 0, sizeof *o);
    o->ext = "png";
    o->retries = 3;
    o->fps = FILM_DEFAULT_FPS;
    o->backend = FARM_PARALLEL;
    o->first = o->last = -1;
    static const struct cli_optdef *const lists[] = {farm_optdefs, NULL};
    struct option longs[16];
    if (cli_optdefs_table(lists, longs, 16) != 0)
        return 2;
    struct cli c;
    cli_init(&c, "links1 farm", argc, argv, "o:h", longs);
    int code;
    while ((code = cli_next(&c)) != -1) {
        int rc = farm_take_option(&c, code, o);
        if (rc != FARM_GO)
            return rc;
    }
    return FARM_GO;
}

/* The options together: what is wanted given, nothing that does not go
 * together, no control character.  FARM_GO, or an exit status after
 * saying why. */
static int farm_check_opts(const struct farm_opts *o)
{
    if (!o->scene || !o->dir || !(o->hosts_file || o->backend == FARM_SLURM) || o->first < 0) {
        cli_usage_error("links1 farm", "want SCENE, --frames A:B, -o DIR and --hosts FILE or "
                        "--slurm");
        return 2;
    }
    if (o->hosts_file && o->backend == FARM_SLURM) {
        cli_usage_error("links1 farm", "--hosts (GNU parallel) or --slurm, not both");
        return 2;
    }
    if (o->fps_given && !o->film) {
        cli_usage_error("links1 farm", "--fps goes with --film");
        return 2;
    }
    if (o->bands && (o->first != o->last || o->film)) {
        cli_usage_error("links1 farm", "--bands cuts one still frame: give --frames F:F and "
                        "no --film");
        return 2;
    }
    if (farm_args_plain(o->scene, o->dir, o->hosts_file, o->film, o->extra, o->nextra) != 0)
        return 1;
    return FARM_GO;
}

/* The programs the farm needs are there: ffmpeg for --film (before any
 * host renders: the film could not be made), sbatch or GNU parallel.
 * FARM_GO, or 1 after saying which is missing. */
static int farm_check_tools(const struct farm_opts *o)
{
    if (o->film) {
        char err[512];
        if (film_program_check(err, sizeof err) != 0) {
            fprintf(stderr, "links1 farm: --film %s: %s\n", o->film, err);
            return 1;
        }
    }
    if (o->backend == FARM_SLURM) {
        if (farm_in_path("sbatch"))
            return FARM_GO;
        fprintf(stderr, "links1 farm: --slurm: Slurm's sbatch is not installed (no 'sbatch' in "
                        "PATH; the Debian package slurm-client)\n");
        return 1;
    }
    if (!farm_in_path("parallel")) {
        fprintf(stderr, "links1 farm: GNU parallel is not installed (no 'parallel' in PATH; "
                        "the Debian package parallel)\n");
        return 1;
    }
    if (!farm_is_gnu_parallel()) {
        fprintf(stderr, "links1 farm: the 'parallel' in PATH is not GNU parallel (`parallel "
                        "--version` does not say so; moreutils has another; install the "
                        "Debian package parallel)\n");
        return 1;
    }
    return FARM_GO;
}

/* The hosts file checked and DIR opened (made when missing); the scene,
 * links1 itself and $FW_DIR (where the firmware is) made absolute, FW_DIR
 * set to it (the jobs run in DIR here and in the login directory there;
 * parallel's --env takes it to the hosts); every path resolved free of
 * control characters (a link on the way could hold a newline).  FARM_GO,
 * or an exit status after saying why. */
static int farm_resolve(struct farm_run *r)
{
    const struct farm_opts *o = r->o;
    snprintf(r->hosts_path, sizeof r->hosts_path, "Slurm");
    r->nhosts_file =
        o->backend == FARM_SLURM ? 0 : farm_check_hosts(o->hosts_file, r->hosts_path, r);
    r->dir_fd = r->nhosts_file < 0 ? -1 : farm_open_dir(o->dir, r->dir);
    if (r->dir_fd < 0 || (o->backend == FARM_PARALLEL && farm_write_slots(r) != 0))
        return 1;
    if (!realpath(o->scene, r->scene)) {
        fprintf(stderr, "links1 farm: %s: %s\n", o->scene, strerror(errno));
        return 1;
    }
    if (self_sibling("links1", r->tool, sizeof r->tool) != 0) {
        fprintf(stderr, "links1 farm: cannot tell where links1 itself is\n");
        return 1;
    }
    for (int i = 0; i < o->nextra; i++)
        if (farm_separator_word(o->extra[i])) {
            fprintf(stderr, "links1 farm: render argument '%s' is parallel's own separator\n",
                    o->extra[i]);
            return 2;
        }
    if (cmd_render_check_args(o->nextra, o->extra) != 0)
        return 2; /* render's own definitions: what every host's render would refuse */
    const char *fw_dir = getenv("FW_DIR");
    if (fw_dir && *fw_dir) {
        if (!realpath(fw_dir, r->fw_dir)) {
            fprintf(stderr, "links1 farm: $FW_DIR %s: %s\n", fw_dir, strerror(errno));
            return 1;
        }
        setenv("FW_DIR", r->fw_dir, 1);
    }
    const char *resolved[] = {r->scene, r->hosts_path, r->dir, r->tool, r->fw_dir};
    for (size_t i = 0; i < sizeof resolved / sizeof *resolved; i++)
        if (farm_plain("the resolved path", resolved[i]) != 0)
            return 1;
    return FARM_GO;
}

/* The items: frames first..last, or with --bands the bands 0..bands-1 of
 * frame first, and the run's arrays for them.  FARM_GO, 0 when that frame
 * is in DIR already (nothing to do), or 1 after saying why. */
static int farm_items(struct farm_run *r)
{
    const struct farm_opts *o = r->o;
    r->unit = o->bands ? "band" : "frame";
    r->item0 = o->bands ? 0 : o->first;
    r->nitems = o->bands ? o->bands : o->last - o->first + 1;
    if (o->bands) {
        char path[PATH_MAX + 32];
        farm_item_path(r->dir, "frame", o->first, o->ext, path, sizeof path);
        if (farm_item_there(path)) {
            printf("links1 farm: frame %ld of %s is in %s already (%s): nothing to do\n",
                   o->first, r->scene, r->dir, path);
            return 0;
        }
    }
    size_t n = (size_t)r->nitems;
    r->todo = calloc(n, sizeof *r->todo);
    r->todo_s = calloc(n, sizeof *r->todo_s);
    r->ok = calloc(n, 1);
    r->again = calloc(n, 1);
    r->hosts = calloc(FARM_MAX_HOSTS, sizeof *r->hosts);
    if (!r->todo || !r->todo_s || !r->ok || !r->again || !r->hosts) {
        fprintf(stderr, "links1 farm: out of memory\n");
        return 1;
    }
    return FARM_GO;
}

/* Round round's items: those not in DIR that may go out (round 1 all of
 * them; later only those again[] marks, and none after --retries rounds)
 * into todo; kept (round 1) and missing counted, the first 10 missing that
 * stay out named. */
static void farm_gather(struct farm_run *r, int round)
{
    const struct farm_opts *o = r->o;
    r->ntodo = 0;
    r->missing = 0;
    for (long f = r->item0; f < r->item0 + r->nitems; f++) {
        char path[PATH_MAX + 32];
        farm_item_path(r->dir, r->unit, f, o->ext, path, sizeof path);
        if (farm_item_there(path)) {
            if (round == 1)
                r->kept++;
            continue;
        }
        r->missing++;
        if (round > o->retries || (round > 1 && !r->again[f - r->item0])) {
            if (r->missing <= 10)
                fprintf(stderr, "links1 farm: %s %ld did not arrive (%s)\n", r->unit, f, path);
            continue;
        }
        r->todo[r->ntodo] = f;
        snprintf(r->todo_s[r->ntodo], sizeof r->todo_s[0], "%04ld", f);
        r->ntodo++;
    }
}

/* The line that opens a round: what is to render where (round 1), or
 * what goes out again. */
static void farm_round_say(const struct farm_run *r, int round)
{
    const struct farm_opts *o = r->o;
    char where[PATH_MAX + 64];
    if (o->backend == FARM_SLURM)
        snprintf(where, sizeof where, "as a Slurm job array");
    else
        snprintf(where, sizeof where, "on %d host(s) of %s", r->nhosts_file, r->hosts_path);
    if (round == 1 && o->bands)
        printf("links1 farm: frame %ld of %s in %d bands: %ld in %s already, %ld to render "
               "%s\n", o->first, r->scene, o->bands, r->kept, r->dir, r->ntodo, where);
    else if (round == 1)
        printf("links1 farm: frames %ld..%ld of %s: %ld in %s already, %ld to render %s\n",
               o->first, o->last, r->scene, r->kept, r->dir, r->ntodo, where);
    else if (r->ntodo > 0)
        printf("links1 farm: %ld %s(s) did not arrive; handing them out again (round "
               "%d of at most %d)\n", r->ntodo, r->unit, round, o->retries);
    fflush(stdout);
}

/* One round as a Slurm job array (farm_slurm.c).  0, or -1 after saying
 * why. */
static int farm_round_slurm(struct farm_run *r)
{
    const struct farm_opts *o = r->o;
    struct farm_slurm_round sr = {r->tool, r->scene, r->dir, o->ext, o->first, o->bands,
                                  o->extra, o->nextra, r->todo, r->ntodo};
    long jobs_round = 0;
    if (farm_slurm_run(&sr, r->hosts, &r->nhosts, &jobs_round) != 0)
        return -1;
    r->njobs += jobs_round;
    /* Slurm tries a task once: each item still missing goes out again */
    memset(r->again, 1, (size_t)r->nitems);
    return 0;
}

/* This round's joblog in DIR, farm-joblog.tsv (round 1) or
 * farm-joblog-R.tsv: its name and path in w, an earlier run's removed
 * first (never followed: DIR is yours alone, and unlinkat removes a link
 * itself).  0, or -1 after saying why. */
static int farm_joblog_fresh(const struct farm_run *r, int round, struct farm_words *w)
{
    if (round == 1)
        snprintf(w->joblog_name, sizeof w->joblog_name, "farm-joblog.tsv");
    else
        snprintf(w->joblog_name, sizeof w->joblog_name, "farm-joblog-%d.tsv", round);
    snprintf(w->joblog, sizeof w->joblog, "%s/%s", r->dir, w->joblog_name);
    if (unlinkat(r->dir_fd, w->joblog_name, 0) != 0 && errno != ENOENT) {
        fprintf(stderr, "links1 farm: %s: cannot remove an earlier run's joblog: %s\n",
                w->joblog, strerror(errno));
        return -1;
    }
    return 0;
}

/* The job's command template in w: fixed words and replacement strings
 * only.  It starts with a word of its own: parallel leaves a first
 * replacement string unquoted (it takes it for the command).  With it the
 * --return pattern and --retries. */
static void farm_template(const struct farm_run *r, struct farm_words *w)
{
    const struct farm_opts *o = r->o;
    int n = o->bands ? snprintf(w->templ, sizeof w->templ,
                                "exec {1} render {2} --frame %ld --band {3}/%d -o band-{3}.%s "
                                "--quiet", o->first, o->bands, o->ext)
                     : snprintf(w->templ, sizeof w->templ,
                                "exec {1} render {2} --frames {3}:{3} -o frame.%s --quiet",
                                o->ext);
    for (int i = 0; i < o->nextra && n < (int)sizeof w->templ; i++)
        n += snprintf(w->templ + n, sizeof w->templ - (size_t)n, " {%d}", 4 + i);
    snprintf(w->ret, sizeof w->ret, "%s-{3}.%s", r->unit, o->ext);
    snprintf(w->retries, sizeof w->retries, "%d", o->retries);
}

/* parallel's argument array for this round (NULL-ended; the caller frees
 * it), or NULL after saying so. */
static const char **farm_parallel_argv(const struct farm_run *r, const struct farm_words *w)
{
    const struct farm_opts *o = r->o;
    size_t cap = (size_t)(32 + 2 * o->nextra + r->ntodo);
    const char **av = calloc(cap, sizeof *av);
    if (!av) {
        fprintf(stderr, "links1 farm: out of memory\n");
        return NULL;
    }
    size_t k = 0;
    av[k++] = "parallel";
    av[k++] = "--will-cite";
    av[k++] = "--sshloginfile";
    av[k++] = r->slots_path;
    av[k++] = "-j100%"; /* each host's N/ (farm_write_slots) */
    av[k++] = "--retries";
    av[k++] = w->retries;
    av[k++] = "--joblog";
    av[k++] = w->joblog;
    av[k++] = "--return";
    av[k++] = w->ret;
    av[k++] = "--cleanup";
    av[k++] = "--termseq"; /* a signal to us stops the jobs, remote ones too */
    av[k++] = "TERM,200,TERM,100,KILL,25";
    if (r->fw_dir[0]) {
        av[k++] = "--env";
        av[k++] = "FW_DIR";
    }
    av[k++] = w->templ;
    av[k++] = ":::";
    av[k++] = r->tool;
    av[k++] = ":::";
    av[k++] = r->scene;
    av[k++] = ":::";
    for (long i = 0; i < r->ntodo; i++)
        av[k++] = r->todo_s[i];
    for (int i = 0; i < o->nextra; i++) {
        av[k++] = ":::";
        av[k++] = o->extra[i];
    }
    av[k] = NULL;
    return av;
}

/* parallel started with av in DIR (its standard input /dev/null) and
 * waited for, its exit status (waitpid's) in r->status.  0, or -1 after
 * saying why (it could not be started). */
static int farm_parallel_spawn(struct farm_run *r, const char *const *av)
{
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "links1 farm: fork: %s\n", strerror(errno));
        return -1;
    }
    if (pid == 0) {
        exit_clean_in_child();
        int null = open("/dev/null", O_RDONLY);
        if (null >= 0) {
            dup2(null, 0);
            close(null);
        }
        if (fchdir(r->dir_fd) != 0) {
            fprintf(stderr, "links1 farm: cd %s: %s\n", r->dir, strerror(errno));
            _exit(127);
        }
        execvp("parallel", (char *const *)av);
        fprintf(stderr, "links1 farm: cannot start parallel: %s\n", strerror(errno));
        _exit(127);
    }
    exit_clean_add_child(pid);
    while (waitpid(pid, &r->status, 0) < 0 && errno == EINTR)
        ;
    exit_clean_drop_child(pid);
    if (WIFEXITED(r->status) && WEXITSTATUS(r->status) == 127) {
        fprintf(stderr, "links1 farm: parallel did not start\n");
        return -1;
    }
    return 0;
}

/* One round through GNU parallel, its joblog read back into the summary.
 * Only an item whose job ended well goes out again (its host died before
 * the item was returned); one that failed every try does not.  0, or -1
 * after saying why. */
static int farm_round_parallel(struct farm_run *r, int round)
{
    struct farm_words w;
    if (farm_joblog_fresh(r, round, &w) != 0)
        return -1;
    farm_template(r, &w);
    const char **av = farm_parallel_argv(r, &w);
    if (!av)
        return -1;
    int rc = farm_parallel_spawn(r, av);
    free(av);
    if (rc != 0)
        return -1;
    long jobs_round = 0;
    memset(r->ok, 0, (size_t)r->nitems);
    if (farm_read_joblog(r->dir_fd, w.joblog_name, w.joblog, r->hosts, &r->nhosts, &jobs_round,
                         r->ok, r->ntodo) != 0)
        return -1;
    r->njobs += jobs_round;
    memset(r->again, 0, (size_t)r->nitems);
    for (long i = 0; i < r->ntodo; i++)
        if (r->ok[i])
            r->again[r->todo[i] - r->item0] = 1;
    return 0;
}

/* Rounds: the items not in DIR handed out; one whose job ended well but
 * which did not arrive (its host died before parallel's --return copied
 * it) is handed out again in the next round, up to --retries rounds.  0
 * once no item goes out, or -1 after saying why. */
static int farm_rounds(struct farm_run *r)
{
    for (int round = 1;; round++) {
        farm_gather(r, round);
        farm_round_say(r, round);
        if (round > 1)
            r->refarmed += r->ntodo;
        if (r->ntodo == 0)
            return 0;
        int rc = r->o->backend == FARM_SLURM ? farm_round_slurm(r) : farm_round_parallel(r, round);
        if (rc != 0)
            return -1;
    }
}

/* The summary: per host from parallel's joblogs, or the Slurm tasks' logs. */
static void farm_summary(const struct farm_run *r)
{
    const char *unit = r->unit;
    long failed = 0;
    for (int h = 0; h < r->nhosts; h++) {
        const struct farm_host *host = &r->hosts[h];
        failed += host->failed;
        printf("links1 farm: host %s: %ld %s(s) in %.1f s of jobs, %.2f %ss/min", host->name,
               host->frames, unit, host->seconds,
               host->seconds > 0 ? host->frames * 60.0 / host->seconds : 0.0, unit);
        if (host->failed)
            printf(", %ld %s(s) failed there on their last try", host->failed, unit);
        printf("\n");
    }
    long arrived = r->nitems - r->missing - r->kept;
    if (r->o->backend == FARM_SLURM)
        printf("links1 farm: %ld %s(s) rendered now, %ld kept from before, %ld missing; "
               "retries: %ld task(s) failed, %ld %s(s) handed out again (missing after a "
               "round), %ld task(s) logged in DIR/slurm-JOB_TASK.log\n",
               arrived, unit, r->kept, r->missing, failed, r->refarmed, unit, r->njobs);
    else
        printf("links1 farm: %ld %s(s) rendered now, %ld kept from before, %ld missing; "
               "retries: %ld job(s) failed on their last try, %ld %s(s) handed out again "
               "(done but not arrived), %ld job(s) in parallel's joblogs (a try parallel "
               "retried is not logged there, only each frame's last)\n",
               arrived, unit, r->kept, r->missing, failed, r->refarmed, unit, r->njobs);
}

/* After the rounds: the summary, then what is missing (exit 1), else the
 * bands stitched or the film made.  The exit status. */
static int farm_finish(const struct farm_run *r)
{
    const struct farm_opts *o = r->o;
    farm_summary(r);
    const char *film_note = o->film ? " (the film is made once every frame is there)" : "";
    if (r->missing && o->backend == FARM_SLURM) {
        fprintf(stderr, "links1 farm: %ld %s(s) missing (their tasks' logs: %s/slurm-*.log); "
                        "run again to render only those%s\n", r->missing, r->unit, r->dir,
                film_note);
        return 1;
    }
    if (r->missing) {
        fprintf(stderr, "links1 farm: %ld %s(s) missing (parallel exit %d); run again to "
                        "render only those%s\n", r->missing, r->unit,
                WIFEXITED(r->status) ? WEXITSTATUS(r->status) : -1, film_note);
        return 1;
    }
    if (o->bands)
        return farm_stitch(r->dir, o->first, o->bands, o->ext);
    return o->film ? farm_film(r->dir, o->first, o->last, o->ext, o->film, o->fps) : 0;
}

static void farm_run_free(struct farm_run *r)
{
    free(r->todo);
    free(r->todo_s);
    free(r->ok);
    free(r->again);
    free(r->hosts);
    if (r->dir_fd >= 0)
        close(r->dir_fd);
}

int cmd_farm(int argc, char **argv)
{
    struct farm_opts o;
    int rc = farm_parse(argc, argv, &o);
    if (rc == FARM_GO)
        rc = farm_check_opts(&o);
    if (rc == FARM_GO)
        rc = farm_check_tools(&o);
    if (rc != FARM_GO)
        return rc;
    struct farm_run r;
    memset(&r, 0, sizeof r);
    r.o = &o;
    r.dir_fd = -1;
    rc = farm_resolve(&r);
    if (rc == FARM_GO)
        rc = farm_items(&r);
    if (rc == FARM_GO)
        rc = farm_rounds(&r) != 0 ? 1 : farm_finish(&r);
    farm_run_free(&r);
    return rc;
}
