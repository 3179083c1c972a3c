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
 * their points.  So each child is read as a union of parts.  Convex parts
 * are cubes, hull() results, extrusions of convex polygons and discs,
 * spheres and cylinders (OpenSCAD's tessellation; a smooth one at least
 * SMOOTH_FRAGMENTS around) and polyhedra whose every vertex is a vertex of
 * their hull.  Anything else — a difference, an intersection, a revolve, a
 * non-convex polyhedron or extrusion — is a solid part S, known by its
 * subtree and its boundary polygons ∂S (solid.c, booleans resolved), and is
 * summed by two identities that hold for closed sets:
 *   S ⊕ Q = (S + q) ∪ ⋃_{f ∈ ∂S} hull(f ⊕ Q)        Q convex, q a point of Q
 *                                                  (its centroid here)
 *   S ⊕ T = (S + V(T)) ∪ (T + V(S)) ∪ ⋃_{f, g} hull(f ⊕ g)
 * (a point a + b of the sum: move b within its part towards q; either a
 * stays in S or it crosses ∂S on the way, and likewise once more for T).
 * The result is the union of those hulls and of translated copies of the
 * solid subtrees: exact, as OpenSCAD's convex decomposition is, and drawn
 * by rays like any union.  The number of parts is capped (MAX_PARTS), and
 * every sum counts against the evaluation's steps.
 */
#include "builtins.h"
#include "../../geom/hull3d.h"
#include "../../geom/minkowski.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum {
    MAX_PARTS = 1 << 18,
    /* Fewest fragments of a smooth sphere or cylinder taken as a convex
     * part: it gets the call's fragments (not yet its own, which
     * scad_leaf_fragments now knows and solid parts use) but at least this
     * many (chords within 0.12 % of the radius). */
    SMOOTH_FRAGMENTS = 64
};

/* A solid part: subtree tree moved by t (the call's frame), its boundary
 * faces (moved too). */
typedef struct msolid {
    const scad_geom *tree;
    double t[3];
    geom_polys faces;
} msolid;

/* One operand, or a partial sum: convex parts and solid parts. */
typedef struct mparts {
    geom_convex_set convex;
    msolid *solid;
    int nsolid, capsolid;
} mparts;

typedef struct mctx {
    scad_eval *ev;
    scad_loc loc;
    const double *lfw;
    scad_facet_params f;
    const char *why; /* first reason a child cannot be summed */
    int oom;
    mparts *solids; /* where decompose puts the operand's solid parts */
} mctx;

static void mparts_free(mparts *m)
{
    geom_convex_set_free(&m->convex);
    for (int i = 0; i < m->nsolid; i++)
        geom_polys_free(&m->solid[i].faces);
    free(m->solid);
    memset(m, 0, sizeof *m);
}

/* Appends solid part tree + t with faces (taken over); -1 out of memory. */
static int solid_add(mparts *m, const scad_geom *tree, const double t[3], geom_polys *faces)
{
    if (m->nsolid == m->capsolid) {
        int cap = m->capsolid ? 2 * m->capsolid : 8;
        msolid *v = realloc(m->solid, (size_t)cap * sizeof *v);
        if (!v) return -1;
        m->solid = v;
        m->capsolid = cap;
    }
    msolid *s = &m->solid[m->nsolid++];
    s->tree = tree;
    memcpy(s->t, t, sizeof s->t);
    s->faces = *faces;
    memset(faces, 0, sizeof *faces);
    return 0;
}

/* g as a solid part of the operand: its faces in the call's frame. */
static void solid_part(mctx *c, const scad_geom *g)
{
    geom_polys faces = {0};
    if (scad_solid_polys(c->ev, c->loc, "minkowski", g, c->lfw, c->f, &faces) != 0) return;
    if (faces.n == 0) return; /* nothing there */
    if (solid_add(c->solids, g, (const double[3]){0, 0, 0}, &faces) != 0) c->oom = 1;
    geom_polys_free(&faces);
}

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
            solid_part(c, g);
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
            double rr, z;
            scad_sphere_ring(r, i, rings, &rr, &z);
            for (int j = 0; j < n; j++) {
                double p[2];
                scad_circle_point(rr, j, n, p);
                put(c, q, g->xf, p[0], p[1], z);
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
            solid_part(c, g);
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
            solid_part(c, g);
            return;
        }
        if (!(q = parts_new(c, P, 2 * n))) return;
        for (int i = 0; i < n; i++) {
            put(c, q, g->xf, V[i][0], V[i][1], z0);
            put(c, q, g->xf, V[i][0], V[i][1], z1);
        }
        return;
    }
    default: /* a revolve */
        solid_part(c, g);
        return;
    }
}

/* Polygon i of faces as a convex part; -1 out of memory. */
static int face_part(const geom_polys *faces, int i, geom_convex *q)
{
    int k = faces->start[i + 1] - faces->start[i];
    q->p = malloc((size_t)k * sizeof *q->p);
    if (!q->p) return -1;
    memcpy(q->p, faces->v + faces->start[i], (size_t)k * sizeof *q->p);
    q->n = k;
    return 0;
}

/* Appends solid s moved by d to out. */
static int solid_moved(mparts *out, const msolid *s, const double d[3])
{
    geom_polys f = {0};
    double t[3] = {s->t[0] + d[0], s->t[1] + d[1], s->t[2] + d[2]};
    if (geom_polys_append(&f, &s->faces) != 0) return -1;
    for (int i = 0; i < f.nv; i++)
        for (int k = 0; k < 3; k++)
            f.v[i][k] += d[k];
    int rc = solid_add(out, s->tree, t, &f);
    geom_polys_free(&f);
    return rc;
}

/* hull(f ⊕ Q) for every face f of s into out. */
static int faces_sum(mctx *c, const msolid *s, const geom_convex *q, geom_convex_set *out)
{
    for (int i = 0; i < s->faces.n; i++) {
        geom_convex f;
        if (face_part(&s->faces, i, &f) != 0) return -1;
        int rc = scad_eval_steps(c->ev, (long)f.n * q->n, c->loc, "minkowski")
                     ? 0
                     : geom_minkowski_pair(&f, q, out);
        free(f.p);
        if (rc != 0) return -1;
        if (c->ev->aborted) return 0;
    }
    return 0;
}

/* The distinct vertices of s's faces as points to move copies by. */
static int solid_vertices(const msolid *s, geom_convex *q)
{
    return scad_polys_vertices(&s->faces, &q->p, &q->n, NULL);
}

/* a ⊕ b into next (every pair of parts, by the identities above). */
static int sum_parts(mctx *c, const mparts *a, const mparts *b, mparts *next)
{
    scad_eval *ev = c->ev;
    long parts = (long)(a->convex.n + a->nsolid) * (b->convex.n + b->nsolid);
    if (parts > MAX_PARTS) return 1;
    for (int x = 0; x < a->convex.n && !ev->aborted; x++)
        for (int y = 0; y < b->convex.n && !ev->aborted; y++) {
            if (scad_eval_steps(ev, (long)a->convex.v[x].n * b->convex.v[y].n, c->loc, "minkowski"))
                break;
            if (geom_minkowski_pair(&a->convex.v[x], &b->convex.v[y], &next->convex) != 0)
                return -1;
        }
    for (int side = 0; side < 2; side++) { /* solids of one with convex parts of the other */
        const mparts *s = side ? b : a, *q = side ? a : b;
        for (int i = 0; i < s->nsolid && !ev->aborted; i++)
            for (int j = 0; j < q->convex.n && !ev->aborted; j++) {
                /* q: the part's centroid, deep inside it, so that the copy
                 * also covers where a smooth solid's facets differ from it */
                const geom_convex *Q = &q->convex.v[j];
                double m[3] = {0, 0, 0};
                for (int k = 0; k < Q->n; k++)
                    for (int a3 = 0; a3 < 3; a3++)
                        m[a3] += Q->p[k][a3] / Q->n;
                if (solid_moved(next, &s->solid[i], m) != 0 ||
                    faces_sum(c, &s->solid[i], &q->convex.v[j], &next->convex) != 0)
                    return -1;
            }
    }
    for (int i = 0; i < a->nsolid && !ev->aborted; i++)
        for (int j = 0; j < b->nsolid && !ev->aborted; j++) {
            const msolid *s = &a->solid[i], *t = &b->solid[j];
            geom_convex vs, vt;
            if (solid_vertices(s, &vs) != 0) return -1;
            if (solid_vertices(t, &vt) != 0) {
                free(vs.p);
                return -1;
            }
            long copies = next->nsolid + (long)vs.n + vt.n;
            int rc = copies > MAX_PARTS ? 1 : 0;
            for (int k = 0; rc == 0 && k < vt.n; k++)
                rc = solid_moved(next, s, vt.p[k]);
            for (int k = 0; rc == 0 && k < vs.n; k++)
                rc = solid_moved(next, t, vs.p[k]);
            free(vs.p);
            free(vt.p);
            for (int f = 0; rc == 0 && f < s->faces.n && !ev->aborted; f++) {
                geom_convex g;
                if (face_part(&s->faces, f, &g) != 0) return -1;
                rc = faces_sum(c, t, &g, &next->convex);
                free(g.p);
            }
            if (rc != 0) return rc;
        }
    return next->convex.n + next->nsolid > MAX_PARTS ? 1 : 0;
}

/* A copy of subtree g moved by t (world from world). */
static scad_geom *moved_copy(scad_eval *ev, const scad_geom *g, const csg_affine t)
{
    if (g->is_leaf) {
        scad_state st;
        csg_affine_mul(t, g->xf, st.xf);
        st.mat = g->mat;
        scad_geom *k = scad_geom_leaf(ev, &g->shape, &st);
        if (k) k->cap = g->cap;
        return k;
    }
    scad_geom *k = scad_geom_op(ev, g->op);
    for (int i = 0; k && i < g->n; i++)
        scad_geom_add(ev, k, moved_copy(ev, g->kids[i], t));
    return k;
}

static scad_geom *sum_3d(scad_eval *ev, scad_geom **ops, int nops, const scad_stmt *st,
                         const scad_state *state, mctx *c)
{
    mparts acc = {0};
    c->solids = &acc;
    decompose(c, ops[0], &acc.convex);
    int too_many = 0;
    for (int i = 1; i < nops && !c->why && !c->oom && !ev->aborted && !too_many; i++) {
        mparts b = {0}, next = {0};
        c->solids = &b;
        decompose(c, ops[i], &b.convex);
        if (b.convex.n + b.nsolid == 0 || acc.convex.n + acc.nsolid == 0) {
            /* an empty operand is passed over, as 2021.01 does */
            if (acc.convex.n + acc.nsolid == 0) {
                mparts_free(&acc);
                acc = b;
            } else {
                mparts_free(&b);
            }
            continue;
        }
        if (!c->why && !c->oom && !ev->aborted) {
            int rc = sum_parts(c, &acc, &b, &next);
            if (rc < 0) c->oom = 1;
            too_many = rc > 0;
        }
        mparts_free(&b);
        mparts_free(&acc);
        acc = next;
    }
    scad_geom *u = NULL;
    if (ev->aborted) {
        /* the step limit, reported */
    } else if (c->why) {
        scad_eval_error(ev, st->loc, "minkowski() of %s is not supported; nothing is drawn",
                        c->why);
    } else if (too_many) {
        scad_eval_error(ev, st->loc,
                        "minkowski(): the sum has more than %d convex parts; nothing is drawn",
                        MAX_PARTS);
    } else if (c->oom) {
        scad_eval_error(ev, st->loc, "minkowski(): out of memory");
    } else {
        u = scad_geom_op(ev, CSG_OP_UNION);
        for (int i = 0; u && i < acc.convex.n; i++) {
            iv_shape h;
            if (geom_hull3d(&h, (const double(*)[3])acc.convex.v[i].p, acc.convex.v[i].n) != 0)
                continue;
            if (scad_geom_keep(ev, &h) != 0) continue;
            scad_geom_add(ev, u, scad_geom_leaf(ev, &h, state));
        }
        for (int i = 0; u && i < acc.nsolid; i++) {
            /* the move, from the call's frame to the world */
            const double *t = acc.solid[i].t, *w = state->xf;
            csg_affine m = {1, 0, 0, w[0] * t[0] + w[1] * t[1] + w[2] * t[2],
                            0, 1, 0, w[4] * t[0] + w[5] * t[1] + w[6] * t[2],
                            0, 0, 1, w[8] * t[0] + w[9] * t[1] + w[10] * t[2]};
            scad_geom_add(ev, u, moved_copy(ev, acc.solid[i].tree, m));
        }
        if (u && u->n == 1) u = u->kids[0];
    }
    mparts_free(&acc);
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
    /* each child statement one operand, whatever it is */
    int nall = 0;
    scad_geom **ops = scad_eval_children_list(ev, c->env, st, state, &nall);
    int nops = 0, dims = 0, any_empty = 0;
    for (int i = 0; i < nall; i++) {
        if (scad_geom_is_empty(ops[i])) {
            any_empty = 1;
            continue;
        }
        dims |= scad_geom_dims(ops[i]);
        ops[nops++] = ops[i];
    }
    scad_geom *g = NULL;
    csg_affine inv;
    scad_facet_params f = ((const minkowski_args *)args)->f;
    if (nops == 0 || csg_affine_invert(state->xf, inv) != 0) {
        /* nothing */
    } else if (dims == 1) {
        /* 2021.01 sums an empty operand too (circle(0), union() {}), which
         * empties a 2D sum; in 3D it is passed over (sum_3d) */
        if (!any_empty) g = sum_2d(ev, ops, nops, st, state, inv, f);
    } else {
        mctx m = {ev, st->loc, inv, f, NULL, 0, NULL};
        g = sum_3d(ev, ops, nops, st, state, &m);
    }
    free(ops);
    return g;
}

static const char *const minkowski_params[] = {"convexity", NULL};
static const scad_module_def minkowski = {
    "minkowski",     minkowski_params, 1, sizeof(minkowski_args), minkowski_read,
    minkowski_print, minkowski_build};

const scad_module_def *const scad_minkowski_modules[] = {&minkowski, NULL};
