/*
 * progress.c — see progress.h.  Redraws only when the whole percentage
 * changes, so a fast render does not flood the terminal.
 */
#include "progress.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

double cli_now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void progress_start(progress *p, const char *label)
{
    p->label = label;
    p->enabled = label && isatty(STDERR_FILENO); /* NULL label: silent (-q) */
    p->last = -1;
    p->delay = 0;
    p->drawn = 0;
    clock_gettime(CLOCK_MONOTONIC, &p->t0);
}

void progress_start_after(progress *p, const char *label, double delay)
{
    progress_start(p, label);
    p->delay = delay;
}

void progress_break(progress *p)
{
    if (p->enabled && p->last >= 0) fprintf(stderr, "\r\033[K"); /* the line erased */
    p->last = -1;
}

void progress_update(void *ud, double done)
{
    progress *p = ud;
    if (!p->enabled) return;
    int pct = (int)(done * 100.0 + 0.5);
    if (pct < 0) pct = 0;
    if (pct > 100) pct = 100;
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    double spent = (double)(t.tv_sec - p->t0.tv_sec) + 1e-9 * (double)(t.tv_nsec - p->t0.tv_nsec);
    if (spent < p->delay) return;
    if (pct == p->last && !(p->delay > 0 && spent - p->drawn >= 1)) return;
    p->last = pct;
    p->drawn = spent;
    enum { WIDTH = 40 };
    char bar[WIDTH + 1];
    int fill = pct * WIDTH / 100;
    for (int i = 0; i < WIDTH; i++)
        bar[i] = i < fill ? '#' : '.';
    bar[WIDTH] = '\0';
    /* The time left if the rest goes as fast as what is done: said once
     * a few percent are in, to the second; for a delayed bar (whose share
     * may stand still) the time spent too. */
    char left[48] = "";
    if (pct >= 3 && pct < 100 && done > 0)
        snprintf(left, sizeof left, ", %.0f s left", spent * (1 - done) / done);
    if (p->delay > 0) {
        size_t n = strlen(left);
        snprintf(left + n, sizeof left - n, " (%.0f s)", spent);
    }
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
