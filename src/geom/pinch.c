/*
 * pinch.c — solids that touch along an edge or at a corner made apart
 * (pinch.h).
 *
 * Pairing.  The half-edges of each undirected edge are sorted by the
 * angle of their triangles about it.  Seen along the edge from its lower
 * numbered end, a triangle that runs the edge backwards has the solid just
 * above its angle and one that runs it forwards just below (the outward
 * normal is the edge's direction crossed with the way into the triangle),
 * so each backward one is the twin of the next one up, which must run
 * forwards.  An edge of two half-edges is paired as it is.
 *
 * Fans.  From a corner at v the next corner about v is across the edge
 * that enters v: its twin leaves v, from the next triangle's corner at v.
 * Each cycle is a fan; the first met keeps v, the rest get copies.
 */
#include "pinch.h"

#include "../intervals/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct half {
    int lo, hi; /* the edge's ends, lower number first */
    int h;      /* 3·triangle + corner of its start */
    double angle;
    int forward; /* runs lo -> hi */
} half;

static int by_edge(const void *x, const void *y)
{
    const half *p = x, *q = y;
    if (p->lo != q->lo) return p->lo < q->lo ? -1 : 1;
    return (p->hi > q->hi) - (p->hi < q->hi);
}

static int by_angle(const void *x, const void *y)
{
    double a = ((const half *)x)->angle, b = ((const half *)y)->angle;
    return (a > b) - (a < b);
}

/* The angles about edge lo -> hi of the half-edges H[0 .. n). */
static void angles(const double (*V)[3], const int (*T)[3], half *H, int n)
{
    double e[3], u[3], w[3];
    sub3(V[H[0].hi], V[H[0].lo], e);
    double l = sqrt(dot3(e, e));
    for (int k = 0; k < 3; k++)
        e[k] /= l;
    /* u: across e, from the axis e is least along */
    int a = fabs(e[0]) <= fabs(e[1]) && fabs(e[0]) <= fabs(e[2]) ? 0
            : fabs(e[1]) <= fabs(e[2])                           ? 1
                                                                 : 2;
    double axis[3] = {0, 0, 0};
    axis[a] = 1;
    cross3(e, axis, u);
    double lu = sqrt(dot3(u, u));
    for (int k = 0; k < 3; k++)
        u[k] /= lu;
    cross3(e, u, w);
    for (int i = 0; i < n; i++) {
        int t = H[i].h / 3, k = H[i].h % 3;
        double d[3];
        sub3(V[T[t][(k + 2) % 3]], V[H[i].lo], d);
        H[i].angle = atan2(dot3(d, w), dot3(d, u));
    }
}

/* Twins of the n > 2 half-edges H (one edge), solid wedge by solid wedge:
 * 0, or GEOM_PINCH_CANNOT. */
static int pair_around(const double (*V)[3], const int (*T)[3], half *H, int n, int *twin)
{
    angles(V, T, H, n);
    qsort(H, (size_t)n, sizeof *H, by_angle);
    for (int i = 0; i < n; i++) {
        const half *p = &H[i], *q = &H[(i + 1) % n];
        double gap = i + 1 < n ? q->angle - p->angle : q->angle + 6.283185307179586 - p->angle;
        if (!(gap > 1e-12)) return GEOM_PINCH_CANNOT; /* one plane, one side */
        if (p->forward) continue;
        if (!q->forward) return GEOM_PINCH_CANNOT;
        twin[p->h] = q->h;
        twin[q->h] = p->h;
    }
    return 0;
}

/* Each half-edge's twin, into twin[3 nt]: 0, or a GEOM_PINCH_ code. */
static int pair_edges(const double (*V)[3], const int (*T)[3], int nt, int *twin)
{
    int n = 3 * nt, rc = 0;
    half *H = malloc((size_t)(n ? n : 1) * sizeof *H);
    if (!H) return GEOM_PINCH_NO_MEMORY;
    for (int t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) {
            int a = T[t][k], b = T[t][(k + 1) % 3];
            H[3 * t + k] = (half){a < b ? a : b, a < b ? b : a, 3 * t + k, 0, a < b};
            twin[3 * t + k] = -1;
        }
    qsort(H, (size_t)n, sizeof *H, by_edge);
    for (int i = 0, j; i < n && rc == 0; i = j) {
        int fw = 0;
        for (j = i; j < n && by_edge(&H[i], &H[j]) == 0; j++)
            fw += H[j].forward;
        if (2 * fw != j - i || H[i].lo == H[i].hi) {
            rc = GEOM_PINCH_CANNOT;
        } else if (j - i == 2) {
            twin[H[i].h] = H[i + 1].h;
            twin[H[i + 1].h] = H[i].h;
        } else {
            rc = pair_around(V, T, H + i, j - i, twin);
        }
    }
    free(H);
    return rc;
}

int geom_unpinch(double (**V)[3], int *nv, int (*T)[3], int nt)
{
    int n = 3 * nt, copies = 0, cap = *nv;
    int *twin = malloc((size_t)(n ? n : 1) * sizeof *twin);
    unsigned char *seen = calloc((size_t)(n ? n : 1), 1);
    unsigned char *kept = calloc((size_t)(*nv ? *nv : 1), 1); /* a vertex's first fan met */
    int rc = !twin || !seen || !kept
                 ? GEOM_PINCH_NO_MEMORY
                 : pair_edges((const double(*)[3]) * V, (const int(*)[3])T, nt, twin);
    for (int c = 0; c < n && rc == 0; c++) {
        if (seen[c]) continue;
        int v = T[c / 3][c % 3], to = v;
        if (kept[v]) { /* another fan about v: a copy of v for it */
            if (*nv == cap) {
                cap = 2 * cap + 16;
                double(*g)[3] = realloc(*V, (size_t)cap * sizeof *g);
                if (!g) {
                    rc = GEOM_PINCH_NO_MEMORY;
                    break;
                }
                *V = g;
            }
            memcpy((*V)[*nv], (*V)[v], sizeof **V);
            to = (*nv)++;
            copies++;
        }
        kept[v] = 1;
        for (int x = c, steps = 0; !seen[x]; steps++) {
            if (steps > n || T[x / 3][x % 3] != v) {
                rc = GEOM_PINCH_CANNOT;
                break;
            }
            seen[x] = 1;
            T[x / 3][x % 3] = to;
            int in = 3 * (x / 3) + (x % 3 + 2) % 3; /* the half-edge into v */
            x = twin[in];
            if (x < 0) {
                rc = GEOM_PINCH_CANNOT;
                break;
            }
        }
    }
    free(twin);
    free(seen);
    free(kept);
    /* (a failure past the first copy leaves T renumbered: the caller's
     * mesh is dropped then) */
    return rc == 0 ? copies : rc;
}

typedef struct at {
    double p[3];
    int v;
} at;

static int by_position(const void *x, const void *y)
{
    const at *a = x, *b = y;
    for (int k = 0; k < 3; k++)
        if (a->p[k] != b->p[k]) return a->p[k] < b->p[k] ? -1 : 1;
    return 0;
}

int geom_move_apart(double (*V)[3], int nv, const int (*T)[3], int nt, double gap)
{
    at *a = malloc((size_t)(nv ? nv : 1) * sizeof *a);
    double(*n)[3] = calloc((size_t)(nv ? nv : 1), sizeof *n);
    unsigned char *shared = calloc((size_t)(nv ? nv : 1), 1);
    int rc = !a || !n || !shared ? GEOM_PINCH_NO_MEMORY : 0;
    for (int v = 0; v < nv && rc == 0; v++) {
        memcpy(a[v].p, V[v], sizeof a[v].p);
        a[v].v = v;
    }
    if (rc == 0) qsort(a, (size_t)nv, sizeof *a, by_position);
    for (int i = 0; i + 1 < nv && rc == 0; i++)
        if (by_position(&a[i], &a[i + 1]) == 0) shared[a[i].v] = shared[a[i + 1].v] = 1;
    /* the angle-weighted normals of the shared ones' fans */
    for (int t = 0; t < nt && rc == 0; t++)
        for (int k = 0; k < 3; k++) {
            int v = T[t][k];
            if (!shared[v]) continue;
            double f[3], e1[3], e2[3];
            tri_normal3(V[T[t][0]], V[T[t][1]], V[T[t][2]], f);
            sub3(V[T[t][(k + 1) % 3]], V[v], e1);
            sub3(V[T[t][(k + 2) % 3]], V[v], e2);
            double lf = sqrt(dot3(f, f)), l1 = sqrt(dot3(e1, e1)), l2 = sqrt(dot3(e2, e2));
            if (!(lf > 0 && l1 > 0 && l2 > 0)) continue;
            double angle = acos(fmax(-1, fmin(1, dot3(e1, e2) / (l1 * l2))));
            for (int c = 0; c < 3; c++)
                n[v][c] += angle * f[c] / lf;
        }
    for (int v = 0; v < nv && rc == 0; v++) {
        if (!shared[v]) continue;
        double l = sqrt(dot3(n[v], n[v]));
        if (!(l > 0.1)) { /* the normals cancel: no side is inward */
            rc = GEOM_PINCH_CANNOT;
            break;
        }
        for (int c = 0; c < 3; c++)
            V[v][c] -= gap * n[v][c] / l;
    }
    free(a);
    free(n);
    free(shared);
    return rc;
}
