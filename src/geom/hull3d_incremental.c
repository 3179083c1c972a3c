/*
 * hull3d_incremental.c — the convex hull's first steps and its fallback
 * (hull3d_internal.h): the tolerance and the starting tetrahedron both
 * algorithms share, so the same points give the same solid, and the plain
 * incremental hull (Barber et al.'s quickhull without the outside sets,
 * O(n·faces)) that hull3d.c falls back on when rounding defeats quickhull,
 * and that the tests check quickhull against.
 *
 * A tetrahedron of extreme points, then each point that lies more than a
 * relative tolerance outside some face replaces the faces it sees by a cone
 * to their horizon.  Points within the tolerance are inside, which keeps
 * nearly coplanar input from making slivers; faces are triangles, so
 * coplanar ones repeat a plane, which costs time, not correctness.
 */
#include "hull3d_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../intervals/vec3.h"

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

int geom_hull_tetrahedron(const double (*P)[3], int n, double eps, int ids[4], int t[4][3])
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
int geom_hull_eps(const double (*P)[3], int n, double *eps)
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

int geom_hull3d_incremental(iv_shape *s, const double (*P)[3], int n)
{
    double eps;
    if (n < 4 || geom_hull_eps(P, n, &eps) != 0) return -1;
    int ids[4], t[4][3];
    if (geom_hull_tetrahedron(P, n, eps, ids, t) != 0) return -1;
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
            if (vis[i]) {
                vis[i] = nv; /* now its index among vv */
                memcpy(vv[nv++], P[i], sizeof vv[0]);
            }
        rc = iv_shape_polytope(s, (const double(*)[4])pl, nf, (const double(*)[3])vv, nv);
        int(*tri)[3] = rc == 0 ? malloc((size_t)(nf > 0 ? nf : 1) * sizeof *tri) : NULL;
        if (tri) {
            for (int k = 0; k < nf; k++) {
                tri[k][0] = vis[F[k].a];
                tri[k][1] = vis[F[k].b];
                tri[k][2] = vis[F[k].c];
            }
            iv_polytope_set_faces(s, (const int(*)[3])tri); /* lines walk over them */
            free(tri);
        }
        free(pl);
        free(vv);
    }
done:
    free(F);
    free(edges);
    free(vis);
    return rc;
}
