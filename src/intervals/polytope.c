/*
 * polytope.c — convex polytopes as intersections of halfspaces, and the 3D
 * convex hull that makes them from points.
 *
 * A polytope is its planes n·x <= d with unit n, plus the vertices it was
 * made from (for bounds and for hull() of a hull).  A line meets it in one
 * interval, found by Cyrus–Beck clipping: each plane the line runs into
 * raises the entry, each it runs out of lowers the exit, and a plane the line
 * is parallel to keeps it all or nothing — the same closed-halfspace rule as
 * shapes.c's halfspace, so two polytopes sharing a face leave no crack.  The
 * boundary's part is the index of the plane that made it.
 *
 * The hull is incremental (Barber et al.'s quickhull without the outside
 * sets, O(n·faces), ample for tessellated primitives): a tetrahedron of
 * extreme points, then each point that lies more than a relative tolerance
 * outside some face replaces the faces it sees by a cone to their horizon.
 * Points within the tolerance are inside, which keeps nearly coplanar input
 * from making slivers; faces are triangles, so coplanar ones repeat a plane,
 * which costs time, not correctness.
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

typedef struct face {
    int a, b, c;    /* counter-clockwise seen from outside */
    double n[3], d; /* outward plane, unit n */
    int alive;
} face;

static int make_face(const double (*P)[3], int a, int b, int c, face *f)
{
    if (vec3_plane(P, a, b, c, f->n, &f->d) != 0) return -1;
    f->a = a;
    f->b = b;
    f->c = c;
    f->alive = 1;
    return 0;
}

int iv_hull_tetrahedron(const double (*P)[3], int n, double eps, int ids[4], int t[4][3])
{
    int i0 = 0, i1 = 0;
    for (int i = 0; i < n; i++)
        if (P[i][0] < P[i0][0]) i0 = i;
    double best = -1;
    for (int i = 0; i < n; i++) {
        double v[3];
        sub3(P[i], P[i0], v);
        double l = dot3(v, v);
        if (l > best) {
            best = l;
            i1 = i;
        }
    }
    if (!(sqrt(best) > eps)) return -1;
    int i2 = -1;
    best = eps;
    double e[3];
    sub3(P[i1], P[i0], e);
    for (int i = 0; i < n; i++) {
        double v[3], c[3];
        sub3(P[i], P[i0], v);
        cross3(e, v, c);
        double l = sqrt(dot3(c, c) / dot3(e, e));
        if (l > best) {
            best = l;
            i2 = i;
        }
    }
    if (i2 < 0) return -1;
    double n0[3], d0;
    if (vec3_plane(P, i0, i1, i2, n0, &d0)) return -1;
    int i3 = -1;
    best = eps;
    for (int i = 0; i < n; i++) {
        double l = fabs(dot3(n0, P[i]) - d0);
        if (l > best) {
            best = l;
            i3 = i;
        }
    }
    if (i3 < 0) return -1;
    ids[0] = i0;
    ids[1] = i1;
    ids[2] = i2;
    ids[3] = i3;
    const int faces[4][3] = {{i0, i1, i2}, {i0, i3, i1}, {i1, i3, i2}, {i2, i3, i0}};
    memcpy(t, faces, sizeof faces);
    if (dot3(n0, P[i3]) - d0 > 0) /* i3 above (i0, i1, i2): turn every face */
        for (int k = 0; k < 4; k++) {
            int x = t[k][1];
            t[k][1] = t[k][2];
            t[k][2] = x;
        }
    return 0;
}

/* Distances below eps count as on the plane: a few thousand ulps of the
 * coordinates, far above the rounding of a plane test, far below any
 * feature OpenSCAD's grid (1e-6 mm at its default snap) keeps. */
int iv_hull_eps(const double (*P)[3], int n, double *eps)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            if (!isfinite(P[i][k])) return -1;
            lo[k] = fmin(lo[k], P[i][k]);
            hi[k] = fmax(hi[k], P[i][k]);
        }
    double scale = 0;
    for (int k = 0; k < 3; k++)
        scale = fmax(scale, fmax(fabs(lo[k]), fabs(hi[k])));
    scale = fmax(scale, fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2])));
    *eps = 1e-11 * scale + 1e-300;
    return 0;
}

int iv_shape_hull(iv_shape *s, const double (*P)[3], int n)
{
    double eps;
    if (n < 4 || iv_hull_eps(P, n, &eps) != 0) return -1;
    int ids[4], t[4][3];
    if (iv_hull_tetrahedron(P, n, eps, ids, t) != 0) return -1;
    int cap = 64, nf = 0;
    face *F = malloc((size_t)cap * sizeof *F);
    int ecap = 64;
    int(*edges)[2] = malloc((size_t)ecap * sizeof *edges);
    int *vis = NULL;
    int rc = -1;
    if (!F || !edges) goto done;
    for (int k = 0; k < 4; k++)
        if (make_face(P, t[k][0], t[k][1], t[k][2], &F[nf++])) goto done;
    for (int i = 0; i < n; i++) {
        if (i == ids[0] || i == ids[1] || i == ids[2] || i == ids[3]) continue;
        int ne = 0, nvis = 0;
        for (int k = 0; k < nf; k++) {
            if (!F[k].alive || !(dot3(F[k].n, P[i]) - F[k].d > eps)) continue;
            nvis++;
            int tri[3] = {F[k].a, F[k].b, F[k].c};
            for (int j = 0; j < 3; j++) {
                int a = tri[j], b = tri[(j + 1) % 3];
                /* An edge seen from both sides is interior to the visible
                 * patch: drop the reverse instead of adding. */
                int found = -1;
                for (int q = 0; q < ne; q++)
                    if (edges[q][0] == b && edges[q][1] == a) {
                        found = q;
                        break;
                    }
                if (found >= 0) {
                    edges[found][0] = edges[ne - 1][0];
                    edges[found][1] = edges[ne - 1][1];
                    ne--;
                    continue;
                }
                if (ne == ecap) {
                    ecap *= 2;
                    int(*ne2)[2] = realloc(edges, (size_t)ecap * sizeof *edges);
                    if (!ne2) goto done;
                    edges = ne2;
                }
                edges[ne][0] = a;
                edges[ne][1] = b;
                ne++;
            }
            F[k].alive = 0;
        }
        if (nvis == 0) continue;
        for (int q = 0; q < ne; q++) {
            if (nf == cap) {
                cap *= 2;
                face *F2 = realloc(F, (size_t)cap * sizeof *F);
                if (!F2) goto done;
                F = F2;
            }
            /* A degenerate new face (the point on an edge's line) cannot
             * arise for a point more than eps outside; skip it if rounding
             * says otherwise. */
            if (make_face(P, edges[q][0], edges[q][1], i, &F[nf]) == 0) nf++;
        }
        /* Compact dead faces now and then so the scans stay short. */
        if (nf > 256 && nf == cap) {
            int w = 0;
            for (int k = 0; k < nf; k++)
                if (F[k].alive) F[w++] = F[k];
            nf = w;
        }
    }
    {
        int w = 0;
        for (int k = 0; k < nf; k++)
            if (F[k].alive) F[w++] = F[k];
        nf = w;
        double(*pl)[4] = malloc((size_t)nf * sizeof *pl);
        vis = calloc((size_t)n, sizeof *vis);
        if (!pl || !vis) {
            free(pl);
            goto done;
        }
        int nv = 0;
        for (int k = 0; k < nf; k++) {
            pl[k][0] = F[k].n[0];
            pl[k][1] = F[k].n[1];
            pl[k][2] = F[k].n[2];
            pl[k][3] = F[k].d;
            int tri[3] = {F[k].a, F[k].b, F[k].c};
            for (int j = 0; j < 3; j++)
                if (!vis[tri[j]]) {
                    vis[tri[j]] = 1;
                    nv++;
                }
        }
        double(*vv)[3] = malloc((size_t)(nv > 0 ? nv : 1) * sizeof *vv);
        if (!vv) {
            free(pl);
            goto done;
        }
        nv = 0;
        for (int i = 0; i < n; i++)
            if (vis[i]) memcpy(vv[nv++], P[i], sizeof vv[0]);
        rc = iv_shape_polytope(s, (const double(*)[4])pl, nf, (const double(*)[3])vv, nv);
        free(pl);
        free(vv);
    }
done:
    free(F);
    free(edges);
    free(vis);
    return rc;
}
