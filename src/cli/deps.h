/*
 * deps.h — openscad's -d (a Makefile rule naming every file a run read)
 * and -m (run a make command for a file to import that is missing), as
 * rayscad_services hooks.
 */
#ifndef RAYSCAD_CLI_DEPS_H
#define RAYSCAD_CLI_DEPS_H

#include "../../include/rayscad.h"

typedef struct cli_deps {
    const char *input;    /* the main file, listed as given */
    const char *make_cmd; /* -m, or NULL */
    char **paths;         /* every file read, once, in the order first read */
    int n, cap;
    int oom;
} cli_deps;

/* Point services' file_read and make_file at d (make_file only with a
 * make command). */
void cli_deps_hook(cli_deps *d, rayscad_services *services);

/* Write "T1 T2: \\\n\tdep \\\n\t…dep\n" to path, as openscad 2021.01 does
 * (other files absolute, the main file as given; spaces escaped).  0, or
 * -1 with a message in err. */
int cli_deps_write(const cli_deps *d, const char *path, const char *const *targets, int ntargets,
                   char *err, size_t errlen);

void cli_deps_free(cli_deps *d);

#endif
