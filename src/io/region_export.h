/*
 * region_export.h — a 2D model (one polygon set) written as openscad
 * 2021.01 writes a 2D export: SVG (export_svg.cc) and DXF (export_dxf.cc).
 * C, no library: both are text.
 */
#ifndef RAYSCAD_IO_REGION_EXPORT_H
#define RAYSCAD_IO_REGION_EXPORT_H

#include <stddef.h>

typedef enum io_region_format { IO_REGION_NONE = 0, IO_REGION_SVG, IO_REGION_DXF } io_region_format;

/* The format path's extension (any case) names, or IO_REGION_NONE. */
io_region_format io_region_format_of(const char *path);

/* Write the closed paths pts[start[i] .. start[i+1]) (x, y pairs, model
 * units; start holds npaths + 1 entries, npaths >= 0) to path in format
 * fmt.  Points are written as openscad's ostream writes doubles (six
 * significant digits, %g).  The file goes to a temporary name beside path
 * (io_temp_beside), renamed into place once flushed and closed: a failure
 * leaves no partial file and an existing one untouched.  Returns 0, or -1
 * with a message in err (errlen bytes); a coordinate that is not finite
 * is refused before a byte is written. */
int io_region_write(const char *path, io_region_format fmt, const double (*pts)[2],
                    const int *start, int npaths, char *err, size_t errlen);

#endif
