/*
 * unfold.c — the contour's folds (two triangles back to back across an
 * edge) taken away by flipping that edge (see dexels.h, mesh_unfold),
 * edges cut across sharp edges (mesh_unbend) and a simplified mesh's
 * slivers likewise (mesh_unsliver).
 *
 * Every vertex of the contour lies on the surface, but where a crease or a
 * surface passes close to a grid node, the loops of neighbouring cells can
 * join them the wrong way round: two triangles (a, b, c) and (b, a, d) with
 * d on c's side of their edge, whose normals point 150° or more apart — a
 * fin standing off the surface, or a groove bridged by a tent.  The quad
 * they make is triangulated the other way, (c, a, d) and (d, b, c), when
 * that leaves fewer folded edges among the five it touches (its diagonal
 * and its four sides, against the triangles beyond them), neither new
 * triangle without area and the edge (c, d) not already there (it would be
 * an edge of four triangles).  Since every flip lowers the count of folded
 * edges, passes end; they stop when one flips nothing, or after PASSES.
 * The mesh's boundary, its vertices and their places do not change.
 *
 * Before refine.c splits the contour's edges, an edge cut across a sharp
 * edge the wrong way is flipped (mesh_unbend): where a rim passes close to
 * a grid edge, a cell's loop can join a vertex on one surface to one on the
 * other past two vertices on the rim itself, and the two triangles bend by
 * 130° to 150° — less than a fold, more than the rim's surfaces part.  An
 * edge whose two triangles bend by 30° more than the exact normals of the
 * quad's corners part (those that have one: ray crossings, not points on
 * the sharp edge) is flipped where the new pair bends by 30° less and
 * neither new triangle turns 90° or more from a normal of its corners
 * (refine's splits of such an edge had knotted the rim beyond repair:
 * bored_cone.scad's mesh 249 samples 4 tolerances or more off the surface
 * -> 145, its cross hole's side on the cone no longer among them).  Only
 * triangles with a corner on a sharp edge start it.
 *
 * A sliver the simplifier left on a smooth part (a corner c within a tenth
 * of its longest side ab, above the side's middle) joins c to a vertex that
 * mesh_balance then moves out by half its triangles' sag, while ab, which
 * spans the sag's whole width, stays under the surface: the sliver stands
 * 30° off the surface, and mesh_tighten, which measures only triangles
 * that bend less than 20° against their neighbours, passes it and the
 * triangle across ab by (a torus's inner side, 1.8 tolerances).  Flipped
 * to cd where the triangles about it turn less than 20° against each
 * other, the flip leaves two that do likewise and are no slivers, and cd's
 * middle lies nearer the surface than ab's (on a surface bent one way
 * only, a sliver along the straight way is the best shape: a torus's top).
 */
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define COS_FOLD (-0.866) /* normals more than 150° apart: folded */
#define COS_SMOOTH 0.94   /* cos 20° */
#define SLIVER 0.1        /* a corner this near its opposite side, of its length */
#define COS_FACING 0.5    /* the surface under a side turned no more than 60° from it */
#define BENT 0.5236       /* 30°, in radians */
#define COS_BENT 0.866    /* its cosine */
#define PASSES 8
#define AROUND 1024 /* the most edges looked at around a vertex */

typedef struct quad quad;
typedef struct fold_mesh fold_mesh;
/* Whether the edge of quad q should be flipped; the flipped triangles'
 * unit normals into n3 and n4 (flip_normals) where it should. */
typedef int (*flip_rule)(const fold_mesh *f, const quad *q, double n3[3], double n4[3]);

struct fold_mesh {
    mesh *m;
    int t0;
    int32_t *opp;   /* half-edge 3·t + k (tv[k] → tv[k + 1], t from t0) → its twin; -1 */
    double min2;    /* |cross|² below which a triangle has no area */
    double (*n)[3]; /* each triangle's unit normal, when has */
    uint8_t *has;
    flip_rule wanted;
    mesh_snapper *sn;        /* the surface (sliver_wanted) */
    const mesh_vnormals *vn; /* the contour's vertices (bent_wanted) */
    uint8_t *again;          /* triangles a flip changed or bordered: the next pass's */
};

static int32_t *corners(const fold_mesh *f, int32_t t)
{
    return &f->m->t[3 * ((size_t)t + (size_t)f->t0)];
}

/* The unit normal of the triangle a, b, c into n; 0 when it has no area. */
static int unit_normal(const mesh *m, int32_t a, int32_t b, int32_t c, double min2, double n[3])
{
    double p[3], q[3], r[3];
    mesh_vertex_at(m, a, p);
    mesh_vertex_at(m, b, q);
    mesh_vertex_at(m, c, r);
    tri_normal3(p, q, r, n);
    double l2 = dot3(n, n);
    if (!(l2 > min2)) return 0;
    double l = sqrt(l2);
    for (int k = 0; k < 3; k++)
        n[k] /= l;
    return 1;
}

/* Cache triangle t's unit normal. */
static void note_normal(fold_mesh *f, int32_t t)
{
    const int32_t *tv = corners(f, t);
    f->has[t] = (uint8_t)unit_normal(f->m, tv[0], tv[1], tv[2], f->min2, f->n[t]);
}

/* Whether the triangle of half-edge x (its unit normal nx) is folded
 * against the triangle across x. */
static int folded_across(const fold_mesh *f, int32_t x, const double nx[3])
{
    int32_t y = f->opp[x];
    if (y < 0 || !f->has[y / 3]) return 0;
    return dot3(nx, f->n[y / 3]) < COS_FOLD;
}

/* Whether an edge joins the start of half-edge x to d: the half-edges out
 * of that vertex, turning about it from x. */
static int has_edge(const fold_mesh *f, int32_t x, int32_t d)
{
    for (int i = 0, y = x; i < AROUND; i++) {
        const int32_t *tv = corners(f, y / 3);
        if (tv[(y % 3 + 1) % 3] == d) return 1;
        /* the half-edge into c in this triangle, then its twin, out of c */
        int32_t in = y / 3 * 3 + (y % 3 + 2) % 3;
        y = f->opp[in];
        if (y < 0) return 1; /* open: take no risk */
        if (y == x) return 0;
    }
    return 1;
}

/* Link half-edges x and y as twins (either may be -1). */
static void link(fold_mesh *f, int32_t x, int32_t y)
{
    if (x >= 0) f->opp[x] = y;
    if (y >= 0) f->opp[y] = x;
}

/* The quad of half-edge x: triangle t = (a, b, c) holds x (a → b), u =
 * (b, a, d) its twin y; its sides b → c, c → a (in t), a → d, d → b (in
 * u). */
struct quad {
    int32_t t, u, a, b, c, d, bc, ca, ad, db;
};

static int quad_of(const fold_mesh *f, int32_t x, quad *q)
{
    int32_t y = f->opp[x];
    if (y < 0 || x / 3 == y / 3) return 0;
    int32_t t = x / 3, u = y / 3;
    int k = x % 3, j = y % 3;
    const int32_t *tv = corners(f, t), *uv = corners(f, u);
    *q = (quad){t,
                u,
                tv[k],
                tv[(k + 1) % 3],
                tv[(k + 2) % 3],
                uv[(j + 2) % 3],
                3 * t + (k + 1) % 3,
                3 * t + (k + 2) % 3,
                3 * u + (j + 1) % 3,
                3 * u + (j + 2) % 3};
    return q->c != q->d;
}

/* The unit normals of the quad's triangles after a flip, (c, a, d) and
 * (d, b, c), into n3 and n4; 0 when one has no area. */
static int flip_normals(const fold_mesh *f, const quad *q, double n3[3], double n4[3])
{
    return unit_normal(f->m, q->c, q->a, q->d, f->min2, n3) &&
           unit_normal(f->m, q->d, q->b, q->c, f->min2, n4);
}

/* Whether the quad's triangles are folded and a flip, to normals n3 and
 * n4, leaves fewer folded edges among the five it touches. */
static int fold_wanted(const fold_mesh *f, const quad *q, double n3[3], double n4[3])
{
    const double *n1 = f->n[q->t], *n2 = f->n[q->u];
    if (!f->has[q->t] || !f->has[q->u] || !(dot3(n1, n2) < COS_FOLD) || !flip_normals(f, q, n3, n4))
        return 0;
    int before = 1 + folded_across(f, q->bc, n1) + folded_across(f, q->ca, n1) +
                 folded_across(f, q->ad, n2) + folded_across(f, q->db, n2);
    /* after: (c, a, d) holds c → a and a → d, (d, b, c) holds d → b and b → c */
    int after = (dot3(n3, n4) < COS_FOLD) + folded_across(f, q->ca, n3) +
                folded_across(f, q->ad, n3) + folded_across(f, q->db, n4) +
                folded_across(f, q->bc, n4);
    return after < before;
}

/* The triangle a, b, c's height over its longest side, over that side's
 * length, into *shape; 1 when ab is that side. */
static int shape_of(const mesh *m, int32_t a, int32_t b, int32_t c, double *shape)
{
    double p[3][3], n[3], l2[3];
    mesh_vertex_at(m, a, p[0]);
    mesh_vertex_at(m, b, p[1]);
    mesh_vertex_at(m, c, p[2]);
    for (int k = 0; k < 3; k++) {
        double e[3];
        sub3(p[(k + 1) % 3], p[k], e);
        l2[k] = dot3(e, e);
    }
    tri_normal3(p[0], p[1], p[2], n);
    double top = fmax(l2[0], fmax(l2[1], l2[2]));
    *shape = top > 0 ? sqrt(dot3(n, n)) / top : 0;
    return l2[0] >= top;
}

/* How far the middle of side ab lies from the surface along n (not unit),
 * looked for within the side's length; INFINITY when it is not found. */
static double sag(const fold_mesh *f, int32_t a, int32_t b, const double n[3])
{
    double p[3], r[3], x[3], e[3], u[3], hit[3], hn[3];
    mesh_vertex_at(f->m, a, p);
    mesh_vertex_at(f->m, b, r);
    sub3(r, p, e);
    double l = sqrt(dot3(n, n));
    if (!(l > 0)) return INFINITY;
    for (int k = 0; k < 3; k++) {
        x[k] = 0.5 * (p[k] + r[k]);
        u[k] = n[k] / l;
    }
    if (!mesh_snap_probe(f->sn, x, u, sqrt(dot3(e, e)), COS_FACING, hit, hn)) return INFINITY;
    sub3(hit, x, e);
    return sqrt(dot3(e, e));
}

/* Whether the triangle across half-edge x has a normal within COS_SMOOTH
 * of n (an open edge or a triangle without area: no). */
static int smooth_across(const fold_mesh *f, int32_t x, const double n[3])
{
    int32_t y = f->opp[x];
    return y >= 0 && f->has[y / 3] && dot3(n, f->n[y / 3]) >= COS_SMOOTH;
}

/* Whether t is a sliver on ab (its longest side, c within SLIVER of it)
 * in a smooth part — u and the triangles across t's other sides turn less
 * than 20° against each other, so ab is no sharp edge — and the flip, to
 * normals n3 and n4, leaves two triangles that turn less than that against
 * u and are no slivers themselves. */
static int sliver_wanted(const fold_mesh *f, const quad *q, double n3[3], double n4[3])
{
    const mesh *m = f->m;
    const double *n2 = f->n[q->u];
    double s1, s3, s4;
    if (!f->has[q->u] || !shape_of(m, q->a, q->b, q->c, &s1) || s1 >= SLIVER ||
        !flip_normals(f, q, n3, n4))
        return 0;
    if (f->has[q->t] && dot3(n3, n4) <= dot3(f->n[q->t], n2)) return 0;
    if (!smooth_across(f, q->bc, n2) || !smooth_across(f, q->ca, n2)) return 0;
    if (dot3(n3, n2) < COS_SMOOTH || dot3(n4, n2) < COS_SMOOTH) return 0;
    shape_of(m, q->c, q->a, q->d, &s3);
    shape_of(m, q->d, q->b, q->c, &s4);
    if (s3 < SLIVER || s4 < SLIVER) return 0;
    /* the new side nearer the surface than the old (along a surface bent
     * one way only, a sliver along the straight way is the best shape) */
    double n12[3], n34[3];
    for (int k = 0; k < 3; k++) {
        n12[k] = f->n[q->t][k] + n2[k];
        n34[k] = n3[k] + n4[k];
    }
    return sag(f, q->c, q->d, n34) < sag(f, q->a, q->b, n12);
}

/* Vertex v's exact normal into n (a ray crossing's); 0 when it has none
 * or lies on a sharp edge. */
static int crossing_normal(const fold_mesh *f, int32_t v, double n[3])
{
    const mesh_vnormals *vn = f->vn;
    if ((size_t)v >= vn->cap || vn->edge[v]) return 0;
    for (int k = 0; k < 3; k++)
        n[k] = vn->n[v][k];
    return dot3(n, n) > 0.25;
}

/* Whether vertex v lies on a sharp edge (mesh_snap put it there). */
static int edge_vertex(const fold_mesh *f, int32_t v)
{
    return (size_t)v < f->vn->cap && f->vn->edge[v];
}

/* The cosine of the widest angle between the exact normals of the quad's
 * corners that have one (1 when fewer than two have); 0 when a new
 * triangle, of normal n3 (c, a, d) or n4 (d, b, c), turns 90° or more from
 * a normal of its corners. */
static int corner_spread(const fold_mesh *f, const quad *q, const double n3[3], const double n4[3],
                         double *spread)
{
    const int32_t v[4] = {q->a, q->b, q->c, q->d};
    double n[4][3];
    int has[4];
    *spread = 1;
    for (int i = 0; i < 4; i++) {
        has[i] = crossing_normal(f, v[i], n[i]);
        if (!has[i]) continue;
        double l = sqrt(dot3(n[i], n[i]));
        for (int k = 0; k < 3; k++)
            n[i][k] /= l;
        if (i != 1 && dot3(n3, n[i]) <= 0) return 0; /* c, a, d */
        if (i != 0 && dot3(n4, n[i]) <= 0) return 0; /* d, b, c */
        for (int j = 0; j < i; j++)
            if (has[j]) *spread = fmin(*spread, dot3(n[i], n[j]));
    }
    return 1;
}

/* Whether the quad's triangles bend against each other by BENT more than
 * the exact normals of their corners part (an edge cut across a sharp
 * edge the wrong way: a groove or fin about it), and the flip, to normals
 * n3 and n4, bends by BENT less and turns neither new triangle away from
 * its corners' normals. */
static int bent_wanted(const fold_mesh *f, const quad *q, double n3[3], double n4[3])
{
    double spread;
    if (!f->has[q->t] || !f->has[q->u] || dot3(f->n[q->t], f->n[q->u]) > COS_BENT ||
        !flip_normals(f, q, n3, n4) || !corner_spread(f, q, n3, n4, &spread))
        return 0;
    double before = acos(fmax(-1, fmin(1, dot3(f->n[q->t], f->n[q->u]))));
    double after = acos(fmax(-1, fmin(1, dot3(n3, n4))));
    return before > acos(spread) + BENT && after < before - BENT;
}

/* Flip the edge of half-edge x when f->wanted says so and the new edge is
 * not there already; 1 when flipped. */
static int try_flip(fold_mesh *f, int32_t x)
{
    quad q;
    if (!quad_of(f, x, &q)) return 0;
    double n3[3], n4[3];
    if (!f->wanted(f, &q, n3, n4) || has_edge(f, q.ca, q.d)) return 0;
    int32_t oca = f->opp[q.ca], oad = f->opp[q.ad], odb = f->opp[q.db], obc = f->opp[q.bc];
    int32_t *tv = corners(f, q.t), *uv = corners(f, q.u);
    tv[0] = q.c, tv[1] = q.a, tv[2] = q.d; /* c → a, a → d, d → c */
    uv[0] = q.d, uv[1] = q.b, uv[2] = q.c; /* d → b, b → c, c → d */
    link(f, 3 * q.t, oca);
    link(f, 3 * q.t + 1, oad);
    link(f, 3 * q.u, odb);
    link(f, 3 * q.u + 1, obc);
    link(f, 3 * q.t + 2, 3 * q.u + 2);
    note_normal(f, q.t);
    note_normal(f, q.u);
    /* the next pass looks at the two and the triangles across them */
    const int32_t near[6] = {3 * q.t, 3 * q.u, oca, oad, odb, obc};
    for (int i = 0; i < 6; i++)
        if (near[i] >= 0) f->again[near[i] / 3] = 1;
    return 1;
}

/* Flip edges of triangles [t0, m->nt) of m while wanted says so, in up to
 * PASSES passes (the first over the triangles with a corner on a sharp
 * edge when vn is given, else all; each next one over those a flip
 * changed or bordered); 0 or -1 when out of memory. */
static int flip_all(mesh *m, int t0, double h, flip_rule wanted, mesh_snapper *sn,
                    const mesh_vnormals *vn)
{
    if (m->nt <= t0) return 0;
    size_t nt = (size_t)(m->nt - t0);
    if (3 * nt > INT32_MAX) return 0;
    fold_mesh f = {m,
                   t0,
                   malloc(3 * nt * sizeof *f.opp),
                   1e-12 * h * h * h * h,
                   malloc(nt * sizeof *f.n),
                   malloc(nt),
                   wanted,
                   sn,
                   vn,
                   calloc(nt, 1)};
    uint8_t *look = malloc(nt);
    int rc = -1;
    if (!f.opp || !f.n || !f.has || !f.again || !look || mesh_half_twins(m, t0, f.opp) != 0)
        goto done;
    for (size_t t = 0; t < nt; t++) {
        note_normal(&f, (int32_t)t);
        look[t] = 1;
        if (!vn) continue;
        /* the contour's folds across sharp edges: a corner on one */
        const int32_t *tv = corners(&f, (int32_t)t);
        look[t] = edge_vertex(&f, tv[0]) || edge_vertex(&f, tv[1]) || edge_vertex(&f, tv[2]);
    }
    for (int pass = 0; pass < PASSES; pass++) {
        int flipped = 0;
        for (size_t t = 0; t < nt; t++)
            for (int k = 0; k < 3 && look[t]; k++)
                flipped += try_flip(&f, (int32_t)(3 * t + (size_t)k));
        if (!flipped) break;
        uint8_t *swap = look;
        look = f.again;
        f.again = swap;
        memset(f.again, 0, nt);
    }
    rc = 0;
done:
    free(f.opp);
    free(f.n);
    free(f.has);
    free(f.again);
    free(look);
    return rc;
}

int mesh_unfold(mesh *m, int t0, double h)
{
    return flip_all(m, t0, h, fold_wanted, NULL, NULL);
}

int mesh_unbend(mesh *m, int t0, double h, const mesh_vnormals *vn)
{
    return flip_all(m, t0, h, bent_wanted, NULL, vn);
}

int mesh_unsliver(mesh *m, mesh_snapper *sn, double h)
{
    return flip_all(m, 0, h, sliver_wanted, sn, NULL);
}
