/*
 * atomic_file.h — write a whole file or nothing: the bytes go to a temporary
 * file beside the target, which is renamed over it only once complete.
 */
#ifndef RAYSCAD_CLI_ATOMIC_FILE_H
#define RAYSCAD_CLI_ATOMIC_FILE_H

#include <stddef.h>

/* Returns 0, or -1 with a message in err; on failure the target is untouched
 * and no temporary file is left behind. */
int atomic_file_write(const char *path, const char *data, size_t len, char *err,
                      size_t errlen);

#endif
