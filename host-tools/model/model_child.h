/* model_child.h: a model file read in a child process, so that the model
 * library (libassimp, which crashes, aborts or loops on some malformed
 * files) cannot take the program down with it.  The child reads the file
 * and hands the model back as bytes (model_wire.h); the parent takes at
 * most max_bytes, waits at most timeout_ms, checks what it got, and names
 * what happened when the child crashed, failed, ran too long or sent
 * something malformed.  model_load (model.h) is this with
 * model_assimp_load and the default limits. */
#ifndef LINKS1_HOST_SCENE_MODEL_CHILD_H
#define LINKS1_HOST_SCENE_MODEL_CHILD_H

#include <stddef.h>

#include "host-tools/model/model.h"

#define MODEL_CHILD_TIMEOUT_MS 120000u             /* the default time limit */
#define MODEL_CHILD_MAX_BYTES (1024u * 1024u * 1024u) /* the default size limit */
/* The child's own limits (setrlimit in the child): CPU seconds
 * (RLIMIT_CPU: SIGXCPU, then SIGKILL a second later), and the memory it
 * may add to the address space it had when it started (RLIMIT_AS: what it
 * started with counts too, which under ASan is terabytes of shadow). */
#define MODEL_CHILD_CPU_S 100u
#define MODEL_CHILD_MEMORY_MB 4096u

struct model_child_limits {
    unsigned timeout_ms;
    size_t max_bytes;
    unsigned cpu_s;         /* 0: MODEL_CHILD_CPU_S */
    unsigned memory_mb;     /* 0: MODEL_CHILD_MEMORY_MB */
};

/* fd, open as path, is a regular file of at most max bytes (what the
 * parent checks of the model, and what model_assimp_load checks of every
 * file the library opens: its MTL, buffers, ...).  0, or -1 with "PATH: not
 * a regular file (a FIFO): not read" or "PATH: N bytes, more than MAX: not
 * read" in err. */
int model_file_check(int fd, const char *path, size_t max, char *err, size_t errlen);

/* A loader run in the child: model_load's contract (model.h). */
typedef int (*model_loader_fn)(const char *path, struct model *m, char *err, size_t errlen);

/* load(path) in a child process within lim, once path is seen to be a
 * regular file (opened O_NONBLOCK: a FIFO is refused at once, "PATH: not a
 * regular file (a FIFO): not read").  0 with *m filled, or -1 with
 * "PATH: what happened" in err and *m empty. */
int model_child_load(const char *path, model_loader_fn load, const struct model_child_limits *lim,
                     struct model *m, char *err, size_t errlen);

#endif
