/*
 * extrude.c — the twisted and scaled linear_extrude of OpenSCAD 2021.01 as
 * a closed triangle mesh (extrude.h), and the slice count it defaults to.
 *
 * The mesh is OpenSCAD's own (extrudePolygon and add_slice): the outline
 * points at each of the slices + 1 layers turned by -twist·j/slices and
 * scaled by 1 - (1 - scale)·j/slices about the origin, every quad between
 * two layers split along its shorter diagonal (ties broken as OpenSCAD
 * does: by the path's sign and the twist's direction), the caps flat.
 * OpenSCAD walks outer paths counter-clockwise and holes clockwise (as
 * Clipper leaves them) and emits its triangles clockwise seen from outside,
 * iv_shape_mesh's winding; the faces here are those triangles.  (The walk
 * decides which diagonal a tie takes: an edge in line with the origin has
 * two equal diagonals, and the twisted square at x = 10 of
 * tests/mesh_models/twist_ties.scad differs by 10 % the other way.)
 */
#include "extrude.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "earcut.h"
#include "fragments.h"

static double archimedes_length(double a, double theta)
{
    return 0.5 * a * (theta * sqrt(1 + theta * theta) + asinh(theta));
}

int geom_extrusion_slices(const geom_extrusion *e, double max_r2, double max_d2, double fn,
                          double fa, double fs)
{
    double sx = e->scale[0], sy = e->scale[1], h = e->h2 - e->h1;
    if (e->twist != 0) {
        double tw = fabs(e->twist), r = sqrt(max_r2);
        int min_slices = (int)fmax(ceil(tw / 120.0), 1);
        if (r < GEOM_GRID_FINE || !isfinite(fn)) return min_slices;
        if (fn > 0) return (int)fmax(ceil(tw / 360.0 * fn), min_slices);
        double len, rads = tw * IV_PI / 180;
        if ((sx == 1 && sy == 1) || sx != sy) { /* a helix */
            double k = h / rads;
            len = rads * sqrt(max_r2 + k * k);
        } else { /* uniform scale: a conical helix, its plan an Archimedes spiral */
            double end = sx > 1 ? rads * sx / (sx - 1) : rads / (1 - sx);
            double a = r / end;
            double spiral = archimedes_length(a, end) - archimedes_length(a, end - rads);
            len = sqrt(spiral * spiral + h * h);
        }
        double fs_slices = ceil(len / fmax(fs, 0.01)), fa_slices = ceil(tw / fmax(fa, 0.01));
        double n = fmax(fmin(fa_slices, fs_slices), min_slices);
        return n > 100000 ? 100000 : (int)n;
    }
    if (sx != sy) { /* non-uniform scale alone: the longest diagonal path */
        if (sqrt(max_d2) < GEOM_GRID_FINE || !isfinite(fn)) return 1;
        if (fn > 0) return fn > 100000 ? 100000 : (int)fmax(fn, 1);
        double n = fmax(ceil(sqrt(max_d2 + h * h) / fmax(fs, 0.01)), 1);
        return n > 100000 ? 100000 : (int)n;
    }
    return 1;
}

/* OpenSCAD's sgn_vdiff: compares |a| with |b|, equal within 10 ppm of
 * their mean, so that the diagonal choice below does not flip on
 * rounding. */
static int length_order(double ax, double ay, double bx, double by)
{
    double l1 = hypot(ax, ay), l2 = hypot(bx, by);
    return 2 * fabs(l1 - l2) * 1e5 > l1 + l2 ? (l1 < l2 ? -1 : 1) : 0;
}

typedef struct mesh_build {
    double (*v)[3];
    int nv, capv;
    int *idx, nidx, capidx;
    int *start, nf, capf;
    int oom;
} mesh_build;

static int mb_vertex(mesh_build *m, double x, double y, double z)
{
    if (m->nv == m->capv) {
        int cap = m->capv ? 2 * m->capv : 256;
        double(*v)[3] = realloc(m->v, (size_t)cap * sizeof *v);
        if (!v) {
            m->oom = 1;
            return 0;
        }
        m->v = v;
        m->capv = cap;
    }
    m->v[m->nv][0] = x;
    m->v[m->nv][1] = y;
    m->v[m->nv][2] = z;
    return m->nv++;
}

/* Append a face of k vertex indices (iv_shape_mesh's winding). */
static void mb_face(mesh_build *m, const int *f, int k)
{
    if (m->nidx + k > m->capidx) {
        int cap = m->capidx ? 2 * m->capidx : 1024;
        while (cap < m->nidx + k)
            cap *= 2;
        int *v = realloc(m->idx, (size_t)cap * sizeof *v);
        if (!v) {
            m->oom = 1;
            return;
        }
        m->idx = v;
        m->capidx = cap;
    }
    if (m->nf + 2 > m->capf) {
        int cap = m->capf ? 2 * m->capf : 256;
        int *v = realloc(m->start, (size_t)cap * sizeof *v);
        if (!v) {
            m->oom = 1;
            return;
        }
        m->start = v;
        m->capf = cap;
    }
    if (m->nf == 0) m->start[0] = 0;
    memcpy(m->idx + m->nidx, f, (size_t)k * sizeof *f);
    m->nidx += k;
    m->start[++m->nf] = m->nidx;
}

static void mb_free(mesh_build *m)
{
    free(m->v);
    free(m->idx);
    free(m->start);
}

typedef struct keyed_vertex {
    double p[3];
    int i;
} keyed_vertex;

static int cmp_keyed(const void *a, const void *b)
{
    const keyed_vertex *u = a, *v = b;
    for (int k = 0; k < 3; k++)
        if (u->p[k] != v->p[k]) return u->p[k] < v->p[k] ? -1 : 1;
    return 0;
}

/* Merge vertices at exactly the same position (a zero scale collapses a
 * layer), then drop repeated indices within each face and faces left with
 * fewer than 3: what OpenSCAD's PolySet does when it becomes a mesh. */
static void mb_weld(mesh_build *m)
{
    int n = m->nv;
    keyed_vertex *order = malloc((size_t)(n ? n : 1) * sizeof *order);
    int *to = malloc((size_t)(n ? n : 1) * sizeof *to);
    if (!order || !to) {
        free(order);
        free(to);
        m->oom = 1;
        return;
    }
    for (int i = 0; i < n; i++) {
        memcpy(order[i].p, m->v[i], sizeof order[i].p);
        order[i].i = i;
    }
    qsort(order, (size_t)n, sizeof *order, cmp_keyed);
    for (int i = 0; i < n; i++)
        to[order[i].i] =
            i > 0 && cmp_keyed(&order[i - 1], &order[i]) == 0 ? to[order[i - 1].i] : order[i].i;
    int k = 0, nf = 0;
    for (int f = 0; f < m->nf; f++) {
        int s = m->start[f], e = m->start[f + 1], k0 = k;
        for (int i = s; i < e; i++) {
            int x = to[m->idx[i]];
            if (k > k0 && m->idx[k - 1] == x) continue;
            m->idx[k++] = x;
        }
        while (k - k0 > 1 && m->idx[k - 1] == m->idx[k0])
            k--;
        if (k - k0 < 3) {
            k = k0;
            continue;
        }
        m->start[nf] = k0;
        m->start[++nf] = k;
    }
    m->nidx = k;
    m->nf = nf;
    free(order);
    free(to);
}

/* Whether the path of k vertices from vertex b turns left at every one. */
static int convex_alone(const mesh_build *m, int b, int k)
{
    for (int i = 0; i < k; i++) {
        const double *a = m->v[b + i], *p = m->v[b + (i + 1) % k], *c = m->v[b + (i + 2) % k];
        if (!((p[0] - a[0]) * (c[1] - p[1]) - (p[1] - a[1]) * (c[0] - p[0]) > 0)) return 0;
    }
    return 1;
}

/* A flat cap face f of k vertices.  The mesh splits a polygon face into a
 * fan from its first vertex, long thin triangles all through one corner,
 * whose boxes a ray over a cap of many points meets by the thousand; a
 * strictly convex cap (a circle's), when it is the only path, goes in as
 * a zig-zag strip instead: triangles across the cap, side by side, the
 * same solid (they tile it without overlap). */
static void cap_face(mesh_build *m, const int *f, int k, int alone)
{
    if (!alone || k <= 3 || f[1] != f[0] + 1 || !convex_alone(m, f[0], k)) {
        mb_face(m, f, k);
        return;
    }
    for (int lo = 0, hi = k - 1; hi - lo >= 2;) {
        mb_face(m, (int[3]){f[lo], f[lo + 1], f[hi]}, 3);
        if (hi - ++lo >= 2) mb_face(m, (int[3]){f[lo], f[hi - 1], f[hi]}, 3);
        hi--;
    }
}

/* The caps: the region cut into triangles (geom_region_triangles: each
 * outer path with the holes right inside it), the same triangles turned to
 * the top (its layer is the bottom's turned and scaled: an affine map,
 * which keeps them apart), so that they meet only at their edges and the
 * mesh bounds its solid.  A lone strictly convex path, and a region the
 * cut refuses (paths that touch), as each path its own face (cap_face:
 * the holes' faces cancel the outer's under the nonzero rule).  Region
 * point x = ps[p] + j of path p (k points) is vertex vert[x] = base[p] + j,
 * or base[p] + k - 1 - j where the walk turned path p (rev), and S layers
 * up vert[n + x] = vert[x] + S k.  0, or -1 when out of memory. */
static int caps(mesh_build *m, const double (*P)[2], const int *ps, int np, const int *base,
                const signed char *rev, int S, int top)
{
    int(*tri)[3] = NULL, nt = -1, *vert = NULL, n = ps[np];
    if (np > 1 || !convex_alone(m, base[0], ps[1] - ps[0])) {
        nt = geom_region_triangles(P, ps, np, &tri);
        vert = malloc(2 * (size_t)n * sizeof *vert);
        if (nt >= 0 && !vert) {
            free(tri);
            return -1;
        }
        for (int p = 0; vert && p < np; p++)
            for (int j = 0, k = ps[p + 1] - ps[p]; j < k; j++) {
                vert[ps[p] + j] = base[p] + (rev[p] ? k - 1 - j : j);
                vert[n + ps[p] + j] = vert[ps[p] + j] + S * k;
            }
    }
    for (int t = 0; t < nt; t++) {
        int lo[3], up[3];
        for (int j = 0; j < 3; j++) {
            lo[j] = vert[tri[t][j]];
            up[2 - j] = vert[n + tri[t][j]];
        }
        mb_face(m, lo, 3);
        if (top) mb_face(m, up, 3);
    }
    free(tri);
    free(vert);
    for (int p = 0; nt < 0 && p < np; p++) { /* each path its own face */
        int k = ps[p + 1] - ps[p], b = base[p];
        int *f = malloc((size_t)k * sizeof *f);
        if (!f) return -1;
        for (int i = 0; i < k; i++)
            f[i] = b + i;
        cap_face(m, f, k, np == 1);
        if (top) {
            for (int i = 0; i < k; i++)
                f[i] = b + S * k + (k - 1 - i);
            cap_face(m, f, k, np == 1);
        }
        free(f);
    }
    return 0;
}

int geom_extrusion_mesh(const geom_extrusion *c, const iv_region *r, iv_shape *out)
{
    int n, np;
    const double(*P)[2] = iv_region_points(r, &n);
    const int *ps = iv_region_paths(r, &np);
    int S = c->slices;
    mesh_build m = {0};
    int *base = malloc((size_t)np * sizeof *base); /* first vertex of each path */
    signed char *outer = malloc((size_t)(np ? np : 1)), *rev = malloc((size_t)(np ? np : 1));
    if (!base || !outer || !rev) {
        free(base);
        free(outer);
        free(rev);
        return -1;
    }
    /* outline order: outer paths (even nesting depth) counter-clockwise,
     * holes clockwise, as Clipper's sanitising leaves them for 2021.01 */
    for (int p = 0; p < np; p++) {
        const double(*Q)[2] = P + ps[p];
        int k = ps[p + 1] - ps[p];
        double area = 0;
        for (int i = 0, j = k - 1; i < k; j = i++)
            area += Q[j][0] * Q[i][1] - Q[i][0] * Q[j][1];
        int depth = 0;
        for (int q = 0; q < np; q++)
            if (q != p && geom_path_contains(P + ps[q], ps[q + 1] - ps[q], Q[0][0], Q[0][1]))
                depth++;
        outer[p] = depth % 2 == 0;
        int reverse = rev[p] = outer[p] ? area < 0 : area > 0;
        base[p] = m.nv;
        for (int j = 0; j <= S; j++) {
            double rot = c->twist * j / S;
            double sx = 1 - (1 - c->scale[0]) * j / S, sy = 1 - (1 - c->scale[1]) * j / S;
            double z = c->h1 + (c->h2 - c->h1) * j / S;
            double cs = iv_cos_degrees(-rot), sn = iv_sin_degrees(-rot);
            for (int i = 0; i < k; i++) {
                const double *q = Q[reverse ? k - 1 - i : i];
                mb_vertex(&m, sx * (cs * q[0] - sn * q[1]), sy * (sn * q[0] + cs * q[1]), z);
            }
        }
    }
    if (m.oom) goto fail;
    int back_twist = c->twist <= 0;
    for (int p = 0; p < np; p++) {
        int k = ps[p + 1] - ps[p], b = base[p];
        int flip = !outer[p] ^ back_twist;
        for (int j = 0; j < S; j++) {
            double s2x = 1 - (1 - c->scale[0]) * (j + 1) / S;
            double s2y = 1 - (1 - c->scale[1]) * (j + 1) / S;
            int any_zero = s2x == 0 || s2y == 0, any_non_zero = s2x != 0 || s2y != 0;
            for (int i = 1; i <= k; i++) {
                int p1 = b + j * k + (i - 1), c1 = b + j * k + i % k;
                int p2 = p1 + k, c2 = c1 + k;
                const double *P1 = m.v[p1], *C1 = m.v[c1], *P2 = m.v[p2], *C2 = m.v[c2];
                int d = length_order(P1[0] - C2[0], P1[1] - C2[1], C1[0] - P2[0], C1[1] - P2[1]);
                int split_first = d == -1 || (d == 0 && !flip);
                int second = !any_zero || (any_non_zero && (P2[0] != C2[0] || P2[1] != C2[1]));
                /* OpenSCAD's triangles */
                if (split_first ^ any_zero) {
                    mb_face(&m, (int[3]){p1, c2, c1}, 3);
                    if (second) mb_face(&m, (int[3]){c2, p1, p2}, 3);
                } else {
                    mb_face(&m, (int[3]){p1, p2, c1}, 3);
                    if (second) mb_face(&m, (int[3]){p2, c2, c1}, 3);
                }
            }
        }
    }
    /* caps: the bottom counter-clockwise seen from above (clockwise seen
     * from outside, below), the top clockwise; no top at a zero scale */
    int top = c->scale[0] > 0 && c->scale[1] > 0;
    if (!m.oom && caps(&m, P, ps, np, base, rev, S, top) != 0) m.oom = 1;
    if (m.oom) goto fail;
    mb_weld(&m);
    if (m.oom || m.nf == 0) goto fail;
    int rc = iv_shape_mesh(out, (const double(*)[3])m.v, m.nv, m.idx, m.start, m.nf);
    free(base);
    free(rev);
    free(outer);
    mb_free(&m);
    return rc < 0 ? -1 : 0;
fail:
    free(base);
    free(rev);
    free(outer);
    mb_free(&m);
    return -1;
}
