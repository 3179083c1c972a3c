/*
 * builtin_minkowski.c — minkowski(): the Minkowski sum of the children.
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

/* A convex part: its points in the call's frame. */
typedef struct part {
    double (*p)[3];
    int n;
} part;

typedef struct parts {
    part *v;
    int n, cap;
} parts;

typedef struct mctx {
    scad_eval *ev;
    scad_loc loc;
    const double *lfw;
    scad_facet_params f;
    const char *why; /* first reason a child cannot be decomposed */
    int oom;
} mctx;

static void parts_free(parts *P)
{
    for (int i = 0; i < P->n; i++)
        free(P->v[i].p);
    free(P->v);
    P->v = NULL;
    P->n = P->cap = 0;
}

/* Append an empty part with room for n points; NULL when out of memory. */
static part *parts_new(mctx *c, parts *P, int n)
{
    if (P->n == P->cap) {
        int cap = P->cap ? 2 * P->cap : 8;
        part *v = realloc(P->v, (size_t)cap * sizeof *v);
        if (!v) {
            c->oom = 1;
            return NULL;
        }
        P->v = v;
        P->cap = cap;
    }
    part *q = &P->v[P->n];
    q->p = malloc((size_t)(n ? n : 1) * sizeof *q->p);
    q->n = 0;
    if (!q->p) {
        c->oom = 1;
        return NULL;
    }
    P->n++;
    return q;
}

static void put(const mctx *c, part *q, const double xf[12], double x, double y, double z)
{
    double o[3] = {x, y, z}, w[3];
    csg_affine_point(xf, o, w);
    csg_affine_point(c->lfw, w, q->p[q->n++]);
}

static void circle(const mctx *c, part *q, const double xf[12], double r, double z, int n)
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

/* Fragments of a smooth leaf of radius r (faceted leaves are polytopes). */
static int fragments(const mctx *c, double r)
{
    int n = scad_fragments(r, c->f);
    return scad_facets_shown(c->ev, c->f, r) || n >= SMOOTH_FRAGMENTS ? n : SMOOTH_FRAGMENTS;
}

/* 1 when every vertex of the mesh is a vertex of its hull. */
static int mesh_is_convex(const double (*V)[3], int n)
{
    iv_shape h;
    if (geom_hull3d(&h, V, n) != 0) return 0;
    int m;
    iv_polytope_vertices(&h, &m);
    iv_shape_release(&h);
    return m == n;
}

/* 1 when the closed polygon turns one way only (collinear points allowed). */
static int convex_polygon(const double (*V)[2], int n)
{
    int pos = 0, neg = 0;
    for (int i = 0; i < n; i++) {
        const double *a = V[i], *b = V[(i + 1) % n], *d = V[(i + 2) % n];
        double t = (b[0] - a[0]) * (d[1] - b[1]) - (b[1] - a[1]) * (d[0] - b[0]);
        pos |= t > 0;
        neg |= t < 0;
    }
    return !(pos && neg);
}

static void decompose(mctx *c, const scad_geom *g, parts *P)
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
    part *q;
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
        if (!mesh_is_convex(V, n)) {
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
        if (np != 1 || !convex_polygon(V, n)) {
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

/* The hull of all sums p + q; -1 when flat or out of memory. */
static int hull_of_sums(const part *a, const part *b, iv_shape *out)
{
    size_t n = (size_t)a->n * (size_t)b->n;
    double(*S)[3] = malloc((n ? n : 1) * sizeof *S);
    if (!S) return -1;
    size_t k = 0;
    for (int i = 0; i < a->n; i++)
        for (int j = 0; j < b->n; j++, k++)
            for (int d = 0; d < 3; d++)
                S[k][d] = a->p[i][d] + b->p[j][d];
    int rc = geom_hull3d(out, (const double(*)[3])S, (int)n);
    free(S);
    return rc;
}

static scad_geom *sum_3d(scad_eval *ev, scad_geom **ops, int nops, const scad_stmt *st,
                         const scad_state *state, mctx *c)
{
    parts acc = {NULL, 0, 0};
    decompose(c, ops[0], &acc);
    for (int i = 1; i < nops && !c->why && !c->oom; i++) {
        parts b = {NULL, 0, 0}, next = {NULL, 0, 0};
        decompose(c, ops[i], &b);
        if (!c->why && (long)acc.n * b.n > MAX_PARTS) c->why = "too many convex parts";
        for (int x = 0; x < acc.n && !c->why && !c->oom && !ev->aborted; x++)
            for (int y = 0; y < b.n && !c->oom; y++) {
                /* each pairwise sum is a step of work */
                if (scad_eval_steps(ev, (long)acc.v[x].n * b.v[y].n, st->loc, "minkowski")) break;
                iv_shape h;
                if (hull_of_sums(&acc.v[x], &b.v[y], &h) != 0) continue;
                int m;
                const double(*V)[3] = iv_polytope_vertices(&h, &m);
                part *q = parts_new(c, &next, m);
                if (q) {
                    memcpy(q->p, V, (size_t)m * sizeof *V);
                    q->n = m;
                }
                iv_shape_release(&h);
            }
        parts_free(&b);
        parts_free(&acc);
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
    parts_free(&acc);
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
    scad_geom *kids = scad_eval_children(ev, c->env, st, state, CSG_OP_UNION);
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

static const scad_module_def minkowski = {
    "minkowski",     {"convexity"},  1, sizeof(minkowski_args), minkowski_read,
    minkowski_print, minkowski_build};

const scad_module_def *const scad_minkowski_modules[] = {&minkowski, NULL};
