/*
 * temp_write.c — see temp_file.h (io_write_through_temp).
 */
#include "temp_file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int io_write_through_temp(const char *path, io_stream_writer write, void *ctx, char *err,
                          size_t errlen)
{
    size_t tmplen = strlen(path) + 64;
    char *tmp = malloc(tmplen);
    if (!tmp) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    if (io_temp_beside(path, tmp, tmplen, err, errlen) != 0) {
        free(tmp);
        return -1;
    }
    errno = 0;
    FILE *f = fopen(tmp, "wb");
    int saved = errno, failed = !f;
    char why[256] = "";
    if (f) {
        errno = 0;
        if (write(f, ctx, why, sizeof why) != 0) failed = 1;
        failed = failed || ferror(f);
        saved = errno;
        if (fclose(f) != 0 && !failed) {
            failed = 1;
            saved = errno;
        }
    }
    if (failed) {
        unlink(tmp);
        free(tmp);
        if (why[0])
            snprintf(err, errlen, "%s: writing failed: %s", path, why);
        else
            snprintf(err, errlen, "%s: writing failed%s%s", path, saved ? ": " : "",
                     saved ? strerror(saved) : "");
        return -1;
    }
    int rc = io_temp_commit(tmp, path, err, errlen);
    free(tmp);
    return rc;
}
