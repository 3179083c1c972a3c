/*
 * region_export.c — 2D exports laid out byte for byte as openscad 2021.01
 * writes them, from its export_svg.cc and export_dxf.cc:
 *
 *   SVG: a fixed header, width/height in mm and a viewBox from the bounds
 *   rounded outwards to whole units (y negated: SVG's y points down), then
 *   one <path> whose d holds every contour as "M x,y L x,y … z", a line
 *   break after every sixth point.
 *   DXF: an empty BLOCKS section (Inkscape wants one), then every edge of
 *   every contour as its own LINE on layer 0 (codes 10/20 the start, 11/21
 *   the end), then an OBJECTS section with an empty DICTIONARY.
 *
 *   PDF: openscad's A4 page, drawn by cairo (pdf.cpp); this file only
 *   opens and commits it.
 *
 * Numbers are openscad's ostream defaults: %g, six significant digits, so
 * -0 stays "-0" as it does there.  The decimal point is '.' whatever the
 * caller's locale (openscad sets LC_NUMERIC "C" around its writers).
 */
#include "region_export.h"
#include "io.h"

#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pdf.h"
#include "temp_file.h"

io_region_format io_region_format_of(const char *path)
{
    if (!path) return IO_REGION_NONE;
    if (io_path_has_extension(path, "svg")) return IO_REGION_SVG;
    if (io_path_has_extension(path, "dxf")) return IO_REGION_DXF;
    if (io_path_has_extension(path, "pdf")) return IO_REGION_PDF;
    return IO_REGION_NONE;
}

/* x as ostream << double writes it (%g), with a '.' for a decimal point. */
static const char *num(char buf[32], double x)
{
    snprintf(buf, 32, "%g", x);
    char point = localeconv()->decimal_point[0];
    if (point != '.')
        for (char *p = buf; *p; p++)
            if (*p == point) *p = '.';
    return buf;
}

static void write_svg(FILE *f, const double (*pts)[2], const int *start, int npaths)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    int any = start[npaths] > start[0];
    for (int k = start[0]; k < start[npaths]; k++)
        for (int a = 0; a < 2; a++) {
            lo[a] = fmin(lo[a], pts[k][a]);
            hi[a] = fmax(hi[a], pts[k][a]);
        }
    /* openscad: (int)floor / (int)ceil of the bounds, y negated */
    int minx = any ? (int)floor(lo[0]) : 0, miny = any ? (int)floor(-hi[1]) : 0;
    int maxx = any ? (int)ceil(hi[0]) : 0, maxy = any ? (int)ceil(-lo[1]) : 0;
    int width = maxx - minx, height = maxy - miny;
    fprintf(f,
            "<?xml version=\"1.0\" standalone=\"no\"?>\n"
            "<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" "
            "\"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n"
            "<svg width=\"%dmm\" height=\"%dmm\" viewBox=\"%d %d %d %d\" "
            "xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\">\n"
            "<title>OpenSCAD Model</title>\n"
            "<path d=\"\n",
            width, height, minx, miny, width, height);
    char bx[32], by[32];
    for (int i = 0; i < npaths; i++) {
        int k0 = start[i], n = start[i + 1] - k0;
        if (n <= 0) continue;
        fprintf(f, "M %s,%s", num(bx, pts[k0][0]), num(by, -pts[k0][1]));
        for (int idx = 1; idx < n; idx++) {
            fprintf(f, " L %s,%s", num(bx, pts[k0 + idx][0]), num(by, -pts[k0 + idx][1]));
            if (idx % 6 == 5) fputc('\n', f);
        }
        fputs(" z\n", f);
    }
    fputs("\" stroke=\"black\" fill=\"lightgray\" stroke-width=\"0.5\"/>\n</svg>\n", f);
}

static void write_dxf(FILE *f, const double (*pts)[2], const int *start, int npaths)
{
    fputs("  0\nSECTION\n  2\nBLOCKS\n  0\nENDSEC\n"
          "  0\nSECTION\n  2\nENTITIES\n",
          f);
    char b[4][32];
    for (int i = 0; i < npaths; i++) {
        int k0 = start[i], n = start[i + 1] - k0;
        for (int j = 0; j < n; j++) {
            const double *p = pts[k0 + j], *q = pts[k0 + (j + 1) % n];
            fprintf(f, "  0\nLINE\n  8\n0\n 10\n%s\n 20\n%s\n 11\n%s\n 21\n%s\n", num(b[0], p[0]),
                    num(b[1], p[1]), num(b[2], q[0]), num(b[3], q[1]));
        }
    }
    fputs("  0\nENDSEC\n"
          "  0\nSECTION\n  2\nOBJECTS\n  0\nDICTIONARY\n  0\nENDSEC\n"
          "  0\nEOF\n",
          f);
}

typedef struct region_job {
    io_region_format fmt;
    const double (*pts)[2];
    const int *start;
    int npaths;
} region_job;

static int write_region(FILE *f, void *ctx, char *why, size_t whylen)
{
    const region_job *j = ctx;
    if (j->fmt == IO_REGION_SVG)
        write_svg(f, j->pts, j->start, j->npaths);
    else if (j->fmt == IO_REGION_DXF)
        write_dxf(f, j->pts, j->start, j->npaths);
    else
        return io_pdf_write(f, j->pts, j->start, j->npaths, why, whylen);
    return 0;
}

int io_region_write(const char *path, io_region_format fmt, const double (*pts)[2],
                    const int *start, int npaths, char *err, size_t errlen)
{
    if (fmt != IO_REGION_SVG && fmt != IO_REGION_DXF && fmt != IO_REGION_PDF) {
        snprintf(err, errlen, "%s: unknown 2D format (use .svg, .dxf or .pdf)", path);
        return -1;
    }
    if (npaths < 0 || (npaths > 0 && (!pts || !start))) {
        snprintf(err, errlen, "%s: no polygon set to write", path);
        return -1;
    }
    static const int none[1] = {0};
    if (npaths == 0) start = none;
    for (int k = start[0]; k < start[npaths]; k++)
        if (!isfinite(pts[k][0]) || !isfinite(pts[k][1])) {
            snprintf(err, errlen, "%s: point %d has a coordinate that is not finite", path, k);
            return -1;
        }
    region_job job = {fmt, pts, start, npaths};
    return io_write_through_temp(path, write_region, &job, err, errlen);
}
