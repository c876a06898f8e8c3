/* capture.h: what a host test's code under test prints on stdout or
 * stderr, caught in a temporary file and handed back as a string. */
#ifndef LINKS1_TESTS_CAPTURE_H
#define LINKS1_TESTS_CAPTURE_H

#include <stdio.h>
#include <unistd.h>

struct capture {
    int saved, fd;
    FILE *f;
};

/* From now on, what goes to which (STDOUT_FILENO or STDERR_FILENO) is caught. */
static inline void capture_begin(struct capture *c, int which)
{
    fflush(stdout);
    fflush(stderr);
    c->f = tmpfile();
    c->fd = which;
    c->saved = dup(which);
    if (c->f)
        dup2(fileno(c->f), which);
}

/* Ends the catch: what was printed, terminated, into out; its length. */
static inline size_t capture_end(struct capture *c, char *out, size_t cap)
{
    fflush(stdout);
    fflush(stderr);
    dup2(c->saved, c->fd);
    close(c->saved);
    size_t n = 0;
    if (c->f) {
        rewind(c->f);
        n = fread(out, 1, cap - 1, c->f);
        fclose(c->f);
    }
    out[n] = 0;
    return n;
}

#endif
