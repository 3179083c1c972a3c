/*
 * shape.c — what the geometry modules share: leaves placed by the call's
 * state (with the $rs_ optics), OpenSCAD's circles as polygons, 2D leaves in
 * the preview slab, and for the 2D operations (offset, projection,
 * minkowski, text) flattening a 2D subtree into one polygon set and a
 * polygon set back into region leaves.
 *
 * A flattened set is always normalised by the paths_clip service (no
 * overlaps, outlines counter-clockwise, holes clockwise), so the offset and
 * Minkowski services, which read paths as they wind, see what OpenSCAD's
 * Clipper sees.  A region leaf takes the set under the even-odd rule, which
 * agrees with nonzero on a normalised set.
 */
#include "builtins.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SMOOTH_DISC 256 /* points of a smooth circle made into a polygon */

scad_geom *scad_geometry_leaf(scad_eval *ev, iv_shape *s, const scad_state *state)
{
    if (scad_geom_keep(ev, s) != 0) return NULL;
    return scad_geom_leaf(ev, s, state);
}

scad_geom *scad_leaf_at(scad_eval *ev, const iv_shape *s, const scad_state *state,
                        const csg_affine local)
{
    scad_state st = *state;
    if (local) csg_affine_mul(state->xf, local, st.xf);
    return scad_geom_leaf(ev, s, &st);
}

scad_geom *scad_optics_leaf(scad_call *c, const iv_shape *s, const csg_affine local)
{
    scad_state st = *c->state;
    if (local) csg_affine_mul(c->state->xf, local, st.xf);
    scad_material_apply(c, s, st.xf, &st.mat);
    return scad_geom_leaf(c->ev, s, &st);
}

scad_geom *scad_call_children(scad_call *c, const scad_state *state)
{
    return scad_eval_children(c->ev, c->env, c->st, state ? state : c->state, CSG_OP_UNION);
}

scad_geom *scad_with_optics(scad_call *c, scad_geom *g)
{
    if (g && g->is_leaf) scad_material_apply(c, &g->shape, g->xf, &g->mat);
    return g;
}

scad_geom *scad_region_leaf(scad_eval *ev, iv_region *g, const scad_state *state)
{
    if (!g) return NULL;
    iv_shape s;
    iv_shape_prism(&s, g, -SCAD_SLAB, SCAD_SLAB);
    iv_region_release(g); /* the shape holds it now */
    if (scad_geom_keep(ev, &s) != 0) return NULL;
    return scad_leaf_at(ev, &s, state, NULL);
}

void scad_circle_point(double r, int i, int n, double out[2])
{
    double a = 360.0 * i / n;
    out[0] = r * iv_cos_degrees(a);
    out[1] = r * iv_sin_degrees(a);
    /* openscad's cos_degrees and sin_degrees negate a folded angle's
     * value, so their zeros at 270° and 180° are -0, which its 2D exports
     * print ("-5,0" in SVG's flipped y) */
    if (out[0] == 0 && a > 90 && a <= 270) out[0] = -0.0;
    if (out[1] == 0 && a >= 180) out[1] = -0.0;
}

void scad_sphere_ring(double r, int i, int rings, double *rr, double *z)
{
    double phi = 180.0 * (i + 0.5) / rings;
    *rr = r * iv_sin_degrees(phi);
    *z = r * iv_cos_degrees(phi);
}

int scad_leaf_fragments(const scad_geom *g, scad_facet_params f)
{
    if (g->cap >= 3) return g->cap;
    const iv_shape *s = &g->shape;
    double r = s->kind == IV_SHAPE_SPHERE ? s->u.sphere.r
               : s->kind == IV_SHAPE_CONE ? fmax(s->u.cone.r1, s->u.cone.r2)
                                          : s->u.prism.r;
    return scad_fragments(r, f);
}

iv_region *scad_circle_region(double r, int n)
{
    double(*P)[2] = malloc((size_t)n * sizeof *P);
    if (!P) return NULL;
    for (int i = 0; i < n; i++)
        scad_circle_point(r, i, n, P[i]);
    int st[2] = {0, n};
    iv_region *g = iv_region_new((const double(*)[2])P, st, 1);
    free(P);
    return g;
}

/* One region leaf over paths [start[0], start[n]) of pts (copied). */
static scad_geom *region_leaf(scad_eval *ev, const double (*pts)[2], const int *start, int n,
                              const scad_state *state)
{
    return scad_region_leaf(ev, iv_region_new(pts, start, n), state);
}

typedef struct xspan {
    double lo, hi;
    int path;
} xspan;

static int cmp_xspan(const void *a, const void *b)
{
    const xspan *p = a, *q = b;
    if (p->lo != q->lo) return p->lo < q->lo ? -1 : 1;
    return (p->path > q->path) - (p->path < q->path);
}

/* A set of many paths (a line of text has thousands) is cut where no path
 * spans across in x, and each part is a leaf of its own under a union: a
 * path nested in another overlaps it in x, so each part keeps its holes,
 * and the region's nesting test, every path against all the others, runs
 * per part (a 5,000-character text() took seconds in it). */
enum { CLUSTER_MIN = 64 };

scad_geom *scad_region_geom(scad_eval *ev, const scad_paths *p, const scad_state *state)
{
    if (!p || p->npaths == 0) return NULL;
    const double(*pts)[2] = (const double(*)[2])p->pts;
    if (p->npaths < CLUSTER_MIN) return region_leaf(ev, pts, p->start, p->npaths, state);
    int n = p->npaths;
    xspan *sp = malloc((size_t)n * sizeof *sp);
    double(*q)[2] = malloc((size_t)(p->start[n] - p->start[0]) * sizeof *q);
    int *qs = malloc((size_t)(n + 1) * sizeof *qs);
    scad_geom *u = NULL;
    if (!sp || !q || !qs) {
        free(sp);
        free(q);
        free(qs);
        return region_leaf(ev, pts, p->start, n, state);
    }
    for (int i = 0; i < n; i++) {
        sp[i].lo = INFINITY;
        sp[i].hi = -INFINITY;
        sp[i].path = i;
        for (int k = p->start[i]; k < p->start[i + 1]; k++) {
            sp[i].lo = fmin(sp[i].lo, pts[k][0]);
            sp[i].hi = fmax(sp[i].hi, pts[k][0]);
        }
    }
    qsort(sp, (size_t)n, sizeof *sp, cmp_xspan);
    for (int i = 0; i < n && !ev->aborted;) {
        /* the part: paths whose x ranges chain into one */
        int j = i, nq = 0, np = 0;
        double hi = sp[i].hi;
        qs[0] = 0;
        while (j < n && (j == i || !(sp[j].lo > hi))) {
            hi = fmax(hi, sp[j].hi);
            int a = p->start[sp[j].path], b = p->start[sp[j].path + 1];
            memcpy(q + nq, pts + a, (size_t)(b - a) * sizeof *q);
            nq += b - a;
            qs[++np] = nq;
            j++;
        }
        if (i == 0 && j == n) { /* one part: the set as it came */
            u = region_leaf(ev, pts, p->start, n, state);
            break;
        }
        scad_geom *leaf = region_leaf(ev, (const double(*)[2])q, qs, np, state);
        if (leaf && !u) u = scad_geom_op(ev, CSG_OP_UNION);
        scad_geom_add(ev, u, leaf);
        i = j;
    }
    free(sp);
    free(q);
    free(qs);
    return u;
}

void scad_paths_free(scad_paths *p)
{
    if (!p) return;
    free(p->pts);
    free(p->start);
    p->pts = NULL;
    p->start = NULL;
    p->npaths = 0;
}

int scad_geom_dims(const scad_geom *g)
{
    if (!g) return 0;
    if (!g->is_leaf) {
        int d = 0;
        for (int i = 0; i < g->n; i++)
            d |= scad_geom_dims(g->kids[i]);
        return d;
    }
    return scad_geom_is_flat(g) ? 1 : 2;
}

int scad_geom_is_flat(const scad_geom *g)
{
    return g->is_leaf && !g->extruded && g->shape.kind == IV_SHAPE_PRISM &&
           g->shape.u.prism.z0 == -SCAD_SLAB && g->shape.u.prism.z1 == SCAD_SLAB;
}

/* ---- flattening ------------------------------------------------------------------ */

typedef struct flat {
    scad_eval *ev;
    const double *lfw; /* local_from_world */
    scad_facet_params f;
    scad_loc loc;
    const char *who;
    int failed;
} flat;

/* A leaf's polygons in the local frame, raw (even-odd); -1 out of memory. */
static int leaf_paths(flat *c, const scad_geom *g, scad_paths *out)
{
    csg_affine t;
    csg_affine_mul(c->lfw, g->xf, t);
    const iv_region *src = g->shape.u.prism.g;
    int n, np;
    const double(*P)[2] = NULL;
    const int *ps = NULL;
    int circle_start[2];
    double(*C)[2] = NULL;
    if (src) {
        P = iv_region_points(src, &n);
        ps = iv_region_paths(src, &np);
    } else {
        double r = g->shape.u.prism.r;
        n = scad_facets_shown(c->ev, c->f, r) ? scad_fragments(r, c->f) : SMOOTH_DISC;
        C = malloc((size_t)n * sizeof *C);
        if (!C) return -1;
        for (int i = 0; i < n; i++) {
            double a = 360.0 * i / n;
            C[i][0] = r * iv_cos_degrees(a);
            C[i][1] = r * iv_sin_degrees(a);
        }
        P = (const double(*)[2])C;
        circle_start[0] = 0;
        circle_start[1] = n;
        ps = circle_start;
        np = 1;
    }
    out->pts = malloc((size_t)(n ? n : 1) * sizeof *out->pts);
    out->start = malloc((size_t)(np + 1) * sizeof *out->start);
    if (!out->pts || !out->start) {
        free(C);
        scad_paths_free(out);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        out->pts[i][0] = t[0] * P[i][0] + t[1] * P[i][1] + t[3];
        out->pts[i][1] = t[4] * P[i][0] + t[5] * P[i][1] + t[7];
    }
    memcpy(out->start, ps, (size_t)(np + 1) * sizeof *ps);
    out->npaths = np;
    free(C);
    return 0;
}

static void fail(flat *c, const char *msg)
{
    if (!c->failed) scad_eval_error(c->ev, c->loc, "%s(): %s", c->who, msg);
    c->failed = 1;
}

/* Combine *acc (eo: raw even-odd, else normalised) with b by op. */
static void combine(flat *c, int op, scad_paths *acc, int *acc_eo, scad_paths *b, int b_eo)
{
    const scad_services *s = c->ev->services;
    if (!s->paths_clip) {
        fail(c, "2D booleans are not available here (no polygon service)");
        return;
    }
    scad_paths r = {NULL, NULL, 0};
    char err[256];
    if (s->paths_clip(s->ud, op, acc, *acc_eo, b, b_eo, &r, err, sizeof err) != 0) {
        fail(c, err);
        return;
    }
    scad_paths_free(acc);
    *acc = r;
    *acc_eo = 0;
}

/* g's polygon set into *out; *eo tells whether it is still raw even-odd. */
static void flatten(flat *c, const scad_geom *g, scad_paths *out, int *eo)
{
    out->pts = NULL;
    out->start = NULL;
    out->npaths = 0;
    *eo = 0;
    if (!g || c->failed) return;
    if (g->is_leaf) {
        if (!scad_geom_is_flat(g)) return; /* 3D: not part of a 2D set */
        if (leaf_paths(c, g, out) != 0)
            fail(c, "out of memory");
        else
            *eo = 1;
        return;
    }
    if (g->n == 0) return;
    flatten(c, g->kids[0], out, eo);
    for (int i = 1; i < g->n && !c->failed; i++) {
        if (g->op != CSG_OP_UNION && out->npaths == 0) break; /* empty stays empty */
        scad_paths k;
        int keo;
        flatten(c, g->kids[i], &k, &keo);
        if (!c->failed) combine(c, g->op, out, eo, &k, keo);
        scad_paths_free(&k);
    }
}

int scad_flatten_2d(scad_eval *ev, const scad_geom *g, const csg_affine local_from_world,
                    scad_facet_params f, scad_loc loc, const char *who, scad_paths *out)
{
    flat c = {ev, local_from_world, f, loc, who, 0};
    int eo;
    flatten(&c, g, out, &eo);
    if (!c.failed && eo) { /* a lone leaf: normalise it */
        scad_paths none = {NULL, NULL, 0};
        combine(&c, CSG_OP_UNION, out, &eo, &none, 0);
    }
    if (c.failed) {
        scad_paths_free(out);
        return -1;
    }
    return 0;
}
