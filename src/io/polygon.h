/*
 * polygon.h — 2D polygon booleans, offsets and Minkowski sums through
 * Clipper 6.4 (libpolyclipping), the library OpenSCAD 2021.01 uses, with
 * OpenSCAD's fixed-point scale (2^16 units per model unit) and its
 * clean-up of the results.  Nothing here prints or throws.
 */
#ifndef RAYSCAD_IO_POLYGON_H
#define RAYSCAD_IO_POLYGON_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Closed paths: path i is pts[start[i] .. start[i+1]); start has npaths + 1
 * entries (start may be NULL when npaths is 0).  A set returned here is
 * malloc'ed (free with io_paths_free), non-overlapping, with outlines
 * counter-clockwise and holes clockwise: even-odd and nonzero agree. */
typedef struct io_paths {
    double (*pts)[2];
    int *start;
    int npaths;
} io_paths;

void io_paths_free(io_paths *p);

typedef enum io_clip_op {
    IO_CLIP_UNION,
    IO_CLIP_INTERSECTION,
    IO_CLIP_DIFFERENCE, /* a minus b */
    IO_CLIP_XOR
} io_clip_op;

/* a op b, a filled by the even-odd rule when a_evenodd (else nonzero), b
 * likewise.  Either may be empty.  Coordinates must stay within ±2^46 model
 * units (Clipper's range after the 2^16 scale).  Returns 0 and *out, or -1
 * with a message in err (out of range, out of memory). */
int io_polygon_clip(io_clip_op op, const io_paths *a, int a_evenodd, const io_paths *b,
                    int b_evenodd, io_paths *out, char *err, size_t errlen);

typedef enum io_join { IO_JOIN_ROUND, IO_JOIN_MITER, IO_JOIN_SQUARE } io_join;

/* a (nonzero) offset by delta model units with ClipperOffset, as OpenSCAD's
 * ClipperUtils::applyOffset: miter_limit is in multiples of delta;
 * arc_tolerance (model units) bounds a round join's chord error.  Paths
 * are taken as they wind, so hand it a normalised set (io_polygon_clip's
 * output).  Returns 0 and *out, or -1 with a message. */
int io_polygon_offset(const io_paths *a, double delta, io_join join, double miter_limit,
                      double arc_tolerance, io_paths *out, char *err, size_t errlen);

typedef enum io_cap { IO_CAP_BUTT, IO_CAP_ROUND, IO_CAP_SQUARE } io_cap;

/* An SVG stroke as OpenSCAD 2021.01's libsvg draws it: the open polyline
 * pts[0 .. n) (n >= 1) widened by width / 2 each side with ClipperOffset
 * at libsvg's 10^4 units per model unit, mitre joins (Clipper's default
 * limit 2), ends cut by cap; arcs of round caps within Clipper's default
 * 0.25 units.  *out holds the offset's paths as it gives them (outlines
 * and holes, not cleaned).  Returns 0 and *out, or -1 with a message. */
int io_polygon_stroke(const double (*pts)[2], int n, double width, io_cap cap, io_paths *out,
                      char *err, size_t errlen);

/* The Minkowski sum a ⊕ b of two normalised sets, any shapes: the union of
 * every edge of a swept along every edge of b (parallelograms), plus a
 * moved to a point of each outline of b and b to a point of each outline of
 * a (to fill the insides).  Returns 0 and *out, or -1 with a message. */
int io_polygon_minkowski(const io_paths *a, const io_paths *b, io_paths *out, char *err,
                         size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
