/*
 * mesh_boundary.c — whether a closed triangle mesh is the boundary of the
 * solid the nonzero rule makes of it (geom_mesh_is_boundary).
 *
 * The ray queries read a polyhedron by the nonzero rule: a point is inside
 * where the winding number of the triangles about it is not 0.  Its
 * triangles are that solid's boundary exactly when the surface is a set of
 * disjoint closed 2-manifolds (every edge once each way, one fan about
 * each vertex, no two triangles meeting but where they share corners) and
 * the winding number steps from 0 to 1 across every triangle (in front of
 * each shell it is 0).  Two overlapping cubes written as one polyhedron
 * fail the first (their faces cross), two nested cubes wound alike the
 * second (winding 2 inside the inner one, whose faces are then no
 * boundary).
 *
 * Pairs of triangles are found through a uniform grid of their boxes; each
 * pair is tested with orientation
 * predicates in doubles, a near-zero orientation (relative to the edges
 * involved) read as zero, so a near touch counts as a touch: where it
 * cannot tell, the answer is no, and the caller contours the solid.
 */
#include "mesh_boundary.h"

#include "../intervals/vec3.h"
#include "edges.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PAIRS_PER_TRIANGLE 512 /* pair tests allowed, per triangle */
#define CELL_REFS 16           /* grid cells a triangle may fill, on average */
#define WINDING_WORK 50000000  /* shells times triangles for the winding check */
#define REL 1e-12              /* an orientation this small, relative, is 0 */

/* The sign of the orientation of d against the plane of a, b, c: 0 within
 * REL of the product of the three edges from a. */
static int orient(const double a[3], const double b[3], const double c[3], const double d[3])
{
    double u[3], w[3], x[3];
    sub3(b, a, u);
    sub3(c, a, w);
    sub3(d, a, x);
    double o = triple3(u, w, x), m = sqrt(dot3(u, u) * dot3(w, w) * dot3(x, x));
    return fabs(o) <= REL * m ? 0 : o > 0 ? 1 : -1;
}

/* Whether convex polygons A (na points) and B (nb points, 2 or 3), in
 * 2D, overlap: no edge normal separates them.  With strict, a separation
 * by nothing (touching) counts as separated; without, touching overlaps. */
static int overlap2(const double (*A)[2], int na, const double (*B)[2], int nb, int strict)
{
    double ext = 0;
    for (int i = 0; i < na; i++)
        ext = fmax(ext, fmax(fabs(A[i][0]), fabs(A[i][1])));
    for (int i = 0; i < nb; i++)
        ext = fmax(ext, fmax(fabs(B[i][0]), fabs(B[i][1])));
    for (int side = 0; side < 2; side++) {
        const double(*P)[2] = side ? B : A;
        int np = side ? nb : na;
        for (int i = 0; i < (np == 2 ? 1 : np); i++) {
            const double *p = P[i], *q = P[(i + 1) % np];
            double ax = q[1] - p[1], ay = p[0] - q[0], len = hypot(ax, ay);
            if (!(len > 0)) continue;
            double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
            for (int s = 0; s < 2; s++)
                for (int k = 0; k < (s ? nb : na); k++) {
                    const double *r = s ? B[k] : A[k];
                    double d = (ax * r[0] + ay * r[1]) / len;
                    lo[s] = fmin(lo[s], d);
                    hi[s] = fmax(hi[s], d);
                }
            double gap = fmax(lo[1] - hi[0], lo[0] - hi[1]), tol = REL * 4 * ext;
            if (strict ? gap >= -tol : gap > tol) return 0;
        }
    }
    return 1;
}

/* Points P[0 .. n) of the plane of normal nrm, dropped to 2D along its
 * largest component. */
static void flatten(const double nrm[3], const double *const *P, int n, double (*out)[2])
{
    int k = fabs(nrm[0]) > fabs(nrm[1]) ? (fabs(nrm[0]) > fabs(nrm[2]) ? 0 : 2)
                                        : (fabs(nrm[1]) > fabs(nrm[2]) ? 1 : 2);
    for (int i = 0; i < n; i++) {
        out[i][0] = P[i][(k + 1) % 3];
        out[i][1] = P[i][(k + 2) % 3];
    }
}

/* Whether segment p q touches triangle a b c (of normal nrm). */
static int segment_meets(const double p[3], const double q[3], const double a[3], const double b[3],
                         const double c[3], const double nrm[3])
{
    int sp = orient(a, b, c, p), sq = orient(a, b, c, q);
    if (sp * sq > 0) return 0;
    if (sp == 0 && sq == 0) {
        const double *S[2] = {p, q}, *T[3] = {a, b, c};
        double s2[2][2], t2[3][2];
        flatten(nrm, S, 2, s2);
        flatten(nrm, T, 3, t2);
        return overlap2((const double(*)[2])t2, 3, (const double(*)[2])s2, 2, 0);
    }
    int s1 = orient(p, q, a, b), s2 = orient(p, q, b, c), s3 = orient(p, q, c, a);
    return !((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0));
}

/* Whether triangles i and j meet anywhere but at the corners they share. */
static int pair_meets(const double (*v)[3], const int (*tri)[3], const double (*nrm)[3], int i,
                      int j)
{
    const int *A = tri[i], *B = tri[j];
    int shared = 0, sa = -1, sb = -1;
    for (int x = 0; x < 3; x++)
        for (int y = 0; y < 3; y++)
            if (A[x] == B[y]) {
                shared++;
                sa = x;
                sb = y;
            }
    if (shared == 3) return 1;
    int coplanar = 1;
    for (int y = 0; y < 3 && coplanar; y++)
        coplanar = orient(v[A[0]], v[A[1]], v[A[2]], v[B[y]]) == 0;
    if (shared == 2) return coplanar && dot3(nrm[i], nrm[j]) < 0; /* folded onto each other */
    if (coplanar) {
        const double *P[3] = {v[A[0]], v[A[1]], v[A[2]]}, *Q[3] = {v[B[0]], v[B[1]], v[B[2]]};
        double p2[3][2], q2[3][2];
        flatten(nrm[i], P, 3, p2);
        flatten(nrm[i], Q, 3, q2);
        return overlap2((const double(*)[2])p2, 3, (const double(*)[2])q2, 3, shared == 1);
    }
    if (shared == 1) /* the edges away from the shared corner (see the header) */
        return segment_meets(v[A[(sa + 1) % 3]], v[A[(sa + 2) % 3]], v[B[0]], v[B[1]], v[B[2]],
                             nrm[j]) ||
               segment_meets(v[B[(sb + 1) % 3]], v[B[(sb + 2) % 3]], v[A[0]], v[A[1]], v[A[2]],
                             nrm[i]);
    for (int k = 0; k < 3; k++)
        if (segment_meets(v[A[k]], v[A[(k + 1) % 3]], v[B[0]], v[B[1]], v[B[2]], nrm[j]) ||
            segment_meets(v[B[k]], v[B[(k + 1) % 3]], v[A[0]], v[A[1]], v[A[2]], nrm[i]))
            return 1;
    return 0;
}

static int by_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* The cells of a grid of spacing h from lo that box [blo, bhi] covers:
 * c0 .. c1 along each axis. */
static void cells_of(const double lo[3], double h, const int dim[3], const double blo[3],
                     const double bhi[3], int c0[3], int c1[3])
{
    for (int k = 0; k < 3; k++) {
        c0[k] = (int)fmin(dim[k] - 1, fmax(0, floor((blo[k] - lo[k]) / h)));
        c1[k] = (int)fmin(dim[k] - 1, fmax(0, floor((bhi[k] - lo[k]) / h)));
    }
}

/* 1 when two triangles meet improperly, 0 when none do, 2 when there were
 * too many candidates to tell, -1 out of memory.  Candidates share a cell
 * of a uniform grid (spacing: the median triangle's size, doubled while the
 * triangles would fill more than CELL_REFS cells each on average); a pair
 * is tested in the first cell both cover only. */
static int any_crossing(const double (*v)[3], const int (*tri)[3], const double (*nrm)[3], int nt)
{
    double(*box)[2][3] = malloc((size_t)nt * sizeof *box),
    *size = malloc((size_t)nt * sizeof *size);
    int *start = NULL, *ref = NULL, rc = -1;
    if (!box || !size) goto out;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int t = 0; t < nt; t++) {
        size[t] = 0;
        for (int k = 0; k < 3; k++) {
            box[t][0][k] = fmin(v[tri[t][0]][k], fmin(v[tri[t][1]][k], v[tri[t][2]][k]));
            box[t][1][k] = fmax(v[tri[t][0]][k], fmax(v[tri[t][1]][k], v[tri[t][2]][k]));
            lo[k] = fmin(lo[k], box[t][0][k]);
            hi[k] = fmax(hi[k], box[t][1][k]);
            size[t] = fmax(size[t], box[t][1][k] - box[t][0][k]);
        }
    }
    double ext = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2])), pad = 1e-9 * ext;
    qsort(size, (size_t)nt, sizeof *size, by_double);
    double h = fmax(size[nt / 2], 1e-6 * ext);
    long long nref;
    int dim[3];
    for (;;) {
        long long cells = 1;
        for (int k = 0; k < 3; k++) {
            dim[k] = (int)fmin(1 << 20, floor((hi[k] - lo[k]) / h) + 1);
            cells *= dim[k];
        }
        nref = 0;
        for (int t = 0; t < nt; t++) {
            int c0[3], c1[3];
            cells_of(lo, h, dim, box[t][0], box[t][1], c0, c1);
            nref += (long long)(c1[0] - c0[0] + 1) * (c1[1] - c0[1] + 1) * (c1[2] - c0[2] + 1);
        }
        if (cells <= 4LL * nt + 64 && nref <= (long long)CELL_REFS * nt) break;
        h *= 2;
    }
    long long ncell = (long long)dim[0] * dim[1] * dim[2];
    start = calloc((size_t)ncell + 1, sizeof *start);
    ref = malloc((size_t)nref * sizeof *ref);
    if (!start || !ref) goto out;
    for (int pass = 0; pass < 2; pass++) {
        for (int t = 0; t < nt; t++) {
            int c0[3], c1[3];
            cells_of(lo, h, dim, box[t][0], box[t][1], c0, c1);
            for (int x = c0[0]; x <= c1[0]; x++)
                for (int y = c0[1]; y <= c1[1]; y++)
                    for (int z = c0[2]; z <= c1[2]; z++) {
                        long long c = ((long long)z * dim[1] + y) * dim[0] + x;
                        if (pass == 0)
                            start[c + 1]++;
                        else
                            ref[start[c]++] = t;
                    }
        }
        if (pass == 0)
            for (long long c = 0; c < ncell; c++)
                start[c + 1] += start[c];
        else
            for (long long c = ncell; c > 0; c--)
                start[c] = start[c - 1];
        if (pass == 1) start[0] = 0;
    }
    long long budget = (long long)PAIRS_PER_TRIANGLE * nt + 100000;
    rc = 0;
    for (long long c = 0; c < ncell && rc == 0; c++) {
        int here[3] = {(int)(c % dim[0]), (int)(c / dim[0] % dim[1]), (int)(c / dim[0] / dim[1])};
        for (int i = start[c]; i < start[c + 1] && rc == 0; i++)
            for (int j = i + 1; j < start[c + 1] && rc == 0; j++) {
                int a = ref[i], b = ref[j], apart = 0, first = 1;
                for (int k = 0; k < 3; k++)
                    apart |= box[b][0][k] > box[a][1][k] + pad || box[a][0][k] > box[b][1][k] + pad;
                if (apart) continue;
                int ca[3], cb[3], d1[3];
                cells_of(lo, h, dim, box[a][0], box[a][1], ca, d1);
                cells_of(lo, h, dim, box[b][0], box[b][1], cb, d1);
                for (int k = 0; k < 3; k++)
                    first &= (ca[k] > cb[k] ? ca[k] : cb[k]) == here[k];
                if (!first) continue;
                if (--budget < 0)
                    rc = 2;
                else if (pair_meets(v, tri, nrm, a, b))
                    rc = 1;
            }
    }
out:
    free(box);
    free(size);
    free(start);
    free(ref);
    return rc;
}

/* The winding number of the triangles about x: the sum of their solid
 * angles (Van Oosterom and Strackee) over 4π. */
static double winding(const double (*v)[3], const int (*tri)[3], int nt, const double x[3])
{
    double sum = 0;
    for (int t = 0; t < nt; t++) {
        double a[3], b[3], c[3], bc[3];
        sub3(v[tri[t][0]], x, a);
        sub3(v[tri[t][1]], x, b);
        sub3(v[tri[t][2]], x, c);
        cross3(b, c, bc);
        double la = sqrt(dot3(a, a)), lb = sqrt(dot3(b, b)), lc = sqrt(dot3(c, c));
        double den = la * lb * lc + dot3(a, b) * lc + dot3(a, c) * lb + dot3(b, c) * la;
        sum += 2 * atan2(dot3(a, bc), den);
    }
    return sum / (4 * 3.14159265358979323846);
}

int geom_mesh_is_boundary(const double (*v)[3], int nv, const int (*tri)[3], int nt)
{
    if (nt < 4) return 0;
    int ne = 3 * nt, rc = 0;
    geom_edge *e = malloc((size_t)ne * sizeof *e);
    int *first = malloc((size_t)nv * sizeof *first), *deg = calloc((size_t)nv, sizeof *deg);
    int *up = malloc((size_t)nt * sizeof *up);
    double(*nrm)[3] = malloc((size_t)nt * sizeof *nrm);
    if (!e || !first || !deg || !up || !nrm) {
        rc = -1;
        goto done;
    }
    for (int i = 0; i < nv; i++)
        first[i] = -1;
    for (int t = 0; t < nt; t++) {
        up[t] = t;
        for (int k = 0; k < 3; k++) {
            int a = tri[t][k], b = tri[t][(k + 1) % 3];
            if (a < 0 || a >= nv || a == b) goto done;
            e[3 * t + k] = (geom_edge){a, b, t};
            deg[a]++;
            if (first[a] < 0) first[a] = t;
        }
        tri_normal3(v[tri[t][0]], v[tri[t][1]], v[tri[t][2]], nrm[t]);
        if (!(dot3(nrm[t], nrm[t]) > 0)) goto done; /* no area */
    }
    qsort(e, (size_t)ne, sizeof *e, geom_edge_cmp);
    /* every edge once each way; the triangles across it are one shell */
    for (int i = 0; i < ne; i++) {
        if (i > 0 && geom_edge_cmp(&e[i - 1], &e[i]) == 0) goto done;
        int o = geom_edge_find(e, ne, e[i].b, e[i].a);
        o = o < 0 ? -1 : e[o].t;
        if (o < 0) goto done;
        up[geom_set_find(up, e[i].t)] = geom_set_find(up, o);
    }
    /* one fan about each vertex: from a triangle (a, b, c) the next about a
     * is the one across c -> a, which holds a -> c */
    for (int a = 0; a < nv; a++) {
        if (first[a] < 0) continue;
        int t = first[a], n = 0;
        do {
            const int *T = tri[t];
            int k = T[0] == a ? 0 : T[1] == a ? 1 : 2;
            t = geom_edge_find(e, ne, a, T[(k + 2) % 3]);
            t = t < 0 ? -1 : e[t].t;
            n++;
        } while (t >= 0 && t != first[a] && n <= deg[a]);
        if (t != first[a] || n != deg[a]) goto done;
    }
    int cross = any_crossing(v, tri, (const double(*)[3])nrm, nt);
    if (cross != 0) {
        rc = cross < 0 ? -1 : 0;
        goto done;
    }
    /* in front of each shell's largest triangle, winding 0; behind it, 1 */
    int *root_best = malloc((size_t)nt * sizeof *root_best), shells = 0;
    if (!root_best) {
        rc = -1;
        goto done;
    }
    for (int t = 0; t < nt; t++)
        root_best[t] = -1;
    for (int t = 0; t < nt; t++) {
        int r = geom_set_find(up, t);
        if (root_best[r] < 0) shells++;
        if (root_best[r] < 0 || dot3(nrm[t], nrm[t]) > dot3(nrm[root_best[r]], nrm[root_best[r]]))
            root_best[r] = t;
    }
    rc = (long long)shells * nt <= WINDING_WORK;
    for (int t = 0; t < nt && rc == 1; t++) {
        if (root_best[t] < 0 || geom_set_find(up, t) != t) continue;
        int b = root_best[t];
        double len = sqrt(dot3(nrm[b], nrm[b])), c[3], x[2][3];
        for (int k = 0; k < 3; k++)
            c[k] = (v[tri[b][0]][k] + v[tri[b][1]][k] + v[tri[b][2]][k]) / 3;
        /* a step off the face small against the triangle (its size is
         * sqrt(len)) */
        double step = 1e-6 * sqrt(len);
        for (int k = 0; k < 3; k++) {
            x[0][k] = c[k] + step * nrm[b][k] / len;
            x[1][k] = c[k] - step * nrm[b][k] / len;
        }
        double front = winding(v, tri, nt, x[0]), back = winding(v, tri, nt, x[1]);
        rc = fabs(front) < 0.5 && fabs(fabs(back) - 1) < 0.5;
    }
    free(root_best);
done:
    free(e);
    free(first);
    free(deg);
    free(up);
    free(nrm);
    return rc;
}
