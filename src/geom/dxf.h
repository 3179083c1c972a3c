/*
 * dxf.h — OpenSCAD 2021.01's DXF reader (its DxfData), for import() of a
 * .dxf as a 2D region, dxf_dim() and dxf_cross().  It reads text the
 * caller supplies (the language reads the file through its services).
 */
#ifndef RAYSCAD_GEOM_DXF_H
#define RAYSCAD_GEOM_DXF_H

#include <stddef.h>

/* What to read: one layer or all, OpenSCAD's origin and scale, and the
 * $fn/$fa/$fs that cut circles, arcs and ellipses into segments. */
typedef struct geom_dxf_params {
    const char *layer; /* NULL or "": every layer */
    double xorigin, yorigin, scale;
    double fn, fa, fs;
} geom_dxf_params;

/* A DIMENSION entity: group 70 (type), the points of groups 10..16 / 20..26
 * with origin and scale applied as OpenSCAD applies them, group 50 (angle)
 * and group 40 (leader length); name is group 1 (owned). */
typedef struct geom_dxf_dim {
    int type;
    double coords[7][2];
    double angle, length;
    char *name;
} geom_dxf_dim;

/* The drawing: every point added (two per segment), the segments joined
 * into paths — path i is pts[idx[path_start[i]]], … up to path_start[i+1];
 * the open paths come first, then the closed ones, whose last point
 * repeats the first (within the 0.001 grid) — and the dimensions. */
typedef struct geom_dxf {
    double (*pts)[2];
    int npts;
    int *idx, *path_start;
    int npaths;
    unsigned char *closed; /* per path */
    geom_dxf_dim *dims;
    int ndims;
} geom_dxf;

/* Messages of the reader: kind GEOM_DXF_WARNING for OpenSCAD's own
 * warnings (text as OpenSCAD words them, without "WARNING: "), or
 * GEOM_DXF_NOTE when one of rayscad's limits was hit. */
enum { GEOM_DXF_WARNING, GEOM_DXF_NOTE };
typedef void (*geom_dxf_message_fn)(void *ud, int kind, const char *text);

/* Reads the DXF text (len bytes) into *out, as OpenSCAD 2021.01's DxfData
 * does: LINE, LWPOLYLINE, CIRCLE, ARC, ELLIPSE, INSERT of BLOCKs and
 * DIMENSION; other entities are counted in a warning.  Points snap to a
 * 0.001 grid; segments join into paths where their ends meet on it.
 * abs_path and rel_path name the file in messages, as OpenSCAD names it
 * (absolute; relative to the working folder).  Segments are capped
 * (GEOM_DXF_MAX_SEGMENTS) and the joining's work is bounded, so any input
 * ends.  Returns 0, or -1 when out of memory (*out then empty).  Free *out
 * with geom_dxf_free. */
int geom_dxf_read(const char *text, size_t len, const char *abs_path, const char *rel_path,
                  const geom_dxf_params *p, geom_dxf_message_fn msg, void *ud, geom_dxf *out);
void geom_dxf_free(geom_dxf *d);

enum { GEOM_DXF_MAX_SEGMENTS = 1000000 };

/* The drawing as OpenSCAD's toPolygon2d makes it, for iv_region_new: one
 * closed outline per path of at least 3 points (open paths closed, the
 * repeated end of closed ones dropped).  *pts and *start (npaths + 1
 * entries) are malloc'd, owned by the caller.  Returns 0 (*npaths may be
 * 0), or -1 when out of memory. */
int geom_dxf_outlines(const geom_dxf *d, double (**pts)[2], int **start, int *npaths);

#endif
