/*
 * region.c — a 2D model's polygon set (evaluated with for_2d, kept in the
 * scad_result) and its SVG, DXF and PDF exports (src/io/region_export.c,
 * src/io/pdf.cpp).
 */
#include "../io/region_export.h"
#include "rayscad_internal.h"

rayscad_status rayscad_model_region(const rayscad_model *m, const double **points,
                                    const int **path_start, int *path_count)
{
    if (!m || m->r.region.npaths <= 0) return RAYSCAD_ERROR_ARGUMENT;
    if (points) *points = &m->r.region.pts[0][0];
    if (path_start) *path_start = m->r.region.start;
    if (path_count) *path_count = m->r.region.npaths;
    return RAYSCAD_OK;
}

int rayscad_region_format_supported(const char *path)
{
    return io_region_format_of(path) != IO_REGION_NONE;
}

int rayscad_region_fits_pdf_page(const rayscad_model *m)
{
    if (!m || m->r.region.npaths <= 0) return 1;
    const scad_paths *p = &m->r.region;
    return io_region_fits_pdf_page((const double(*)[2])p->pts, p->start, p->npaths);
}

rayscad_status rayscad_region_write(const rayscad_model *m, const char *path, char *err,
                                    size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    if (!path || !rayscad_region_format_supported(path)) {
        rayscad_say(err, errlen, "%s: unknown 2D format (use .svg, .dxf or .pdf)",
                    path ? path : "");
        return RAYSCAD_ERROR_ARGUMENT;
    }
    if (!m || m->r.region.npaths <= 0) {
        rayscad_say(err, errlen, "%s: the model was not evaluated as a 2D model", path);
        return RAYSCAD_ERROR_ARGUMENT;
    }
    const scad_paths *p = &m->r.region;
    return io_region_write(path, io_region_format_of(path), (const double(*)[2])p->pts, p->start,
                           p->npaths, err, errlen) == 0
               ? RAYSCAD_OK
               : RAYSCAD_ERROR;
}
