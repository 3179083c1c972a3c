/*
 * meshcmp.c — compare our mesh of a model with OpenSCAD's.
 *
 *   meshcmp OURS REF --h H [--name NAME] [--times OURS_S,REF_S]
 *           [--vol-tol 0.005] [--hausdorff-cells 2]
 *   meshcmp OURS REF --volume-only [--name NAME] [--vol-tol 0.005]
 *
 * Both files are read through OpenMesh (io_mesh_read; STL vertices that
 * coincide are merged).  Checks, each printed when it fails:
 *   - OURS is closed and 2-manifold with consistent orientation: every
 *     directed edge appears once and its reverse once (validatestl.py's edge
 *     pairing), and no triangle repeats a vertex;
 *   - signed volumes agree within --vol-tol (relative);
 *   - bounding boxes agree within H on every side;
 *   - the symmetric Hausdorff distance is at most --hausdorff-cells × H.
 * Hausdorff: points are sampled on every triangle of each mesh (its
 * vertices, and a barycentric lattice no coarser than H/2 along the longest
 * edge), and each point's distance to the nearest triangle of the other
 * mesh is exact (closest point on a triangle, Ericson's method), found
 * through a uniform grid of triangle boxes searched in growing shells until
 * no unseen cell can hold anything nearer.  It is the sampled maximum: the
 * distance is 1-Lipschitz and every point of a triangle lies within
 * (H/2)/√3 of a sample, so the true value exceeds it by at most 0.29 H.
 * --volume-only makes only the first two checks (the corpus's STL rule,
 * tests/cli/corpus.py), and prints "closed=0|1 volume=V ref_volume=W".
 * Prints one table row and exits 0 when every check passes, 1 when one
 * fails, 2 on bad input.
 */
#include "trimesh.h"

static double signed_volume(const tmesh *m)
{
    double s = 0;
    for (int q = 0; q < m->nt; q++) {
        const float *a = m->v + 3 * (size_t)m->t[3 * q], *b = m->v + 3 * (size_t)m->t[3 * q + 1],
                    *c = m->v + 3 * (size_t)m->t[3 * q + 2];
        s += ((double)a[0] * ((double)b[1] * c[2] - (double)b[2] * c[1]) -
              (double)a[1] * ((double)b[0] * c[2] - (double)b[2] * c[0]) +
              (double)a[2] * ((double)b[0] * c[1] - (double)b[1] * c[0])) /
             6;
    }
    return s;
}

/* ---- edge pairing ------------------------------------------------------- */

typedef struct {
    int32_t a, b;
} dedge;

static int cmp_dedge(const void *x, const void *y)
{
    const dedge *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    return p->b < q->b ? -1 : p->b > q->b;
}

/* NULL when every directed edge appears once and its reverse once, else
 * what is wrong. */
static const char *manifold_problem(const tmesh *m, long long *bad)
{
    size_t n = 3 * (size_t)m->nt;
    dedge *e = malloc((n ? n : 1) * sizeof *e);
    if (!e) return "out of memory";
    for (int q = 0; q < m->nt; q++)
        for (int k = 0; k < 3; k++) {
            int32_t a = m->t[3 * q + k], b = m->t[3 * q + (k + 1) % 3];
            if (a == b) {
                free(e);
                *bad = q;
                return "a triangle repeats a vertex";
            }
            e[3 * (size_t)q + k] = (dedge){a, b};
        }
    qsort(e, n, sizeof *e, cmp_dedge);
    const char *msg = NULL;
    *bad = 0;
    for (size_t i = 0; i < n; i++) {
        if (i + 1 < n && cmp_dedge(&e[i], &e[i + 1]) == 0) {
            msg = "a directed edge appears twice (non-manifold or flipped triangles)";
            (*bad)++;
            continue;
        }
        dedge r = {e[i].b, e[i].a};
        if (!bsearch(&r, e, n, sizeof *e, cmp_dedge)) {
            if (!msg) msg = "an edge without its reverse (a hole)";
            (*bad)++;
        }
    }
    free(e);
    return msg;
}

/* The largest distance from points sampled on `from` (spacing <= s) to `to`. */
static double directed_hausdorff(const tmesh *from, grid *to, double s, double where[3])
{
    double worst = 0;
    /* Vertices once each, then each triangle's lattice without its corners. */
    for (int i = 0; i < from->nv; i++) {
        double p[3];
        vertex(from, i, p);
        keep_worst(grid_nearest(to, p), p, &worst, where);
    }
    for (int q = 0; q < from->nt; q++) {
        double a[3], b[3], c[3];
        vertex(from, from->t[3 * q], a);
        vertex(from, from->t[3 * q + 1], b);
        vertex(from, from->t[3 * q + 2], c);
        double lmax =
            fmax(fmax(sqrt(geom_triangle_dist2(a, b, b, b)), sqrt(geom_triangle_dist2(b, c, c, c))),
                 sqrt(geom_triangle_dist2(c, a, a, a)));
        int n = (int)ceil(lmax / s);
        if (n < 1) n = 1;
        if (n > 4096) n = 4096;
        for (int i = 0; i <= n; i++)
            for (int j = 0; j <= n - i; j++) {
                if ((i == 0 && j == 0) || i == n || j == n) continue;
                double u = (double)i / n, v = (double)j / n, p[3];
                for (int k = 0; k < 3; k++)
                    p[k] = a[k] + u * (b[k] - a[k]) + v * (c[k] - a[k]);
                keep_worst(grid_nearest(to, p), p, &worst, where);
            }
    }
    return worst;
}

int main(int argc, char **argv)
{
    const char *ours = NULL, *ref = NULL, *name = "", *times = NULL;
    double h = 0, vol_tol = 0.005, cells = 2;
    int volume_only = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--volume-only") == 0)
            volume_only = 1;
        else if (i + 1 < argc && strcmp(argv[i], "--h") == 0)
            h = atof(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--name") == 0)
            name = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--times") == 0)
            times = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--vol-tol") == 0)
            vol_tol = atof(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--hausdorff-cells") == 0)
            cells = atof(argv[++i]);
        else if (!ours)
            ours = argv[i];
        else if (!ref)
            ref = argv[i];
        else
            ours = NULL, i = argc;
    }
    if (!ours || !ref || !(h > 0 || volume_only)) {
        fprintf(stderr, "usage: meshcmp OURS REF --h H [--name NAME] [--times A,B] "
                        "[--vol-tol X] [--hausdorff-cells N]\n"
                        "       meshcmp OURS REF --volume-only [--name NAME] [--vol-tol X]\n");
        return 2;
    }
    tmesh a, b;
    if (load(ours, &a) != 0 || load(ref, &b) != 0) return 2;
    int fail = 0;

    long long bad = 0;
    const char *mp = manifold_problem(&a, &bad);
    if (mp) {
        fprintf(stderr, "FAIL %s: ours is not closed and manifold: %s (%lld edges)\n", name, mp,
                bad);
        fail = 1;
    }
    double va = signed_volume(&a), vb = signed_volume(&b);
    double dv = (va - vb) / fabs(vb);
    if (!(fabs(dv) <= vol_tol)) {
        fprintf(stderr, "FAIL %s: volume %.6g vs OpenSCAD's %.6g (%.3f %%, tolerance %.3f %%)\n",
                name, va, vb, 100 * dv, 100 * vol_tol);
        fail = 1;
    }
    if (volume_only) {
        printf("closed=%d volume=%.9g ref_volume=%.9g\n", mp == NULL, va, vb);
        free(a.v);
        free(a.t);
        free(b.v);
        free(b.t);
        return fail;
    }
    double dbox = 0;
    for (int c = 0; c < 3; c++)
        dbox = fmax(dbox, fmax(fabs(a.lo[c] - b.lo[c]), fabs(a.hi[c] - b.hi[c])));
    if (!(dbox <= h)) {
        fprintf(stderr, "FAIL %s: bounding boxes differ by %g (> h = %g)\n", name, dbox, h);
        fail = 1;
    }
    /* Cells of about h, but no more than ~4M of them. */
    double diag = 0;
    for (int c = 0; c < 3; c++)
        diag = fmax(diag, fmax(a.hi[c], b.hi[c]) - fmin(a.lo[c], b.lo[c]));
    double cell = fmax(h, diag / 160);
    grid ga, gb;
    if (grid_build(&ga, &a, cell) != 0 || grid_build(&gb, &b, cell) != 0) {
        fprintf(stderr, "meshcmp: out of memory\n");
        return 2;
    }
    double wa[3] = {0, 0, 0}, wb[3] = {0, 0, 0};
    double hab = directed_hausdorff(&a, &gb, h / 2, wa);
    double hba = directed_hausdorff(&b, &ga, h / 2, wb);
    double hd = fmax(hab, hba);
    if (!(hd <= cells * h)) {
        const double *w = hab >= hba ? wa : wb;
        fprintf(stderr,
                "FAIL %s: Hausdorff distance %g (%.2f h) > %g h, at [%g, %g, %g] on %s mesh\n",
                name, hd, hd / h, cells, w[0], w[1], w[2], hab >= hba ? "our" : "OpenSCAD's");
        fail = 1;
    }
    char ta[32] = "-", tb[32] = "-";
    if (times) sscanf(times, "%31[^,],%31s", ta, tb);
    printf("%-24s %10.3f %10.3f %+7.3f%% %7.4f %5.2fh %8d %8d %8s %8s %s\n", name, va, vb, 100 * dv,
           hd, hd / h, a.nt, b.nt, ta, tb, fail ? "FAIL" : "ok");
    grid_free(&ga);
    grid_free(&gb);
    free(a.v);
    free(a.t);
    free(b.v);
    free(b.t);
    return fail;
}
