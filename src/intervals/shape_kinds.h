/*
 * shape_kinds.h — private to src/intervals: the shapes with shared data
 * (polytope.c, mesh.c, prism.c, revolve.c), as shapes.c dispatches to them.
 * Each _intersect follows iv_shape_intersect's contract.
 */
#ifndef RAYSCAD_SHAPE_KINDS_H
#define RAYSCAD_SHAPE_KINDS_H

#include "intervals.h"

#include <stdatomic.h>

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

#endif
