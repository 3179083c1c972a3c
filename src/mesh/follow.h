/*
 * follow.h — private to src/mesh: a ray's boundaries followed along a line
 * of parallel rays without casting more (follow.c).
 *
 * Every boundary lies on a plane or a quadric (csg_scene_quadric).  On the
 * rays x(u, t) = p0 + u·e1 + t·d of a line, that surface is the zeros of
 * al t² + (bu u + bt) t + (cu2 u² + cu1 u + c0), so the boundary's t is a
 * root of a quadratic in t whose coefficients are polynomials in u — the
 * same root, by the sign of ∂q/∂t, until the ray passes the surface's
 * silhouette.  A ray's boundaries thus say what every ray of the line
 * crosses as long as the list keeps its make-up, and where the make-up can
 * change: where a boundary reaches its silhouette, or two boundaries meet.
 */
#ifndef RAYSCAD_MESH_FOLLOW_H
#define RAYSCAD_MESH_FOLLOW_H

#include "../intervals/intervals.h"

#include <stdint.h>

/* The rays of a line: x(u, t) = p0 + u·e1 + t·d. */
typedef struct mesh_line_frame {
    double p0[3], e1[3], e2[3], d[3];
} mesh_line_frame;

/* One boundary of a ray, followed along its line. */
typedef struct mesh_form {
    double g0[3], gu[3], gt[3];      /* its gradient 2Ax + b on the line: g0 + u gu + t gt */
    double al, bu, bt, cu2, cu1, c0; /* its quadratic on the line (above) */
    double s;                        /* the root: the sign of ∂q/∂t there */
    double w;                        /* +1: the ray leaves the solid; −1: enters */
    uint64_t face;                   /* which surface (prim, part, flip) */
} mesh_form;

/* The boundary through world point x on surface q (its gradient pointing
 * out of the solid), the rays of line F leaving (w = 1) or entering
 * (w = −1) there, followed along F's rays: the root of x's side.  x may be
 * on another line's ray. */
void mesh_form_init(mesh_form *f, const iv_quadric *q, const mesh_line_frame *F, const double x[3],
                    double w, uint64_t face);

/* Its t on the ray u: 0, or -1 past its silhouette. */
int mesh_form_t(const mesh_form *f, double u, double *t);

/* What the ray u crosses, from the boundaries f[0 .. n-1] of one ray of the
 * line (in order along it): the length of solid, ∫ t dt over it, Σ |n·d|,
 * and Σ ±dt/du and Σ ±dt/dv (the length's rates along e1 and e2).  0, or 1
 * where the boundaries no longer describe the ray u (one past its
 * silhouette, two out of order). */
typedef struct mesh_follow_sums {
    double len, tt, area, slope, across;
} mesh_follow_sums;
int mesh_forms_sums(const mesh_form *f, int n, const mesh_line_frame *F, double u,
                    mesh_follow_sums *out);

/* Where between the rays lo and hi (< hi) the make-up of a ray with
 * boundaries a[0 .. na-1] at lo may change into one with b[0 .. nb-1] at
 * hi: the silhouettes of the boundaries one has and the other lacks, where
 * two of those meet (one of each, or two neighbours of one), in increasing
 * order into x (at most cap); their number.  0 when the two differ in more
 * than a few boundaries. */
int mesh_forms_events(const mesh_form *a, int na, const mesh_form *b, int nb, double lo, double hi,
                      double *x, int cap);

#endif
