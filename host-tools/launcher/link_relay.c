/* link_relay.c: the noisy relay of --link-noise (see link_relay.h). */
#include "host-tools/launcher/link_relay.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/launcher/link_noise.h"

#define RELAY_BUF 65536
#define RELAY_READ 4096 /* read at most this much at once: its damage fits twice */

struct relay_dir {
    int from, to;
    struct link_noise noise;
    uint8_t buf[RELAY_BUF];
    size_t head, tail; /* bytes buf[head..tail) wait to be written */
};

struct relay {
    struct relay_dir dir[2]; /* 0: tool -> QEMU, 1: QEMU -> tool */
};

/* Reads what from has (when there is room) and damages it; 0, or -1 at the
 * end of that side. */
static int relay_fill(struct relay_dir *d)
{
    /* One read's worth in the relay at a time, like a line, not a queue. */
    if (d->head != d->tail)
        return 0;
    d->head = d->tail = 0;
    uint8_t in[RELAY_READ];
    ssize_t n = read(d->from, in, sizeof in);
    if (n == 0)
        return -1;
    if (n < 0)
        return errno == EAGAIN || errno == EINTR ? 0 : -1;
    d->tail += link_noise_apply(&d->noise, in, (size_t)n, d->buf + d->tail);
    return 0;
}

static int relay_drain(struct relay_dir *d)
{
    if (d->head == d->tail)
        return 0;
    ssize_t n = write(d->to, d->buf + d->head, d->tail - d->head);
    if (n < 0)
        return errno == EAGAIN || errno == EINTR ? 0 : -1;
    d->head += (size_t)n;
    return 0;
}

static void *relay_thread(void *arg)
{
    struct relay *r = arg;
    for (;;) {
        struct pollfd p[4];
        for (int k = 0; k < 2; k++) {
            struct relay_dir *d = &r->dir[k];
            p[2 * k].fd = d->from;
            p[2 * k].events = RELAY_BUF - d->tail >= 2 * RELAY_READ || d->head == d->tail
                                  ? POLLIN : 0;
            p[2 * k + 1].fd = d->to;
            p[2 * k + 1].events = d->head != d->tail ? POLLOUT : 0;
        }
        if (poll(p, 4, -1) < 0 && errno != EINTR)
            break;
        int end = 0;
        for (int k = 0; k < 2; k++) {
            struct relay_dir *d = &r->dir[k];
            if (p[2 * k].revents & (POLLIN | POLLHUP | POLLERR))
                end |= relay_fill(d) < 0;
            if (p[2 * k + 1].revents & (POLLOUT | POLLERR | POLLHUP))
                end |= relay_drain(d) < 0;
        }
        if (end) {
            /* Hand on what is already through, then end both sides. */
            for (int k = 0; k < 2; k++) {
                struct relay_dir *d = &r->dir[k];
                int fl = fcntl(d->to, F_GETFL);
                fcntl(d->to, F_SETFL, fl & ~O_NONBLOCK);
                while (d->head != d->tail && relay_drain(d) == 0) {
                }
            }
            break;
        }
    }
    close(r->dir[0].from);
    close(r->dir[0].to);
    free(r);
    return NULL;
}

int link_relay_start(int tool_fd, int qemu_fd, double rate, uint64_t seed)
{
    struct relay *r = calloc(1, sizeof *r);
    if (!r) {
        fprintf(stderr, "links1: --link-noise: out of memory\n");
        return -1;
    }
    r->dir[0].from = tool_fd;
    r->dir[0].to = qemu_fd;
    r->dir[1].from = qemu_fd;
    r->dir[1].to = tool_fd;
    link_noise_init(&r->dir[0].noise, rate, seed);
    link_noise_init(&r->dir[1].noise, rate, seed ^ 0x9E3779B97F4A7C15ull);
    fcntl(tool_fd, F_SETFL, fcntl(tool_fd, F_GETFL) | O_NONBLOCK);
    fcntl(qemu_fd, F_SETFL, fcntl(qemu_fd, F_GETFL) | O_NONBLOCK);
    pthread_t th;
    int e = pthread_create(&th, NULL, relay_thread, r);
    if (e != 0) {
        fprintf(stderr, "links1: --link-noise: cannot start the relay: %s\n", strerror(e));
        free(r);
        return -1;
    }
    pthread_detach(th);
    return 0;
}
