/*
 * follow.c — a ray's boundaries followed along its line (follow.h).
 */
#include "follow.h"

#include "../intervals/vec3.h"

#include <math.h>
#include <stdlib.h>

#define MAX_CHANGED 12 /* boundaries one ray has and the other lacks */
#define SCAN 6         /* samples of a meeting's difference across [lo, hi] */

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

/* Where f and g meet in (lo, hi), into x; their number (at most SCAN + 1).
 * Two planes: where their difference, linear in u, is zero; a plane and a
 * quadric: plane_meets; two quadrics: each sign change of their difference
 * over SCAN steps, closed in on by the Illinois rule. */
static int meetings(const mesh_form *f, const mesh_form *g, double lo, double hi, double *x)
{
    int n = 0;
    if (flat(f) != flat(g))
        return flat(f) ? plane_meets(f, g, lo, hi, x) : plane_meets(g, f, lo, hi, x);
    if (flat(f)) {
        /* two planes: their difference is linear in u */
        double hl, hh;
        if (gap(f, g, lo, &hl) != 0 || gap(f, g, hi, &hh) != 0 || hl == hh) return 0;
        double r = lo - hl * (hi - lo) / (hh - hl);
        if (r > lo && r < hi) x[n++] = r;
        return n;
    }
    double pu = NAN, ph = NAN;
    for (int i = 0; i <= SCAN; i++) {
        double u = i == SCAN ? hi : lo + (hi - lo) * i / SCAN, h;
        if (gap(f, g, u, &h) != 0) {
            pu = NAN;
            continue;
        }
        if (h == 0 && u > lo && u < hi) x[n++] = u;
        if (!isnan(pu) && ((ph < 0 && h > 0) || (ph > 0 && h < 0))) {
            double a = pu, fa = ph, b = u, fb = h;
            int side = 0;
            for (int it = 0; it < 100 && b - a > 1e-15 * (hi - lo); it++) {
                double m = (a * fb - b * fa) / (fb - fa), fm;
                if (!(m > a && m < b)) m = 0.5 * (a + b);
                if (gap(f, g, m, &fm) != 0) break;
                if (fm == 0) {
                    a = b = m;
                    break;
                }
                if ((fm < 0) == (fa < 0)) {
                    a = m;
                    fa = fm;
                    if (side == -1) fb *= 0.5;
                    side = -1;
                } else {
                    b = m;
                    fb = fm;
                    if (side == 1) fa *= 0.5;
                    side = 1;
                }
            }
            double r = fabs(fa) < fabs(fb) ? a : b;
            if (r > lo && r < hi) x[n++] = r;
        }
        pu = u;
        ph = h;
    }
    return n;
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
    double buf[MAX_CHANGED * (2 + MAX_CHANGED * (SCAN + 1))];
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
