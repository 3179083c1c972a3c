/*
 * snap.c — contour vertices put on the exact surface, sharp edge and corner
 * by rays (see dexels.h, mesh_snap).
 *
 * The contour's QEF places a feature vertex where the tangent planes of its
 * cell's samples meet.  Those samples lie on the cell's edges, up to a cell
 * from the feature, so on a curved surface their planes meet off it: where
 * two spheres meet at 60°, 0.06 of a cell of 0.25 away (and a crease that
 * lies in a grid plane pins the QEF to a corner of its cell).  Planes taken
 * at the feature do not have that error.  Each iteration therefore asks the
 * scene for every surface at a point just beside the current vertex, on the
 * surface's own side (towards its samples): a ray along the surface's normal
 * through that point crosses it there, with the exact normal.  The vertex
 * moves to the nearest point on all of those planes, and the next iteration
 * probes nearer.  A surface whose samples are coplanar is a plane already
 * known exactly and costs no ray.  Given the samples' patches, two planes
 * are two surfaces at any angle over 1° (mesh_planes_crease), and where the
 * planes meet (in a line, or a point) the vertex goes there, however slight
 * their angles; elsewhere the least-squares step drops the directions the
 * planes hardly fix (as contour.c's QEF does).
 */
#include "dexels.h"
#include "../intervals/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SURF 3
#define ITERATIONS 3
#define FIT 1e-4 /* cells: planes meet where a point lies this near all of them */

int mesh_snapper_init(mesh_snapper *sn, const mesh_dexels *d, double cos_feature)
{
    memset(sn, 0, sizeof *sn);
    sn->d = d;
    sn->cos_feature = cos_feature;
    if (!d->scene) return 0;
    sn->arena = iv_arena_new(0);
    return sn->arena ? 0 : -1;
}

void mesh_snapper_free(mesh_snapper *sn)
{
    if (sn->arena) iv_arena_free(sn->arena);
    sn->arena = NULL;
}

/* The crossing of the line x + t·n (|t| <= reach, n a unit vector) with
 * the surface nearest x whose normal is within acos(min_cos) of n, on
 * patch `patch` (0: any): its place into p, its normal into pn, and its
 * boundary (in sn's arena, traced from o = x - reach·n) returned; NULL
 * when there is none. */
static const iv_bound *probe(mesh_snapper *sn, const double x[3], const double n[3], double reach,
                             double min_cos, uint32_t patch, double o[3], double p[3], double pn[3])
{
    const mesh_dexels *d = sn->d;
    if (!sn->arena) return NULL;
    for (int c = 0; c < 3; c++)
        o[c] = x[c] - reach * n[c];
    iv_arena_reset(sn->arena);
    iv_list l;
    if (csg_trace(d->scene, d->root, o, n, 0, 2 * reach, sn->arena, &l) != 0) return NULL;
    double best = INFINITY;
    const iv_bound *at = NULL;
    for (int k = 0; k < l.n; k++)
        for (int e = 0; e < 2; e++) {
            const iv_bound *b = e == 0 ? &l.v[k].enter : &l.v[k].exit;
            if (b->prim == IV_PRIM_NONE || !(fabs(b->t - reach) < best)) continue;
            uint32_t bp = mesh_patch_of(b->prim, b->part);
            if (patch && bp != (patch & ~MESH_PATCH_PLANAR)) continue;
            double bn[3];
            csg_scene_normal(d->scene, b, o, n, bn);
            if (dot3(bn, n) < min_cos) continue;
            best = fabs(b->t - reach);
            at = b;
            for (int c = 0; c < 3; c++) {
                p[c] = o[c] + b->t * n[c];
                pn[c] = bn[c];
            }
        }
    return at;
}

int mesh_snap_probe_patch(mesh_snapper *sn, const double x[3], const double n[3], double reach,
                          double min_cos, uint32_t patch, double p[3], double pn[3],
                          uint32_t *found)
{
    double o[3];
    const iv_bound *b = probe(sn, x, n, reach, min_cos, patch, o, p, pn);
    if (b && found) *found = mesh_patch_flagged(sn->d, mesh_patch_of(b->prim, b->part));
    return b != NULL;
}

int mesh_snap_probe_quadric(mesh_snapper *sn, const double x[3], const double n[3], double reach,
                            double p[3], double pn[3], uint32_t *found, iv_quadric *q)
{
    double o[3];
    const iv_bound *b = probe(sn, x, n, reach, -1, 0, o, p, pn);
    if (!b || csg_scene_quadric(sn->d->scene, b, o, n, q) != 0) return 0;
    *found = mesh_patch_of(b->prim, b->part);
    return 1;
}

int mesh_snap_probe(mesh_snapper *sn, const double x[3], const double n[3], double reach,
                    double min_cos, double p[3], double pn[3])
{
    return mesh_snap_probe_patch(sn, x, n, reach, min_cos, 0, p, pn, NULL);
}

int mesh_snap_inside(mesh_snapper *sn, const double x[3], int a)
{
    const mesh_dexels *d = sn->d;
    if (!sn->arena) return -1;
    double o[3] = {x[0], x[1], x[2]}, dir[3] = {0, 0, 0}, h = d->h;
    o[a] -= h;
    dir[a] = 1;
    iv_arena_reset(sn->arena);
    iv_list l;
    if (csg_trace(d->scene, d->root, o, dir, 0, 2 * h, sn->arena, &l) != 0) return -1;
    for (int k = 0; k < l.n; k++)
        if (l.v[k].enter.t <= h && l.v[k].exit.t > h) return 1;
    return 0;
}

/* How far x lies behind the plane through p with unit normal n. */
static double behind(const double p[3], const double n[3], const double x[3])
{
    double d[3];
    sub3(p, x, d);
    return dot3(n, d);
}

/* The symmetric solve of contour.c (mesh_qef_solve) for the nearest point
 * to x on the planes (p[i], n[i]), the coordinate `fixed` (or none: -1)
 * kept: x moves by the minimum-norm least-squares step. */
static void solve_planes(const double (*p)[3], const double (*n)[3], int np, int fixed, double cut,
                         double x[3])
{
    double a[3][3] = {{0}}, b[3] = {0, 0, 0}, dx[3];
    for (int i = 0; i < np; i++) {
        double r = behind(p[i], n[i], x);
        for (int u = 0; u < 3; u++) {
            if (u == fixed) continue;
            b[u] += n[i][u] * r;
            for (int v = 0; v < 3; v++)
                if (v != fixed) a[u][v] += n[i][u] * n[i][v];
        }
    }
    mesh_qef_solve(a, b, cut, dx);
    for (int c = 0; c < 3; c++)
        x[c] += dx[c];
}

/* The farthest x lies from one of the planes. */
static double farthest(const double (*p)[3], const double (*n)[3], int np, const double x[3])
{
    double f = 0;
    for (int i = 0; i < np; i++)
        f = fmax(f, fabs(behind(p[i], n[i], x)));
    return f;
}

/* solve_planes, every direction kept where the planes meet in a line or
 * point (to tol): planes of distinct patches at slight angles; else those
 * under 5 % of the largest eigenvalue dropped. */
static void nearest_on_planes(const double (*p)[3], const double (*n)[3], int np, int fixed,
                              int exact, double tol, double x[3])
{
    double y[3] = {x[0], x[1], x[2]};
    if (exact) {
        solve_planes(p, n, np, fixed, 1e-6, y);
        if (farthest(p, n, np, y) <= tol) {
            memcpy(x, y, sizeof y);
            return;
        }
    }
    solve_planes(p, n, np, fixed, 0.05, x);
}

/* The sum of squared distances of x from the planes. */
static double residual(const double (*p)[3], const double (*n)[3], int np, const double x[3])
{
    double s = 0;
    for (int i = 0; i < np; i++) {
        double r = behind(p[i], n[i], x);
        s += r * r;
    }
    return s;
}

int mesh_snap(mesh_snapper *sn, const double (*sp)[3], const double (*nrm)[3],
              const uint32_t *patch, int ns, int fixed, const double lo[3], const double hi[3],
              double x[3])
{
    if (!sn->arena || ns <= 0) return 0;
    double h = sn->d->h;
    /* The surfaces: samples grouped by normal, each group's first sample
     * its representative; more than MAX_SURF surfaces: left as it is. */
    double p[MAX_SURF][3], n[MAX_SURF][3];
    int flat[MAX_SURF], np = 0;
    uint32_t gp[MAX_SURF]; /* each surface's first patch */
    for (int i = 0; i < ns && i < 12; i++) {
        double ni[3] = {nrm[i][0], nrm[i][1], nrm[i][2]};
        double len = sqrt(dot3(ni, ni));
        if (!(len > 0.5)) return 0; /* a sample without a surface normal */
        int g = 0;
        while (g < np && (dot3(ni, n[g]) / len < sn->cos_feature ||
                          (patch && mesh_planes_crease(gp[g], patch[i], dot3(ni, n[g]) / len))))
            g++;
        if (g == np) {
            if (np == MAX_SURF) return 0;
            gp[np] = patch ? patch[i] : 0;
            flat[np] = 1;
            for (int c = 0; c < 3; c++) {
                n[np][c] = ni[c] / len;
                p[np][c] = sp[i][c];
            }
            np++;
        } else {
            double dn[3] = {ni[0] / len - n[g][0], ni[1] / len - n[g][1], ni[2] / len - n[g][2]};
            double dp[3] = {sp[i][0] - p[g][0], sp[i][1] - p[g][1], sp[i][2] - p[g][2]};
            if (dot3(dn, dn) > 1e-12 || fabs(dot3(dp, n[g])) > 1e-6 * h) flat[g] = 0;
        }
    }
    double start[3] = {x[0], x[1], x[2]};
    double step = 0.05 * h;
    for (int it = 0; it < ITERATIONS; it++, step *= 0.1) {
        int curved = 0;
        for (int g = 0; g < np; g++) {
            if (flat[g]) continue;
            curved = 1;
            /* Beside x on the surface's own side: towards its sample,
             * within its tangent plane. */
            double t[3];
            for (int c = 0; c < 3; c++)
                t[c] = p[g][c] - x[c];
            double tn = dot3(t, n[g]);
            for (int c = 0; c < 3; c++)
                t[c] -= tn * n[g][c];
            double tl = sqrt(dot3(t, t));
            double q[3];
            for (int c = 0; c < 3; c++)
                q[c] = x[c] + (tl > 1e-12 * h ? step * t[c] / tl : 0);
            double hp[3], hn[3];
            if (mesh_snap_probe_patch(sn, q, n[g], h, sn->cos_feature, gp[g], hp, hn, NULL)) {
                memcpy(p[g], hp, sizeof hp);
                memcpy(n[g], hn, sizeof hn);
            }
        }
        nearest_on_planes((const double(*)[3])p, (const double(*)[3])n, np, fixed, patch != NULL,
                          FIT * h, x);
        for (int c = 0; c < 3; c++)
            x[c] = fmin(fmax(x[c], lo[c]), hi[c]);
        if (!curved) break;
    }
    /* Kept only where it fits the planes at the feature better. */
    if (residual((const double(*)[3])p, (const double(*)[3])n, np, start) <
        residual((const double(*)[3])p, (const double(*)[3])n, np, x)) {
        memcpy(x, start, sizeof start);
        return 0;
    }
    return np;
}
