/*
 * hull.c — hull() and resize(), which both measure their children by the
 * points of OpenSCAD's tessellation of each leaf: hull() takes the convex
 * hull of those points (3D, or 2D when every leaf is flat), resize() their
 * bounding box.
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../geom/hull2d.h"
#include "../../geom/hull3d.h"
#include "../../intervals/vec3.h"
#include "builtins.h"

typedef struct pts {
    double (*p)[3];
    int n, cap;
    int any3d, any2d;
    scad_eval *ev; /* each point a round leaf makes is a step of work, */
    scad_loc loc;  /* counted here */
    const char *who;
} pts;

/* Room for n more points of a round leaf: 0, or -1 past the step limit
 * (reported; a $fn of 10^9 would make 5·10^9). */
static int pts_steps(pts *P, long n)
{
    return scad_eval_steps(P->ev, n, P->loc, P->who);
}

/* Appends point q (already in the hull's frame). */
static void pts_put(pts *P, const double q[3])
{
    if (P->n == P->cap) {
        if (P->cap > INT_MAX / 2 / (int)sizeof *P->p) return;
        int cap = P->cap ? 2 * P->cap : 256;
        double(*v)[3] = realloc(P->p, (size_t)cap * sizeof *v);
        if (!v) return;
        P->p = v;
        P->cap = cap;
    }
    memcpy(P->p[P->n++], q, sizeof *P->p);
}

static void pts_add(pts *P, const double local_from_world[12], const double xf[12], double x,
                    double y, double z)
{
    double o[3] = {x, y, z}, w[3], q[3];
    csg_affine_point(xf, o, w);
    csg_affine_point(local_from_world, w, q);
    pts_put(P, q);
}

/* The vertices of the polygons (in the hull's frame). */
static void pts_polys(pts *P, geom_polys *s)
{
    for (int i = 0; i < s->nv; i++)
        pts_put(P, s->v[i]);
    geom_polys_free(s);
}

/* The vertices of a 3D leaf's faces (extrusions and revolves). */
static void pts_faces(pts *P, const scad_geom *g, const double lfw[12], scad_facet_params f)
{
    geom_polys q = {0};
    P->any3d = 1;
    if (scad_leaf_polys(g, lfw, f, &q) == 0)
        pts_polys(P, &q);
    else
        geom_polys_free(&q);
}

/* The points of a 2D subtree's boolean result (Clipper, as OpenSCAD). */
static void pts_flat(pts *P, const scad_geom *g, const double lfw[12], scad_facet_params f)
{
    scad_paths r = {0};
    if (scad_flatten_2d(P->ev, g, lfw, f, P->loc, P->who, &r) != 0) return;
    P->any2d = 1;
    int n = r.npaths > 0 ? r.start[r.npaths] : 0;
    for (int i = 0; i < n; i++)
        pts_put(P, (const double[3]){r.pts[i][0], r.pts[i][1], 0});
    scad_paths_free(&r);
}

/* Points whose hull is the subtree's solid as OpenSCAD tessellates it:
 * the points of each leaf, the union of its operands' for a union, and
 * the vertices of the result for an intersection or a difference (2D
 * through Clipper, 3D through BSP: solid.c). */
static void hull_points(pts *P, const scad_geom *g, const double lfw[12], scad_facet_params f)
{
    if (!g || P->ev->aborted) return;
    if (!g->is_leaf) {
        if (g->op == CSG_OP_UNION) {
            for (int i = 0; i < g->n; i++)
                hull_points(P, g->kids[i], lfw, f);
        } else if (scad_geom_dims(g) == 1) {
            pts_flat(P, g, lfw, f);
        } else {
            geom_polys s = {0};
            P->any3d = 1;
            if (scad_solid_polys(P->ev, P->loc, P->who, g, lfw, f, &s) == 0) pts_polys(P, &s);
        }
        return;
    }
    const iv_shape *s = &g->shape;
    switch (s->kind) {
    case IV_SHAPE_BOX:
        P->any3d = 1;
        for (int i = 0; i < 8; i++)
            pts_add(P, lfw, g->xf, (i & 1) ? s->u.box.hi[0] : s->u.box.lo[0],
                    (i & 2) ? s->u.box.hi[1] : s->u.box.lo[1],
                    (i & 4) ? s->u.box.hi[2] : s->u.box.lo[2]);
        return;
    case IV_SHAPE_SPHERE: {
        P->any3d = 1;
        double r = s->u.sphere.r;
        int n = scad_leaf_fragments(g, f), rings = (n + 1) / 2;
        if (pts_steps(P, (long)n * rings)) return;
        for (int i = 0; i < rings; i++) {
            double rr, z;
            scad_sphere_ring(r, i, rings, &rr, &z);
            for (int j = 0; j < n; j++) {
                double c[2];
                scad_circle_point(rr, j, n, c);
                pts_add(P, lfw, g->xf, c[0], c[1], z);
            }
        }
        return;
    }
    case IV_SHAPE_CONE: {
        P->any3d = 1;
        int n = scad_leaf_fragments(g, f);
        if (pts_steps(P, 2L * n)) return;
        for (int k = 0; k < 2; k++)
            for (int j = 0; j < n; j++) {
                double c[2];
                scad_circle_point(k ? s->u.cone.r2 : s->u.cone.r1, j, n, c);
                pts_add(P, lfw, g->xf, c[0], c[1], k ? s->u.cone.h : 0);
            }
        return;
    }
    case IV_SHAPE_POLYTOPE:
    case IV_SHAPE_MESH: {
        P->any3d = 1;
        int n;
        const double(*V)[3] =
            s->kind == IV_SHAPE_MESH ? iv_mesh_vertices(s, &n) : iv_polytope_vertices(s, &n);
        for (int i = 0; i < n; i++)
            pts_add(P, lfw, g->xf, V[i][0], V[i][1], V[i][2]);
        return;
    }
    case IV_SHAPE_PRISM:
        if (scad_geom_is_flat(g)) {
            P->any2d = 1;
            if (!s->u.prism.g) {
                int n = scad_leaf_fragments(g, f);
                if (pts_steps(P, n)) return;
                for (int j = 0; j < n; j++) {
                    double c[2];
                    scad_circle_point(s->u.prism.r, j, n, c);
                    pts_add(P, lfw, g->xf, c[0], c[1], 0);
                }
            } else {
                int n;
                const double(*V)[2] = iv_region_points(s->u.prism.g, &n);
                for (int i = 0; i < n; i++)
                    pts_add(P, lfw, g->xf, V[i][0], V[i][1], 0);
            }
            return;
        }
        pts_faces(P, g, lfw, f); /* an extrusion */
        return;
    default: /* a revolve */
        pts_faces(P, g, lfw, f);
        return;
    }
}

/* The hull of n >= 3 points that lie in one plane (geom_hull3d found no
 * volume): the convex polygon they span, as a sheet — CGAL's hull of
 * coplanar points, which OpenSCAD's preview draws, is that polygon.
 * Returns 0 with *s made, or -1 when they lie on one line or memory ran
 * out. */
static int flat_hull(const double (*p)[3], int n, iv_shape *s)
{
    int b = 0, c = 0;
    double far = 0, u[3], w[3], nrm[3] = {0, 0, 0}, a[3];
    for (int i = 1; i < n; i++) {
        sub3(p[i], p[0], a);
        double d = dot3(a, a);
        if (d > far) far = d, b = i;
    }
    if (!(far > 0)) return -1;
    for (int k = 0; k < 3; k++)
        u[k] = (p[b][k] - p[0][k]) / sqrt(far);
    double best = 0;
    for (int i = 1; i < n; i++) {
        double x[3];
        sub3(p[i], p[0], a);
        cross3(u, a, x);
        double l = dot3(x, x);
        if (l > best) best = l, c = i, memcpy(nrm, x, sizeof nrm);
    }
    if (!(best > 1e-24 * far) || c == 0) return -1;
    double l = sqrt(best);
    for (int k = 0; k < 3; k++)
        nrm[k] /= l;
    cross3(nrm, u, w);
    double(*Q)[3] = malloc((size_t)n * sizeof *Q), (*H)[2] = malloc((size_t)(n + 1) * sizeof *H);
    double(*V)[3] = malloc((size_t)(n + 1) * sizeof *V);
    int *idx = malloc((size_t)(n + 1) * sizeof *idx), rc = -1;
    if (Q && H && V && idx) {
        for (int i = 0; i < n; i++) {
            sub3(p[i], p[0], a);
            Q[i][0] = dot3(a, u);
            Q[i][1] = dot3(a, w);
            Q[i][2] = 0;
        }
        int k = geom_hull2d(Q, n, H);
        for (int i = 0; i < k; i++) {
            for (int j = 0; j < 3; j++)
                V[i][j] = p[0][j] + H[i][0] * u[j] + H[i][1] * w[j];
            idx[i] = i;
        }
        int start[2] = {0, k};
        if (k >= 3)
            rc = iv_shape_polyhedron(s, (const double(*)[3])V, k, idx, start, 1) < 0 ? -1 : 0;
    }
    free(Q);
    free(H);
    free(V);
    free(idx);
    return rc;
}

typedef struct hull_args {
    scad_facet_params f;
} hull_args;

static void hull_read(scad_call *c, void *out)
{
    ((hull_args *)out)->f = scad_facets_read(c);
}

static scad_geom *hull_build(scad_call *c, const void *args)
{
    scad_eval *ev = c->ev;
    const scad_stmt *st = c->st;
    const scad_state *state = c->state;
    scad_geom *kids = scad_call_children(c, NULL);
    if (!kids) return NULL;
    csg_affine inv;
    if (csg_affine_invert(state->xf, inv) != 0) return NULL;
    pts P = {.ev = ev, .loc = st->loc, .who = "hull"};
    hull_points(&P, kids, inv, ((const hull_args *)args)->f);
    scad_geom *g = NULL;
    if (ev->aborted) P.n = 0;
    if (P.any3d && P.n >= 3) {
        iv_shape s;
        int rc = geom_hull3d(&s, (const double(*)[3])P.p, P.n);
        if (rc == GEOM_HULL_FLAT) rc = flat_hull((const double(*)[3])P.p, P.n, &s);
        if (rc == 0 && scad_geom_keep(ev, &s) == 0) g = scad_leaf_at(ev, &s, state, NULL);
        if (rc == GEOM_HULL_TOO_MANY)
            scad_eval_error(ev, st->loc,
                            "hull() of %d points has more than 65536 faces, more than a "
                            "polytope holds; nothing is drawn",
                            P.n);
    } else if (!P.any3d && P.n >= 3) {
        double(*H)[2] = malloc((size_t)(P.n + 1) * sizeof *H);
        if (H) {
            int k = geom_hull2d(P.p, P.n, H);
            int ps[2] = {0, k};
            if (k >= 3)
                g = scad_region_leaf(ev, iv_region_new((const double(*)[2])H, ps, 1), state);
            free(H);
        }
    }
    free(P.p);
    return scad_with_optics(c, g);
}

static int hull_print(scad_call *c, const void *args, scad_buf *b)
{
    (void)c, (void)args;
    scad_buf_puts(b, "hull()");
    return 1;
}

static const scad_module_def hull = {"hull",    NULL,       0,         sizeof(hull_args),
                                     hull_read, hull_print, hull_build};

/* ---- resize ------------------------------------------------------------------------ */

/* The bounding box of the subtree as OpenSCAD's geometry has it: each leaf
 * by the points of its OpenSCAD tessellation (hull_points), a difference by
 * its first operand, an intersection by the overlap of its operands' boxes
 * (exact for the usual cases; an upper bound where a solid trims another).
 * Returns 0, or -1 when empty. */
static int tree_box(scad_eval *ev, scad_loc loc, const scad_geom *g, scad_facet_params f,
                    double lo[3], double hi[3], int *any3d)
{
    if (!g || ev->aborted) return -1;
    if (!g->is_leaf) {
        int n = g->op == CSG_OP_DIFFERENCE && g->n > 0 ? 1 : g->n, have = 0;
        for (int i = 0; i < n; i++) {
            double a[3], b[3];
            if (tree_box(ev, loc, g->kids[i], f, a, b, any3d) != 0) {
                if (g->op == CSG_OP_INTERSECTION) return -1;
                continue;
            }
            for (int k = 0; k < 3; k++) {
                int meet = g->op == CSG_OP_INTERSECTION && have;
                lo[k] = !have ? a[k] : meet ? fmax(lo[k], a[k]) : fmin(lo[k], a[k]);
                hi[k] = !have ? b[k] : meet ? fmin(hi[k], b[k]) : fmax(hi[k], b[k]);
            }
            have = 1;
        }
        if (!have) return -1;
        for (int k = 0; k < 3; k++)
            if (lo[k] > hi[k]) return -1;
        return 0;
    }
    pts P = {.ev = ev, .loc = loc, .who = "resize"};
    hull_points(&P, g, csg_affine_identity, f);
    if (ev->aborted) P.n = 0;
    *any3d |= P.any3d;
    for (int i = 0; i < P.n; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = i ? fmin(lo[k], P.p[i][k]) : P.p[i][k];
            hi[k] = i ? fmax(hi[k], P.p[i][k]) : P.p[i][k];
        }
    int n = P.n;
    free(P.p);
    return n > 0 ? 0 : -1;
}

/* Moves every leaf of g by m; with `flat` (2D children), each leaf's own z
 * scale and offset are dropped first: OpenSCAD resizes 2D children as 2D
 * geometry, so what a scale([1, 1, 20]) below did to their preview slab is
 * gone. */
static void place_tree(scad_geom *g, const csg_affine m, int flat)
{
    if (!g) return;
    if (!g->is_leaf) {
        for (int i = 0; i < g->n; i++)
            place_tree(g->kids[i], m, flat);
        return;
    }
    if (flat) {
        g->xf[2] = g->xf[6] = g->xf[8] = g->xf[9] = g->xf[11] = 0;
        g->xf[10] = 1;
    }
    csg_affine_mul(m, g->xf, g->xf);
}

/* resize(newsize, auto): OpenSCAD's CGAL_Nef_polyhedron::resize (and its 2D
 * twin) — scale about the origin so that the box of the children's
 * geometry gets the new size on each axis where it is non-zero; an axis
 * with newsize 0 keeps its size, or with auto takes the scale of the
 * largest newsize.  2D children have two axes (their slab keeps its
 * thickness). */
enum { RESIZE_NEWSIZE, RESIZE_AUTO, RESIZE_CONVEXITY };

typedef struct resize_args {
    double newsize[3];
    int autosize[3], convexity;
    scad_facet_params f;
} resize_args;

static void resize_read(scad_call *c, void *out)
{
    resize_args *p = out;
    scad_value nv = c->arg[RESIZE_NEWSIZE], av = c->arg[RESIZE_AUTO];
    if (nv.kind == SV_VEC)
        for (int i = 0; i < 3 && i < nv.u.vec->n; i++)
            scad_arg_num(nv.u.vec->v[i], &p->newsize[i]);
    if (av.kind == SV_BOOL) {
        p->autosize[0] = p->autosize[1] = p->autosize[2] = av.u.b;
    } else if (av.kind == SV_VEC) {
        for (int i = 0; i < 3 && i < av.u.vec->n; i++)
            p->autosize[i] = scad_value_truthy(av.u.vec->v[i]);
    }
    p->convexity = scad_arg_int(c->arg[RESIZE_CONVEXITY], 0);
    p->f = scad_facets_read(c);
}

static int resize_print(scad_call *c, const void *args, scad_buf *b)
{
    const resize_args *p = args;
    (void)c;
    scad_buf_puts(b, "resize(newsize = [");
    for (int i = 0; i < 3; i++) {
        if (i) scad_buf_puts(b, ",");
        scad_print_g(b, p->newsize[i]);
    }
    scad_buf_printf(b, "], auto = [%d,%d,%d], convexity = %d)", p->autosize[0], p->autosize[1],
                    p->autosize[2], p->convexity);
    return 1;
}

static scad_geom *resize_build(scad_call *c, const void *args)
{
    const resize_args *p = args;
    scad_eval *ev = c->ev;
    const scad_stmt *st = c->st;
    const scad_state *state = c->state;
    double ns[3];
    const int *aut = p->autosize;
    for (int i = 0; i < 3; i++)
        ns[i] = isfinite(p->newsize[i]) ? p->newsize[i] : 0;
    /* the children in the resize's own frame, placed at the end */
    scad_state local = *state;
    memcpy(local.xf, csg_affine_identity, sizeof local.xf);
    scad_geom *kids = scad_call_children(c, &local);
    if (!kids) return NULL;
    double lo[3], hi[3];
    int any3d = 0;
    double scale[3] = {1, 1, 1};
    int flat = 0;
    if (tree_box(ev, st->loc, kids, p->f, lo, hi, &any3d) == 0) {
        flat = !any3d;
        int dim = any3d ? 3 : 2, imax = 0;
        for (int i = 0; i < dim; i++) {
            if (ns[i] == 0) continue;
            if (hi[i] - lo[i] == 0) {
                scad_diag_warning(ev->d, st->loc,
                                  "Resize in direction normal to flat object is not implemented");
                dim = 0;
                scale[0] = scale[1] = scale[2] = 1;
                break;
            }
            scale[i] = ns[i] / (hi[i] - lo[i]);
            if (ns[i] > ns[imax]) imax = i;
        }
        double autoscale = ns[imax] != 0 && dim > 0 ? ns[imax] / (hi[imax] - lo[imax]) : 1;
        for (int i = 0; i < dim; i++)
            if (aut[i] && ns[i] == 0) scale[i] = autoscale;
    }
    csg_affine s = {scale[0], 0, 0, 0, 0, scale[1], 0, 0, 0, 0, scale[2], 0}, m;
    csg_affine_mul(state->xf, s, m);
    place_tree(kids, m, flat);
    kids->whole = !kids->is_leaf;
    return kids;
}

static const char *const resize_params[] = {"newsize", "auto", "convexity", NULL};
static const scad_module_def resize = {"resize",    resize_params, 3,           sizeof(resize_args),
                                       resize_read, resize_print,  resize_build};

const scad_module_def *const scad_hull_modules[] = {&hull, &resize, NULL};
