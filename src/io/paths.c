/*
 * paths.c — see io.h (io_path_has_extension).
 */
#include "io.h"

#include <ctype.h>
#include <string.h>

int io_path_has_extension(const char *path, const char *ext)
{
    size_t n = strlen(path), k = strlen(ext);
    if (n <= k || path[n - k - 1] != '.') return 0;
    for (size_t i = 0; i < k; i++)
        if (tolower((unsigned char)path[n - k + i]) != ext[i]) return 0;
    return 1;
}
