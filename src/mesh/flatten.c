/*
 * flatten.c — the inner vertices of a contour's plane faces taken away
 * before it is simplified (see dexels.h, mesh_flatten).
 *
 * The contour puts a vertex in every cell a plane face crosses: half the
 * bench part's 53,828 vertices lie inside its six faces, and the simplifier
 * took them away one collapse at a time, each through its queue, its
 * quadrics and its checks.  A vertex whose
 * triangles all lie in one plane and have one colour stands for nothing
 * but that plane: collapsing it into a neighbour whose fan over its ring
 * turns no triangle over changes the surface by no more than the plane's
 * rounding.  So the pass goes in rounds: each collapses every such vertex
 * it can into its nearest neighbour that allows it, then the fans are built
 * again.  Within a round a vertex that took in another is not collapsed,
 * nor taken as a target or a side of one (its fan as built is no longer
 * all of its triangles); the fans of the others still list theirs, less
 * the ones the round dropped, which are skipped.  What it leaves — vertices no
 * collapse could take (a ring no neighbour sees whole) and the faces'
 * borders — the simplifier takes on.  The bench part: 25,574 vertices gone
 * in 17 rounds, 0.04 s; the process 0.39 s -> 0.30 s (with the simplifier's
 * slabs halved; median of 11), its user time 0.47 s -> 0.32 s.
 *
 * A collapse of v into u, a neighbour in v's ring w₀ … w_{k−1} (counter-
 * clockwise seen from outside), is allowed when
 *   - u and v have no common neighbour but u's two in the ring (the link
 *     condition: no edge of four triangles), and those two keep three
 *     neighbours or more;
 *   - every new triangle (u, w_j, w_{j+1}) faces the way v's did, with an
 *     area over a millionth of its two sides' product (none without area).
 */
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_RING 64 /* a longer ring is left to the simplifier */
#define MIN_SINE 1e-6

typedef struct flat {
    mesh *m;
    double eps;     /* off the plane, at most */
    int32_t *start; /* the fans (mesh_vertex_fans) */
    int32_t *fan;
    uint8_t *locked; /* took in a vertex this round, or was taken away */
    int32_t *cand;   /* the vertices that may go: all at first, then those */
    int ncand;       /* whose fans were flat and that did not go */
} flat;

/* Vertex v's ring (counter-clockwise seen from outside) into w and the
 * triangle of each ring edge w[i] → w[i+1] into tri: its length, or 0 where
 * v's fan is not one closed disc of at most MAX_RING triangles. */
static int ring_of(const flat *f, int32_t v, int32_t *w, int32_t *tri)
{
    const mesh *m = f->m;
    int n = 0;
    int32_t from[MAX_RING], to[MAX_RING], ts[MAX_RING];
    for (int32_t x = f->start[v]; x < f->start[v + 1]; x++) {
        int32_t t = f->fan[x];
        const int32_t *tv = m->t + 3 * (size_t)t;
        if (tv[0] < 0) continue; /* dropped this round */
        if (n == MAX_RING) return 0;
        int i = n++, k = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        from[i] = tv[(k + 1) % 3];
        to[i] = tv[(k + 2) % 3];
        ts[i] = t;
        if (from[i] == v || to[i] == v || from[i] == to[i]) return 0;
    }
    if (n < 3) return 0;
    /* chained from -> to: each ring vertex starts one edge */
    w[0] = from[0];
    tri[0] = ts[0];
    int32_t next = to[0];
    for (int i = 1; i < n; i++) {
        int found = -1;
        for (int j = 0; j < n && found < 0; j++)
            if (from[j] == next) found = j;
        if (found < 0) return 0;
        w[i] = from[found];
        tri[i] = ts[found];
        next = to[found];
    }
    if (next != w[0]) return 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (w[i] == w[j]) return 0;
    return n;
}

/* Whether v's fan lies in one plane to f->eps, all of it facing one way,
 * and has one colour: that plane's unit normal into nrm (a test of the fan
 * as the round found it, before its ring is made: most vertices fail it). */
static int flat_fan(const flat *f, int32_t v, double nrm[3])
{
    const mesh *m = f->m;
    double pv[3];
    int32_t first = -1;
    mesh_vertex_at(m, v, pv);
    for (int32_t x = f->start[v]; x < f->start[v + 1]; x++) {
        int32_t t = f->fan[x];
        const int32_t *tv = m->t + 3 * (size_t)t;
        if (tv[0] < 0) continue;
        double p[3][3], c[3];
        for (int k = 0; k < 3; k++)
            mesh_vertex_at(m, tv[k], p[k]);
        tri_normal3(p[0], p[1], p[2], c);
        if (first < 0) {
            double l = sqrt(dot3(c, c));
            if (!(l > 0)) return 0;
            for (int k = 0; k < 3; k++)
                nrm[k] = c[k] / l;
            first = t;
        }
        if (!(dot3(c, nrm) > 0) || (m->npal && m->tc[t] != m->tc[first])) return 0;
        for (int k = 0; k < 3; k++) {
            double d[3];
            sub3(p[k], pv, d);
            if (!(fabs(dot3(d, nrm)) <= f->eps)) return 0;
        }
    }
    return first >= 0;
}

/* The triangles around v the round has not dropped. */
static int live(const flat *f, int32_t v)
{
    int n = 0;
    for (int32_t x = f->start[v]; x < f->start[v + 1]; x++)
        n += f->m->t[3 * (size_t)f->fan[x]] >= 0;
    return n;
}

/* Whether u (ring index i) and v share no neighbour but u's two in the
 * ring, which keep three neighbours or more (none of the three having
 * taken in a vertex this round). */
static int link_ok(const flat *f, const int32_t *w, int n, int i)
{
    const mesh *m = f->m;
    int32_t u = w[i], a = w[(i + n - 1) % n], b = w[(i + 1) % n];
    if (f->locked[u] || f->locked[a] || f->locked[b] || live(f, a) < 4 || live(f, b) < 4) return 0;
    for (int32_t x = f->start[u]; x < f->start[u + 1]; x++) {
        const int32_t *tv = m->t + 3 * (size_t)f->fan[x];
        if (tv[0] < 0) continue;
        for (int k = 0; k < 3; k++) {
            int32_t o = tv[k];
            if (o == u || o == a || o == b) continue;
            for (int j = 0; j < n; j++)
                if (w[j] == o) return 0;
        }
    }
    return 1;
}

/* Whether the fan of u (ring index i) over the rest of the ring faces nrm,
 * every triangle with area. */
static int fan_ok(const flat *f, const int32_t *w, int n, int i, const double nrm[3])
{
    double pu[3];
    mesh_vertex_at(f->m, w[i], pu);
    for (int j = 0; j < n; j++) {
        if (j == i || (j + 1) % n == i) continue;
        double a[3], b[3], ea[3], eb[3], c[3];
        mesh_vertex_at(f->m, w[j], a);
        mesh_vertex_at(f->m, w[(j + 1) % n], b);
        sub3(a, pu, ea);
        sub3(b, pu, eb);
        cross3(ea, eb, c); /* (tri_normal3 of pu, a, b) */
        if (!(dot3(c, nrm) > MIN_SINE * sqrt(dot3(ea, ea) * dot3(eb, eb)))) return 0;
    }
    return 1;
}

/* One round; the number of vertices collapsed, or -1 when out of memory. */
static int round_once(flat *f)
{
    mesh *m = f->m;
    if (mesh_vertex_fans(m, 0, &f->start, &f->fan) != 0) return -1;
    memset(f->locked, 0, (size_t)m->nv);
    int done = 0, kept = 0;
    for (int c = 0; c < f->ncand; c++) {
        int32_t v = f->cand[c], w[MAX_RING], tri[MAX_RING];
        double nrm[3] = {0, 0, 0};
        if (f->locked[v]) {
            f->cand[kept++] = v; /* (took in a vertex: its fan is stale) */
            continue;
        }
        if (!flat_fan(f, v, nrm)) continue;
        int n = ring_of(f, v, w, tri);
        if (n == 0) continue;
        f->cand[kept++] = v;
        double pv[3], best = INFINITY;
        int to = -1;
        mesh_vertex_at(m, v, pv);
        for (int i = 0; i < n; i++) {
            double pu[3];
            mesh_vertex_at(m, w[i], pu);
            double d[3];
            sub3(pu, pv, d);
            if (dot3(d, d) < best && link_ok(f, w, n, i) && fan_ok(f, w, n, i, nrm)) {
                best = dot3(d, d);
                to = i;
            }
        }
        if (to < 0) continue;
        kept--;
        for (int i = 0; i < n; i++) {
            int32_t *tv = m->t + 3 * (size_t)tri[i];
            if (i == to || (i + 1) % n == to) {
                tv[0] = tv[1] = tv[2] = -1; /* (dropped below) */
                continue;
            }
            for (int k = 0; k < 3; k++)
                if (tv[k] == v) tv[k] = w[to];
        }
        f->locked[v] = f->locked[w[to]] = 1;
        done++;
    }
    f->ncand = kept;
    free(f->start);
    free(f->fan);
    f->start = f->fan = NULL;
    /* the dropped triangles out */
    int nt = 0;
    for (int t = 0; t < m->nt; t++) {
        if (m->t[3 * (size_t)t] < 0) continue;
        memmove(m->t + 3 * (size_t)nt, m->t + 3 * (size_t)t, 3 * sizeof *m->t);
        if (m->npal) m->tc[nt] = m->tc[t];
        nt++;
    }
    m->nt = nt;
    return done;
}

int mesh_flatten(mesh *m, double eps)
{
    flat f = {m,
              eps,
              NULL,
              NULL,
              malloc((size_t)m->nv + 1),
              malloc(((size_t)m->nv + 1) * sizeof *f.cand),
              m->nv};
    if (!f.locked || !f.cand) {
        free(f.locked);
        free(f.cand);
        return -1;
    }
    for (int32_t v = 0; v < m->nv; v++)
        f.cand[v] = v;
    int rc;
    while ((rc = round_once(&f)) > 0)
        ;
    free(f.locked);
    free(f.cand);
    if (rc < 0) return -1;
    /* the vertices still used, renumbered in order */
    int32_t *map = malloc(((size_t)m->nv + 1) * sizeof *map);
    if (!map) return -1;
    for (int v = 0; v < m->nv; v++)
        map[v] = -1;
    for (size_t i = 0; i < 3 * (size_t)m->nt; i++)
        map[m->t[i]] = 0;
    int nv = 0;
    for (int v = 0; v < m->nv; v++)
        if (map[v] == 0) {
            memmove(m->v + 3 * (size_t)nv, m->v + 3 * (size_t)v, 3 * sizeof *m->v);
            map[v] = nv++;
        }
    for (size_t i = 0; i < 3 * (size_t)m->nt; i++)
        m->t[i] = map[m->t[i]];
    m->nv = nv;
    free(map);
    return 0;
}
