/*
 * flat_faces.c — flat faces of a closed triangle mesh re-cut from their
 * outlines (geom_merge_flat_faces).
 *
 * Triangles that share an edge, a plane and a tag are one face (union-find
 * over the edges).  A face's outline is its edges whose twin lies in another
 * face; walked from vertex to vertex it makes closed loops, one outer and
 * one per hole, unless a vertex has two ways on (the face touches itself
 * there), and then the face is left as it is.  A vertex is dropped from the
 * loops where exactly two faces meet at it and it lies on the straight line
 * between its neighbours: the face across has it on the same straight
 * stretch and drops it too, so the edges still pair up.  The loops, seen
 * along the face's normal, are cut by geom_region_triangles.
 */
#include "flat_faces.h"

#include "../intervals/vec3.h"
#include "edges.h"
#include "earcut.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A boundary edge (an edge whose twin lies in another face) of face g. */
typedef struct bedge {
    int g, a, b;
} bedge;

static int by_face_start(const void *x, const void *y)
{
    const bedge *p = x, *q = y;
    if (p->g != q->g) return p->g < q->g ? -1 : 1;
    return (p->a > q->a) - (p->a < q->a);
}

/* The boundary edge of face g leaving vertex a in B[0 .. nb) (sorted by
 * face and start), or -1; *two set where there are two. */
static int leaving(const bedge *B, int nb, int g, int a, int *two)
{
    int lo = 0, hi = nb;
    bedge key = {g, a, 0};
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (by_face_start(&B[mid], &key) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo >= nb || B[lo].g != g || B[lo].a != a) return -1;
    if (two) *two = lo + 1 < nb && B[lo + 1].g == g && B[lo + 1].a == a;
    return lo;
}

/* Squared distance of V[v] from the line through V[a] and V[b]. */
static double off_line(const double (*V)[3], int a, int b, int v)
{
    double ab[3], av[3], cr[3];
    sub3(V[b], V[a], ab);
    sub3(V[v], V[a], av);
    cross3(av, ab, cr);
    double l2 = dot3(ab, ab);
    return l2 > 0 ? dot3(cr, cr) / l2 : dot3(av, av);
}

/* Face g's outline, its boundary edges B[0 .. nb) (all of face g, sorted
 * by start), walked into loops less the dropped vertices and cut into
 * triangles wound as n: *out (the caller frees it) and their number, or -1
 * when the outline touches itself, will not cut, or out of memory. */
static int recut(const double (*V)[3], const bedge *B, int nb, const double n[3],
                 const unsigned char *drop, int (**out)[3])
{
    int *used = calloc((size_t)nb, sizeof *used), *loop = malloc((size_t)nb * sizeof *loop);
    int *start = malloc((size_t)(nb + 1) * sizeof *start);
    double(*P)[2] = malloc((size_t)nb * sizeof *P);
    int rc = -1, np = 0, k = 0, (*t)[3] = NULL;
    *out = NULL;
    if (!used || !loop || !start || !P) goto done;
    int ax = fabs(n[0]) > fabs(n[1]) ? (fabs(n[0]) > fabs(n[2]) ? 0 : 2)
                                     : (fabs(n[1]) > fabs(n[2]) ? 1 : 2);
    for (int i = 0; i < nb; i++) {
        if (used[i]) continue;
        start[np] = k;
        for (int j = i; !used[j];) {
            used[j] = 1;
            int v = B[j].a, two = 0;
            if (!drop[v]) {
                loop[k] = v;
                P[k][0] = V[v][(ax + 1) % 3];
                P[k][1] = V[v][(ax + 2) % 3];
                k++;
            }
            j = leaving(B, nb, B[j].g, B[j].b, &two);
            if (j < 0 || two) goto done; /* open, or two ways on */
        }
        if (k - start[np] < 3) goto done;
        np++;
    }
    start[np] = k;
    int m = geom_region_triangles((const double(*)[2])P, start, np, &t);
    if (m < 0) goto done;
    for (int i = 0; i < m; i++) {
        double c[3];
        tri_normal3(V[loop[t[i][0]]], V[loop[t[i][1]]], V[loop[t[i][2]]], c);
        int turn = dot3(c, n) < 0;
        int a = loop[t[i][0]], b = loop[t[i][1]], d = loop[t[i][2]];
        t[i][0] = a;
        t[i][1] = turn ? d : b;
        t[i][2] = turn ? b : d;
    }
    rc = m;
    *out = t;
    t = NULL;
done:
    free(used);
    free(loop);
    free(start);
    free(P);
    free(t);
    return rc;
}

typedef struct pair {
    int v, g;
} pair;

static int by_pair(const void *x, const void *y)
{
    const pair *p = x, *q = y;
    if (p->v != q->v) return p->v < q->v ? -1 : 1;
    return (p->g > q->g) - (p->g < q->g);
}

int geom_merge_flat_faces(const double (*V)[3], int nv, int (**T)[3], int **tag, int *nt,
                          double tol)
{
    int n = *nt, ne = 3 * n, rc = -1, nout = 0, capout = n + 16;
    const int(*tri)[3] = (const int(*)[3]) * T;
    geom_edge *e = malloc((size_t)ne * sizeof *e);
    int *up = malloc((size_t)n * sizeof *up), *tw = malloc((size_t)ne * sizeof *tw);
    double(*pl)[4] = malloc((size_t)n * sizeof *pl);
    pair *vg = malloc((size_t)ne * sizeof *vg);
    unsigned char *drop = calloc((size_t)(nv ? nv : 1), 1);
    int *faces = calloc((size_t)(nv ? nv : 1), sizeof *faces);
    pair *order = malloc((size_t)n * sizeof *order); /* .v its face, .g a triangle: by face */
    bedge *B = malloc((size_t)ne * sizeof *B);
    int(*out)[3] = malloc((size_t)capout * sizeof *out);
    int *otag = tag ? malloc((size_t)capout * sizeof *otag) : NULL;
    const int *in_tag = tag ? *tag : NULL;
    int nb = 0;
    if (!e || !up || !tw || !pl || !vg || !drop || !faces || !order || !B || !out || (tag && !otag))
        goto done;
    for (int t = 0; t < n; t++) {
        up[t] = t;
        tri_normal3(V[tri[t][0]], V[tri[t][1]], V[tri[t][2]], pl[t]);
        double l = sqrt(dot3(pl[t], pl[t]));
        for (int k = 0; k < 3; k++)
            pl[t][k] = l > 0 ? pl[t][k] / l : 0;
        pl[t][3] = dot3(pl[t], V[tri[t][0]]);
        for (int k = 0; k < 3; k++)
            e[3 * t + k] = (geom_edge){tri[t][k], tri[t][(k + 1) % 3], t};
    }
    qsort(e, (size_t)ne, sizeof *e, geom_edge_cmp);
    for (int i = 0; i < ne; i++) {
        tw[i] = geom_edge_find(e, ne, e[i].b, e[i].a);
        if (tw[i] < 0) { /* not closed: leave it be */
            rc = 0;
            goto done;
        }
        int t = e[i].t, u = e[tw[i]].t, apart = 0;
        if (dot3(pl[t], pl[u]) < 1 - 1e-12 || (in_tag && in_tag[t] != in_tag[u])) continue;
        for (int k = 0; k < 3; k++)
            apart |= fabs(dot3(pl[t], V[tri[u][k]]) - pl[t][3]) > tol;
        if (!apart) up[geom_set_find(up, t)] = geom_set_find(up, u);
    }
    for (int t = 0; t < n; t++)
        up[t] = geom_set_find(up, t);
    /* how many faces meet at each vertex; the faces' outlines */
    for (int i = 0; i < ne; i++) {
        vg[i] = (pair){e[i].a, up[e[i].t]};
        if (up[e[i].t] != up[e[tw[i]].t]) B[nb++] = (bedge){up[e[i].t], e[i].a, e[i].b};
    }
    qsort(vg, (size_t)ne, sizeof *vg, by_pair);
    for (int i = 0; i < ne; i++)
        if (i == 0 || by_pair(&vg[i - 1], &vg[i]) != 0) faces[vg[i].v]++;
    qsort(B, (size_t)nb, sizeof *B, by_face_start);
    /* a vertex where two faces meet, on a straight stretch of one's outline
     * (so of the other's) */
    for (int i = 0; i < nb; i++) {
        int j = leaving(B, nb, B[i].g, B[i].b, NULL);
        if (faces[B[i].b] == 2 && j >= 0 && off_line(V, B[i].a, B[j].b, B[i].b) <= tol * tol)
            drop[B[i].b] = 1;
    }
    for (int t = 0; t < n; t++)
        order[t] = (pair){up[t], t};
    qsort(order, (size_t)n, sizeof *order, by_pair);
    /* each face re-cut from its outline; where one cannot be, its dropped
     * vertices are kept and every face cut again */
    int again = 1;
    for (int round = 0; again && round < 8; round++) {
        again = 0;
        nout = 0;
        for (int i = 0, bi = 0; i < n && !again;) {
            int g = order[i].v, members = 0;
            while (i + members < n && order[i + members].v == g)
                members++;
            while (bi < nb && B[bi].g < g)
                bi++;
            int b0 = bi;
            while (bi < nb && B[bi].g == g)
                bi++;
            int(*cut)[3] = NULL, m = -1;
            if (members > 1) m = recut(V, B + b0, bi - b0, pl[g], drop, &cut);
            if (m < 0) { /* as it was: its vertices all stay */
                free(cut);
                cut = NULL;
                for (int u = i; u < i + members; u++)
                    for (int k = 0; k < 3; k++)
                        if (drop[tri[order[u].g][k]]) {
                            drop[tri[order[u].g][k]] = 0;
                            again = 1;
                        }
            }
            int add = m >= 0 ? m : members;
            if (nout + add > capout) {
                int c2 = 2 * (nout + add);
                int(*g2)[3] = realloc(out, (size_t)c2 * sizeof *g2);
                if (g2) out = g2;
                int *t2 = g2 && tag ? realloc(otag, (size_t)c2 * sizeof *t2) : NULL;
                if (t2) otag = t2;
                if (!g2 || (tag && !t2)) {
                    free(cut);
                    goto done;
                }
                capout = c2;
            }
            for (int u = 0; u < add; u++) {
                if (tag) otag[nout] = in_tag[order[i].g]; /* one face, one tag */
                memcpy(out[nout++], m >= 0 ? cut[u] : tri[order[i + u].g], sizeof *out);
            }
            free(cut);
            i += members;
        }
    }
    if (again) { /* did not settle: as it was */
        rc = 0;
        goto done;
    }
    free(*T);
    *T = out;
    *nt = nout;
    out = NULL;
    if (tag) {
        free(*tag);
        *tag = otag;
        otag = NULL;
    }
    rc = 0;
done:
    free(e);
    free(up);
    free(tw);
    free(pl);
    free(vg);
    free(drop);
    free(faces);
    free(order);
    free(B);
    free(out);
    free(otag);
    return rc;
}
