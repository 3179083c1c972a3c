/*
 * refine.c — edges of the contour split where the exact surface bends away
 * from them (see dexels.h, mesh_refine_edges), after its vertices that lie
 * off the surface are moved onto it (settle).
 *
 * The contour joins the samples of a cell by edges, and where a concave
 * sharp edge runs between two grid nodes without changing their signs (the
 * groove between two spheres, a cell away from where the node signs would
 * see it), an edge of the contour bridges the groove: its midpoint is off
 * the surface by the groove's depth (0.06 of a cell of 0.25 there).  A ray
 * through the midpoint along the two triangles' mean normal finds the
 * surface under it; where it is farther than a hundredth of a cell (or
 * half the mesh tolerance, if less), the edge is split there (each of its
 * two triangles in two).  An edge between two samples of surfaces that
 * meet at a sharp edge (a convex rim that passes between two nodes, which a
 * chord between its two sides cuts off) is split on that sharp edge
 * instead, found as contour vertices are (mesh_snap) — between the two
 * opposite corners where both are on it already, so the sharp edge runs
 * through the split.  The ends' surfaces are their normals; a fan centre
 * or face point without one takes the surface a ray finds it on.  Only
 * edges whose triangles meet at more than 10°, or whose ends' normals do,
 * are looked at — on smooth parts the contour is already within a small
 * fraction of a cell — and each round splits at most one edge of a
 * triangle, so the split is checked on the triangles it makes: neither may
 * have no area or turn against its parent, nor (on a sharp edge) against
 * the surface it lies on.  Later rounds look at the edges of the vertices
 * the one before added: splits on surfaces for three rounds (each halves
 * the distance to a crease the normals do not see, and would go on), on
 * sharp edges until none is left, or eight rounds.  A split onto the
 * surface under the middle must also leave no half turned over against the
 * exact surface under it (unless the triangle was): where a crease passes
 * close by, the ray found the other surface, and the halves lasted through
 * every later stage as folds (hull_extrusions.scad: 54 triangles turned
 * over after the splits, none before).
 *
 * Measured (tests/tools/meshdev, at each mesh model's default tolerance):
 * the exact surface's greatest distance from the mesh fell from 0.028 to
 * 0.0014 on bored_cone.scad (the cross hole's rim on the cone), 0.016 to
 * 0.007 on rotated_box_pin.scad.
 */
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ROUNDS 8 /* on sharp edges; elsewhere PROBE_ROUNDS */
#define PROBE_ROUNDS 3
#define COS_BENT 0.985   /* cos 10° */
#define OFF 0.01         /* cells: a midpoint farther from the surface is split there */
#define COS_TURNED 0.707 /* cos 45°: a half turned more from its triangle is checked by rays */

int mesh_vnormal_set(mesh_vnormals *vn, int32_t v, const double n[3], int on_edge, uint32_t patch)
{
    if ((size_t)v >= vn->cap) {
        size_t cap = vn->cap ? vn->cap : 1024;
        while (cap <= (size_t)v)
            cap *= 2;
        float(*g)[3] = realloc(vn->n, cap * sizeof *g);
        if (g) vn->n = g;
        uint8_t *e = realloc(vn->edge, cap);
        if (e) vn->edge = e;
        uint32_t *pa = realloc(vn->patch, cap * sizeof *pa);
        if (pa) vn->patch = pa;
        if (!g || !e || !pa) return -1;
        memset(g + vn->cap, 0, (cap - vn->cap) * sizeof *g);
        memset(e + vn->cap, 0, cap - vn->cap);
        memset(pa + vn->cap, 0, (cap - vn->cap) * sizeof *pa);
        vn->cap = cap;
    }
    for (int c = 0; c < 3; c++)
        vn->n[v][c] = (float)n[c];
    vn->edge[v] = (uint8_t)on_edge;
    vn->patch[v] = patch;
    return 0;
}

void mesh_vnormals_free(mesh_vnormals *vn)
{
    free(vn->n);
    free(vn->edge);
    free(vn->patch);
    vn->n = NULL;
    vn->edge = NULL;
    vn->patch = NULL;
    vn->cap = 0;
}

/* Vertex v's patch (mesh_hit.patch); 0 when not known. */
static uint32_t vpatch(const mesh_vnormals *vn, int32_t v)
{
    return (size_t)v < vn->cap ? vn->patch[v] : 0;
}

/* Whether vertex v lies on a sharp edge (mesh_snap put it there). */
static int on_edge(const mesh_vnormals *vn, int32_t v)
{
    return (size_t)v < vn->cap && vn->edge[v];
}

/* Vertex v's normal into n; 0 when it has none. */
static int vnormal(const mesh_vnormals *vn, int32_t v, double n[3])
{
    if ((size_t)v >= vn->cap) return 0;
    for (int c = 0; c < 3; c++)
        n[c] = vn->n[v][c];
    return dot3(n, n) > 0.25;
}

/* Vertex v's surface normal into n: its own, or, for a vertex the contour
 * left without one (a fan centre or face point) that lies on the surface,
 * the normal a ray along `dir` finds there (kept in vn); 0 when it has none
 * (a point on a sharp edge, or off the surface). */
static int surface_normal(const mesh *m, mesh_snapper *sn, mesh_vnormals *vn, int32_t v,
                          const double dir[3], double n[3])
{
    if (vnormal(vn, v, n)) return 1;
    if (on_edge(vn, v)) return 0;
    double x[3], p[3], d[3], h = sn->d->h;
    mesh_vertex_at(m, v, x);
    uint32_t patch = 0;
    if (!mesh_snap_probe_patch(sn, x, dir, 1e-4 * h, -1, 0, p, n, &patch)) return 0;
    sub3(p, x, d);
    /* vertices are floats: on the surface to their rounding */
    return dot3(d, d) < 1e-12 * h * h && dot3(n, n) > 0.25 &&
           mesh_vnormal_set(vn, v, n, 0, patch) == 0;
}

/* Whether vertex v lies on the sharp edge between the surfaces of normals
 * n0 and n1 near it: marked so, or on both (rays along either normal cross
 * it within 1e-3 h: the contour moves crossings up to EPS h off the
 * nodes, and vertices are floats). */
static int on_sharp(const mesh *m, mesh_snapper *sn, const mesh_vnormals *vn, int32_t v,
                    const double n0[3], const double n1[3])
{
    if (on_edge(vn, v)) return 1;
    double x[3], p[3], pn[3], d[3], h = sn->d->h;
    mesh_vertex_at(m, v, x);
    for (int s = 0; s < 2; s++) {
        if (!mesh_snap_probe(sn, x, s ? n1 : n0, 1e-3 * h, sn->cos_feature, p, pn)) return 0;
        sub3(p, x, d);
        if (!(dot3(d, d) < 1e-6 * h * h)) return 0;
    }
    return 1;
}

/* Whether triangle (a, b, c) of normal n (not unit) is not turned over
 * against the exact surface that a ray along its normal through its
 * centroid finds within half its longest side (more than 120° from it):
 * 1 where it finds none.  (Its corners are on the surface; further off, at
 * a thin tip, the ray finds the far side.) */
static int not_over(mesh_snapper *sn, const double a[3], const double b[3], const double c[3],
                    const double n[3])
{
    double x[3], u[3], p[3], pn[3], ab[3], bc[3], ca[3], l = sqrt(dot3(n, n));
    sub3(b, a, ab);
    sub3(c, b, bc);
    sub3(a, c, ca);
    double reach = 0.5 * sqrt(fmax(dot3(ab, ab), fmax(dot3(bc, bc), dot3(ca, ca))));
    for (int i = 0; i < 3; i++) {
        x[i] = (a[i] + b[i] + c[i]) / 3;
        u[i] = n[i] / l;
    }
    return !mesh_snap_probe(sn, x, u, reach, -1, p, pn) || dot3(u, pn) >= -0.5;
}

/* Triangle t's corners with the edge (ea, eb) of corner k replaced by p:
 * the two triangles it becomes, each with some area and turned less than
 * 90° from t.  Where the surfaces of the edge's ends are known (vn not
 * NULL, a split on a sharp edge), each half must also face like the
 * surface of the end it keeps, and is held to t only where t does: a chord
 * across a sharp edge can lean more than 90° from one of the two surfaces
 * it cuts, and its half on that surface is then right to turn from it.
 * 1 when both are. */
static int halves_ok(const mesh *m, mesh_snapper *sn, int32_t t, int k, const double p[3], double h,
                     const mesh_vnormals *vn)
{
    const int32_t *tv = &m->t[3 * (size_t)t];
    double a[3], b[3], c[3], n[3], n1[3], n2[3], r1[3], r2[3];
    mesh_vertex_at(m, tv[k], a);
    mesh_vertex_at(m, tv[(k + 1) % 3], b);
    mesh_vertex_at(m, tv[(k + 2) % 3], c);
    tri_normal3(a, b, c, n);
    tri_normal3(a, p, c, n1);
    tri_normal3(p, b, c, n2);
    double min2 = 1e-10 * h * h * h * h;
    if (!(dot3(n1, n1) > min2 && dot3(n2, n2) > min2)) return 0;
    /* a split onto the surface under the middle must not turn a half
     * over against it (a sharp edge's split is held to its surfaces below);
     * asked by rays only of a half turned 45° or more from t */
    double l = sqrt(dot3(n, n)), l1 = sqrt(dot3(n1, n1)), l2 = sqrt(dot3(n2, n2));
    if (!vn && (dot3(n, n1) < COS_TURNED * l * l1 || dot3(n, n2) < COS_TURNED * l * l2) &&
        not_over(sn, a, b, c, n) && (!not_over(sn, a, p, c, n1) || !not_over(sn, p, b, c, n2)))
        return 0;
    if (!vn || !vnormal(vn, tv[k], r1) || !vnormal(vn, tv[(k + 1) % 3], r2))
        return dot3(n, n1) > 0 && dot3(n, n2) > 0;
    return dot3(r1, n1) > 0 && dot3(r2, n2) > 0 && (dot3(n, n1) > 0 || dot3(n, r1) <= 0) &&
           (dot3(n, n2) > 0 || dot3(n, r2) <= 0);
}

/* Whether triangle t has a corner numbered v0 or above. */
static int has_new(const mesh *m, int32_t t, int32_t v0)
{
    const int32_t *tv = &m->t[3 * (size_t)t];
    return tv[0] >= v0 || tv[1] >= v0 || tv[2] >= v0;
}

/* Whether vertex v may have an edge the last round changed: it was an end
 * or opposite corner of a split (touch, NULL in the first round: all are),
 * or the split added it (v0 and above). */
static int touched(const uint8_t *touch, int32_t v0, int32_t v)
{
    return !touch || v >= v0 || touch[v];
}

/* The edges of triangles [t0, m->nt) whose ends are both touched: for
 * each half-edge x (3·triangle + corner, from t0) that is the first of its
 * edge's sides (either way round, in the order of the triangles),
 * other[x] is the last of the others; else -1.  Found among the triangles
 * about the edge's first end (its fan), not through a map of the edges:
 * the fans lie in the order the contour made them, a map's slots at random
 * (a tenth of the time on a contour of 200,000 triangles).  0 or -1. */
static int edge_sides(const mesh *m, int t0, int32_t v0, const uint8_t *touch, int32_t *other)
{
    int32_t *start, *fan, nt = m->nt - t0;
    if (mesh_vertex_fans(m, t0, &start, &fan) != 0) return -1;
    for (int32_t x = 0; x < 3 * nt; x++) {
        const int32_t *tx = &m->t[3 * (size_t)(t0 + x / 3)];
        int32_t a = tx[x % 3], b = tx[(x % 3 + 1) % 3], first = x, last = -1;
        other[x] = -1;
        if (!touched(touch, v0, a) || !touched(touch, v0, b)) continue;
        for (int32_t f = start[a]; f < start[a + 1] && first == x; f++) {
            const int32_t *ty = &m->t[3 * (size_t)fan[f]];
            for (int k = 0; k < 3; k++) {
                int32_t ya = ty[k], yb = ty[(k + 1) % 3], y = 3 * (fan[f] - t0) + k;
                if (!((ya == a && yb == b) || (ya == b && yb == a)) || y == x) continue;
                if (y < first) first = y;
                if (y > last) last = y;
            }
        }
        if (first == x) other[x] = last;
    }
    free(start);
    free(fan);
    return 0;
}

/* One round over the edges of the triangles with a corner numbered v0 or
 * above (the vertices the last round added; all in the first), a midpoint
 * farther than `off` from the surface split there — on the sharp edge its
 * ends' surfaces meet at, or (probe) on the surface under it; *split set
 * when it split an edge.  The edges mapped are those of the triangles with
 * two touched corners: so an edge between a triangle the last round split
 * and one it left is found from both sides.  The corners of this round's
 * splits are marked in next (m->nv entries).  0 or -1 (out of memory). */
static int round_once(mesh *m, int t0, int32_t v0, const uint8_t *touch, uint8_t *next, double off_,
                      int probe, mesh_fmap *pos, mesh_snapper *sn, mesh_vnormals *vn, int *split)
{
    int nt = m->nt - t0;
    if (nt <= 0) return 0;
    double h = sn->d->h;
    int32_t *other = malloc(3 * (size_t)nt * sizeof *other);
    uint8_t *used = calloc((size_t)nt, 1);
    int rc = -1;
    if (!other || !used || edge_sides(m, t0, v0, touch, other) != 0) goto done;
    /* the edges in the order of their first triangles (a map's order
     * visited the vertices at random: a quarter of the time on a contour of
     * two million triangles went to cache misses) */
    for (int32_t x = 0; x < 3 * nt; x++) {
        if (used[x / 3] || other[x] < 0) continue;
        int32_t ta = x / 3, tb = other[x] / 3;
        int ka = x % 3, kb = other[x] % 3;
        if (used[ta] || used[tb] || !(has_new(m, t0 + ta, v0) || has_new(m, t0 + tb, v0))) continue;
        const int32_t *va = &m->t[3 * (size_t)(t0 + ta)], *vb = &m->t[3 * (size_t)(t0 + tb)];
        double a[3], b[3], c[3], d[3], na[3], nb[3];
        mesh_vertex_at(m, va[ka], a);
        mesh_vertex_at(m, va[(ka + 1) % 3], b);
        mesh_vertex_at(m, va[(ka + 2) % 3], c);
        mesh_vertex_at(m, vb[(kb + 2) % 3], d);
        tri_normal3(a, b, c, na);
        tri_normal3(b, a, d, nb);
        double la = sqrt(dot3(na, na)), lb = sqrt(dot3(nb, nb)), ends[2][3], ep[2][3];
        if (!(la > 0 && lb > 0)) continue;
        double guess[3];
        for (int q = 0; q < 3; q++)
            guess[q] = na[q] / la + nb[q] / lb;
        double gl = sqrt(dot3(guess, guess));
        if (!(gl > 1e-6)) continue;
        for (int q = 0; q < 3; q++)
            guess[q] /= gl;
        int known = surface_normal(m, sn, vn, va[ka], guess, ends[0]) &&
                    surface_normal(m, sn, vn, va[(ka + 1) % 3], guess, ends[1]);
        double cos_ends = known ? dot3(ends[0], ends[1]) : 1;
        if (dot3(na, nb) >= COS_BENT * la * lb && cos_ends >= COS_BENT) continue;
        /* along a sharp edge: its ends are on it, its middle within the
         * edge's own sag over a cell */
        if (on_edge(vn, va[ka]) && on_edge(vn, va[(ka + 1) % 3])) continue;
        double dir[3], mid[3];
        for (int q = 0; q < 3; q++) {
            dir[q] = na[q] / la + nb[q] / lb;
            mid[q] = 0.5 * (a[q] + b[q]);
        }
        double dl = sqrt(dot3(dir, dir));
        if (!(dl > 1e-6)) continue;
        for (int q = 0; q < 3; q++)
            dir[q] /= dl;
        /* Where to split: on the sharp edge of the ends' two surfaces, else
         * on the surface under the midpoint; the first that is off the edge
         * and keeps both triangles' halves the right way up. */
        double hit[3], hn[3] = {0, 0, 0}, off[3];
        uint32_t hpatch = 0, ep_patch[2] = {vpatch(vn, va[ka]), vpatch(vn, va[(ka + 1) % 3])};
        int found = 0, crease = 0,
            sharp = cos_ends < sn->cos_feature ||
                    (known && mesh_planes_crease(ep_patch[0], ep_patch[1], cos_ends));
        for (int how = sharp ? 0 : 1; how < (probe ? 2 : 1) && !found; how++) {
            if (how == 0) {
                /* From the middle of the edge; or, where the two opposite
                 * corners are on the sharp edge already, from the middle
                 * of theirs: the edge crosses it between them, and the
                 * split point must lie between them too (the snap can
                 * slide along the sharp edge to one of them, and the
                 * halves then fold).  That middle is on the sharp edge to
                 * its sag, and stays where the snap slides. */
                int across = on_sharp(m, sn, vn, va[(ka + 2) % 3], ends[0], ends[1]) &&
                             on_sharp(m, sn, vn, vb[(kb + 2) % 3], ends[0], ends[1]);
                const double *p0 = across ? c : a, *p1 = across ? d : b;
                double blo[3], bhi[3], start[3], cd[3], cx[3];
                for (int q = 0; q < 3; q++) {
                    ep[0][q] = a[q];
                    ep[1][q] = b[q];
                    blo[q] = fmin(p0[q], p1[q]) - 0.5 * h;
                    bhi[q] = fmax(p0[q], p1[q]) + 0.5 * h;
                    hit[q] = start[q] = 0.5 * (p0[q] + p1[q]);
                }
                int sr = mesh_snap(sn, (const double(*)[3])ep, (const double(*)[3])ends, ep_patch,
                                   2, -1, blo, bhi, hit);
                if (across) {
                    sub3(d, c, cd);
                    sub3(hit, c, cx);
                    double s = dot3(cx, cd) / fmax(dot3(cd, cd), 1e-300);
                    if (sr != 2 || s < 0.25 || s > 0.75) memcpy(hit, start, sizeof start);
                } else if (sr != 2) {
                    continue;
                }
            } else if (!mesh_snap_probe_patch(sn, mid, dir, 0.5 * h, -1, 0, hit, hn, &hpatch)) {
                continue;
            }
            sub3(hit, mid, off);
            crease = how == 0;
            /* never where a vertex is: solids that touch along an edge,
             * split on it from both sides, made two vertices at one point,
             * which a reader welding by position joins into one edge of
             * four triangles */
            found = dot3(off, off) > off_ * off_ && !mesh_fmap_has(pos, mesh_pos_key(hit)) &&
                    halves_ok(m, sn, t0 + ta, ka, hit, h, crease ? vn : NULL) &&
                    halves_ok(m, sn, t0 + tb, kb, hit, h, crease ? vn : NULL);
        }
        if (!found) continue;
        /* (m->t may move as triangles are added) */
        int32_t corner[4] = {va[ka], va[(ka + 1) % 3], va[(ka + 2) % 3], vb[(kb + 2) % 3]};
        int fresh;
        int32_t v = mesh_push_vertex(m, hit[0], hit[1], hit[2]),
                *slot = mesh_fmap_slot(pos, mesh_pos_key(hit), &fresh);
        if (v < 0 || !slot || mesh_vnormal_set(vn, v, hn, crease, crease ? 0 : hpatch) != 0)
            goto done;
        *slot = v;
        int32_t tri[2] = {t0 + ta, t0 + tb};
        int kk[2] = {ka, kb};
        for (int s = 0; s < 2; s++) {
            int32_t *tv = &m->t[3 * (size_t)tri[s]];
            int32_t e1 = tv[(kk[s] + 1) % 3], e2 = tv[(kk[s] + 2) % 3];
            uint16_t color = m->tc && m->npal ? m->tc[tri[s]] : 0;
            tv[(kk[s] + 1) % 3] = v; /* (e0, v, e2) */
            if (mesh_push_triangle(m, v, e1, e2, color) < 0) goto done;
        }
        used[ta] = used[tb] = 1;
        *split = 1;
        for (int q = 0; q < 4; q++)
            next[corner[q]] = 1;
    }
    rc = 0;
done:
    free(other);
    free(used);
    return rc;
}

/* The loose vertices near a sharp edge — fan centres and face points
 * (vertices without a normal) not on the edge themselves, that share a
 * triangle with a vertex on it — moved to the nearest surface along the
 * normals of their neighbours that are ray crossings, within a cell, unless
 * that turns one of their triangles over.  Where a sharp edge passes beyond its
 * cell, the contour left such a centre off both surfaces (clamped into the
 * cell); with the edge now split onto the sharp edge, its place is on the
 * nearer of them. */
static int project_loose(mesh *m, int t0, mesh_snapper *sn, const mesh_vnormals *vn)
{
    if (m->nt <= t0) return 0;
    double h = sn->d->h;
    uint8_t *near = calloc((size_t)m->nv, 1);
    int32_t *start = NULL, *fan = NULL;
    if (!near || mesh_vertex_fans(m, t0, &start, &fan) != 0) {
        free(near);
        return -1;
    }
    for (int32_t t = t0; t < m->nt; t++) {
        const int32_t *tv = &m->t[3 * (size_t)t];
        if (on_edge(vn, tv[0]) || on_edge(vn, tv[1]) || on_edge(vn, tv[2]))
            near[tv[0]] = near[tv[1]] = near[tv[2]] = 1;
    }
    for (int32_t v = 0; v < m->nv; v++) {
        double nn[3];
        if (!near[v] || on_edge(vn, v) || vnormal(vn, v, nn)) continue;
        /* the nearest surface along the normals of its neighbours that
         * are ray crossings (their surfaces) */
        double x[3], hit[3] = {0, 0, 0}, best = INFINITY, tried[4][3];
        int ntried = 0;
        mesh_vertex_at(m, v, x);
        for (int f = start[v]; f < start[v + 1]; f++) {
            const int32_t *tv = &m->t[3 * (size_t)fan[f]];
            for (int k = 0; k < 3; k++) {
                double dn[3], q[3], qn[3], d[3];
                if (tv[k] == v || !vnormal(vn, tv[k], dn)) continue;
                int seen = 0;
                for (int i = 0; i < ntried && !seen; i++)
                    seen = dot3(dn, tried[i]) > 0.999;
                if (seen || ntried == 4) continue;
                memcpy(tried[ntried++], dn, sizeof dn);
                if (!mesh_snap_probe(sn, x, dn, h, -1, q, qn)) continue;
                sub3(q, x, d);
                if (dot3(d, d) < best) {
                    best = dot3(d, d);
                    memcpy(hit, q, sizeof q);
                }
            }
        }
        if (best < INFINITY)
            mesh_vertex_move(m, v, fan + start[v], start[v + 1] - start[v], hit, 0,
                             1e-10 * h * h * h * h);
    }
    free(near);
    free(start);
    free(fan);
    return 0;
}

/* The contour's vertices without a normal (fan centres and face points)
 * that lie off the exact surface by more than `off`, moved onto it: to the
 * nearest crossing of a ray along their triangles' mean normal within a
 * cell, facing within 90° of it, unless that turns one of their triangles
 * 90° or more or takes a place in pos; they then have that crossing's
 * normal.  The QEF puts a vertex where the planes of its cell's samples
 * meet, and where a face narrower than a cell runs between them (a hull's
 * sliver facets fanning out of a corner, a twisted extrusion's rims), no
 * sample sees it and that point lies off the solid, on the planes carried
 * past their faces (hull_extrusions.scad: 330 vertices up to 28
 * tolerances off); mesh_snap, asked for two surfaces' sharp edge, finds
 * such a point too.  Settled on the surface with the normal there, the
 * splits below see the face the samples missed, and the sharp edges on
 * both of its sides.  Measured over the mesh models (build/tools/meshdev
 * at their default tolerance): mesh samples beyond it 0.59 -> 0.37 % on
 * average, hull_revolve.scad 2.07 -> 1.44 tolerances and 16,476 -> 9,962
 * triangles, hull_extrusions.scad 3.86 -> 0.90 % and 3,098 -> 1,212. */
static int settle(mesh *m, int t0, double off, mesh_snapper *sn, mesh_vnormals *vn, mesh_fmap *pos)
{
    double h = sn->d->h;
    int32_t *start = NULL, *fan = NULL;
    if (mesh_vertex_fans(m, t0, &start, &fan) != 0) return -1;
    for (int32_t v = 0; v < m->nv; v++) {
        double x[3], n[3] = {0, 0, 0}, p[3], pn[3], d[3];
        if (start[v] == start[v + 1] || vnormal(vn, v, x)) continue;
        for (int f = start[v]; f < start[v + 1]; f++) {
            double tn[3];
            mesh_triangle_normal(m, fan[f], tn);
            for (int k = 0; k < 3; k++)
                n[k] += tn[k];
        }
        double l = sqrt(dot3(n, n));
        if (!(l > 0)) continue;
        for (int k = 0; k < 3; k++)
            n[k] /= l;
        mesh_vertex_at(m, v, x);
        uint32_t patch = 0;
        if (!mesh_snap_probe_patch(sn, x, n, h, 0, 0, p, pn, &patch)) continue;
        sub3(p, x, d);
        if (!(dot3(d, d) > off * off) || mesh_fmap_has(pos, mesh_pos_key(p)) ||
            !mesh_vertex_move(m, v, fan + start[v], start[v + 1] - start[v], p, 0,
                              1e-10 * h * h * h * h))
            continue;
        int fresh;
        int32_t *slot = mesh_fmap_slot(pos, mesh_pos_key(p), &fresh);
        if (!slot || mesh_vnormal_set(vn, v, pn, 0, patch) != 0) {
            free(start);
            free(fan);
            return -1;
        }
        *slot = v;
    }
    free(start);
    free(fan);
    return 0;
}

int mesh_refine_edges(mesh *m, int t0, double tol, mesh_snapper *sn, mesh_vnormals *vn,
                      mesh_fmap *pos)
{
    if (!sn->arena) return 0;
    double off = OFF * sn->d->h;
    if (tol > 0) off = fmin(off, 0.5 * tol);
    if (m->nt > t0 && settle(m, t0, off, sn, vn, pos) != 0) return -1;
    int32_t v0 = 0;
    uint8_t *touch = NULL, *next = NULL;
    int rc = 0;
    for (int r = 0; r < ROUNDS && rc == 0; r++) {
        int split = 0;
        int32_t nv = m->nv;
        next = calloc((size_t)nv + 1, 1);
        if (!next ||
            round_once(m, t0, v0, touch, next, off, r < PROBE_ROUNDS, pos, sn, vn, &split) != 0)
            rc = -1;
        free(touch);
        touch = next;
        next = NULL;
        if (!split) break;
        v0 = nv;
    }
    free(touch);
    return rc == 0 ? project_loose(m, t0, sn, vn) : -1;
}
