/*
 * temp_file.h — whole-or-nothing output files: write to a temporary file
 * beside the target, then rename it into place.  Shared by every writer (the
 * OpenImageIO and OpenMesh adapters, the CLI's text outputs), so they agree
 * on names, permissions and clean-up.
 */
#ifndef RAYSCAD_IO_TEMP_FILE_H
#define RAYSCAD_IO_TEMP_FILE_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Create an empty temporary file in the directory of `path`, named
 * ".NAME.XXXXXX.EXT" so that it keeps path's extension (writers pick their
 * format by it), with the permissions the target should get: an existing
 * target's mode, else 0666 & ~umask.  Its name goes to tmp (tmplen bytes).
 * Returns 0, or -1 with a message in err (then nothing was created). */
int io_temp_beside(const char *path, char *tmp, size_t tmplen, char *err, size_t errlen);

/* Rename tmp over path.  Returns 0, or -1 with a message in err; on failure
 * tmp is removed and path untouched. */
int io_temp_commit(const char *tmp, const char *path, char *err, size_t errlen);

/* The whole of writing a file through a stream (temp_write.c): a temporary
 * file beside path opened as f, write(f, ctx, why, whylen) (0, or -1 with
 * its reason in why, or "" for the stream's own error), the stream's errors
 * checked, and the file renamed into place.  0, or -1 with "path: writing
 * failed: …" in err and nothing left behind. */
typedef int (*io_stream_writer)(FILE *f, void *ctx, char *why, size_t whylen);
int io_write_through_temp(const char *path, io_stream_writer write, void *ctx, char *err,
                          size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
