/*
 * solid.c — the boundary of a 3D subtree as OpenSCAD tessellates it:
 * convex polygons, outward, in a frame of the caller's choosing.  Each
 * leaf gives its faces at OpenSCAD's facets (the fragment count recorded
 * when the leaf was made, or the caller's $fn/$fa/$fs); unions,
 * intersections and differences are resolved by BSP (geom/bsp.h), so
 * hull() and minkowski() see the vertices and faces of the result, not of
 * the operands.  2D leaves count as empty here.
 */
#include "builtins.h"
#include "../../geom/trapezoid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The plane tests one boolean may take (geom_bsp_boolean's work). */
#define SOLID_WORK 400000000L

typedef struct leaf_out {
    geom_polys *out;
    double m[12]; /* local_from_object */
    int flip;     /* m turns orientation over */
    double c[3];  /* a point inside a convex leaf, or NaN */
    int failed;
} leaf_out;

/* Adds polygon v[0 .. k) of the leaf, given in its own frame. */
static void put(leaf_out *o, const double (*v)[3], int k)
{
    if (k < 3 || o->failed) return;
    double w[64][3], (*q)[3] = k <= 64 ? w : malloc((size_t)k * sizeof *q);
    if (!q) {
        o->failed = 1;
        return;
    }
    int reverse = o->flip;
    if (!isnan(o->c[0])) { /* convex: outward is away from the inside point */
        double n[3] = {0, 0, 0}, g[3] = {0, 0, 0};
        for (int i = 0; i < k; i++) {
            const double *a = v[i], *b = v[(i + 1) % k];
            n[0] += (a[1] - b[1]) * (a[2] + b[2]);
            n[1] += (a[2] - b[2]) * (a[0] + b[0]);
            n[2] += (a[0] - b[0]) * (a[1] + b[1]);
            for (int a3 = 0; a3 < 3; a3++)
                g[a3] += a[a3] / k;
        }
        double d = n[0] * (g[0] - o->c[0]) + n[1] * (g[1] - o->c[1]) + n[2] * (g[2] - o->c[2]);
        if (d < 0) reverse = !reverse;
    }
    for (int i = 0; i < k; i++)
        csg_affine_point(o->m, v[reverse ? k - 1 - i : i], q[i]);
    if (geom_polys_add(o->out, (const double(*)[3])q, k) != 0) o->failed = 1;
    if (q != w) free(q);
}

/* put() with consecutive repeated points dropped (a cone's apex, a profile
 * point on the axis). */
static void put_distinct(leaf_out *o, const double (*v)[3], int k)
{
    double q[4][3];
    int n = 0;
    for (int i = 0; i < k && i < 4; i++)
        if (n == 0 || memcmp(q[n - 1], v[i], sizeof q[0]) != 0) memcpy(q[n++], v[i], sizeof q[0]);
    while (n > 1 && memcmp(q[n - 1], q[0], sizeof q[0]) == 0)
        n--;
    put(o, (const double(*)[3])q, n);
}

static void ring(double r, int n, double z, double (*v)[3])
{
    for (int j = 0; j < n; j++) {
        double c[2];
        scad_circle_point(r, j, n, c);
        v[j][0] = c[0];
        v[j][1] = c[1];
        v[j][2] = z;
    }
}

static void sphere_faces(leaf_out *o, double r, int n)
{
    int rings = (n + 1) / 2;
    double(*a)[3] = malloc((size_t)n * sizeof *a), (*b)[3] = malloc((size_t)n * sizeof *b);
    if (!a || !b) {
        o->failed = 1;
    } else {
        for (int i = 0; i < rings; i++) {
            double rr, z;
            scad_sphere_ring(r, i, rings, &rr, &z);
            ring(rr, n, z, b);
            if (i == 0 || i == rings - 1) put(o, (const double(*)[3])b, n);
            for (int j = 0; i > 0 && j < n; j++) {
                double q[4][3];
                memcpy(q[0], a[j], sizeof q[0]);
                memcpy(q[1], b[j], sizeof q[0]);
                memcpy(q[2], b[(j + 1) % n], sizeof q[0]);
                memcpy(q[3], a[(j + 1) % n], sizeof q[0]);
                put(o, (const double(*)[3])q, 4);
            }
            double(*t)[3] = a;
            a = b;
            b = t;
        }
    }
    free(a);
    free(b);
}

/* A cone or cylinder from radius r1 at z0 to r2 at z1, n-gons. */
static void cone_faces(leaf_out *o, double r1, double r2, double z0, double z1, int n)
{
    double(*a)[3] = malloc((size_t)n * sizeof *a), (*b)[3] = malloc((size_t)n * sizeof *b);
    if (!a || !b) {
        o->failed = 1;
    } else {
        ring(r1, n, z0, a);
        ring(r2, n, z1, b);
        if (r1 > 0) put(o, (const double(*)[3])a, n);
        if (r2 > 0) put(o, (const double(*)[3])b, n);
        for (int j = 0; j < n; j++) {
            double q[4][3];
            memcpy(q[0], a[j], sizeof q[0]);
            memcpy(q[1], a[(j + 1) % n], sizeof q[0]);
            memcpy(q[2], b[(j + 1) % n], sizeof q[0]);
            memcpy(q[3], b[j], sizeof q[0]);
            put_distinct(o, (const double(*)[3])q, 4);
        }
    }
    free(a);
    free(b);
}

static void box_faces(leaf_out *o, const double lo[3], const double hi[3])
{
    static const int f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int i = 0; i < 6; i++) {
        double q[4][3];
        for (int k = 0; k < 4; k++)
            for (int a = 0; a < 3; a++)
                q[k][a] = f[i][k] >> a & 1 ? hi[a] : lo[a];
        put(o, (const double(*)[3])q, 4);
    }
}

/* The faces of a convex polytope: on each plane, the vertices on it in
 * turn around the plane's normal. */
static void polytope_faces(leaf_out *o, const iv_shape *s)
{
    int nv, np;
    const double(*V)[3] = iv_polytope_vertices(s, &nv);
    const double(*Pl)[4] = iv_polytope_planes(s, &np);
    double scale = 1;
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++)
            scale = fmax(scale, fabs(V[i][k]));
    double(*q)[3] = malloc((size_t)nv * sizeof *q);
    double *ang = malloc((size_t)nv * sizeof *ang);
    if (!q || !ang) o->failed = 1;
    for (int p = 0; q && ang && p < np; p++) {
        const double *n = Pl[p];
        int k = 0;
        for (int i = 0; i < nv; i++)
            if (fabs(n[0] * V[i][0] + n[1] * V[i][1] + n[2] * V[i][2] - n[3]) <= 1e-9 * scale)
                memcpy(q[k++], V[i], sizeof q[0]);
        if (k < 3) continue;
        double c[3] = {0, 0, 0}, u[3], w[3];
        for (int i = 0; i < k; i++)
            for (int a = 0; a < 3; a++)
                c[a] += q[i][a] / k;
        for (int a = 0; a < 3; a++)
            u[a] = q[0][a] - c[a];
        w[0] = n[1] * u[2] - n[2] * u[1];
        w[1] = n[2] * u[0] - n[0] * u[2];
        w[2] = n[0] * u[1] - n[1] * u[0];
        for (int i = 0; i < k; i++) {
            double d[3] = {q[i][0] - c[0], q[i][1] - c[1], q[i][2] - c[2]};
            ang[i] = atan2(d[0] * w[0] + d[1] * w[1] + d[2] * w[2],
                           d[0] * u[0] + d[1] * u[1] + d[2] * u[2]);
        }
        for (int i = 1; i < k; i++) /* insertion sort by angle */
            for (int j = i; j > 0 && ang[j - 1] > ang[j]; j--) {
                double t = ang[j], tq[3];
                ang[j] = ang[j - 1];
                ang[j - 1] = t;
                memcpy(tq, q[j], sizeof tq);
                memcpy(q[j], q[j - 1], sizeof tq);
                memcpy(q[j - 1], tq, sizeof tq);
            }
        put(o, (const double(*)[3])q, k);
    }
    free(q);
    free(ang);
}

static void mesh_faces(leaf_out *o, const iv_shape *s)
{
    int nv, nt;
    const double(*V)[3] = iv_mesh_vertices(s, &nv);
    const int(*T)[3] = iv_mesh_triangles(s, &nt);
    for (int i = 0; i < nt; i++) { /* OpenSCAD's clockwise triangles, reversed */
        double q[3][3];
        memcpy(q[0], V[T[i][2]], sizeof q[0]);
        memcpy(q[1], V[T[i][1]], sizeof q[0]);
        memcpy(q[2], V[T[i][0]], sizeof q[0]);
        put(o, (const double(*)[3])q, 3);
    }
}

/* Trapezoids of a region mapped to 3D: at height z (prism caps, reversed
 * below), or in the half-plane at azimuth a (revolve ends). */
typedef struct cap {
    leaf_out *o;
    int kind; /* 0: the plane z; 1: the half-plane at azimuth a */
    double z, a;
    int reverse;
} cap;

static int cap_emit(void *ud, const double (*q)[2], int k)
{
    cap *c = ud;
    double v[4][3];
    for (int i = 0; i < k; i++) {
        const double *p = q[c->reverse ? k - 1 - i : i];
        if (c->kind == 0) {
            v[i][0] = p[0];
            v[i][1] = p[1];
            v[i][2] = c->z;
        } else {
            v[i][0] = p[0] * iv_cos_degrees(c->a);
            v[i][1] = p[0] * iv_sin_degrees(c->a);
            v[i][2] = p[1];
        }
    }
    put(c->o, (const double(*)[3])v, k);
    return c->o->failed;
}

static void region_caps(leaf_out *o, const iv_region *g, cap c)
{
    int n, np;
    const double(*P)[2] = iv_region_points(g, &n);
    const int *start = iv_region_paths(g, &np);
    c.o = o;
    if (geom_trapezoids(P, start, np, cap_emit, &c) != 0) o->failed = 1;
}

static void prism_faces(leaf_out *o, const scad_geom *g, scad_facet_params f)
{
    const iv_shape *s = &g->shape;
    double z0 = s->u.prism.z0, z1 = s->u.prism.z1;
    if (!s->u.prism.g) { /* a disc: OpenSCAD's n-gon */
        o->c[0] = o->c[1] = 0;
        o->c[2] = 0.5 * (z0 + z1);
        cone_faces(o, s->u.prism.r, s->u.prism.r, z0, z1, scad_leaf_fragments(g, f));
        return;
    }
    const iv_region *r = s->u.prism.g;
    int n, np;
    const double(*P)[2] = iv_region_points(r, &n);
    const int *start = iv_region_paths(r, &np);
    region_caps(o, r, (cap){NULL, 0, z1, 0, 0});
    region_caps(o, r, (cap){NULL, 0, z0, 0, 1});
    for (int p = 0; p < np; p++)
        for (int i = start[p]; i < start[p + 1]; i++) {
            int j = i + 1 < start[p + 1] ? i + 1 : start[p];
            double q[4][3] = {{P[i][0], P[i][1], z0},
                              {P[j][0], P[j][1], z0},
                              {P[j][0], P[j][1], z1},
                              {P[i][0], P[i][1], z1}};
            put(o, (const double(*)[3])q, 4);
        }
}

/* OpenSCAD's rotate_extrude polyhedron: the profile's rings at the
 * fragment angles (from the -x axis round for a whole turn, from +x for a
 * part, as 2021.01's fill_ring), its ends capped. */
static void revolve_faces(leaf_out *o, const iv_shape *s, scad_facet_params f)
{
    const iv_region *r = s->u.revolve.g;
    double angle = s->u.revolve.angle;
    int n, np;
    const double(*P)[2] = iv_region_points(r, &n);
    const int *start = iv_region_paths(r, &np);
    int k = s->u.revolve.fragments;
    if (k < 1) {
        double xmax = 0;
        for (int i = 0; i < n; i++)
            xmax = fmax(xmax, P[i][0]);
        k = (int)fmax(scad_fragments(xmax, f) * angle / 360, 1);
    }
    int whole = angle >= 360;
    for (int step = 0; step < k && !o->failed; step++) {
        double a0 = whole ? 180 + 360.0 * step / k : angle * step / k;
        double a1 = whole ? 180 + 360.0 * (step + 1) / k : angle * (step + 1) / k;
        double c0 = iv_cos_degrees(a0), s0 = iv_sin_degrees(a0);
        double c1 = iv_cos_degrees(a1), s1 = iv_sin_degrees(a1);
        for (int p = 0; p < np; p++)
            for (int i = start[p]; i < start[p + 1]; i++) {
                int j = i + 1 < start[p + 1] ? i + 1 : start[p];
                double q[4][3] = {{P[i][0] * c0, P[i][0] * s0, P[i][1]},
                                  {P[i][0] * c1, P[i][0] * s1, P[i][1]},
                                  {P[j][0] * c1, P[j][0] * s1, P[j][1]},
                                  {P[j][0] * c0, P[j][0] * s0, P[j][1]}};
                put_distinct(o, (const double(*)[3])q, 4);
            }
    }
    if (!whole) {
        region_caps(o, r, (cap){NULL, 1, 0, 0, 0});
        region_caps(o, r, (cap){NULL, 1, 0, angle, 1});
    }
}

int scad_leaf_polys(const scad_geom *g, const double local_from_world[12], scad_facet_params f,
                    geom_polys *out)
{
    const iv_shape *s = &g->shape;
    leaf_out o = {out, {0}, 0, {NAN, NAN, NAN}, 0};
    csg_affine_mul(local_from_world, g->xf, o.m);
    double det = o.m[0] * (o.m[5] * o.m[10] - o.m[6] * o.m[9]) -
                 o.m[1] * (o.m[4] * o.m[10] - o.m[6] * o.m[8]) +
                 o.m[2] * (o.m[4] * o.m[9] - o.m[5] * o.m[8]);
    if (!(det != 0) || !isfinite(det)) return 0;
    o.flip = det < 0;
    switch (s->kind) {
    case IV_SHAPE_BOX:
        o.c[0] = 0.5 * (s->u.box.lo[0] + s->u.box.hi[0]);
        o.c[1] = 0.5 * (s->u.box.lo[1] + s->u.box.hi[1]);
        o.c[2] = 0.5 * (s->u.box.lo[2] + s->u.box.hi[2]);
        box_faces(&o, s->u.box.lo, s->u.box.hi);
        break;
    case IV_SHAPE_SPHERE:
        o.c[0] = o.c[1] = o.c[2] = 0;
        sphere_faces(&o, s->u.sphere.r, scad_leaf_fragments(g, f));
        break;
    case IV_SHAPE_CONE: {
        o.c[0] = o.c[1] = 0;
        o.c[2] = 0.5 * s->u.cone.h;
        cone_faces(&o, s->u.cone.r1, s->u.cone.r2, 0, s->u.cone.h, scad_leaf_fragments(g, f));
        break;
    }
    case IV_SHAPE_POLYTOPE: {
        int nv;
        const double(*V)[3] = iv_polytope_vertices(s, &nv);
        o.c[0] = o.c[1] = o.c[2] = 0;
        for (int i = 0; i < nv; i++)
            for (int k = 0; k < 3; k++)
                o.c[k] += V[i][k] / nv;
        polytope_faces(&o, s);
        break;
    }
    case IV_SHAPE_MESH:
        mesh_faces(&o, s);
        break;
    case IV_SHAPE_PRISM:
        if (!scad_geom_is_flat(g)) prism_faces(&o, g, f);
        break;
    case IV_SHAPE_REVOLVE:
        revolve_faces(&o, s, f);
        break;
    default:
        break;
    }
    return o.failed ? -1 : 0;
}

/* ---- as a mesh -------------------------------------------------------------------- */

typedef struct vkey {
    double p[3];
    int i;
} vkey;

static int cmp_vkey(const void *a, const void *b)
{
    const double *x = ((const vkey *)a)->p, *y = ((const vkey *)b)->p;
    for (int k = 0; k < 3; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}

int scad_polys_vertices(const geom_polys *p, double (**V)[3], int *nv, int *map)
{
    int n = p->nv;
    vkey *K = malloc((size_t)(n ? n : 1) * sizeof *K);
    *V = malloc((size_t)(n ? n : 1) * sizeof **V);
    *nv = 0;
    if (!K || !*V) {
        free(K);
        free(*V);
        *V = NULL;
        return -1;
    }
    for (int i = 0; i < n; i++) {
        memcpy(K[i].p, p->v[i], sizeof K[i].p);
        K[i].i = i;
    }
    qsort(K, (size_t)n, sizeof *K, cmp_vkey);
    for (int i = 0; i < n; i++) {
        if (i == 0 || cmp_vkey(&K[i - 1], &K[i]) != 0) memcpy((*V)[(*nv)++], K[i].p, sizeof **V);
        if (map) map[K[i].i] = *nv - 1;
    }
    free(K);
    return 0;
}

int scad_polys_mesh(const geom_polys *p, iv_shape *out)
{
    int n = p->nv, nv, rc = -1;
    int *map = malloc((size_t)(n ? n : 1) * sizeof *map);
    int *idx = malloc((size_t)(n ? n : 1) * sizeof *idx);
    double(*V)[3] = NULL;
    if (map && idx && p->n > 0 && scad_polys_vertices(p, &V, &nv, map) == 0) {
        /* OpenSCAD's winding: clockwise seen from outside */
        for (int f = 0; f < p->n; f++)
            for (int i = p->start[f]; i < p->start[f + 1]; i++)
                idx[i] = map[p->start[f + 1] - 1 - (i - p->start[f])];
        rc = iv_shape_mesh(out, (const double(*)[3])V, nv, idx, p->start, p->n) < 0 ? -1 : 0;
    }
    free(map);
    free(V);
    free(idx);
    return rc;
}

/* ---- booleans ------------------------------------------------------------------ */

typedef struct solid {
    scad_eval *ev;
    scad_loc loc;
    const char *who;
    const double *lfw;
    scad_facet_params f;
} solid;

static int solid_of(solid *c, const scad_geom *g, geom_polys *out)
{
    if (!g || c->ev->aborted) return -1;
    if (g->is_leaf) {
        if (scad_leaf_polys(g, c->lfw, c->f, out) == 0) return 0;
        scad_eval_error(c->ev, c->loc, "%s(): out of memory", c->who);
        return -1;
    }
    if (g->n == 0 || solid_of(c, g->kids[0], out) != 0) return g->n == 0 ? 0 : -1;
    for (int i = 1; i < g->n; i++) {
        if (out->n == 0 && g->op != CSG_OP_UNION) break; /* nothing left to cut */
        geom_polys k = {0}, r = {0};
        if (solid_of(c, g->kids[i], &k) != 0) {
            geom_polys_free(&k);
            return -1;
        }
        int meet = out->n > 0 && k.n > 0 && geom_polys_meet(out, &k);
        int rc = 0;
        if (g->op == CSG_OP_UNION) {
            if (meet) {
                long work = SOLID_WORK;
                rc = geom_bsp_boolean(GEOM_BSP_UNION, out, &k, &work, &r);
                if (rc == 0) scad_eval_steps(c->ev, (SOLID_WORK - work) / 100, c->loc, c->who);
            } else {
                rc = geom_polys_append(out, &k);
            }
        } else if (g->op == CSG_OP_INTERSECTION && !meet) {
            geom_polys_free(out);
        } else if (meet) {
            long work = SOLID_WORK;
            rc = geom_bsp_boolean(g->op == CSG_OP_INTERSECTION ? GEOM_BSP_INTERSECTION
                                                               : GEOM_BSP_DIFFERENCE,
                                  out, &k, &work, &r);
            if (rc == 0) scad_eval_steps(c->ev, (SOLID_WORK - work) / 100, c->loc, c->who);
        }
        geom_polys_free(&k);
        if (rc == GEOM_BSP_TOO_MUCH) {
            scad_eval_error(c->ev, c->loc,
                            "%s(): the boolean of its children takes more than %ld steps", c->who,
                            SOLID_WORK);
            return -1;
        }
        if (rc != 0) {
            scad_eval_error(c->ev, c->loc, "%s(): out of memory", c->who);
            return -1;
        }
        if (r.n > 0 || (meet && g->op != CSG_OP_UNION)) {
            geom_polys_free(out);
            *out = r;
        }
        if (c->ev->aborted) return -1;
    }
    return 0;
}

int scad_solid_polys(scad_eval *ev, scad_loc loc, const char *who, const scad_geom *g,
                     const double local_from_world[12], scad_facet_params f, geom_polys *out)
{
    solid c = {ev, loc, who, local_from_world, f};
    int rc = solid_of(&c, g, out);
    if (rc != 0) geom_polys_free(out);
    return rc;
}
