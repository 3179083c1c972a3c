/*
 * minkowski.c — the Minkowski sum of convex parts (minkowski.h).
 */
#include "minkowski.h"

#include "hull3d.h"

#include <stdlib.h>
#include <string.h>

void geom_convex_set_free(geom_convex_set *s)
{
    for (int i = 0; i < s->n; i++)
        free(s->v[i].p);
    free(s->v);
    s->v = NULL;
    s->n = s->cap = 0;
}

geom_convex *geom_convex_set_add(geom_convex_set *s, int n)
{
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 8;
        geom_convex *v = realloc(s->v, (size_t)cap * sizeof *v);
        if (!v) return NULL;
        s->v = v;
        s->cap = cap;
    }
    geom_convex *q = &s->v[s->n];
    q->p = malloc((size_t)(n ? n : 1) * sizeof *q->p);
    q->n = 0;
    if (!q->p) return NULL;
    s->n++;
    return q;
}

/* The hull of all sums p + q; nonzero when flat or out of memory. */
static int hull_of_sums(const geom_convex *a, const geom_convex *b, iv_shape *out)
{
    size_t n = (size_t)a->n * (size_t)b->n;
    double(*S)[3] = malloc((n ? n : 1) * sizeof *S);
    if (!S) return -1;
    size_t k = 0;
    for (int i = 0; i < a->n; i++)
        for (int j = 0; j < b->n; j++, k++)
            for (int d = 0; d < 3; d++)
                S[k][d] = a->p[i][d] + b->p[j][d];
    int rc = geom_hull3d(out, (const double(*)[3])S, (int)n);
    free(S);
    return rc;
}

int geom_minkowski_pair(const geom_convex *a, const geom_convex *b, geom_convex_set *out)
{
    iv_shape h;
    if (hull_of_sums(a, b, &h) != 0) return 0;
    int m;
    const double(*V)[3] = iv_polytope_vertices(&h, &m);
    geom_convex *q = geom_convex_set_add(out, m);
    if (q) {
        memcpy(q->p, V, (size_t)m * sizeof *V);
        q->n = m;
    }
    iv_shape_release(&h);
    return q ? 0 : -1;
}

int geom_points_convex(const double (*V)[3], int n)
{
    iv_shape h;
    if (geom_hull3d(&h, V, n) != 0) return 0;
    int m;
    iv_polytope_vertices(&h, &m);
    iv_shape_release(&h);
    return m == n;
}

int geom_polygon_convex(const double (*V)[2], int n)
{
    int pos = 0, neg = 0;
    for (int i = 0; i < n; i++) {
        const double *a = V[i], *b = V[(i + 1) % n], *d = V[(i + 2) % n];
        double t = (b[0] - a[0]) * (d[1] - b[1]) - (b[1] - a[1]) * (d[0] - b[0]);
        pos |= t > 0;
        neg |= t < 0;
    }
    return !(pos && neg);
}
