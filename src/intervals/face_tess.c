/*
 * face_tess.c — a non-planar face cut into triangles as OpenSCAD 2021.01
 * cuts it.  It tessellates a polyhedron's faces with libtess2, constrained
 * Delaunay, no normal given: libtess2 finds a normal from the two vertices
 * farthest apart along the widest axis and the vertex making the largest
 * triangle with them, projects the face by dropping that normal's largest
 * coordinate, and triangulates the projected polygon, then flips diagonals
 * until every one is Delaunay (the corner opposite it lies outside the
 * circle through the other three).  Here the projected polygon is cut by
 * ear clipping and flipped to the same end; a quadrilateral whose two
 * candidate diagonals tie (a corner on the circle, or corners that project
 * onto each other) keeps the diagonal F[0]F[2], as libtess2 was seen to.
 */
#include "shape_kinds.h"
#include "vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Faces longer than this keep the fan (the clipping is quadratic, the
 * flipping more). */
enum { TESS_MAX = 256 };

/* The face projected as libtess2 projects it, into P[0..len). */
static void project(const double (*v)[3], const int *F, int len, double (*P)[2])
{
    int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int j = 1; j < len; j++)
        for (int k = 0; k < 3; k++) {
            if (v[F[j]][k] < v[F[lo[k]]][k]) lo[k] = j;
            if (v[F[j]][k] > v[F[hi[k]]][k]) hi[k] = j;
        }
    int w = 0;
    for (int k = 1; k < 3; k++)
        if (v[F[hi[k]]][k] - v[F[lo[k]]][k] > v[F[hi[w]]][w] - v[F[lo[w]]][w]) w = k;
    const double *b = v[F[hi[w]]];
    double d1[3], n[3] = {0, 0, 0}, best = 0;
    sub3(v[F[lo[w]]], b, d1);
    for (int j = 0; j < len; j++) {
        double d2[3], c[3];
        sub3(v[F[j]], b, d2);
        cross3(d1, d2, c);
        double l2 = dot3(c, c);
        if (l2 > best) {
            best = l2;
            memcpy(n, c, sizeof n);
        }
    }
    int ax = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(n[k]) > fabs(n[ax])) ax = k;
    for (int j = 0; j < len; j++) {
        P[j][0] = v[F[j]][(ax + 1) % 3];
        P[j][1] = v[F[j]][(ax + 2) % 3];
    }
}

static double orient(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* > 0 when d lies inside the circle through a, b, c (counter-clockwise). */
static double in_circle(const double *a, const double *b, const double *c, const double *d)
{
    double m[3][3];
    const double *p[3] = {a, b, c};
    for (int j = 0; j < 3; j++) {
        double x = p[j][0] - d[0], y = p[j][1] - d[1];
        m[j][0] = x;
        m[j][1] = y;
        m[j][2] = x * x + y * y;
    }
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/* 1 when point p lies inside or on triangle (a, b, c), counter-clockwise. */
static int in_triangle(const double *a, const double *b, const double *c, const double *p)
{
    return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

/* Ear clipping of the counter-clockwise polygon P[0..n) into T (indices
 * into P).  Returns 0, or -1 when no ear is found (a self-crossing or
 * degenerate projection). */
static int clip_ears(const double (*P)[2], int n, int (*T)[3])
{
    int idx[TESS_MAX], m = n, t = 0;
    for (int i = 0; i < n; i++)
        idx[i] = i;
    while (m > 3) {
        int found = -1;
        /* from the second corner: a tie keeps the diagonal F[0]F[2] */
        for (int ii = 0; ii < m && found < 0; ii++) {
            int i = (ii + 1) % m;
            int a = idx[(i + m - 1) % m], b = idx[i], c = idx[(i + 1) % m];
            if (!(orient(P[a], P[b], P[c]) > 0)) continue;
            int empty = 1;
            for (int j = 0; j < m && empty; j++) {
                int q = idx[j];
                if (q != a && q != b && q != c && in_triangle(P[a], P[b], P[c], P[q])) empty = 0;
            }
            if (empty) found = i;
        }
        if (found < 0) return -1;
        T[t][0] = idx[(found + m - 1) % m];
        T[t][1] = idx[found];
        T[t][2] = idx[(found + 1) % m];
        t++;
        memmove(idx + found, idx + found + 1, (size_t)(m - found - 1) * sizeof *idx);
        m--;
    }
    T[t][0] = idx[0];
    T[t][1] = idx[1];
    T[t][2] = idx[2];
    return 0;
}

/* Flips the inner diagonals of the triangulation T (nt counter-clockwise
 * triangles over P) until each is Delaunay.  An edge of the polygon (i and
 * i + 1 mod n) is never flipped; a flip is made only where the two
 * triangles form a convex quadrilateral. */
static void make_delaunay(const double (*P)[2], int n, int (*T)[3], int nt)
{
    for (int round = 0; round < 4 * nt * nt + 8; round++) {
        int flipped = 0;
        for (int x = 0; x < nt; x++)
            for (int e = 0; e < 3; e++) {
                int a = T[x][e], b = T[x][(e + 1) % 3], c = T[x][(e + 2) % 3];
                if ((a + 1) % n == b || (b + 1) % n == a) continue;
                /* the triangle across (a, b): it has (b, a) */
                for (int y = 0; y < nt; y++) {
                    if (y == x) continue;
                    int f = -1;
                    for (int g = 0; g < 3; g++)
                        if (T[y][g] == b && T[y][(g + 1) % 3] == a) f = g;
                    if (f < 0) continue;
                    int d = T[y][(f + 2) % 3];
                    if (in_circle(P[a], P[b], P[c], P[d]) > 0 && orient(P[c], P[a], P[d]) > 0 &&
                        orient(P[d], P[b], P[c]) > 0) {
                        T[x][0] = c, T[x][1] = a, T[x][2] = d;
                        T[y][0] = d, T[y][1] = b, T[y][2] = c;
                        flipped = 1;
                    }
                    break;
                }
                if (flipped) break;
            }
        if (!flipped) return;
    }
}

int iv_face_tessellate(const double (*v)[3], const int *F, int len, int (*tri)[3])
{
    if (len < 4 || len > TESS_MAX) return -1;
    double P[TESS_MAX][2];
    project(v, F, len, P);
    /* counter-clockwise in the projection: read the face backwards if not */
    double area = 0;
    for (int i = 0, j = len - 1; i < len; j = i++)
        area += (P[j][0] - P[i][0]) * (P[j][1] + P[i][1]);
    int back = area < 0;
    double Q[TESS_MAX][2];
    for (int i = 0; i < len; i++)
        memcpy(Q[i], P[back ? len - 1 - i : i], sizeof Q[i]);
    int T[TESS_MAX][3];
    if (clip_ears((const double(*)[2])Q, len, T) != 0) return -1;
    make_delaunay((const double(*)[2])Q, len, T, len - 2);
    for (int x = 0; x < len - 2; x++)
        for (int k = 0; k < 3; k++) {
            /* back: the face's own winding is the other way round */
            int q = T[x][back ? 2 - k : k];
            tri[x][k] = F[back ? len - 1 - q : q];
        }
    return 0;
}
