/*
 * io.h — the C face of the C++ adapters: images through OpenImageIO
 * (meshes through OpenMesh come with the mesh exporter).  Nothing here prints
 * or throws: every C++ exception is caught at this boundary and becomes a
 * status with a message.
 */
#ifndef RAYSCAD_IO_H
#define RAYSCAD_IO_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Write a width × height image with `channels` (3 or 4) floats per pixel,
 * row-major from the top, values sRGB-encoded in [0, 1] (alpha straight, not
 * premultiplied).  The format follows the extension of path (png, jpg/jpeg,
 * tif/tiff, exr, …): 8-bit sRGB for LDR formats; linear half floats for
 * EXR/HDR.  The file is written to a temporary name beside path and renamed,
 * so a failure never leaves a partial file nor touches an existing one.
 * Returns 0, or -1 with a message in err. */
int io_image_write(const char *path, int width, int height, int channels,
                   const float *pixels, char *err, size_t errlen);

/* Read an image as sRGB-encoded floats (channels as stored, 1–4).  *pixels
 * is malloc'ed; the caller frees it.  Returns 0, or -1 with a message. */
int io_image_read(const char *path, int *width, int *height, int *channels, float **pixels,
                  char *err, size_t errlen);

/* 1 when the extension of path names an image format OpenImageIO can
 * write, else 0. */
int io_image_format_supported(const char *path);

#ifdef __cplusplus
}
#endif

#endif
