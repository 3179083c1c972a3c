/*
 * bsp.c — booleans of polyhedral solids through BSP trees (bsp.h).
 *
 * Each solid becomes a BSP tree of its polygons; a polygon is clipped to
 * the other solid's tree by pushing it down through the planes (a polygon
 * spanning a plane is split) and keeping the pieces that end in the
 * outside cells.  The three operations are csg.js's sequences of clip,
 * invert and build.  Polygons and nodes come from one pool freed at the
 * end; every split and classification counts against the work bound.
 */
#include "bsp.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ---- polygon sets --------------------------------------------------------- */

void geom_polys_free(geom_polys *p)
{
    free(p->v);
    free(p->start);
    free(p->tag);
    memset(p, 0, sizeof *p);
}

int geom_polys_add(geom_polys *p, const double (*v)[3], int k)
{
    return geom_polys_add_tagged(p, v, k, 0);
}

int geom_polys_add_tagged(geom_polys *p, const double (*v)[3], int k, int tag)
{
    if (k < 3) return 0;
    if (p->nv + k > p->capv) {
        int cap = p->capv ? p->capv : 64;
        while (cap < p->nv + k)
            cap *= 2;
        double(*nv)[3] = realloc(p->v, (size_t)cap * sizeof *nv);
        if (!nv) return -1;
        p->v = nv;
        p->capv = cap;
    }
    if (p->n + 2 > p->capn) {
        int cap = p->capn ? 2 * p->capn : 64;
        int *ns = realloc(p->start, (size_t)cap * sizeof *ns);
        if (ns) p->start = ns;
        int *nt = ns ? realloc(p->tag, (size_t)cap * sizeof *nt) : NULL;
        if (!nt) return -1;
        p->tag = nt;
        p->capn = cap;
    }
    if (p->n == 0) p->start[0] = 0;
    memcpy(p->v + p->nv, v, (size_t)k * sizeof *v);
    p->nv += k;
    p->tag[p->n] = tag;
    p->start[++p->n] = p->nv;
    return 0;
}

int geom_polys_append(geom_polys *p, const geom_polys *q)
{
    for (int i = 0; i < q->n; i++)
        if (geom_polys_add_tagged(p, (const double(*)[3])q->v + q->start[i],
                                  q->start[i + 1] - q->start[i], q->tag[i]) != 0)
            return -1;
    return 0;
}

/* ---- the pool --------------------------------------------------------------- */

typedef struct poly {
    int n, tag;
    double plane[4]; /* unit normal (outward) and offset: n·x = w on the polygon */
    double (*v)[3];
} poly;

typedef struct plist {
    poly **v;
    int n, cap;
} plist;

typedef struct node {
    double plane[4];
    int has_plane;
    struct node *front, *back;
    plist polys;
} node;

#define MAX_DEPTH 5000 /* of a tree (see build) */

typedef struct block {
    struct block *next;
    size_t used, size;
    _Alignas(16) unsigned char data[];
} block;

typedef struct bsp {
    block *blocks;
    double eps;
    long *work;
    int failed; /* a GEOM_BSP_ code */
} bsp;

static void *pool_alloc(bsp *b, size_t n)
{
    n = (n + 15) & ~(size_t)15;
    if (!b->blocks || b->blocks->used + n > b->blocks->size) {
        size_t size = n > ((size_t)1 << 20) ? n : ((size_t)1 << 20);
        block *k = malloc(sizeof *k + size);
        if (!k) {
            b->failed = GEOM_BSP_NO_MEMORY;
            return NULL;
        }
        k->next = b->blocks;
        k->used = 0;
        k->size = size;
        b->blocks = k;
    }
    void *p = b->blocks->data + b->blocks->used;
    b->blocks->used += n;
    return p;
}

static void pool_free(bsp *b)
{
    while (b->blocks) {
        block *k = b->blocks->next;
        free(b->blocks);
        b->blocks = k;
    }
}

static void plist_push(bsp *b, plist *l, poly *p)
{
    if (b->failed) return;
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 8;
        poly **v = realloc(l->v, (size_t)cap * sizeof *v);
        if (!v) {
            b->failed = GEOM_BSP_NO_MEMORY;
            return;
        }
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = p;
}

/* A polygon of the n points v (copied) with `tag`, its plane by Newell's
 * method; NULL when degenerate (no area) or out of memory. */
static poly *poly_new(bsp *b, const double (*v)[3], int n, int tag)
{
    double nx = 0, ny = 0, nz = 0, c[3] = {0, 0, 0};
    for (int i = 0; i < n; i++) {
        const double *p = v[i], *q = v[(i + 1) % n];
        nx += (p[1] - q[1]) * (p[2] + q[2]);
        ny += (p[2] - q[2]) * (p[0] + q[0]);
        nz += (p[0] - q[0]) * (p[1] + q[1]);
        for (int k = 0; k < 3; k++)
            c[k] += p[k] / n;
    }
    double len = sqrt(nx * nx + ny * ny + nz * nz);
    if (!(len > 0) || !isfinite(len)) return NULL;
    poly *p = pool_alloc(b, sizeof *p);
    double(*pv)[3] = pool_alloc(b, (size_t)n * sizeof *pv);
    if (!p || !pv) return NULL;
    p->n = n;
    p->tag = tag;
    p->v = pv;
    memcpy(pv, v, (size_t)n * sizeof *pv);
    p->plane[0] = nx / len;
    p->plane[1] = ny / len;
    p->plane[2] = nz / len;
    p->plane[3] = p->plane[0] * c[0] + p->plane[1] * c[1] + p->plane[2] * c[2];
    return p;
}

static void poly_flip(poly *p)
{
    for (int i = 0, j = p->n - 1; i < j; i++, j--) {
        double t[3];
        memcpy(t, p->v[i], sizeof t);
        memcpy(p->v[i], p->v[j], sizeof t);
        memcpy(p->v[j], t, sizeof t);
    }
    for (int k = 0; k < 4; k++)
        p->plane[k] = -p->plane[k];
}

/* ---- splitting ---------------------------------------------------------- */

enum { COPLANAR = 0, FRONT = 1, BACK = 2, SPANNING = 3 };

/* Puts p (or its pieces) on the lists by the plane: coplanar ones facing
 * the same way on cf, the other way on cb. */
static void split(bsp *b, const double pl[4], poly *p, plist *cf, plist *cb, plist *f, plist *bk)
{
    if (b->failed) return;
    if (--*b->work < 0) {
        b->failed = GEOM_BSP_TOO_MUCH;
        return;
    }
    int type = 0;
    enum { LOCAL = 64 };
    int tl[LOCAL], *t = p->n <= LOCAL ? tl : malloc((size_t)p->n * sizeof *t);
    if (!t) {
        b->failed = GEOM_BSP_NO_MEMORY;
        return;
    }
    for (int i = 0; i < p->n; i++) {
        double d = pl[0] * p->v[i][0] + pl[1] * p->v[i][1] + pl[2] * p->v[i][2] - pl[3];
        t[i] = d < -b->eps ? BACK : d > b->eps ? FRONT : COPLANAR;
        type |= t[i];
    }
    switch (type) {
    case COPLANAR:
        plist_push(b, pl[0] * p->plane[0] + pl[1] * p->plane[1] + pl[2] * p->plane[2] > 0 ? cf : cb,
                   p);
        break;
    case FRONT:
        plist_push(b, f, p);
        break;
    case BACK:
        plist_push(b, bk, p);
        break;
    default: {
        double(*fv)[3] = malloc((size_t)(2 * p->n) * sizeof *fv);
        double(*bv)[3] = malloc((size_t)(2 * p->n) * sizeof *bv);
        int nf = 0, nb = 0;
        if (!fv || !bv) {
            b->failed = GEOM_BSP_NO_MEMORY;
        } else {
            for (int i = 0; i < p->n; i++) {
                int j = (i + 1) % p->n;
                const double *vi = p->v[i], *vj = p->v[j];
                if (t[i] != BACK) memcpy(fv[nf++], vi, sizeof *fv);
                if (t[i] != FRONT) memcpy(bv[nb++], vi, sizeof *bv);
                if ((t[i] | t[j]) == SPANNING) {
                    double di = pl[0] * vi[0] + pl[1] * vi[1] + pl[2] * vi[2] - pl[3];
                    double dj = pl[0] * vj[0] + pl[1] * vj[1] + pl[2] * vj[2] - pl[3];
                    double s = di / (di - dj), x[3];
                    for (int k = 0; k < 3; k++)
                        x[k] = vi[k] + (vj[k] - vi[k]) * s;
                    memcpy(fv[nf++], x, sizeof x);
                    memcpy(bv[nb++], x, sizeof x);
                }
            }
            /* the pieces keep the polygon's plane */
            poly *pf = nf >= 3 ? pool_alloc(b, sizeof *pf) : NULL;
            poly *pb = nb >= 3 ? pool_alloc(b, sizeof *pb) : NULL;
            double(*vf)[3] = pf ? pool_alloc(b, (size_t)nf * sizeof *vf) : NULL;
            double(*vb)[3] = pb ? pool_alloc(b, (size_t)nb * sizeof *vb) : NULL;
            if (pf && vf) {
                memcpy(vf, fv, (size_t)nf * sizeof *vf);
                *pf = (poly){nf, p->tag, {p->plane[0], p->plane[1], p->plane[2], p->plane[3]}, vf};
                plist_push(b, f, pf);
            }
            if (pb && vb) {
                memcpy(vb, bv, (size_t)nb * sizeof *vb);
                *pb = (poly){nb, p->tag, {p->plane[0], p->plane[1], p->plane[2], p->plane[3]}, vb};
                plist_push(b, bk, pb);
            }
        }
        free(fv);
        free(bv);
    }
    }
    if (t != tl) free(t);
}

/* ---- trees ------------------------------------------------------------------- */

static node *node_new(bsp *b)
{
    node *n = pool_alloc(b, sizeof *n);
    if (n) memset(n, 0, sizeof *n);
    return n;
}

/* Adds the polygons of l to the tree at n, depth levels down (l is
 * consumed).  A tree deeper than MAX_DEPTH (polygons that each fall to one
 * side of every plane before them: a chain) fails as too much work: every
 * walk of the tree recurses that deep, and the stack has its limits. */
static void build(bsp *b, node *n, plist *l, int depth)
{
    if (depth > MAX_DEPTH && l->n && !b->failed) b->failed = GEOM_BSP_TOO_MUCH;
    if (!l->n || b->failed) {
        free(l->v);
        return;
    }
    if (!n->has_plane) {
        memcpy(n->plane, l->v[0]->plane, sizeof n->plane);
        n->has_plane = 1;
    }
    plist f = {0}, bk = {0};
    for (int i = 0; i < l->n; i++)
        split(b, n->plane, l->v[i], &n->polys, &n->polys, &f, &bk);
    free(l->v);
    if (f.n && !n->front) n->front = node_new(b);
    if (bk.n && !n->back) n->back = node_new(b);
    if (f.n && n->front)
        build(b, n->front, &f, depth + 1);
    else
        free(f.v);
    if (bk.n && n->back)
        build(b, n->back, &bk, depth + 1);
    else
        free(bk.v);
}

static void invert(node *n)
{
    if (!n) return;
    for (int i = 0; i < n->polys.n; i++)
        poly_flip(n->polys.v[i]);
    for (int k = 0; k < 4; k++)
        n->plane[k] = -n->plane[k];
    invert(n->front);
    invert(n->back);
    node *t = n->front;
    n->front = n->back;
    n->back = t;
}

/* The parts of the polygons of l outside the solid of the tree at n (l is
 * consumed, the result returned). */
static plist clip_polys(bsp *b, const node *n, plist l)
{
    if (!n->has_plane || b->failed) return l;
    plist f = {0}, bk = {0};
    for (int i = 0; i < l.n; i++)
        split(b, n->plane, l.v[i], &f, &bk, &f, &bk);
    free(l.v);
    if (n->front) f = clip_polys(b, n->front, f);
    if (n->back) {
        bk = clip_polys(b, n->back, bk);
    } else {
        bk.n = 0;
    }
    for (int i = 0; i < bk.n; i++)
        plist_push(b, &f, bk.v[i]);
    free(bk.v);
    return f;
}

/* Removes the parts of the tree a's polygons inside the solid of tree t. */
static void clip_to(bsp *b, node *a, const node *t)
{
    if (!a || b->failed) return;
    a->polys = clip_polys(b, t, a->polys);
    clip_to(b, a->front, t);
    clip_to(b, a->back, t);
}

static void all_polys(bsp *b, const node *n, plist *out)
{
    if (!n) return;
    for (int i = 0; i < n->polys.n; i++)
        plist_push(b, out, n->polys.v[i]);
    all_polys(b, n->front, out);
    all_polys(b, n->back, out);
}

static void free_lists(node *n)
{
    if (!n) return;
    free(n->polys.v);
    n->polys.v = NULL;
    free_lists(n->front);
    free_lists(n->back);
}

/* The polygons of l in an order fixed by their number alone: a tree built
 * from a mesh's polygons in their own order takes each splitting plane from
 * a neighbour of the last, and a curved shape's then cut one another into
 * many pieces (two tori differenced, 1,800 and 1,560 polygons: 2.9 million
 * tests and 27,717 pieces in order; shuffled, 1.1 million and 11,116). */
static void shuffle(plist *l)
{
    uint32_t x = 2463534242u;
    for (int i = l->n - 1; i > 0; i--) {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        int j = (int)(x % (uint32_t)(i + 1));
        poly *t = l->v[i];
        l->v[i] = l->v[j];
        l->v[j] = t;
    }
}

static node *tree_of(bsp *b, const geom_polys *s)
{
    node *n = node_new(b);
    plist l = {0};
    for (int i = 0; n && i < s->n && !b->failed; i++) {
        poly *p = poly_new(b, (const double(*)[3])s->v + s->start[i], s->start[i + 1] - s->start[i],
                           s->tag[i]);
        if (p) plist_push(b, &l, p);
    }
    shuffle(&l);
    if (n)
        build(b, n, &l, 0);
    else
        free(l.v);
    return n;
}

static double extent(const geom_polys *s, double m)
{
    for (int i = 0; i < s->nv; i++)
        for (int k = 0; k < 3; k++)
            if (fabs(s->v[i][k]) > m) m = fabs(s->v[i][k]);
    return m;
}

int geom_bsp_boolean(geom_bsp_op op, const geom_polys *a, const geom_polys *b, long *work,
                     geom_polys *out)
{
    geom_polys_free(out);
    bsp B = {0};
    B.work = work;
    B.eps = 1e-9 * extent(b, extent(a, 1.0));
    node *A = tree_of(&B, a), *N = tree_of(&B, b);
    if (A && N && !B.failed) {
        /* csg.js: union, subtract and intersect */
        if (op == GEOM_BSP_DIFFERENCE || op == GEOM_BSP_INTERSECTION) invert(A);
        if (op == GEOM_BSP_INTERSECTION) {
            clip_to(&B, N, A);
            invert(N);
            clip_to(&B, A, N);
            clip_to(&B, N, A);
        } else {
            clip_to(&B, A, N);
            clip_to(&B, N, A);
            invert(N);
            clip_to(&B, N, A);
            invert(N);
        }
        plist rest = {0};
        all_polys(&B, N, &rest);
        build(&B, A, &rest, 0);
        if (op != GEOM_BSP_UNION) invert(A);
        plist res = {0};
        all_polys(&B, A, &res);
        for (int i = 0; i < res.n && !B.failed; i++)
            if (geom_polys_add_tagged(out, (const double(*)[3])res.v[i]->v, res.v[i]->n,
                                      res.v[i]->tag) != 0)
                B.failed = GEOM_BSP_NO_MEMORY;
        free(res.v);
    } else if (!B.failed) {
        B.failed = GEOM_BSP_NO_MEMORY;
    }
    free_lists(A);
    free_lists(N);
    pool_free(&B);
    if (B.failed) geom_polys_free(out);
    return B.failed;
}

static void polys_box(const geom_polys *p, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (int i = 0; i < p->nv; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], p->v[i][k]);
            hi[k] = fmax(hi[k], p->v[i][k]);
        }
}

int geom_polys_meet(const geom_polys *a, const geom_polys *b)
{
    double alo[3], ahi[3], blo[3], bhi[3];
    polys_box(a, alo, ahi);
    polys_box(b, blo, bhi);
    for (int k = 0; k < 3; k++)
        if (ahi[k] < blo[k] || bhi[k] < alo[k]) return 0;
    return 1;
}
