/*
 * watch.h — noticing that the files a model was read from change (inotify):
 * the viewer's automatic reload.  Each file's folder is watched, not the
 * file, so an editor that saves by writing a new file and renaming it over
 * the old one (and one that deletes and recreates it) is noticed too.
 */
#ifndef RAYSCAD_CLI_WATCH_H
#define RAYSCAD_CLI_WATCH_H

typedef struct cli_watch cli_watch;

/* A watch on nothing yet; NULL when inotify is not to be had. */
cli_watch *cli_watch_new(void);
void cli_watch_free(cli_watch *w);

/* Watch exactly these n files from now on (earlier ones forgotten).  A
 * file or folder that does not exist is skipped.  0, or -1 when out of
 * memory. */
int cli_watch_set(cli_watch *w, const char *const *paths, int n);

/* Wait up to timeout_ms for a change to a watched file (a write closed, a
 * file renamed or moved over it, created, deleted).  1 when one changed, 0
 * when the time passed.  Changes in a burst count once: after the first,
 * it keeps reading until the folder has been quiet for settle_ms. */
int cli_watch_wait(cli_watch *w, int timeout_ms, int settle_ms);

#endif
