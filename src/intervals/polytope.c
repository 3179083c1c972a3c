/*
 * polytope.c — convex polytopes as intersections of halfspaces (the convex
 * hulls of src/geom/hull3d.c are made of them).
 *
 * A polytope is its planes n·x <= d with unit n, plus the vertices it was
 * made from (for bounds and for hull() of a hull).  A line meets it in one
 * interval, found by Cyrus–Beck clipping: each plane the line runs into
 * raises the entry, each it runs out of lowers the exit, and a plane the line
 * is parallel to keeps it all or nothing — the same closed-halfspace rule as
 * shapes.c's halfspace, so two polytopes sharing a face leave no crack.  The
 * boundary's part is the index of the plane that made it, the first of
 * those alike to rounding (a hull's flat face is many triangles, each its
 * own plane: which of them a line meets first was rounding's choice, and a
 * part that changed with it made a flat face look like many).
 *
 * A hull of many faces knows which faces border which (iv_polytope_set_faces:
 * each plane one triangle of the hull).  A line then walks instead of
 * clipping against every plane: from a face facing it (the last line's
 * entry face on this thread, else the face that faces its direction most,
 * from a table over directions), where the line crosses the face's plane
 * beyond an edge of the triangle it steps across, until the crossing lies
 * on the triangle — the entry, as the clipping
 * finds it: the largest entry parameter of all the planes, since the front
 * of a convex body is the upper envelope of its faces' planes.  A step onto
 * a face turned away from the line means the line passes the silhouette:
 * it misses (behind the first face's plane before the crossing, beyond the
 * other's after).  The exit likewise over the faces turned away.  Lines
 * next to each other meet the same faces or neighbours, so a walk takes a
 * step or two; one that takes more than WALK_MAX (a cycle that rounding can
 * make) falls back to the clipping.  hull_revolve.scad's hull has 2,000
 * faces: clipping was 92 % of meshing it.
 */
#include "shape_kinds.h"
#include "vec3.h"

#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Directions are binned on the cube's six faces, BINS × BINS cells each. */
#define BINS 8
#define WALK_MIN 48  /* fewer planes are clipped: a walk would cost more */
#define WALK_MAX 256 /* steps before a walk gives way to clipping */

struct iv_polytope {
    atomic_int refs;
    int n, nv;
    double (*pl)[4];
    double (*v)[3];
    double lo[3], hi[3];
    int32_t (*nb)[3];               /* the planes across each triangle's edges; NULL: clip */
    double (*edge)[3][4];           /* each triangle's edges as planes across it, outward */
    int32_t start[6 * BINS * BINS]; /* per direction bin: the plane facing against it most */
    double eps;                     /* how far beyond an edge a crossing may lie */
    uint16_t *part;                 /* per plane: the first plane alike, its part */
    int32_t (*tri)[3];              /* per plane, its triangle of the hull; NULL: unknown */
};

void iv_polytope_retain(iv_polytope *p)
{
    atomic_fetch_add(&p->refs, 1);
}

void iv_polytope_release(iv_polytope *p)
{
    if (atomic_fetch_sub(&p->refs, 1) != 1) return;
    free(p->nb);
    free(p->edge);
    free(p->tri);
    free(p->part);
    free(p->pl);
    free(p->v);
    free(p);
}

typedef struct {
    double nx;
    int32_t i;
} by_nx;

static int cmp_nx(const void *a, const void *b)
{
    const by_nx *x = a, *y = b;
    return x->nx < y->nx ? -1 : x->nx > y->nx ? 1 : (x->i > y->i) - (x->i < y->i);
}

/* The first plane alike plane i (part[] holds links toward it). */
static int first_alike(uint16_t *part, int i)
{
    while (part[i] != i)
        i = part[i] = part[part[i]];
    return i;
}

/* p->part: each plane's first alike (normals within ALIKE, offsets within
 * ALIKE of the polytope's size), found among the planes sorted on their
 * normals' x. */
static int alike_planes(iv_polytope *p)
{
    const double ALIKE = 1e-9;
    by_nx *o = malloc((size_t)p->n * sizeof *o);
    p->part = malloc((size_t)p->n * sizeof *p->part);
    if (!o || !p->part) {
        free(o);
        return -1;
    }
    double scale = 0;
    for (int k = 0; k < 3; k++)
        scale = fmax(scale, fmax(fabs(p->lo[k]), fabs(p->hi[k])));
    for (int i = 0; i < p->n; i++) {
        o[i] = (by_nx){p->pl[i][0], i};
        p->part[i] = (uint16_t)i;
    }
    qsort(o, (size_t)p->n, sizeof *o, cmp_nx);
    for (int a = 0; a < p->n; a++)
        for (int b = a + 1; b < p->n && o[b].nx - o[a].nx <= ALIKE; b++) {
            const double *q = p->pl[o[b].i], *r = p->pl[o[a].i];
            if (fabs(q[1] - r[1]) > ALIKE || fabs(q[2] - r[2]) > ALIKE ||
                fabs(q[3] - r[3]) > ALIKE * scale)
                continue;
            int x = first_alike(p->part, o[a].i), y = first_alike(p->part, o[b].i);
            p->part[x > y ? x : y] = (uint16_t)(x < y ? x : y);
        }
    for (int i = 0; i < p->n; i++)
        p->part[i] = (uint16_t)first_alike(p->part, i);
    free(o);
    return 0;
}

int iv_shape_polytope(iv_shape *s, const double (*planes)[4], int nplanes, const double (*verts)[3],
                      int nverts)
{
    if (nplanes <= 0 || nplanes > 65536 || nverts <= 0) return -1;
    iv_polytope *p = calloc(1, sizeof *p);
    if (!p) return -1;
    p->pl = malloc((size_t)nplanes * sizeof *p->pl);
    p->v = malloc((size_t)nverts * sizeof *p->v);
    if (!p->pl || !p->v) goto fail;
    for (int i = 0; i < nplanes; i++) {
        double l = sqrt(planes[i][0] * planes[i][0] + planes[i][1] * planes[i][1] +
                        planes[i][2] * planes[i][2]);
        if (!(l > 0) || !isfinite(l) || !isfinite(planes[i][3])) goto fail;
        for (int k = 0; k < 4; k++)
            p->pl[i][k] = planes[i][k] / l;
    }
    for (int k = 0; k < 3; k++) {
        p->lo[k] = INFINITY;
        p->hi[k] = -INFINITY;
    }
    for (int i = 0; i < nverts; i++)
        for (int k = 0; k < 3; k++) {
            if (!isfinite(verts[i][k])) goto fail;
            p->v[i][k] = verts[i][k];
            p->lo[k] = fmin(p->lo[k], verts[i][k]);
            p->hi[k] = fmax(p->hi[k], verts[i][k]);
        }
    p->n = nplanes;
    p->nv = nverts;
    if (alike_planes(p) != 0) goto fail;
    atomic_init(&p->refs, 1);
    memset(s, 0, sizeof *s);
    s->kind = IV_SHAPE_POLYTOPE;
    s->u.polytope.p = p;
    return 0;
fail:
    free(p->part);
    free(p->pl);
    free(p->v);
    free(p);
    return -1;
}

const double (*iv_polytope_vertices(const iv_shape *s, int *n))[3]
{
    if (s->kind != IV_SHAPE_POLYTOPE) return NULL;
    *n = s->u.polytope.p->nv;
    return (const double(*)[3])s->u.polytope.p->v;
}

const double (*iv_polytope_planes(const iv_shape *s, int *n))[4]
{
    if (s->kind != IV_SHAPE_POLYTOPE) return NULL;
    *n = s->u.polytope.p->n;
    return (const double(*)[4])s->u.polytope.p->pl;
}

/* The bin of direction d. */
static int bin_of(const double d[3])
{
    int a = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(d[k]) > fabs(d[a])) a = k;
    double m = fabs(d[a]);
    if (!(m > 0)) return 0;
    int u = (a + 1) % 3, v = (a + 2) % 3;
    int i = (int)((d[u] / m + 1) * 0.5 * BINS), j = (int)((d[v] / m + 1) * 0.5 * BINS);
    i = i < 0 ? 0 : i >= BINS ? BINS - 1 : i;
    j = j < 0 ? 0 : j >= BINS ? BINS - 1 : j;
    return ((2 * a + (d[a] < 0)) * BINS + i) * BINS + j;
}

/* The slot of directed edge a→b in the open-addressed table key (cap a
 * power of two; entries are the edge's bits + 1, 0 empty): its own, or the
 * empty one where it goes. */
static size_t edge_slot(const uint64_t *key, size_t cap, int32_t a, int32_t b)
{
    uint64_t k = ((uint64_t)(uint32_t)a << 32 | (uint32_t)b) + 1;
    size_t h = (size_t)((k * 0x9e3779b97f4a7c15ULL) >> 20) & (cap - 1);
    while (key[h] && key[h] != k)
        h = (h + 1) & (cap - 1);
    return h;
}

int iv_polytope_set_faces(iv_shape *s, const int (*tri)[3])
{
    if (s->kind != IV_SHAPE_POLYTOPE) return -1;
    iv_polytope *p = s->u.polytope.p;
    size_t cap = 16;
    while (cap < 6 * (size_t)p->n)
        cap *= 2;
    uint64_t *key = calloc(cap, sizeof *key);
    int32_t *val = malloc(cap * sizeof *val);
    int32_t(*nb)[3] = malloc((size_t)p->n * sizeof *nb),
    (*own)[3] = malloc((size_t)p->n * sizeof *own);
    double(*edge)[3][4] = NULL;
    int rc = -1;
    if (!key || !val || !nb || !own) goto done;
    /* an edge a→b of one triangle is b→a of its neighbour */
    for (int f = 0; f < p->n; f++)
        for (int k = 0; k < 3; k++) {
            int32_t a = tri[f][k], b = tri[f][(k + 1) % 3];
            if (a < 0 || a >= p->nv || b < 0 || b >= p->nv || a == b) goto done;
            size_t h = edge_slot(key, cap, a, b);
            if (key[h]) goto done; /* the same directed edge twice: not a closed hull */
            key[h] = ((uint64_t)(uint32_t)a << 32 | (uint32_t)b) + 1;
            val[h] = f;
        }
    for (int f = 0; f < p->n; f++)
        for (int k = 0; k < 3; k++) {
            size_t h = edge_slot(key, cap, tri[f][(k + 1) % 3], tri[f][k]);
            if (!key[h]) goto done; /* an open edge */
            nb[f][k] = val[h];
            own[f][k] = tri[f][k];
        }
    p->tri = own;
    own = NULL;
    rc = 0;
    if (p->n < WALK_MIN) goto done; /* clipping is quicker: no walks */
    rc = -1;
    if (!(edge = malloc((size_t)p->n * sizeof *edge))) goto done;
    /* Edge k of triangle f, a–b, as the plane through it square to the
     * face, facing away from the third corner: a crossing of f's plane
     * lies on the triangle when no edge plane has it in front.  (Not the
     * plane across the edge: that is f's own where the two are coplanar, a
     * flat part of the hull made of many triangles.) */
    for (int f = 0; f < p->n; f++)
        for (int k = 0; k < 3; k++) {
            const double *a = p->v[tri[f][k]], *b = p->v[tri[f][(k + 1) % 3]],
                         *c = p->v[tri[f][(k + 2) % 3]];
            double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, m[3];
            cross3(e, p->pl[f], m);
            double l = sqrt(dot3(m, m));
            if (!(l > 0)) goto done;
            double side = dot3(m, c) - dot3(m, a) > 0 ? -1 : 1;
            for (int i = 0; i < 3; i++)
                edge[f][k][i] = side * m[i] / l;
            edge[f][k][3] = side * dot3(m, a) / l;
        }
    for (int b = 0; b < 6 * BINS * BINS; b++) {
        /* the bin's middle direction */
        int a = b / (2 * BINS * BINS), neg = b / (BINS * BINS) % 2, i = b / BINS % BINS,
            j = b % BINS;
        double d[3];
        d[a] = neg ? -1 : 1;
        d[(a + 1) % 3] = (i + 0.5) * 2.0 / BINS - 1;
        d[(a + 2) % 3] = (j + 0.5) * 2.0 / BINS - 1;
        double best = INFINITY;
        for (int f = 0; f < p->n; f++) {
            double c = dot3(p->pl[f], d);
            if (c < best) {
                best = c;
                p->start[b] = f;
            }
        }
    }
    double scale = 0;
    for (int k = 0; k < 3; k++)
        scale = fmax(scale, fmax(fabs(p->lo[k]), fabs(p->hi[k])));
    p->eps = 1e-12 * scale;
    p->nb = nb;
    p->edge = edge;
    nb = NULL;
    edge = NULL;
    rc = 0;
done:
    free(key);
    free(val);
    free(nb);
    free(own);
    free(edge);
    return rc;
}

const int32_t (*iv_polytope_triangles(const iv_shape *s, int *n))[3]
{
    if (s->kind != IV_SHAPE_POLYTOPE || !s->u.polytope.p->tri) return NULL;
    *n = s->u.polytope.p->n;
    return (const int32_t(*)[3])s->u.polytope.p->tri;
}

/* Clip the line o + t·d against every plane: 1 with the entry t0 (plane
 * p0) and exit t1 (p1), 0 when it misses. */
static int clip(const iv_polytope *p, const double o[3], const double d[3], double *t0_,
                double *t1_, int *p0_, int *p1_)
{
    double t0 = -INFINITY, t1 = INFINITY;
    int p0 = 0, p1 = 0;
    for (int i = 0; i < p->n; i++) {
        const double *q = p->pl[i];
        double a = q[0] * d[0] + q[1] * d[1] + q[2] * d[2];
        double c = q[0] * o[0] + q[1] * o[1] + q[2] * o[2] - q[3];
        if (a == 0) {
            if (c > 0) return 0;
            continue;
        }
        double t = -c / a;
        if (a < 0) {
            if (t > t0) {
                t0 = t;
                p0 = i;
            }
        } else if (t < t1) {
            t1 = t;
            p1 = i;
        }
        if (!(t0 < t1)) return 0;
    }
    *t0_ = t0;
    *t1_ = t1;
    *p0_ = p0;
    *p1_ = p1;
    return t0 < t1;
}

/* Walk from face f over the faces turned against the line (side -1: the
 * entry) or away from it (+1: the exit) to the one its crossing lies on:
 * 1 with *t and *face, 0 when the line misses, -1 when the walk gives up. */
static int walk(const iv_polytope *p, const double o[3], const double d[3], int f, int side,
                double *t, int *face)
{
    for (int step = 0; step < WALK_MAX; step++) {
        const double *q = p->pl[f];
        double a = dot3(q, d);
        if (!(a * side > 0)) return -1;
        double tf = -(dot3(q, o) - q[3]) / a, x[3];
        for (int k = 0; k < 3; k++)
            x[k] = o[k] + tf * d[k];
        int g = -1;
        double worst = p->eps;
        for (int k = 0; k < 3; k++) {
            double over = dot3(p->edge[f][k], x) - p->edge[f][k][3];
            if (over > worst) {
                worst = over;
                g = p->nb[f][k];
            }
        }
        if (g < 0) {
            *t = tf;
            *face = f;
            return 1;
        }
        if (!(dot3(p->pl[g], d) * side > 0)) return 0; /* past the silhouette */
        f = g;
    }
    return -1;
}

/* walk() from face `from` (the last line's on this thread; -1 none) and,
 * where there is none or it is turned the wrong way for this line, from the
 * face facing it most (for the exit, away from it), from the table over
 * directions. */
static int walk_from(const iv_polytope *p, const double o[3], const double d[3], int from, int side,
                     double *t, int *face)
{
    int hit = from >= 0 ? walk(p, o, d, from, side, t, face) : -1;
    if (hit >= 0) return hit;
    double dir[3] = {-side * d[0], -side * d[1], -side * d[2]};
    int fresh = p->start[bin_of(dir)];
    return fresh != from ? walk(p, o, d, fresh, side, t, face) : -1;
}

/* The faces the last walks on this thread ended on, by polytope: where the
 * next line's walks start. */
static _Thread_local struct {
    const iv_polytope *p;
    int32_t f[2];
} last[16];

int iv_polytope_intersect(const iv_polytope *p, const double o[3], const double d[3], int32_t prim,
                          iv_list *out)
{
    double t0, t1;
    int p0, p1, hit = -1;
    if (p->nb) {
        size_t slot = ((uintptr_t)p >> 6) % 16;
        /* (a polytope freed and another made at its address: any face in
         * range is a start) */
        int known = last[slot].p == p && last[slot].f[0] < p->n && last[slot].f[1] < p->n;
        hit = walk_from(p, o, d, known ? last[slot].f[0] : -1, -1, &t0, &p0);
        if (hit == 1) {
            hit = walk_from(p, o, d, known ? last[slot].f[1] : -1, 1, &t1, &p1);
            if (hit == 0) hit = -1; /* an exit walk cannot miss where the entry hit: rounding */
        }
        if (hit == 1) {
            last[slot].p = p;
            last[slot].f[0] = p0;
            last[slot].f[1] = p1;
            hit = t0 < t1;
        }
    }
    if (hit < 0) hit = clip(p, o, d, &t0, &t1, &p0, &p1);
    if (!hit) return 0;
    if (out->n >= out->cap) return -1;
    iv_span *sp = &out->v[out->n++];
    sp->enter = (iv_bound){t0, prim, p->part[p0], 0};
    sp->exit = (iv_bound){t1, prim, p->part[p1], 0};
    return 1;
}

void iv_polytope_normal(const iv_polytope *p, int part, double n[3])
{
    int i = part >= 0 && part < p->n ? part : 0;
    n[0] = p->pl[i][0];
    n[1] = p->pl[i][1];
    n[2] = p->pl[i][2];
}

int iv_polytope_bounds(const iv_polytope *p, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        if (!(p->lo[k] < p->hi[k])) return -1;
        lo[k] = p->lo[k];
        hi[k] = p->hi[k];
    }
    return 0;
}

/* ---- convex hull ------------------------------------------------------------ */
