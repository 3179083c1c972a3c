/*
 * shape_kinds.h — private to src/intervals: the shapes with shared data
 * (polytope.c, mesh.c, prism.c, revolve.c), as shapes.c dispatches to them.
 * Each _intersect follows iv_shape_intersect's contract.
 */
#ifndef RAYSCAD_SHAPE_KINDS_H
#define RAYSCAD_SHAPE_KINDS_H

#include "intervals.h"

#include <math.h>
#include <stdatomic.h>

/* The span [*t0, *t1] of the line o + t·d (one axis) inside the slab
 * lo <= x <= hi, and the parts it enters and leaves through: *p0 and *p1
 * come in as lo's and hi's and are swapped with the ends.  A line parallel
 * to the slab is inside for every t (returns 1 with ±inf) or for none
 * (returns 0); testing that before dividing keeps 0·inf (a NaN) out, and
 * dividing rather than multiplying by 1/d keeps a subnormal d's inf out. */
static inline int iv_slab(double o, double d, double lo, double hi, double *t0, double *t1, int *p0,
                          int *p1)
{
    *t0 = -INFINITY;
    *t1 = INFINITY;
    if (d == 0) return !(o < lo || o > hi);
    *t0 = (lo - o) / d;
    *t1 = (hi - o) / d;
    if (*t0 > *t1) {
        double t = *t0;
        *t0 = *t1;
        *t1 = t;
        int p = *p0;
        *p0 = *p1;
        *p1 = p;
    }
    return 1;
}

/* The roots *t0 <= *t1 of A t² + 2B t + C = 0 whose discriminant
 * (B² - AC, scaled by A as the caller finds it most exact) is disc > 0:
 * q = -(B + copysign(√disc, B)) adds like-signed terms, and the roots are
 * q/A and C/q (Vieta), neither losing digits. */
static inline void iv_quadratic_roots(double A, double B, double C, double disc, double *t0,
                                      double *t1)
{
    double q = -(B + copysign(sqrt(disc), B));
    *t0 = q / A;
    *t1 = C / q;
    if (*t0 > *t1) {
        double t = *t0;
        *t0 = *t1;
        *t1 = t;
    }
}

/* Sorts n bounds by t, keeping equal ones in order (insertion: the lists
 * are short). */
static inline void iv_bounds_sort(iv_bound *c, long n)
{
    for (long i = 1; i < n; i++) {
        iv_bound x = c[i];
        long j = i;
        while (j > 0 && c[j - 1].t > x.t) {
            c[j] = c[j - 1];
            j--;
        }
        c[j] = x;
    }
}

int iv_polytope_intersect(const iv_polytope *p, const double o[3], const double d[3], int32_t prim,
                          iv_list *out);
void iv_polytope_normal(const iv_polytope *p, int part, double n[3]);
int iv_polytope_bounds(const iv_polytope *p, double lo[3], double hi[3]);
void iv_polytope_retain(iv_polytope *p);
void iv_polytope_release(iv_polytope *p);

int iv_mesh_intersect(const iv_mesh *m, const double o[3], const double d[3], int32_t prim,
                      iv_list *out);
void iv_mesh_normal(const iv_mesh *m, const double p[3], int part, double n[3]);
int iv_mesh_bounds(const iv_mesh *m, double lo[3], double hi[3]);
int iv_mesh_max_spans(const iv_mesh *m);
void iv_mesh_retain(iv_mesh *m);
void iv_mesh_release(iv_mesh *m);

/* The non-planar face F[0..len) (4 <= len <= 256) cut into len - 2
 * triangles in tri, wound as the face, as OpenSCAD 2021.01 cuts it
 * (face_tess.c).  Returns 0, or -1 (too long, or its projection has no
 * ear): then a fan will do. */
int iv_face_tessellate(const double (*v)[3], const int *F, int len, int (*tri)[3]);

/* What a mesh's edges say about it (mesh_orient.c). */
typedef enum iv_mesh_reading {
    IV_MESH_READ_FAILED = -1, /* out of memory */
    IV_MESH_CLOSED,           /* every edge used once each way */
    IV_MESH_TURNED,           /* so once the triangles flip[] marks were turned */
    IV_MESH_CRACKED,          /* every edge used once is a T-junction's */
    IV_MESH_OPEN              /* it has holes, or is one-sided */
} iv_mesh_reading;
/* 1 when every directed edge of the triangles is matched by exactly one
 * reverse edge, 0 when not, -1 when out of memory. */
int iv_mesh_edges_closed(const int (*tri)[3], int nt, int nv);
/* Reads the triangles' edges as mesh_orient.c says; for IV_MESH_TURNED the
 * triangles flip[t] marks have been turned in tri (flip: nt bytes, all 0
 * otherwise). */
iv_mesh_reading iv_mesh_read_edges(const double (*v)[3], int nv, int (*tri)[3], int nt,
                                   unsigned char *flip);

int iv_prism_intersect(const iv_shape *s, const double o[3], const double d[3], int32_t prim,
                       iv_list *out);
void iv_prism_normal(const iv_shape *s, const double p[3], int part, double n[3]);
int iv_prism_bounds(const iv_shape *s, double lo[3], double hi[3]);
int iv_prism_max_spans(const iv_shape *s);

int iv_revolve_intersect(const iv_shape *s, const double o[3], const double d[3], int32_t prim,
                         iv_list *out);
void iv_revolve_normal(const iv_shape *s, const double p[3], int part, double n[3]);
int iv_revolve_bounds(const iv_shape *s, double lo[3], double hi[3]);
int iv_revolve_max_spans(const iv_shape *s);

/* Region internals shared by prism.c and revolve.c. */
struct iv_region {
    atomic_int refs;
    int npts, npaths;
    double (*pt)[2]; /* paths oriented so the region lies on their left */
    int *start;      /* npaths + 1 */
    double lo[2], hi[2];
};
/* Index of the path holding point/edge e. */
int iv_region_path_of(const iv_region *g, int e);
/* Next point index after e within its path (wrapping). */
int iv_region_next(const iv_region *g, int e);
/* The edge e = first, first + stride, … (< npts) nearest (x, y); -1 if none. */
int iv_region_nearest_edge(const iv_region *g, int first, int stride, double x, double y);

#endif
