/*
 * pdf.h — a 2D model's polygon set drawn on one A4 page as openscad
 * 2021.01 draws its PDF export (export_pdf.cc), through cairo.  Private to
 * src/io: region_export.c opens the file and calls it; the page-size test
 * (io_region_fits_pdf_page) is declared in region_export.h.
 */
#ifndef RAYSCAD_IO_PDF_H
#define RAYSCAD_IO_PDF_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Draw the closed paths pts[start[i] .. start[i+1]) (x, y pairs in mm;
 * start holds npaths + 1 entries, npaths >= 0, every coordinate finite)
 * and openscad's rulers onto f (opened for writing, binary), as one PDF
 * page of 595 x 842 points.  The outlines are stroked in black, one point
 * wide, unfilled, as openscad strokes them.  Returns 0, or -1 with
 * cairo's or the stream's message in err (errlen bytes); f is left open
 * either way, its contents then unusable. */
int io_pdf_write(FILE *f, const double (*pts)[2], const int *start, int npaths, char *err,
                 size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
