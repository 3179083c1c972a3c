/*
 * follow.c — a ray's boundaries followed along its line (follow.h).
 */
#include "follow.h"

#include "../intervals/vec3.h"

#include <math.h>
#include <stdlib.h>

#define MAX_CHANGED 12 /* boundaries one ray has and the other lacks */

static void mat_vec(const double A[3][3], const double x[3], double y[3])
{
    for (int i = 0; i < 3; i++)
        y[i] = A[i][0] * x[0] + A[i][1] * x[1] + A[i][2] * x[2];
}

/* The gradient 2Ax + b of the surface xᵀAx + b·x + c at x. */
static void gradient(const double A[3][3], const double b[3], const double x[3], double g[3])
{
    mat_vec(A, x, g);
    for (int i = 0; i < 3; i++)
        g[i] = 2 * g[i] + b[i];
}

void mesh_form_init(mesh_form *f, const iv_quadric *q, const mesh_line_frame *F, const double x[3],
                    double w, uint64_t face)
{
    double Ad[3], Ae[3], Ap[3], g[3];
    mat_vec(q->A, F->d, Ad);
    mat_vec(q->A, F->e1, Ae);
    mat_vec(q->A, F->p0, Ap);
    for (int i = 0; i < 3; i++) {
        f->g0[i] = 2 * Ap[i] + q->b[i];
        f->gu[i] = 2 * Ae[i];
        f->gt[i] = 2 * Ad[i];
    }
    f->al = dot3(F->d, Ad);
    f->bu = 2 * dot3(F->e1, Ad);
    f->bt = 2 * dot3(F->p0, Ad) + dot3(q->b, F->d);
    f->cu2 = dot3(F->e1, Ae);
    f->cu1 = 2 * dot3(F->p0, Ae) + dot3(q->b, F->e1);
    f->c0 = dot3(F->p0, Ap) + dot3(q->b, F->p0) + q->c;
    gradient(q->A, q->b, x, g);
    f->s = dot3(g, F->d) < 0 ? -1 : 1;
    f->w = w;
    f->face = face;
}

int mesh_form_t(const mesh_form *f, double u, double *t)
{
    double B = f->bu * u + f->bt, C = (f->cu2 * u + f->cu1) * u + f->c0;
    if (f->al == 0) {
        if (B == 0) return -1;
        *t = -C / B;
        return 0;
    }
    double D = B * B - 4 * f->al * C;
    if (!(D >= 0)) return -1;
    /* the roots q/al and C/q, neither losing digits; C/q is the one where
     * ∂q/∂t = 2 al t + B has the sign of B */
    double q = -0.5 * (B + copysign(sqrt(D), B));
    if (q == 0)
        *t = -B / (2 * f->al);
    else
        *t = (f->s < 0) == (B < 0) ? C / q : q / f->al;
    return 0;
}

int mesh_forms_sums(const mesh_form *f, int n, const mesh_line_frame *F, double u,
                    mesh_follow_sums *out)
{
    *out = (mesh_follow_sums){0, 0, 0, 0, 0};
    double last = -INFINITY;
    for (int i = 0; i < n; i++) {
        double t, g[3];
        if (mesh_form_t(&f[i], u, &t) != 0 || t < last) return 1;
        last = t;
        for (int k = 0; k < 3; k++)
            g[k] = f[i].g0[k] + u * f[i].gu[k] + t * f[i].gt[k];
        double gd = dot3(g, F->d), gl = sqrt(dot3(g, g));
        if (!(fabs(gd) > 0) || !((gd < 0) == (f[i].s < 0))) return 1;
        out->len += f[i].w * t;
        out->tt += f[i].w * 0.5 * t * t;
        out->area += fabs(gd) / gl;
        /* t on the surface as u moves: dt/du = −(g·e1)/(g·d) */
        out->slope -= f[i].w * dot3(g, F->e1) / gd;
        out->across -= f[i].w * dot3(g, F->e2) / gd;
    }
    return 0;
}

/* The roots of c2 u² + c1 u + c0 in (lo, hi) into x; their number. */
static int quadratic_in(double c2, double c1, double c0, double lo, double hi, double *x)
{
    double r[2];
    int n = 0;
    if (c2 == 0) {
        if (c1 != 0) r[n++] = -c0 / c1;
    } else {
        double D = c1 * c1 - 4 * c2 * c0;
        if (D < 0) return 0;
        double q = -0.5 * (c1 + copysign(sqrt(D), c1));
        r[n++] = q / c2;
        if (q != 0) r[n++] = c0 / q;
    }
    int m = 0;
    for (int i = 0; i < n; i++)
        if (r[i] > lo && r[i] < hi) x[m++] = r[i];
    return m;
}

/* t_f − t_g at u into *h: 0, or -1 where either is past its silhouette. */
static int gap(const mesh_form *f, const mesh_form *g, double u, double *h)
{
    double a, b;
    if (mesh_form_t(f, u, &a) != 0 || mesh_form_t(g, u, &b) != 0) return -1;
    *h = a - b;
    return 0;
}

/* Whether f is a plane: its t linear in u. */
static int flat(const mesh_form *f)
{
    return f->al == 0 && f->bu == 0 && f->cu2 == 0 && f->bt != 0;
}

/* Where plane p meets quadric g in (lo, hi): p's t = αu + β put into g's
 * quadratic, a quadratic in u; its roots where g's root is the one followed
 * (∂q/∂t of g's sign there).  Into x, their number. */
static int plane_meets(const mesh_form *p, const mesh_form *g, double lo, double hi, double *x)
{
    double al = -p->cu1 / p->bt, be = -p->c0 / p->bt, r[2];
    int n = quadratic_in(g->al * al * al + g->bu * al + g->cu2,
                         2 * g->al * al * be + g->bu * be + g->bt * al + g->cu1,
                         g->al * be * be + g->bt * be + g->c0, lo, hi, r),
        m = 0;
    for (int i = 0; i < n; i++) {
        double t = al * r[i] + be, dq = 2 * g->al * t + g->bu * r[i] + g->bt;
        if ((dq < 0) == (g->s < 0)) x[m++] = r[i];
    }
    return m;
}

/* The value at u of the polynomial c[0] + c[1] u + … + c[deg] u^deg. */
static double poly_at(const double *c, int deg, double u)
{
    double v = c[deg];
    for (int i = deg - 1; i >= 0; i--)
        v = v * u + c[i];
    return v;
}

/* The roots in (lo, hi) of the polynomial c (degree deg, at most 4) into
 * x, in order; their number.  Past a quadratic, each found between the
 * roots of its derivative, where it is monotone, by the Illinois rule (to
 * 1e-12 of the stretch: quadrics_meet closes in on them after): a double
 * root (a meeting that touches) is not one. */
static int poly_roots(const double *c, int deg, double lo, double hi, double *x)
{
    if (deg <= 2) {
        int n = quadratic_in(deg == 2 ? c[2] : 0, deg >= 1 ? c[1] : 0, c[0], lo, hi, x);
        if (n == 2 && x[0] > x[1]) {
            double t = x[0];
            x[0] = x[1];
            x[1] = t;
        }
        return n;
    }
    double d[4], cut[6];
    for (int i = 0; i < deg; i++)
        d[i] = (i + 1) * c[i + 1];
    int nc = 0, n = 0;
    cut[nc++] = lo;
    nc += poly_roots(d, deg - 1, lo, hi, cut + nc);
    cut[nc++] = hi;
    for (int i = 0; i + 1 < nc; i++) {
        double a = cut[i], b = cut[i + 1], fa = poly_at(c, deg, a), fb = poly_at(c, deg, b);
        if (!((fa < 0 && fb > 0) || (fa > 0 && fb < 0))) continue;
        int side = 0;
        for (int it = 0; it < 100 && b - a > 1e-12 * (hi - lo); it++) {
            double m = (a * fb - b * fa) / (fb - fa), fm;
            if (!(m > a && m < b)) m = 0.5 * (a + b);
            fm = poly_at(c, deg, m);
            if (fm == 0) {
                a = b = m;
                break;
            }
            if ((fm < 0) == (fa < 0)) {
                a = m, fa = fm;
                if (side == -1) fb *= 0.5;
                side = -1;
            } else {
                b = m, fb = fm;
                if (side == 1) fa *= 0.5;
                side = 1;
            }
        }
        x[n++] = fabs(fa) < fabs(fb) ? a : b;
    }
    return n;
}

/* The product of polynomials p (degree np) and q (nq) into r (np + nq). */
static void poly_mul(const double *p, int np, const double *q, int nq, double *r)
{
    for (int i = 0; i <= np + nq; i++)
        r[i] = 0;
    for (int i = 0; i <= np; i++)
        for (int j = 0; j <= nq; j++)
            r[i + j] += p[i] * q[j];
}

/* Where quadrics f and g meet in (lo, hi), into x; their number (at most
 * 4).  On the line's plane each is a conic in (u, t), a t² + b(u) t +
 * c(u) = 0: where both hold, the resultant of the two in t, (a₁c₂ −
 * a₂c₁)² − (a₁b₂ − a₂b₁)(b₁c₂ − b₂c₁), a quartic in u, is zero.  Its roots
 * where the two boundaries followed (their own roots in t) meet, each
 * closed in on by Newton's method on their difference.  (Sign changes of
 * the difference over six steps of [lo, hi] straddled meetings that close
 * in on each other, an event about to end: closing() found the piece on
 * its own line in fewer than half the tries.) */
static int quadrics_meet(const mesh_form *f, const mesh_form *g, double lo, double hi, double *x)
{
    double A[3] = {f->al * g->c0 - g->al * f->c0, f->al * g->cu1 - g->al * f->cu1,
                   f->al * g->cu2 - g->al * f->cu2};
    double B[2] = {f->al * g->bt - g->al * f->bt, f->al * g->bu - g->al * f->bu};
    double bf[2] = {f->bt, f->bu}, bg[2] = {g->bt, g->bu}, cf[3] = {f->c0, f->cu1, f->cu2},
           cg[3] = {g->c0, g->cu1, g->cu2}, C1[4], C2[4], C[4], AA[5], BC[5], P[5];
    poly_mul(bf, 1, cg, 2, C1);
    poly_mul(bg, 1, cf, 2, C2);
    for (int i = 0; i < 4; i++)
        C[i] = C1[i] - C2[i];
    poly_mul(A, 2, A, 2, AA);
    poly_mul(B, 1, C, 3, BC);
    for (int i = 0; i < 5; i++)
        P[i] = AA[i] - BC[i];
    double r[4], scale = hi - lo;
    int nr = poly_roots(P, 4, lo, hi, r), n = 0;
    for (int i = 0; i < nr; i++) {
        double u = r[i], h, h2, du = 1e-7 * scale;
        int ok = gap(f, g, u, &h) == 0;
        for (int it = 0; it < 8 && ok && h != 0; it++) {
            ok = gap(f, g, u + du, &h2) == 0 && h2 != h;
            if (!ok) break;
            double step = h * du / (h2 - h);
            if (!(fabs(step) < 1e-3 * scale)) {
                ok = 0;
                break;
            }
            u -= step;
            ok = gap(f, g, u, &h) == 0;
            du = fmax(fabs(step), 1e-12 * scale);
        }
        if (ok && fabs(h) <= 1e-9 * scale && u > lo && u < hi) x[n++] = u;
    }
    return n;
}

/* Where f and g meet in (lo, hi), into x; their number (at most 4).  Two
 * planes: where their difference, linear in u, is zero; a plane and a
 * quadric: plane_meets; two quadrics: quadrics_meet. */
static int meetings(const mesh_form *f, const mesh_form *g, double lo, double hi, double *x)
{
    if (flat(f) != flat(g))
        return flat(f) ? plane_meets(f, g, lo, hi, x) : plane_meets(g, f, lo, hi, x);
    if (!flat(f)) return quadrics_meet(f, g, lo, hi, x);
    /* two planes: their difference is linear in u */
    double hl, hh;
    if (gap(f, g, lo, &hl) != 0 || gap(f, g, hi, &hh) != 0 || hl == hh) return 0;
    double r = lo - hl * (hi - lo) / (hh - hl);
    if (!(r > lo && r < hi)) return 0;
    x[0] = r;
    return 1;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The boundaries of p[0 .. np-1] that q[0 .. nq-1] lacks (matched by
 * surface and side, one for one) into idx; their number, or -1 past cap. */
static int lacks(const mesh_form *p, int np, const mesh_form *q, int nq, int *idx, int cap)
{
    char used[256] = {0};
    if (nq > 256) return -1;
    int n = 0;
    for (int i = 0; i < np; i++) {
        int j = 0;
        while (j < nq && (used[j] || q[j].face != p[i].face || q[j].w != p[i].w))
            j++;
        if (j < nq) {
            used[j] = 1;
            continue;
        }
        if (n == cap) return -1;
        idx[n++] = i;
    }
    return n;
}

int mesh_forms_events(const mesh_form *a, int na, const mesh_form *b, int nb, double lo, double hi,
                      double *x, int cap)
{
    int ia[MAX_CHANGED], ib[MAX_CHANGED];
    int ma = lacks(a, na, b, nb, ia, MAX_CHANGED), mb = lacks(b, nb, a, na, ib, MAX_CHANGED);
    if (ma < 0 || mb < 0 || ma + mb > MAX_CHANGED) return 0;
    const mesh_form *c[MAX_CHANGED];
    int pos[MAX_CHANGED];
    for (int i = 0; i < ma; i++) {
        c[i] = &a[ia[i]];
        pos[i] = ia[i];
    }
    for (int i = 0; i < mb; i++) {
        c[ma + i] = &b[ib[i]];
        pos[ma + i] = ib[i];
    }
    double buf[MAX_CHANGED * (2 + MAX_CHANGED * 4)];
    int n = 0;
    for (int i = 0; i < ma + mb; i++) {
        const mesh_form *f = c[i];
        /* the discriminant (bu u + bt)² − 4 al (cu2 u² + cu1 u + c0) */
        if (f->al != 0)
            n += quadratic_in(f->bu * f->bu - 4 * f->al * f->cu2,
                              2 * f->bu * f->bt - 4 * f->al * f->cu1,
                              f->bt * f->bt - 4 * f->al * f->c0, lo, hi, buf + n);
        for (int j = i + 1; j < ma + mb; j++) {
            int across = (i < ma) != (j < ma); /* one of each */
            if (across || pos[j] == pos[i] + 1) n += meetings(f, c[j], lo, hi, buf + n);
        }
    }
    qsort(buf, (size_t)n, sizeof *buf, by_value);
    int m = 0;
    for (int i = 0; i < n && m < cap; i++)
        if (m == 0 || buf[i] > x[m - 1]) x[m++] = buf[i];
    return m;
}
