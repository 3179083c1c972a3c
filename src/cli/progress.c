/*
 * progress.c — see progress.h.  Redraws only when the whole percentage
 * changes, so a fast render does not flood the terminal.
 */
#include "progress.h"

#include <stdio.h>
#include <unistd.h>

void progress_start(progress *p, const char *label)
{
    p->label = label;
    p->enabled = label && isatty(STDERR_FILENO); /* NULL label: silent (-q) */
    p->last = -1;
    clock_gettime(CLOCK_MONOTONIC, &p->t0);
}

void progress_update(void *ud, double done)
{
    progress *p = ud;
    if (!p->enabled) return;
    int pct = (int)(done * 100.0 + 0.5);
    if (pct < 0) pct = 0;
    if (pct > 100) pct = 100;
    if (pct == p->last) return;
    p->last = pct;
    enum { WIDTH = 40 };
    char bar[WIDTH + 1];
    int fill = pct * WIDTH / 100;
    for (int i = 0; i < WIDTH; i++)
        bar[i] = i < fill ? '#' : '.';
    bar[WIDTH] = '\0';
    /* The time left if the rest goes as fast as what is done: said once
     * a few percent are in, to the second. */
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    double spent = (double)(t.tv_sec - p->t0.tv_sec) + 1e-9 * (double)(t.tv_nsec - p->t0.tv_nsec);
    char left[32] = "";
    if (pct >= 3 && pct < 100 && done > 0)
        snprintf(left, sizeof left, ", %.0f s left", spent * (1 - done) / done);
    fprintf(stderr, "\r%s [%s] %3d%%%-16s", p->label, bar, pct, left);
    fflush(stderr);
}

void progress_phase(void *ud, const char *phase, double done)
{
    progress *p = ud;
    if (!p->enabled) return;
    if (p->label != phase) {
        progress_finish(p);
        progress_start(p, phase);
    }
    progress_update(p, done);
}

void progress_finish(progress *p)
{
    if (p->enabled && p->last >= 0) fprintf(stderr, "\n");
}
