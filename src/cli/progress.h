/*
 * progress.h — a progress bar on stderr with an estimate of the time left,
 * drawn only when stderr is a terminal (and not with -q: a NULL label).
 */
#ifndef RAYSCAD_CLI_PROGRESS_H
#define RAYSCAD_CLI_PROGRESS_H

#include <time.h>

typedef struct progress {
    const char *label;
    int enabled;
    int last; /* last percentage drawn, -1 before the first */
    struct timespec t0;
    double delay; /* seconds before the first drawing */
    double drawn; /* when it last drew, seconds from t0 */
} progress;

void progress_start(progress *p, const char *label);
/* A bar that shows only once `delay` seconds have passed (a short phase
 * draws nothing) and then, while the share done stands still, redraws
 * each second with the time spent. */
void progress_start_after(progress *p, const char *label, double delay);
/* Something else is about to be printed on stderr: erase the bar (the
 * next update draws it again, below what was printed). */
void progress_break(progress *p);
/* A render_options.progress callback: ud is the progress, done in [0, 1]. */
void progress_update(void *ud, double done);
void progress_finish(progress *p);
/* A mesh_options.progress callback: a new phase's name ends the bar drawn
 * so far and starts one of its own (labels are the library's static
 * strings). */
void progress_phase(void *ud, const char *phase, double done);

/* Seconds on the monotonic clock (for spans of time: deadlines, timings). */
double cli_now_s(void);

#endif
