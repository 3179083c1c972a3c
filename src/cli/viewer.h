/*
 * viewer.h — `rayscad FILE.scad` without -o: a window on the model (SDL2),
 * orbited, panned and zoomed with the mouse as in openscad's preview,
 * rendered progressively off the event thread, reloaded when a file it
 * read changes.
 */
#ifndef RAYSCAD_CLI_VIEWER_H
#define RAYSCAD_CLI_VIEWER_H

#include <stddef.h>

#include "../../include/rayscad.h"
#include "options.h"

/* What the viewer asks of the command line: evaluate the model for the
 * view vpr/vpt/vpd (its $vp*) as a preview, printing its messages as the
 * command line prints them, and commit it.  RAYSCAD_OK with *scene (taken
 * by the viewer), its file's $vp* in *file and every file it read in
 * *files (n of them, malloc'ed strings in a malloc'ed array, taken); or a
 * failure, with the first error's text in err (and still the files read,
 * so a fix to any of them reloads). */
typedef rayscad_status (*cli_viewer_load)(void *ud, const double vpr[3], const double vpt[3],
                                          double vpd, rayscad_scene **scene,
                                          rayscad_file_view *file, char ***files, int *n, char *err,
                                          size_t errlen);

/* Run the window until it is closed or q is pressed: 0; 2 (printed) when
 * there is no display to open it on, 1 when the first load fails. */
int cli_viewer_run(const cli_options *o, cli_viewer_load load, void *ud);

#endif
