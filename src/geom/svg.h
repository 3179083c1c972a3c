/*
 * svg.h — OpenSCAD 2021.01's SVG reader (its libsvg and import_svg), for
 * import() of a .svg as a 2D region.  It reads bytes the caller supplies
 * (the language reads the file through its services); the XML is parsed
 * with libxml2 (svg_parse.c), the geometry is svg.c's.
 *
 * What comes out is libsvg's shape list: per drawing element its outlines
 * in its own user units, the open lines that are to be stroked (OpenSCAD
 * widens them with ClipperOffset, which the caller supplies), and the
 * matrix of the transforms of the element and of its enclosing groups.
 * geom_svg_frame then places them on OpenSCAD's page: millimetres, y up.
 */
#ifndef RAYSCAD_GEOM_SVG_H
#define RAYSCAD_GEOM_SVG_H

#include <stddef.h>

/* stroke-linecap, as Clipper's open end types (square unless told). */
enum { GEOM_SVG_CAP_BUTT, GEOM_SVG_CAP_ROUND, GEOM_SVG_CAP_SQUARE };

/* A length attribute: number and unit (libsvg's unit_t). */
typedef enum geom_svg_unit {
    GEOM_SVG_UNIT_NONE,
    GEOM_SVG_UNIT_PX,
    GEOM_SVG_UNIT_PT,
    GEOM_SVG_UNIT_PC,
    GEOM_SVG_UNIT_IN,
    GEOM_SVG_UNIT_CM,
    GEOM_SVG_UNIT_MM,
    GEOM_SVG_UNIT_EM,
    GEOM_SVG_UNIT_EX,
    GEOM_SVG_UNIT_PERCENT,
    GEOM_SVG_UNIT_UNDEFINED /* missing or not a length */
} geom_svg_unit;

typedef struct geom_svg_length {
    double number;
    geom_svg_unit unit;
} geom_svg_length;

enum { GEOM_SVG_ALIGN_NONE, GEOM_SVG_ALIGN_MIN, GEOM_SVG_ALIGN_MID, GEOM_SVG_ALIGN_MAX };

/* An <svg> element: width, height, viewBox and preserveAspectRatio. */
typedef struct geom_svg_page {
    geom_svg_length width, height;
    double vb[4]; /* viewBox x, y, width, height, when vb_valid */
    int vb_valid;
    int align_x, align_y, meet;
} geom_svg_page;

/* One drawing element.  Its paths are paths[first .. first + count) of
 * the document; world_from_local = (a b c d e f) maps (x, y) to
 * (a x + c y + e, b x + d y + f).  page: the last <svg> element before it
 * in the document (-1: none), whose scale OpenSCAD measures it with. */
typedef struct geom_svg_shape {
    double world_from_local[6];
    int first, count;
    double stroke_width; /* user units, for its open paths */
    int cap;             /* GEOM_SVG_CAP_* */
    int page;
} geom_svg_shape;

/* The document: every path's points (path i is pts[start[i] ..
 * start[i+1])); stroke[i] is 1 for an open line to be widened by the
 * shape's stroke (ClipperOffset, mitre joins, the shape's cap), 0 for an
 * outline taken as it is (filled even-odd with the shape's others). */
typedef struct geom_svg {
    double (*pts)[2];
    int npts, cappts;
    int *start;
    unsigned char *stroke;
    int npaths, cappaths;
    geom_svg_shape *shapes;
    int nshapes, capshapes;
    geom_svg_page *pages;
    int npages, cappages;
} geom_svg;

/* At most this many points in a document (the rest is dropped). */
enum { GEOM_SVG_MAX_POINTS = 10000000 };

/* Reads the SVG bytes (len) into *out as OpenSCAD 2021.01's libsvg does:
 * svg, g, path, rect, circle, ellipse, line, polyline and polygon; text,
 * use and the elements inside defs draw nothing.  Returns 0; 1 when the
 * XML does not parse (why, with its line and column in the SVG file, in
 * err); -1 when out of memory.  Free *out with geom_svg_free (after any
 * return). */
int geom_svg_read(const char *bytes, size_t len, geom_svg *out, char *err, size_t errlen);
void geom_svg_free(geom_svg *d);

/* ---- the pieces, for svg_parse.c and the tests ---- */

/* Attribute lookup of the element being read: its value or NULL. */
typedef const char *(*geom_svg_attr_fn)(void *ud, const char *name);

/* The element `name` with its attributes, drawn into d as libsvg draws it
 * (a shape is added even when it has no paths; elements that draw nothing
 * add nothing).  m is the matrix of its enclosing groups, NULL when it has
 * none (the document's root: libsvg leaves out its own transform too).
 * 0 or -1 (out of memory). */
int geom_svg_add_element(geom_svg *d, const char *name, geom_svg_attr_fn attr, void *ud,
                         const double m[6]);

/* out = m · (the transform attribute text), libsvg's reading of it. */
void geom_svg_transform(const char *text, const double m[6], double out[6]);

/* libsvg's parse_double: the whole text a number, else 0. */
double geom_svg_number(const char *text);
geom_svg_length geom_svg_parse_length(const char *text);

/* Millimetres per user unit (x, y) after page `page` (-1: none, 1 and 1)
 * at dpi, as import_svg measures it. */
void geom_svg_scale(const geom_svg *d, int page, double dpi, double s[2]);

/* Where a point lands: (s[0] (x - vb_x) - c[0], s[1] (-vb_y - y) + c[1]). */
typedef struct geom_svg_frame {
    double s[2], vb[2], c[2];
} geom_svg_frame;

/* import_svg's placement, from the last page: bbox (xmin, ymin, xmax,
 * ymax) is that of every point scaled by its shape's geom_svg_scale, for
 * center (empty: xmin > xmax). */
void geom_svg_frame_of(const geom_svg *d, double dpi, int center, const double bbox[4],
                       geom_svg_frame *f);

#endif
