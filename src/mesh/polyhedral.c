/*
 * polyhedral.c — a part of a model whose every primitive is plane-faced
 * (boxes, hulls and faceted primitives, polyhedra, imported meshes, prisms
 * of polygons) meshed as the exact boundary of its booleans
 * (mesh_polyhedral) rather than contoured from its samples.
 *
 * Each primitive's own faces (exact_faces.c), in world space, go through
 * the part's unions, intersections and differences by BSP (geom/bsp.h),
 * whose result covers the boundary with convex polygons, exact up to its
 * plane tolerance (1e-9 of the size), but split along every plane that cut
 * it, with vertices where one polygon's corner lies on another's edge (a
 * T-junction).  Corners within WELD of one another become one vertex; each
 * polygon's corners along a straight edge are dropped and the rest fanned;
 * a triangle with a vertex on its edge is split there (both found through
 * a grid of points); where solids touch along an edge or at a corner, the
 * faces are paired solid wedge by solid wedge and each solid's corners
 * moved a hair into it (geom/pinch.h); then the triangles of each flat
 * face are cut again from the face's outline (flat_faces.h): the BSP's
 * cuts leave no trace.  The result stands only
 * where it is a closed mesh that bounds its solid (geom_mesh_is_boundary:
 * every edge once each way, no two triangles crossing) with its corners
 * apart as floats; otherwise, or where a primitive is curved, the part is
 * contoured as before.  Each polygon carries its primitive's colour through
 * the booleans (a difference's cut faces take the colour of what cut them,
 * as the rays see it), and faces of two colours are not merged.  A
 * primitive alone in its part needs no booleans and no limit on its size;
 * where primitives are joined, MAX_TRIANGLES and WORK bound the BSP.
 */
#include "../geom/bsp.h"
#include "../geom/flat_faces.h"
#include "../geom/mesh_boundary.h"
#include "../geom/pinch.h"
#include "../geom/point_grid.h"
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define WORK 6000000L /* BSP plane tests a part may take (about 0.6 s) */
#define WELD 1e-8     /* of the part's size: corners this close are one */
#define MAX_CORNERS 4000000
#define MAX_TRIANGLES 20000 /* of the primitives' faces, where booleans join them */

typedef struct ctx {
    const csg_scene *s;
    mesh_palette const *pal;
    const double *lo, *hi;
    const int32_t *only; /* the top-level operands to take (nonly nodes); NULL: all */
    int nonly;
    long work;
    int leaves;     /* the part's primitives, counted to 2 */
    long triangles; /* the primitives' so far */
    int no;         /* 1: not plane-faced, too much work */
} ctx;

static int mend(const geom_polys *p, double size, mesh_polyhedron *out);

/* Whether f's triangles (a mesh's or a prism's, which need not bound their
 * solid as given) do once mended as a part's boundary is (mend: corners
 * welded, T-junctions split, solids that touch kept apart): an extrusion
 * scaled to nothing has walls that end on one line from both sides, with
 * corners of one wall along the other's edge.  The booleans take the
 * triangles as they are; the part's own mend checks the result (and alone
 * in its part, with no booleans, a primitive is checked by that alone). */
static int mends(const mesh_faces *f)
{
    geom_polys p = {0};
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY},
           size = 0;
    int rc = 0;
    for (int i = 0; i < f->nv; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], f->v[i][k]);
            hi[k] = fmax(hi[k], f->v[i][k]);
            size = fmax(size, hi[k] - lo[k]);
        }
    for (int i = 0; rc == 0 && i < f->nt; i++) {
        double q[3][3];
        for (int k = 0; k < 3; k++)
            memcpy(q[k], f->v[f->t[i][f->cw ? 2 - k : k]], sizeof q[k]);
        rc = geom_polys_add(&p, (const double(*)[3])q, 3);
    }
    mesh_polyhedron m = {0};
    if (rc == 0) rc = mend(&p, size, &m);
    mesh_polyhedron_free(&m);
    geom_polys_free(&p);
    return rc == 1;
}

/* Primitive prim's faces in world space, outward, into out: 0, or -1 when
 * out of memory (c->no where it has no such faces). */
static int leaf(ctx *c, int32_t prim, geom_polys *out)
{
    const iv_shape *sh = csg_scene_prim_shape(c->s, prim);
    int color = mesh_palette_of(c->pal, prim);
    mesh_faces f = {0};
    int ok = !c->no && mesh_faces_of(sh, &f);
    c->triangles += ok ? f.nt : 0;
    if (ok && (sh->kind == IV_SHAPE_MESH || sh->kind == IV_SHAPE_PRISM))
        ok = c->leaves < 2 || mesh_faces_bound(&f) || mends(&f);
    csg_affine w;
    csg_scene_prim_transform(c->s, prim, w);
    double d = csg_affine_det(w);
    ok = ok && isfinite(d) && d != 0;
    int turn = (d < 0) != f.cw, rc = 0;
    for (int i = 0; ok && rc == 0 && i < f.nt; i++) {
        double q[3][3];
        for (int k = 0; k < 3; k++)
            csg_affine_point(w, f.v[f.t[i][turn ? 2 - k : k]], q[k]);
        rc = geom_polys_add_tagged(out, (const double(*)[3])q, 3, color);
    }
    if (!ok) c->no = 1;
    mesh_faces_free(&f);
    return rc;
}

static int box_meets(const csg_scene_node_info *f, const double *lo, const double *hi)
{
    for (int k = 0; k < 3; k++)
        if (f->lo[k] > hi[k] || f->hi[k] < lo[k]) return 0;
    return 1;
}

/* Whether top-level operand j (node k) is this part's: its box meets the
 * part's, and it is one of c->only (a union among them is looked into). */
static int wanted(const ctx *c, int32_t j, const csg_scene_node_info *k)
{
    if (!box_meets(k, c->lo, c->hi)) return 0;
    if (!c->only || (!k->is_leaf && k->op == CSG_OP_UNION)) return 1;
    for (int i = 0; i < c->nonly; i++)
        if (c->only[i] == j) return 1;
    return 0;
}

/* The primitives of node i's subtree that boundary takes, up to 2. */
static int count_leaves(const ctx *c, int32_t i, int top)
{
    csg_scene_node_info f, k;
    csg_scene_node_get(c->s, i, &f);
    if (f.is_leaf) return 1;
    int n = 0;
    for (int32_t j = i + 1; j < f.end && n < 2; j = k.end) {
        csg_scene_node_get(c->s, j, &k);
        if (top && f.op == CSG_OP_UNION && !wanted(c, j, &k)) continue;
        n += count_leaves(c, j, top && f.op == CSG_OP_UNION);
    }
    return n;
}

/* The boundary of node i's subtree into out (empty): 0, or -1 when out of
 * memory (c->no where it cannot be had). */
static int boundary(ctx *c, int32_t i, int top, geom_polys *out)
{
    csg_scene_node_info f;
    csg_scene_node_get(c->s, i, &f);
    if (f.is_leaf) return leaf(c, f.prim, out);
    csg_scene_node_info k;
    int first = 1, rc = 0;
    for (int32_t j = i + 1; j < f.end && rc == 0 && !c->no; j = k.end) {
        csg_scene_node_get(c->s, j, &k);
        /* the top-level unions' operands of other parts are not this one's */
        if (top && f.op == CSG_OP_UNION && !wanted(c, j, &k)) continue;
        geom_polys g = {0}, r = {0};
        rc = boundary(c, j, top && f.op == CSG_OP_UNION, first ? out : &g);
        if (first || rc != 0 || c->no) {
            first = 0;
            geom_polys_free(&g);
            continue;
        }
        if (out->n == 0 && f.op != CSG_OP_UNION) { /* nothing left to cut */
            geom_polys_free(&g);
            continue;
        }
        if (!geom_polys_meet(out, &g)) { /* apart: a union keeps both, a difference the first */
            if (f.op == CSG_OP_UNION) rc = geom_polys_append(out, &g);
            if (f.op == CSG_OP_INTERSECTION) geom_polys_free(out);
            geom_polys_free(&g);
            continue;
        }
        if (c->triangles > MAX_TRIANGLES) { /* a boolean of so many takes seconds */
            c->no = 1;
            geom_polys_free(&g);
            continue;
        }
        geom_bsp_op op = f.op == CSG_OP_UNION          ? GEOM_BSP_UNION
                         : f.op == CSG_OP_INTERSECTION ? GEOM_BSP_INTERSECTION
                                                       : GEOM_BSP_DIFFERENCE;
        int b = geom_bsp_boolean(op, out, &g, &c->work, &r);
        geom_polys_free(&g);
        if (b == GEOM_BSP_TOO_MUCH) c->no = 1;
        if (b == GEOM_BSP_NO_MEMORY) rc = -1;
        if (b == 0) {
            geom_polys_free(out);
            *out = r;
        } else {
            geom_polys_free(&r);
        }
    }
    return rc;
}

/* The polygons' welded vertices and the triangles being made of them. */
typedef struct welded {
    double (*V)[3];
    int nv;
    geom_point_grid grid; /* of V, for on_edge */
    double tol;
    int (*T)[3];
    int *tag; /* each triangle's colour */
    int nt, cap;
    int failed;
} welded;

typedef struct near_query {
    const double (*p)[3];
    const double *at;
    double tol;
    int *map, v;
} near_query;

static int claim(void *ud, int j)
{
    near_query *q = ud;
    if (q->map[j] < 0 && fabs(q->p[j][0] - q->at[0]) <= q->tol &&
        fabs(q->p[j][1] - q->at[1]) <= q->tol && fabs(q->p[j][2] - q->at[2]) <= q->tol)
        q->map[j] = q->v;
    return 0;
}

/* The corners of p welded within w->tol into w->V, map[corner] -> vertex
 * (each corner not yet taken takes those within tol of it); then w->grid.
 * 0 or -1. */
static int weld(const geom_polys *p, welded *w, int *map, double size)
{
    int n = p->nv;
    geom_point_grid g;
    w->V = malloc((size_t)n * sizeof *w->V);
    if (!w->V || geom_point_grid_build(&g, (const double(*)[3])p->v, n, fmax(4 * w->tol, 1e-300)))
        return -1;
    for (int i = 0; i < n; i++)
        map[i] = -1;
    for (int i = 0; i < n; i++) {
        if (map[i] >= 0) continue;
        near_query q = {(const double(*)[3])p->v, p->v[i], w->tol, map, w->nv};
        memcpy(w->V[w->nv++], p->v[i], sizeof *w->V);
        double lo[3], hi[3];
        for (int k = 0; k < 3; k++) {
            lo[k] = p->v[i][k] - w->tol;
            hi[k] = p->v[i][k] + w->tol;
        }
        geom_point_grid_each(&g, lo, hi, 64, claim, &q);
    }
    geom_point_grid_free(&g);
    /* cells about as far apart as the vertices are across the surface */
    double cell = fmax(size / sqrt((double)w->nv + 1), 4 * w->tol);
    return geom_point_grid_build(&w->grid, (const double(*)[3])w->V, w->nv, fmax(cell, 1e-300));
}

/* Distance of V[v] from the line through V[a] and V[b], squared, and
 * where along a b it lies (0 at a, 1 at b). */
static double off_line(const welded *w, int a, int b, int v, double *s)
{
    double ab[3], av[3], cr[3];
    sub3(w->V[b], w->V[a], ab);
    sub3(w->V[v], w->V[a], av);
    double l2 = dot3(ab, ab);
    *s = dot3(av, ab) / l2;
    cross3(av, ab, cr);
    return dot3(cr, cr) / l2;
}

typedef struct edge_query {
    const welded *w;
    int a, b, v;
    double best, inner;
} edge_query;

static int nearer_on_edge(void *ud, int u)
{
    edge_query *q = ud;
    double s;
    if (u != q->a && u != q->b && u != q->v &&
        off_line(q->w, q->a, q->b, u, &s) <= q->w->tol * q->w->tol && s > q->inner &&
        s < 1 - q->inner && s < q->best) {
        q->best = s;
        q->v = u;
    }
    return 0;
}

/* The first vertex (along a b) inside edge a b, more than tol from either
 * end, or -1: a corner of another polygon on this one's edge (a
 * T-junction). */
static int on_edge(const welded *w, int a, int b)
{
    const double *A = w->V[a], *B = w->V[b];
    double ab[3], lo[3], hi[3];
    sub3(B, A, ab);
    for (int k = 0; k < 3; k++) {
        lo[k] = fmin(A[k], B[k]) - w->tol;
        hi[k] = fmax(A[k], B[k]) + w->tol;
    }
    edge_query q = {w, a, b, -1, 2, w->tol / sqrt(dot3(ab, ab))}; /* inner: tol, along a b */
    geom_point_grid_each(&w->grid, lo, hi, 64 + w->nv / 16, nearer_on_edge, &q);
    return q.v;
}

/* Triangle a b c of colour tag, split from the opposite corner at every
 * vertex that lies on one of its edges, into w->T. */
static void split_tri(welded *w, int a, int b, int c, int tag, int depth)
{
    if (w->failed) return;
    const int t[3] = {a, b, c};
    for (int e = 0; e < 3; e++) {
        int v = on_edge(w, t[e], t[(e + 1) % 3]);
        if (v < 0) continue;
        if (depth > 10000) {
            w->failed = 1;
            return;
        }
        split_tri(w, t[e], v, t[(e + 2) % 3], tag, depth + 1);
        split_tri(w, v, t[(e + 1) % 3], t[(e + 2) % 3], tag, depth + 1);
        return;
    }
    if (w->nt == w->cap) {
        int c2 = w->cap ? 2 * w->cap : 256;
        int(*g)[3] = realloc(w->T, (size_t)c2 * sizeof *g);
        if (g) w->T = g;
        int *gt = g ? realloc(w->tag, (size_t)c2 * sizeof *gt) : NULL;
        if (!gt) {
            w->failed = -1;
            return;
        }
        w->tag = gt;
        w->cap = c2;
    }
    w->tag[w->nt] = tag;
    w->T[w->nt][0] = a;
    w->T[w->nt][1] = b;
    w->T[w->nt][2] = c;
    w->nt++;
}

/* Drop the vertices no triangle uses, renumbering the rest. */
static void compact(welded *w)
{
    int *to = malloc((size_t)(w->nv ? w->nv : 1) * sizeof *to), k = 0;
    if (!to) {
        w->failed = -1;
        return;
    }
    for (int v = 0; v < w->nv; v++)
        to[v] = -1;
    for (int t = 0; t < w->nt; t++)
        for (int e = 0; e < 3; e++)
            to[w->T[t][e]] = 0;
    for (int v = 0; v < w->nv; v++)
        if (to[v] == 0) {
            memmove(w->V[k], w->V[v], sizeof w->V[k]);
            to[v] = k++;
        }
    for (int t = 0; t < w->nt; t++)
        for (int e = 0; e < 3; e++)
            w->T[t][e] = to[w->T[t][e]];
    w->nv = k;
    free(to);
}

/* The polygons of p as a mesh: corners welded, each polygon's corners
 * along a straight edge dropped, the rest fanned, and every triangle split
 * where a vertex lies on its edge (the mesh's T-junctions mended), each
 * triangle of its polygon's colour.  1 with *out; 0 when it does not come
 * out closed and bounding; -1 out of memory. */
static int mend(const geom_polys *p, double size, mesh_polyhedron *out)
{
    if (p->nv > MAX_CORNERS || p->n == 0) return 0;
    welded w = {.tol = WELD * size};
    int *map = malloc((size_t)p->nv * sizeof *map), *ring = NULL, rc = -1;
    if (!map || weld(p, &w, map, size) != 0) goto done;
    ring = malloc((size_t)p->nv * sizeof *ring);
    if (!ring) goto done;
    for (int f = 0; f < p->n && !w.failed; f++) {
        int k = 0;
        for (int j = p->start[f]; j < p->start[f + 1]; j++)
            if (k == 0 || map[j] != ring[k - 1]) ring[k++] = map[j];
        while (k > 1 && ring[k - 1] == ring[0])
            k--;
        /* drop corners on a straight line between their neighbours */
        for (int i = 0; k >= 3 && i < k;) {
            double s;
            int a = ring[(i + k - 1) % k], b = ring[(i + 1) % k];
            if (off_line(&w, a, b, ring[i], &s) <= w.tol * w.tol) {
                memmove(ring + i, ring + i + 1, (size_t)(k - i - 1) * sizeof *ring);
                k--;
                i = 0;
            } else {
                i++;
            }
        }
        for (int i = 1; k >= 3 && i + 1 < k; i++)
            split_tri(&w, ring[0], ring[i], ring[i + 1], p->tag[f], 0);
    }
    /* solids that touch along an edge or at a corner: kept apart */
    int pinched = 0;
    if (!w.failed) {
        pinched = geom_unpinch(&w.V, &w.nv, w.T, w.nt);
        if (pinched == GEOM_PINCH_NO_MEMORY) goto done;
        if (pinched < 0) w.failed = 1;
    }
    if (w.failed < 0) goto done;
    if (!w.failed &&
        geom_merge_flat_faces((const double(*)[3])w.V, w.nv, &w.T, &w.tag, &w.nt, w.tol) != 0)
        goto done;
    if (!w.failed) compact(&w);
    if (w.failed < 0) goto done;
    if (!w.failed && pinched > 0) {
        double far = 0;
        for (int v = 0; v < w.nv; v++)
            for (int k = 0; k < 3; k++)
                far = fmax(far, fabs(w.V[v][k]));
        /* MESH_PINCH_GAP, and at least 128 steps of a float there */
        int m = geom_move_apart(w.V, w.nv, (const int(*)[3])w.T, w.nt,
                                fmax(MESH_PINCH_GAP * size, ldexp(far, -16)));
        if (m == GEOM_PINCH_NO_MEMORY) goto done;
        if (m < 0) w.failed = 1;
    }
    rc = w.failed
             ? 0
             : geom_mesh_is_boundary((const double(*)[3])w.V, w.nv, (const int(*)[3])w.T, w.nt);
done:
    free(map);
    free(ring);
    geom_point_grid_free(&w.grid);
    if (rc == 1) {
        *out = (mesh_polyhedron){.v = w.V, .t = w.T, .nv = w.nv, .nt = w.nt};
        out->color = malloc((size_t)(w.nt ? w.nt : 1) * sizeof *out->color);
        for (int i = 0; out->color && i < w.nt; i++)
            out->color[i] = (uint16_t)w.tag[i];
        if (!out->color) {
            mesh_polyhedron_free(out);
            rc = -1;
        }
    } else {
        free(w.V);
        free(w.T);
    }
    free(w.tag);
    return rc;
}

int mesh_polyhedral_of(const mesh_dexels *d, const double lo[3], const double hi[3],
                       const int32_t *only, int nonly, mesh_polyhedron *out)
{
    memset(out, 0, sizeof *out);
    int32_t r = csg_scene_root_node(d->scene, d->root);
    if (r < 0) return 0;
    ctx c = {.s = d->scene,
             .pal = &d->pal,
             .lo = lo,
             .hi = hi,
             .only = only,
             .nonly = nonly,
             .work = WORK};
    geom_polys p = {0};
    c.leaves = count_leaves(&c, r, 1);
    int rc = boundary(&c, r, 1, &p);
    double size = 0;
    for (int k = 0; k < 3; k++)
        size = fmax(size, hi[k] - lo[k]);
    if (rc == 0 && !c.no) rc = mend(&p, size, out);
    geom_polys_free(&p);
    if (rc != 1) mesh_polyhedron_free(out);
    return rc;
}

int mesh_polyhedral_agrees(mesh_polyhedron *p, double volume, double h)
{
    double vol = 0, area = 0;
    for (int i = 0; i < p->nt; i++) {
        const double *a = p->v[p->t[i][0]], *b = p->v[p->t[i][1]], *c = p->v[p->t[i][2]];
        double n[3];
        tri_normal3(a, b, c, n);
        vol += triple3(a, b, c) / 6;
        area += sqrt(dot3(n, n)) / 2;
    }
    int ok = fabs(vol - volume) <= 0.02 * fabs(volume) + area * h &&
             mesh_floats_apart((const double(*)[3])p->v, p->nv, (const int32_t(*)[3])p->t, p->nt);
    if (!ok) mesh_polyhedron_free(p);
    return ok;
}

int mesh_polyhedral(const mesh_dexels *d, const double lo[3], const double hi[3],
                    mesh_polyhedron *out)
{
    int rc = mesh_polyhedral_of(d, lo, hi, NULL, 0, out);
    if (rc != 1) return rc;
    mesh_measure g;
    mesh_dexels_measure(d, &g);
    return mesh_polyhedral_agrees(out, g.volume, d->h);
}

void mesh_polyhedron_free(mesh_polyhedron *p)
{
    free(p->v);
    free(p->t);
    free(p->color);
    memset(p, 0, sizeof *p);
}
