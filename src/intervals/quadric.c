/*
 * quadric.c — the surface a boundary lies on, as an implicit quadric
 * (iv_shape_quadric).  Every curved part of every shape is one: a sphere, a
 * cone's or a disc prism's side, and a revolve's swept profile edge (its
 * distance from the axis linear in z, squared).  The rest are flat.  An
 * integrator that knows the surface of each boundary of a ray knows where
 * that boundary goes as the ray moves, without casting another.
 */
#include "shape_kinds.h"

#include <string.h>

/* x² + y² − (r0 + k z)² (a cylinder: k = 0). */
static void axial(double r0, double k, iv_quadric *q)
{
    q->A[0][0] = q->A[1][1] = 1;
    q->A[2][2] = -k * k;
    q->b[2] = -2 * r0 * k;
    q->c = -r0 * r0;
}

/* The side swept by profile edge a → b (region on its left) about z: the
 * points whose (ρ, z) lie on the edge's line, nr ρ + nz z = e. */
static int revolve_side(const iv_shape *s, const double p[3], int part, iv_quadric *q)
{
    const iv_region *g = s->u.revolve.g;
    int best = iv_region_nearest_edge(g, part, IV_PART_REVOLVE_START, hypot(p[0], p[1]), p[2]);
    if (best < 0) return 0;
    const double *a = g->pt[best], *b = g->pt[iv_region_next(g, best)];
    double nr = b[1] - a[1], nz = a[0] - b[0];
    if (!(fabs(nr) > 1e-12 * fabs(nz))) return 0; /* horizontal: a flat annulus */
    /* ρ = r0 + k z */
    axial((nr * a[0] + nz * a[1]) / nr, -nz / nr, q);
    return 1;
}

int iv_shape_quadric(const iv_shape *s, const double p[3], int part, iv_quadric *q)
{
    memset(q, 0, sizeof *q);
    switch (s->kind) {
    case IV_SHAPE_SPHERE:
        q->A[0][0] = q->A[1][1] = q->A[2][2] = 1;
        q->c = -s->u.sphere.r * s->u.sphere.r;
        return 1;
    case IV_SHAPE_CONE:
        if (part != IV_PART_CONE_SIDE || !(s->u.cone.h > 0)) return 0;
        axial(s->u.cone.r1, (s->u.cone.r2 - s->u.cone.r1) / s->u.cone.h, q);
        return 1;
    case IV_SHAPE_PRISM:
        if (part == IV_PART_PRISM_BOTTOM || part == IV_PART_PRISM_TOP || s->u.prism.g) return 0;
        axial(s->u.prism.r, 0, q);
        return 1;
    case IV_SHAPE_REVOLVE:
        if (part == IV_PART_REVOLVE_START || part == IV_PART_REVOLVE_END) return 0;
        return revolve_side(s, p, part, q);
    default:
        return 0;
    }
}
