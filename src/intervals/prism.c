/*
 * prism.c — 2D regions (closed paths, even-odd rule) and the prisms over
 * them: a 2D shape in the preview slab, and linear_extrude without twist.
 *
 * A region's paths are re-oriented at creation so that the region lies on
 * their left (outer paths counter-clockwise, holes clockwise, by nesting
 * parity), which gives every edge an outward normal without knowing the ray.
 *
 * A line meets a prism where its xy shadow is inside the region and its z is
 * inside the slab.  The shadow's crossings with the region's edges are found
 * by classifying every vertex once by the side of the shadow line it lies on
 * (a vertex on the line counts as left, the same as moving the line a little
 * to the right), and an edge crosses exactly when its ends differ.  So every
 * vertex is decided once for both edges that share it: a line through a
 * vertex, or along an edge, crosses an even number of times per closed path,
 * and the even-odd pairing of the sorted crossings is always consistent.
 * The crossings are computed into the caller's list as scratch and rewritten
 * in place as spans, each cut to the slab.
 */
#include "shape_kinds.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

static atomic_int *refs_of(iv_region *g)
{
    return &g->refs;
}

void iv_region_retain(iv_region *g)
{
    if (g) atomic_fetch_add(refs_of(g), 1);
}

void iv_region_release(iv_region *g)
{
    if (!g || atomic_fetch_sub(refs_of(g), 1) != 1) return;
    free(g->pt);
    free(g->start);
    free(g);
}

int iv_region_next(const iv_region *g, int e)
{
    int p = iv_region_path_of(g, e);
    return e + 1 < g->start[p + 1] ? e + 1 : g->start[p];
}

int iv_region_nearest_edge(const iv_region *g, int first, int stride, double x, double y)
{
    int best = -1;
    double bd = INFINITY;
    for (int e = first; e < g->npts; e += stride) {
        const double *a = g->pt[e], *b = g->pt[iv_region_next(g, e)];
        double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
        double u = l2 > 0 ? ((x - a[0]) * ex + (y - a[1]) * ey) / l2 : 0;
        u = u < 0 ? 0 : u > 1 ? 1 : u;
        double qx = a[0] + u * ex - x, qy = a[1] + u * ey - y;
        double dist = qx * qx + qy * qy;
        if (dist < bd) {
            bd = dist;
            best = e;
        }
    }
    return best;
}

int iv_region_path_of(const iv_region *g, int e)
{
    int lo = 0, hi = g->npaths - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (g->start[mid] <= e)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/* Even-odd test of (x, y) against paths [p0, p1) of g. */
static int contains_paths(const iv_region *g, int p0, int p1, double x, double y)
{
    int in = 0;
    for (int p = p0; p < p1; p++) {
        int a = g->start[p], b = g->start[p + 1];
        for (int i = a, j = b - 1; i < b; j = i++) {
            const double *u = g->pt[i], *v = g->pt[j];
            if ((u[1] > y) != (v[1] > y) && x < (v[0] - u[0]) * (y - u[1]) / (v[1] - u[1]) + u[0])
                in = !in;
        }
    }
    return in;
}

int iv_region_contains(const iv_region *g, double x, double y)
{
    return contains_paths(g, 0, g->npaths, x, y);
}

/* 1 when the path's points lie on one line (each within 1e-12 of the
 * path's extent of the line through the first point and the point
 * farthest from it): it bounds nothing, as Clipper's cleaning in OpenSCAD
 * finds, and its coincident sides would only meet a ray in rounding noise.
 * (Not its signed area: a symmetric bow-tie's is 0 too.) */
static int flat_path(const double (*pt)[2], int n)
{
    int far = 0;
    double d2 = 0;
    for (int i = 1; i < n; i++) {
        double dx = pt[i][0] - pt[0][0], dy = pt[i][1] - pt[0][1];
        if (dx * dx + dy * dy > d2) d2 = dx * dx + dy * dy, far = i;
    }
    if (!(d2 > 0)) return 1;
    double ux = pt[far][0] - pt[0][0], uy = pt[far][1] - pt[0][1];
    for (int i = 1; i < n; i++) {
        double cross = ux * (pt[i][1] - pt[0][1]) - uy * (pt[i][0] - pt[0][0]);
        /* cross / |u| is the distance; compare squared against 1e-12 |u| */
        if (cross * cross > 1e-24 * d2 * d2) return 0;
    }
    return 1;
}

iv_region *iv_region_new(const double (*pts)[2], const int *path_start, int npaths)
{
    iv_region *g = calloc(1, sizeof *g);
    if (!g) return NULL;
    int total = path_start[npaths] - path_start[0];
    g->pt = malloc((size_t)(total > 0 ? total : 1) * sizeof *g->pt);
    g->start = malloc((size_t)(npaths + 1) * sizeof *g->start);
    if (!g->pt || !g->start) goto fail;
    int n = 0, np = 0;
    g->start[0] = 0;
    for (int p = 0; p < npaths; p++) {
        int first = n;
        for (int i = path_start[p]; i < path_start[p + 1]; i++) {
            if (!isfinite(pts[i][0]) || !isfinite(pts[i][1])) goto fail;
            /* drop repeated points, including the closing one */
            if (n > first && g->pt[n - 1][0] == pts[i][0] && g->pt[n - 1][1] == pts[i][1]) continue;
            g->pt[n][0] = pts[i][0];
            g->pt[n][1] = pts[i][1];
            n++;
        }
        while (n - first > 1 && g->pt[n - 1][0] == g->pt[first][0] &&
               g->pt[n - 1][1] == g->pt[first][1])
            n--;
        if (n - first < 3 || flat_path((const double(*)[2])(g->pt + first), n - first)) {
            n = first;
            continue;
        }
        g->start[++np] = n;
    }
    if (np == 0) goto fail;
    g->npts = n;
    g->npaths = np;
    g->lo[0] = g->lo[1] = INFINITY;
    g->hi[0] = g->hi[1] = -INFINITY;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 2; k++) {
            g->lo[k] = fmin(g->lo[k], g->pt[i][k]);
            g->hi[k] = fmax(g->hi[k], g->pt[i][k]);
        }
    /* Orientation by nesting parity: a path inside an even number of the
     * others bounds the region from outside and must turn left. */
    for (int p = 0; p < np; p++) {
        int a = g->start[p], b = g->start[p + 1];
        double area = 0;
        for (int i = a, j = b - 1; i < b; j = i++)
            area += (g->pt[j][0] - g->pt[i][0]) * (g->pt[j][1] + g->pt[i][1]);
        /* area is twice the signed area (positive: counter-clockwise) */
        int depth = contains_paths(g, 0, p, g->pt[a][0], g->pt[a][1]) ^
                    contains_paths(g, p + 1, np, g->pt[a][0], g->pt[a][1]);
        int want_ccw = !depth;
        if ((area > 0) != want_ccw) {
            for (int i = a, j = b - 1; i < j; i++, j--) {
                double t0 = g->pt[i][0], t1 = g->pt[i][1];
                g->pt[i][0] = g->pt[j][0];
                g->pt[i][1] = g->pt[j][1];
                g->pt[j][0] = t0;
                g->pt[j][1] = t1;
            }
        }
    }
    atomic_init(refs_of(g), 1);
    return g;
fail:
    free(g->pt);
    free(g->start);
    free(g);
    return NULL;
}

const double (*iv_region_points(const iv_region *g, int *n))[2]
{
    *n = g->npts;
    return (const double(*)[2])g->pt;
}

const int *iv_region_paths(const iv_region *g, int *npaths)
{
    *npaths = g->npaths;
    return g->start;
}

void iv_shape_prism(iv_shape *s, iv_region *g, double z0, double z1)
{
    memset(s, 0, sizeof *s);
    s->kind = IV_SHAPE_PRISM;
    iv_region_retain(g);
    s->u.prism.g = g;
    s->u.prism.z0 = z0;
    s->u.prism.z1 = z1;
}

int iv_prism_max_spans(const iv_shape *s)
{
    return s->u.prism.g ? s->u.prism.g->npts / 2 + 1 : 1;
}

int iv_prism_bounds(const iv_shape *s, double lo[3], double hi[3])
{
    const iv_region *g = s->u.prism.g;
    double z0 = s->u.prism.z0, z1 = s->u.prism.z1;
    if (!(z0 < z1) || !isfinite(z0) || !isfinite(z1)) return -1;
    if (g) {
        lo[0] = g->lo[0];
        lo[1] = g->lo[1];
        hi[0] = g->hi[0];
        hi[1] = g->hi[1];
    } else {
        double r = s->u.prism.r;
        if (!(r > 0) || !isfinite(r)) return -1;
        lo[0] = lo[1] = -r;
        hi[0] = hi[1] = r;
    }
    lo[2] = z0;
    hi[2] = z1;
    return 0;
}

static int emit(iv_list *out, int at, double t0, int p0, double t1, int p1, int32_t prim)
{
    (void)out;
    iv_span *s = &out->v[at];
    s->enter = (iv_bound){t0, prim, (uint16_t)p0, 0};
    s->exit = (iv_bound){t1, prim, (uint16_t)p1, 0};
    return 1;
}

int iv_prism_intersect(const iv_shape *s, const double o[3], const double d[3], int32_t prim,
                       iv_list *out)
{
    const double z0 = s->u.prism.z0, z1 = s->u.prism.z1;
    double s0, s1;
    int c0 = IV_PART_PRISM_BOTTOM, c1 = IV_PART_PRISM_TOP;
    if (!(z0 < z1) || !iv_slab(o[2], d[2], z0, z1, &s0, &s1, &c0, &c1)) return 0;
    const iv_region *g = s->u.prism.g;
    const double dx = d[0], dy = d[1], ox = o[0], oy = o[1];
    const double A = dx * dx + dy * dy;
    if (out->n >= out->cap) return -1;
    if (!g) {
        /* Disc: the 2D version of shapes.c's sphere, same cancellation
         * care. */
        const double r = s->u.prism.r;
        double C = ox * ox + oy * oy - r * r;
        if (A == 0) {
            if (!(C <= 0) || !(s0 < s1)) return 0;
            emit(out, out->n++, s0, c0, s1, c1, prim);
            return 1;
        }
        double B = ox * dx + oy * dy, sc = B / A;
        double fx = ox - sc * dx, fy = oy - sc * dy;
        double lf = sqrt(fx * fx + fy * fy);
        double disc = A * (r - lf) * (r + lf);
        if (!(disc > 0)) return 0;
        double ta, tb;
        iv_quadratic_roots(A, B, C, disc, &ta, &tb);
        int pa = IV_PART_PRISM_EDGE, pb = IV_PART_PRISM_EDGE;
        if (!(ta > s0)) ta = s0, pa = c0;
        if (!(tb < s1)) tb = s1, pb = c1;
        if (!(ta < tb)) return 0;
        emit(out, out->n++, ta, pa, tb, pb, prim);
        return 1;
    }
    if (A == 0) {
        if (!iv_region_contains(g, ox, oy) || !(s0 < s1)) return 0;
        emit(out, out->n++, s0, c0, s1, c1, prim);
        return 1;
    }
    iv_bound *c = &out->v[out->n].enter;
    const long room = 2L * (out->cap - out->n);
    long nc = 0;
    for (int p = 0; p < g->npaths; p++) {
        int a = g->start[p], b = g->start[p + 1];
        const double *v0 = g->pt[b - 1];
        double w0 = dx * (v0[1] - oy) - dy * (v0[0] - ox);
        for (int i = a; i < b; i++) {
            const double *v1 = g->pt[i];
            double w1 = dx * (v1[1] - oy) - dy * (v1[0] - ox);
            if ((w0 >= 0) != (w1 >= 0)) {
                double f = w0 / (w0 - w1);
                double qx = v0[0] + f * (v1[0] - v0[0]), qy = v0[1] + f * (v1[1] - v0[1]);
                double t = ((qx - ox) * dx + (qy - oy) * dy) / A;
                if (nc >= room) return -1;
                int e = i == a ? b - 1 : i - 1; /* the edge from v0 to v1 */
                c[nc++] = (iv_bound){t, prim, (uint16_t)((IV_PART_PRISM_EDGE + e) & 0xffff), 0};
            }
            v0 = v1;
            w0 = w1;
        }
    }
    iv_bounds_sort(c, nc);
    int ns = 0;
    for (long i = 0; i + 1 < nc; i += 2) {
        double ta = c[i].t, tb = c[i + 1].t;
        int pa = c[i].part, pb = c[i + 1].part;
        if (!(ta > s0)) ta = s0, pa = c0;
        if (!(tb < s1)) tb = s1, pb = c1;
        if (!(ta < tb)) continue;
        /* Touching spans (a line through a reflex vertex) merge, as the
         * list invariant requires. */
        if (ns > 0 && out->v[out->n + ns - 1].exit.t >= ta) {
            out->v[out->n + ns - 1].exit = (iv_bound){tb, prim, (uint16_t)pb, 0};
            continue;
        }
        emit(out, out->n + ns, ta, pa, tb, pb, prim);
        ns++;
    }
    out->n += ns;
    return ns;
}

void iv_prism_normal(const iv_shape *s, const double p[3], int part, double n[3])
{
    n[0] = n[1] = n[2] = 0;
    if (part == IV_PART_PRISM_BOTTOM || part == IV_PART_PRISM_TOP) {
        n[2] = part == IV_PART_PRISM_TOP ? 1 : -1;
        return;
    }
    const iv_region *g = s->u.prism.g;
    if (!g) {
        double r = sqrt(p[0] * p[0] + p[1] * p[1]);
        if (r > 0 && isfinite(r)) {
            n[0] = p[0] / r;
            n[1] = p[1] / r;
        } else {
            n[0] = 1;
        }
        return;
    }
    int best = iv_region_nearest_edge(g, (part - IV_PART_PRISM_EDGE) & 0xffff, 65536, p[0], p[1]);
    if (best < 0) {
        n[2] = 1;
        return;
    }
    const double *a = g->pt[best], *b = g->pt[iv_region_next(g, best)];
    double ex = b[0] - a[0], ey = b[1] - a[1], l = sqrt(ex * ex + ey * ey);
    if (l > 0) {
        /* region on the left: outward is the right-hand normal */
        n[0] = ey / l;
        n[1] = -ex / l;
    } else {
        n[2] = 1;
    }
}
