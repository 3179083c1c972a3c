/*
 * polytope.c — convex polytopes as intersections of halfspaces (the convex
 * hulls of src/geom/hull3d.c are made of them).
 *
 * A polytope is its planes n·x <= d with unit n, plus the vertices it was
 * made from (for bounds and for hull() of a hull).  A line meets it in one
 * interval, found by Cyrus–Beck clipping: each plane the line runs into
 * raises the entry, each it runs out of lowers the exit, and a plane the line
 * is parallel to keeps it all or nothing — the same closed-halfspace rule as
 * shapes.c's halfspace, so two polytopes sharing a face leave no crack.  The
 * boundary's part is the index of the plane that made it.
 */
#include "shape_kinds.h"
#include "vec3.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

struct iv_polytope {
    atomic_int refs;
    int n, nv;
    double (*pl)[4];
    double (*v)[3];
    double lo[3], hi[3];
};

void iv_polytope_retain(iv_polytope *p)
{
    atomic_fetch_add(&p->refs, 1);
}

void iv_polytope_release(iv_polytope *p)
{
    if (atomic_fetch_sub(&p->refs, 1) != 1) return;
    free(p->pl);
    free(p->v);
    free(p);
}

int iv_shape_polytope(iv_shape *s, const double (*planes)[4], int nplanes, const double (*verts)[3],
                      int nverts)
{
    if (nplanes <= 0 || nplanes > 65536 || nverts <= 0) return -1;
    iv_polytope *p = calloc(1, sizeof *p);
    if (!p) return -1;
    p->pl = malloc((size_t)nplanes * sizeof *p->pl);
    p->v = malloc((size_t)nverts * sizeof *p->v);
    if (!p->pl || !p->v) goto fail;
    for (int i = 0; i < nplanes; i++) {
        double l = sqrt(planes[i][0] * planes[i][0] + planes[i][1] * planes[i][1] +
                        planes[i][2] * planes[i][2]);
        if (!(l > 0) || !isfinite(l) || !isfinite(planes[i][3])) goto fail;
        for (int k = 0; k < 4; k++)
            p->pl[i][k] = planes[i][k] / l;
    }
    for (int k = 0; k < 3; k++) {
        p->lo[k] = INFINITY;
        p->hi[k] = -INFINITY;
    }
    for (int i = 0; i < nverts; i++)
        for (int k = 0; k < 3; k++) {
            if (!isfinite(verts[i][k])) goto fail;
            p->v[i][k] = verts[i][k];
            p->lo[k] = fmin(p->lo[k], verts[i][k]);
            p->hi[k] = fmax(p->hi[k], verts[i][k]);
        }
    p->n = nplanes;
    p->nv = nverts;
    atomic_init(&p->refs, 1);
    memset(s, 0, sizeof *s);
    s->kind = IV_SHAPE_POLYTOPE;
    s->u.polytope.p = p;
    return 0;
fail:
    free(p->pl);
    free(p->v);
    free(p);
    return -1;
}

const double (*iv_polytope_vertices(const iv_shape *s, int *n))[3]
{
    if (s->kind != IV_SHAPE_POLYTOPE) return NULL;
    *n = s->u.polytope.p->nv;
    return (const double(*)[3])s->u.polytope.p->v;
}

const double (*iv_polytope_planes(const iv_shape *s, int *n))[4]
{
    if (s->kind != IV_SHAPE_POLYTOPE) return NULL;
    *n = s->u.polytope.p->n;
    return (const double(*)[4])s->u.polytope.p->pl;
}

int iv_polytope_intersect(const iv_polytope *p, const double o[3], const double d[3], int32_t prim,
                          iv_list *out)
{
    double t0 = -INFINITY, t1 = INFINITY;
    int p0 = 0, p1 = 0;
    for (int i = 0; i < p->n; i++) {
        const double *q = p->pl[i];
        double a = q[0] * d[0] + q[1] * d[1] + q[2] * d[2];
        double c = q[0] * o[0] + q[1] * o[1] + q[2] * o[2] - q[3];
        if (a == 0) {
            if (c > 0) return 0;
            continue;
        }
        double t = -c / a;
        if (a < 0) {
            if (t > t0) {
                t0 = t;
                p0 = i;
            }
        } else if (t < t1) {
            t1 = t;
            p1 = i;
        }
        if (!(t0 < t1)) return 0;
    }
    if (!(t0 < t1)) return 0;
    if (out->n >= out->cap) return -1;
    iv_span *sp = &out->v[out->n++];
    sp->enter = (iv_bound){t0, prim, (uint16_t)p0, 0};
    sp->exit = (iv_bound){t1, prim, (uint16_t)p1, 0};
    return 1;
}

void iv_polytope_normal(const iv_polytope *p, int part, double n[3])
{
    int i = part >= 0 && part < p->n ? part : 0;
    n[0] = p->pl[i][0];
    n[1] = p->pl[i][1];
    n[2] = p->pl[i][2];
}

int iv_polytope_bounds(const iv_polytope *p, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        if (!(p->lo[k] < p->hi[k])) return -1;
        lo[k] = p->lo[k];
        hi[k] = p->hi[k];
    }
    return 0;
}

/* ---- convex hull ------------------------------------------------------------ */
