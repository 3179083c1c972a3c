/*
 * info.h — `rayscad --info`: what this rayscad is and runs with, as
 * `openscad --info` says what it is built with.
 */
#ifndef RAYSCAD_CLI_INFO_H
#define RAYSCAD_CLI_INFO_H

#include <stdio.h>

/* Print it to f; 0, or -1 when f could not be written. */
int cli_print_info(FILE *f);

#endif
