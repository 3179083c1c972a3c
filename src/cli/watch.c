/*
 * watch.c — see watch.h.
 */
#define _DEFAULT_SOURCE /* strdup */
#include "watch.h"

#include <errno.h>
#include <limits.h>
#include <poll.h>
#include <stdlib.h>
#include <string.h>
#include <sys/inotify.h>
#include <unistd.h>

enum { MASK = IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_ATTRIB | IN_MOVED_FROM };

typedef struct watched {
    int wd;     /* the folder's watch */
    char *name; /* the file's name within it */
} watched;

struct cli_watch {
    int fd;
    watched *w;
    int n;
};

cli_watch *cli_watch_new(void)
{
    cli_watch *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    w->fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (w->fd < 0) {
        free(w);
        return NULL;
    }
    return w;
}

static void forget(cli_watch *w)
{
    for (int i = 0; i < w->n; i++) {
        int seen = 0; /* a folder's watch is shared by its files */
        for (int j = 0; j < i; j++)
            seen |= w->w[j].wd == w->w[i].wd;
        if (!seen && w->w[i].wd >= 0) inotify_rm_watch(w->fd, w->w[i].wd);
        free(w->w[i].name);
    }
    free(w->w);
    w->w = NULL;
    w->n = 0;
}

void cli_watch_free(cli_watch *w)
{
    if (!w) return;
    forget(w);
    close(w->fd);
    free(w);
}

int cli_watch_set(cli_watch *w, const char *const *paths, int n)
{
    forget(w);
    w->w = calloc(n > 0 ? (size_t)n : 1, sizeof *w->w);
    if (!w->w) return -1;
    for (int i = 0; i < n; i++) {
        char *dir = strdup(paths[i]);
        if (!dir) return -1;
        char *slash = strrchr(dir, '/');
        const char *name = strrchr(paths[i], '/') ? strrchr(paths[i], '/') + 1 : paths[i];
        if (slash == dir)
            dir[1] = '\0';
        else if (slash)
            *slash = '\0';
        else
            strcpy(dir, ".");
        int wd = inotify_add_watch(w->fd, dir, MASK);
        free(dir);
        if (wd < 0) continue; /* gone, or not ours to watch: nothing to notice */
        w->w[w->n].wd = wd;
        w->w[w->n].name = strdup(name);
        if (!w->w[w->n].name) return -1;
        w->n++;
    }
    return 0;
}

/* Read what is pending; 1 when an event names a watched file. */
static int drain(cli_watch *w)
{
    char buf[4096] __attribute__((aligned(__alignof__(struct inotify_event))));
    int hit = 0;
    for (;;) {
        ssize_t len = read(w->fd, buf, sizeof buf);
        if (len <= 0) return hit;
        for (char *p = buf; p < buf + len;) {
            const struct inotify_event *e = (const struct inotify_event *)p;
            for (int i = 0; i < w->n && !hit; i++)
                hit = w->w[i].wd == e->wd && e->len && !strcmp(w->w[i].name, e->name);
            p += sizeof *e + e->len;
        }
    }
}

int cli_watch_wait(cli_watch *w, int timeout_ms, int settle_ms)
{
    struct pollfd p = {.fd = w->fd, .events = POLLIN};
    if (poll(&p, 1, timeout_ms) <= 0) return 0;
    if (!drain(w)) return 0;
    while (poll(&p, 1, settle_ms) > 0) /* the rest of the burst */
        drain(w);
    return 1;
}
