/*
 * earcut.c — ear clipping of a polygon with holes (earcut.h).
 *
 * The rings are one circular doubly linked list of nodes.  Each hole, the
 * rightmost first, is joined to the list by a bridge from its rightmost
 * point M to a point P of the list that M sees: of the list's points to
 * M's right, the nearest whose segment to M crosses no edge of any ring,
 * passes through no corner, and enters the polygon at P (aligned holes,
 * as a grid of them has, put corners and edges exactly on the ray that
 * Eberly's rule casts from M; this asks less of the coordinates).  The
 * bridge is walked both ways, M and P repeated.
 * Then ears are cut: a corner turning left whose triangle holds no other
 * point of the list (a point at one of its corners — a bridge's repeat —
 * aside), until three are left.  Every triangle turns left, so none is
 * without area; an outline that turns back on itself finds no ear and the
 * cut fails.  O(n²) in the points (a hole's bridge O(n) a candidate).
 */
#include "earcut.h"

#include <math.h>
#include <stdlib.h>

#define MAX_POINTS 20000

typedef struct node {
    int i, prev, next;
    double x, y;
} node;

/* > 0 where a -> b -> c turns left. */
static double turn(const node *a, const node *b, const node *c)
{
    return (b->x - a->x) * (c->y - b->y) - (b->y - a->y) * (c->x - b->x);
}

static int same_place(const node *a, const node *b)
{
    return a->x == b->x && a->y == b->y;
}

/* A turn this small against the points' size is none: corners that
 * rounding left a hair off a straight line (a boolean's cuts, 13 computed
 * as 12.999999999999998) count as on it. */
static double slack(const node *a, const node *b, const node *c, const node *p)
{
    double s = 0;
    const node *q[4] = {a, b, c, p};
    for (int i = 0; i < 4; i++)
        s = fmax(s, fmax(fabs(q[i]->x), fabs(q[i]->y)));
    return 1e-12 * s * s;
}

/* Whether p is in triangle a b c (counter-clockwise), its edges and a
 * hair around them included. */
static int in_triangle(const node *a, const node *b, const node *c, const node *p)
{
    double e = -slack(a, b, c, p);
    return turn(a, b, p) >= e && turn(b, c, p) >= e && turn(c, a, p) >= e;
}

/* Whether the segment from a to b starts into the polygon at a. */
static int locally_inside(const node *N, int a, const node *b)
{
    const node *A = &N[a], *pa = &N[A->prev], *na = &N[A->next];
    if (turn(pa, A, na) > 0) return turn(A, b, na) <= 0 && turn(A, pa, b) <= 0;
    return turn(A, b, pa) > 0 || turn(A, na, b) > 0;
}

/* Whether segment m p (nodes) is clear of every edge of the nn nodes'
 * rings: crosses none, passes through no corner. */
static int clear(const node *N, int nn, int m, int p)
{
    const node *M = &N[m], *P = &N[p];
    double lo[2] = {fmin(M->x, P->x), fmin(M->y, P->y)},
           hi[2] = {fmax(M->x, P->x), fmax(M->y, P->y)};
    for (int u = 0; u < nn; u++) {
        const node *A = &N[u], *B = &N[A->next];
        if (fmax(A->x, B->x) < lo[0] || fmin(A->x, B->x) > hi[0] || fmax(A->y, B->y) < lo[1] ||
            fmin(A->y, B->y) > hi[1])
            continue;
        int am = same_place(A, M) || same_place(A, P), bm = same_place(B, M) || same_place(B, P);
        double o1 = turn(M, P, A), o2 = turn(M, P, B), e = slack(M, P, A, B);
        /* a corner on the segment (to a hair), inside it */
        if (!am && fabs(o1) <= e && A->x >= lo[0] && A->x <= hi[0] && A->y >= lo[1] &&
            A->y <= hi[1])
            return 0;
        if (am || bm) continue;
        double o3 = turn(A, B, M), o4 = turn(A, B, P);
        if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) &&
            ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
            return 0;
    }
    return 1;
}

typedef struct near {
    double d;
    int p;
} near;

static int by_d(const void *a, const void *b)
{
    double x = ((const near *)a)->d, y = ((const near *)b)->d;
    return (x > y) - (x < y);
}

/* The point of the list through `start` that hole point m (its rightmost)
 * sees: the nearest to its right whose segment to m is clear of every
 * ring (nn nodes) and enters the polygon at it; -1 when none (or out of
 * memory). */
static int bridge_to(const node *N, int nn, int start, int m)
{
    int n = 0, p = start, rc = -1;
    do {
        n++;
        p = N[p].next;
    } while (p != start);
    near *c = malloc((size_t)n * sizeof *c);
    if (!c) return -1;
    n = 0;
    p = start;
    do {
        const node *q = &N[p];
        if (q->x > N[m].x)
            c[n++] =
                (near){(q->x - N[m].x) * (q->x - N[m].x) + (q->y - N[m].y) * (q->y - N[m].y), p};
        p = q->next;
    } while (p != start);
    qsort(c, (size_t)n, sizeof *c, by_d);
    for (int i = 0; i < n && rc < 0; i++)
        if (locally_inside(N, c[i].p, &N[m]) && clear(N, nn, m, c[i].p)) rc = c[i].p;
    free(c);
    return rc;
}

static int is_ear(const node *N, int b, int count, int start)
{
    const node *A = &N[N[b].prev], *B = &N[b], *C = &N[N[b].next];
    if (!(turn(A, B, C) > slack(A, B, C, C))) return 0; /* (a straight corner is no ear) */
    int p = start;
    for (int k = 0; k < count; k++, p = N[p].next) {
        const node *q = &N[p];
        if (q == A || q == B || q == C || same_place(q, A) || same_place(q, B) || same_place(q, C))
            continue;
        if (in_triangle(A, B, C, q)) return 0;
    }
    return 1;
}

static int by_right(const void *x, const void *y)
{
    const double *a = x, *b = y;
    return (a[0] < b[0]) - (a[0] > b[0]); /* rightmost first */
}

int geom_earcut(const double (*P)[2], const int *ring, const int *start, int nrings, int (**tri)[3])
{
    *tri = NULL;
    int n = start[nrings] - start[0];
    if (nrings < 1 || n > MAX_POINTS) return -1;
    for (int r = 0; r < nrings; r++)
        if (start[r + 1] - start[r] < 3) return -1;
    node *N = malloc((size_t)(n + 2 * nrings) * sizeof *N);
    double(*hole)[2] = malloc((size_t)nrings * sizeof *hole); /* rightmost x, its node */
    int(*out)[3] = malloc((size_t)(n + 2 * nrings) * sizeof *out);
    int nn = 0, nt = 0, rc = -1;
    if (!N || !hole || !out) goto done;
    for (int r = 0; r < nrings; r++) {
        int first = nn, k = start[r + 1] - start[r], right = first;
        for (int j = 0; j < k; j++, nn++) {
            int i = ring[start[r] + j];
            N[nn] = (node){i, nn - 1, nn + 1, P[i][0], P[i][1]};
            if (N[nn].x > N[right].x) right = nn;
        }
        N[first].prev = nn - 1;
        N[nn - 1].next = first;
        hole[r][0] = N[right].x;
        hole[r][1] = right;
    }
    qsort(hole + 1, (size_t)(nrings - 1), sizeof *hole, by_right);
    for (int h = 1; h < nrings; h++) {
        int m = (int)hole[h][1], p = bridge_to(N, nn, 0, m);
        if (p < 0) goto done;
        int p2 = nn++, m2 = nn++, pn = N[p].next, mp = N[m].prev;
        N[p2] = N[p];
        N[m2] = N[m];
        N[p].next = m;
        N[m].prev = p;
        N[p2].next = pn;
        N[pn].prev = p2;
        N[m2].next = p2;
        N[p2].prev = m2;
        N[mp].next = m2;
        N[m2].prev = mp;
    }
    int count = 0, p = 0;
    do {
        count++;
        p = N[p].next;
    } while (p != 0);
    int head = 0, stop = 0;
    p = 0;
    while (count > 3) {
        if (is_ear(N, p, count, head)) {
            int a = N[p].prev, c = N[p].next;
            out[nt][0] = N[a].i;
            out[nt][1] = N[p].i;
            out[nt][2] = N[c].i;
            nt++;
            N[a].next = c;
            N[c].prev = a;
            if (head == p) head = c;
            count--;
            p = stop = c;
            continue;
        }
        p = N[p].next;
        if (p == stop) goto done; /* no ear: the rings cross */
    }
    if (!(turn(&N[N[p].prev], &N[p], &N[N[p].next]) > 0)) goto done;
    out[nt][0] = N[N[p].prev].i;
    out[nt][1] = N[p].i;
    out[nt][2] = N[N[p].next].i;
    nt++;
    rc = nt;
    *tri = out;
    out = NULL;
done:
    free(N);
    free(hole);
    free(out);
    return rc;
}

int geom_path_contains(const double (*P)[2], int n, double x, double y)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((P[i][1] > y) != (P[j][1] > y) &&
            x < P[j][0] + (y - P[j][1]) * (P[i][0] - P[j][0]) / (P[i][1] - P[j][1]))
            in = !in;
    return in;
}

/* Twice the signed area of path P[0 .. n) (> 0: counter-clockwise). */
static double path_area(const double (*P)[2], int n)
{
    double a = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        a += P[j][0] * P[i][1] - P[i][0] * P[j][1];
    return a;
}

int geom_region_triangles(const double (*P)[2], const int *start, int npaths, int (**tri)[3])
{
    *tri = NULL;
    int n = start[npaths], nt = 0, rc = -1;
    int *depth = malloc((size_t)npaths * sizeof *depth), *ring = malloc((size_t)n * sizeof *ring);
    int *rs = malloc((size_t)(npaths + 1) * sizeof *rs);
    int(*all)[3] = malloc((size_t)(n + 2 * npaths) * sizeof *all);
    if (!depth || !ring || !rs || !all) goto done;
    for (int p = 0; p < npaths; p++) {
        depth[p] = 0;
        for (int q = 0; q < npaths; q++)
            depth[p] += q != p && geom_path_contains(P + start[q], start[q + 1] - start[q],
                                                     P[start[p]][0], P[start[p]][1]);
    }
    for (int o = 0; o < npaths; o++) {
        if (depth[o] % 2) continue;
        int nr = 0, at = 0;
        rs[0] = 0;
        for (int pass = 0; pass < 2; pass++) /* the outline, then its holes */
            for (int q = 0; q < npaths; q++) {
                int k = start[q + 1] - start[q];
                if (pass == 0 ? q != o
                              : q == o || depth[q] != depth[o] + 1 ||
                                    !geom_path_contains(P + start[o], start[o + 1] - start[o],
                                                        P[start[q]][0], P[start[q]][1]))
                    continue;
                /* the outline counter-clockwise, holes clockwise */
                int turn = (pass == 0) != (path_area(P + start[q], k) > 0);
                for (int i = 0; i < k; i++)
                    ring[at++] = start[q] + (turn ? k - 1 - i : i);
                rs[++nr] = at;
            }
        int(*t)[3];
        int m = geom_earcut(P, ring, rs, nr, &t);
        if (m < 0) goto done;
        for (int i = 0; i < m; i++)
            for (int c = 0; c < 3; c++)
                all[nt + i][c] = t[i][c];
        nt += m;
        free(t);
    }
    rc = nt;
    *tri = all;
    all = NULL;
done:
    free(depth);
    free(ring);
    free(rs);
    free(all);
    return rc;
}

static int by_edge(const void *x, const void *y)
{
    const long long *a = x, *b = y;
    return (*a > *b) - (*a < *b);
}

int geom_prism_mesh(const double (*P)[2], const int *start, int npaths, double z0, double z1,
                    double (**v)[3], int (**tri)[3])
{
    *v = NULL;
    *tri = NULL;
    int n = start[npaths], (*cap)[3];
    int nc = geom_region_triangles(P, start, npaths, &cap);
    if (nc < 0) return -1;
    int nt = 2 * nc + 2 * n, rc = -1;
    double(*V)[3] = malloc((size_t)(2 * n) * sizeof *V);
    int(*T)[3] = malloc((size_t)nt * sizeof *T);
    long long *e = malloc((size_t)(3 * nc) * sizeof *e); /* the caps' edges, a * n + b */
    if (!V || !T || !e) goto done;
    for (int i = 0; i < n; i++) {
        V[i][0] = V[n + i][0] = P[i][0];
        V[i][1] = V[n + i][1] = P[i][1];
        V[i][2] = z0;
        V[n + i][2] = z1;
    }
    int t = 0;
    for (int i = 0; i < nc; i++) {
        for (int k = 0; k < 3; k++)
            e[3 * i + k] = (long long)cap[i][k] * n + cap[i][(k + 1) % 3];
        T[t][0] = cap[i][0], T[t][1] = cap[i][2], T[t][2] = cap[i][1]; /* seen from below */
        t++;
        T[t][0] = n + cap[i][0], T[t][1] = n + cap[i][1], T[t][2] = n + cap[i][2];
        t++;
    }
    qsort(e, (size_t)(3 * nc), sizeof *e, by_edge);
    /* a path's edge runs as a cap triangle's (the region on its left) or
     * against it: the side faces outward, to its right */
    for (int p = 0; p < npaths; p++)
        for (int i = start[p]; i < start[p + 1]; i++) {
            int j = i + 1 < start[p + 1] ? i + 1 : start[p];
            long long ij = (long long)i * n + j, ji = (long long)j * n + i;
            int a, b;
            if (bsearch(&ij, e, (size_t)(3 * nc), sizeof *e, by_edge))
                a = i, b = j;
            else if (bsearch(&ji, e, (size_t)(3 * nc), sizeof *e, by_edge))
                a = j, b = i;
            else
                goto done;
            T[t][0] = a, T[t][1] = b, T[t][2] = n + b;
            t++;
            T[t][0] = a, T[t][1] = n + b, T[t][2] = n + a;
            t++;
        }
    rc = t;
    *v = V;
    *tri = T;
    V = NULL;
    T = NULL;
done:
    free(cap);
    free(V);
    free(T);
    free(e);
    return rc;
}
