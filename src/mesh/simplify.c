/*
 * simplify.c — a contoured mesh simplified to a tolerance (see mesh.h,
 * mesh_simplify).
 *
 * Method: half-edge collapses in order of a quadric error (Garland &
 * Heckbert 1997).  Each vertex starts with the planes of its triangles,
 * weighted by their area; a collapse of v into its neighbour u keeps u where
 * it is and gives it both quadrics, and its cost is the merged quadric at u
 * over the merged weight: the area-weighted mean squared distance of u from
 * the planes of every triangle the two stand for.  Kept vertices never
 * move, so every vertex of the result is one the contour placed (most of
 * them exact ray crossings on the surface, the rest its sharp-feature
 * points), and a plane's vertices leave it only when a neighbour off it
 * takes them: on a flat face every collapse costs nothing, along a sharp
 * edge only those along the edge, and a corner is never taken.  Edges
 * between two colours add a plane through the edge across the surface, so
 * a colour's border keeps its course.
 *
 * A collapse is refused when it would
 *   - cost more than tol² (costs only grow: refused for good);
 *   - break the surface's manifoldness: the two ends must share exactly
 *     the two neighbours opposite the edge (the link condition), and
 *     those must keep three neighbours each;
 *   - turn a triangle by more than 60°, or leave one of zero area;
 *   - make a triangle more needle-like than both the worst it replaces
 *     and MIN_QUALITY, unless it costs nothing (the triangles stay on one
 *     plane, where later collapses take the needles away again).
 * Refused collapses are looked at again only when one end changes.
 */
#include "dexels.h"
#include "../intervals/vec3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* 4√3·area / Σ edge²: 1 for an equilateral triangle, 0 for a needle. */
#define MIN_QUALITY 0.05
#define COS_TURN 0.5 /* cos 60° */

typedef struct quad {
    double a[10]; /* xx xy xz xw yy yz yw zz zw ww of Σ w·(n·x + d)² */
} quad;

static void quad_plane(quad *q, const double n[3], double d, double w)
{
    double v[4] = {n[0], n[1], n[2], d};
    int k = 0;
    for (int i = 0; i < 4; i++)
        for (int j = i; j < 4; j++)
            q->a[k++] += w * v[i] * v[j];
}

static double quad_at(const quad *q, const double p[3])
{
    const double *a = q->a;
    double x = p[0], y = p[1], z = p[2];
    return a[0] * x * x + 2 * a[1] * x * y + 2 * a[2] * x * z + 2 * a[3] * x + a[4] * y * y +
           2 * a[5] * y * z + 2 * a[6] * y + a[7] * z * z + 2 * a[8] * z + a[9];
}

typedef struct entry {
    double cost;
    int32_t v, u; /* collapse v into u */
    uint32_t sv, su;
} entry;

typedef struct simp {
    int nv, nt;
    double *p; /* 3 per vertex */
    quad *q;
    double *w;     /* the weight (area) of each vertex's quadric */
    int32_t *t;    /* 3 per triangle; t[3i] < 0: gone */
    int32_t *next; /* corner 3i+k's next corner of the same vertex */
    int32_t *head; /* a vertex's first corner; -1: none (gone) */
    uint32_t *stamp;
    uint32_t *mark; /* link-condition marks */
    uint32_t mark_now;
    double tol2;
    entry *heap;
    size_t nheap, capheap;
} simp;

static int heap_push(simp *s, entry e)
{
    if (s->nheap == s->capheap) {
        size_t c = s->capheap ? 2 * s->capheap : 1024;
        entry *h = realloc(s->heap, c * sizeof *h);
        if (!h) return -1;
        s->heap = h;
        s->capheap = c;
    }
    size_t i = s->nheap++;
    while (i > 0) {
        size_t up = (i - 1) / 2;
        if (s->heap[up].cost <= e.cost) break;
        s->heap[i] = s->heap[up];
        i = up;
    }
    s->heap[i] = e;
    return 0;
}

static entry heap_pop(simp *s)
{
    entry top = s->heap[0], last = s->heap[--s->nheap];
    size_t i = 0, n = s->nheap;
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= n) break;
        if (c + 1 < n && s->heap[c + 1].cost < s->heap[c].cost) c++;
        if (last.cost <= s->heap[c].cost) break;
        s->heap[i] = s->heap[c];
        i = c;
    }
    if (n) s->heap[i] = last;
    return top;
}

static const double *P(const simp *s, int32_t v)
{
    return s->p + 3 * (size_t)v;
}

/* The cost of collapsing v into u, INFINITY past the tolerance. */
static double cost(const simp *s, int32_t v, int32_t u)
{
    quad q = s->q[u];
    for (int k = 0; k < 10; k++)
        q.a[k] += s->q[v].a[k];
    double w = s->w[u] + s->w[v];
    double e = quad_at(&q, P(s, u)) / (w > 0 ? w : 1);
    if (e < 0) e = 0;
    return e <= s->tol2 ? e : INFINITY;
}

/* Push the cheaper direction of edge a–b, if either is within tolerance. */
static int push_edge(simp *s, int32_t a, int32_t b)
{
    double ab = cost(s, a, b), ba = cost(s, b, a);
    if (ab == INFINITY && ba == INFINITY) return 0;
    entry e = ab <= ba ? (entry){ab, a, b, s->stamp[a], s->stamp[b]}
                       : (entry){ba, b, a, s->stamp[b], s->stamp[a]};
    return heap_push(s, e);
}

static void normal_of(const double a[3], const double b[3], const double c[3], double n[3])
{
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
    }
    cross3(e1, e2, n);
}

static double quality(const double a[3], const double b[3], const double c[3])
{
    double n[3], l = 0;
    normal_of(a, b, c, n);
    for (int k = 0; k < 3; k++)
        l += (b[k] - a[k]) * (b[k] - a[k]) + (c[k] - b[k]) * (c[k] - b[k]) +
             (a[k] - c[k]) * (a[k] - c[k]);
    return l > 0 ? 2 * sqrt(3.0) * sqrt(dot3(n, n)) / l : 0;
}

/* Mark the neighbours of v (the other corners of its triangles). */
static void mark_ring(simp *s, int32_t v)
{
    for (int32_t c = s->head[v]; c >= 0; c = s->next[c]) {
        int32_t t = c / 3;
        for (int k = 0; k < 3; k++)
            s->mark[s->t[3 * t + k]] = s->mark_now;
    }
}

static int valence(const simp *s, int32_t v)
{
    int n = 0;
    for (int32_t c = s->head[v]; c >= 0; c = s->next[c])
        n++;
    return n; /* a closed manifold: as many neighbours as triangles */
}

/* Whether collapsing v into u keeps the mesh manifold and its triangles
 * sound. */
static int can_collapse(simp *s, int32_t v, int32_t u, double cost)
{
    /* the link condition: v and u share exactly the two opposite vertices */
    s->mark_now++;
    mark_ring(s, u);
    int shared = 0, edge = 0;
    int32_t opp[2] = {-1, -1};
    for (int32_t c = s->head[v]; c >= 0; c = s->next[c]) {
        int32_t t = c / 3, k = c % 3;
        int32_t b = s->t[3 * t + (k + 1) % 3], d = s->t[3 * t + (k + 2) % 3];
        if (b == u || d == u) {
            if (edge < 2) opp[edge] = b == u ? d : b;
            edge++;
        }
        /* each neighbour appears as the next corner of exactly one triangle */
        if (b != u && s->mark[b] == s->mark_now) shared++;
    }
    if (edge != 2 || shared != 2) return 0;
    if (valence(s, opp[0]) <= 3 || valence(s, opp[1]) <= 3) return 0;
    if (valence(s, v) + valence(s, u) - 4 < 3) return 0;

    /* the triangles that move */
    double worst_old = 1, worst_new = 1;
    const double *pu = P(s, u);
    for (int32_t c = s->head[v]; c >= 0; c = s->next[c]) {
        int32_t t = c / 3, k = c % 3;
        int32_t b = s->t[3 * t + (k + 1) % 3], d = s->t[3 * t + (k + 2) % 3];
        if (b == u || d == u) continue;
        double n0[3], n1[3];
        normal_of(P(s, v), P(s, b), P(s, d), n0);
        normal_of(pu, P(s, b), P(s, d), n1);
        double l0 = sqrt(dot3(n0, n0)), l1 = sqrt(dot3(n1, n1));
        if (!(l1 > 0) || dot3(n0, n1) < COS_TURN * l0 * l1) return 0;
        double q0 = quality(P(s, v), P(s, b), P(s, d)), q1 = quality(pu, P(s, b), P(s, d));
        if (q0 < worst_old) worst_old = q0;
        if (q1 < worst_new) worst_new = q1;
    }
    /* on a plane (a collapse of no cost) needles may pass: later collapses
     * on it take them away */
    return cost <= 1e-6 * s->tol2 || !(worst_new < MIN_QUALITY && worst_new < worst_old);
}

/* Unlink corner c from vertex v's list. */
static void unlink_corner(simp *s, int32_t v, int32_t c)
{
    int32_t *at = &s->head[v];
    while (*at >= 0 && *at != c)
        at = &s->next[*at];
    if (*at == c) *at = s->next[c];
}

static int collapse(simp *s, int32_t v, int32_t u)
{
    int32_t c = s->head[v];
    while (c >= 0) {
        int32_t nc = s->next[c], t = c / 3;
        int32_t *tv = s->t + 3 * t;
        if (tv[0] == u || tv[1] == u || tv[2] == u) { /* the edge's triangle: gone */
            for (int k = 0; k < 3; k++)
                if (tv[k] != v) unlink_corner(s, tv[k], 3 * t + k);
            tv[0] = tv[1] = tv[2] = -1;
        } else {
            tv[c % 3] = u;
            s->next[c] = s->head[u];
            s->head[u] = c;
        }
        c = nc;
    }
    s->head[v] = -1;
    for (int k = 0; k < 10; k++)
        s->q[u].a[k] += s->q[v].a[k];
    s->w[u] += s->w[v];
    s->stamp[u]++;
    s->stamp[v]++;
    /* u's edges, at their new costs */
    for (c = s->head[u]; c >= 0; c = s->next[c]) {
        int32_t t = c / 3, k = c % 3;
        if (push_edge(s, u, s->t[3 * t + (k + 1) % 3]) != 0) return -1;
    }
    return 0;
}

static void simp_free(simp *s)
{
    free(s->p);
    free(s->q);
    free(s->w);
    free(s->t);
    free(s->next);
    free(s->head);
    free(s->stamp);
    free(s->mark);
    free(s->heap);
}

static int simp_init(simp *s, const mesh *m, double tol)
{
    memset(s, 0, sizeof *s);
    s->nv = m->nv;
    s->nt = m->nt;
    s->tol2 = tol * tol;
    size_t nv = (size_t)m->nv, nt = (size_t)m->nt;
    s->p = malloc(3 * nv * sizeof *s->p);
    s->q = calloc(nv, sizeof *s->q);
    s->w = calloc(nv, sizeof *s->w);
    s->t = malloc(3 * nt * sizeof *s->t);
    s->next = malloc(3 * nt * sizeof *s->next);
    s->head = malloc(nv * sizeof *s->head);
    s->stamp = calloc(nv, sizeof *s->stamp);
    s->mark = calloc(nv, sizeof *s->mark);
    if (!s->p || !s->q || !s->w || !s->t || !s->next || !s->head || !s->stamp || !s->mark)
        return -1;
    for (size_t i = 0; i < 3 * nv; i++)
        s->p[i] = m->v[i];
    memcpy(s->t, m->t, 3 * nt * sizeof *s->t);
    for (size_t i = 0; i < nv; i++)
        s->head[i] = -1;
    for (size_t c = 3 * nt; c-- > 0;) {
        s->next[c] = s->head[s->t[c]];
        s->head[s->t[c]] = (int32_t)c;
    }
    for (size_t t = 0; t < nt; t++) {
        const int32_t *tv = s->t + 3 * t;
        double n[3];
        normal_of(P(s, tv[0]), P(s, tv[1]), P(s, tv[2]), n);
        double a2 = sqrt(dot3(n, n));
        if (!(a2 > 0)) continue;
        for (int k = 0; k < 3; k++)
            n[k] /= a2;
        double d = -dot3(n, P(s, tv[0]));
        for (int k = 0; k < 3; k++) {
            quad_plane(&s->q[tv[k]], n, d, a2 / 2);
            s->w[tv[k]] += a2 / 2;
        }
        if (!m->npal) continue;
        /* a colour's border: a plane through the edge, across the surface */
        for (int k = 0; k < 3; k++) {
            int32_t a = tv[k], b = tv[(k + 1) % 3];
            int32_t other = -1;
            for (int32_t c = s->head[b]; c >= 0 && other < 0; c = s->next[c]) {
                int32_t t2 = c / 3;
                if ((size_t)t2 != t && s->t[3 * t2 + (c % 3 + 1) % 3] == a) other = t2;
            }
            if (other < 0 || m->tc[other] == m->tc[t]) continue;
            double e[3], x[3];
            for (int i = 0; i < 3; i++)
                e[i] = P(s, b)[i] - P(s, a)[i];
            cross3(e, n, x);
            double l = sqrt(dot3(x, x));
            if (!(l > 0)) continue;
            for (int i = 0; i < 3; i++)
                x[i] /= l;
            double w = dot3(e, e); /* each side adds one: the edge counts twice */
            quad_plane(&s->q[a], x, -dot3(x, P(s, a)), w);
            quad_plane(&s->q[b], x, -dot3(x, P(s, a)), w);
            s->w[a] += w;
            s->w[b] += w;
        }
    }
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) {
            int32_t a = s->t[3 * t + k], b = s->t[3 * t + (k + 1) % 3];
            if (a < b && push_edge(s, a, b) != 0) return -1; /* each edge once */
        }
    return 0;
}

int mesh_simplify(mesh *m, double tol, char *err, size_t errlen)
{
    if (!(tol > 0) || m->nt == 0) return 0;
    simp s;
    if (simp_init(&s, m, tol) != 0) goto oom;
    while (s.nheap > 0) {
        entry e = heap_pop(&s);
        if (s.head[e.v] < 0 || s.head[e.u] < 0 || s.stamp[e.v] != e.sv || s.stamp[e.u] != e.su)
            continue;
        if (!can_collapse(&s, e.v, e.u, e.cost)) continue;
        if (collapse(&s, e.v, e.u) != 0) goto oom;
    }
    /* compact: the vertices still used, renumbered in order */
    int32_t *map = s.head; /* reused: -1 gone, else the new index */
    int nv = 0;
    for (int v = 0; v < s.nv; v++)
        if (s.head[v] >= 0) {
            m->v[3 * nv] = (float)s.p[3 * v];
            m->v[3 * nv + 1] = (float)s.p[3 * v + 1];
            m->v[3 * nv + 2] = (float)s.p[3 * v + 2];
            map[v] = nv++;
        }
    int nt = 0;
    for (int t = 0; t < s.nt; t++) {
        if (s.t[3 * t] < 0) continue;
        for (int k = 0; k < 3; k++)
            m->t[3 * nt + k] = map[s.t[3 * t + k]];
        if (m->npal) m->tc[nt] = m->tc[t];
        nt++;
    }
    m->nv = nv;
    m->nt = nt;
    simp_free(&s);
    return 0;
oom:
    simp_free(&s);
    snprintf(err, errlen, "out of memory simplifying the mesh");
    return -1;
}
