/*
 * simplify.c — a contoured mesh simplified to a tolerance (see mesh.h,
 * mesh_simplify).
 *
 * Method: half-edge collapses in the order of a quadric error (Garland &
 * Heckbert 1997), each checked against the points it takes away.
 *
 * Order.  Each vertex starts with the planes of its triangles, weighted by
 * their area; a collapse of v into its neighbour u keeps u where it is and
 * gives it both quadrics, and costs the merged quadric at u over the merged
 * weight (the mean squared distance of u from the planes of every triangle
 * the two stand for).  On a flat face every collapse costs nothing; there
 * the shorter edge goes first, so the face shrinks evenly instead of into
 * one vertex of ever more triangles.
 *
 * The bound.  Kept vertices never move, so every vertex of the result is
 * one the contour placed: most are exact ray crossings on the surface, the
 * rest its sharp-feature points, within EPS·h of the features (contour.c).
 * The contour's surface is kept as points: its vertices and the midpoints
 * of its sharp edges (on a curved one, a hole's rim, the vertices alone are
 * too sparse), each on a triangle near it.  A collapse is made
 * only when v and every point on the triangles around v lie within tol of
 * the triangles around u that replace them (the exact distance to a
 * triangle; a point on a sharp edge, of one of their edges, so that a
 * curved sharp edge is followed by the mesh's edges, not cut across), and the points move to one
 * such (the one they lay on, when it stays and is near enough).  The points sample the surface at
 * the grid's spacing, its sharp edges at half of it, so the result stays within about tol of the
 * contour's surface, and of the exact one (measured: 1.2 tol).
 *
 * Where the contour is curved (a vertex whose edges bend by 0.5° to 20°,
 * not a saddle)
 * the bound is the larger tolerance passed (balance.c then moves the
 * vertices out by half the sag); on flat faces, at sharp edges and on the
 * triangles that touch them it is edge_tol.  (A flat face's collapses
 * judged by the larger one left a box 40 triangles, not 12: the vertices
 * the contour pins EPS·h off an edge then pass.)
 *
 * A collapse is refused, besides, when it would
 *   - cost more than tol² (a mean beyond the bound; costs only grow);
 *   - break the surface's manifoldness: the two ends must share exactly
 *     the two neighbours opposite the edge (the link condition), and those
 *     must keep three neighbours each;
 *   - turn a triangle by more than 60° (but a sliver, whose normal says
 *     nothing), or leave one of zero area;
 *   - leave the surface folded: a moved triangle back to back with one
 *     across an edge (more than 150° apart), even where they were so;
 *   - make a triangle more needle-like than both MIN_QUALITY and the worst
 *     it replaces, unless it costs nothing (a plane, where later collapses
 *     take the needles away again).
 * Plane faces.  A triangle whose neighbours all lie in its plane is exact:
 * its shape is the surface there.  While collapses keep it in its plane it
 * needs no points, and a vertex whose triangles are all exact, in one
 * plane, goes without becoming one (flat_within, flat_stays_near).
 *
 * Edges between two colours add a plane through the edge across the
 * surface to both ends' quadrics, so a colour's border keeps its course.
 * A refused collapse is looked at again when one of its ends changes.
 *
 * Threads.  A mesh of more than 2·REGION_VERTICES vertices is cut into
 * slabs of about equal vertex counts across its longest side, each with
 * its own queue, run on the threads; a slab collapses only where every
 * triangle around both ends is its own, so no two touch the same
 * triangles, corner lists or points.  Then the whole mesh's queue takes
 * what is left (the slabs' borders).  The slabs are a rule of the mesh,
 * not of the threads: the result is the same on any number of them.
 */
#include "../geom/closest.h"
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* 4√3·area / Σ edge²: 1 for an equilateral triangle, 0 for a needle. */
#define MIN_QUALITY 0.05
#define COS_TURN 0.5       /* cos 60° */
#define SHARP_COS 0.94     /* cos 20°: an edge that bends more is sharp */
#define COS_CURVED 0.99996 /* cos 0.5° */
#define COS_FOLD 0.866     /* cos 30°: normals more than 150° apart are folded */
#define FLAT 1e-3          /* of the sharp-edge bound: a plane face's triangles, to rounding */
#define FAN_MAX 64         /* the most triangles a collapse may leave around a vertex */

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

/* A collapse in the queue: 16 bytes, four to a cache line.  The key is a
 * float (the order of costs within 1e-7 of each other does not matter) and
 * the ends' stamps are their low 16 bits: an entry taken for current after
 * 65536 changes of an end is only tried out of turn (its cost is computed
 * afresh). */
typedef struct entry {
    float key;
    int32_t v, u; /* collapse v into u */
    uint16_t sv, su;
} entry;

typedef struct simp {
    int nv, nt;
    double *p; /* 3 per vertex: where the contour put it */
    quad *q;
    double *w;     /* the weight (area) of each vertex's quadric */
    int32_t *t;    /* 3 per triangle; t[3i] < 0: gone */
    int32_t *next; /* corner 3i+k's neighbours in its vertex's list */
    int32_t *prev;
    int32_t *head; /* a vertex's first corner; -1: taken away */
    int32_t *val;  /* triangles around a vertex */
    uint32_t *stamp;
    uint32_t *mark;  /* link-condition marks, of each region's own vertices */
    uint8_t *region; /* each vertex's region: only its queue collapses it */
    uint8_t *own;    /* while there are regions: owned(v) */
    /* the points taken away: a list per triangle, through pnext */
    int32_t *phead, *ptail, *pnext;
    int32_t *best;   /* scratch: a point's nearest new triangle */
    uint8_t *crease; /* a point on a sharp edge: it must stay near an edge */
    uint8_t *curved; /* a vertex whose triangles bend (by 0.5° to 20°): on a curve */
    uint8_t *exact;  /* a triangle that is its part of a plane face (flat_within) */
    double tol2, crease_tol2, len_scale, flat_eps;
    int nregions;
} simp;

/* One region's collapses in order of cost: a 4-ary min-heap (shallower than
 * a binary one: fewer cache misses per pop).  Entries are only appended
 * while heaped is 0 (the first edges), then ordered at once by heapify. */
typedef struct queue {
    simp *s;
    int region;
    int32_t *tris; /* the triangles whose three corners are the region's */
    int ntris;
    uint32_t mark_now;
    int live; /* the region's vertices not yet taken away */
    entry *heap;
    size_t nheap, capheap;
    int heaped;
    int oom;
    /* can_collapse's verdict for collapse: each moved triangle's exact
     * flag after it, and whether v is dropped rather than kept as a point */
    uint8_t exact_after[FAN_MAX];
    int drop;
} queue;

static void sift_down(queue *s, size_t i)
{
    entry e = s->heap[i];
    size_t n = s->nheap;
    for (;;) {
        size_t c = 4 * i + 1, best = c;
        if (c >= n) break;
        for (size_t k = c + 1; k < c + 4 && k < n; k++)
            if (s->heap[k].key < s->heap[best].key) best = k;
        if (e.key <= s->heap[best].key) break;
        s->heap[i] = s->heap[best];
        i = best;
    }
    s->heap[i] = e;
}

static int heap_push(queue *s, entry e)
{
    if (s->nheap == s->capheap) {
        size_t c = s->capheap ? 2 * s->capheap : 1024;
        entry *h = realloc(s->heap, c * sizeof *h);
        if (!h) return -1;
        s->heap = h;
        s->capheap = c;
    }
    size_t i = s->nheap++;
    while (s->heaped && i > 0) {
        size_t up = (i - 1) / 4;
        if (s->heap[up].key <= e.key) break;
        s->heap[i] = s->heap[up];
        i = up;
    }
    s->heap[i] = e;
    return 0;
}

static void heapify(queue *s)
{
    for (size_t i = s->nheap / 4 + 1; i-- > 0;)
        if (i < s->nheap) sift_down(s, i);
    s->heaped = 1;
}

static entry heap_pop(queue *s)
{
    entry top = s->heap[0];
    s->heap[0] = s->heap[--s->nheap];
    if (s->nheap) sift_down(s, 0);
    return top;
}

static const double *P(const simp *s, int32_t v)
{
    return s->p + 3 * (size_t)v;
}

/* The quadric of a and b merged into *q, over their merged weight, and
 * the bound its cost must keep: what a collapse of either into the other
 * costs, evaluated at the one kept (cost_at). */
typedef struct merged {
    quad q;
    double w, bound;
} merged;

static void merge(const simp *s, int32_t a, int32_t b, merged *m)
{
    m->q = s->q[a];
    for (int k = 0; k < 10; k++)
        m->q.a[k] += s->q[b].a[k];
    m->w = s->w[a] + s->w[b];
    m->bound = s->curved[a] && s->curved[b] ? s->tol2 : s->crease_tol2;
}

/* The cost of a collapse into the vertex at p, INFINITY past the
 * tolerance. */
static double cost_at(const merged *m, const double *p)
{
    double e = quad_at(&m->q, p) / (m->w > 0 ? m->w : 1);
    return e < 0 ? 0 : e <= m->bound ? e : INFINITY;
}

/* The cost of collapsing v into u, INFINITY past the tolerance. */
static double cost(const simp *s, int32_t v, int32_t u)
{
    merged m;
    merge(s, v, u, &m);
    return cost_at(&m, P(s, u));
}

/* A number in [0, 1) fixed by edge a–b: the order of edges that cost the
 * same (a grid's on a plane), which the heap would otherwise leave to the
 * order they came in - a sweep across a face that drew its triangles into
 * long fans and doubled the points checked (cube_holes cut in two slabs). */
static double jitter(int32_t a, int32_t b)
{
    uint32_t h = (uint32_t)(a < b ? a : b) * 2654435761u ^ (uint32_t)(a < b ? b : a) * 2246822519u;
    h ^= h >> 15;
    h *= 2654435761u;
    h ^= h >> 13;
    return h / 4294967296.0;
}

/* Push the cheaper direction of edge a–b, if either is within tolerance;
 * ties (a plane) go to the shorter edge. */
static int push_edge(queue *qu, int32_t a, int32_t b)
{
    const simp *s = qu->s;
    merged m;
    merge(s, a, b, &m);
    double ab = cost_at(&m, P(s, b)), ba = cost_at(&m, P(s, a));
    if (ab == INFINITY && ba == INFINITY) return 0;
    double l2 = 0;
    for (int k = 0; k < 3; k++)
        l2 += (P(s, a)[k] - P(s, b)[k]) * (P(s, a)[k] - P(s, b)[k]);
    double tie = 1e-9 * s->tol2 * l2 * s->len_scale * (1 + 0.01 * jitter(a, b));
    entry e = ab <= ba
                  ? (entry){(float)(ab + tie), a, b, (uint16_t)s->stamp[a], (uint16_t)s->stamp[b]}
                  : (entry){(float)(ba + tie), b, a, (uint16_t)s->stamp[b], (uint16_t)s->stamp[a]};
    return heap_push(qu, e);
}

/* The quality of triangle abc whose tri_normal3 has length nlen (twice its
 * area). */
static double quality(const double a[3], const double b[3], const double c[3], double nlen)
{
    double l = 0;
    for (int k = 0; k < 3; k++)
        l += (b[k] - a[k]) * (b[k] - a[k]) + (c[k] - b[k]) * (c[k] - b[k]) +
             (a[k] - c[k]) * (a[k] - c[k]);
    return l > 0 ? 2 * sqrt(3.0) * nlen / l : 0;
}

/* Whether point x lies within the tolerance of one of the n triangles nt
 * (moved[i] their indices) — a point on a sharp edge, of one of their
 * edges — trying first the triangle it lies on now (`on`, if among them);
 * the first near enough into s->best[x]. */
static int near_enough(simp *s, int32_t x, int32_t on, double nt[][3][3], const int32_t *moved,
                       const uint8_t *edgy, int n)
{
    int first = 0;
    for (int m = 0; m < n; m++)
        if (moved[m] == on) first = m;
    for (int i = 0; i < n; i++) {
        int m = (first + i) % n;
        int near = 0;
        if (s->crease[x]) {
            for (int e = 0; e < 3 && !near; e++) /* a degenerate triangle: its segment */
                near = geom_triangle_dist2(P(s, x), nt[m][e], nt[m][(e + 1) % 3],
                                           nt[m][(e + 1) % 3]) <= s->crease_tol2;
        } else {
            near = geom_triangle_dist2(P(s, x), nt[m][0], nt[m][1], nt[m][2]) <=
                   (edgy[m] || !s->curved[x] ? s->crease_tol2 : s->tol2);
        }
        if (near) {
            s->best[x] = moved[m];
            return 1;
        }
    }
    return 0;
}

static int32_t across(const simp *s, int32_t t, int32_t a, int32_t b);

/* Whether p lies within s->flat_eps of the plane through `on` across n
 * (of length l). */
static int in_plane(const simp *s, const double n[3], double l, const double *on, const double *p)
{
    return fabs(dot3(n, p) - dot3(n, on)) <= s->flat_eps * l;
}
static int flat_stays_near(queue *qu, int32_t v, const int32_t *moved, double nt[][3][3],
                           const uint8_t *edgy, int nmoved);

/* Whether triangle a (twice its area l2a) is a sliver whose normal says
 * nothing at the tolerance: all of it within 0.3 of the sharp-edge
 * tolerance (squared: tol2) of its longest edge.  The contour leaves such
 * slivers where vertices crowd (crossings held EPS·h off a node, a face
 * point beside a crossing), facing any way; judged by the turn of their
 * normals, the collapses that would take them away were refused
 * (faceted_prisms 580 -> 432 triangles, openscad 336; minkowski_solids
 * 900 -> 732, folds 53 -> 3; both as near the surface as before). */
static int sliver(const double *const a[3], double l2a, double tol2)
{
    double longest = 0;
    for (int i = 0; i < 3; i++) {
        double e[3];
        sub3(a[(i + 1) % 3], a[i], e);
        longest = fmax(longest, dot3(e, e));
    }
    return longest > 0 && l2a * l2a < 0.09 * tol2 * longest;
}

/* Whether two triangles across an edge (normals n1, n2) lie back to back:
 * normals more than COS_FOLD apart. */
static int back_to_back(const double *n1, const double *n2)
{
    return dot3(n1, n2) < -COS_FOLD * sqrt(dot3(n1, n1) * dot3(n2, n2));
}

/* Whether normals a and b point the same way (to about 1e-6 rad). */
static int same_way(const double a[3], const double b[3])
{
    double c[3];
    cross3(a, b, c);
    return dot3(a, b) > 0 && dot3(c, c) <= 1e-12 * dot3(a, a) * dot3(b, b);
}

/* Whether triangle t, whose normal would be `now`, keeps its plane's
 * direction (only a corner in its plane moved). */
static int keeps_plane(const simp *s, int32_t t, const double *now)
{
    const int32_t *tv = s->t + 3 * t;
    double n0[3];
    tri_normal3(P(s, tv[0]), P(s, tv[1]), P(s, tv[2]), n0);
    return same_way(n0, now);
}

/* Whether collapsing v into u leaves the surface folded: a moved triangle
 * (moved[], its corners v, b[], d[] in order, its normal now[] after) back
 * to back with one across an edge of it.  The turn bound alone lets two
 * triangles on either side of a narrow notch each turn less than 60° and
 * meet as a flat flap across it.  A fold the contour left (two triangles
 * back to back already, at a cell whose feature it could not resolve) may
 * not be carried along either: collapses that kept one stretched it into a
 * fin of two long triangles into the solid (0.5 long, minkowski_solids).
 * But where v, u and the edge's ends all lie on a sharp edge the exact
 * surfaces confirmed (crease points, simp_init's on_edge) and the
 * triangles keep their planes, the two faces meet at an acute crease (a
 * star's 20° point) and the collapse runs along it: allowed (the crease
 * vertices crease_cap.c put along such points stayed, acute_tips.scad 844
 * triangles -> 220; 40 random stars and slots 22,512 -> 16,296, none
 * farther from their surface).  Across an edge through v lies another
 * moved triangle (or one of the edge's, which go); across the third, one
 * that stays as it is. */
static int folds(const simp *s, int32_t v, int32_t u, const int32_t *moved, const int32_t *b,
                 const int32_t *d, double (*now)[3], int nmoved)
{
    for (int m = 0; m < nmoved; m++) {
        for (int j = m + 1; j < nmoved; j++) {
            int32_t x = b[j] == d[m] ? d[m] : d[j] == b[m] ? b[m] : -1;
            if (x >= 0 && back_to_back(now[m], now[j]) &&
                !(s->crease[v] && s->crease[u] && s->crease[x] &&
                  keeps_plane(s, moved[m], now[m]) && keeps_plane(s, moved[j], now[j])))
                return 1;
        }
        int32_t o = across(s, moved[m], b[m], d[m]);
        if (o < 0) continue;
        const int32_t *ov = s->t + 3 * o;
        double n2[3];
        tri_normal3(P(s, ov[0]), P(s, ov[1]), P(s, ov[2]), n2);
        if (back_to_back(now[m], n2) && !(s->crease[v] && s->crease[u] && s->crease[b[m]] &&
                                          s->crease[d[m]] && keeps_plane(s, moved[m], now[m])))
            return 1;
    }
    return 0;
}

/* Whether point x lies beside segment a–b, as a point of the curve the
 * segment is a chord of would (its foot in the middle four fifths, nearer
 * than an eighth of the length: a chord of an arc turning up to about 55°),
 * but further than the sharp-edge tolerance.  Points of another sharp edge
 * through a (a box's corner) lie off to the side, not beside. */
static int strays(const simp *s, const double a[3], const double b[3], int32_t x)
{
    double ab[3], ax[3];
    sub3(b, a, ab);
    sub3(P(s, x), a, ax);
    double l2 = dot3(ab, ab), t = dot3(ax, ab);
    if (!(t > 0.1 * l2 && t < 0.9 * l2)) return 0;
    double d2 = dot3(ax, ax) - t * t / l2;
    return d2 > s->crease_tol2 && d2 < l2 / 64;
}

/* Whether a new sharp edge strays from the sharp edge it stands for: an
 * edge u–x that was v–x between two moved triangles (corners as in folds),
 * now bent by more than 20°, with v or a sharp edge's point on v's triangles beside it but
 * further than the tolerance (strays).  The points' own check is one-sided
 * (each near some edge): at the rim of a round hole, collapses along the
 * rim once left a sliver across the hole's mouth, all three corners on the
 * rim, one edge a chord twice the tolerance from it. */
static int sharp_chord_strays(const simp *s, int32_t v, int32_t u, const int32_t *b,
                              const int32_t *d, double (*now)[3], int nmoved)
{
    if (!s->crease[u]) return 0;
    for (int m = 0; m < nmoved; m++) {
        int32_t x = d[m]; /* edge x–v of moved[m] */
        if (!s->crease[x]) continue;
        for (int j = 0; j < nmoved; j++) {
            if (j == m || b[j] != x) continue; /* v–x of moved[j] */
            double l = sqrt(dot3(now[m], now[m]) * dot3(now[j], now[j]));
            if (!(dot3(now[m], now[j]) < SHARP_COS * l)) break;
            if (s->crease[v] && strays(s, P(s, u), P(s, x), v)) return 1;
            for (int32_t k = s->head[v]; k >= 0; k = s->next[k])
                for (int32_t p = s->phead[k / 3]; p >= 0; p = s->pnext[p])
                    if (s->crease[p] && strays(s, P(s, u), P(s, x), p)) return 1;
            break;
        }
    }
    return 0;
}

/* Whether every triangle around v is its region's alone: a collapse there
 * changes nothing another region's queue reads (its triangles, their
 * vertices' corner lists and points) or writes.  It stays so while the
 * regions run (a collapse in r gives u only neighbours in r, and a vertex
 * beside another region's is never collapsed by that one), so it is
 * worked out once (run_regions, into s->own). */
static int owned(const simp *s, int32_t v)
{
    for (int32_t k = s->head[v]; k >= 0; k = s->next[k])
        for (int i = 0; i < 3; i++)
            if (s->region[s->t[3 * (k / 3) + i]] != s->region[v]) return 0;
    return 1;
}

/* Whether collapsing v into u (costing c) keeps the mesh manifold, its
 * triangles sound and every point it moves within the tolerance; fills
 * s->best for those points. */
static int can_collapse(queue *qu, int32_t v, int32_t u, double c)
{
    simp *s = qu->s;
    if (s->val[v] + s->val[u] - 4 > FAN_MAX) return 0;
    if (s->nregions > 1 &&
        !(s->own[v] && s->own[u] && s->region[v] == qu->region && s->region[u] == qu->region))
        return 0;
    /* the link condition: v and u share exactly the two opposite vertices */
    uint32_t mk = ++qu->mark_now;
    for (int32_t k = s->head[u]; k >= 0; k = s->next[k])
        for (int i = 0; i < 3; i++)
            s->mark[s->t[3 * (k / 3) + i]] = mk;
    int shared = 0, edge = 0;
    int32_t opp[2] = {-1, -1};
    int32_t moved[FAN_MAX], nmoved = 0; /* triangles around v that stay */
    for (int32_t k = s->head[v]; k >= 0; k = s->next[k]) {
        int32_t t = k / 3, i = k % 3;
        int32_t b = s->t[3 * t + (i + 1) % 3], d = s->t[3 * t + (i + 2) % 3];
        if (b == u || d == u) {
            if (edge < 2) opp[edge] = b == u ? d : b;
            edge++;
        } else {
            moved[nmoved++] = t;
        }
        /* each neighbour is the next corner of exactly one triangle */
        if (b != u && s->mark[b] == mk) shared++;
    }
    if (edge != 2 || shared != 2) return 0;
    if (s->val[opp[0]] <= 3 || s->val[opp[1]] <= 3) return 0;
    if (s->val[v] + s->val[u] - 4 < 3) return 0;

    /* the triangles that move */
    double worst_old = 1, worst_new = 1, nt[FAN_MAX][3][3], now[FAN_MAX][3];
    uint8_t edgy[FAN_MAX];
    int32_t b[FAN_MAX], d[FAN_MAX]; /* moved[m] is v, b[m], d[m] in order */
    const double *pu = P(s, u);
    for (int m = 0; m < nmoved; m++) {
        const int32_t *tv = s->t + 3 * moved[m];
        const double *a[3], *an[3];
        edgy[m] = 0;
        for (int i = 0; i < 3; i++) {
            edgy[m] |= s->crease[tv[i] == v ? u : tv[i]];
            a[i] = P(s, tv[i]);
            an[i] = tv[i] == v ? pu : a[i];
            memcpy(nt[m][i], an[i], sizeof nt[m][i]);
            if (tv[i] == v) {
                b[m] = tv[(i + 1) % 3];
                d[m] = tv[(i + 2) % 3];
            }
        }
        double n0[3], *n1 = now[m];
        tri_normal3(a[0], a[1], a[2], n0);
        tri_normal3(an[0], an[1], an[2], n1);
        double l0 = sqrt(dot3(n0, n0)), l1 = sqrt(dot3(n1, n1));
        if (!(l1 > 0) || (dot3(n0, n1) < COS_TURN * l0 * l1 && !sliver(a, l0, s->crease_tol2)))
            return 0;
        qu->exact_after[m] =
            s->exact[moved[m]] && dot3(n0, n1) > 0 && in_plane(s, n0, l0, P(s, b[m]), pu);
        double q0 = quality(a[0], a[1], a[2], l0), q1 = quality(an[0], an[1], an[2], l1);
        if (q0 < worst_old) worst_old = q0;
        if (q1 < worst_new) worst_new = q1;
    }
    if (!(c <= 1e-6 * s->tol2) && worst_new < MIN_QUALITY && worst_new < worst_old) return 0;
    if (folds(s, v, u, moved, b, d, now, nmoved)) return 0;
    if (!flat_stays_near(qu, v, moved, nt, edgy, nmoved)) return 0;

    /* v and the points on v's triangles, against the triangles that stay */
    if (!qu->drop && !near_enough(s, v, -1, nt, moved, edgy, nmoved)) return 0;
    for (int32_t k = s->head[v]; k >= 0; k = s->next[k])
        for (int32_t x = s->phead[k / 3]; x >= 0; x = s->pnext[x])
            if (!near_enough(s, x, k / 3, nt, moved, edgy, nmoved)) return 0;
    return !sharp_chord_strays(s, v, u, b, d, now, nmoved);
}

/* Whether the exact triangles around v (parts of plane faces, which keep
 * no points: flat_within) stay within the bound as v goes into u; sets
 * qu->drop.  A moved one that leaves its plane lies, whole, as near the
 * triangle that replaces it as its corners do (the distance to a triangle
 * is convex), and only v moved: v must be within the bound of that one
 * triangle, not only of some new triangle (the check near_enough makes).
 * The edge's two triangles keep their other corners on the new surface,
 * and v is checked as a point.  Where every triangle around v is exact, in
 * one plane, and stays so, the new triangles cover what the old ones did
 * (none turned over, so their areas sum to the old ones'): v is dropped,
 * not kept as a point. */
static int flat_stays_near(queue *qu, int32_t v, const int32_t *moved, double nt[][3][3],
                           const uint8_t *edgy, int nmoved)
{
    simp *s = qu->s;
    const double *pv = P(s, v);
    int drop = 1;
    for (int32_t k = s->head[v]; k >= 0 && drop; k = s->next[k])
        drop = s->exact[k / 3];
    for (int m = 0; m < nmoved && drop; m++)
        drop = qu->exact_after[m];
    /* all in one plane: their normals parallel (each holds v) */
    double ref[3] = {0, 0, 0};
    for (int32_t k = s->head[v]; k >= 0 && drop; k = s->next[k]) {
        const int32_t *tv = s->t + 3 * (k / 3);
        double n[3];
        tri_normal3(P(s, tv[0]), P(s, tv[1]), P(s, tv[2]), n);
        if (k == s->head[v]) memcpy(ref, n, sizeof n);
        drop = same_way(ref, n);
    }
    qu->drop = drop;
    if (drop) return 1;
    for (int m = 0; m < nmoved; m++)
        if (s->exact[moved[m]] && !qu->exact_after[m] &&
            geom_triangle_dist2(pv, nt[m][0], nt[m][1], nt[m][2]) >
                (edgy[m] || !s->curved[v] ? s->crease_tol2 : s->tol2))
            return 0;
    return 1;
}

static void unlink_corner(simp *s, int32_t v, int32_t k)
{
    if (s->prev[k] >= 0)
        s->next[s->prev[k]] = s->next[k];
    else
        s->head[v] = s->next[k];
    if (s->next[k] >= 0) s->prev[s->next[k]] = s->prev[k];
    s->val[v]--;
}

static void link_corner(simp *s, int32_t v, int32_t k)
{
    s->prev[k] = -1;
    s->next[k] = s->head[v];
    if (s->head[v] >= 0) s->prev[s->head[v]] = k;
    s->head[v] = k;
    s->val[v]++;
}

/* Append point x to triangle t's list. */
static void attach(simp *s, int32_t t, int32_t x)
{
    s->pnext[x] = -1;
    if (s->ptail[t] >= 0)
        s->pnext[s->ptail[t]] = x;
    else
        s->phead[t] = x;
    s->ptail[t] = x;
}

static int collapse(queue *qu, int32_t v, int32_t u)
{
    simp *s = qu->s;
    /* the points first, to the triangles can_collapse found for them */
    for (int32_t k = s->head[v]; k >= 0; k = s->next[k]) {
        int32_t t = k / 3, x = s->phead[t];
        s->phead[t] = s->ptail[t] = -1;
        while (x >= 0) {
            int32_t nx = s->pnext[x];
            attach(s, s->best[x], x);
            x = nx;
        }
    }
    int32_t k = s->head[v];
    int m = 0;
    while (k >= 0) {
        int32_t nk = s->next[k], t = k / 3;
        int32_t *tv = s->t + 3 * t;
        if (tv[0] == u || tv[1] == u || tv[2] == u) { /* the edge's triangle: gone */
            for (int i = 0; i < 3; i++)
                if (tv[i] != v) unlink_corner(s, tv[i], 3 * t + i);
            tv[0] = tv[1] = tv[2] = -1;
        } else {
            tv[k % 3] = u;
            link_corner(s, u, k);
            s->exact[t] = qu->exact_after[m++];
        }
        k = nk;
    }
    if (!qu->drop) attach(s, s->best[v], v);
    s->head[v] = -1;
    s->val[v] = 0;
    for (int i = 0; i < 10; i++)
        s->q[u].a[i] += s->q[v].a[i];
    s->w[u] += s->w[v];
    s->stamp[u]++;
    s->stamp[v]++;
    /* u's edges, at their new costs */
    for (k = s->head[u]; k >= 0; k = s->next[k])
        if (push_edge(qu, u, s->t[3 * (k / 3) + (k % 3 + 1) % 3]) != 0) return -1;
    return 0;
}

static void simp_free(simp *s)
{
    free(s->p);
    free(s->q);
    free(s->w);
    free(s->t);
    free(s->next);
    free(s->prev);
    free(s->head);
    free(s->val);
    free(s->stamp);
    free(s->mark);
    free(s->phead);
    free(s->ptail);
    free(s->pnext);
    free(s->best);
    free(s->crease);
    free(s->exact);
    free(s->curved);
    free(s->region);
}

/* A colour's border along edge a–b of a triangle of unit normal n: a plane
 * through the edge, across the surface, in both ends' quadrics. */
static void border_plane(simp *s, int32_t a, int32_t b, const double n[3])
{
    double e[3], x[3];
    for (int i = 0; i < 3; i++)
        e[i] = P(s, b)[i] - P(s, a)[i];
    cross3(e, n, x);
    double l = sqrt(dot3(x, x));
    if (!(l > 0)) return;
    for (int i = 0; i < 3; i++)
        x[i] /= l;
    double w = dot3(e, e); /* each side adds one: the edge counts twice */
    quad_plane(&s->q[a], x, -dot3(x, P(s, a)), w);
    quad_plane(&s->q[b], x, -dot3(x, P(s, a)), w);
    s->w[a] += w;
    s->w[b] += w;
}

/* The triangle on the other side of edge a–b of triangle t, or -1. */
static int32_t across(const simp *s, int32_t t, int32_t a, int32_t b)
{
    for (int32_t c = s->head[b]; c >= 0; c = s->next[c]) {
        int32_t o = c / 3;
        if (o != t && s->t[3 * o + (c % 3 + 1) % 3] == a) return o;
    }
    return -1;
}

/* Whether edge a–b of triangle t bends by more than SHARP_COS between t
 * and the triangle on its other side (tn: every triangle's tri_normal3). */
static int sharp(const simp *s, const double *tn, int32_t t, int32_t a, int32_t b)
{
    int32_t o = across(s, t, a, b);
    if (o < 0) return 1;
    const double *n0 = tn + 3 * (size_t)t, *n1 = tn + 3 * (size_t)o;
    return dot3(n0, n1) < SHARP_COS * sqrt(dot3(n0, n0) * dot3(n1, n1));
}

/* Midpoint x of sharp edge a–b between triangles t and o (tn: every
 * triangle's tri_normal3) moved onto the exact edge between their surfaces:
 * where the planes touching the two surfaces meet the plane across the edge
 * through x, the planes found by rays along the surfaces' normals from
 * points on each triangle's side, a half, a tenth, then a fiftieth of the
 * way from the edge to its centroid; left where it is when a ray finds
 * nothing, or the move is longer than half the edge.  0 when the first two
 * rays find the surfaces either side within 20° of each other: the edge is
 * not sharp, only bent by where the contour put its vertices (a cluster of
 * them held EPS·h off a slight crease between facets, and the slivers
 * between them: faceted_prisms was a quarter more triangles); else 1. */
static int on_edge(const simp *s, mesh_snapper *sn, const double *tn, int32_t t, int32_t o,
                   int32_t a, int32_t b, double x[3])
{
    if (o < 0) return 1;
    double n[3][3], d[3], y[3] = {x[0], x[1], x[2]}, c[2][3], dir[2][3];
    sub3(P(s, b), P(s, a), n[2]);
    double len = sqrt(dot3(n[2], n[2]));
    const int32_t tri[2] = {t, o};
    for (int i = 0; i < 2; i++) {
        const int32_t *tv = s->t + 3 * tri[i];
        const double *m = tn + 3 * (size_t)tri[i];
        double l = sqrt(dot3(m, m));
        if (!(l > 0)) return 1;
        for (int k = 0; k < 3; k++) {
            c[i][k] = (P(s, tv[0])[k] + P(s, tv[1])[k] + P(s, tv[2])[k]) / 3;
            dir[i][k] = m[k] / l;
        }
    }
    static const double toward[3] = {0.5, 0.1, 0.02};
    for (int it = 0; it < 3; it++) {
        for (int i = 0; i < 2; i++) {
            double q[3], hit[3];
            for (int k = 0; k < 3; k++)
                q[k] = y[k] + toward[it] * (c[i][k] - y[k]);
            if (!mesh_snap_probe(sn, q, dir[i], len, sn->cos_feature, hit, n[i])) return 1;
            memcpy(dir[i], n[i], sizeof dir[i]);
            d[i] = dot3(n[i], hit);
        }
        if (it == 0 && dot3(n[0], n[1]) > SHARP_COS) return 0; /* not sharp after all */
        d[2] = dot3(n[2], x);
        double c01[3], c12[3], c20[3];
        cross3(n[0], n[1], c01);
        cross3(n[1], n[2], c12);
        cross3(n[2], n[0], c20);
        double det = dot3(n[0], c12);
        if (!(fabs(det) > 1e-3 * len)) return 1; /* the surfaces meet too flat to tell */
        for (int k = 0; k < 3; k++)
            y[k] = (d[0] * c12[k] + d[1] * c20[k] + d[2] * c01[k]) / det;
    }
    double mv[3];
    sub3(y, x, mv);
    if (dot3(mv, mv) < 0.25 * len * len) memcpy(x, y, sizeof y);
    return 1;
}

/* Whether the surface around vertex v is a saddle: its neighbours lie well
 * to both sides of the plane through it across its normal (the sum of its
 * triangles' tn).  There a triangle's sag changes sign across it, and
 * mesh_balance cannot halve it by moving the corners one way: it is
 * simplified to the tighter bound. */
static int saddle(const simp *s, const double *tn, int32_t v)
{
    double n[3] = {0, 0, 0}, lo = 0, hi = 0;
    for (int32_t k = s->head[v]; k >= 0; k = s->next[k])
        for (int i = 0; i < 3; i++)
            n[i] += tn[3 * (k / 3) + i];
    double l = sqrt(dot3(n, n));
    if (!(l > 0)) return 0;
    for (int32_t k = s->head[v]; k >= 0; k = s->next[k]) {
        double d[3];
        sub3(P(s, s->t[3 * (k / 3) + (k % 3 + 1) % 3]), P(s, v), d);
        double g = dot3(d, n) / l;
        lo = fmin(lo, g);
        hi = fmax(hi, g);
    }
    return -lo > 0.25 * hi && hi > 0.25 * -lo;
}

/* Whether triangle t and its three neighbours lie in one plane (to
 * s->flat_eps): t is then its part of a plane face, exactly (the contour's
 * vertices are on the surface), and stays so while collapses keep it in
 * that plane (can_collapse).  Such triangles need no points: their own
 * shape is the surface (flat_stays_near).  Without points a plane face
 * shrinks to its few triangles at the cost of its collapses alone; with
 * them the last triangles carried every vertex taken away, each checked
 * again at each collapse (cube(20) at --mesh-size 0.25, 80,628 triangles
 * to 12: 0.21 s the whole process before, 0.13 s so). */
static int flat_within(const simp *s, const double *tn, int32_t t)
{
    const int32_t *tv = s->t + 3 * (size_t)t;
    const double *n = tn + 3 * (size_t)t;
    double l = sqrt(dot3(n, n));
    if (!(l > 0)) return 0;
    for (int k = 0; k < 3; k++) {
        int32_t o = across(s, t, tv[k], tv[(k + 1) % 3]);
        if (o < 0) return 0;
        const int32_t *ov = s->t + 3 * (size_t)o;
        const double *no = tn + 3 * (size_t)o;
        if (!(dot3(n, no) > 0)) return 0;
        for (int i = 0; i < 3; i++)
            if (!in_plane(s, n, l, P(s, tv[0]), P(s, ov[i]))) return 0;
    }
    return 1;
}

static int simp_init(simp *s, const mesh *m, double tol, double edge_tol, mesh_snapper *sn)
{
    memset(s, 0, sizeof *s);
    s->nv = m->nv;
    s->nt = m->nt;
    s->tol2 = tol * tol;
    s->crease_tol2 = edge_tol * edge_tol;
    size_t nv = (size_t)m->nv, nt = (size_t)m->nt;
    size_t np = nv + 3 * nt / 2; /* the vertices, then room for a point per edge */
    s->p = malloc(3 * np * sizeof *s->p);
    s->q = calloc(nv, sizeof *s->q);
    s->w = calloc(nv, sizeof *s->w);
    s->t = malloc(3 * nt * sizeof *s->t);
    s->next = malloc(3 * nt * sizeof *s->next);
    s->prev = malloc(3 * nt * sizeof *s->prev);
    s->head = malloc(nv * sizeof *s->head);
    s->val = calloc(nv, sizeof *s->val);
    s->stamp = calloc(nv, sizeof *s->stamp);
    s->mark = calloc(nv, sizeof *s->mark);
    s->phead = malloc(nt * sizeof *s->phead);
    s->ptail = malloc(nt * sizeof *s->ptail);
    s->pnext = malloc(np * sizeof *s->pnext);
    s->best = malloc(np * sizeof *s->best);
    s->crease = calloc(np, 1);
    s->curved = calloc(np, 1);
    s->exact = calloc(nt ? nt : 1, 1);
    s->region = calloc(nv ? nv : 1, 1);
    s->nregions = 1;
    if (!s->region || !s->p || !s->q || !s->w || !s->t || !s->next || !s->prev || !s->head ||
        !s->val || !s->stamp || !s->mark || !s->phead || !s->ptail || !s->pnext || !s->best ||
        !s->crease || !s->curved || !s->exact)
        return -1;
    for (size_t i = 0; i < 3 * nv; i++)
        s->p[i] = m->v[i];
    memcpy(s->t, m->t, 3 * nt * sizeof *s->t);
    for (size_t i = 0; i < nv; i++)
        s->head[i] = -1;
    for (size_t i = 0; i < nt; i++)
        s->phead[i] = s->ptail[i] = -1;
    for (size_t k = 3 * nt; k-- > 0;)
        link_corner(s, s->t[k], (int32_t)k);
    double *tn = malloc(3 * nt * sizeof *tn); /* each triangle's tri_normal3 */
    if (!tn) return -1;
    for (size_t t = 0; t < nt; t++) {
        const int32_t *tv = s->t + 3 * t;
        tri_normal3(P(s, tv[0]), P(s, tv[1]), P(s, tv[2]), tn + 3 * t);
    }
    /* the midpoint of every sharp edge is a point to keep within the bound
     * too: on a curved one (a hole's rim) the vertices alone are too few.
     * With a snapper it is moved onto the exact sharp edge: the chord's
     * midpoint lies inside a curved one by the chord's sag (h²/8r: a fifth
     * of the tolerance at a cube_holes rim, at h 0.25, tolerance 0.006) */
    size_t x = nv;
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) {
            int32_t a = s->t[3 * t + k], b = s->t[3 * t + (k + 1) % 3];
            if (a > b || x >= np || !sharp(s, tn, (int32_t)t, a, b)) continue;
            for (int i = 0; i < 3; i++)
                s->p[3 * x + i] = (P(s, a)[i] + P(s, b)[i]) / 2;
            if (sn &&
                !on_edge(s, sn, tn, (int32_t)t, across(s, (int32_t)t, a, b), a, b, s->p + 3 * x))
                continue;
            s->crease[a] = s->crease[b] = s->crease[x] = 1;
            attach(s, (int32_t)t, (int32_t)x++);
        }
    /* curved: some edge around the vertex bends by more than 0.5°, none
     * is sharp */
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) {
            int32_t a = s->t[3 * t + k], b = s->t[3 * t + (k + 1) % 3];
            int32_t o = across(s, (int32_t)t, a, b);
            if (o < 0) continue;
            const double *n0 = tn + 3 * t, *n1 = tn + 3 * o;
            double l = sqrt(dot3(n0, n0) * dot3(n1, n1));
            if (l > 0 && dot3(n0, n1) < COS_CURVED * l) s->curved[a] = s->curved[b] = 1;
        }
    for (size_t v = 0; v < nv; v++)
        if (s->crease[v] || (s->curved[v] && saddle(s, tn, (int32_t)v))) s->curved[v] = 0;
    s->flat_eps = FLAT * edge_tol;
    for (size_t t = 0; t < nt; t++)
        s->exact[t] = flat_within(s, tn, (int32_t)t);
    double total = 0;
    for (size_t t = 0; t < nt; t++) {
        const int32_t *tv = s->t + 3 * t;
        double n[3] = {tn[3 * t], tn[3 * t + 1], tn[3 * t + 2]};
        double a2 = sqrt(dot3(n, n));
        total += a2 / 2;
        if (!(a2 > 0)) continue;
        for (int k = 0; k < 3; k++)
            n[k] /= a2;
        double d = -dot3(n, P(s, tv[0]));
        for (int k = 0; k < 3; k++) {
            quad_plane(&s->q[tv[k]], n, d, a2 / 2);
            s->w[tv[k]] += a2 / 2;
        }
        if (!m->npal) continue;
        for (int k = 0; k < 3; k++) {
            int32_t a = tv[k], b = tv[(k + 1) % 3], other = across(s, (int32_t)t, a, b);
            if (other >= 0 && m->tc[other] != m->tc[t]) border_plane(s, a, b, n);
        }
    }
    free(tn);
    /* the tie-break's scale: 1 / (the mean triangle's area) */
    s->len_scale = total > 0 ? (double)nt / total : 1;
    return 0;
}

/* Whether e's ends are there and unchanged since it was pushed. */
static int current(const simp *s, const entry *e)
{
    return s->head[e->v] >= 0 && s->head[e->u] >= 0 && (uint16_t)s->stamp[e->v] == e->sv &&
           (uint16_t)s->stamp[e->u] == e->su;
}

/* Collapse what region q->region can, cheapest first.  A collapse refused
 * is looked at again when one of its ends changes, but it may have been
 * refused for a neighbour that changed since (a link, a needle): once the
 * heap is empty, every edge left is tried again, until a pass collapses
 * nothing (a box's last vertex on an edge goes so; trying the dearer
 * direction too let triangles across a curved sharp edge through). */
static void run_queue(queue *q)
{
    simp *s = q->s;
    for (int pass = 0; pass < 4; pass++) {
        int collapsed = 0;
        for (int i = 0; i < q->ntris; i++) {
            const int32_t *tv = s->t + 3 * q->tris[i];
            for (int k = 0; k < 3 && tv[0] >= 0; k++)
                if (tv[k] < tv[(k + 1) % 3] && push_edge(q, tv[k], tv[(k + 1) % 3]) != 0)
                    goto oom; /* each edge once (or twice, when shared with a mixed one) */
        }
        if (!q->heaped) heapify(q);
        /* A closed mesh has three edges a vertex, and a collapse leaves
         * about six entries stale: past four entries a vertex, those are
         * dropped at once rather than popped one by one (a fifth of the
         * time; a looser bound saves less).  At least an eighth more than
         * the entries kept, each time, so that this stays linear. */
        size_t floor = 1024;
        while (q->nheap > 0) {
            if (q->nheap > floor && q->nheap > 4 * (size_t)q->live) {
                size_t n = 0;
                for (size_t i = 0; i < q->nheap; i++)
                    if (current(s, &q->heap[i])) q->heap[n++] = q->heap[i];
                q->nheap = n;
                heapify(q);
                floor = n + n / 8 > 1024 ? n + n / 8 : 1024;
            }
            entry e = heap_pop(q);
            if (!current(s, &e)) continue;
            double c = cost(s, e.v, e.u);
            if (!can_collapse(q, e.v, e.u, c)) continue;
            if (collapse(q, e.v, e.u) != 0) goto oom;
            collapsed++;
            q->live--;
        }
        if (pass && !collapsed) break;
    }
    return;
oom:
    q->oom = 1;
}

typedef struct team {
    queue *q;
    int nq;
    atomic_int next;
} team;

static void *run_team(void *arg)
{
    team *tm = arg;
    for (int r; (r = atomic_fetch_add(&tm->next, 1)) < tm->nq;)
        run_queue(&tm->q[r]);
    return NULL;
}

/* Regions: slabs of about equal vertex counts across the mesh's longest
 * side, at least REGION_VERTICES each, at most MAX_REGIONS (a fixed rule,
 * so the result does not depend on the number of threads). */
#define REGION_VERTICES 10000
#define MAX_REGIONS 16
#define REGION_BINS 4096

static int split_regions(simp *s)
{
    int n = s->nv / REGION_VERTICES;
    if (n > MAX_REGIONS) n = MAX_REGIONS;
    if (n < 2) return 1;
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++)
        lo[k] = hi[k] = s->p[k];
    for (int v = 0; v < s->nv; v++)
        for (int k = 0; k < 3; k++) {
            double x = P(s, v)[k];
            lo[k] = x < lo[k] ? x : lo[k];
            hi[k] = x > hi[k] ? x : hi[k];
        }
    int ax = 0;
    for (int k = 1; k < 3; k++)
        if (hi[k] - lo[k] > hi[ax] - lo[ax]) ax = k;
    double span = hi[ax] - lo[ax];
    if (!(span > 0)) return 1;
    int count[REGION_BINS] = {0}, of[REGION_BINS];
    for (int v = 0; v < s->nv; v++) {
        int b = (int)((P(s, v)[ax] - lo[ax]) / span * REGION_BINS);
        count[b < REGION_BINS ? b : REGION_BINS - 1]++;
    }
    for (int b = 0, seen = 0; b < REGION_BINS; b++) {
        of[b] = (int)((long long)(seen + count[b] / 2) * n / s->nv);
        seen += count[b];
    }
    for (int v = 0; v < s->nv; v++) {
        int b = (int)((P(s, v)[ax] - lo[ax]) / span * REGION_BINS);
        s->region[v] = (uint8_t)of[b < REGION_BINS ? b : REGION_BINS - 1];
    }
    return n;
}

/* The region all three corners of triangle t are in, or -1. */
static int own_region(const simp *s, int t)
{
    int r = s->region[s->t[3 * t]];
    return r == s->region[s->t[3 * t + 1]] && r == s->region[s->t[3 * t + 2]] ? r : -1;
}

/* Each region's queue run on `threads` threads, then (regions' borders)
 * the whole mesh on one; 0 or -1 (out of memory). */
static int run_regions(simp *s, int threads)
{
    int n = split_regions(s), rc = 0;
    queue *q = calloc((size_t)n, sizeof *q);
    int32_t *tris = malloc((size_t)s->nt * sizeof *tris);
    if (!q || !tris) {
        free(q);
        free(tris);
        return -1;
    }
    if (n > 1 && !(s->own = malloc((size_t)s->nv))) n = 1;
    if (n > 1) {
        s->nregions = n;
        for (int v = 0; v < s->nv; v++)
            s->own[v] = (uint8_t)owned(s, v);
        for (int t = 0; t < s->nt; t++) { /* counted, then filled */
            int r = own_region(s, t);
            if (r >= 0) q[r].ntris++;
        }
        for (int r = 0, at = 0; r < n; r++) {
            q[r].tris = tris + at;
            at += q[r].ntris;
            q[r].ntris = 0;
        }
        for (int t = 0; t < s->nt; t++) {
            int r = own_region(s, t);
            if (r >= 0) q[r].tris[q[r].ntris++] = t;
        }
        team tm = {q, n, 0};
        for (int r = 0; r < n; r++) {
            q[r].s = s;
            q[r].region = r;
        }
        for (int v = 0; v < s->nv; v++)
            q[s->region[v]].live++;
        if (threads > n) threads = n;
        pthread_t th[MAX_REGIONS];
        int started = 0;
        for (; started < threads - 1; started++)
            if (pthread_create(&th[started], NULL, run_team, &tm) != 0) break;
        run_team(&tm);
        for (int i = 0; i < started; i++)
            pthread_join(th[i], NULL);
        for (int r = 0; r < n; r++) {
            rc |= q[r].oom ? -1 : 0;
            free(q[r].heap);
        }
        memset(q, 0, sizeof *q);
        free(s->own);
        s->own = NULL;
        memset(s->region, 0, (size_t)s->nv);
        memset(s->mark, 0, (size_t)s->nv * sizeof *s->mark);
        s->nregions = 1;
    }
    q->s = s;
    for (int v = 0; v < s->nv; v++)
        q->live += s->head[v] >= 0;
    q->tris = tris;
    q->ntris = s->nt;
    for (int t = 0; t < s->nt; t++)
        tris[t] = t;
    if (rc == 0) run_queue(q);
    rc |= q->oom ? -1 : 0;
    free(q->heap);
    free(q);
    free(tris);
    return rc;
}

int mesh_simplify(mesh *m, double tol, double edge_tol, mesh_snapper *sn, int threads, char *err,
                  size_t errlen)
{
    if (!(tol > 0) || !(edge_tol > 0) || m->nt == 0) return 0;
    simp s;
    if (simp_init(&s, m, tol, edge_tol, sn) != 0 || run_regions(&s, threads) != 0) goto oom;
    /* compact: the vertices still used, renumbered in order */
    int32_t *map = s.val; /* reused: the new index of each kept vertex */
    int nv = 0;
    for (int v = 0; v < s.nv; v++)
        if (s.head[v] >= 0) {
            for (int k = 0; k < 3; k++)
                m->v[3 * nv + k] = (float)s.p[3 * v + k];
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
