/*
 * minkowski.c — minkowski(): the Minkowski sum of the children.
 *
 * 2D children (all of them 2D): each child is flattened to a polygon set
 * (geom2d.c; any booleans) and the sets are summed one after the other by
 * the paths_minkowski service — Clipper, edge by edge, as OpenSCAD does; any
 * shape, holes included.
 *
 * 3D children: the sum distributes over union, (A ∪ B) ⊕ C = (A ⊕ C) ∪
 * (B ⊕ C), and the sum of two convex sets is the convex hull of the sums of
 * their points.  So each child is read as a union of convex parts — cubes,
 * hull() results, extrusions of convex polygons and discs, and OpenSCAD-faceted spheres and
 * cylinders (polytopes), smooth spheres and cylinders tessellated OpenSCAD's way with the call's
 * $fn/$fa/$fs but at least SMOOTH_FRAGMENTS around (a smooth leaf no longer
 * knows its own $fn), and closed polyhedra whose every vertex is a vertex of their
 * hull (taken as convex) — and the result is the union of the hulls of the
 * pairwise vertex sums over every choice of one part per child: exactly
 * OpenSCAD's result for such children.  A child that is a difference, an
 * intersection, a solid of revolution or a non-convex polyhedron is not
 * decomposed: the call reports an error at its location and builds nothing.
 * The number of part combinations is capped (MAX_PARTS).
 */
#include "builtins.h"
#include "../../geom/hull3d.h"
#include "../../geom/minkowski.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum {
    MAX_PARTS = 4096,
    /* Fewest fragments of a smooth sphere or cylinder: a smooth leaf no
     * longer knows its own $fn, so it gets the call's fragments but at
     * least this many (chords within 0.12 % of the radius). */
    SMOOTH_FRAGMENTS = 64
};

typedef struct mctx {
    scad_eval *ev;
    scad_loc loc;
    const double *lfw;
    scad_facet_params f;
    const char *why; /* first reason a child cannot be decomposed */
    int oom;
} mctx;

static void put(const mctx *c, geom_convex *q, const double xf[12], double x, double y, double z)
{
    double o[3] = {x, y, z}, w[3];
    csg_affine_point(xf, o, w);
    csg_affine_point(c->lfw, w, q->p[q->n++]);
}

static void circle(const mctx *c, geom_convex *q, const double xf[12], double r, double z, int n)
{
    if (r == 0) {
        put(c, q, xf, 0, 0, z);
        return;
    }
    for (int j = 0; j < n; j++) {
        double a = 360.0 * j / n;
        put(c, q, xf, r * iv_cos_degrees(a), r * iv_sin_degrees(a), z);
    }
}

/* Append an empty part with room for n points; NULL when out of memory. */
static geom_convex *parts_new(mctx *c, geom_convex_set *P, int n)
{
    geom_convex *q = geom_convex_set_add(P, n);
    if (!q) c->oom = 1;
    return q;
}

/* Fragments of a smooth leaf of radius r (faceted leaves are polytopes). */
static int fragments(const mctx *c, double r)
{
    int n = scad_fragments(r, c->f);
    return scad_facets_shown(c->ev, c->f, r) || n >= SMOOTH_FRAGMENTS ? n : SMOOTH_FRAGMENTS;
}

static void decompose(mctx *c, const scad_geom *g, geom_convex_set *P)
{
    if (!g || c->why || c->oom || c->ev->aborted) return;
    if (!g->is_leaf) {
        if (g->op != CSG_OP_UNION && g->n > 1) {
            c->why = g->op == CSG_OP_DIFFERENCE ? "a difference" : "an intersection";
            return;
        }
        for (int i = 0; i < g->n; i++)
            decompose(c, g->kids[i], P);
        return;
    }
    const iv_shape *s = &g->shape;
    geom_convex *q;
    switch (s->kind) {
    case IV_SHAPE_BOX:
        if (!(q = parts_new(c, P, 8))) return;
        for (int i = 0; i < 8; i++)
            put(c, q, g->xf, (i & 1) ? s->u.box.hi[0] : s->u.box.lo[0],
                (i & 2) ? s->u.box.hi[1] : s->u.box.lo[1],
                (i & 4) ? s->u.box.hi[2] : s->u.box.lo[2]);
        return;
    case IV_SHAPE_SPHERE: {
        double r = s->u.sphere.r;
        int n = fragments(c, r), rings = (n + 1) / 2;
        /* each point a step: the call's $fn of 10^9 would make 5·10^9 */
        if (scad_eval_steps(c->ev, (long)n * rings, c->loc, "minkowski")) return;
        if (!(q = parts_new(c, P, n * rings))) return;
        for (int i = 0; i < rings; i++) {
            double phi = 180.0 * (i + 0.5) / rings;
            double rr = r * iv_sin_degrees(phi), z = r * iv_cos_degrees(phi);
            for (int j = 0; j < n; j++) {
                double a = 360.0 * j / n;
                put(c, q, g->xf, rr * iv_cos_degrees(a), rr * iv_sin_degrees(a), z);
            }
        }
        return;
    }
    case IV_SHAPE_CONE: {
        int n = fragments(c, fmax(s->u.cone.r1, s->u.cone.r2));
        if (!(q = parts_new(c, P, 2 * n))) return;
        circle(c, q, g->xf, s->u.cone.r1, 0, n);
        circle(c, q, g->xf, s->u.cone.r2, s->u.cone.h, n);
        return;
    }
    case IV_SHAPE_POLYTOPE: {
        int n;
        const double(*V)[3] = iv_polytope_vertices(s, &n);
        if (!(q = parts_new(c, P, n))) return;
        for (int i = 0; i < n; i++)
            put(c, q, g->xf, V[i][0], V[i][1], V[i][2]);
        return;
    }
    case IV_SHAPE_MESH: {
        int n;
        const double(*V)[3] = iv_mesh_vertices(s, &n);
        if (!geom_points_convex(V, n)) {
            c->why = "a polyhedron that is not convex";
            return;
        }
        if (!(q = parts_new(c, P, n))) return;
        for (int i = 0; i < n; i++)
            put(c, q, g->xf, V[i][0], V[i][1], V[i][2]);
        return;
    }
    case IV_SHAPE_PRISM: {
        if (scad_geom_is_flat(g)) {
            c->why = "a mix of 2D and 3D objects";
            return;
        }
        /* an extruded convex polygon or disc: its two caps' corners */
        double z0 = s->u.prism.z0, z1 = s->u.prism.z1;
        if (!s->u.prism.g) {
            int n = fragments(c, s->u.prism.r);
            if (!(q = parts_new(c, P, 2 * n))) return;
            circle(c, q, g->xf, s->u.prism.r, z0, n);
            circle(c, q, g->xf, s->u.prism.r, z1, n);
            return;
        }
        int n, np;
        const double(*V)[2] = iv_region_points(s->u.prism.g, &n);
        iv_region_paths(s->u.prism.g, &np);
        if (np != 1 || !geom_polygon_convex(V, n)) {
            c->why = "an extrusion of a shape that is not convex";
            return;
        }
        if (!(q = parts_new(c, P, 2 * n))) return;
        for (int i = 0; i < n; i++) {
            put(c, q, g->xf, V[i][0], V[i][1], z0);
            put(c, q, g->xf, V[i][0], V[i][1], z1);
        }
        return;
    }
    default:
        c->why = "a solid of revolution";
        return;
    }
}

static scad_geom *sum_3d(scad_eval *ev, scad_geom **ops, int nops, const scad_stmt *st,
                         const scad_state *state, mctx *c)
{
    geom_convex_set acc = {NULL, 0, 0};
    decompose(c, ops[0], &acc);
    for (int i = 1; i < nops && !c->why && !c->oom; i++) {
        geom_convex_set b = {NULL, 0, 0}, next = {NULL, 0, 0};
        decompose(c, ops[i], &b);
        if (!c->why && (long)acc.n * b.n > MAX_PARTS) c->why = "too many convex parts";
        for (int x = 0; x < acc.n && !c->why && !c->oom && !ev->aborted; x++)
            for (int y = 0; y < b.n && !c->oom; y++) {
                /* each pairwise sum is a step of work */
                if (scad_eval_steps(ev, (long)acc.v[x].n * b.v[y].n, st->loc, "minkowski")) break;
                if (geom_minkowski_pair(&acc.v[x], &b.v[y], &next) != 0) c->oom = 1;
            }
        geom_convex_set_free(&b);
        geom_convex_set_free(&acc);
        acc = next;
    }
    scad_geom *u = NULL;
    if (ev->aborted) {
        /* the step limit, reported */
    } else if (c->why) {
        scad_eval_error(ev, st->loc,
                        "minkowski() of %s is not supported: each child must be a convex shape "
                        "or a union of convex shapes; nothing is drawn",
                        c->why);
    } else if (c->oom) {
        scad_eval_error(ev, st->loc, "minkowski(): out of memory");
    } else {
        u = acc.n > 1 ? scad_geom_op(ev, CSG_OP_UNION) : NULL;
        scad_geom *one = NULL;
        for (int i = 0; i < acc.n; i++) {
            iv_shape h;
            if (geom_hull3d(&h, (const double(*)[3])acc.v[i].p, acc.v[i].n) != 0) continue;
            if (scad_geom_keep(ev, &h) != 0) continue;
            one = scad_geom_leaf(ev, &h, state);
            if (u) scad_geom_add(ev, u, one);
        }
        if (!u) u = one;
    }
    geom_convex_set_free(&acc);
    return u;
}

static scad_geom *sum_2d(scad_eval *ev, scad_geom **ops, int nops, const scad_stmt *st,
                         const scad_state *state, const double *lfw, scad_facet_params f)
{
    const scad_services *s = ev->services;
    if (!s->paths_minkowski || !s->paths_clip) {
        scad_eval_error(ev, st->loc,
                        "minkowski() of 2D shapes is not available here "
                        "(no polygon service)");
        return NULL;
    }
    scad_paths acc;
    if (scad_flatten_2d(ev, ops[0], lfw, f, st->loc, "minkowski", &acc) != 0) return NULL;
    for (int i = 1; i < nops; i++) {
        scad_paths b, r;
        if (scad_flatten_2d(ev, ops[i], lfw, f, st->loc, "minkowski", &b) != 0) {
            scad_paths_free(&acc);
            return NULL;
        }
        char err[256];
        int rc = s->paths_minkowski(s->ud, &acc, &b, &r, err, sizeof err);
        scad_paths_free(&b);
        scad_paths_free(&acc);
        if (rc != 0) {
            scad_eval_error(ev, st->loc, "minkowski(): %s", err);
            return NULL;
        }
        acc = r;
    }
    scad_geom *g = scad_region_geom(ev, &acc, state);
    scad_paths_free(&acc);
    return g;
}

typedef struct minkowski_args {
    int convexity;
    scad_facet_params f;
} minkowski_args;

static void minkowski_read(scad_call *c, void *out)
{
    minkowski_args *p = out;
    p->convexity = scad_arg_int(c->arg[0], 0);
    p->f = scad_facets_read(c);
}

static int minkowski_print(scad_call *c, const void *args, scad_buf *b)
{
    (void)c;
    scad_buf_printf(b, "minkowski(convexity = %d)", ((const minkowski_args *)args)->convexity);
    return 1;
}

static scad_geom *minkowski_build(scad_call *c, const void *args)
{
    scad_eval *ev = c->ev;
    const scad_stmt *st = c->st;
    const scad_state *state = c->state;
    scad_geom *kids = scad_call_children(c, NULL);
    if (!kids) return NULL;
    /* Several child statements come back as one union whose operands are
     * the children; a single statement is one operand, whatever it is. */
    scad_geom **ops = &kids;
    int nops = 1;
    if (st->children && st->children->nstmts > 1 && !kids->is_leaf && kids->op == CSG_OP_UNION &&
        kids->n > 1) {
        ops = kids->kids;
        nops = kids->n;
    }
    csg_affine inv;
    if (csg_affine_invert(state->xf, inv) != 0) return NULL;
    scad_facet_params f = ((const minkowski_args *)args)->f;
    if (scad_geom_dims(kids) == 1) return sum_2d(ev, ops, nops, st, state, inv, f);
    mctx m = {ev, st->loc, inv, f, NULL, 0};
    return sum_3d(ev, ops, nops, st, state, &m);
}

static const char *const minkowski_params[] = {"convexity", NULL};
static const scad_module_def minkowski = {
    "minkowski",     minkowski_params, 1, sizeof(minkowski_args), minkowski_read,
    minkowski_print, minkowski_build};

const scad_module_def *const scad_minkowski_modules[] = {&minkowski, NULL};
