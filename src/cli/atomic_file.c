/*
 * atomic_file.c — see atomic_file.h.  The temporary file comes from the io
 * module's io_temp_beside, like every other output, so permissions and
 * clean-up are the same for text, images and meshes.
 */
#include "atomic_file.h"

#include "../io/temp_file.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

int atomic_file_write(const char *path, const char *data, size_t len, char *err, size_t errlen)
{
    char tmp[4096];
    if (io_temp_beside(path, tmp, sizeof tmp, err, errlen) != 0) return -1;
    FILE *f = fopen(tmp, "wb");
    int bad = !f || fwrite(data, 1, len, f) != len;
    int saved = errno;
    if (f && fclose(f) != 0 && !bad) {
        bad = 1;
        saved = errno;
    }
    if (bad) {
        snprintf(err, errlen, "cannot write '%s': %s", path, strerror(saved));
        unlink(tmp);
        return -1;
    }
    return io_temp_commit(tmp, path, err, errlen);
}
