/*
 * unfold.c — the contour's folds (two triangles back to back across an
 * edge) taken away by flipping that edge (see dexels.h, mesh_unfold).
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
 */
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <stdlib.h>

#define COS_FOLD (-0.866) /* normals more than 150° apart: folded */
#define PASSES 8
#define AROUND 1024 /* the most edges looked at around a vertex */

typedef struct fold_mesh {
    mesh *m;
    int t0;
    int32_t *opp;   /* half-edge 3·t + k (tv[k] → tv[k + 1], t from t0) → its twin; -1 */
    double min2;    /* |cross|² below which a triangle has no area */
    double (*n)[3]; /* each triangle's unit normal, when has */
    uint8_t *has;
} fold_mesh;

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

/* Flip the edge of half-edge x when its triangles are folded and the flip
 * leaves fewer folded edges; 1 when flipped. */
static int try_flip(fold_mesh *f, int32_t x)
{
    int32_t y = f->opp[x];
    if (y < 0) return 0;
    int32_t t = x / 3, u = y / 3;
    int k = x % 3, j = y % 3;
    if (t == u) return 0;
    int32_t *tv = corners(f, t), *uv = corners(f, u);
    int32_t a = tv[k], b = tv[(k + 1) % 3], c = tv[(k + 2) % 3], d = uv[(j + 2) % 3];
    if (c == d) return 0;
    mesh *m = f->m;
    if (!f->has[t] || !f->has[u] || !(dot3(f->n[t], f->n[u]) < COS_FOLD)) return 0;
    const double *n1 = f->n[t], *n2 = f->n[u];
    double n3[3], n4[3];
    /* the quad's sides: b → c, c → a (in t), a → d, d → b (in u) */
    int32_t bc = 3 * t + (k + 1) % 3, ca = 3 * t + (k + 2) % 3, ad = 3 * u + (j + 1) % 3,
            db = 3 * u + (j + 2) % 3;
    int before = 1 + folded_across(f, bc, n1) + folded_across(f, ca, n1) +
                 folded_across(f, ad, n2) + folded_across(f, db, n2);
    /* after: (c, a, d) holds c → a and a → d, (d, b, c) holds d → b and b → c */
    if (!unit_normal(m, c, a, d, f->min2, n3) || !unit_normal(m, d, b, c, f->min2, n4)) return 0;
    int after = (dot3(n3, n4) < COS_FOLD) + folded_across(f, ca, n3) + folded_across(f, ad, n3) +
                folded_across(f, db, n4) + folded_across(f, bc, n4);
    if (after >= before || has_edge(f, ca, d)) return 0;
    int32_t oca = f->opp[ca], oad = f->opp[ad], odb = f->opp[db], obc = f->opp[bc];
    tv[0] = c, tv[1] = a, tv[2] = d; /* c → a, a → d, d → c */
    uv[0] = d, uv[1] = b, uv[2] = c; /* d → b, b → c, c → d */
    link(f, 3 * t, oca);
    link(f, 3 * t + 1, oad);
    link(f, 3 * u, odb);
    link(f, 3 * u + 1, obc);
    link(f, 3 * t + 2, 3 * u + 2);
    note_normal(f, t);
    note_normal(f, u);
    return 1;
}

int mesh_unfold(mesh *m, int t0, double h)
{
    if (m->nt <= t0) return 0;
    size_t nt = (size_t)(m->nt - t0);
    if (3 * nt > INT32_MAX) return 0;
    fold_mesh f = {m,
                   t0,
                   malloc(3 * nt * sizeof *f.opp),
                   1e-12 * h * h * h * h,
                   malloc(nt * sizeof *f.n),
                   malloc(nt)};
    if (!f.opp || !f.n || !f.has || mesh_half_twins(m, t0, f.opp) != 0) {
        free(f.opp);
        free(f.n);
        free(f.has);
        return -1;
    }
    for (size_t t = 0; t < nt; t++)
        note_normal(&f, (int32_t)t);
    for (int pass = 0; pass < PASSES; pass++) {
        int flipped = 0;
        for (size_t x = 0; x < 3 * nt; x++)
            flipped += try_flip(&f, (int32_t)x);
        if (!flipped) break;
    }
    free(f.opp);
    free(f.n);
    free(f.has);
    return 0;
}
