/*
 * crease.c — a simplified mesh's chords across the edges and corners of
 * plane faces split on them, exactly (see dexels.h, mesh_split_creases).
 *
 * Where an edge between two plane faces runs obliquely through the grid,
 * a cell it passes through may see only one of the faces on its edges, put
 * its vertex on that face, and join it to a vertex on the other: a chord
 * that cuts the edge off (a chamfer up to a tenth of a cell deep); where
 * the third face of a corner meets no cell edge at all, the corner is cut
 * off likewise.  The simplifier keeps every such chord, and the vertices
 * about it: a box turned obliquely came out as 352 triangles where 12
 * describe it, and 8 tolerances off at its corners.
 *
 * Plane faces are known exactly: a ray through a triangle's centroid finds
 * the face under it, and a planar patch is one plane, read off that
 * crossing.  A vertex lies on those planes, of the faces under the
 * triangles around it, that pass within rounding of it.  In each pass:
 *   - a vertex whose triangles lie over two or three planes, not all
 *     through it, moves onto the line or point where they meet (a contour
 *     vertex a little off a crease), where no more of its triangles then
 *     misfit (lie on no plane their corners share, or face against it) and
 *     none that fit now would not;
 *   - an edge shorter than half a cell, amid plane faces, collapses where
 *     that leaves fewer triangles that misfit, and none that fit now would
 *     not (a knot of vertices the contour left about a crease, its
 *     triangles folded back on the face);
 *   - an edge whose ends share no plane is flipped where its quad's other
 *     diagonal lies on the crease; where both halves would then face
 *     against their planes (the quad's far corners lie on the crease in the
 *     wrong order along it: a crossed knot), those two corners are merged
 *     and the edge's triangles go; else it is split where it crosses the
 *     crease: one end on A and the other on B, at the point of the line
 *     where A and B meet nearest the edge;
 *   - a triangle whose corners still share no plane, and lie on three,
 *     gets the point where the three meet as a new corner (a fan of three);
 *   - and first of all, a knot about a corner where three planes meet
 *     (the vertices within three cells of it, reached through each other:
 *     a twisted extrusion's acute corners held 40), or about a point of a
 *     crease, goes whole where some of its triangles misfit: its triangles
 *     become a fan from the corner to their rim, where the rim is one loop
 *     and every fan triangle lies on a plane its corners share, facing like
 *     it, over the surface (a pass that fans knots leaves the rules above
 *     to the next; a vertex whose knots were refused is not tried again
 *     until its triangles change);
 *   - and last, where the rules change nothing more, a cap the contour
 *     left across an acute crease, short of it, is unzipped into strips on
 *     the crease's two faces (crease_cap.c), and the rules run again.
 * Every such point must be one a ray through it finds on the surface (else
 * the planes do not meet there: a face lies between them; crease_meets_on_surface),
 * and every change must leave triangles with area that face like
 * the plane they lie on.  Creases slighter than 10° are left to the
 * simplifier (a faceted curve's: hull_revolve.scad's 64 x 32 facets), and
 * only what lies about a bend is looked at; later passes look at the
 * triangles with a corner the last one changed (and so at every edge of
 * them: a knot's chord whose ends were not touched, between two corners
 * that were, waited for a pass that never came).  The simplifier then runs
 * again (mesh_dexels_simplify).  The contour's own mesh, before the simplifier,
 * is crowded with slivers along such edges, and most splits there would
 * fold one.
 *
 * Measured (build/tools/meshdev, the mesh models at their default
 * tolerance): star_prism.scad 122 -> 36 triangles (openscad's), its tips 14
 * D off -> exact; import_amf_3mf 212 -> 188, 1.09 -> 0.69 D; revolve_faceted
 * 1,084 -> 344 (openscad 260); pinched_cells 1,874 -> 776; twist_ties 1,876
 * -> 1,250; svg_import 968 -> 800, 30 -> 10 D; the box above 352 -> 68,
 * all eight of its corners found where five were.  Over the 17 models, mesh
 * samples beyond the tolerance 1.31 % -> 0.72 %, surface samples 67 -> 19.
 * Knots these rules do not untie are left as they are (two on the box,
 * about its corners).  The cost: the corpus's twisted and scaled
 * extrusions (linear_extrude-scale-zero-tests.scad, 140,000 triangles
 * simplified) take 1.2 s more, for a mesh of 68,000 triangles where it was
 * 156,000.  Knots fanned from their corners, later (first in a pass: run
 * last, they found their triangles changed by the other rules pass after
 * pass): over the 17 models, mesh samples beyond the tolerance 0.29 % ->
 * 0.13 % on average, pinched_cells 480 -> 204 triangles (openscad 216) and
 * exact, twist_ties 978 -> 310, the 24-gon frustum of tests/models 100 ->
 * 92 (openscad's); the scaled extrusions above 5.1 -> 6.5 s (each knot
 * tried once a pass whichever of its vertices finds it, not at all about
 * a corner where a crowd of vertices is too big to be one: 20 s before).
 */
#include "../geom/closest.h"
#include "../intervals/vec3.h"
#include "crease.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PASSES 8
#define KNOT 0.5       /* cells: an edge shorter may be collapsed (collapse_knot) */
#define TIE 0.001      /* cells: see stays() */
#define NEAR 0.01      /* cells: see misfits_after() */
#define REFUSED 2      /* c->hot: see knot_refused() */
#define COS_BENT 0.996 /* cos 5°: a chord across a crease of 10° bends more */

/* The plane of the planar face under triangle t (a ray along its normal
 * through its centroid), as an index into c->pl; -1 when none, -3 when out
 * of memory. */
static int32_t face_under(crease_mesh *c, int32_t t)
{
    double p[3][3], g[3], n[3], hit[3], hn[3];
    for (int k = 0; k < 3; k++)
        mesh_vertex_at(c->m, c->m->t[3 * (size_t)t + k], p[k]);
    tri_normal3(p[0], p[1], p[2], n);
    double l = sqrt(dot3(n, n));
    if (!(l > 0)) return -1;
    for (int k = 0; k < 3; k++) {
        n[k] /= l;
        g[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
    }
    uint32_t patch = 0;
    if (!mesh_snap_probe_patch(c->sn, g, n, c->h, 0.5, 0, hit, hn, &patch) || !patch ||
        !(mesh_patch_flagged(c->sn->d, patch) & MESH_PATCH_PLANAR))
        return -1;
    int fresh;
    int32_t *slot = mesh_fmap_slot(&c->by_patch, patch, &fresh);
    if (!slot) return -3;
    if (fresh) {
        if (c->npl == c->cap) {
            int32_t cap = c->cap ? 2 * c->cap : 64;
            plane *more = realloc(c->pl, (size_t)cap * sizeof *more);
            if (!more) return -3;
            c->pl = more;
            c->cap = cap;
        }
        if (!((l = sqrt(dot3(hn, hn))) > 0)) l = 1;
        plane *q = &c->pl[c->npl];
        for (int k = 0; k < 3; k++)
            q->n[k] = hn[k] / l;
        q->d = dot3(q->n, hit);
        *slot = c->npl++;
    }
    return *slot;
}

/* The planes under the triangles around vertices vs (nv of them),
 * distinct, into out (cap at most); their count. */
static int candidates_max(const crease_mesh *c, const int32_t *vs, int nv, const plane **out,
                          int cap)
{
    int n = 0;
    for (int i = 0; i < nv; i++)
        for (int32_t f = c->start[vs[i]]; f < c->start[vs[i] + 1]; f++) {
            if (c->tp[c->fan[f]] < 0) continue;
            const plane *p = &c->pl[c->tp[c->fan[f]]];
            int seen = 0;
            for (int j = 0; j < n && !seen; j++)
                seen = out[j] == p;
            if (!seen && n < cap) out[n++] = p;
        }
    return n;
}

/* candidates_max, MAX_PLANES at most. */
int crease_candidates(const crease_mesh *c, const int32_t *vs, int nv, const plane **out)
{
    return candidates_max(c, vs, nv, out, MAX_PLANES);
}

/* Which of the planes pl (np) point x lies within `cells` of (or of
 * rounding: vertices are floats), as bits. */
unsigned crease_planes_near(const crease_mesh *c, const double x[3], const plane *const *pl, int np,
                            double cells)
{
    double big = fmax(fabs(x[0]), fmax(fabs(x[1]), fabs(x[2])));
    double eps = fmax(cells * c->h, 5e-7 * big);
    unsigned s = 0;
    for (int i = 0; i < np; i++)
        if (fabs(dot3(pl[i]->n, x) - pl[i]->d) < eps) s |= 1u << i;
    return s;
}

/* planes_near for vertex v. */
static unsigned near_planes(const crease_mesh *c, int32_t v, const plane *const *pl, int np,
                            double cells)
{
    double x[3];
    mesh_vertex_at(c->m, v, x);
    return crease_planes_near(c, x, pl, np, cells);
}

/* Which of the planes pl (np) vertex v lies on, as bits. */
unsigned crease_on_planes(const crease_mesh *c, int32_t v, const plane *const *pl, int np)
{
    return near_planes(c, v, pl, np, ON);
}

/* Whether vertex v lies on the plane under one of its triangles (kept in
 * c->known once vertices stop moving in a pass). */
int crease_on_a_plane(crease_mesh *c, int32_t v)
{
    if ((size_t)v < c->nknown && c->known[v]) return c->known[v] == 2;
    const plane *pl[MAX_PLANES];
    int np = crease_candidates(c, &v, 1, pl), on = crease_on_planes(c, v, pl, np) != 0;
    if ((size_t)v < c->nknown) c->known[v] = (uint8_t)(1 + on);
    return on;
}

/* Whether x lies on the surface: a ray through it along n (not unit) finds
 * the surface there. */
int crease_on_surface(crease_mesh *c, const double x[3], const double n[3])
{
    double u[3], hit[3], hn[3], d[3], l = sqrt(dot3(n, n));
    if (!(l > 1e-9)) return 0;
    for (int k = 0; k < 3; k++)
        u[k] = n[k] / l;
    if (!mesh_snap_probe(c->sn, x, u, c->h, -1, hit, hn)) return 0;
    sub3(hit, x, d);
    return dot3(d, d) < 1e-8 * c->h * c->h;
}

/* Whether a triangle at p lies on the surface: rays along its normal
 * through its centroid, halfway from there to each corner and nine tenths
 * of the way to its last find it there. */
int crease_lies_on_surface(crease_mesh *c, double p[3][3])
{
    static const double toward[5] = {0, 0.5, 0.5, 0.5, 0.9};
    double n[3], g[3];
    tri_normal3(p[0], p[1], p[2], n);
    for (int q = 0; q < 5; q++) {
        const double *e = p[q == 1 ? 0 : q == 2 ? 1 : 2];
        for (int k = 0; k < 3; k++) {
            g[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
            g[k] += toward[q] * (e[k] - g[k]);
        }
        if (!crease_on_surface(c, g, n)) return 0;
    }
    return 1;
}

/* Whether x, where the n (2 or 3) planes pl meet, lies on the surface: a ray
 * through it along the sum of their normals finds the surface there, or one
 * along a pair's sum, or along one normal.  The sum alone can miss: where a
 * concave edge meets a face (a faceted sphere minus a faceted cylinder, at
 * the hole's rim) the solid about x is a thin wedge that the line along the
 * sum only touches at x, and whether a ray through a touching point reports
 * a crossing is left to rounding. */
int crease_meets_on_surface(crease_mesh *c, const double x[3], const plane *const *pl, int n)
{
    static const unsigned order[] = {7, 3, 5, 6, 1, 2, 4};
    unsigned all = (1u << n) - 1;
    for (size_t i = 0; i < sizeof order / sizeof *order; i++) {
        unsigned s = order[i] & all;
        if (s != order[i]) continue;
        double d[3] = {0, 0, 0};
        for (int p = 0; p < n; p++)
            if (s >> p & 1)
                for (int k = 0; k < 3; k++)
                    d[k] += pl[p]->n[k];
        if (crease_on_surface(c, x, d)) return 1;
    }
    return 0;
}

/* Whether the triangle p, q, r has area and faces like the first of the
 * planes of bits `shared` of pl, which its corners share (like n where
 * they share none: it still crosses a crease). */
int crease_half_ok(const plane *const *pl, unsigned shared, const double p[3], const double q[3],
                   const double r[3], const double n[3], double min2)
{
    double t[3];
    tri_normal3(p, q, r, t);
    for (int i = 0; i < KNOT_PLANES; i++)
        if (shared >> i & 1) {
            n = pl[i]->n;
            break;
        }
    return dot3(t, t) > min2 && dot3(t, n) > 0;
}

/* The slot of place x in c->pos: the vertex there, or -1 where none is
 * (one moved or collapsed away); NULL when out of memory. */
int32_t *crease_place(crease_mesh *c, const double x[3])
{
    int fresh;
    int32_t *slot = mesh_fmap_slot(&c->pos, mesh_pos_key(x), &fresh);
    if (slot && fresh) *slot = -1;
    return slot;
}

/* Vertex v leaves its place (moved or collapsed away); 0 or -1. */
int crease_leave_place(crease_mesh *c, int32_t v)
{
    double x[3];
    mesh_vertex_at(c->m, v, x);
    int32_t *slot = crease_place(c, x);
    if (!slot) return -1;
    if (*slot == v) *slot = -1;
    return 0;
}

/* A vertex at x (float), not where one is; its number, -1 when one is
 * there, -2 when out of memory. */
int32_t crease_add_vertex(crease_mesh *c, const double x[3])
{
    int32_t *slot = crease_place(c, x);
    if (!slot) return -2;
    if (*slot >= 0) return -1;
    int32_t v = mesh_push_vertex(c->m, x[0], x[1], x[2]);
    if (v < 0) return -2;
    *slot = v;
    return v;
}

/* A point of the line where planes a and b meet into p0, its direction
 * (not unit) into e; 0 when they are parallel. */
int crease_line(const plane *a, const plane *b, double p0[3], double e[3])
{
    cross3(a->n, b->n, e);
    double ee = dot3(e, e), t1[3], t2[3];
    if (!(ee > 1 - COS_APART * COS_APART)) return 0;
    /* (d_a (n_b × e) + d_b (e × n_a)) / |e|² */
    cross3(b->n, e, t1);
    cross3(e, a->n, t2);
    for (int k = 0; k < 3; k++)
        p0[k] = (a->d * t1[k] + b->d * t2[k]) / ee;
    return 1;
}

/* The point of the line where planes a and b meet nearest p, into x; 0
 * when they part by less than COS_APART. */
static int crease_nearest(const plane *a, const plane *b, const double p[3], double x[3])
{
    double p0[3], e[3], d[3];
    if (!crease_line(a, b, p0, e)) return 0;
    sub3(p, p0, d);
    double t = dot3(d, e) / dot3(e, e);
    for (int k = 0; k < 3; k++)
        x[k] = p0[k] + t * e[k];
    return 1;
}

/* Where planes a, b and c meet, into x; 0 when they nearly share a line. */
int crease_corner(const plane *a, const plane *b, const plane *c, double x[3])
{
    double bc[3], ca[3], ab[3];
    cross3(b->n, c->n, bc);
    cross3(c->n, a->n, ca);
    cross3(a->n, b->n, ab);
    double det = dot3(a->n, bc);
    if (!(fabs(det) > 0.05)) return 0;
    for (int i = 0; i < 3; i++)
        x[i] = (a->d * bc[i] + b->d * ca[i] + c->d * ab[i]) / det;
    return 1;
}

/* The point of the line where planes a and b meet nearest the segment
 * from u to w, well inside it and within a cell of it, into x; 0 when
 * there is none. */
static int crease_point(const plane *a, const plane *b, const double u[3], const double w[3],
                        double h, double x[3])
{
    double e[3], p0[3], s[3], r[3];
    if (!crease_line(a, b, p0, e)) return 0;
    double ee = dot3(e, e);
    /* the nearest points of the line p0 + t e and the segment u + s (w − u) */
    sub3(w, u, s);
    sub3(u, p0, r);
    double A = ee, B = dot3(e, s), C = dot3(s, s), D = dot3(e, r), E = dot3(s, r);
    double den = A * C - B * B;
    if (!(den > 1e-12 * A * C)) return 0;
    double sg = (B * D - A * E) / den, tl = (B * sg + D) / A, gap[3];
    if (!(sg > 0.02 && sg < 0.98)) return 0;
    for (int k = 0; k < 3; k++) {
        x[k] = p0[k] + tl * e[k];
        gap[k] = u[k] + sg * s[k] - x[k];
    }
    return dot3(gap, gap) < h * h;
}

/* Triangle t's corners with vertex v read as w, as points, into p; 0 when
 * two of them are then one vertex (the triangle goes). */
int crease_corners_as(const crease_mesh *c, int32_t t, int32_t v, int32_t w, int32_t tv[3],
                      double p[3][3])
{
    for (int k = 0; k < 3; k++) {
        tv[k] = c->m->t[3 * (size_t)t + k];
        if (tv[k] == v) tv[k] = w;
    }
    if (tv[0] == tv[1] || tv[1] == tv[2] || tv[2] == tv[0]) return 0;
    for (int k = 0; k < 3; k++)
        mesh_vertex_at(c->m, tv[k], p[k]);
    return 1;
}

/* Whether triangle t, its corners tv at p, lies within `cells` of a plane
 * of pl (np) its corners share, with area, facing like it. */
static int fits_within(const crease_mesh *c, const int32_t tv[3], double p[3][3],
                       const plane *const *pl, int np, double cells)
{
    unsigned s = near_planes(c, tv[0], pl, np, cells) & near_planes(c, tv[1], pl, np, cells) &
                 near_planes(c, tv[2], pl, np, cells);
    return s && crease_half_ok(pl, s, p[0], p[1], p[2], NULL, c->min2);
}

/* Whether triangle t, its corners tv at p, lies on a plane of pl (np)
 * its corners share, with area, facing like it. */
int crease_fits(const crease_mesh *c, const int32_t tv[3], double p[3][3], const plane *const *pl,
                int np)
{
    return fits_within(c, tv, p, pl, np, ON);
}

/* Move vertex v to `to` where that leaves no more of its triangles that
 * misfit their planes pl (np) than before, none that fit now misfitting
 * and every one with area; 1 when moved. */
static int move_fits(crease_mesh *c, int32_t v, const double to[3], const plane *const *pl, int np)
{
    enum { MAX_FAN = 64 };
    int nf = c->start[v + 1] - c->start[v], before = 0, after = 0, lost = 0;
    uint8_t was[MAX_FAN];
    if (nf > MAX_FAN) return 0;
    double old[3];
    for (int i = 0; i < nf; i++) {
        int32_t tv[3];
        double p[3][3];
        crease_corners_as(c, c->fan[c->start[v] + i], v, v, tv, p);
        was[i] = (uint8_t)crease_fits(c, tv, p, pl, np);
        before += !was[i];
    }
    mesh_vertex_at(c->m, v, old);
    float *pv = &c->m->v[3 * (size_t)v];
    for (int k = 0; k < 3; k++)
        pv[k] = (float)to[k];
    for (int i = 0; i < nf && !lost; i++) {
        int32_t tv[3];
        double p[3][3], n[3];
        crease_corners_as(c, c->fan[c->start[v] + i], v, v, tv, p);
        tri_normal3(p[0], p[1], p[2], n);
        int is = crease_fits(c, tv, p, pl, np);
        lost = !(dot3(n, n) > c->min2) || (was[i] && !is);
        after += !is;
    }
    if (!lost && after <= before) return 1;
    for (int k = 0; k < 3; k++)
        pv[k] = (float)old[k];
    return 0;
}

/* Move vertex v, whose triangles lie over two or three plane faces, not
 * all through v, onto the line or point where those meet, where a ray
 * finds it on the surface within half a cell (a contour vertex off a
 * crease, whose chords cut it off), where move_fits allows; 1 when moved,
 * -1 when out of memory. */
static int snap_vertex(crease_mesh *c, int32_t v)
{
    const plane *pl[MAX_PLANES];
    int np = crease_candidates(c, &v, 1, pl);
    if (np < 2 || np > 3 || crease_on_planes(c, v, pl, np) == (1u << np) - 1) return 0;
    double x[3], to[3], d[3];
    mesh_vertex_at(c->m, v, x);
    if (np == 3) {
        if (!crease_corner(pl[0], pl[1], pl[2], to)) return 0;
    } else if (!crease_nearest(pl[0], pl[1], x, to)) {
        return 0;
    }
    sub3(to, x, d);
    if (!(dot3(d, d) < 0.25 * c->h * c->h) || !crease_meets_on_surface(c, to, pl, np)) return 0;
    mesh_round_to_float(to);
    if (to[0] == (float)x[0] && to[1] == (float)x[1] && to[2] == (float)x[2])
        return 0; /* there already, to float precision: a "move" would only block its
                     neighbours this pass, and every pass */
    int32_t *slot = crease_place(c, to);
    if (!slot) return -1;
    if (*slot >= 0) return 0;
    if (!move_fits(c, v, to, pl, np)) return 0;
    int32_t *old = crease_place(c, x);
    if (!old || !(slot = crease_place(c, to))) return -1; /* (the map may have grown) */
    if (*old == v) *old = -1;
    *slot = v;
    for (int32_t f = c->start[v]; f < c->start[v + 1]; f++)
        c->used[c->fan[f]] = 1;
    return 1;
}

/* The quad of half-edge x: its triangle t = (vs[0], vs[1], vs[2]), x from
 * corner k, and the triangle o across, (vs[1], vs[0], vs[3]), its twin
 * from corner j; 0 when x has no twin or the two triangles share all three
 * corners. */
static int quad_at(const crease_mesh *c, int32_t x, int32_t vs[4], int32_t *t, int32_t *o, int *k,
                   int *j)
{
    int32_t y = c->opp[x];
    if (y < 0 || x / 3 == y / 3) return 0;
    const int32_t *tv = c->m->t;
    *t = x / 3, *o = y / 3, *k = x % 3, *j = y % 3;
    vs[0] = tv[3 * (size_t)*t + *k];
    vs[1] = tv[3 * (size_t)*t + (*k + 1) % 3];
    vs[2] = tv[3 * (size_t)*t + (*k + 2) % 3];
    vs[3] = tv[3 * (size_t)*o + (*j + 2) % 3];
    return vs[2] != vs[3];
}

/* An edge whose ends share no plane: its quad (quad_at), the planes
 * under the triangles about its ends, and which of them each corner of the
 * quad lies on. */
typedef struct chord {
    int32_t vs[4], t, o;
    int k, j;
    const plane *pl[MAX_PLANES];
    int np;
    unsigned s[4];
} chord;

/* The chord of half-edge x, its triangles unchanged this pass, into q; 0
 * when x is none. */
static int chord_at(crease_mesh *c, int32_t x, chord *q)
{
    if (!quad_at(c, x, q->vs, &q->t, &q->o, &q->k, &q->j) || c->used[q->t] || c->used[q->o])
        return 0;
    q->np = crease_candidates(c, q->vs, 2, q->pl);
    for (int i = 0; i < 4; i++)
        q->s[i] = q->np < 2 ? 0 : crease_on_planes(c, q->vs[i], q->pl, q->np);
    return q->s[0] && q->s[1] && !(q->s[0] & q->s[1]);
}

/* Whether triangle t has corner v. */
int crease_has(const mesh *m, int32_t t, int32_t v)
{
    const int32_t *tv = &m->t[3 * (size_t)t];
    return tv[0] == v || tv[1] == v || tv[2] == v;
}

/* Whether vertices a and b share an edge (a's triangles, as the pass
 * began). */
static int joined(const crease_mesh *c, int32_t a, int32_t b)
{
    for (int32_t f = c->start[a]; f < c->start[a + 1]; f++)
        if (crease_has(c->m, c->fan[f], b)) return 1;
    return 0;
}

/* How many of the triangles around v and w would misfit (not fit) were v
 * read as w (gone1 and gone2, and those of an edge v–w, go), and how many
 * do now (*before); -1 when one that fits now would not, or one would have
 * no area.  One that fits within NEAR cells counts as fitting for that: a
 * contour vertex a hair off a crease (0.002 cells, hull_extrusions.scad's
 * cylinder rim under a hull's slope) misfits every triangle it is on, and
 * merged into the knot's far end, 0.5 cells away, it took a strip of the
 * face off the mesh (17 tolerances). */
static int misfits_after(const crease_mesh *c, int32_t v, int32_t w, int32_t gone1, int32_t gone2,
                         int *before)
{
    const plane *pl[MAX_PLANES];
    int32_t ends[2] = {v, w};
    int np = crease_candidates(c, ends, 2, pl), bad = 0;
    *before = 0;
    for (int e = 0; e < 2; e++)
        for (int32_t f = c->start[ends[e]]; f < c->start[ends[e] + 1]; f++) {
            int32_t t = c->fan[f], tv[3], tw[3];
            double p[3][3], q[3][3], n[3];
            if (e == 1 && crease_has(c->m, t, v)) continue; /* seen from v */
            crease_corners_as(c, t, v, v, tv, p);
            int was = crease_fits(c, tv, p, pl, np);
            *before += !was;
            was = was || fits_within(c, tv, p, pl, np, NEAR);
            if (t == gone1 || t == gone2 || !crease_corners_as(c, t, v, w, tw, q))
                continue; /* it goes */
            tri_normal3(q[0], q[1], q[2], n);
            int is = crease_fits(c, tw, q, pl, np);
            if (!(dot3(n, n) > c->min2) || (was && !is)) return -1;
            bad += !is;
        }
    return bad;
}

/* Whether merging vertex v into w takes nothing off the surface: v lies
 * within TIE cells of the triangles about it then (gone1, gone2 and the
 * edge's go).  A merge that mends no misfit may still untie a knot (the
 * oblique box's last two, 24 -> 16 triangles); it may not take a vertex
 * off a curved part or a sharp edge (hull_extrusions.scad's cone rims, 2 D
 * more at 0.1 cells). */
static int stays(const crease_mesh *c, int32_t v, int32_t w, int32_t gone1, int32_t gone2)
{
    double pv[3], best = INFINITY;
    mesh_vertex_at(c->m, v, pv);
    for (int32_t f = c->start[v]; f < c->start[v + 1]; f++) {
        int32_t t = c->fan[f], tv[3];
        double p[3][3];
        if (t == gone1 || t == gone2 || !crease_corners_as(c, t, v, w, tv, p)) continue;
        best = fmin(best, geom_triangle_dist2(pv, p[0], p[1], p[2]));
    }
    return best <= TIE * TIE * c->h * c->h;
}

/* Merge vertices v and w (an edge's ends, or gone1 and gone2's far
 * corners) into whichever leaves fewer misfits about them, where fewer
 * misfit than before (or as many, where the merged vertex stays on the
 * surface: stays) and none that fits would not (misfits_after):
 * triangles left without area (the edge's two) and gone1, gone2 are
 * emptied (compacted after the pass).  1 when merged, 0 when not, -1 when
 * out of memory. */
static int merge_ends(crease_mesh *c, int32_t v, int32_t w, int32_t gone1, int32_t gone2)
{
    int before, into_w = misfits_after(c, v, w, gone1, gone2, &before),
                into_v = misfits_after(c, w, v, gone1, gone2, &before);
    if (into_w < 0) into_w = INT32_MAX;
    if (into_v < 0) into_v = INT32_MAX;
    int32_t from = into_w <= into_v ? v : w, to = from == v ? w : v, ends[2] = {v, w};
    int after = from == v ? into_w : into_v;
    if (after > before || (after == before && !stays(c, from, to, gone1, gone2))) return 0;
    if (crease_leave_place(c, from) != 0) return -1;
    for (int e = 0; e < 2; e++)
        for (int32_t f = c->start[ends[e]]; f < c->start[ends[e] + 1]; f++) {
            int32_t t = c->fan[f], *tv = &c->m->t[3 * (size_t)t];
            for (int k = 0; k < 3; k++)
                if (tv[k] == from) tv[k] = to;
            if (t == gone1 || t == gone2 || tv[0] == tv[1] || tv[1] == tv[2] || tv[2] == tv[0])
                tv[0] = tv[1] = tv[2] = -1;
            c->used[t] = 1;
        }
    c->gone = 1;
    return 1;
}

/* Whether vertices a and b lie within KNOT cells of each other, their
 * triangles unchanged this pass, and share no neighbour but p and q (else
 * merging them would pinch the mesh). */
static int mergeable(const crease_mesh *c, int32_t a, int32_t b, int32_t p, int32_t q)
{
    double pa[3], pb[3], d[3];
    mesh_vertex_at(c->m, a, pa);
    mesh_vertex_at(c->m, b, pb);
    sub3(pb, pa, d);
    if (!(dot3(d, d) < KNOT * KNOT * c->h * c->h)) return 0;
    int32_t ends[2] = {a, b};
    for (int e = 0; e < 2; e++)
        for (int32_t f = c->start[ends[e]]; f < c->start[ends[e] + 1]; f++)
            if (c->used[c->fan[f]]) return 0;
    for (int32_t f = c->start[a]; f < c->start[a + 1]; f++)
        for (int k = 0; k < 3; k++) {
            int32_t n = c->m->t[3 * (size_t)c->fan[f] + k];
            if (n != a && n != b && n != p && n != q && joined(c, b, n)) return 0;
        }
    return 1;
}

/* Collapse the edge of half-edge x, shorter than half a cell, one of
 * whose ends and every other corner of whose ends' triangles lie on plane
 * faces (not on curved ones, where a triangle lies on no plane anyway), into
 * whichever end leaves fewer triangles about it that misfit (lie on no
 * plane their corners share, or face against it: a knot of vertices the
 * contour left about a crease, its triangles folded back on the face),
 * where there are fewer than before, none that fits now would not, every
 * triangle keeps some area, and the ends share no neighbour but the two
 * opposite corners (else the mesh would pinch).  The
 * two triangles of the edge become empty (compacted after the pass).  1
 * when collapsed, 0 when not, -1 when out of memory. */
static int collapse_knot(crease_mesh *c, int32_t x)
{
    int32_t vs[4], t, o;
    int k, j;
    if (!quad_at(c, x, vs, &t, &o, &k, &j)) return 0;
    mesh *m = c->m;
    int32_t v = vs[0], w = vs[1], ends[2] = {v, w};
    if (!mergeable(c, v, w, vs[2], vs[3]) || (!crease_on_a_plane(c, v) && !crease_on_a_plane(c, w)))
        return 0;
    for (int e = 0; e < 2; e++)
        for (int32_t f = c->start[ends[e]]; f < c->start[ends[e] + 1]; f++)
            for (int q = 0; q < 3; q++) {
                int32_t n = m->t[3 * (size_t)c->fan[f] + q];
                if (n != v && n != w && !crease_on_a_plane(c, n)) return 0;
            }
    return merge_ends(c, v, w, -1, -1);
}

/* Drop the triangles merge_ends emptied (their planes with them). */
static void compact(crease_mesh *c)
{
    mesh *m = c->m;
    int32_t n = 0;
    for (int32_t t = 0; t < m->nt; t++) {
        if (m->t[3 * (size_t)t] < 0) continue;
        memmove(&m->t[3 * (size_t)n], &m->t[3 * (size_t)t], 3 * sizeof *m->t);
        if (m->tc && m->npal) m->tc[n] = m->tc[t];
        c->tp[n] = c->tp[t];
        n++;
    }
    m->nt = n;
}

/* Merge the two far corners of chord q, both on the crease its ends' planes
 * meet at but in the wrong order along it (the flip would turn both
 * halves over: a knot the contour crossed), into whichever leaves fewer
 * misfits: the chord's two triangles go.  Where they share no neighbour
 * but the chord's ends, no triangle that fits would misfit, and fewer
 * misfit than before; 1 when merged, else 0, -1 when out of memory. */
static int merge_across(crease_mesh *c, const chord *q)
{
    const int32_t *vs = q->vs;
    int32_t a = vs[2], b = vs[3];
    if (joined(c, a, b) || !mergeable(c, a, b, vs[0], vs[1])) return 0;
    return merge_ends(c, a, b, q->t, q->o);
}

/* Flip the edge of half-edge x (triangle t = (u, w, c), its twin in o =
 * (w, u, d)), whose ends share no plane, to c–d where then (c, u, d) and
 * (d, w, c) each lie on a plane, facing like it: the chord's quad has its
 * other diagonal on the crease; where both would face against their
 * planes, merge_across.  1 when flipped (or merged), 0 when not, -1 when
 * out of memory. */
static int flip_edge(crease_mesh *c, int32_t x)
{
    chord q;
    if (!chord_at(c, x, &q)) return 0;
    const int32_t *vs = q.vs;
    const unsigned *s = q.s;
    const plane *const *pl = q.pl;
    int32_t t = q.t, o = q.o;
    mesh *m = c->m;
    if (!(s[2] & s[0] & s[3]) || !(s[3] & s[1] & s[2]) || (c->ends[vs[2]] && c->ends[vs[3]]) ||
        joined(c, vs[2], vs[3]))
        return 0;
    double p[4][3];
    for (int i = 0; i < 4; i++)
        mesh_vertex_at(m, vs[i], p[i]);
    int up = crease_half_ok(pl, s[2] & s[0] & s[3], p[2], p[0], p[3], NULL, c->min2),
        down = crease_half_ok(pl, s[3] & s[1] & s[2], p[3], p[1], p[2], NULL, c->min2);
    if (!up && !down) return merge_across(c, &q); /* c, d both on the crease */
    if (!up || !down) return 0;
    int32_t *tv = &m->t[3 * (size_t)t], *ov = &m->t[3 * (size_t)o];
    tv[0] = vs[2], tv[1] = vs[0], tv[2] = vs[3];
    ov[0] = vs[3], ov[1] = vs[1], ov[2] = vs[2];
    c->used[t] = c->used[o] = 1;
    c->ends[vs[2]] = c->ends[vs[3]] = 1; /* (the fans do not show c–d) */
    return 1;
}

/* Split the edge of half-edge x (triangle t = (u, w, c), its twin in o =
 * (w, u, d)) on the crease its ends' planes meet at; 1 when split, 0 when
 * not, -1 when out of memory. */
static int split_edge(crease_mesh *c, int32_t x)
{
    chord q;
    if (!chord_at(c, x, &q)) return 0;
    const int32_t *vs = q.vs;
    const plane *const *pl = q.pl;
    int32_t t = q.t, o = q.o;
    int k = q.k, j = q.j, np = q.np;
    unsigned su = q.s[0], sw = q.s[1], sc = q.s[2], sd = q.s[3];
    mesh *m = c->m;
    double u[3], w[3], pc[3], pd[3], tn[3], on[3];
    mesh_vertex_at(m, vs[0], u);
    mesh_vertex_at(m, vs[1], w);
    mesh_vertex_at(m, vs[2], pc);
    mesh_vertex_at(m, vs[3], pd);
    tri_normal3(u, w, pc, tn);
    tri_normal3(w, u, pd, on);
    for (int a = 0; a < np; a++)
        for (int b = 0; b < np; b++) {
            double xp[3];
            const plane *two[2] = {pl[a], pl[b]};
            if (!(su >> a & 1) || !(sw >> b & 1) || !crease_point(pl[a], pl[b], u, w, c->h, xp) ||
                !crease_meets_on_surface(c, xp, two, 2))
                continue;
            mesh_round_to_float(xp); /* as the mesh will hold it */
            unsigned sx = 1u << a | 1u << b;
            if (!crease_half_ok(pl, su & sx & sc, u, xp, pc, tn, c->min2) ||
                !crease_half_ok(pl, sx & sw & sc, xp, w, pc, tn, c->min2) ||
                !crease_half_ok(pl, sw & sx & sd, w, xp, pd, on, c->min2) ||
                !crease_half_ok(pl, sx & su & sd, xp, u, pd, on, c->min2))
                continue;
            int32_t v = crease_add_vertex(c, xp);
            if (v == -2) return -1;
            if (v < 0) continue;
            uint16_t ct = m->tc && m->npal ? m->tc[t] : 0, co = m->tc && m->npal ? m->tc[o] : 0;
            m->t[3 * (size_t)t + (k + 1) % 3] = v; /* (u, v, c) */
            m->t[3 * (size_t)o + (j + 1) % 3] = v; /* (w, v, d) */
            if (mesh_push_triangle(m, v, vs[1], vs[2], ct) < 0 ||
                mesh_push_triangle(m, v, vs[0], vs[3], co) < 0)
                return -1;
            c->used[t] = c->used[o] = 1;
            return 1;
        }
    return 0;
}

/* Give triangle t, whose corners share no plane and lie on three, the
 * point where those meet as a new corner; 1 when split, 0 when not, -1
 * when out of memory. */
static int split_corner(crease_mesh *c, int32_t t)
{
    if (c->used[t]) return 0;
    mesh *m = c->m;
    int32_t vs[3];
    memcpy(vs, &m->t[3 * (size_t)t], sizeof vs);
    const plane *pl[MAX_PLANES];
    int np = crease_candidates(c, vs, 3, pl);
    unsigned s0 = crease_on_planes(c, vs[0], pl, np), s1 = crease_on_planes(c, vs[1], pl, np),
             s2 = crease_on_planes(c, vs[2], pl, np), all = s0 | s1 | s2;
    if (!s0 || !s1 || !s2 || (s0 & s1 & s2)) return 0;
    const plane *three[3];
    int n3 = 0;
    for (int i = 0; i < np; i++)
        if (all >> i & 1) {
            if (n3 == 3) return 0;
            three[n3++] = pl[i];
        }
    if (n3 != 3) return 0;
    double x[3], mean[3], p[3][3], g[3];
    if (!crease_corner(three[0], three[1], three[2], x)) return 0;
    for (int i = 0; i < 3; i++)
        mean[i] = three[0]->n[i] + three[1]->n[i] + three[2]->n[i];
    for (int q = 0; q < 3; q++)
        mesh_vertex_at(m, vs[q], p[q]);
    for (int i = 0; i < 3; i++)
        g[i] = (p[0][i] + p[1][i] + p[2][i]) / 3 - x[i];
    if (!(dot3(g, g) < 4 * c->h * c->h) || !crease_meets_on_surface(c, x, three, 3)) return 0;
    mesh_round_to_float(x);
    unsigned sv[3] = {s0, s1, s2};
    for (int q = 0; q < 3; q++)
        if (!crease_half_ok(pl, sv[q] & sv[(q + 1) % 3], p[q], p[(q + 1) % 3], x, mean, c->min2))
            return 0;
    int32_t v = crease_add_vertex(c, x);
    if (v == -2) return -1;
    if (v < 0) return 0;
    uint16_t ct = m->tc && m->npal ? m->tc[t] : 0;
    m->t[3 * (size_t)t + 2] = v; /* (a, b, x) */
    if (mesh_push_triangle(m, vs[1], vs[2], v, ct) < 0 ||
        mesh_push_triangle(m, vs[2], vs[0], v, ct) < 0)
        return -1;
    c->used[t] = 1;
    return 1;
}

enum { KNOT_VERTS = 48, KNOT_TRIS = 192 };

static int in_list(const int32_t *a, int n, int32_t x)
{
    for (int i = 0; i < n; i++)
        if (a[i] == x) return 1;
    return 0;
}

/* The planes of bits s of pl that the corners of fan triangle ft (-1: x,
 * on the planes sx) share. */
static unsigned fan_shared(crease_mesh *c, const int32_t ft[3], unsigned sx, const plane *const *pl,
                           int np)
{
    unsigned s = ~0u;
    for (int k = 0; k < 3; k++)
        s &= ft[k] < 0 ? sx : crease_on_planes(c, ft[k], pl, np);
    return s;
}

/* The triangles of a fan from x (on the planes sx) to the rim edges from[i]
 * -> to[i] into ft, rim edge i's first (-1 standing for x): whether each
 * lies on a plane its corners share, faces like it and lies on the surface
 * (rays along its normal through its centroid, halfway from there to each
 * corner and nine tenths of the way to its last find it there: a notch of
 * the model within the knot would not be covered, and x is no corner of
 * the model unless the faces reach it — a ray through x itself can only
 * touch the solid at an overhanging corner, a twisted extrusion's top
 * corner where four planes meet).  A rim edge that runs along a crease out
 * of x (x and its ends on two planes: one line) would make a needle; the
 * edge from x to the farther end is flipped with the fan triangle beyond
 * it instead: (a, b, x) and (b, q, x) become (a, b, q) and (a, q, x). */
static int fan_triangles(crease_mesh *c, const double x[3], unsigned sx, const plane *const *pl,
                         int np, const int32_t *from, const int32_t *to, int nr, int32_t (*ft)[3])
{
    uint8_t straight[KNOT_TRIS] = {0}, taken[KNOT_TRIS] = {0};
    for (int i = 0; i < nr; i++) {
        ft[i][0] = from[i], ft[i][1] = to[i], ft[i][2] = -1;
        unsigned sh = fan_shared(c, ft[i], sx, pl, np);
        double a[3], b[3];
        mesh_vertex_at(c->m, from[i], a);
        mesh_vertex_at(c->m, to[i], b);
        straight[i] = (sh & (sh - 1)) && !crease_half_ok(pl, sh, a, b, x, NULL, c->min2);
    }
    for (int i = 0; i < nr; i++) {
        if (!straight[i]) continue;
        double a[3], b[3], da[3], db[3];
        mesh_vertex_at(c->m, from[i], a);
        mesh_vertex_at(c->m, to[i], b);
        sub3(a, x, da);
        sub3(b, x, db);
        if (!(dot3(da, db) > 0)) return 0; /* x between them */
        int near_a = dot3(da, da) < dot3(db, db), j = 0;
        while (j < nr && (near_a ? from[j] != to[i] : to[j] != from[i]))
            j++;
        if (j == nr || straight[j] || taken[j]) return 0;
        /* the new edge, a–q or p–b, may not be one the mesh has */
        if (near_a ? joined(c, from[i], to[j]) : joined(c, from[j], to[i])) return 0;
        taken[j] = 1;
        if (near_a) { /* (b, q, x) beyond */
            int32_t q = to[j];
            ft[i][0] = from[i], ft[i][1] = to[i], ft[i][2] = q;
            ft[j][0] = from[i], ft[j][1] = q, ft[j][2] = -1;
        } else { /* (p, a, x) before */
            int32_t p = from[j];
            ft[i][0] = p, ft[i][1] = from[i], ft[i][2] = to[i];
            ft[j][0] = p, ft[j][1] = to[i], ft[j][2] = -1;
        }
    }
    for (int i = 0; i < nr; i++) {
        double p[3][3];
        for (int k = 0; k < 3; k++)
            if (ft[i][k] < 0)
                memcpy(p[k], x, sizeof p[k]);
            else
                mesh_vertex_at(c->m, ft[i][k], p[k]);
        unsigned sh = fan_shared(c, ft[i], sx, pl, np);
        if (!sh || !crease_half_ok(pl, sh, p[0], p[1], p[2], NULL, c->min2) ||
            !crease_lies_on_surface(c, p))
            return 0;
    }
    return 1;
}

/* Replace the knot about corner x (the vertices within KNOT_R cells of it
 * that v reaches through them) by a fan from x to the rim of their
 * triangles, where the rim is one loop, some triangle of the knot misfits
 * and the fan passes fan_triangles; 1 when done, 0 when not, -1 when out
 * of memory.  Every vertex of the knot gets x as its last corner tried
 * (c->tried). */
static int fan_knot(crease_mesh *c, int32_t v, const double x[3])
{
    mesh *m = c->m;
    int32_t kv[KNOT_VERTS], kt[KNOT_TRIS];
    int nkv = 0, nkt = 0;
    uint32_t mk = ++c->mark_now; /* kv's and kt's members marked so */
    kv[nkv++] = v;
    c->vmark[v] = mk;
    int whole = 1; /* the knot: breadth first through near vertices */
    for (int i = 0; i < nkv && whole; i++)
        for (int32_t f = c->start[kv[i]]; f < c->start[kv[i] + 1] && whole; f++) {
            int32_t t = c->fan[f];
            if (c->used[t] || m->t[3 * (size_t)t] < 0) {
                whole = 0; /* changed this pass */
                break;
            }
            if (c->tmark[t] != mk && nkt == KNOT_TRIS) {
                whole = -1; /* too big */
                break;
            }
            if (c->tmark[t] != mk) {
                kt[nkt++] = t;
                c->tmark[t] = mk;
            }
            for (int k = 0; k < 3 && whole; k++) {
                int32_t w = m->t[3 * (size_t)t + k];
                double p[3], d[3];
                if (c->vmark[w] == mk) continue;
                mesh_vertex_at(m, w, p);
                sub3(p, x, d);
                if (!(dot3(d, d) < KNOT_R * KNOT_R * c->h * c->h)) continue;
                if (nkv == KNOT_VERTS)
                    whole = -1;
                else {
                    kv[nkv++] = w;
                    c->vmark[w] = mk;
                }
            }
        }
    /* whichever of its vertices finds the knot, it is the same: it is not
     * tried at x again from any of them this pass */
    uint64_t key = mesh_pos_key(x);
    for (int i = 0; i < nkv; i++)
        c->tried[kv[i]] = key;
    if (whole < 0) { /* nor from any other vertex near x: the crowd there is too big */
        int fresh;
        if (!mesh_fmap_slot(&c->crowded, key, &fresh)) return -1;
    }
    if (whole != 1) return 0;
    /* the rim: the knot's half-edges whose twins are not the knot's */
    int32_t from[KNOT_TRIS], to[KNOT_TRIS], rt[KNOT_TRIS];
    int nr = 0;
    for (int i = 0; i < nkt; i++) {
        const int32_t *tv = &m->t[3 * (size_t)kt[i]];
        for (int k = 0; k < 3; k++) {
            int32_t y = c->opp[3 * kt[i] + k];
            if (y < 0) return 0;
            if (c->tmark[y / 3] == mk) continue;
            if (nr == KNOT_TRIS) return 0;
            from[nr] = tv[k];
            to[nr] = tv[(k + 1) % 3];
            rt[nr++] = kt[i];
        }
    }
    /* one loop through distinct vertices, and the knot a disc (V - E + F
     * = 1 with the rim's vertices) */
    if (nr < 3 || nkv + nr - (3 * nkt + nr) / 2 + nkt != 1) return 0;
    for (int i = 0; i < nr; i++)
        for (int j = i + 1; j < nr; j++)
            if (from[i] == from[j]) return 0;
    const plane *pl[KNOT_PLANES]; /* the planes under its triangles */
    int np = candidates_max(c, kv, nkv, pl, KNOT_PLANES), misfit = 0;
    for (int i = 0; i < nkt && !misfit; i++) {
        int32_t tv[3];
        double p[3][3];
        crease_corners_as(c, kt[i], -1, -1, tv, p);
        misfit = !crease_fits(c, tv, p, pl, np);
    }
    if (!misfit) return 0;
    int32_t centre = -1, *slot = crease_place(c, x);
    if (!slot) return -1;
    if (*slot >= 0) {
        if (*slot >= c->nv0 || c->vmark[*slot] != mk) return 0;
        centre = *slot; /* the corner is a vertex of the knot already: it stays */
    }
    unsigned sx = crease_planes_near(c, x, pl, np, ON);
    int32_t ft[KNOT_TRIS][3]; /* the new triangles, -1 for the centre */
    if (!fan_triangles(c, x, sx, pl, np, from, to, nr, ft)) return 0;
    if (centre < 0 && (centre = crease_add_vertex(c, x)) < 0) return centre == -2 ? -1 : 0;
    for (int i = 0; i < nkv; i++)
        if (kv[i] != centre && crease_leave_place(c, kv[i]) != 0) return -1;
    for (int i = 0; i < nr; i++) {
        uint16_t col = m->tc && m->npal ? m->tc[rt[i]] : 0;
        int32_t tv3[3];
        for (int k = 0; k < 3; k++)
            tv3[k] = ft[i][k] < 0 ? centre : ft[i][k];
        if (i < nkt) {
            memcpy(&m->t[3 * (size_t)kt[i]], tv3, sizeof tv3);
            if (m->tc && m->npal) m->tc[kt[i]] = col;
        } else if (mesh_push_triangle(m, tv3[0], tv3[1], tv3[2], col) < 0) {
            return -1;
        }
    }
    for (int i = 0; i < nkt; i++) {
        c->used[kt[i]] = 1;
        if (i >= nr) {
            m->t[3 * (size_t)kt[i]] = m->t[3 * (size_t)kt[i] + 1] = m->t[3 * (size_t)kt[i] + 2] =
                -1;
            c->gone = 1;
        }
    }
    return 1;
}

/* A knot of vertices the contour left about a corner where three plane
 * faces meet (a twisted extrusion's acute top corners: 40 vertices within
 * four cells), fanned from the corner (fan_knot): the points where three
 * of the planes under the triangles about v and its neighbours meet,
 * within KNOT_R cells of v and on the surface, each tried in turn; where
 * none is, a knot along a crease of two (vertices of either plane carried
 * past it: twist_ties' side facets), fanned from the crease's point nearest
 * v.  1 when done, 0 when not, -1 when out of memory. */
static int untie_corner(crease_mesh *c, int32_t v)
{
    mesh *m = c->m;
    int32_t ring[64];
    int n = 0;
    ring[n++] = v;
    for (int32_t f = c->start[v]; f < c->start[v + 1]; f++) {
        if (c->used[c->fan[f]]) return 0; /* changed this pass */
        for (int k = 0; k < 3; k++) {
            int32_t w = m->t[3 * (size_t)c->fan[f] + k];
            if (n < 64 && !in_list(ring, n, w)) ring[n++] = w;
        }
    }
    const plane *pl[MAX_PLANES];
    int np = crease_candidates(c, ring, n, pl), misfit = 0;
    if (np < 2) return 0;
    for (int32_t f = c->start[v]; f < c->start[v + 1] && !misfit; f++) {
        int32_t tv[3];
        double q[3][3];
        crease_corners_as(c, c->fan[f], -1, -1, tv, q);
        misfit = !crease_fits(c, tv, q, pl, np);
    }
    if (!misfit) return 0;
    double p[3], tried[16][3];
    int ntried = 0, near = 0;
    mesh_vertex_at(m, v, p);
    /* a corner within KNOT_R cells is at least as near each of its planes */
    for (int i = 0; i < np; i++)
        if (fabs(dot3(pl[i]->n, p) - pl[i]->d) < KNOT_R * c->h) pl[near++] = pl[i];
    np = near;
    for (int i = 0; i < np; i++)
        for (int j = i + 1; j < np; j++)
            for (int k = j + 1; k < np; k++) {
                double x[3], d[3];
                if (!crease_corner(pl[i], pl[j], pl[k], x)) continue;
                sub3(x, p, d);
                mesh_round_to_float(x);
                if (!(dot3(d, d) < KNOT_R * KNOT_R * c->h * c->h)) continue;
                /* a corner of more than three planes is found by more than
                 * one triple: not tried again where its knot was refused
                 * (tried), nor right after any try of it (c->tried: the
                 * last corner v's knot was tried at), nor where the crowd
                 * about it was too big */
                int seen = 0;
                for (int q = 0; q < ntried && !seen; q++)
                    seen = tried[q][0] == x[0] && tried[q][1] == x[1] && tried[q][2] == x[2];
                uint64_t key = mesh_pos_key(x);
                if (seen || c->tried[v] == key || mesh_fmap_has(&c->crowded, key)) continue;
                int r = fan_knot(c, v, x);
                if (r != 0) return r;
                if (ntried < 16) memcpy(tried[ntried++], x, sizeof x);
            }
    /* no corner: a knot along a crease, fanned from the point of the crease
     * nearest v (the fan's rim runs along the crease on both sides), the
     * crease of two planes some triangles about v lie on */
    unsigned under = 0;
    for (int32_t f = c->start[v]; f < c->start[v + 1]; f++) {
        const int32_t *tv = &m->t[3 * (size_t)c->fan[f]];
        under |= crease_on_planes(c, tv[0], pl, np) & crease_on_planes(c, tv[1], pl, np) &
                 crease_on_planes(c, tv[2], pl, np);
    }
    for (int i = 0; i < np; i++)
        for (int j = i + 1; j < np; j++) {
            double x[3], d[3];
            if (!(under >> i & under >> j & 1) || !crease_nearest(pl[i], pl[j], p, x)) continue;
            sub3(x, p, d);
            mesh_round_to_float(x);
            uint64_t key = mesh_pos_key(x);
            if (!(dot3(d, d) < KNOT * KNOT * c->h * c->h) || mesh_fmap_has(&c->crowded, key))
                continue;
            int r = fan_knot(c, v, x);
            if (r != 0) return r;
        }
    return 0;
}

/* Grow *a (*cap entries of size `size`) to n at least, the new entries
 * filled with byte `fill`; 0 or -1. */
static int grow_to(void **a, size_t *cap, size_t n, size_t size, int fill)
{
    if (n <= *cap) return 0;
    size_t c = *cap ? *cap : 1024;
    while (c < n)
        c *= 2;
    void *g = realloc(*a, c * size);
    if (!g) return -1;
    memset((char *)g + *cap * size, fill, (c - *cap) * size);
    *a = g;
    *cap = c;
    return 0;
}

/* Whether vertex v is hot (one added this pass is). */
static int is_hot(const crease_mesh *c, int32_t v)
{
    return (size_t)v >= c->hot_cap || c->hot[v];
}

/* Whether vertex v's knot was refused in an earlier pass and none of its
 * triangles has changed since (c->hot REFUSED: still hot for the other
 * rules).  A failed knot fails again: the first knot passes of a corpus
 * file tried 160,000 crease points each, to fan a few knots a pass. */
static int knot_refused(const crease_mesh *c, int32_t v)
{
    return (size_t)v < c->hot_cap && c->hot[v] == REFUSED;
}

/* Whether triangle t has a hot corner. */
static int hot_triangle(const crease_mesh *c, int32_t t)
{
    const int32_t *tv = &c->m->t[3 * (size_t)t];
    return is_hot(c, tv[0]) || is_hot(c, tv[1]) || is_hot(c, tv[2]);
}

/* Keep hot only the vertices of edges whose triangles bend by more than
 * half the slightest crease looked at (a chord across it bends at least
 * so), or that have no area or twin.  0 or -1. */
static int mark_bent(crease_mesh *c, size_t nt)
{
    mesh *m = c->m;
    uint8_t *bent = calloc((size_t)m->nv, 1);
    double(*n)[3] = malloc(nt * sizeof *n);
    if (!bent || !n) {
        free(bent);
        free(n);
        return -1;
    }
    for (size_t t = 0; t < nt; t++) {
        double p[3][3];
        for (int k = 0; k < 3; k++)
            mesh_vertex_at(m, m->t[3 * t + k], p[k]);
        tri_normal3(p[0], p[1], p[2], n[t]);
    }
    for (size_t x = 0; x < 3 * nt; x++) {
        int32_t y = c->opp[x];
        const double *a = n[x / 3], *b = y >= 0 ? n[y / 3] : a;
        double la = dot3(a, a), lb = dot3(b, b);
        if (y >= 0 && la > 0 && lb > 0 && dot3(a, b) >= COS_BENT * sqrt(la * lb)) continue;
        bent[m->t[x]] = bent[m->t[x / 3 * 3 + (x + 1) % 3]] = 1;
    }
    for (int32_t v = 0; v < m->nv && (size_t)v < c->hot_cap; v++)
        if (!bent[v]) c->hot[v] = 0;
    free(bent);
    free(n);
    return 0;
}

/* The rules' scale, c->h, to the spacing of the grid that sampled the
 * part vertex v lies in (a model's far-apart parts have grids of their own,
 * sized to each). */
static void scale_at(crease_mesh *c, int32_t v)
{
    double p[3];
    mesh_vertex_at(c->m, v, p);
    c->h = mesh_dexels_h_at(c->sn->d, p);
    c->min2 = 1e-10 * c->h * c->h * c->h * c->h;
}

/* Apply op to each of the first nt triangles that has a hot corner and has
 * not been emptied this pass, counting its changes in *count; 0, or -1
 * when op ran out of memory. */
static int each_hot_triangle(crease_mesh *c, size_t nt, int (*op)(crease_mesh *, int32_t),
                             int *count)
{
    for (size_t t = 0; t < nt; t++) {
        int hot = c->m->t[3 * t] >= 0 && hot_triangle(c, (int32_t)t);
        if (hot) scale_at(c, c->m->t[3 * t]);
        int r = hot ? op(c, (int32_t)t) : 0;
        if (r < 0) return -1;
        *count += r;
    }
    return 0;
}

/* Apply op to every half-edge of the first nt triangles that has a hot
 * corner and has not been emptied this pass, counting its changes in
 * *split; 0, or -1 when op ran out of memory. */

static int each_hot_edge(crease_mesh *c, size_t nt, int (*op)(crease_mesh *, int32_t), int *split)
{
    for (size_t x = 0; x < 3 * nt; x++) {
        int hot = c->m->t[x] >= 0 && hot_triangle(c, (int32_t)(x / 3));
        if (hot) scale_at(c, c->m->t[x]);
        int r = hot ? op(c, (int32_t)x) : 0;
        if (r < 0) return -1;
        *split += r;
    }
    return 0;
}

/* One pass over what is hot: knots fanned from their corners, and where
 * there were none (the other rules read the fans as the pass began, and a
 * fan's new corner has none), the vertices snapped, knots collapsed,
 * edges flipped and split, then corners; or, with caps_only, caps across
 * acute creases unzipped about every bend; *split counts the changes,
 * *kind is 1 when knots were fanned, 2 for caps, else 0.  The corners of
 * what changed are hot for the next (and after knots or caps, what is hot
 * now).  0 or -1. */
static int pass_once(crease_mesh *c, int caps_only, int *split, int *kind)
{
    mesh *m = c->m;
    size_t nt = (size_t)m->nt, nv = (size_t)m->nv;
    c->opp = malloc(3 * nt * sizeof *c->opp);
    c->used = calloc(nt, 1);
    c->ends = calloc((size_t)m->nv, 1);
    c->known = calloc((size_t)m->nv, 1);
    c->vmark = calloc((size_t)m->nv, sizeof *c->vmark);
    c->tried = calloc((size_t)m->nv, sizeof *c->tried);
    memset(&c->crowded, 0, sizeof c->crowded);
    c->tmark = calloc(nt, sizeof *c->tmark);
    c->mark_now = 0;
    c->nv0 = m->nv;
    c->nknown = 0;
    c->start = c->fan = NULL;
    c->gone = 0;
    int rc = -1;
    if (!c->opp || !c->used || !c->ends || !c->known || !c->vmark || !c->tmark || !c->tried ||
        mesh_half_twins(m, 0, c->opp) != 0 || mesh_vertex_fans(m, 0, &c->start, &c->fan) != 0)
        goto done;
    /* only what is about a bend matters: elsewhere the triangles are flat
     * already, or the faces' creases are slighter than COS_APART (a pass
     * for caps looks at every bend) */
    if (caps_only) memset(c->hot, 1, c->hot_cap);
    if (mark_bent(c, nt) != 0) goto done;
    for (size_t t = 0; t < nt; t++)
        if (c->tp[t] == -2 && hot_triangle(c, (int32_t)t)) {
            scale_at(c, m->t[3 * t]);
            if ((c->tp[t] = face_under(c, (int32_t)t)) == -3) goto done;
        }
    int knots = 0, caps = 0;
    if (caps_only) {
        c->nknown = (size_t)m->nv; /* the vertices stay put */
        if (each_hot_triangle(c, nt, crease_unzip_cap, &caps) != 0) goto done;
        *split += caps;
        *kind = 2;
        goto next;
    }
    for (int32_t v = 0; v < (int32_t)nv; v++) {
        int try = is_hot(c, v) && !knot_refused(c, v);
        if (try) scale_at(c, v);
        int r = try ? untie_corner(c, v) : 0;
        if (r < 0) goto done;
        if (r == 0 && (size_t)v < c->hot_cap && c->hot[v]) c->hot[v] = REFUSED;
        knots += r;
    }
    *split += knots;
    *kind = knots > 0;
    if (knots) goto next; /* the other rules next pass, on the fans as they are then */
    for (int32_t v = 0; v < m->nv; v++) {
        if (is_hot(c, v)) scale_at(c, v);
        int r = is_hot(c, v) ? snap_vertex(c, v) : 0;
        if (r < 0) goto done;
        *split += r;
    }
    c->nknown = (size_t)m->nv; /* the vertices stay put from here */
    if (each_hot_edge(c, nt, collapse_knot, split) != 0 ||
        each_hot_edge(c, nt, flip_edge, split) != 0 || each_hot_edge(c, nt, split_edge, split) != 0)
        goto done;
    if (each_hot_triangle(c, nt, split_corner, split) != 0) goto done;
next:
    /* what is hot next: the corners of what changed, and what was added
     * (and, after knots only, what is hot now) */
    if (grow_to((void **)&c->tp, &c->tp_cap, (size_t)m->nt, sizeof *c->tp, 0xff) != 0 ||
        grow_to((void **)&c->hot, &c->hot_cap, (size_t)m->nv, 1, 0) != 0)
        goto done;
    if (!knots && !caps) memset(c->hot, 0, (size_t)m->nv);
    for (int32_t t = 0; t < m->nt; t++) {
        int32_t *tv = &m->t[3 * (size_t)t];
        if ((size_t)t < nt && !c->used[t]) continue;
        c->tp[t] = -2;
        if (tv[0] >= 0) c->hot[tv[0]] = c->hot[tv[1]] = c->hot[tv[2]] = 1;
    }
    rc = 0;
done:
    if (c->gone) compact(c);
    free(c->opp);
    free(c->used);
    free(c->ends);
    free(c->known);
    free(c->vmark);
    free(c->tried);
    free(c->crowded.key);
    free(c->crowded.val);
    free(c->tmark);
    free(c->start);
    free(c->fan);
    return rc;
}

int mesh_split_creases(mesh *m, mesh_snapper *sn, int *splits)
{
    *splits = 0;
    if (!sn->arena || m->nt == 0) return 0;
    crease_mesh c;
    memset(&c, 0, sizeof c);
    c.m = m;
    c.sn = sn;
    c.h = sn->d->h;
    c.min2 = 1e-10 * c.h * c.h * c.h * c.h;
    int rc = grow_to((void **)&c.hot, &c.hot_cap, (size_t)m->nv, 1, 1) != 0 ||
                     grow_to((void **)&c.tp, &c.tp_cap, (size_t)m->nt, sizeof *c.tp, 0xff) != 0
                 ? -1
                 : 0;
    for (int32_t t = 0; t < m->nt && rc == 0; t++)
        c.tp[t] = -2;
    /* the places of the vertices the triangles use (the simplifier's
     * leftovers are free) */
    for (size_t k = 0; k < 3 * (size_t)m->nt && rc == 0; k++) {
        double p[3];
        mesh_vertex_at(m, m->t[k], p);
        int32_t *slot = crease_place(&c, p);
        if (!slot)
            rc = -1;
        else if (*slot < 0)
            *slot = m->t[k];
    }
    /* PASSES of the rules, and as many more that fan knots; where they
     * change nothing more (or may not), a pass that unzips caps across
     * acute creases (crease_cap.c: the last resort, for what the rules
     * leave), and the rules again after it, PASSES such at most */
    int passes[3] = {0, 0, 0}, caps_next = 0;
    while (rc == 0) {
        int spent = passes[0] >= PASSES || passes[1] >= PASSES, caps_only = caps_next || spent;
        if (caps_only && passes[2] >= PASSES) break;
        int split = 0, kind = 0;
        rc = pass_once(&c, caps_only, &split, &kind);
        *splits += split;
        if (caps_only) {
            passes[2]++;
            if (!split || spent) break;
            caps_next = 0;
        } else if (!split) {
            caps_next = 1;
        } else {
            passes[kind]++;
        }
    }
    free(c.capk);
    free(c.pl);
    free(c.by_patch.key);
    free(c.by_patch.val);
    free(c.tp);
    free(c.hot);
    free(c.pos.key);
    free(c.pos.val);
    return rc;
}
