/*
 * revolve.c — rotate_extrude: the solid swept by a 2D region about the z
 * axis, {p : (sqrt(px² + py²), pz) in region, azimuth of p in [0, angle]}.
 *
 * Each profile edge sweeps a piece of a cone (or a cylinder, or a flat
 * annulus when the edge is horizontal); along a line the squared distance
 * from the axis is a quadratic in t, so the line meets each swept edge at the
 * roots of a quadratic, and meets the two end half-planes of a partial sweep
 * at one t each.  Those t values are only candidates: the solid's boundary
 * lies among them, so between two consecutive candidates the line is either
 * inside or outside throughout, and the midpoint decides it by an exact
 * point-in-profile test.  Generous candidates (roots slightly outside an
 * edge's z range, on the phantom nappe of a cone) therefore cost time,
 * never correctness; consecutive inside pieces merge into one span.  The
 * solid is bounded, so the line is outside before the first candidate and
 * after the last.
 */
#include "shape_kinds.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DEG (3.14159265358979323846 / 180)

void iv_shape_revolve(iv_shape *s, iv_region *g, double angle)
{
    memset(s, 0, sizeof *s);
    s->kind = IV_SHAPE_REVOLVE;
    iv_region_retain(g);
    s->u.revolve.g = g;
    s->u.revolve.angle = angle;
}

int iv_revolve_max_spans(const iv_shape *s)
{
    return s->u.revolve.g->npts + 2;
}

int iv_revolve_bounds(const iv_shape *s, double lo[3], double hi[3])
{
    const iv_region *g = s->u.revolve.g;
    double r = fmax(fabs(g->lo[0]), fabs(g->hi[0]));
    if (!(r > 0) || !(g->lo[1] < g->hi[1]) || !(s->u.revolve.angle > 0)) return -1;
    lo[0] = lo[1] = -r;
    hi[0] = hi[1] = r;
    lo[2] = g->lo[1];
    hi[2] = g->hi[1];
    return 0;
}

static int in_sweep(double angle, double x, double y)
{
    if (angle >= 360) return 1;
    double a = atan2(y, x) / DEG;
    if (a < 0) a += 360;
    return a <= angle;
}

static int inside(const iv_shape *s, const double o[3], const double d[3], double t)
{
    double x = o[0] + t * d[0], y = o[1] + t * d[1], z = o[2] + t * d[2];
    return in_sweep(s->u.revolve.angle, x, y) && iv_region_contains(s->u.revolve.g, hypot(x, y), z);
}

int iv_revolve_intersect(const iv_shape *s, const double o[3], const double d[3], int32_t prim,
                         iv_list *out)
{
    const iv_region *g = s->u.revolve.g;
    const double angle = s->u.revolve.angle;
    iv_bound *c = &out->v[out->n].enter;
    const long room = 2L * (out->cap - out->n);
    long nc = 0;
    const double dxy = d[0] * d[0] + d[1] * d[1];
    const double bxy = o[0] * d[0] + o[1] * d[1];
    const double cxy = o[0] * o[0] + o[1] * o[1];
    const double zext = g->hi[1] - g->lo[1];
#define ADD(tv, pv)                                                                                \
    do {                                                                                           \
        double tt_ = (tv);                                                                         \
        if (isfinite(tt_)) {                                                                       \
            if (nc >= room) return -1;                                                             \
            c[nc++] = (iv_bound){tt_, prim, (uint16_t)(pv), 0};                                    \
        }                                                                                          \
    } while (0)
    for (int e = 0; e < g->npts; e++) {
        const double *a = g->pt[e], *b = g->pt[iv_region_next(g, e)];
        int part = e % IV_PART_REVOLVE_START;
        if (a[1] == b[1]) {
            if (d[2] != 0) ADD((a[1] - o[2]) / d[2], part);
            continue;
        }
        /* rho = P + Q t along the line, from rho = alpha + beta z */
        double beta = (b[0] - a[0]) / (b[1] - a[1]);
        double alpha = a[0] - beta * a[1];
        double P = alpha + beta * o[2], Q = beta * d[2];
        double A = dxy - Q * Q, B = bxy - P * Q, C = cxy - P * P;
        double zlo = fmin(a[1], b[1]) - 1e-9 * zext, zhi = fmax(a[1], b[1]) + 1e-9 * zext;
        double r[2];
        int nr = 0;
        if (A == 0) {
            if (B != 0) r[nr++] = -C / (2 * B);
        } else {
            double disc = B * B - A * C;
            if (disc >= 0) {
                double q = -(B + copysign(sqrt(disc), B));
                if (q != 0) {
                    r[nr++] = q / A;
                    r[nr++] = C / q;
                } else {
                    r[nr++] = -B / A;
                }
            }
        }
        for (int k = 0; k < nr; k++) {
            double z = o[2] + r[k] * d[2];
            if (d[2] == 0 || (z >= zlo && z <= zhi)) ADD(r[k], part);
        }
    }
    if (angle < 360) {
        /* azimuth 0: the plane y = 0; azimuth a: -sin(a) x + cos(a) y = 0 */
        if (d[1] != 0) ADD(-o[1] / d[1], IV_PART_REVOLVE_START);
        double sa = sin(angle * DEG), ca = cos(angle * DEG);
        double den = -sa * d[0] + ca * d[1];
        if (den != 0) ADD(-(-sa * o[0] + ca * o[1]) / den, IV_PART_REVOLVE_END);
    }
#undef ADD
    if (nc < 2) return 0;
    iv_bounds_sort(c, nc);
    /* Sweep the gaps; write spans behind the read position. */
    long w = 0;
    int in = 0;
    for (long i = 0; i + 1 < nc; i++) {
        if (!(c[i].t < c[i + 1].t)) continue;
        int now = inside(s, o, d, 0.5 * (c[i].t + c[i + 1].t));
        if (now != in) {
            c[w++] = c[i];
            in = now;
        }
    }
    if (in) c[w++] = c[nc - 1];
    int ns = (int)(w / 2);
    out->n += ns;
    return ns;
}

void iv_revolve_normal(const iv_shape *s, const double p[3], int part, double n[3])
{
    const iv_region *g = s->u.revolve.g;
    n[0] = n[1] = n[2] = 0;
    if (part == IV_PART_REVOLVE_START) {
        n[1] = -1;
        return;
    }
    if (part == IV_PART_REVOLVE_END) {
        double a = s->u.revolve.angle * DEG;
        n[0] = -sin(a);
        n[1] = cos(a);
        return;
    }
    double rho = hypot(p[0], p[1]);
    int best = iv_region_nearest_edge(g, part, IV_PART_REVOLVE_START, rho, p[2]);
    if (best < 0) {
        n[2] = 1;
        return;
    }
    const double *a = g->pt[best], *b = g->pt[iv_region_next(g, best)];
    double ex = b[0] - a[0], ey = b[1] - a[1], l = hypot(ex, ey);
    if (!(l > 0)) {
        n[2] = 1;
        return;
    }
    double nr = ey / l, nz = -ex / l;
    if (rho > 0) {
        n[0] = nr * p[0] / rho;
        n[1] = nr * p[1] / rho;
    } else {
        n[0] = nr;
    }
    n[2] = nz;
}
