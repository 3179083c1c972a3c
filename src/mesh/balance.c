/*
 * balance.c — a simplified mesh's smooth vertices moved off the surface by
 * half the sag of their triangles (see dexels.h, mesh_balance).
 *
 * A triangle whose corners lie on a curved surface lies inside it where the
 * surface is convex (outside where concave) by up to its sag; the corners
 * are on it.  Moving each corner out by half the sag of its triangles
 * splits the deviation between both sides: the same bound then holds with
 * triangles about twice the area (sag grows with the square of size).  The
 * sag of a triangle is measured by rays along its normal through its
 * centroid and its edges' midpoints (the centroid alone missed it on long
 * triangles, whose deepest point is by the longest edge: a sphere's mesh
 * strayed 1.29 tolerances, 1.15 with the midpoints).  A vertex moves to the
 * middle of the band its triangles' sags span, the most inward to the most
 * outward: on a saddle they lie to both sides, and a move by the largest
 * alone doubled the other side's (a torus's inner equator, 3.2
 * tolerances; 2.4 so).  The move is at most half the simplifier's bound: a
 * sag beyond it is a triangle the simplifier did not see stray, which a
 * larger move only carries to the other side (the surface samples of
 * bored_cone.scad beyond the tolerance: 1,621 -> 0).  A vertex on a sharp
 * edge or corner (its triangles' normals spread more than 20°) stays: it is
 * exact, and moving it would move the edge.  A vertex whose triangles lie on
 * plane patches alone (MESH_PATCH_PLANAR: a faceted curve, an imported
 * ring's 6,144 facets) moves only where their sags span no more than the
 * simplifier allowed: wider, they are a crease the triangles cut across,
 * not a curve's sag (pinched_cells.scad's 12-gon facets, spans of 3 to 6
 * tolerances: 395 surface samples were moved beyond the tolerance, 37 so;
 * the ring's volume stays within 0.11 % of openscad's, -0.75 % with planes
 * never moved).  A move that would turn one of its triangles by more than
 * 30° is not made.
 */
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define COS_SMOOTH 0.94 /* cos 20° */
#define COS_KEEP 0.866  /* cos 30° */

/* Triangle t's normal (tri_normal3) and where its sag is measured: its
 * corners' centroid (at[0]) and its edges' midpoints. */
static void triangle_at(const mesh *m, int32_t t, double n[3], double at[4][3])
{
    double p[3][3];
    for (int k = 0; k < 3; k++)
        mesh_vertex_at(m, m->t[3 * (size_t)t + k], p[k]);
    tri_normal3(p[0], p[1], p[2], n);
    for (int q = 0; q < 3; q++) {
        at[0][q] = (p[0][q] + p[1][q] + p[2][q]) / 3;
        for (int k = 0; k < 3; k++)
            at[k + 1][q] = 0.5 * (p[k][q] + p[(k + 1) % 3][q]);
    }
}

int mesh_balance(mesh *m, mesh_snapper *sn, double bound)
{
    double reach = 4 * bound;
    if (!sn->arena) return 0;
    int nv = m->nv, nt = m->nt;
    double(*vn)[3] = calloc((size_t)nv, sizeof *vn), (*vs)[2] = calloc((size_t)nv, sizeof *vs);
    double(*tn)[3] = malloc((size_t)nt * sizeof *tn);
    uint8_t *bent = calloc((size_t)nv + 1, 1); /* some triangle around it is on a curved patch */
    int32_t *start = NULL, *fan = NULL;
    int rc = -1;
    if (!vn || !vs || !tn || !bent || mesh_vertex_fans(m, 0, &start, &fan) != 0) goto done;
    /* each triangle's sag, and each vertex's largest and its normal */
    for (int32_t t = 0; t < nt; t++) {
        double at[4][3];
        triangle_at(m, t, tn[t], at);
        double len = sqrt(dot3(tn[t], tn[t])), n[3], hit[3], hn[3], d[3];
        if (!(len > 0)) continue;
        for (int q = 0; q < 3; q++)
            n[q] = tn[t][q] / len;
        double sag[2] = {0, 0}; /* the most inward, the most outward */
        int curved = 0;
        for (int i = 0; i < 4; i++) {
            uint32_t patch = 0;
            if (!mesh_snap_probe_patch(sn, at[i], n, reach, -1, 0, hit, hn, &patch) ||
                !(dot3(hn, n) > COS_KEEP))
                continue;
            curved |= !(patch & MESH_PATCH_PLANAR);
            sub3(hit, at[i], d);
            double g = dot3(d, n); /* > 0: the surface is outside the triangle */
            sag[0] = fmin(sag[0], g);
            sag[1] = fmax(sag[1], g);
        }
        for (int k = 0; k < 3; k++) {
            int32_t v = m->t[3 * (size_t)t + k];
            for (int q = 0; q < 3; q++)
                vn[v][q] += tn[t][q];
            vs[v][0] = fmin(vs[v][0], sag[0]);
            vs[v][1] = fmax(vs[v][1], sag[1]);
            bent[v] |= (uint8_t)curved;
        }
    }
    /* the smooth vertices (their triangles within 20° of their normal)
     * moved; the normals are of the triangles before any move */
    for (int v = 0; v < nv; v++) {
        double l = sqrt(dot3(vn[v], vn[v]));
        int smooth = l > 0 && (bent[v] || vs[v][1] - vs[v][0] <= bound);
        for (int f = start[v]; f < start[v + 1] && smooth; f++) {
            double len = sqrt(dot3(tn[fan[f]], tn[fan[f]]));
            smooth = len > 0 && dot3(tn[fan[f]], vn[v]) >= COS_SMOOTH * len * l;
        }
        if (!smooth) continue;
        double to[3];
        mesh_vertex_at(m, v, to);
        double by = fmin(fmax(0.5 * (vs[v][0] + vs[v][1]), -0.5 * bound), 0.5 * bound);
        for (int q = 0; q < 3; q++)
            to[q] += by * vn[v][q] / l;
        mesh_vertex_move(m, v, fan + start[v], start[v + 1] - start[v], to, COS_KEEP, 0);
    }
    rc = 0;
done:
    free(vn);
    free(vs);
    free(tn);
    free(bent);
    free(start);
    free(fan);
    return rc;
}

/* Smooth parts are simplified to SMOOTH times the tolerance, the sag then
 * split in two by mesh_balance, sharp edges and flat faces to EDGE times
 * it: the contour's points are samples, and between them the surface strays
 * a little further (a rim's arc between its points, the surface between the
 * balanced vertices; mesh_tighten splits the triangles where it strays past
 * the tolerance).  Measured with tests/tools/meshdev (both ways, by rays):
 * the bench part and two spheres within 0.93-0.94 of the tolerance at 0.008
 * and h 0.25 (1.8 and 1 gave 1.07-1.15).  Where mesh_split_creases put
 * chords back on the edges and corners of plane faces, the simplifier runs
 * again, to AGAIN times those bounds: the faces' vertices go, and the
 * error does not add up (at the full bounds, hull_revolve.scad's 64 x 32
 * facets came out with 0.16 % of the surface's samples beyond the
 * tolerance, 0.015 % before).  Primitives' own faces
 * (mesh_exact_append) are set aside meanwhile: they are exact. */
#define SMOOTH 1.6
#define EDGE 0.9
#define AGAIN 0.25

int mesh_dexels_simplify(const mesh_dexels *d, mesh *m, double tol, const mesh_options *o,
                         char *err, size_t errlen)
{
    mesh_snapper sn;
    mesh_exact_tail exact;
    if (mesh_exact_detach(m, &exact) != 0) {
        snprintf(err, errlen, "out of memory simplifying the mesh");
        return -1;
    }
    if (mesh_snapper_init(&sn, d, cos(3.14159265358979323846 / 6)) != 0) {
        mesh_exact_tail_free(&exact);
        snprintf(err, errlen, "out of memory simplifying the mesh");
        return -1;
    }
    /* (the simplifier's own measure of a plane: FLAT of the sharp-edge
     * bound) */
    if (mesh_flatten(m, 1e-3 * EDGE * tol) != 0) {
        mesh_snapper_free(&sn);
        mesh_exact_tail_free(&exact);
        snprintf(err, errlen, "out of memory simplifying the mesh");
        return -1;
    }
    int rc = mesh_simplify(m, SMOOTH * tol, EDGE * tol, &sn, mesh_thread_count(o), err, errlen);
    int splits = 0;
    if (rc == 0 && mesh_split_creases(m, &sn, &splits) != 0) {
        snprintf(err, errlen, "out of memory simplifying the mesh");
        rc = -1;
    }
    if (rc == 0 && splits)
        rc = mesh_simplify(m, AGAIN * SMOOTH * tol, AGAIN * EDGE * tol, &sn, mesh_thread_count(o),
                           err, errlen);
    if (rc == 0 && (mesh_balance(m, &sn, SMOOTH * tol) != 0 || mesh_unsliver(m, &sn, d->h) != 0 ||
                    mesh_tighten(m, &sn, tol, mesh_thread_count(o)) != 0)) {
        snprintf(err, errlen, "out of memory simplifying the mesh");
        rc = -1;
    }
    mesh_snapper_free(&sn);
    if (rc == 0 && mesh_exact_attach(m, &exact) != 0) {
        snprintf(err, errlen, "out of memory simplifying the mesh");
        rc = -1;
    }
    mesh_exact_tail_free(&exact);
    return rc;
}
