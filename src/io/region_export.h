/*
 * region_export.h — a 2D model (one polygon set) written as openscad
 * 2021.01 writes a 2D export: SVG (export_svg.cc) and DXF (export_dxf.cc),
 * text written here, and PDF (export_pdf.cc), drawn by cairo (pdf.cpp).
 */
#ifndef RAYSCAD_IO_REGION_EXPORT_H
#define RAYSCAD_IO_REGION_EXPORT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum io_region_format {
    IO_REGION_NONE = 0,
    IO_REGION_SVG,
    IO_REGION_DXF,
    IO_REGION_PDF
} io_region_format;

/* The format path's extension (any case) names, or IO_REGION_NONE. */
io_region_format io_region_format_of(const char *path);

/* Write the closed paths pts[start[i] .. start[i+1]) (x, y pairs, model
 * units; start holds npaths + 1 entries, npaths >= 0) to path in format
 * fmt.  SVG and DXF points are written as openscad's ostream writes
 * doubles (six significant digits, %g); PDF is openscad's A4 page with
 * the outlines stroked (pdf.h).  The file goes to a temporary name beside
 * path (io_temp_beside), renamed into place once flushed and closed: a
 * failure leaves no partial file and an existing one untouched.  Returns 0, or -1
 * with a message in err (errlen bytes); a coordinate that is not finite
 * is refused before a byte is written. */
int io_region_write(const char *path, io_region_format fmt, const double (*pts)[2],
                    const int *start, int npaths, char *err, size_t errlen);

/* 0 when openscad 2021.01's PDF export would warn "Geometry is too large
 * to fit into A4 size." for these paths (pdf.cpp: a point past the page by
 * its test, which skips each path's first point and truncates to whole
 * points), else 1.  The paths as io_region_write takes them. */
int io_region_fits_pdf_page(const double (*pts)[2], const int *start, int npaths);

#ifdef __cplusplus
}
#endif

#endif
