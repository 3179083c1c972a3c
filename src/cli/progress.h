/*
 * progress.h — a progress bar on stderr, drawn only when stderr is a
 * terminal.
 */
#ifndef RAYSCAD_CLI_PROGRESS_H
#define RAYSCAD_CLI_PROGRESS_H

typedef struct progress {
    const char *label;
    int enabled;
    int last; /* last percentage drawn, -1 before the first */
} progress;

void progress_start(progress *p, const char *label);
/* A render_options.progress callback: ud is the progress, done in [0, 1]. */
void progress_update(void *ud, double done);
void progress_finish(progress *p);

#endif
