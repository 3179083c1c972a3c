/*
 * tighten.c — triangles of a simplified mesh's smooth parts that stray from
 * the exact surface by more than the tolerance split until they do not (see
 * dexels.h, mesh_tighten).
 *
 * The simplifier bounds how far the contour's points lie from the
 * triangles that replace them, and mesh_balance halves the sag; between
 * those points the surface can stray further: 2 tolerances on a torus
 * where it turns from convex to saddle, 1 to 2 over a sixteenth of a cone
 * whose tolerance (its cross hole's $fn) is a hundredth of a cell.  So each
 * triangle of a smooth part (bending less than 20° against each neighbour,
 * or lying over one smooth piece of surface: a torus's top triangulated
 * across the way it bends least, a bore's wall beside its rim) is
 * measured at seven points (its centroid, its edges' midpoints, and
 * halfway from the centroid to each corner) by rays along its normal and
 * on rings 30°, 60° and 85° off it (beside a sharp edge the nearest surface
 * is to the side), up to REACH tolerances away.  A triangle with a point
 * farther than the tolerance has its longest edge split at the surface
 * under the edge's midpoint (along the mean normal of its two triangles;
 * where the two lie over different pieces, a rim, on the sharp edge where
 * those meet, found as contour vertices are),
 * each of the two in two, where both halves of both keep some area and
 * turn by less than 60° from the triangle they were, and no vertex is at
 * that place already (two solids touching along an edge would be split at
 * the same points from both sides, and a reader welding by position would
 * join them).  Later rounds measure the triangles the last one made or
 * changed, until one splits nothing or for ROUNDS (a triangle whose
 * neighbour took the side it would split waits for the next round, and
 * on bored_cone.scad splits went on to the thirteenth: at six, 0.23 % of
 * its mesh's samples were beyond the tolerance, 0.14 % now, 17,408 ->
 * 17,862 triangles; no other mesh model changes).  At sharp edges and
 * tips the contour's own error is the larger, and halving triangles there
 * does not end: left alone.
 *
 * Measured (tests/tools/meshdev --points, the mesh models at their default
 * tolerance): torus.scad 1.22 % of its mesh's samples beyond the tolerance,
 * 2.04 D at most -> 0.13 %, 1.77 D, 11,920 -> 14,012 triangles;
 * bored_cone.scad 6.3 % -> 2.4 %, 13,548 -> 17,216; the bench scenes,
 * already within it, unchanged.  Smooth parts told by the surface under
 * them too (with mesh_unsliver): the torus 1.76 -> 1.30 D, 0.034 % ->
 * 0.016 %; hull_extrusions.scad 4,468 -> 4,710 triangles, as far off.
 * A triangle whose split the triangle across had taken in the same round
 * is measured again in the next (the torus had such strays left for
 * good: 1.30 -> 1.14 D); points are held to 0.95 of the tolerance, and a
 * sliver over curved patches is measured on a lattice too: the torus
 * within its tolerance (0.99 D), 13,476 -> 14,226 triangles.  Triangles
 * beside a rim measured, and rims split on their sharp edge: bored_cone's
 * mesh samples beyond D 0.85 -> 0.45 %, rotated_box_pin's 0.18 -> 0.10 %,
 * hull_extrusions' surface within 0.99 D of its mesh (2 D); the 17 mesh
 * models 67,194 -> 68,604 triangles.
 *
 * A triangle that is not smooth is measured another way: a side whose ends
 * lie on two surfaces (the crossings a hundredth of the way in from each
 * end, along the triangle's normal, on two patches whose normals part by
 * more than the feature angle) cuts across the sharp edge where they meet,
 * a chamfer or a fold; that point (Newton's method on the two surfaces'
 * quadrics, csg_scene_quadric, from the side's middle; on the solid's
 * surface, and off the side by more than the tolerance) splits the side
 * and the triangle across it.  The two sides from it each end on it, so
 * halving ends.  bored_cone.scad (after mesh_unbend): mesh samples 4
 * tolerances or more off its surface 145 -> 61, beyond the tolerance
 * 0.29 % -> 0.20 %, 16,774 -> 17,274 triangles; the bench part 5,500 ->
 * 5,602, as near its surface (0.95 -> 0.96 D); the other mesh models as
 * near as before.
 *
 * A triangle that strays and that no split took this round (its sides
 * may not be split, or it is not smooth and no side of it cuts a sharp
 * edge: a chamfer whose crease point lies too far off its side, a sliver
 * standing off a wall) has the side flipped that brings it and the
 * triangle across nearest the surface, where both new triangles come
 * within half of how far it strays (the farthest of their seven points
 * each) and face out; rounds go on while anything splits or flips.  bored_cone.scad:
 * mesh samples beyond the tolerance 0.142 % -> 0.093 %, 17,862 -> 17,878
 * triangles; rotated_box_pin 0.090 % -> 0.050 %; the other mesh models and
 * the bench parts the same meshes.  And a sharp edge's point found off a
 * side (cuts_crease) is told from where the surfaces meet beyond the
 * solid by whether each surface goes on from it (on_crease: a ray through
 * it grazed a convex rim and crossed nothing), up to the side's length
 * off it, and splits it where the halves face out though they turn more
 * than 60°: bored_cone 0.093 % -> 0.048 % (18,100 triangles),
 * rotated_box_pin 0.050 % -> 0.034 % (2,444), rounded_cube 4,922 -> 4,932
 * triangles as near, the rest the same meshes.
 */
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#define ROUNDS 16
#define REACH 4         /* tolerances: rays are cast this far either side */
#define COS_TURN 0.5    /* cos 60° */
#define COS_SMOOTH 0.94 /* cos 20° */
#define COS_ALONG 0.866 /* cos 30° */
#define COS_FACING 0.5  /* the surface under a split turned no more than 60° from it */
/* Of the tolerance: a measured point farther strays (the surface between
 * the points strays a little further). */
#define AIM 0.95
#define LATTICE 4 /* a curved sliver's lattice: steps along its sides */
#define MEET_STEPS 16
#define FLIP_GAIN 0.5 /* a flip takes a pair of triangles at least this much nearer */

/* What a round found of a triangle (measure_job.bad): nothing (0); smooth
 * and straying; a side that cuts across a sharp edge (CUT + the side); not
 * smooth, straying and no side that does. */
enum { STRAY = 1, CUT = 2, ASTRAY = 5 };

/* Corner k of triangle t. */
static void corner(const mesh *m, int32_t t, int k, double p[3])
{
    mesh_vertex_at(m, m->t[3 * (size_t)t + k], p);
}

/* How far x (on a triangle of unit normal n, first edge direction e) lies
 * from the surface, once no farther than `enough`: the nearest crossing on
 * the normal, then on rings of eight lines 30°, 60° and 85° off it (beside
 * a sharp edge the nearest surface lies to the side), within reach;
 * INFINITY where no line crosses anything. */
static double nearest(mesh_snapper *sn, const double x[3], const double n[3], const double e[3],
                      double enough, double reach)
{
    double f[3], best = INFINITY;
    cross3(n, e, f);
    static const double tilts[4] = {0, 0.5235987755982988, 1.0471975511965976, 1.4835298641951802};
    for (int ring = 0; ring < 4 && !(best <= enough); ring++)
        for (int i = 0; i < (ring ? 8 : 1) && !(best <= enough); i++) {
            double tilt = tilts[ring], az = i * 3.14159265358979323846 / 4;
            double dir[3], hit[3], hn[3], d[3];
            for (int k = 0; k < 3; k++)
                dir[k] = cos(tilt) * n[k] + sin(tilt) * (cos(az) * e[k] + sin(az) * f[k]);
            if (!mesh_snap_probe(sn, x, dir, fmin(reach, best), -1, hit, hn)) continue;
            sub3(hit, x, d);
            best = fmin(best, sqrt(dot3(d, d)));
        }
    return best;
}

/* Whether x lies within tol of the surface (nearest); lines that cross
 * nothing say nothing. */
static int within(mesh_snapper *sn, const double x[3], const double n[3], const double e[3],
                  double tol, double reach)
{
    double d = nearest(sn, x, n, e, tol, reach);
    return isinf(d) || d <= tol;
}

/* Point i of the four under which triangle p's surface is probed: its
 * centroid (i = 0), then nine tenths of the way from it to corner i - 1. */
static void probe_point(const double p[3][3], int i, double x[3])
{
    for (int k = 0; k < 3; k++) {
        double c = (p[0][k] + p[1][k] + p[2][k]) / 3;
        x[k] = i ? c + 0.9 * (p[i - 1][k] - c) : c;
    }
}

/* Whether the surface under triangle p (unit normal n) is curved: the
 * crossings under its centroid and nine tenths of the way to each corner
 * all on curved patches (a hull's facets are planes: the contour's error
 * where they meet, not the triangle's sag, is what strays there, and
 * halving does not end). */
static int over_curved(mesh_snapper *sn, const double p[3][3], const double n[3], double tol)
{
    for (int i = 0; i < 4; i++) {
        double x[3], hit[3], hn[3];
        uint32_t patch = 0;
        probe_point(p, i, x);
        if (!mesh_snap_probe_patch(sn, x, n, REACH * tol, COS_FACING, 0, hit, hn, &patch) ||
            (patch & MESH_PATCH_PLANAR))
            return 0;
    }
    return 1;
}

/* Triangle p's unit normal n and first side's direction e, and *l twice
 * its area; 0 where it has none. */
static int frame_of(const double p[3][3], double n[3], double e[3], double *l)
{
    tri_normal3(p[0], p[1], p[2], n);
    sub3(p[1], p[0], e);
    double le = sqrt(dot3(e, e));
    *l = sqrt(dot3(n, n));
    if (!(*l > 0 && le > 0)) return 0;
    for (int q = 0; q < 3; q++) {
        n[q] /= *l;
        e[q] /= le;
    }
    return 1;
}

/* Point i of the seven at which a triangle p is measured: its centroid,
 * its sides' middles, and halfway from the centroid to each corner. */
static void point_of(const double p[3][3], int i, double x[3])
{
    static const double w[7][3] = {{1.0 / 3, 1.0 / 3, 1.0 / 3},
                                   {0.5, 0.5, 0},
                                   {0, 0.5, 0.5},
                                   {0.5, 0, 0.5},
                                   {2.0 / 3, 1.0 / 6, 1.0 / 6},
                                   {1.0 / 6, 2.0 / 3, 1.0 / 6},
                                   {1.0 / 6, 1.0 / 6, 2.0 / 3}};
    for (int q = 0; q < 3; q++)
        x[q] = w[i][0] * p[0][q] + w[i][1] * p[1][q] + w[i][2] * p[2][q];
}

/* How far triangle p strays from the surface: the farthest of its seven
 * points (nearest, each no nearer than it need be: `enough`), at most
 * reach, or the first at stop or farther (its caller's answer is then
 * known); reach where it has no normal, or a point's lines cross nothing. */
static double farthest(mesh_snapper *sn, const double p[3][3], double enough, double stop,
                       double reach)
{
    double n[3], e[3], l, worst = 0;
    if (!frame_of(p, n, e, &l)) return reach;
    for (int i = 0; i < 7 && worst < stop; i++) {
        double x[3];
        point_of(p, i, x);
        worst = fmax(worst, fmin(nearest(sn, x, n, e, enough, reach), reach));
    }
    return worst;
}

/* Whether triangle t strays: a point of it farther than tol from the
 * surface (within). */
static int strays(const mesh *m, mesh_snapper *sn, int32_t t, double tol)
{
    double p[3][3], n[3], e[3], l;
    for (int k = 0; k < 3; k++)
        corner(m, t, k, p[k]);
    if (!frame_of((const double(*)[3])p, n, e, &l)) return 0; /* (its neighbours measure it) */
    for (int i = 0; i < 7; i++) {
        double x[3];
        point_of((const double(*)[3])p, i, x);
        if (!within(sn, x, n, e, tol, REACH * tol)) return 1;
    }
    /* A sliver over a curved surface (its longest side over three times its
     * height) strays most between those points: a lattice of them too. */
    double l2max = 0;
    for (int k = 0; k < 3; k++) {
        double d[3];
        sub3(p[(k + 1) % 3], p[k], d);
        l2max = fmax(l2max, dot3(d, d));
    }
    if (l2max > 9 * (l * l / l2max) && over_curved(sn, (const double(*)[3])p, n, tol))
        for (int i = 0; i <= LATTICE; i++)
            for (int j = 0; i + j <= LATTICE; j++) {
                double a = (double)i / LATTICE, b = (double)j / LATTICE, x[3];
                for (int q = 0; q < 3; q++)
                    x[q] = a * p[0][q] + b * p[1][q] + (1 - a - b) * p[2][q];
                if (!within(sn, x, n, e, tol, REACH * tol)) return 1;
            }
    return 0;
}

/* A round's view of the mesh: each half-edge's twin (mesh_half_twins)
 * and each triangle's tri_normal3, as the round began. */
typedef struct round_view {
    int32_t *opp;
    double (*tn)[3];
} round_view;

/* The unit normal of the surface nearest x along n (not unit; within
 * REACH tolerances) into sn_n; 0 when there is none. */
static int surface_normal(mesh_snapper *sn, const double x[3], const double n[3], double tol,
                          double sn_n[3])
{
    double u[3], hit[3], l = sqrt(dot3(n, n));
    if (!(l > 0)) return 0;
    for (int k = 0; k < 3; k++)
        u[k] = n[k] / l;
    if (!mesh_snap_probe(sn, x, u, REACH * tol, COS_FACING, hit, sn_n)) return 0;
    l = sqrt(dot3(sn_n, sn_n));
    if (!(l > 0)) return 0;
    for (int k = 0; k < 3; k++)
        sn_n[k] /= l;
    return 1;
}

/* Whether triangle t lies over one smooth piece of surface: the exact
 * normals under its centroid and nine tenths of the way from it to each
 * corner turn less than 20° from the centroid's (into cn): no crease under
 * it, no tip at a corner; and t turns less than 30° from it (not crumpled
 * by the contour, as where a surface grazes the grid). */
static int over_smooth(const mesh *m, mesh_snapper *sn, const round_view *rv, int32_t t, double tol,
                       double cn[3])
{
    double p[3][3];
    for (int k = 0; k < 3; k++)
        corner(m, t, k, p[k]);
    for (int i = 0; i < 4; i++) {
        double x[3], n[3];
        probe_point((const double(*)[3])p, i, x);
        if (!surface_normal(sn, x, rv->tn[t], tol, i ? n : cn)) return 0;
        if (i && dot3(n, cn) < COS_SMOOTH) return 0;
    }
    const double *tn = rv->tn[t];
    return dot3(tn, cn) >= COS_ALONG * sqrt(dot3(tn, tn));
}

/* Whether triangle t lies on a smooth part: against each neighbour it
 * bends by less than 20°, or it lies over one smooth piece of surface
 * itself (a torus's top, triangulated across the way it bends least, is
 * no sharp edge; a triangle beside a rim lies over the wall it is part
 * of, whatever the triangle across the rim lies over).  A triangle cut
 * across a crease lies over two pieces: at a sharp edge or tip the
 * contour's own error is the larger, and halving triangles there does not
 * end. */
static int smooth(const mesh *m, mesh_snapper *sn, const round_view *rv, int32_t t, double tol)
{
    const double *n = rv->tn[t];
    double under[3];
    int known = 0;
    for (int k = 0; k < 3; k++) {
        int32_t h = rv->opp[3 * t + k];
        if (h < 0) return 0;
        const double *o = rv->tn[h / 3];
        if (dot3(n, o) >= COS_SMOOTH * sqrt(dot3(n, n) * dot3(o, o))) continue;
        if (!known && !(known = over_smooth(m, sn, rv, t, tol, under))) return 0;
    }
    return 1;
}

/* Whether the edge between t and the triangle across, o, is a sharp edge:
 * they bend by 20° or more and do not both lie over one smooth piece. */
static int sharp_edge(const mesh *m, mesh_snapper *sn, const round_view *rv, int32_t t, int32_t o,
                      double tol)
{
    const double *n = rv->tn[t], *on = rv->tn[o];
    if (dot3(n, on) >= COS_SMOOTH * sqrt(dot3(n, n) * dot3(on, on))) return 0;
    double a[3], b[3];
    return !over_smooth(m, sn, rv, t, tol, a) || !over_smooth(m, sn, rv, o, tol, b) ||
           dot3(a, b) < COS_SMOOTH;
}

/* Whether splitting edge k of triangle t (corners a, b, c from k) at x
 * leaves halves (a, x, c) and (x, b, c) with area, turned by less than
 * 60° from t. */
static int halves_keep(const mesh *m, int32_t t, int k, const double x[3], double min2)
{
    double a[3], b[3], c[3], n[3], n1[3], n2[3];
    corner(m, t, k, a);
    corner(m, t, (k + 1) % 3, b);
    corner(m, t, (k + 2) % 3, c);
    tri_normal3(a, b, c, n);
    tri_normal3(a, x, c, n1);
    tri_normal3(x, b, c, n2);
    double l = sqrt(dot3(n, n)), l1 = sqrt(dot3(n1, n1)), l2 = sqrt(dot3(n2, n2));
    return l1 * l1 > min2 && l2 * l2 > min2 && dot3(n, n1) > COS_TURN * l * l1 &&
           dot3(n, n2) > COS_TURN * l * l2;
}

/* Split edge k of triangle t (a → b) at new vertex v: t becomes (a, v, c)
 * and (v, b, c) is added; 0 or -1. */
static int split_side(mesh *m, int32_t t, int k, int32_t v)
{
    int32_t *tv = &m->t[3 * (size_t)t];
    int32_t b = tv[(k + 1) % 3], c = tv[(k + 2) % 3];
    uint16_t color = m->tc && m->npal ? m->tc[t] : 0;
    tv[(k + 1) % 3] = v;
    return mesh_push_triangle(m, v, b, c, color) < 0 ? -1 : 0;
}

/* q's value at x into *v and its gradient into g. */
static void quadric_at(const iv_quadric *q, const double x[3], double *v, double g[3])
{
    double ax[3];
    for (int i = 0; i < 3; i++)
        ax[i] = dot3(q->A[i], x);
    *v = dot3(ax, x) + dot3(q->b, x) + q->c;
    for (int i = 0; i < 3; i++)
        g[i] = 2 * ax[i] + q->b[i];
}

/* A point where surfaces qa and qb meet, near x (Newton's method on both,
 * each step the least move that zeroes both linearised), into x; 1 when
 * it converges within `room` of where it began, 0 when not. */
static int meet(const iv_quadric *qa, const iv_quadric *qb, double room, double x[3])
{
    double x0[3] = {x[0], x[1], x[2]};
    for (int it = 0; it < MEET_STEPS; it++) {
        double va, vb, ga[3], gb[3];
        quadric_at(qa, x, &va, ga);
        quadric_at(qb, x, &vb, gb);
        double aa = dot3(ga, ga), ab = dot3(ga, gb), bb = dot3(gb, gb), det = aa * bb - ab * ab;
        if (!(det > 1e-6 * aa * bb)) return 0; /* tangent: no crease to find */
        double a = (-va * bb + vb * ab) / det, b = (-vb * aa + va * ab) / det, d2 = 0;
        for (int i = 0; i < 3; i++) {
            double dx = a * ga[i] + b * gb[i];
            x[i] += dx;
            d2 += dx * dx;
        }
        double off[3];
        sub3(x, x0, off);
        if (!(dot3(off, off) <= room * room)) return 0;
        if (d2 <= 1e-24 * room * room) return 1;
    }
    return 0;
}

/* Whether x, where surfaces q[0] and q[1] (on patches patch[0] and
 * patch[1], their normals near x about sn_n) meet, lies on the solid's
 * sharp edge between them, not where the two meet beyond the solid: each
 * goes on from x one way or the other, away from the other surface (a
 * ray along its normal from 2 tol off x crosses it on its patch within a
 * tenth of tol).  (A ray through x itself along the triangle's normal
 * grazes a convex edge and crosses nothing.) */
static int on_crease(mesh_snapper *sn, const double x[3], const iv_quadric q[2], double sn_n[2][3],
                     const uint32_t patch[2], double tol)
{
    double n[2][3];
    for (int s = 0; s < 2; s++) {
        double v;
        quadric_at(&q[s], x, &v, n[s]);
        double l = sqrt(dot3(n[s], n[s]));
        if (!(l > 0)) return 0;
        if (dot3(n[s], sn_n[s]) < 0) l = -l;
        for (int i = 0; i < 3; i++)
            n[s][i] /= l;
    }
    for (int s = 0; s < 2; s++) {
        const double *f = n[s], *g = n[1 - s];
        double w[3], c = dot3(f, g);
        for (int i = 0; i < 3; i++)
            w[i] = c * f[i] - g[i]; /* along f's surface, away from g's */
        double l = sqrt(dot3(w, w));
        if (!(l > 1e-9)) return 0;
        int goes = 0;
        for (int side = -1; side <= 1 && !goes; side += 2) {
            double p[3], hit[3], hn[3], d[3];
            uint32_t found;
            for (int i = 0; i < 3; i++)
                p[i] = x[i] + side * 2 * tol * w[i] / l;
            if (!mesh_snap_probe_patch(sn, p, f, tol, -1, patch[s], hit, hn, &found)) continue;
            sub3(hit, p, d);
            goes = dot3(d, d) <= 0.01 * tol * tol;
        }
        if (!goes) return 0;
    }
    return 1;
}

/* Whether side k of triangle t (unit normal n) cuts across a sharp edge
 * by more than tol: its ends lie on two surfaces (the crossings nearest
 * points a hundredth of the way in from each end, along n) whose normals
 * part by more than the feature angle, which meet (meet, from the side's
 * middle) at a point x of the solid's sharp edge (on_crease) off the side
 * by more than tol, beside its middle nine tenths and within its length
 * of it (a chamfer across a rim, or a fold where the contour joined two
 * vertices across it: on a rim of bored_cone.scad's cross hole, 0.088
 * from a side 0.156 long, when it had to be within half).  1 with that
 * point in x. */
static int cuts_crease(const mesh *m, mesh_snapper *sn, int32_t t, int k, const double n[3],
                       double tol, double x[3])
{
    double p[2][3], sp[3], sn_n[2][3], e[3];
    uint32_t patch[2];
    iv_quadric q[2];
    corner(m, t, k, p[0]);
    corner(m, t, (k + 1) % 3, p[1]);
    sub3(p[1], p[0], e);
    double len = sqrt(dot3(e, e));
    if (!(len > 2 * tol)) return 0;
    for (int s = 0; s < 2; s++) {
        double r[3];
        for (int i = 0; i < 3; i++)
            r[i] = s ? p[1][i] - 0.01 * e[i] : p[0][i] + 0.01 * e[i];
        if (!mesh_snap_probe_quadric(sn, r, n, 0.25 * len, sp, sn_n[s], &patch[s], &q[s])) return 0;
    }
    double l0 = sqrt(dot3(sn_n[0], sn_n[0])), l1 = sqrt(dot3(sn_n[1], sn_n[1]));
    if (patch[0] == patch[1] || !(dot3(sn_n[0], sn_n[1]) < sn->cos_feature * l0 * l1)) return 0;
    for (int i = 0; i < 3; i++)
        x[i] = 0.5 * (p[0][i] + p[1][i]);
    if (!meet(&q[0], &q[1], len, x)) return 0;
    double ax[3], d[3];
    sub3(x, p[0], ax);
    double u = dot3(ax, e) / (len * len);
    for (int i = 0; i < 3; i++)
        d[i] = p[0][i] + u * e[i] - x[i];
    if (!(u > 0.05 && u < 0.95 && dot3(d, d) > tol * tol && dot3(d, d) < len * len)) return 0;
    return on_crease(sn, x, q, sn_n, patch, tol);
}

/* The side of triangle t (unit normal n) that cuts across a sharp edge
 * (cuts_crease), the point on it into x; -1 when none does. */
static int side_cutting(const mesh *m, mesh_snapper *sn, int32_t t, const double n[3], double tol,
                        double x[3])
{
    for (int k = 0; k < 3; k++)
        if (cuts_crease(m, sn, t, k, n, tol, x)) return k;
    return -1;
}

/* The triangles of a round to measure, shared by the threads: thread w
 * takes every nth from w, with a snapper of its own. */
typedef struct measure_job {
    const mesh *m;
    const round_view *rv;
    const uint8_t *look;
    uint8_t *bad;     /* out: STRAY, CUT + the side that cuts a crease, ASTRAY; 0 */
    double (*cut)[3]; /* out: where that side cuts it */
    const mesh_snapper *proto;
    double tol;
    int n, w, failed;
} measure_job;

static void *measure(void *arg)
{
    measure_job *j = arg;
    mesh_snapper sn;
    if (mesh_snapper_init(&sn, j->proto->d, j->proto->cos_feature) != 0) {
        j->failed = 1;
        return NULL;
    }
    for (int32_t t = j->w; t < j->m->nt; t += j->n) {
        j->bad[t] = 0;
        if (!j->look[t]) continue;
        if (smooth(j->m, &sn, j->rv, t, j->tol)) {
            j->bad[t] = (uint8_t)strays(j->m, &sn, t, AIM * j->tol);
            continue;
        }
        double n[3], l = sqrt(dot3(j->rv->tn[t], j->rv->tn[t]));
        if (!(l > 0)) continue;
        for (int i = 0; i < 3; i++)
            n[i] = j->rv->tn[t][i] / l;
        int k = side_cutting(j->m, &sn, t, n, AIM * j->tol, j->cut[t]);
        if (k >= 0)
            j->bad[t] = (uint8_t)(CUT + k);
        else if (strays(j->m, &sn, t, AIM * j->tol))
            j->bad[t] = ASTRAY;
    }
    mesh_snapper_free(&sn);
    return NULL;
}

/* bad[t] (and cut[t]) for the triangles of m flagged in look, on up to
 * `threads` threads; 0 or -1. */
static int measure_all(const mesh *m, const round_view *rv, const uint8_t *look, uint8_t *bad,
                       double (*cut)[3], const mesh_snapper *sn, double tol, int threads)
{
    enum { MAX_THREADS = 64 };
    int n = threads < 1 ? 1 : threads > MAX_THREADS ? MAX_THREADS : threads;
    measure_job job[MAX_THREADS];
    pthread_t th[MAX_THREADS];
    int started[MAX_THREADS] = {0}, failed = 0;
    for (int w = 0; w < n; w++) {
        job[w] = (measure_job){m, rv, look, bad, cut, sn, tol, n, w, 0};
        if (w > 0) started[w] = pthread_create(&th[w], NULL, measure, &job[w]) == 0;
    }
    measure(&job[0]);
    for (int w = 1; w < n; w++) {
        if (started[w])
            pthread_join(th[w], NULL);
        else
            measure(&job[w]);
        failed |= job[w].failed;
    }
    return failed || job[0].failed ? -1 : 0;
}

/* The point of the sharp edge under edge k of t (o's edge j) nearest its
 * middle mid: the surfaces under t and o, each found by a ray along the
 * triangle's normal a quarter of the way from mid to its far corner, met
 * as contour vertices are (mesh_snap) within a box about the edge; 1 with
 * it in x, 0 when they do not meet there. */
static int crease_point(const mesh *m, mesh_snapper *sn, int32_t t, int k, int32_t o, int j,
                        const double mid[3], double tol, double x[3])
{
    double sp[2][3], sn_n[2][3], lo[3], hi[3], a[3], b[3];
    int32_t tri[2] = {t, o}, far[2] = {(k + 2) % 3, (j + 2) % 3};
    for (int s = 0; s < 2; s++) {
        double n[3], q[3], c[3];
        mesh_triangle_normal(m, tri[s], n);
        double l = sqrt(dot3(n, n));
        if (!(l > 0)) return 0;
        corner(m, tri[s], far[s], c);
        for (int i = 0; i < 3; i++) {
            n[i] /= l;
            q[i] = mid[i] + 0.25 * (c[i] - mid[i]);
        }
        if (!mesh_snap_probe(sn, q, n, REACH * tol, COS_FACING, sp[s], sn_n[s])) return 0;
    }
    corner(m, t, k, a);
    corner(m, t, (k + 1) % 3, b);
    for (int i = 0; i < 3; i++) {
        lo[i] = fmin(a[i], b[i]);
        hi[i] = fmax(a[i], b[i]);
        x[i] = mid[i];
    }
    return mesh_snap(sn, (const double(*)[3])sp, (const double(*)[3])sn_n, NULL, 2, -1, lo, hi,
                     x) == 2;
}

static int faces_out(mesh_snapper *sn, const double p[3][3], double reach);

/* Whether the halves (a, c, x) and (x, b, c) of triangle t = (a, b, c)
 * (from corner k) split at x each face the way the surface under them
 * does (faces_out). */
static int halves_face_out(const mesh *m, mesh_snapper *sn, int32_t t, int k, const double x[3],
                           double reach)
{
    double p[3][3], h[2][3][3];
    for (int q = 0; q < 3; q++)
        corner(m, t, (k + q) % 3, p[q]);
    memcpy(h[0][0], p[0], sizeof p[0]);
    memcpy(h[0][1], x, sizeof p[0]);
    memcpy(h[0][2], p[2], sizeof p[0]);
    memcpy(h[1][0], x, sizeof p[0]);
    memcpy(h[1][1], p[1], sizeof p[0]);
    memcpy(h[1][2], p[2], sizeof p[0]);
    return faces_out(sn, (const double(*)[3])h[0], reach) &&
           faces_out(sn, (const double(*)[3])h[1], reach);
}

/* Split edge k of triangle t and the triangle across it at x, where both
 * keep their halves — or, at a point of a sharp edge (crease, with sn),
 * each half faces out (a chamfer across a rim whose point lies well off
 * its side has halves that turn more than 60° from it, each onto a face
 * of the rim: bored_cone.scad's mesh samples beyond its tolerance 0.093 %
 * -> 0.048 %) — and no vertex is there already (pos holds them all; the
 * new one is added); the four triangles flagged used and in nx.  1 when
 * split, 0 when not, -1 when out of memory. */
static int split_at(mesh *m, mesh_snapper *crease, const round_view *rv, mesh_fmap *pos, int32_t t,
                    int k, const double x[3], double tol, uint8_t *used, uint8_t *nx)
{
    int32_t h = rv->opp[3 * t + k];
    if (h < 0) return 0;
    int32_t o = h / 3;
    int j = h % 3;
    double c[3];
    /* the place as the mesh will hold it (floats) */
    memcpy(c, x, sizeof c);
    mesh_round_to_float(c);
    double min2 = 1e-12 * tol * tol * tol * tol;
    int keep = (halves_keep(m, t, k, c, min2) && halves_keep(m, o, j, c, min2)) ||
               (crease && halves_face_out(m, crease, t, k, c, REACH * tol) &&
                halves_face_out(m, crease, o, j, c, REACH * tol));
    if (mesh_fmap_has(pos, mesh_pos_key(c)) || !keep) return 0;
    int fresh;
    int32_t v = mesh_push_vertex(m, c[0], c[1], c[2]),
            *slot = mesh_fmap_slot(pos, mesh_pos_key(c), &fresh);
    if (v < 0 || !slot) return -1;
    *slot = v;
    int32_t first = m->nt;
    if (split_side(m, t, k, v) != 0 || split_side(m, o, j, v) != 0) return -1;
    used[t] = used[o] = 1;
    nx[t] = nx[o] = nx[first] = nx[first + 1] = 1;
    return 1;
}

/* Split edge k of triangle t, and the triangle across it (unused this
 * round: the caller sees to that), at the surface under the edge's middle,
 * where the triangle across is smooth, both keep their halves and no
 * vertex is there already (pos holds them all; the new one is added); the
 * four triangles flagged used and in nx.  1 when split, 0 when not, -1
 * when out of memory. */
static int split_edge(mesh *m, mesh_snapper *sn, const round_view *rv, mesh_fmap *pos, int32_t t,
                      int k, double tol, uint8_t *used, uint8_t *nx)
{
    double p[2][3];
    corner(m, t, k, p[0]);
    corner(m, t, (k + 1) % 3, p[1]);
    int32_t h = rv->opp[3 * t + k];
    if (h < 0) return 0;
    int32_t o = h / 3;
    int j = h % 3;
    if (!smooth(m, sn, rv, o, tol)) return 0;
    const double *n0 = rv->tn[t], *n1 = rv->tn[o];
    double dir[3], mid[3], hit[3], hn[3];
    double l0 = sqrt(dot3(n0, n0)), l1 = sqrt(dot3(n1, n1));
    if (!(l0 > 0 && l1 > 0)) return 0;
    for (int i = 0; i < 3; i++) {
        dir[i] = n0[i] / l0 + n1[i] / l1;
        mid[i] = 0.5 * (p[0][i] + p[1][i]);
    }
    int sharp = sharp_edge(m, sn, rv, t, o, tol);
    if (sharp) {
        if (!crease_point(m, sn, t, k, o, j, mid, tol, hit)) return 0;
    } else {
        double dl = sqrt(dot3(dir, dir));
        if (!(dl > 1e-6)) return 0;
        for (int i = 0; i < 3; i++)
            dir[i] /= dl;
        if (!mesh_snap_probe(sn, mid, dir, REACH * tol, COS_FACING, hit, hn)) return 0;
    }
    return split_at(m, sharp ? sn : NULL, rv, pos, t, k, hit, tol, used, nx);
}

/* Whether triangle p faces the way the surface under its centroid does
 * (within reach along its normal). */
static int faces_out(mesh_snapper *sn, const double p[3][3], double reach)
{
    double n[3], e[3], l, c[3], hit[3], hn[3];
    if (!frame_of(p, n, e, &l)) return 0;
    point_of(p, 0, c);
    return mesh_snap_probe(sn, c, n, reach, -1, hit, hn) && dot3(hn, n) > 0;
}

/* A round's state for flips: the triangles about each vertex as it began
 * (mesh_vertex_fans), and the vertices a flip has used this round. */
typedef struct flip_view {
    int32_t *start, *fan;
    uint8_t *busy;
} flip_view;

/* Whether the vertices a and b share a side (as the round began). */
static int joined(const mesh *m, const flip_view *fv, int32_t a, int32_t b)
{
    for (int32_t f = fv->start[a]; f < fv->start[a + 1]; f++)
        for (int q = 0; q < 3; q++)
            if (m->t[3 * (size_t)fv->fan[f] + q] == b) return 1;
    return 0;
}

/* Flip the side of straying triangle t (unused this round) that brings it
 * and the triangle across (unused, of its colour) nearest the surface,
 * both new triangles within FLIP_GAIN of how far t strays (farthest; a
 * triangle across that strays further is flipped from its own side, when
 * it is measured) and facing out:
 * t = (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c), where c and
 * d share no side yet.  The two flagged used and in nx; 1 when flipped. */
static int flip_side(mesh *m, mesh_snapper *sn, const round_view *rv, flip_view *fv, int32_t t,
                     double tol, uint8_t *used, uint8_t *nx)
{
    double reach = REACH * tol, enough = 0.1 * tol, p[3][3];
    for (int q = 0; q < 3; q++)
        corner(m, t, q, p[q]);
    double ft = NAN, best = INFINITY; /* (ft measured once a side may flip) */
    int bestk = -1;
    for (int k = 0; k < 3; k++) {
        int32_t h = rv->opp[3 * t + k], o = h / 3;
        if (h < 0 || used[o]) continue;
        const int32_t *tv = &m->t[3 * (size_t)t], *ov = &m->t[3 * (size_t)o];
        int32_t a = tv[k], b = tv[(k + 1) % 3], c = tv[(k + 2) % 3], d = ov[(h % 3 + 2) % 3];
        if (c == d || fv->busy[a] || fv->busy[b] || fv->busy[c] || fv->busy[d] ||
            (m->tc && m->npal && m->tc[t] != m->tc[o]) || joined(m, fv, c, d))
            continue;
        double pd[3], n1[3][3], n2[3][3];
        mesh_vertex_at(m, d, pd);
        memcpy(n1[0], p[(k + 2) % 3], sizeof n1[0]);
        memcpy(n1[1], p[k], sizeof n1[1]);
        memcpy(n1[2], pd, sizeof n1[2]);
        memcpy(n2[0], pd, sizeof n2[0]);
        memcpy(n2[1], p[(k + 1) % 3], sizeof n2[1]);
        memcpy(n2[2], p[(k + 2) % 3], sizeof n2[2]);
        /* (the cheap tests first; the new pair measured no further than
         * decides it) */
        if (!faces_out(sn, (const double(*)[3])n1, reach) ||
            !faces_out(sn, (const double(*)[3])n2, reach))
            continue;
        if (isnan(ft)) {
            ft = farthest(sn, (const double(*)[3])p, enough, INFINITY, reach);
            best = FLIP_GAIN * ft;
        }
        double stop = best;
        double f1 = farthest(sn, (const double(*)[3])n1, enough, stop, reach);
        double after =
            f1 < stop ? fmax(f1, farthest(sn, (const double(*)[3])n2, enough, stop, reach)) : f1;
        if (!(after < stop)) continue;
        best = after;
        bestk = k;
    }
    if (bestk < 0) return 0;
    int32_t h = rv->opp[3 * t + bestk], o = h / 3, *tv = &m->t[3 * (size_t)t],
            *ov = &m->t[3 * (size_t)o];
    int32_t a = tv[bestk], b = tv[(bestk + 1) % 3], c = tv[(bestk + 2) % 3],
            d = ov[(h % 3 + 2) % 3];
    tv[0] = c, tv[1] = a, tv[2] = d;
    ov[0] = d, ov[1] = b, ov[2] = c;
    fv->busy[a] = fv->busy[b] = fv->busy[c] = fv->busy[d] = 1;
    used[t] = used[o] = nx[t] = nx[o] = 1;
    return 1;
}

/* One round over the triangles flagged in look (m->nt of them): the
 * strays split; the triangles it makes or changes flagged in next (room
 * for m->nt + 2·splits).  *split counts the splits; 0 or -1. */
static int round_once(mesh *m, mesh_snapper *sn, double tol, int threads, mesh_fmap *pos,
                      const uint8_t *look, uint8_t **next, int *split, int *flips)
{
    int32_t nt = m->nt;
    round_view rv = {malloc(3 * (size_t)nt * sizeof *rv.opp), malloc((size_t)nt * sizeof *rv.tn)};
    uint8_t *used = calloc((size_t)nt, 1), *nx = calloc(3 * (size_t)nt, 1),
            *bad = malloc((size_t)nt);
    double(*cut)[3] = malloc((size_t)nt * sizeof *cut);
    flip_view fv = {NULL, NULL, calloc((size_t)m->nv, 1)};
    int rc = -1;
    if (!rv.opp || !rv.tn || !used || !nx || !bad || !cut || !fv.busy ||
        mesh_half_twins(m, 0, rv.opp) != 0 || mesh_vertex_fans(m, 0, &fv.start, &fv.fan) != 0)
        goto done;
    for (int32_t t = 0; t < nt; t++) {
        double p[3][3];
        for (int k = 0; k < 3; k++)
            corner(m, t, k, p[k]);
        tri_normal3(p[0], p[1], p[2], rv.tn[t]);
    }
    if (measure_all(m, &rv, look, bad, cut, sn, tol, threads) != 0) goto done;
    for (int32_t t = 0; t < nt; t++) {
        if (!bad[t] || bad[t] == ASTRAY || used[t]) continue;
        /* a side cut across a sharp edge: that side, split on the edge;
         * else the longest edge only (a shorter one where the longest may
         * not be split took bored_cone.scad from 16,646 to 19,702
         * triangles about its sharp rims, for a torus 1.30 -> 1.13
         * tolerances) */
        int k = bad[t] - CUT;
        if (bad[t] == STRAY) {
            double p[3][3], best = -1;
            for (int i = 0; i < 3; i++)
                corner(m, t, i, p[i]);
            for (int i = 0; i < 3; i++) {
                double d[3];
                sub3(p[(i + 1) % 3], p[i], d);
                if (dot3(d, d) > best) best = dot3(d, d), k = i;
            }
        }
        int32_t across = rv.opp[3 * t + k];
        if (across >= 0 && used[across / 3]) {
            nx[t] = 1; /* the triangle across was split this round: the next */
            bad[t] = 0;
            continue;
        }
        int r = bad[t] == STRAY ? split_edge(m, sn, &rv, pos, t, k, tol, used, nx)
                                : split_at(m, sn, &rv, pos, t, k, cut[t], tol, used, nx);
        if (r < 0) goto done;
        *split += r;
    }
    for (int32_t t = 0; t < nt; t++)
        if (bad[t] && !used[t]) *flips += flip_side(m, sn, &rv, &fv, t, tol, used, nx);
    rc = 0;
done:
    free(fv.start);
    free(fv.fan);
    free(fv.busy);
    free(rv.opp);
    free(rv.tn);
    free(used);
    free(bad);
    free(cut);
    *next = nx;
    return rc;
}

int mesh_tighten(mesh *m, mesh_snapper *sn, double tol, int threads)
{
    if (!sn->arena || !(tol > 0) || m->nt == 0) return 0;
    mesh_fmap pos;
    memset(&pos, 0, sizeof pos);
    int rc = 0, fresh;
    for (int32_t v = 0; v < m->nv && rc == 0; v++) {
        double p[3];
        mesh_vertex_at(m, v, p);
        int32_t *slot = mesh_fmap_slot(&pos, mesh_pos_key(p), &fresh);
        if (!slot)
            rc = -1;
        else if (fresh)
            *slot = v;
    }
    uint8_t *look = malloc((size_t)m->nt);
    if (!look)
        rc = -1;
    else
        memset(look, 1, (size_t)m->nt);
    for (int r = 0; r < ROUNDS && rc == 0; r++) {
        int split = 0, flips = 0;
        uint8_t *next = NULL;
        rc = round_once(m, sn, tol, threads, &pos, look, &next, &split, &flips);
        free(look);
        look = next;
        if (!split && !flips) break;
    }
    free(look);
    free(pos.key);
    free(pos.val);
    return rc;
}
