/*
 * meshdev.c — how far a mesh of a model strays from the model's exact
 * surface, both ways (the symmetric Hausdorff distance), by rays.
 *
 *   meshdev MODEL.scad MESH --tolerance D [--name NAME] [--surface-only]
 *           [--points FILE] [--share P]
 *
 * The model is evaluated and sampled as `rayscad -o` does (default grid,
 * every CPU); MESH is read through OpenMesh.
 *   - Mesh to surface: points on every triangle (its corners and a lattice
 *     of at least 4 and at most 16 steps along its longest edge, no coarser
 *     than the grid) each lie no further from the surface than the nearest
 *     crossing of five lines through them — the triangle's normal and four
 *     lines 30° off it — with the model (exact ray crossings): an upper
 *     bound of the distance, so the check cannot pass a mesh that strays.
 *   - Surface to mesh: the sampling's crossings are points on the exact
 *     surface; each one's distance to the nearest triangle (exact).
 * Prints one row (the two distances, their largest over D, the points
 * where they were found); exits 0 when both are at most D, 1 when not, 2
 * on bad input.  --surface-only measures and bounds the second alone: how
 * closely the mesh follows every part of the surface (its sharp edges
 * above all) where the first is known to fail elsewhere.  --points FILE
 * writes every sample point farther than D ("way distance/D x y z", way 0
 * from the mesh to the surface, 1 back) and prints how many there were of
 * how many: where a mesh strays, and how much of it.  --share P passes a
 * mesh whose samples lie farther than D, each way, for at most P % of them
 * (and prints those counts).
 */
#include "trimesh.h"

#include "../../src/intervals/vec3.h"
#include "../../src/mesh/dexels.h"
#include "../../src/rayscad/rayscad_internal.h"

#define REACH 8 /* lines are cast out to REACH·D: past it, a point is "far" */

/* The sample points seen, each way (0: mesh to surface), and those farther
 * than tol, written to out (not NULL: --points) as "way distance/tol x y z". */
typedef struct tally {
    FILE *out;
    double tol;
    long seen[2], over[2];
} tally;

static void note(tally *t, int way, double d, const double p[3], double *worst, double where[3])
{
    t->seen[way]++;
    if (d > t->tol) {
        t->over[way]++;
        if (t->out) fprintf(t->out, "%d %g %.9g %.9g %.9g\n", way, d / t->tol, p[0], p[1], p[2]);
    }
    keep_worst(d, p, worst, where);
}

/* The distance from p (on a triangle of unit normal n, first edge e) to the
 * model's surface, at most: the nearest crossing on lines through p — the
 * normal, then (while that crossing is past `enough`) rings of 16 more, 15°
 * to 90° off it, which find a wall or edge nearer than the faces' planes (a
 * ring 15° apart overestimates by at most 1/cos 7.5°, 0.9 %, where the
 * surface is flat); reach when there is none within it. */
static double to_surface(mesh_snapper *sn, const double p[3], const double n[3], const double e[3],
                         double reach, double enough)
{
    double f[3], best = reach;
    cross3(n, e, f);
    for (int ring = 0; ring < 7 && best > enough; ring++)
        for (int i = 0; i < (ring ? 16 : 1); i++) {
            double tilt = ring * 3.14159265358979323846 / 12, az = i * 3.14159265358979323846 / 8;
            double dir[3], hit[3], hn[3], d[3];
            for (int k = 0; k < 3; k++)
                dir[k] = cos(tilt) * n[k] + sin(tilt) * (cos(az) * e[k] + sin(az) * f[k]);
            if (!mesh_snap_probe(sn, p, dir, best, -1, hit, hn)) continue;
            sub3(hit, p, d);
            best = fmin(best, sqrt(dot3(d, d)));
        }
    return best;
}

/* The largest to_surface of points on m's triangles (where: its point; each noted
 * in t). */
static double mesh_to_surface(const tmesh *m, mesh_snapper *sn, double h, double reach,
                              double enough, tally *t, double where[3])
{
    double worst = 0;
    for (int q = 0; q < m->nt; q++) {
        double a[3], b[3], c[3], ab[3], ac[3], n[3], e[3];
        vertex(m, m->t[3 * q], a);
        vertex(m, m->t[3 * q + 1], b);
        vertex(m, m->t[3 * q + 2], c);
        sub3(b, a, ab);
        sub3(c, a, ac);
        cross3(ab, ac, n);
        double ln = sqrt(dot3(n, n)), le = sqrt(dot3(ab, ab));
        if (!(ln > 0) || !(le > 0)) continue; /* a sliver: its neighbours speak for it */
        for (int k = 0; k < 3; k++) {
            n[k] /= ln;
            e[k] = ab[k] / le;
        }
        double lmax = fmax(fmax(le, sqrt(dot3(ac, ac))), sqrt(geom_triangle_dist2(b, c, c, c)));
        int steps = (int)ceil(lmax / h);
        steps = steps < 4 ? 4 : steps > 16 ? 16 : steps;
        for (int i = 0; i <= steps; i++)
            for (int j = 0; j <= steps - i; j++) {
                double u = (double)i / steps, v = (double)j / steps, p[3];
                for (int k = 0; k < 3; k++)
                    p[k] = a[k] + u * ab[k] + v * ac[k];
                note(t, 0, to_surface(sn, p, n, e, reach, enough), p, &worst, where);
            }
    }
    return worst;
}

/* The largest distance from the crossings of d (every grid) to m's
 * triangles in g (each noted in ty). */
static double surface_to_mesh(const mesh_dexels *d, grid *g, tally *ty, double where[3])
{
    double worst = 0;
    for (; d; d = d->next)
        for (int a = 0; a < 3; a++) {
            int u = (a + 1) % 3, v = (a + 2) % 3;
            if (u > v) {
                int t = u;
                u = v;
                v = t;
            }
            size_t rays = (size_t)(d->n[u] + 1) * (size_t)(d->n[v] + 1);
            for (size_t r = 0; r < rays; r++)
                for (size_t k = d->off[a][r]; k < d->off[a][r + 1]; k++) {
                    double p[3];
                    p[a] = d->org[a] + d->hit[a][k].t;
                    p[u] = d->org[u] + d->h * (double)(r % (size_t)(d->n[u] + 1));
                    p[v] = d->org[v] + d->h * (double)(r / (size_t)(d->n[u] + 1));
                    note(ty, 1, grid_nearest(g, p), p, &worst, where);
                }
        }
    return worst;
}

int main(int argc, char **argv)
{
    const char *model = NULL, *path = NULL, *name = "", *points = NULL;
    double tol = 0, share = -1;
    int surface_only = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--surface-only") == 0)
            surface_only = 1;
        else if (i + 1 < argc && strcmp(argv[i], "--tolerance") == 0)
            tol = atof(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--name") == 0)
            name = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--points") == 0)
            points = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--share") == 0)
            share = atof(argv[++i]);
        else if (!model)
            model = argv[i];
        else if (!path)
            path = argv[i];
        else
            model = NULL, i = argc;
    }
    if (!model || !path || !(tol > 0)) {
        fprintf(stderr, "usage: meshdev MODEL.scad MESH --tolerance D [--name NAME] "
                        "[--surface-only] [--points FILE] [--share P]\n");
        return 2;
    }
    char err[512] = "";
    rayscad_model *mdl;
    rayscad_eval_options eo = {0};
    eo.for_mesh = 1; /* as -o evaluates it */
    rayscad_scene *scene;
    if (rayscad_model_load(model, &eo, &mdl) != RAYSCAD_OK) {
        fprintf(stderr, "meshdev: %s does not evaluate\n", model);
        return 2;
    }
    if (rayscad_scene_new(mdl, &scene, err, sizeof err) != RAYSCAD_OK) {
        fprintf(stderr, "meshdev: %s\n", err);
        return 2;
    }
    rayscad_model_free(mdl);
    rayscad_mesh_options mo;
    rayscad_mesh_options_default(&mo);
    mo.root = RAYSCAD_ROOT_MODEL;
    rayscad_sampling *sampling;
    if (rayscad_sampling_new(scene, &mo, &sampling, err, sizeof err) != RAYSCAD_OK) {
        fprintf(stderr, "meshdev: %s\n", err);
        return 2;
    }
    tmesh m;
    if (load(path, &m) != 0) return 2;
    const mesh_dexels *d = sampling->d;
    mesh_snapper sn;
    grid g;
    double diag = 0;
    for (int c = 0; c < 3; c++)
        diag = fmax(diag, m.hi[c] - m.lo[c]);
    if (mesh_snapper_init(&sn, d, -1) != 0 || grid_build(&g, &m, fmax(d->h, diag / 160)) != 0) {
        fprintf(stderr, "meshdev: out of memory\n");
        return 2;
    }
    tally t = {points ? fopen(points, "w") : NULL, tol, {0, 0}, {0, 0}};
    if (points && !t.out) {
        fprintf(stderr, "meshdev: cannot write %s\n", points);
        return 2;
    }
    double wm[3] = {0, 0, 0}, ws[3] = {0, 0, 0};
    double dm = surface_only ? 0 : mesh_to_surface(&m, &sn, d->h, REACH * tol, tol / 2, &t, wm);
    double ds = surface_to_mesh(d, &g, &t, ws);
    double pct[2];
    for (int w = 0; w < 2; w++)
        pct[w] = 100.0 * (double)t.over[w] / (double)(t.seen[w] + !t.seen[w]);
    int fail = share >= 0 ? !(pct[0] <= share && pct[1] <= share) : !(dm <= tol && ds <= tol);
    if (surface_only)
        printf("%-24s surface->mesh %9.3g  %5.2f D  %-4s  (at [%.4g, %.4g, %.4g])\n", name, ds,
               ds / tol, fail ? "FAIL" : "ok", ws[0], ws[1], ws[2]);
    else
        printf("%-24s mesh->surface %9.3g  surface->mesh %9.3g  %5.2f D  %-4s  (at [%.4g, %.4g, "
               "%.4g], [%.4g, %.4g, %.4g])\n",
               name, dm, ds, fmax(dm, ds) / tol, fail ? "FAIL" : "ok", wm[0], wm[1], wm[2], ws[0],
               ws[1], ws[2]);
    if (t.out) fclose(t.out);
    if (t.out || share >= 0) {
        printf("%-24s beyond D: mesh->surface %ld of %ld points (%.3g %%), surface->mesh %ld of "
               "%ld (%.3g %%)",
               "", t.over[0], t.seen[0], pct[0], t.over[1], t.seen[1], pct[1]);
        if (share >= 0) printf("; at most %g %% each way asked", share);
        printf("\n");
    }
    grid_free(&g);
    mesh_snapper_free(&sn);
    free(m.v);
    free(m.t);
    rayscad_sampling_free(sampling);
    rayscad_scene_free(scene);
    return fail;
}
