/*
 * hull3d.c — the 3D convex hull of a point set by quickhull with outside
 * sets (Barber, Dobkin and Huhdanpaa 1996), for hull() of hundreds of
 * thousands of points and minkowski()'s pairwise sums.  The
 * incremental hull (hull3d_incremental.c), which tests every point against
 * every face, is the
 * last resort here.
 *
 * The hull starts as a tetrahedron of extreme points.  Every other point is
 * put in the outside set of one face it lies more than eps above, or
 * dropped as inside.  Then, face by face, the farthest point of a face's
 * outside set becomes a vertex: the faces it sees (found by walking
 * neighbours from that face) are replaced by a cone from the point to their
 * horizon, and their outside sets are shared out among the cone's faces
 * (a point above a replaced face that is outside the new hull is above a
 * new face).  Each point is looked at O(log n) times in expectation.
 *
 * Invariants: a live face is a triangle, counter-clockwise seen from
 * outside, with its unit outward plane and its three neighbours (nb[j]
 * across the edge v[j] → v[j+1]); each point that is neither a vertex nor
 * known to be inside is in exactly one live face's outside set.
 *
 * Tolerance.  eps is the incremental hull's (a relative 1e-11 of the coordinates):
 * a point within eps of a face is on it, so exact input (grids, a cube's
 * corners, OpenSCAD's tessellations) gives the same solid as the incremental hull.
 * Input coplanar only to within a few eps, or with points a few eps apart,
 * needs guards, since rounding can then bend the hull by about eps and a
 * thin face turns that into a tilt that cuts the hull far off:
 *   - no two vertices are closer than WELD · eps (a grid of the vertices
 *     says; an eye that close to one is left out);
 *   - the face beyond a horizon edge whose cone face would fold back over
 *     it (the first tetrahedron's centre, deep inside, not below the cone
 *     face) is replaced too (not every face the eye is within eps of: a
 *     cylinder's flat cap would then be rebuilt for every rim point);
 *   - the seen faces' vertices off the horizon, and outside points above
 *     no new face, are placed again, the latter looked for beyond the
 *     horizon over faces they are within eps of;
 *   - a horizon that is not one simple loop stops the build before
 *     anything changes, and it starts again over the points still in play,
 *     each moved at random by 10, 100, then 1000 eps (qhull's joggle);
 *   - at the end, a face with a neighbour's corner more than DENT · eps
 *     above its plane leaves its plane out.
 * On random points 1e-9 to 1e-6 apart the result holds every point within
 * a relative 1e-7, and on random points coplanar to within 20 eps mostly
 * so, at worst within 1e-3 (the incremental hull can be off by the whole size
 * there, or take minutes).
 */
#include "hull3d.h"
#include "hull3d_internal.h"
#include "../intervals/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_FACES = 65536, GIVE_UP_FACES = 8 * MAX_FACES, RESCUE = 64, WELD = 1000, DENT = 4 };

typedef struct hface {
    int v[3];
    int nb[3];
    double n[3], d; /* outward plane n·x = d, unit n */
    int head;       /* first point of the outside set, -1 when empty */
    int far;        /* the outside point farthest above the plane */
    double fard;
    int alive;
    int mark, seen; /* visited in walk `mark`, and then seen from its eye */
    int pmark;      /* visited in rescue walk `pmark` */
} hface;

typedef struct hull {
    const double (*P)[3];
    int n;
    double eps;
    hface *F;
    int nf, capf, nalive;
    int free_head; /* dead faces to reuse, linked through nb[0] */
    int *next;     /* outside-set links, per point */
    int *start;    /* per point: the new face whose horizon edge starts there */
    int *vmark;    /* per point: looked at in step `stamp` */
    int *work;     /* faces whose outside sets wait (may hold stale ones) */
    int nwork, capwork;
    int *vis; /* the faces the current eye sees */
    int nvis, capvis;
    int (*hor)[2]; /* horizon: (seen face, edge index) */
    int nhor, caphor;
    int *fresh; /* the new faces of the current step */
    int capfresh;
    int stamp, pstamp;
    int *queue; /* rescue's walk */
    int capqueue;
    double centre[3]; /* of the first tetrahedron */
    double weld;      /* no two vertices closer than this */
    int *ghead;       /* the vertices' grid: lists by cube, */
    int *gnext;       /* linked through the points */
    size_t gcap;
} hull;

static double above(const hull *h, int f, int p)
{
    return dot3(h->F[f].n, h->P[p]) - h->F[f].d;
}

/* Room for `need` entries of `size` bytes in the array whose pointer is
 * at arrp (any object pointer; copied in and out with memcpy), of *cap
 * entries; -1 when out of memory (the array is kept). */
static int grow(void *arrp, int *cap, int need, size_t size)
{
    if (need <= *cap) return 0;
    int c = *cap ? *cap : 64;
    while (c < need)
        c *= 2;
    void *old, *q;
    memcpy(&old, arrp, sizeof old);
    if (!(q = realloc(old, (size_t)c * size))) return -1;
    memcpy(arrp, &q, sizeof q);
    *cap = c;
    return 0;
}

#define GROW(arr, cap, need) grow(&(arr), &(cap), (need), sizeof *(arr))

/* A new live face a, b, c with its plane (neighbours unset); its index, or
 * -1 when out of memory. */
static int face_new(hull *h, int a, int b, int c, const double n[3], double d)
{
    int f;
    if (h->free_head >= 0) {
        f = h->free_head;
        h->free_head = h->F[f].nb[0];
    } else {
        if (GROW(h->F, h->capf, h->nf + 1)) return -1;
        f = h->nf++;
    }
    hface *F = &h->F[f];
    F->v[0] = a;
    F->v[1] = b;
    F->v[2] = c;
    F->nb[0] = F->nb[1] = F->nb[2] = -1;
    memcpy(F->n, n, sizeof F->n);
    F->d = d;
    F->head = F->far = -1;
    F->fard = 0;
    F->alive = 1;
    F->mark = F->seen = F->pmark = 0;
    h->nalive++;
    return f;
}

static void face_kill(hull *h, int f)
{
    h->F[f].alive = 0;
    h->F[f].nb[0] = h->free_head;
    h->free_head = f;
    h->nalive--;
}

/* Put point p, dist above face f, in f's outside set; -1 when out of
 * memory. */
static int outside_add(hull *h, int f, int p, double dist)
{
    hface *F = &h->F[f];
    if (F->head < 0) {
        if (GROW(h->work, h->capwork, h->nwork + 1)) return -1;
        h->work[h->nwork++] = f;
        F->fard = -1;
    }
    h->next[p] = F->head;
    F->head = p;
    if (dist > F->fard) {
        F->fard = dist;
        F->far = p;
    }
    return 0;
}

/* Make the first tetrahedron, as the incremental hull does (geom_hull_tetrahedron).
 * Returns 0, GEOM_HULL_FLAT or GEOM_HULL_NO_MEMORY. */
static int tetrahedron(hull *h, int ids[4])
{
    const double(*P)[3] = h->P;
    int t[4][3];
    if (geom_hull_tetrahedron(P, h->n, h->eps, ids, t) != 0) return GEOM_HULL_FLAT;
    for (int k = 0; k < 4; k++) {
        double nn[3], dd;
        if (vec3_plane(P, t[k][0], t[k][1], t[k][2], nn, &dd)) return GEOM_HULL_FLAT;
        if (face_new(h, t[k][0], t[k][1], t[k][2], nn, dd) < 0) return GEOM_HULL_NO_MEMORY;
    }
    /* neighbours: the face holding each edge reversed */
    for (int f = 0; f < 4; f++)
        for (int j = 0; j < 3; j++) {
            int a = h->F[f].v[j], b = h->F[f].v[(j + 1) % 3];
            for (int g = 0; g < 4; g++)
                for (int k = 0; g != f && k < 3; k++)
                    if (h->F[g].v[k] == b && h->F[g].v[(k + 1) % 3] == a) h->F[f].nb[j] = g;
        }
    for (int k = 0; k < 3; k++)
        h->centre[k] = (P[ids[0]][k] + P[ids[1]][k] + P[ids[2]][k] + P[ids[3]][k]) / 4;
    return 0;
}

/* A point of a seen face's outside set that is above no new face: in
 * exact arithmetic it is inside.  Where nearly coplanar faces bend the
 * hull by rounding, it can still be above a face some way off, across
 * faces it is within eps of: a walk from the faces beyond the horizon over
 * those (at most RESCUE of them) finds it.  Returns that face and *dist,
 * -1 when none, -2 when out of memory. */
static int rescue(hull *h, int p, double *dist)
{
    int stamp = ++h->pstamp, n = 0;
    for (int k = 0; k < h->nhor; k++) {
        int q = h->F[h->fresh[k]].nb[0];
        if (h->F[q].pmark == stamp) continue;
        h->F[q].pmark = stamp;
        if (GROW(h->queue, h->capqueue, n + 1)) return -2;
        h->queue[n++] = q;
    }
    for (int i = 0; i < n && i < RESCUE; i++) {
        int q = h->queue[i];
        double d = above(h, q, p);
        if (d > h->eps) {
            *dist = d;
            return q;
        }
        if (d <= -h->eps) continue;
        for (int j = 0; j < 3; j++) {
            const hface *R = &h->F[h->F[q].nb[j]];
            if (R->pmark == stamp || (R->mark == h->stamp && R->seen)) continue;
            h->F[h->F[q].nb[j]].pmark = stamp;
            if (GROW(h->queue, h->capqueue, n + 1)) return -2;
            h->queue[n++] = h->F[q].nb[j];
        }
    }
    return -1;
}

/* Point p after a step: into the outside set of a new face it is above,
 * or else (only rounding gets there) of a face beyond the horizon; or
 * dropped.  Returns 0, or -1 when out of memory. */
static int place(hull *h, int p)
{
    int to = -1;
    double dist = 0;
    for (int k = 0; to < 0 && k < h->nhor; k++)
        if ((dist = above(h, h->fresh[k], p)) > h->eps) to = h->fresh[k];
    if (to < 0 && (to = rescue(h, p, &dist)) == -2) return -1;
    return to >= 0 ? outside_add(h, to, p, dist) : 0;
}

/* ---- the vertices' grid: no two vertices closer than WELD · eps -------- */

/* The slot of the cube of side 4w holding p, in a table of cap slots. */
static size_t grid_slot(const hull *h, long long cx, long long cy, long long cz)
{
    unsigned long long x = (unsigned long long)cx * 0x9e3779b97f4a7c15ull +
                           (unsigned long long)cy * 0xc2b2ae3d27d4eb4full +
                           (unsigned long long)cz * 0x165667b19e3779f9ull;
    x ^= x >> 29;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 32;
    return (size_t)x & (h->gcap - 1);
}

static size_t grid_slot_of(const hull *h, int p)
{
    const double side = 4 * h->weld;
    return grid_slot(h, (long long)floor(h->P[p][0] / side), (long long)floor(h->P[p][1] / side),
                     (long long)floor(h->P[p][2] / side));
}

static void grid_add(hull *h, int p)
{
    size_t at = grid_slot_of(h, p);
    h->gnext[p] = h->ghead[at];
    h->ghead[at] = p;
}

static void grid_remove(hull *h, int p)
{
    int *t = &h->ghead[grid_slot_of(h, p)];
    while (*t >= 0 && *t != p)
        t = &h->gnext[*t];
    if (*t == p) *t = h->gnext[p];
}

/* 1 when a vertex other than p lies within weld of p in every coordinate:
 * the cubes p is within weld of (3.4 on average), whose lists may hold
 * other cubes' vertices too (slots are shared), which does no harm. */
static int grid_near(const hull *h, int p)
{
    const double side = 4 * h->weld, *x = h->P[p];
    long long c[3];
    int from[3], to[3];
    for (int k = 0; k < 3; k++) {
        c[k] = (long long)floor(x[k] / side);
        double f = x[k] / side - (double)c[k];
        from[k] = f < 0.25 ? -1 : 0;
        to[k] = f > 0.75 ? 1 : 0;
    }
    for (int dx = from[0]; dx <= to[0]; dx++)
        for (int dy = from[1]; dy <= to[1]; dy++)
            for (int dz = from[2]; dz <= to[2]; dz++)
                for (int t = h->ghead[grid_slot(h, c[0] + dx, c[1] + dy, c[2] + dz)]; t >= 0;
                     t = h->gnext[t]) {
                    const double *o = h->P[t];
                    if (t != p && fabs(o[0] - x[0]) <= h->weld && fabs(o[1] - x[1]) <= h->weld &&
                        fabs(o[2] - x[2]) <= h->weld)
                        return 1;
                }
    return 0;
}

/* Leave out the eye of face f, a vertex all but: f's outside set without
 * it, its farthest point found again. */
static int drop_eye(hull *h, int f)
{
    hface *F = &h->F[f];
    int eye = F->far, p = F->head;
    F->head = F->far = -1;
    F->fard = -1;
    while (p >= 0) {
        int nextp = h->next[p];
        if (p != eye) {
            h->next[p] = F->head;
            F->head = p;
            double d = above(h, f, p);
            if (d > F->fard) {
                F->fard = d;
                F->far = p;
            }
        }
        p = nextp;
    }
    if (F->head >= 0) {
        if (GROW(h->work, h->capwork, h->nwork + 1)) return GEOM_HULL_NO_MEMORY;
        h->work[h->nwork++] = f;
    }
    return 0;
}

/* One step: the farthest point of face f's outside set becomes a vertex.
 * Returns 0; 1 when the horizon is not one simple loop or a new face would
 * have no area (nothing changed); GEOM_HULL_NO_MEMORY. */
static int add_point(hull *h, int f)
{
    int eye = h->F[f].far;
    if (grid_near(h, eye)) return drop_eye(h, f);
    const double *pe = h->P[eye];
    int stamp = ++h->stamp;
    h->nvis = 0;
    if (GROW(h->vis, h->capvis, 1)) return GEOM_HULL_NO_MEMORY;
    h->vis[h->nvis++] = f;
    h->F[f].mark = stamp;
    h->F[f].seen = 1;
    for (int done = 0;;) {
        /* the faces the eye sees, walking out from f */
        for (; done < h->nvis; done++) {
            int g = h->vis[done];
            for (int j = 0; j < 3; j++) {
                hface *Q = &h->F[h->F[g].nb[j]];
                if (Q->mark == stamp) continue;
                Q->mark = stamp;
                Q->seen = dot3(Q->n, pe) - Q->d > h->eps;
                if (!Q->seen) continue;
                if (GROW(h->vis, h->capvis, h->nvis + 1)) return GEOM_HULL_NO_MEMORY;
                h->vis[h->nvis++] = h->F[g].nb[j];
            }
        }
        h->nhor = 0;
        for (int i = 0; i < h->nvis; i++)
            for (int j = 0; j < 3; j++) {
                if (h->F[h->F[h->vis[i]].nb[j]].seen) continue;
                if (GROW(h->hor, h->caphor, h->nhor + 1)) return GEOM_HULL_NO_MEMORY;
                h->hor[h->nhor][0] = h->vis[i];
                h->hor[h->nhor][1] = j;
                h->nhor++;
            }
        /* A cone face that the first tetrahedron's centre (inside the
         * final hull, well away from every face) is not below has folded
         * over: the eye is all but in the plane of the face beyond that
         * horizon edge, on its far side.  That face goes too. */
        int grown = 0;
        for (int i = 0; i < h->nhor; i++) {
            const hface *G = &h->F[h->hor[i][0]];
            int j = h->hor[i][1], q = G->nb[j];
            double nn[3], dd;
            if (!vec3_plane(h->P, G->v[j], G->v[(j + 1) % 3], eye, nn, &dd) &&
                dot3(nn, h->centre) - dd < -h->eps)
                continue;
            if (h->F[q].seen) continue; /* already added for another edge */
            if (GROW(h->vis, h->capvis, h->nvis + 1)) return GEOM_HULL_NO_MEMORY;
            h->F[q].seen = 1;
            h->vis[h->nvis++] = q;
            grown = 1;
        }
        if (!grown) break;
    }
    /* The horizon must be one loop: each vertex starts exactly one edge and
     * ends exactly one; and no new face may be flat. */
    int bad = 0;
    for (int i = 0; i < h->nhor; i++) {
        const hface *G = &h->F[h->hor[i][0]];
        int a = G->v[h->hor[i][1]];
        if (h->start[a] != -1) bad = 1;
        h->start[a] = i;
    }
    for (int i = 0; i < h->nhor && !bad; i++) {
        const hface *G = &h->F[h->hor[i][0]];
        int a = G->v[h->hor[i][1]], b = G->v[(h->hor[i][1] + 1) % 3];
        double nn[3], dd;
        if (h->start[b] == -1 || vec3_plane(h->P, a, b, eye, nn, &dd)) bad = 1;
    }
    int loops = 0; /* one loop, not several */
    if (!bad && h->nhor > 0) {
        int a0 = h->F[h->hor[0][0]].v[h->hor[0][1]], a = a0;
        do {
            const hface *G = &h->F[h->hor[h->start[a]][0]];
            a = G->v[(h->hor[h->start[a]][1] + 1) % 3];
            loops++;
        } while (a != a0 && loops <= h->nhor);
        if (loops != h->nhor) bad = 1;
    }
    if (bad || h->nhor < 3) {
        for (int i = 0; i < h->nhor; i++)
            h->start[h->F[h->hor[i][0]].v[h->hor[i][1]]] = -1;
        return 1;
    }
    if (GROW(h->fresh, h->capfresh, h->nhor)) return GEOM_HULL_NO_MEMORY;
    /* the cone: face i on horizon edge i */
    for (int i = 0; i < h->nhor; i++) {
        int g = h->hor[i][0], j = h->hor[i][1];
        int a = h->F[g].v[j], b = h->F[g].v[(j + 1) % 3], other = h->F[g].nb[j];
        double nn[3], dd = 0;
        vec3_plane(h->P, a, b, eye, nn, &dd); /* has area: checked with the horizon above */
        int nf = face_new(h, a, b, eye, nn, dd);
        if (nf < 0) return GEOM_HULL_NO_MEMORY;
        h->fresh[i] = nf;
        h->F[nf].nb[0] = other;
        for (int k = 0; k < 3; k++) /* other's edge b → a */
            if (h->F[other].v[k] == b && h->F[other].v[(k + 1) % 3] == a) h->F[other].nb[k] = nf;
    }
    for (int i = 0; i < h->nhor; i++) {
        int nf = h->fresh[i];
        int b = h->F[nf].v[1];
        int next = h->fresh[h->start[b]];
        h->F[nf].nb[1] = next; /* edge b → eye */
        h->F[next].nb[2] = nf; /* its edge eye → b */
    }
    for (int i = 0; i < h->nhor; i++)
        h->start[h->F[h->fresh[i]].v[0]] = -1;
    /* share out the seen faces' outside sets, and their vertices off the
     * horizon (inside in exact arithmetic; rounding can leave one out,
     * and it is a vertex again later); the seen faces die */
    for (int i = 0; i < h->nhor; i++)
        h->vmark[h->F[h->fresh[i]].v[0]] = stamp;
    h->vmark[eye] = stamp;
    grid_add(h, eye);
    for (int i = 0; i < h->nvis; i++) {
        int g = h->vis[i];
        for (int k = 0; k < 3; k++) {
            int v = h->F[g].v[k];
            if (h->vmark[v] == stamp) continue;
            h->vmark[v] = stamp;
            grid_remove(h, v);
            if (place(h, v)) return GEOM_HULL_NO_MEMORY;
        }
        int p = h->F[g].head;
        h->F[g].head = -1;
        while (p >= 0) {
            int nextp = h->next[p];
            if (p != eye && place(h, p)) return GEOM_HULL_NO_MEMORY;
            p = nextp;
        }
        face_kill(h, g);
    }
    return 0;
}

/* The points still in play after a failed step, by their index into
 * h->P: live faces' vertices and outside sets (a dropped point is inside
 * the final hull too).  Returns their count into *idx (malloc'ed), or -1
 * when out of memory. */
static int in_play(const hull *h, int **idx)
{
    char *keep = calloc((size_t)h->n, 1);
    if (!keep) return -1;
    int m = 0;
    for (int f = 0; f < h->nf; f++) {
        if (!h->F[f].alive) continue;
        for (int k = 0; k < 3; k++)
            if (!keep[h->F[f].v[k]]) keep[h->F[f].v[k]] = 1, m++;
        for (int p = h->F[f].head; p >= 0; p = h->next[p])
            if (!keep[p]) keep[p] = 1, m++;
    }
    *idx = malloc((size_t)(m ? m : 1) * sizeof **idx);
    if (*idx) {
        m = 0;
        for (int i = 0; i < h->n; i++)
            if (keep[i]) (*idx)[m++] = i;
    }
    free(keep);
    return *idx ? m : -1;
}

/* The live faces as a polytope: their planes, and the points they use in
 * input order (as the incremental hull lists them), taken from V (P itself, or
 * the unjittered points: a plane is then raised to its own vertices). */
static int finish(hull *h, const double (*P)[3], const double (*V)[3], iv_shape *s)
{
    if (h->nalive > MAX_FACES) return GEOM_HULL_TOO_MANY;
    double(*pl)[4] = malloc((size_t)h->nalive * sizeof *pl);
    char *used = calloc((size_t)h->n, 1);
    int rc = GEOM_HULL_NO_MEMORY, *at = NULL, (*tri)[3] = NULL;
    double(*vv)[3] = NULL;
    if (!pl || !used) goto done;
    /* A face whose plane has a neighbour's far corner well above it was
     * made across a dent that rounding left (a thin face, tilted by eps
     * over its width): its plane would cut the hull far off.  Such planes,
     * a few at most, are left out: the neighbours' planes close the hull
     * there within the tolerance.  All of them wrong means something else
     * is, and they stay. */
    int np = 0, nv = 0, dents = 0;
    for (int f = 0; f < h->nf; f++) {
        hface *F = &h->F[f];
        F->mark = 0;
        for (int j = 0; F->alive && j < 3; j++) {
            const hface *Q = &h->F[F->nb[j]];
            for (int k = 0; k < 3; k++)
                if (dot3(F->n, P[Q->v[k]]) - F->d > DENT * h->eps) F->mark = 1;
        }
        dents += F->alive && F->mark;
    }
    int drop = dents <= h->nalive / 8;
    for (int f = 0; f < h->nf; f++) {
        const hface *F = &h->F[f];
        if (!F->alive) continue;
        for (int k = 0; k < 3; k++)
            if (!used[F->v[k]]) used[F->v[k]] = 1, nv++;
        if (drop && F->mark) continue;
        memcpy(pl[np], F->n, sizeof F->n);
        pl[np][3] = F->d;
        for (int k = 0; k < 3; k++)
            pl[np][3] = fmax(pl[np][3], dot3(F->n, V[F->v[k]]));
        np++;
    }
    vv = malloc((size_t)nv * sizeof *vv);
    at = malloc((size_t)h->n * sizeof *at);
    if (!vv || !at) goto done;
    nv = 0;
    for (int i = 0; i < h->n; i++)
        if (used[i]) {
            at[i] = nv;
            memcpy(vv[nv++], V[i], sizeof *vv);
        }
    rc = iv_shape_polytope(s, (const double(*)[4])pl, np, (const double(*)[3])vv, nv) == 0
             ? 0
             : GEOM_HULL_NO_MEMORY;
    /* with every face a plane, lines walk over them (polytope.c) */
    if (rc == 0 && np == h->nalive && (tri = malloc((size_t)np * sizeof *tri)) != NULL) {
        np = 0;
        for (int f = 0; f < h->nf; f++)
            if (h->F[f].alive) {
                for (int k = 0; k < 3; k++)
                    tri[np][k] = at[h->F[f].v[k]];
                np++;
            }
        iv_polytope_set_faces(s, (const int(*)[3])tri);
    }
done:
    free(pl);
    free(used);
    free(vv);
    free(at);
    free(tri);
    return rc;
}

/* Quickhull of the n points P with tolerance eps, vertices taken from V.
 * Returns 0 (the polytope in *s), a GEOM_HULL_ code, or 1 when a step
 * failed: then *idx (malloc'ed) holds the *nidx points still in play. */
static int quickhull(const double (*P)[3], const double (*V)[3], int n, double eps, iv_shape *s,
                     int **idx, int *nidx)
{
    hull h;
    memset(&h, 0, sizeof h);
    h.P = P;
    h.n = n;
    h.eps = eps;
    h.free_head = -1;
    h.next = malloc((size_t)n * sizeof *h.next);
    h.start = malloc((size_t)n * sizeof *h.start);
    h.vmark = calloc((size_t)n, sizeof *h.vmark);
    h.weld = WELD * eps;
    h.gcap = 1024;
    while (h.gcap < (size_t)n)
        h.gcap *= 2;
    h.ghead = malloc(h.gcap * sizeof *h.ghead);
    h.gnext = malloc((size_t)n * sizeof *h.gnext);
    int rc = GEOM_HULL_NO_MEMORY;
    if (!h.next || !h.start || !h.vmark || !h.ghead || !h.gnext) goto done;
    for (size_t i = 0; i < h.gcap; i++)
        h.ghead[i] = -1;
    for (int i = 0; i < n; i++)
        h.start[i] = -1;
    int ids[4];
    if ((rc = tetrahedron(&h, ids)) != 0) goto done;
    for (int k = 0; k < 4; k++)
        grid_add(&h, ids[k]);
    rc = GEOM_HULL_NO_MEMORY;
    for (int i = 0; i < n; i++) {
        if (i == ids[0] || i == ids[1] || i == ids[2] || i == ids[3]) continue;
        for (int f = 0; f < 4; f++) {
            double dist = above(&h, f, i);
            if (dist > h.eps) {
                if (outside_add(&h, f, i, dist)) goto done;
                break;
            }
        }
    }
    rc = 0;
    /* each step makes a vertex for good, but for the rare one rounding
     * takes away and gives back: so many more steps than points is a loop */
    long steps = 0, max_steps = 4L * n + 64;
    while (h.nwork > 0 && rc == 0) {
        int f = h.work[--h.nwork];
        if (h.F[f].alive && h.F[f].head >= 0) rc = ++steps > max_steps ? 1 : add_point(&h, f);
        /* far past a polytope's faces: the points still to come lie
         * closer to the hull than those so far and seldom take faces
         * away, so this will not come back under the limit */
        if (h.nalive > GIVE_UP_FACES) rc = GEOM_HULL_TOO_MANY;
    }
    if (rc == 0)
        rc = finish(&h, P, V, s);
    else if (rc == 1 && (*nidx = in_play(&h, idx)) < 0)
        rc = GEOM_HULL_NO_MEMORY;
done:
    free(h.F);
    free(h.next);
    free(h.start);
    free(h.vmark);
    free(h.ghead);
    free(h.gnext);
    free(h.work);
    free(h.vis);
    free(h.hor);
    free(h.fresh);
    free(h.queue);
    return rc;
}

int geom_hull3d(iv_shape *s, const double (*P)[3], int n)
{
    if (n < 4) return GEOM_HULL_FLAT;
    double eps; /* the incremental hull's tolerance: the same solid */
    if (geom_hull_eps(P, n, &eps) != 0) return GEOM_HULL_BAD_INPUT;
    int *idx = NULL, m = 0, *sub = NULL, ms = 0;
    int rc = quickhull(P, P, n, eps, s, &idx, &m);
    /* A failed step (rounding in nearly coplanar input): again over the
     * points still in play, each moved at random by up to 10, 100, 1000
     * times eps (qhull's joggle), which settles which side of a face they
     * are on; the planes are then raised to the points' own positions. */
    unsigned long long seed = 0x9e3779b97f4a7c15ull;
    for (int attempt = 1; rc == 1 && attempt <= 3; attempt++) {
        double(*V)[3] = malloc((size_t)m * sizeof *V);
        double(*J)[3] = malloc((size_t)m * sizeof *J);
        rc = GEOM_HULL_NO_MEMORY;
        if (V && J) {
            double amp = eps * pow(10, attempt);
            for (int i = 0; i < m; i++)
                for (int k = 0; k < 3; k++) {
                    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
                    V[i][k] = P[idx[i]][k];
                    J[i][k] = V[i][k] + amp * ((double)(seed >> 11) / 4503599627370496.0 - 1);
                }
            sub = NULL;
            rc = quickhull((const double(*)[3])J, (const double(*)[3])V, m, eps, s, &sub, &ms);
            if (rc == 1) { /* fewer points in play now, as indices into idx */
                for (int i = 0; i < ms; i++)
                    sub[i] = idx[sub[i]];
                free(idx);
                idx = sub;
                m = ms;
            }
        }
        free(V);
        free(J);
    }
    if (rc == 1) { /* give up: the incremental O(n · faces) hull of what is left */
        double(*V)[3] = malloc((size_t)m * sizeof *V);
        rc = GEOM_HULL_NO_MEMORY;
        if (V) {
            for (int i = 0; i < m; i++)
                memcpy(V[i], P[idx[i]], sizeof *V);
            rc = geom_hull3d_incremental(s, (const double(*)[3])V, m) == 0 ? 0 : GEOM_HULL_FLAT;
            free(V);
        }
    }
    free(idx);
    return rc;
}
