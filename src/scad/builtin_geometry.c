/*
 * builtin_geometry.c — the geometry modules beyond cube/sphere/cylinder and
 * the transforms: square, circle, polygon, polyhedron, linear_extrude,
 * rotate_extrude, hull, and sphere/cylinder again with OpenSCAD's facets.
 *
 * Facets (scad_options.facets): SMOOTH keeps every round primitive
 * analytic; OPENSCAD builds each sphere, cylinder and circle exactly as
 * OpenSCAD 2021.01 tessellates it (get_fragments_from_r, the sphere's rings
 * at polar angles 180·(i + ½)/rings) — a convex polytope, or a polygon;
 * AUTO, the default, is smooth unless $fn is set to a count of at most 16,
 * where the facets are meant to be seen.
 *
 * 2D objects are prisms over a region (or a disc) between z = -½ and z = ½,
 * which is how OpenSCAD's preview draws them.  The extrusions are point maps
 * from 3D to the plane — p is in linear_extrude(h) of S when its shadow is
 * in S and 0 <= z <= h; p is in rotate_extrude of S when (|p_xy|, p_z) is —
 * and a preimage commutes with union, intersection and difference.  So an
 * extrusion keeps its children's CSG tree and only replaces each 2D leaf by
 * the extrusion of that leaf: the prism's z range for linear_extrude, a
 * revolve of the leaf's region (with the leaf's own 2D transform baked in)
 * for rotate_extrude.
 *
 * Ownership: every shape with shared data made here is recorded in
 * ev->owned, which holds one reference; scad_geometry_release drops them all
 * once the csg nodes (which retain their own) exist.
 */
#include "builtin_geometry.h"
#include "hull3d.h"
#include "material.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define GRID_FINE 0.00000095367431640625 /* OpenSCAD's smallest radius */
/* Half the thickness of the slab OpenSCAD 2021.01 previews a 2D object as
 * (measured: a side view of square(10) shows z from -0.5 to 0.5). */
#define SLAB 0.5

/* ---- small helpers ---------------------------------------------------------- */

static int num_of(scad_value v, double *x)
{
    if (v.kind != SV_NUM) return 0;
    *x = v.u.num;
    return 1;
}

void scad_geometry_release(scad_eval *ev)
{
    for (int i = 0; i < ev->nowned; i++)
        iv_shape_release(&ev->owned[i]);
    free(ev->owned);
    ev->owned = NULL;
    ev->nowned = ev->capowned = 0;
}

scad_geom *scad_geometry_leaf(scad_eval *ev, iv_shape *s, const scad_state *state)
{
    if (scad_geom_keep(ev, s) != 0) return NULL;
    return scad_geom_leaf(ev, s, state);
}

static scad_geom *leaf_at(scad_eval *ev, const iv_shape *s, const scad_state *state,
                          const csg_affine local)
{
    scad_state st = *state;
    if (local) csg_affine_mul(state->xf, local, st.xf);
    return scad_geom_leaf(ev, s, &st);
}

/* ---- facets ------------------------------------------------------------------ */

/* Circle point i of n at radius r, OpenSCAD's generate_circle. */
static void circle_pt(double r, int i, int n, double out[2])
{
    double a = 360.0 * i / n;
    out[0] = r * scad_cos_degrees(a);
    out[1] = r * scad_sin_degrees(a);
}

/* ---- sphere, cylinder ------------------------------------------------------- */

/* OpenSCAD's lookup_radius: d/2 wins over r, with a warning when both. */
static int radius(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *dname,
                  const char *rname, int rpos, double *out)
{
    scad_value d = scad_argv_get(a, dname, -1);
    scad_value r = scad_argv_get(a, rname, rpos);
    double x;
    if (num_of(d, &x)) {
        if (r.kind == SV_NUM)
            scad_diag_warning(ev->d, loc,
                              "Ignoring radius variable '%s' as diameter '%s' is defined too.",
                              rname, dname);
        *out = x / 2;
        return 1;
    }
    if (num_of(r, &x)) {
        *out = x;
        return 1;
    }
    return 0;
}

/* A sphere's or cylinder's leaf: leaf_at plus the $rs_ optics its call and
 * scope set (material.c), as builtin_modules.c's leaf() gives a cube. */
static scad_geom *optics_leaf(scad_eval *ev, scad_env *env, const scad_argv *a, const iv_shape *s,
                              const scad_state *state, const csg_affine local)
{
    scad_state st = *state;
    if (local) csg_affine_mul(state->xf, local, st.xf);
    scad_material_apply(ev, env, a, s, st.xf, &st.mat);
    return scad_geom_leaf(ev, s, &st);
}

static scad_geom *hull_leaf(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                            const double (*P)[3], int n, const scad_state *state,
                            const csg_affine local)
{
    iv_shape s;
    /* every point of a sphere or cylinder is a vertex, and a hull of V
     * vertices has 2V - 4 triangles: too many is known at once */
    int rc = 2L * n - 4 > 65536 ? SCAD_HULL_TOO_MANY : scad_hull3d(&s, P, n);
    if (rc == SCAD_HULL_TOO_MANY)
        scad_diag_error(ev->d, st->loc,
                        "%s() of %d points has more than 65536 faces, more than a polytope "
                        "holds; nothing is drawn",
                        st->name, n);
    if (rc != 0 || scad_geom_keep(ev, &s) != 0) return NULL;
    return optics_leaf(ev, env, a, &s, state, local);
}

static scad_geom *m_sphere(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                           const scad_state *state)
{
    static const char *const known[] = {"r", "d", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double r = 1;
    radius(ev, a, st->loc, "d", "r", 0, &r);
    if (!(r > 0) || !isfinite(r)) return NULL;
    scad_facet_params f = scad_facets_lookup(ev, env, a, st->loc);
    iv_shape sh;
    memset(&sh, 0, sizeof sh);
    if (!scad_facets_shown(ev, f, r)) {
        sh.kind = IV_SHAPE_SPHERE;
        sh.u.sphere.r = r;
        return optics_leaf(ev, env, a, &sh, state, NULL);
    }
    int n = scad_fragments(r, f), rings = (n + 1) / 2;
    /* each point a step: a $fn of 10^9 would make 5·10^9 */
    if (scad_eval_steps(ev, (long)n * rings, st->loc, "sphere")) return NULL;
    if ((long)n * rings > INT_MAX / 32) { /* only under a raised step limit */
        scad_eval_error(ev, st->loc, "sphere() of %ld points is too big", (long)n * rings);
        return NULL;
    }
    double(*P)[3] = malloc((size_t)n * (size_t)rings * sizeof *P);
    if (!P) return NULL;
    for (int i = 0; i < rings; i++) {
        double phi = 180.0 * (i + 0.5) / rings;
        double rr = r * scad_sin_degrees(phi), z = r * scad_cos_degrees(phi);
        for (int j = 0; j < n; j++) {
            double c[2];
            circle_pt(rr, j, n, c);
            P[i * n + j][0] = c[0];
            P[i * n + j][1] = c[1];
            P[i * n + j][2] = z;
        }
    }
    scad_geom *g = hull_leaf(ev, env, st, a, (const double(*)[3])P, n * rings, state, NULL);
    free(P);
    return g;
}

static scad_geom *m_cylinder(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                             const scad_state *state)
{
    static const char *const known[] = {"h", "r1", "r2", "center", "r", "d", "d1", "d2", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double h = 1, r1 = 1, r2 = 1, r;
    num_of(scad_argv_get(a, "h", 0), &h);
    int has_r = radius(ev, a, st->loc, "d", "r", -1, &r);
    double x1, x2;
    int has_r1 = radius(ev, a, st->loc, "d1", "r1", 1, &x1);
    int has_r2 = radius(ev, a, st->loc, "d2", "r2", 2, &x2);
    if (has_r) r1 = r2 = r;
    if (has_r1) r1 = x1;
    if (has_r2) r2 = x2;
    scad_value c = scad_argv_get(a, "center", 3);
    int center = c.kind == SV_BOOL && c.u.b;
    if (!(h > 0) || !isfinite(h) || !(r1 >= 0) || !(r2 >= 0) || !isfinite(r1) || !isfinite(r2) ||
        (r1 == 0 && r2 == 0))
        return NULL;
    csg_affine t = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, center ? -h / 2 : 0};
    scad_facet_params f = scad_facets_lookup(ev, env, a, st->loc);
    iv_shape sh;
    memset(&sh, 0, sizeof sh);
    if (!scad_facets_shown(ev, f, r1 > r2 ? r1 : r2)) {
        sh.kind = IV_SHAPE_CONE;
        sh.u.cone.r1 = r1;
        sh.u.cone.r2 = r2;
        sh.u.cone.h = h;
        return optics_leaf(ev, env, a, &sh, state, t);
    }
    int n = scad_fragments(fmax(r1, r2), f), np = 0;
    double(*P)[3] = malloc((size_t)(2 * n) * sizeof *P);
    if (!P) return NULL;
    for (int k = 0; k < 2; k++) {
        double rr = k ? r2 : r1;
        if (rr == 0) { /* an apex: one point */
            P[np][0] = P[np][1] = 0;
            P[np++][2] = k ? h : 0;
            continue;
        }
        for (int j = 0; j < n; j++) {
            double cp[2];
            circle_pt(rr, j, n, cp);
            P[np][0] = cp[0];
            P[np][1] = cp[1];
            P[np++][2] = k ? h : 0;
        }
    }
    scad_geom *g = hull_leaf(ev, env, st, a, (const double(*)[3])P, np, state, t);
    free(P);
    return g;
}

/* ---- 2D ------------------------------------------------------------------------- */

/* A 2D leaf: region g (its reference passes to the evaluation) in the
 * preview slab. */
static scad_geom *region_leaf(scad_eval *ev, iv_region *g, const scad_state *state)
{
    if (!g) return NULL;
    iv_shape s;
    iv_shape_prism(&s, g, -SLAB, SLAB);
    iv_region_release(g); /* the shape holds it now */
    if (scad_geom_keep(ev, &s) != 0) return NULL;
    return leaf_at(ev, &s, state, NULL);
}

static iv_region *circle_region(double r, int n)
{
    double(*P)[2] = malloc((size_t)n * sizeof *P);
    if (!P) return NULL;
    for (int i = 0; i < n; i++)
        circle_pt(r, i, n, P[i]);
    int st[2] = {0, n};
    iv_region *g = iv_region_new((const double(*)[2])P, st, 1);
    free(P);
    return g;
}

static scad_geom *square_plain(scad_eval *ev, scad_env *env, const scad_stmt *st,
                               const scad_argv *a, const scad_state *state)
{
    (void)env;
    static const char *const known[] = {"size", "center", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double s[2] = {1, 1}, x;
    scad_value size = scad_argv_get(a, "size", 0);
    if (num_of(size, &x)) {
        s[0] = s[1] = x;
    } else if (size.kind == SV_VEC) {
        if (size.u.vec->n < 2 || !num_of(size.u.vec->v[0], &s[0]) ||
            !num_of(size.u.vec->v[1], &s[1]))
            return NULL;
    }
    if (!(s[0] > 0) || !(s[1] > 0) || !isfinite(s[0]) || !isfinite(s[1])) return NULL;
    scad_value c = scad_argv_get(a, "center", 1);
    int center = c.kind == SV_BOOL && c.u.b;
    double x0 = center ? -s[0] / 2 : 0, y0 = center ? -s[1] / 2 : 0;
    double P[4][2] = {{x0, y0}, {x0 + s[0], y0}, {x0 + s[0], y0 + s[1]}, {x0, y0 + s[1]}};
    int ps[2] = {0, 4};
    return region_leaf(ev, iv_region_new((const double(*)[2])P, ps, 1), state);
}

static scad_geom *circle_plain(scad_eval *ev, scad_env *env, const scad_stmt *st,
                               const scad_argv *a, const scad_state *state)
{
    static const char *const known[] = {"r", "d", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double r = 1;
    radius(ev, a, st->loc, "d", "r", 0, &r);
    if (!(r > 0) || !isfinite(r)) return NULL;
    scad_facet_params f = scad_facets_lookup(ev, env, a, st->loc);
    if (scad_facets_shown(ev, f, r))
        return region_leaf(ev, circle_region(r, scad_fragments(r, f)), state);
    iv_shape s;
    memset(&s, 0, sizeof s);
    s.kind = IV_SHAPE_PRISM;
    s.u.prism.r = r;
    s.u.prism.z0 = -SLAB;
    s.u.prism.z1 = SLAB;
    scad_geom *g = leaf_at(ev, &s, state, NULL);
    /* A leaf has no children, so its cap is free: a smooth disc keeps
     * OpenSCAD's fragment count there for a twisted or scaled extrusion,
     * which must build OpenSCAD's polygon (disc_fragments). */
    if (g) g->cap = scad_fragments(r, f);
    return g;
}

/* A vector of n-vectors of numbers (n = 2 or 3; a 2-vector is read with z
 * = 0 when n is 3) into a malloc'd array; NULL when v is not one. */
static double *points_of(scad_value v, int n, int *count)
{
    if (v.kind != SV_VEC || v.u.vec->n == 0) return NULL;
    int m = v.u.vec->n;
    double *P = calloc((size_t)m * (size_t)n, sizeof *P);
    if (!P) return NULL;
    for (int i = 0; i < m; i++) {
        scad_value p = v.u.vec->v[i];
        if (p.kind != SV_VEC || p.u.vec->n < 2) goto bad;
        for (int k = 0; k < n && k < p.u.vec->n; k++)
            if (!num_of(p.u.vec->v[k], &P[i * n + k]) || !isfinite(P[i * n + k])) goto bad;
    }
    *count = m;
    return P;
bad:
    free(P);
    return NULL;
}

/* Index lists (paths or faces) flattened: idx and start (count + 1). */
static int index_lists(scad_value v, int npts, int **idx, int **start, int *count)
{
    *idx = NULL;
    *start = NULL;
    if (v.kind != SV_VEC) return -1;
    int m = v.u.vec->n, total = 0;
    for (int i = 0; i < m; i++) {
        if (v.u.vec->v[i].kind != SV_VEC) return -1;
        total += v.u.vec->v[i].u.vec->n;
    }
    *idx = malloc((size_t)(total ? total : 1) * sizeof **idx);
    *start = malloc((size_t)(m + 1) * sizeof **start);
    if (!*idx || !*start) return -1;
    int k = 0;
    for (int i = 0; i < m; i++) {
        (*start)[i] = k;
        const scad_vec *f = v.u.vec->v[i].u.vec;
        for (int j = 0; j < f->n; j++) {
            double x;
            if (!num_of(f->v[j], &x) || !(x >= 0) || !(x < npts)) return -1;
            (*idx)[k++] = (int)x;
        }
    }
    (*start)[m] = k;
    *count = m;
    return 0;
}

static scad_geom *polygon_plain(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                const scad_argv *a, const scad_state *state)
{
    (void)env;
    static const char *const known[] = {"points", "paths", "convexity", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    int n = 0;
    double *P = points_of(scad_argv_get(a, "points", 0), 2, &n);
    if (!P) return NULL;
    scad_value paths = scad_argv_get(a, "paths", 1);
    iv_region *g = NULL;
    if (paths.kind == SV_UNDEF) {
        int ps[2] = {0, n};
        g = iv_region_new((const double(*)[2])P, ps, 1);
    } else {
        int *idx, *start, np;
        if (index_lists(paths, n, &idx, &start, &np) == 0 && np > 0) {
            double(*Q)[2] = malloc((size_t)(start[np] ? start[np] : 1) * sizeof *Q);
            if (Q) {
                for (int i = 0; i < start[np]; i++) {
                    Q[i][0] = P[2 * idx[i]];
                    Q[i][1] = P[2 * idx[i] + 1];
                }
                g = iv_region_new((const double(*)[2])Q, start, np);
                free(Q);
            }
        } else {
            scad_diag_warning(ev->d, st->loc, "polygon(): paths must be lists of point indices");
        }
        free(idx);
        free(start);
    }
    free(P);
    return region_leaf(ev, g, state);
}

/* ---- polyhedron ----------------------------------------------------------------- */

static scad_geom *polyhedron_plain(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                   const scad_argv *a, const scad_state *state)
{
    (void)env;
    static const char *const known[] = {"points", "faces", "triangles", "convexity", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    int n = 0;
    double *P = points_of(scad_argv_get(a, "points", 0), 3, &n);
    if (!P) return NULL;
    scad_value faces = scad_argv_get(a, "faces", 1);
    if (faces.kind == SV_UNDEF) {
        faces = scad_argv_get(a, "triangles", -1);
        if (faces.kind != SV_UNDEF)
            scad_diag_line(ev->d, SCAD_MSG_WARNING,
                           "DEPRECATED: polyhedron(triangles=[]) will be removed in future "
                           "releases. Use polyhedron(faces=[]) instead.");
    }
    int *idx, *start, nf;
    scad_geom *g = NULL;
    if (index_lists(faces, n, &idx, &start, &nf) != 0 || nf == 0) {
        scad_diag_warning(ev->d, st->loc, "polyhedron(): faces must be lists of point indices");
    } else {
        iv_shape s;
        int rc = iv_shape_mesh(&s, (const double(*)[3])P, n, idx, start, nf);
        if (rc == 1)
            scad_diag_warning(ev->d, st->loc,
                              "polyhedron() is not closed (an edge is not shared by exactly "
                              "two faces); it is rendered best effort");
        if (rc >= 0 && scad_geom_keep(ev, &s) == 0) g = leaf_at(ev, &s, state, NULL);
    }
    free(idx);
    free(start);
    free(P);
    return g;
}

/* ---- extrusions ------------------------------------------------------------------ */

/* The leaf's 2D transform in the extrusion's frame: local_from_world ∘
 * leaf.xf with its z row and column dropped (OpenSCAD extrudes the
 * shadow). */
static void leaf_2d(const csg_affine local_from_world, const csg_affine leaf_xf, csg_affine out)
{
    csg_affine t;
    csg_affine_mul(local_from_world, leaf_xf, t);
    csg_affine r = {t[0], t[1], 0, t[3], t[4], t[5], 0, t[7], 0, 0, 1, 0};
    memcpy(out, r, sizeof r);
}

/* A node that is the empty set. */
static void make_empty(scad_geom *g)
{
    g->is_leaf = 0;
    g->op = CSG_OP_UNION;
    g->n = 0;
}

static void linear_tree(scad_geom *g, const csg_affine local_from_world,
                        const csg_affine world_from_local, double z0, double z1)
{
    if (!g) return;
    if (!g->is_leaf) {
        for (int i = 0; i < g->n; i++)
            linear_tree(g->kids[i], local_from_world, world_from_local, z0, z1);
        return;
    }
    if (g->shape.kind != IV_SHAPE_PRISM) { /* a 3D child: OpenSCAD ignores it */
        make_empty(g);
        return;
    }
    csg_affine t;
    leaf_2d(local_from_world, g->xf, t);
    csg_affine_mul(world_from_local, t, g->xf);
    g->shape.u.prism.z0 = z0;
    g->shape.u.prism.z1 = z1;
}

/* ---- twisted and scaled linear_extrude ------------------------------------------ */

/* The region of a 2D leaf in the extrusion's frame (a new reference), x
 * multiplied by sign; a disc becomes the polygon of disc_n points.  NULL
 * when out of memory. */
static iv_region *shadow_region(const double *local_from_world, const scad_geom *g, int disc_n,
                                double sign)
{
    csg_affine t;
    leaf_2d(local_from_world, g->xf, t);
    const iv_region *src = g->shape.u.prism.g;
    iv_region *tmp = NULL;
    if (!src) {
        tmp = circle_region(g->shape.u.prism.r, disc_n);
        if (!tmp) return NULL;
        src = tmp;
    }
    int n, np;
    const double(*P)[2] = iv_region_points(src, &n);
    const int *ps = iv_region_paths(src, &np);
    double(*Q)[2] = malloc((size_t)n * sizeof *Q);
    iv_region *out = NULL;
    if (Q) {
        for (int i = 0; i < n; i++) {
            Q[i][0] = sign * (t[0] * P[i][0] + t[1] * P[i][1] + t[3]);
            Q[i][1] = t[4] * P[i][0] + t[5] * P[i][1] + t[7];
        }
        out = iv_region_new((const double(*)[2])Q, ps, np);
        free(Q);
    }
    if (tmp) iv_region_release(tmp);
    return out;
}

/* OpenSCAD's fragment count for a disc leaf: the one m_circle recorded, or
 * (a disc made elsewhere) the count the enclosing module's facets give. */
static int disc_fragments(const scad_geom *g, scad_facet_params f)
{
    return g->cap >= 3 ? g->cap : scad_fragments(g->shape.u.prism.r, f);
}

typedef struct twist_ctx {
    scad_eval *ev;
    scad_loc loc;
    const double *local_from_world;
    const double *world_from_local;
    double h1, h2, twist, scale[2];
    int slices;
    scad_facet_params f;
    double max_r2, max_d2; /* the scan's results */
} twist_ctx;

/* The largest squared radius of the shadow's vertices, and the largest
 * squared distance a vertex moves between bottom and top scale — what
 * OpenSCAD sizes its default slices by.  The shadow is bounded as in
 * revolve_scan: a difference by its first operand. */
static void twist_scan(twist_ctx *c, const scad_geom *g)
{
    if (!g) return;
    if (!g->is_leaf) {
        int n = g->op == CSG_OP_DIFFERENCE && g->n > 0 ? 1 : g->n;
        for (int i = 0; i < n; i++)
            twist_scan(c, g->kids[i]);
        return;
    }
    if (g->shape.kind != IV_SHAPE_PRISM) return;
    iv_region *r = shadow_region(c->local_from_world, g, disc_fragments(g, c->f), 1);
    if (!r) return;
    int n;
    const double(*P)[2] = iv_region_points(r, &n);
    for (int i = 0; i < n; i++) {
        double x = P[i][0], y = P[i][1];
        double dx = x - x * c->scale[0], dy = y - y * c->scale[1];
        c->max_r2 = fmax(c->max_r2, x * x + y * y);
        c->max_d2 = fmax(c->max_d2, dx * dx + dy * dy);
    }
    iv_region_release(r);
}

/* Calc::get_helix_slices, get_conical_helix_slices and get_diagonal_slices
 * of OpenSCAD 2021.01: the default slice count from $fn/$fa/$fs.  A twist
 * needs at least one slice per 120°. */
static double archimedes_length(double a, double theta)
{
    return 0.5 * a * (theta * sqrt(1 + theta * theta) + asinh(theta));
}

static int default_slices(const twist_ctx *c, double h)
{
    double sx = c->scale[0], sy = c->scale[1];
    scad_facet_params f = c->f;
    if (c->twist != 0) {
        double tw = fabs(c->twist), r = sqrt(c->max_r2);
        int min_slices = (int)fmax(ceil(tw / 120.0), 1);
        if (r < GRID_FINE || !isfinite(f.fn)) return min_slices;
        if (f.fn > 0) return (int)fmax(ceil(tw / 360.0 * f.fn), min_slices);
        double len, rads = tw * PI / 180;
        if ((sx == 1 && sy == 1) || sx != sy) { /* a helix */
            double k = h / rads;
            len = rads * sqrt(c->max_r2 + k * k);
        } else { /* uniform scale: a conical helix, its plan an Archimedes spiral */
            double end = sx > 1 ? rads * sx / (sx - 1) : rads / (1 - sx);
            double a = r / end;
            double spiral = archimedes_length(a, end) - archimedes_length(a, end - rads);
            len = sqrt(spiral * spiral + h * h);
        }
        double fs_slices = ceil(len / fmax(f.fs, 0.01)), fa_slices = ceil(tw / fmax(f.fa, 0.01));
        double n = fmax(fmin(fa_slices, fs_slices), min_slices);
        return n > 100000 ? 100000 : (int)n;
    }
    if (sx != sy) { /* non-uniform scale alone: the longest diagonal path */
        if (sqrt(c->max_d2) < GRID_FINE || !isfinite(f.fn)) return 1;
        if (f.fn > 0) return f.fn > 100000 ? 100000 : (int)fmax(f.fn, 1);
        double n = fmax(ceil(sqrt(c->max_d2 + h * h) / fmax(f.fs, 0.01)), 1);
        return n > 100000 ? 100000 : (int)n;
    }
    return 1;
}

/* OpenSCAD's sgn_vdiff: compares |a| with |b|, equal within 10 ppm of
 * their mean, so that the diagonal choice below does not flip on
 * rounding. */
static int length_order(double ax, double ay, double bx, double by)
{
    double l1 = hypot(ax, ay), l2 = hypot(bx, by);
    return 2 * fabs(l1 - l2) * 1e5 > l1 + l2 ? (l1 < l2 ? -1 : 1) : 0;
}

typedef struct mesh_build {
    double (*v)[3];
    int nv, capv;
    int *idx, nidx, capidx;
    int *start, nf, capf;
    int oom;
} mesh_build;

static int mb_vertex(mesh_build *m, double x, double y, double z)
{
    if (m->nv == m->capv) {
        int cap = m->capv ? 2 * m->capv : 256;
        double(*v)[3] = realloc(m->v, (size_t)cap * sizeof *v);
        if (!v) {
            m->oom = 1;
            return 0;
        }
        m->v = v;
        m->capv = cap;
    }
    m->v[m->nv][0] = x;
    m->v[m->nv][1] = y;
    m->v[m->nv][2] = z;
    return m->nv++;
}

/* Append a face of k vertex indices (iv_shape_mesh's winding). */
static void mb_face(mesh_build *m, const int *f, int k)
{
    if (m->nidx + k > m->capidx) {
        int cap = m->capidx ? 2 * m->capidx : 1024;
        while (cap < m->nidx + k)
            cap *= 2;
        int *v = realloc(m->idx, (size_t)cap * sizeof *v);
        if (!v) {
            m->oom = 1;
            return;
        }
        m->idx = v;
        m->capidx = cap;
    }
    if (m->nf + 2 > m->capf) {
        int cap = m->capf ? 2 * m->capf : 256;
        int *v = realloc(m->start, (size_t)cap * sizeof *v);
        if (!v) {
            m->oom = 1;
            return;
        }
        m->start = v;
        m->capf = cap;
    }
    if (m->nf == 0) m->start[0] = 0;
    memcpy(m->idx + m->nidx, f, (size_t)k * sizeof *f);
    m->nidx += k;
    m->start[++m->nf] = m->nidx;
}

static void mb_free(mesh_build *m)
{
    free(m->v);
    free(m->idx);
    free(m->start);
}

typedef struct keyed_vertex {
    double p[3];
    int i;
} keyed_vertex;

static int cmp_keyed(const void *a, const void *b)
{
    const keyed_vertex *u = a, *v = b;
    for (int k = 0; k < 3; k++)
        if (u->p[k] != v->p[k]) return u->p[k] < v->p[k] ? -1 : 1;
    return 0;
}

/* Merge vertices at exactly the same position (a zero scale collapses a
 * layer), then drop repeated indices within each face and faces left with
 * fewer than 3: what OpenSCAD's PolySet does when it becomes a mesh. */
static void mb_weld(mesh_build *m)
{
    int n = m->nv;
    keyed_vertex *order = malloc((size_t)(n ? n : 1) * sizeof *order);
    int *to = malloc((size_t)(n ? n : 1) * sizeof *to);
    if (!order || !to) {
        free(order);
        free(to);
        m->oom = 1;
        return;
    }
    for (int i = 0; i < n; i++) {
        memcpy(order[i].p, m->v[i], sizeof order[i].p);
        order[i].i = i;
    }
    qsort(order, (size_t)n, sizeof *order, cmp_keyed);
    for (int i = 0; i < n; i++)
        to[order[i].i] =
            i > 0 && cmp_keyed(&order[i - 1], &order[i]) == 0 ? to[order[i - 1].i] : order[i].i;
    int k = 0, nf = 0;
    for (int f = 0; f < m->nf; f++) {
        int s = m->start[f], e = m->start[f + 1], k0 = k;
        for (int i = s; i < e; i++) {
            int x = to[m->idx[i]];
            if (k > k0 && m->idx[k - 1] == x) continue;
            m->idx[k++] = x;
        }
        while (k - k0 > 1 && m->idx[k - 1] == m->idx[k0])
            k--;
        if (k - k0 < 3) {
            k = k0;
            continue;
        }
        m->start[nf] = k0;
        m->start[++nf] = k;
    }
    m->nidx = k;
    m->nf = nf;
    free(order);
    free(to);
}

/* Even-odd test of (x, y) against path P[0 .. n). */
static int in_path(const double (*P)[2], int n, double x, double y)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((P[i][1] > y) != (P[j][1] > y) &&
            x < P[j][0] + (y - P[j][1]) * (P[i][0] - P[j][0]) / (P[i][1] - P[j][1]))
            in = !in;
    return in;
}

/* A flat cap face f of k vertices.  The mesh splits a polygon face into a
 * fan from its first vertex, long thin triangles all through one corner,
 * whose boxes a ray over a cap of many points meets by the thousand; a
 * strictly convex cap (a circle's), when it is the only path, goes in as
 * a zig-zag strip instead: triangles across the cap, side by side, the
 * same solid (they tile it without overlap). */
static void cap_face(mesh_build *m, const int *f, int k, int alone)
{
    int pos = 0, neg = 0;
    for (int i = 0; alone && k > 3 && i < k && !(pos && neg); i++) {
        const double *a = m->v[f[i]], *b = m->v[f[(i + 1) % k]], *c = m->v[f[(i + 2) % k]];
        double t = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
        pos |= t > 0;
        neg |= !(t > 0);
    }
    if (!alone || k <= 3 || (pos && neg) || !pos) {
        mb_face(m, f, k);
        return;
    }
    for (int lo = 0, hi = k - 1; hi - lo >= 2;) {
        mb_face(m, (int[3]){f[lo], f[lo + 1], f[hi]}, 3);
        if (hi - ++lo >= 2) mb_face(m, (int[3]){f[lo], f[hi - 1], f[hi]}, 3);
        hi--;
    }
}

/* The closed polyhedron OpenSCAD 2021.01 builds for region r
 * (extrudePolygon and add_slice): the outline points at each of the
 * slices + 1 layers turned by -twist·j/slices and scaled by 1 - (1 -
 * scale)·j/slices about the origin, every quad between two layers split
 * along its shorter diagonal (ties broken as OpenSCAD does: by the path's
 * sign and the twist's direction), the caps flat.  OpenSCAD walks outer
 * paths clockwise and holes counter-clockwise (then emits its faces
 * counter-clockwise seen from outside); the faces here are the same
 * triangles in iv_shape_mesh's opposite winding.  Returns 0, or -1. */
static int twisted_mesh(const twist_ctx *c, const iv_region *r, iv_shape *out)
{
    int n, np;
    const double(*P)[2] = iv_region_points(r, &n);
    const int *ps = iv_region_paths(r, &np);
    int S = c->slices;
    mesh_build m = {0};
    int *base = malloc((size_t)np * sizeof *base); /* first vertex of each path */
    signed char *outer = malloc((size_t)(np ? np : 1));
    if (!base || !outer) {
        free(base);
        free(outer);
        return -1;
    }
    /* outline order: outer paths (even nesting depth) clockwise */
    for (int p = 0; p < np; p++) {
        const double(*Q)[2] = P + ps[p];
        int k = ps[p + 1] - ps[p];
        double area = 0;
        for (int i = 0, j = k - 1; i < k; j = i++)
            area += Q[j][0] * Q[i][1] - Q[i][0] * Q[j][1];
        int depth = 0;
        for (int q = 0; q < np; q++)
            if (q != p && in_path(P + ps[q], ps[q + 1] - ps[q], Q[0][0], Q[0][1])) depth++;
        outer[p] = depth % 2 == 0;
        int reverse = outer[p] ? area > 0 : area < 0;
        base[p] = m.nv;
        for (int j = 0; j <= S; j++) {
            double rot = c->twist * j / S;
            double sx = 1 - (1 - c->scale[0]) * j / S, sy = 1 - (1 - c->scale[1]) * j / S;
            double z = c->h1 + (c->h2 - c->h1) * j / S;
            double cs = scad_cos_degrees(-rot), sn = scad_sin_degrees(-rot);
            for (int i = 0; i < k; i++) {
                const double *q = Q[reverse ? k - 1 - i : i];
                mb_vertex(&m, sx * (cs * q[0] - sn * q[1]), sy * (sn * q[0] + cs * q[1]), z);
            }
        }
    }
    if (m.oom) goto fail;
    int back_twist = c->twist <= 0;
    for (int p = 0; p < np; p++) {
        int k = ps[p + 1] - ps[p], b = base[p];
        int flip = !outer[p] ^ back_twist;
        for (int j = 0; j < S; j++) {
            double s2x = 1 - (1 - c->scale[0]) * (j + 1) / S;
            double s2y = 1 - (1 - c->scale[1]) * (j + 1) / S;
            int any_zero = s2x == 0 || s2y == 0, any_non_zero = s2x != 0 || s2y != 0;
            for (int i = 1; i <= k; i++) {
                int p1 = b + j * k + (i - 1), c1 = b + j * k + i % k;
                int p2 = p1 + k, c2 = c1 + k;
                const double *P1 = m.v[p1], *C1 = m.v[c1], *P2 = m.v[p2], *C2 = m.v[c2];
                int d = length_order(P1[0] - C2[0], P1[1] - C2[1], C1[0] - P2[0], C1[1] - P2[1]);
                int split_first = d == -1 || (d == 0 && !flip);
                int second = !any_zero || (any_non_zero && (P2[0] != C2[0] || P2[1] != C2[1]));
                /* OpenSCAD's triangles, each written reversed */
                if (split_first ^ any_zero) {
                    mb_face(&m, (int[3]){p1, c1, c2}, 3);
                    if (second) mb_face(&m, (int[3]){c2, p2, p1}, 3);
                } else {
                    mb_face(&m, (int[3]){p1, c1, p2}, 3);
                    if (second) mb_face(&m, (int[3]){p2, c1, c2}, 3);
                }
            }
        }
    }
    /* caps: the bottom counter-clockwise seen from above (clockwise seen
     * from outside, below), the top clockwise; no top at a zero scale */
    int top = c->scale[0] > 0 && c->scale[1] > 0;
    for (int p = 0; p < np; p++) {
        int k = ps[p + 1] - ps[p], b = base[p];
        int *f = malloc((size_t)k * sizeof *f);
        if (!f) {
            m.oom = 1;
            break;
        }
        for (int i = 0; i < k; i++)
            f[i] = b + (k - 1 - i);
        cap_face(&m, f, k, np == 1);
        if (top) {
            for (int i = 0; i < k; i++)
                f[i] = b + S * k + i;
            cap_face(&m, f, k, np == 1);
        }
        free(f);
    }
    if (m.oom) goto fail;
    mb_weld(&m);
    if (m.oom || m.nf == 0) goto fail;
    int rc = iv_shape_mesh(out, (const double(*)[3])m.v, m.nv, m.idx, m.start, m.nf);
    free(base);
    free(outer);
    mb_free(&m);
    return rc < 0 ? -1 : 0;
fail:
    free(base);
    free(outer);
    mb_free(&m);
    return -1;
}

static void twist_tree(twist_ctx *c, scad_geom *g)
{
    if (!g || c->ev->aborted) return;
    if (!g->is_leaf) {
        for (int i = 0; i < g->n; i++)
            twist_tree(c, g->kids[i]);
        return;
    }
    if (g->shape.kind != IV_SHAPE_PRISM) { /* a 3D child: OpenSCAD ignores it */
        make_empty(g);
        return;
    }
    iv_region *r = shadow_region(c->local_from_world, g, disc_fragments(g, c->f), 1);
    iv_shape s;
    int n = 0, rc = -1;
    if (r) iv_region_points(r, &n);
    /* each vertex of the mesh is a step of work: a 100,000-gon at 25,000
     * slices would be 2.5·10^9 */
    if (r && !scad_eval_steps(c->ev, (long)n * (c->slices + 1), c->loc, "linear_extrude")) {
        rc = twisted_mesh(c, r, &s);
        if (rc != 0)
            scad_diag_error(c->ev->d, c->loc,
                            "linear_extrude(): no mesh of %d points at %d slices (out of "
                            "memory); nothing is drawn",
                            n, c->slices);
    }
    if (r) iv_region_release(r);
    if (rc != 0 || scad_geom_keep(c->ev, &s) != 0) {
        make_empty(g);
        return;
    }
    g->shape = s;
    memcpy(g->xf, c->world_from_local, sizeof(csg_affine));
}

static scad_geom *m_linear_extrude(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                   const scad_argv *a, const scad_state *state)
{
    static const char *const known[] = {"height", "center", "convexity", "twist",  "slices",
                                        "scale",  "file",   "layer",     "origin", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double h = 100, x;
    /* OpenSCAD reads a first positional number as the height */
    if (num_of(scad_argv_get(a, "height", 0), &x)) h = x;
    if (!(h > 0) || !isfinite(h)) return NULL;
    scad_value c = scad_argv_get(a, "center", 5);
    int center = c.kind == SV_BOOL && c.u.b;
    twist_ctx t = {.ev = ev,
                   .loc = st->loc,
                   .world_from_local = state->xf,
                   .h1 = center ? -h / 2 : 0,
                   .h2 = center ? h / 2 : h,
                   .scale = {1, 1},
                   .f = scad_facets_lookup(ev, env, a, st->loc)};
    if (num_of(scad_argv_get(a, "twist", 6), &x) && isfinite(x)) t.twist = x;
    scad_value sv = scad_argv_get(a, "scale", 4);
    if (num_of(sv, &x)) {
        t.scale[0] = t.scale[1] = x;
    } else if (sv.kind == SV_VEC && sv.u.vec->n >= 2) {
        num_of(sv.u.vec->v[0], &t.scale[0]);
        num_of(sv.u.vec->v[1], &t.scale[1]);
    }
    for (int k = 0; k < 2; k++)
        if (!(t.scale[k] >= 0) || !isfinite(t.scale[k])) t.scale[k] = t.scale[k] > 0 ? 1 : 0;
    if (num_of(scad_argv_get(a, "slices", 7), &x) && isfinite(x) && x >= 1)
        t.slices = x > 100000 ? 100000 : (int)x;
    scad_geom *kids = scad_eval_children(ev, env, st, state, CSG_OP_UNION);
    if (!kids) return NULL;
    csg_affine inv;
    if (csg_affine_invert(state->xf, inv) != 0) return NULL;
    if (t.twist == 0 && t.scale[0] == 1 && t.scale[1] == 1) {
        /* straight: the exact prism (more slices change nothing) */
        linear_tree(kids, inv, state->xf, t.h1, t.h2);
        return kids;
    }
    t.local_from_world = inv;
    twist_scan(&t, kids);
    if (t.slices == 0) t.slices = default_slices(&t, h);
    twist_tree(&t, kids);
    return kids;
}

typedef struct revolve_ctx {
    scad_eval *ev;
    const double *local_from_world;
    const double *world_place; /* world_from_local ∘ the flips */
    double xmin, xmax;
    double angle;
    double sign; /* -1: the profile is on the negative side, mirrored */
    int disc_fragments_smooth;
    scad_facet_params f;
} revolve_ctx;

/* The region of a 2D leaf in the extrusion's frame (a new reference), with
 * x multiplied by sign; NULL when out of memory. */
static iv_region *leaf_region(const revolve_ctx *c, const scad_geom *g, double sign)
{
    int n = scad_facets_shown(c->ev, c->f, g->shape.u.prism.r)
                ? scad_fragments(g->shape.u.prism.r, c->f)
                : c->disc_fragments_smooth;
    return shadow_region(c->local_from_world, g, n, sign);
}

/* The x range of the subtree's 2D shape, bounded by its operations: a
 * difference by its first operand, an intersection by the overlap of its
 * operands' ranges (so a circle cut to x >= 0 counts as x >= 0).  Empty:
 * lo > hi. */
static void revolve_scan(revolve_ctx *c, const scad_geom *g, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    if (!g) return;
    if (!g->is_leaf) {
        int n = g->op == CSG_OP_DIFFERENCE && g->n > 0 ? 1 : g->n;
        for (int i = 0; i < n; i++) {
            double a, b;
            revolve_scan(c, g->kids[i], &a, &b);
            if (g->op == CSG_OP_INTERSECTION) {
                if (i == 0) {
                    *lo = a;
                    *hi = b;
                } else {
                    *lo = fmax(*lo, a);
                    *hi = fmin(*hi, b);
                }
            } else {
                *lo = fmin(*lo, a);
                *hi = fmax(*hi, b);
            }
        }
        return;
    }
    if (g->shape.kind != IV_SHAPE_PRISM) return;
    iv_region *r = leaf_region(c, g, 1);
    if (!r) return;
    int n;
    const double(*P)[2] = iv_region_points(r, &n);
    for (int i = 0; i < n; i++) {
        *lo = fmin(*lo, P[i][0]);
        *hi = fmax(*hi, P[i][0]);
    }
    iv_region_release(r);
}

static void revolve_tree(revolve_ctx *c, scad_geom *g)
{
    if (!g) return;
    if (!g->is_leaf) {
        for (int i = 0; i < g->n; i++)
            revolve_tree(c, g->kids[i]);
        return;
    }
    if (g->shape.kind != IV_SHAPE_PRISM) {
        make_empty(g);
        return;
    }
    iv_region *r = leaf_region(c, g, c->sign);
    if (!r) {
        make_empty(g);
        return;
    }
    iv_shape s;
    iv_shape_revolve(&s, r, c->angle);
    iv_region_release(r);
    if (scad_geom_keep(c->ev, &s) != 0) {
        make_empty(g);
        return;
    }
    g->shape = s;
    memcpy(g->xf, c->world_place, sizeof(csg_affine));
}

static scad_geom *m_rotate_extrude(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                   const scad_argv *a, const scad_state *state)
{
    static const char *const known[] = {"angle",  "convexity", "file", "layer",
                                        "origin", "scale",     NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double angle = 360;
    num_of(scad_argv_get(a, "angle", -1), &angle);
    if (!isfinite(angle) || angle == 0) return NULL;
    if (angle <= -360 || angle > 360) angle = 360;
    scad_geom *kids = scad_eval_children(ev, env, st, state, CSG_OP_UNION);
    if (!kids) return NULL;
    csg_affine inv;
    if (csg_affine_invert(state->xf, inv) != 0) return NULL;
    revolve_ctx c = {ev,       inv,       NULL,
                     INFINITY, -INFINITY, fabs(angle),
                     1,        256,       scad_facets_lookup(ev, env, a, st->loc)};
    revolve_scan(&c, kids, &c.xmin, &c.xmax);
    if (!(c.xmin <= c.xmax)) return NULL;
    if (c.xmin < 0 && c.xmax > 0) {
        scad_diag_warning(ev->d, st->loc,
                          "all points for rotate_extrude() must have the same X coordinate sign "
                          "(range is %.2f -> %.2f)",
                          c.xmin, c.xmax);
        return NULL;
    }
    /* A profile on the negative side is the mirrored profile turned by
     * 180°; a negative angle sweeps clockwise: the mirror image in y. */
    csg_affine place = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    if (c.xmax <= 0 && c.xmin < 0) {
        c.sign = -1;
        place[0] = place[5] = -1;
    }
    if (angle < 0) {
        place[1] = -place[1];
        place[5] = -place[5];
    }
    csg_affine world;
    csg_affine_mul(state->xf, place, world);
    c.world_place = world;
    revolve_tree(&c, kids);
    return kids;
}

/* ---- hull ------------------------------------------------------------------------ */

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

static void pts_add(pts *P, const double local_from_world[12], const double xf[12], double x,
                    double y, double z)
{
    if (P->n == P->cap) {
        if (P->cap > INT_MAX / 2 / (int)sizeof *P->p) return;
        int cap = P->cap ? 2 * P->cap : 256;
        double(*v)[3] = realloc(P->p, (size_t)cap * sizeof *v);
        if (!v) return;
        P->p = v;
        P->cap = cap;
    }
    double o[3] = {x, y, z}, w[3];
    csg_affine_point(xf, o, w);
    csg_affine_point(local_from_world, w, P->p[P->n++]);
}

/* The points whose hull is the leaf's solid as OpenSCAD tessellates it. */
static void hull_points(pts *P, const scad_geom *g, const double lfw[12], scad_facet_params f)
{
    if (!g || P->ev->aborted) return;
    if (!g->is_leaf) {
        /* The hull of a difference is at most the hull of its first
         * operand; of an intersection, at most the hull of all. */
        int n = g->op == CSG_OP_DIFFERENCE && g->n > 0 ? 1 : g->n;
        for (int i = 0; i < n; i++)
            hull_points(P, g->kids[i], lfw, f);
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
        int n = scad_fragments(r, f), rings = (n + 1) / 2;
        if (pts_steps(P, (long)n * rings)) return;
        for (int i = 0; i < rings; i++) {
            double phi = 180.0 * (i + 0.5) / rings;
            for (int j = 0; j < n; j++) {
                double c[2];
                circle_pt(r * scad_sin_degrees(phi), j, n, c);
                pts_add(P, lfw, g->xf, c[0], c[1], r * scad_cos_degrees(phi));
            }
        }
        return;
    }
    case IV_SHAPE_CONE: {
        P->any3d = 1;
        int n = scad_fragments(fmax(s->u.cone.r1, s->u.cone.r2), f);
        if (pts_steps(P, 2L * n)) return;
        for (int k = 0; k < 2; k++)
            for (int j = 0; j < n; j++) {
                double c[2];
                circle_pt(k ? s->u.cone.r2 : s->u.cone.r1, j, n, c);
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
    case IV_SHAPE_PRISM: {
        P->any2d = 1;
        if (!s->u.prism.g) {
            int n = scad_fragments(s->u.prism.r, f);
            if (pts_steps(P, n)) return;
            for (int j = 0; j < n; j++) {
                double c[2];
                circle_pt(s->u.prism.r, j, n, c);
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
    default:
        P->any3d = 1; /* a revolve: its bounds' corners, an over-estimate */
        double lo[3], hi[3];
        if (iv_shape_bounds(s, lo, hi) != 0) return;
        for (int i = 0; i < 8; i++)
            pts_add(P, lfw, g->xf, (i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1],
                    (i & 4) ? hi[2] : lo[2]);
        return;
    }
}

static int cmp_xy(const void *a, const void *b)
{
    const double *p = a, *q = b;
    if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
    return (p[1] > q[1]) - (p[1] < q[1]);
}

static double turn(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/* Andrew's monotone chain over the xy of P (sorted in place); the hull
 * counter-clockwise into H (room for n + 1), returns its size. */
static int hull2d(double (*P)[3], int n, double (*H)[2])
{
    qsort(P, (size_t)n, sizeof *P, cmp_xy);
    int k = 0;
    for (int i = 0; i < n; i++) {
        while (k >= 2 && turn(H[k - 2], H[k - 1], P[i]) <= 0)
            k--;
        H[k][0] = P[i][0];
        H[k++][1] = P[i][1];
    }
    for (int i = n - 2, lo = k + 1; i >= 0; i--) {
        while (k >= lo && turn(H[k - 2], H[k - 1], P[i]) <= 0)
            k--;
        H[k][0] = P[i][0];
        H[k++][1] = P[i][1];
    }
    return k > 1 ? k - 1 : k;
}

static scad_geom *hull_plain(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                             const scad_state *state)
{
    static const char *const none[] = {NULL};
    scad_check_arg_names(ev, a, st->loc, none);
    scad_geom *kids = scad_eval_children(ev, env, st, state, CSG_OP_UNION);
    if (!kids) return NULL;
    csg_affine inv;
    if (csg_affine_invert(state->xf, inv) != 0) return NULL;
    pts P = {.ev = ev, .loc = st->loc, .who = "hull"};
    hull_points(&P, kids, inv, scad_facets_lookup(ev, env, a, st->loc));
    scad_geom *g = NULL;
    if (ev->aborted) P.n = 0;
    if (P.any3d && P.n >= 4) {
        iv_shape s;
        int rc = scad_hull3d(&s, (const double(*)[3])P.p, P.n);
        if (rc == 0 && scad_geom_keep(ev, &s) == 0) g = leaf_at(ev, &s, state, NULL);
        if (rc == SCAD_HULL_TOO_MANY)
            scad_diag_error(ev->d, st->loc,
                            "hull() of %d points has more than 65536 faces, more than a "
                            "polytope holds; nothing is drawn",
                            P.n);
    } else if (!P.any3d && P.n >= 3) {
        double(*H)[2] = malloc((size_t)(P.n + 1) * sizeof *H);
        if (H) {
            int k = hull2d(P.p, P.n, H);
            int ps[2] = {0, k};
            if (k >= 3) g = region_leaf(ev, iv_region_new((const double(*)[2])H, ps, 1), state);
            free(H);
        }
    }
    free(P.p);
    return g;
}

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

static void place_tree(scad_geom *g, const csg_affine m)
{
    if (!g) return;
    if (!g->is_leaf) {
        for (int i = 0; i < g->n; i++)
            place_tree(g->kids[i], m);
        return;
    }
    csg_affine_mul(m, g->xf, g->xf);
}

/* resize(newsize, auto): OpenSCAD's CGAL_Nef_polyhedron::resize (and its 2D
 * twin) — scale about the origin so that the box of the children's
 * geometry gets the new size on each axis where it is non-zero; an axis
 * with newsize 0 keeps its size, or with auto takes the scale of the
 * largest newsize.  2D children have two axes (their slab keeps its
 * thickness). */
static scad_geom *m_resize(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                           const scad_state *state)
{
    static const char *const known[] = {"newsize", "auto", "convexity", NULL};
    scad_check_arg_names(ev, a, st->loc, known);
    double ns[3] = {0, 0, 0};
    int aut[3] = {0, 0, 0};
    scad_value nv = scad_argv_get(a, "newsize", 0), av = scad_argv_get(a, "auto", 1);
    if (nv.kind == SV_VEC)
        for (int i = 0; i < 3 && i < nv.u.vec->n; i++)
            if (!num_of(nv.u.vec->v[i], &ns[i]) || !isfinite(ns[i])) ns[i] = 0;
    if (av.kind == SV_BOOL) {
        aut[0] = aut[1] = aut[2] = av.u.b;
    } else if (av.kind == SV_VEC) {
        for (int i = 0; i < 3 && i < av.u.vec->n; i++)
            aut[i] = scad_value_truthy(av.u.vec->v[i]);
    }
    /* the children in the resize's own frame, placed at the end */
    scad_state local = *state;
    memcpy(local.xf, csg_affine_identity, sizeof local.xf);
    scad_geom *kids = scad_eval_children(ev, env, st, &local, CSG_OP_UNION);
    if (!kids) return NULL;
    double lo[3], hi[3];
    int any3d = 0;
    double scale[3] = {1, 1, 1};
    if (tree_box(ev, st->loc, kids, scad_facets_lookup(ev, env, a, st->loc), lo, hi, &any3d) == 0) {
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
    place_tree(kids, m);
    return kids;
}

/* ---- $rs_ materials ----------------------------------------------------------- */

/* The optical $-variables (material.c) on the leaf a primitive module made;
 * sphere and cylinder apply theirs as they build (optics_leaf), extrusions
 * keep their children's. */
static scad_geom *with_optics(scad_eval *ev, scad_env *env, const scad_argv *a, scad_geom *g)
{
    if (g && g->is_leaf) scad_material_apply(ev, env, a, &g->shape, g->xf, &g->mat);
    return g;
}

static scad_geom *m_square(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                           const scad_state *state)
{
    return with_optics(ev, env, a, square_plain(ev, env, st, a, state));
}

static scad_geom *m_circle(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                           const scad_state *state)
{
    return with_optics(ev, env, a, circle_plain(ev, env, st, a, state));
}

static scad_geom *m_polygon(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                            const scad_state *state)
{
    return with_optics(ev, env, a, polygon_plain(ev, env, st, a, state));
}

static scad_geom *m_polyhedron(scad_eval *ev, scad_env *env, const scad_stmt *st,
                               const scad_argv *a, const scad_state *state)
{
    return with_optics(ev, env, a, polyhedron_plain(ev, env, st, a, state));
}

static scad_geom *m_hull(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                         const scad_state *state)
{
    return with_optics(ev, env, a, hull_plain(ev, env, st, a, state));
}

/* ---- the table -------------------------------------------------------------------- */

static const struct {
    const char *name;
    scad_builtin_mod fn;
} table[] = {
    {"circle", m_circle},
    {"cylinder", m_cylinder},
    {"hull", m_hull},
    {"import", scad_module_import},
    {"linear_extrude", m_linear_extrude},
    {"minkowski", scad_module_minkowski},
    {"offset", scad_module_offset},
    {"polygon", m_polygon},
    {"polyhedron", m_polyhedron},
    {"projection", scad_module_projection},
    {"resize", m_resize},
    {"rotate_extrude", m_rotate_extrude},
    {"sphere", m_sphere},
    {"square", m_square},
    {"surface", scad_module_surface},
    {"text", scad_module_text},
};

scad_builtin_mod scad_geometry_module(const char *name)
{
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        if (strcmp(table[i].name, name) == 0) return table[i].fn;
    return NULL;
}
