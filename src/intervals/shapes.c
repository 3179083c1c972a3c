/*
 * shapes.c — where a line meets each primitive, the outward normals, and the
 * object-space bounds.
 *
 * The primitives here are convex, so the points of the line o + t·d inside
 * one form one closed interval (possibly infinite, possibly empty); the
 * functions here compute that interval for all t, not just t >= 0, and append
 * it as at most one span.  The kinds with shared data (polytope, mesh, prism,
 * revolve) live in their own files and are only dispatched from here, as are
 * their reference counts.  The invariant that everything else relies on: a span is appended
 * only when enter.t < exit.t, tested as `t0 < t1` so that a NaN (which cannot
 * arise from finite inputs here, but would from NaN inputs) never gets into a
 * list.  Tangent contact, grazing a curved surface and zero-length chords give
 * no span; a line lying in a flat face (a halfspace's plane, a slab's plane)
 * counts as inside, like the closed solid, so adjacent boxes leave no crack
 * along a shared face.
 */
#include "shape_kinds.h"
#include "vec3.h"

#include <math.h>

/* Append [t0, t1] with the given parts; 0 when it would be empty. */
static int emit(iv_list *out, double t0, int p0, double t1, int p1, int32_t prim)
{
    if (!(t0 < t1)) return 0;
    if (out->n >= out->cap) return -1;
    iv_span *s = &out->v[out->n++];
    s->enter = (iv_bound){t0, prim, (uint16_t)p0, 0};
    s->exit = (iv_bound){t1, prim, (uint16_t)p1, 0};
    return 1;
}

static int halfspace(const double n[3], double hd, const double o[3], const double d[3],
                     int32_t prim, iv_list *out)
{
    /* n·(o + t d) <= hd  <=>  a t + c <= 0 with a = n·d, c = n·o - hd. */
    double a = dot3(n, d), c = dot3(n, o) - hd;
    if (a == 0) return c <= 0 ? emit(out, -INFINITY, 0, INFINITY, 0, prim) : 0;
    /* A tiny |a| may push -c/a to ±inf; the span is then the whole line or
     * nothing, which is what the limit says. */
    double t = -c / a;
    if (a > 0) return emit(out, -INFINITY, IV_PART_SURFACE, t, IV_PART_SURFACE, prim);
    return emit(out, t, IV_PART_SURFACE, INFINITY, IV_PART_SURFACE, prim);
}

static int sphere(double r, const double o[3], const double d[3], int32_t prim, iv_list *out)
{
    if (!(r > 0)) return 0;
    /* |o + t d|² = r²  <=>  A t² + 2B t + C = 0.  */
    double A = dot3(d, d), B = dot3(o, d), C = dot3(o, o) - r * r;
    if (A == 0) /* d = 0: the "line" is the point o */
        return C <= 0 ? emit(out, -INFINITY, 0, INFINITY, 0, prim) : 0;
    /* B² - AC cancels badly when the sphere is small and far from o.  As in
     * pbrt-v4, use B² - AC = A (r² - |f|²) where f = o - (B/A) d is the point
     * of the line closest to the centre, and factor r² - |f|² so that the
     * subtraction happens between two lengths, not their squares. */
    double s = B / A;
    double f[3] = {o[0] - s * d[0], o[1] - s * d[1], o[2] - s * d[2]};
    double lf = sqrt(dot3(f, f));
    double disc = A * (r - lf) * (r + lf);
    if (!(disc > 0)) /* miss, or tangent: a single point is no span */
        return 0;
    double t0, t1;
    iv_quadratic_roots(A, B, C, disc, &t0, &t1);
    return emit(out, t0, IV_PART_SURFACE, t1, IV_PART_SURFACE, prim);
}

static int box(const double lo[3], const double hi[3], const double o[3], const double d[3],
               int32_t prim, iv_list *out)
{
    double t0 = -INFINITY, t1 = INFINITY;
    int p0 = IV_PART_BOX_XMIN, p1 = IV_PART_BOX_XMAX;
    for (int k = 0; k < 3; k++) {
        double ta, tb;
        int pa = 2 * k, pb = 2 * k + 1;
        if (!(lo[k] < hi[k]) || !iv_slab(o[k], d[k], lo[k], hi[k], &ta, &tb, &pa, &pb)) return 0;
        if (ta > t0) {
            t0 = ta;
            p0 = pa;
        }
        if (tb < t1) {
            t1 = tb;
            p1 = pb;
        }
    }
    return emit(out, t0, p0, t1, p1, prim);
}

static int cone_valid(double r1, double r2, double h)
{
    return h > 0 && r1 >= 0 && r2 >= 0 && (r1 > 0 || r2 > 0) && isfinite(h) && isfinite(r1) &&
           isfinite(r2);
}

/* Intersect [c0, c1] (parts q0, q1) with [s0, s1] (parts z0, z1), keeping the
 * part of whichever bound is tighter; ties go to the cap. */
static void clamp_piece(double *c0, int *q0, double *c1, int *q1, double s0, int z0, double s1,
                        int z1)
{
    if (!(*c0 > s0)) {
        *c0 = s0;
        *q0 = z0;
    }
    if (!(*c1 < s1)) {
        *c1 = s1;
        *q1 = z1;
    }
}

static int cone(double r1, double r2, double h, const double o[3], const double d[3], int32_t prim,
                iv_list *out)
{
    if (!cone_valid(r1, r2, h)) return 0;
    /* The slab 0 <= z <= h, handled like a box slab. */
    double s0, s1;
    int z0 = IV_PART_CONE_BOTTOM, z1 = IV_PART_CONE_TOP;
    if (!iv_slab(o[2], d[2], 0, h, &s0, &s1, &z0, &z1)) return 0;
    /* The side: Q = x² + y² - r(z)² <= 0 with r(z) = r1 + k z.  Along the
     * line Q(t) = A t² + 2B t + C.  Q <= 0 is the solid double cone (or a
     * cylinder when k = 0); its second nappe has r(z) < 0, which only
     * happens outside 0 <= z <= h, so the slab removes it. */
    const double k = (r2 - r1) / h;
    const double w = r1 + k * o[2], wd = k * d[2];
    const double dxy = d[0] * d[0] + d[1] * d[1];
    const double A = dxy - wd * wd;
    const double B = o[0] * d[0] + o[1] * d[1] - w * wd;
    const double C = o[0] * o[0] + o[1] * o[1] - w * w;
    const int S = IV_PART_CONE_SIDE;
    /* Up to two pieces of the line where Q <= 0. */
    double c0[2], c1[2];
    int q0[2] = {S, S}, q1[2] = {S, S};
    int np;
    if (A == 0) {
        /* Linear: 2B t + C <= 0.  Covers the ray along a cylinder's axis
         * (B = 0: inside for all t or none) and rays parallel to a
         * generator of the cone. */
        np = 1;
        if (B == 0) {
            /* Q is the constant C; C = 0 is a line lying in the curved
             * surface, which grazes it. */
            if (!(C < 0)) return 0;
            c0[0] = -INFINITY;
            c1[0] = INFINITY;
        } else if (B > 0) {
            c0[0] = -INFINITY;
            c1[0] = -C / (2 * B);
        } else {
            c0[0] = -C / (2 * B);
            c1[0] = INFINITY;
        }
    } else {
        /* B² - AC = -A·Q(t*) at the vertex t* = -B/A.  When A is not much
         * smaller than its terms, evaluate Q(t*) at the point itself and
         * factor it as (ρ - r)(ρ + r), which keeps the digits that B² - AC
         * would cancel for a far-away origin (the pbrt sphere trick).  When
         * A is nearly cancelled, t* is huge and the point imprecise; then
         * B² - AC is the better of the two. */
        double disc;
        if (fabs(A) >= 1e-3 * (dxy + wd * wd)) {
            double ts = -B / A;
            double px = o[0] + ts * d[0], py = o[1] + ts * d[1], pz = o[2] + ts * d[2];
            double rho = sqrt(px * px + py * py), rz = r1 + k * pz;
            disc = -A * (rho - rz) * (rho + rz);
        } else {
            disc = B * B - A * C;
        }
        if (A > 0) {
            if (!(disc > 0)) /* miss or tangent */
                return 0;
        } else if (!(disc > 0)) {
            /* A < 0 and disc <= 0: Q <= 0 for every t (the line runs
             * steeper than the cone through both nappes, e.g. along the
             * axis); the slab alone bounds it. */
            return emit(out, s0, z0, s1, z1, prim);
        }
        double ra, rb;
        iv_quadratic_roots(A, B, C, disc, &ra, &rb);
        if (A > 0) {
            np = 1;
            c0[0] = ra;
            c1[0] = rb;
        } else {
            np = 2;
            c0[0] = -INFINITY;
            c1[0] = ra;
            c0[1] = rb;
            c1[1] = INFINITY;
        }
    }
    /* Clip each piece to the slab.  The solid is convex, so in exact
     * arithmetic at most one piece survives with positive length (the other
     * lies on the phantom nappe); rounding near an apex can leave a sliver
     * of the other, so keep the longer. */
    int best = -1;
    double best_len = 0;
    for (int i = 0; i < np; i++) {
        clamp_piece(&c0[i], &q0[i], &c1[i], &q1[i], s0, z0, s1, z1);
        double len = c1[i] - c0[i];
        if (c0[i] < c1[i] && (best < 0 || len > best_len)) {
            best = i;
            best_len = len;
        }
    }
    if (best < 0) return 0;
    return emit(out, c0[best], q0[best], c1[best], q1[best], prim);
}

int iv_shape_intersect(const iv_shape *s, const double o[3], const double d[3], int32_t prim,
                       iv_list *out)
{
    switch (s->kind) {
    case IV_SHAPE_HALFSPACE:
        return halfspace(s->u.halfspace.n, s->u.halfspace.d, o, d, prim, out);
    case IV_SHAPE_SPHERE:
        return sphere(s->u.sphere.r, o, d, prim, out);
    case IV_SHAPE_BOX:
        return box(s->u.box.lo, s->u.box.hi, o, d, prim, out);
    case IV_SHAPE_CONE:
        return cone(s->u.cone.r1, s->u.cone.r2, s->u.cone.h, o, d, prim, out);
    case IV_SHAPE_POLYTOPE:
        return iv_polytope_intersect(s->u.polytope.p, o, d, prim, out);
    case IV_SHAPE_MESH:
        return iv_mesh_intersect(s->u.mesh.m, o, d, prim, out);
    case IV_SHAPE_PRISM:
        return iv_prism_intersect(s, o, d, prim, out);
    case IV_SHAPE_REVOLVE:
        return iv_revolve_intersect(s, o, d, prim, out);
    }
    return 0;
}

int iv_shape_max_spans(const iv_shape *s)
{
    switch (s->kind) {
    case IV_SHAPE_MESH:
        return iv_mesh_max_spans(s->u.mesh.m);
    case IV_SHAPE_PRISM:
        return iv_prism_max_spans(s);
    case IV_SHAPE_REVOLVE:
        return iv_revolve_max_spans(s);
    default:
        return 1;
    }
}

void iv_shape_retain(const iv_shape *s)
{
    switch (s->kind) {
    case IV_SHAPE_POLYTOPE:
        iv_polytope_retain(s->u.polytope.p);
        return;
    case IV_SHAPE_MESH:
        iv_mesh_retain(s->u.mesh.m);
        return;
    case IV_SHAPE_PRISM:
        iv_region_retain(s->u.prism.g);
        return;
    case IV_SHAPE_REVOLVE:
        iv_region_retain(s->u.revolve.g);
        return;
    default:
        return;
    }
}

void iv_shape_release(iv_shape *s)
{
    switch (s->kind) {
    case IV_SHAPE_POLYTOPE:
        iv_polytope_release(s->u.polytope.p);
        s->u.polytope.p = NULL;
        return;
    case IV_SHAPE_MESH:
        iv_mesh_release(s->u.mesh.m);
        s->u.mesh.m = NULL;
        return;
    case IV_SHAPE_PRISM:
        iv_region_release(s->u.prism.g);
        s->u.prism.g = NULL;
        return;
    case IV_SHAPE_REVOLVE:
        iv_region_release(s->u.revolve.g);
        s->u.revolve.g = NULL;
        return;
    default:
        return;
    }
}

/* v / |v|, or fallback when |v| is zero or not finite. */
static void normalize_or(double v[3], double fx, double fy, double fz)
{
    double l = sqrt(dot3(v, v));
    if (l > 0 && isfinite(l)) {
        v[0] /= l;
        v[1] /= l;
        v[2] /= l;
    } else {
        v[0] = fx;
        v[1] = fy;
        v[2] = fz;
    }
}

void iv_shape_normal(const iv_shape *s, const double p[3], int part, double n[3])
{
    switch (s->kind) {
    case IV_SHAPE_HALFSPACE:
        n[0] = s->u.halfspace.n[0];
        n[1] = s->u.halfspace.n[1];
        n[2] = s->u.halfspace.n[2];
        normalize_or(n, 0, 0, 1);
        return;
    case IV_SHAPE_SPHERE:
        n[0] = p[0];
        n[1] = p[1];
        n[2] = p[2];
        normalize_or(n, 0, 0, 1);
        return;
    case IV_SHAPE_BOX: {
        int axis = (part >> 1) % 3;
        n[0] = n[1] = n[2] = 0;
        n[axis] = (part & 1) ? 1 : -1;
        return;
    }
    case IV_SHAPE_CONE: {
        const double r1 = s->u.cone.r1, r2 = s->u.cone.r2, h = s->u.cone.h;
        n[0] = n[1] = 0;
        if (part == IV_PART_CONE_BOTTOM || part == IV_PART_CONE_TOP) {
            n[2] = part == IV_PART_CONE_TOP ? 1 : -1;
            return;
        }
        /* Side: the gradient of x² + y² - r(z)² is 2(x, y, -k r(z)); on the
         * surface r(z) = ρ = |p_xy|, so (x/ρ, y/ρ, -k) is parallel to it and
         * does not depend on how exactly p lies on the surface.  At an apex
         * (ρ = 0) the normal is undefined; use the axis pointing out of the
         * tip. */
        const double k = h > 0 ? (r2 - r1) / h : 0;
        double rho = sqrt(p[0] * p[0] + p[1] * p[1]);
        if (rho > 0 && isfinite(rho)) {
            n[0] = p[0] / rho;
            n[1] = p[1] / rho;
            n[2] = -k;
            normalize_or(n, 0, 0, 1);
        } else {
            n[2] = k < 0 ? 1 : -1;
        }
        return;
    }
    case IV_SHAPE_POLYTOPE:
        iv_polytope_normal(s->u.polytope.p, part, n);
        return;
    case IV_SHAPE_MESH:
        iv_mesh_normal(s->u.mesh.m, p, part, n);
        return;
    case IV_SHAPE_PRISM:
        iv_prism_normal(s, p, part, n);
        return;
    case IV_SHAPE_REVOLVE:
        iv_revolve_normal(s, p, part, n);
        return;
    }
    n[0] = n[1] = 0;
    n[2] = 1;
}

int iv_shape_bounds(const iv_shape *s, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = -INFINITY;
        hi[k] = INFINITY;
    }
    switch (s->kind) {
    case IV_SHAPE_HALFSPACE: {
        const double *n = s->u.halfspace.n, hd = s->u.halfspace.d;
        if (!isfinite(n[0]) || !isfinite(n[1]) || !isfinite(n[2]) || isnan(hd)) return -1;
        int nz = (n[0] != 0) + (n[1] != 0) + (n[2] != 0);
        if (nz == 0) /* 0 <= d: everything, or nothing */
            return hd >= 0 ? 0 : -1;
        if (nz == 1) {
            /* An axis-aligned plane bounds one side of one axis. */
            int k = n[0] != 0 ? 0 : n[1] != 0 ? 1 : 2;
            if (n[k] > 0)
                hi[k] = hd / n[k];
            else
                lo[k] = hd / n[k];
        }
        return 0;
    }
    case IV_SHAPE_SPHERE: {
        double r = s->u.sphere.r;
        if (!(r > 0) || !isfinite(r)) return -1;
        for (int k = 0; k < 3; k++) {
            lo[k] = -r;
            hi[k] = r;
        }
        return 0;
    }
    case IV_SHAPE_BOX:
        for (int k = 0; k < 3; k++)
            if (!(s->u.box.lo[k] < s->u.box.hi[k])) return -1;
        for (int k = 0; k < 3; k++) {
            lo[k] = s->u.box.lo[k];
            hi[k] = s->u.box.hi[k];
        }
        return 0;
    case IV_SHAPE_CONE: {
        const double r1 = s->u.cone.r1, r2 = s->u.cone.r2, h = s->u.cone.h;
        if (!cone_valid(r1, r2, h)) return -1;
        double r = r1 > r2 ? r1 : r2;
        lo[0] = lo[1] = -r;
        hi[0] = hi[1] = r;
        lo[2] = 0;
        hi[2] = h;
        return 0;
    }
    case IV_SHAPE_POLYTOPE:
        return iv_polytope_bounds(s->u.polytope.p, lo, hi);
    case IV_SHAPE_MESH:
        return iv_mesh_bounds(s->u.mesh.m, lo, hi);
    case IV_SHAPE_PRISM:
        return iv_prism_bounds(s, lo, hi);
    case IV_SHAPE_REVOLVE:
        return iv_revolve_bounds(s, lo, hi);
    }
    return -1;
}
