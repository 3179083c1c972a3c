/*
 * primitives.c — cube, sphere, cylinder, square, circle, polygon and
 * polyhedron: their parameters, OpenSCAD 2021.01's reading of their
 * arguments, their .csg headers and their leaves.
 *
 * Facets (scad_options.facets): SMOOTH keeps every round primitive
 * analytic; OPENSCAD builds each sphere, cylinder and circle exactly as
 * OpenSCAD 2021.01 tessellates it (get_fragments_from_r, the sphere's rings
 * at polar angles 180·(i + ½)/rings) — a convex polytope, or a polygon;
 * AUTO, the default, is smooth unless the user's settings ask for at most
 * 16 fragments, where the facets are meant to be seen.
 *
 * 2D objects are prisms over a region (or a disc) between z = -½ and z = ½,
 * which is how OpenSCAD's preview draws them.  Degenerate sizes (a zero
 * edge, NaN, infinity) make nothing, silently, as OpenSCAD.
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../geom/hull3d.h"
#include "builtins.h"

/* ---- openscad's --check-parameter-ranges ----------------------------------------- */

/* With scad_options.range_check, openscad 2021.01's warning for a size
 * that makes nothing: "<head><a><mid><b><tail>", a and b values formatted
 * as echo() prints them (b may be undefined: then mid and tail are left
 * out, and a is followed by tail2). */
static void range_warning(scad_call *c, const char *head, scad_value a, const char *mid,
                          scad_value b, const char *tail)
{
    const scad_options *o = c->ev->d->opt;
    if (!o || !o->range_check) return;
    scad_buf fa = {0}, fb = {0};
    scad_value_format(&fa, a, 1);
    if (mid) scad_value_format(&fb, b, 1);
    scad_diag_warning(c->ev->d, c->st->loc, "%s%s%s%s%s", head, scad_buf_str(&fa), mid ? mid : "",
                      mid ? scad_buf_str(&fb) : "", tail);
    scad_buf_free(&fa);
    scad_buf_free(&fb);
}

/* ---- cube --------------------------------------------------------------------- */

enum { CUBE_SIZE, CUBE_CENTER };

typedef struct cube_args {
    double size[3];
    int center;
} cube_args;

static void cube_read(scad_call *c, void *out)
{
    cube_args *p = out;
    scad_value size = c->arg[CUBE_SIZE];
    double x;
    p->size[0] = p->size[1] = p->size[2] = 1;
    int ok = size.kind == SV_UNDEF;
    if (scad_arg_num(size, &x)) {
        p->size[0] = p->size[1] = p->size[2] = x;
        ok = 1;
    } else if (scad_arg_vec(size, 3, p->size)) {
        ok = 1;
    }
    if (!ok) {
        scad_buf b = {0};
        scad_value_format(&b, size, 1);
        scad_diag_warning(c->ev->d, c->st->loc,
                          "Unable to convert cube(size=%s, ...) parameter to a number or a vec3 "
                          "of numbers",
                          scad_buf_str(&b));
        scad_buf_free(&b);
    }
    if (!(p->size[0] > 0 && p->size[1] > 0 && p->size[2] > 0))
        range_warning(c, "cube(size=", size, NULL, size, ", ...)");
    p->center = scad_arg_bool(c->arg[CUBE_CENTER], 0);
}

static int cube_print(scad_call *c, const void *args, scad_buf *b)
{
    const cube_args *p = args;
    (void)c;
    scad_buf_puts(b, "cube(size = [");
    for (int i = 0; i < 3; i++) {
        if (i) scad_buf_puts(b, ", ");
        scad_print_g(b, p->size[i]);
    }
    scad_buf_puts(b, "], center = ");
    scad_print_bool(b, p->center);
    scad_buf_puts(b, ")");
    return 0;
}

static scad_geom *cube_build(scad_call *c, const void *args)
{
    const cube_args *p = args;
    for (int i = 0; i < 3; i++)
        if (!(p->size[i] > 0) || !isfinite(p->size[i])) return NULL;
    iv_shape sh;
    memset(&sh, 0, sizeof sh);
    sh.kind = IV_SHAPE_BOX;
    for (int i = 0; i < 3; i++) {
        sh.u.box.lo[i] = p->center ? -p->size[i] / 2 : 0;
        sh.u.box.hi[i] = p->center ? p->size[i] / 2 : p->size[i];
    }
    return scad_optics_leaf(c, &sh, NULL);
}

static const char *const cube_params[] = {"size", "center", NULL};
static const scad_module_def cube = {"cube",    cube_params, 2,         sizeof(cube_args),
                                     cube_read, cube_print,  cube_build};

/* ---- sphere, circle ------------------------------------------------------------- */

enum { ROUND_R, ROUND_D };

typedef struct round_args {
    double r;
    scad_facet_params f;
} round_args;

static void round_read(scad_call *c, void *out)
{
    round_args *p = out;
    p->r = 1;
    scad_arg_radius(c, ROUND_D, ROUND_R, "d", "r", &p->r);
    if (!(p->r > 0)) {
        const char *head = strcmp(c->def->name, "sphere") == 0 ? "sphere(r=" : "circle(r=";
        range_warning(c, head, scad_num(p->r), NULL, scad_num(0), ")");
    }
    p->f = scad_facets_read_clamped(c);
}

static int round_print(scad_call *c, const void *args, scad_buf *b)
{
    const round_args *p = args;
    scad_buf_puts(b, c->def->name);
    scad_buf_puts(b, "(");
    scad_print_facets(b, p->f, "", ", r = ");
    scad_print_g(b, p->r);
    scad_buf_puts(b, ")");
    return 0;
}

static scad_geom *hull_leaf(scad_call *c, const double (*P)[3], int n, const csg_affine local)
{
    scad_eval *ev = c->ev;
    iv_shape s;
    /* every point of a sphere or cylinder is a vertex, and a hull of V
     * vertices has 2V - 4 triangles: too many is known at once */
    int rc = 2L * n - 4 > 65536 ? GEOM_HULL_TOO_MANY : geom_hull3d(&s, P, n);
    if (rc == GEOM_HULL_TOO_MANY)
        scad_eval_error(ev, c->st->loc,
                        "%s() of %d points has more than 65536 faces, more than a polytope "
                        "holds; nothing is drawn",
                        c->def->name, n);
    if (rc != 0 || scad_geom_keep(ev, &s) != 0) return NULL;
    return scad_optics_leaf(c, &s, local);
}

static scad_geom *sphere_build(scad_call *c, const void *args)
{
    const round_args *p = args;
    double r = p->r;
    if (!(r > 0) || !isfinite(r)) return NULL;
    iv_shape sh;
    memset(&sh, 0, sizeof sh);
    if (!scad_facets_shown(c->ev, p->f, r)) {
        sh.kind = IV_SHAPE_SPHERE;
        sh.u.sphere.r = r;
        scad_geom *g = scad_optics_leaf(c, &sh, NULL);
        if (g && g->is_leaf) g->cap = scad_fragments(r, p->f); /* for hull() and minkowski() */
        return g;
    }
    int n = scad_fragments(r, p->f), rings = (n + 1) / 2;
    /* each point a step: a $fn of 10^9 would make 5·10^9 */
    if (scad_eval_steps(c->ev, (long)n * rings, c->st->loc, "sphere")) return NULL;
    if ((long)n * rings > INT_MAX / 32) { /* only under a raised step limit */
        scad_eval_error(c->ev, c->st->loc, "sphere() of %ld points is too big", (long)n * rings);
        return NULL;
    }
    double(*P)[3] = malloc((size_t)n * (size_t)rings * sizeof *P);
    if (!P) return NULL;
    for (int i = 0; i < rings; i++) {
        double rr, z;
        scad_sphere_ring(r, i, rings, &rr, &z);
        for (int j = 0; j < n; j++) {
            double q[2];
            scad_circle_point(rr, j, n, q);
            P[i * n + j][0] = q[0];
            P[i * n + j][1] = q[1];
            P[i * n + j][2] = z;
        }
    }
    scad_geom *g = hull_leaf(c, (const double(*)[3])P, n * rings, NULL);
    free(P);
    return g;
}

static scad_geom *circle_build(scad_call *c, const void *args)
{
    const round_args *p = args;
    double r = p->r;
    if (!(r > 0) || !isfinite(r)) return NULL;
    if (scad_facets_shown(c->ev, p->f, r)) {
        scad_geom *g =
            scad_region_leaf(c->ev, scad_circle_region(r, scad_fragments(r, p->f)), c->state);
        if (g) g->raw2d = 1;
        return scad_with_optics(c, g);
    }
    iv_shape s;
    memset(&s, 0, sizeof s);
    s.kind = IV_SHAPE_PRISM;
    s.u.prism.r = r;
    s.u.prism.z0 = -SCAD_SLAB;
    s.u.prism.z1 = SCAD_SLAB;
    scad_geom *g = scad_leaf_at(c->ev, &s, c->state, NULL);
    /* A leaf has no children, so its cap is free: a smooth disc keeps
     * OpenSCAD's fragment count there for a twisted or scaled extrusion,
     * which must build OpenSCAD's polygon (extrude.c: disc_fragments). */
    if (g) g->cap = scad_fragments(r, p->f);
    return scad_with_optics(c, g);
}

static const char *const sphere_params[] = {"r", "d", NULL};
static const scad_module_def sphere = {"sphere",   sphere_params, 1,           sizeof(round_args),
                                       round_read, round_print,   sphere_build};
static const char *const circle_params[] = {"r", "d", NULL};
static const scad_module_def circle = {"circle",   circle_params, 1,           sizeof(round_args),
                                       round_read, round_print,   circle_build};

/* ---- cylinder ------------------------------------------------------------------- */

enum { CYL_H, CYL_R1, CYL_R2, CYL_CENTER, CYL_R, CYL_D, CYL_D1, CYL_D2 };

typedef struct cylinder_args {
    double h, r1, r2;
    int center;
    scad_facet_params f;
} cylinder_args;

static void cylinder_read(scad_call *c, void *out)
{
    cylinder_args *p = out;
    p->h = p->r1 = p->r2 = 1;
    double r;
    scad_arg_num(c->arg[CYL_H], &p->h);
    int has_r = scad_arg_radius(c, CYL_D, CYL_R, "d", "r", &r);
    if (has_r) p->r1 = p->r2 = r;
    int has_r1 = scad_arg_radius(c, CYL_D1, CYL_R1, "d1", "r1", &p->r1);
    int has_r2 = scad_arg_radius(c, CYL_D2, CYL_R2, "d2", "r2", &p->r2);
    if (has_r && (has_r1 || has_r2))
        scad_diag_warning(c->ev->d, c->st->loc, "Cylinder parameters ambiguous");
    if (!(p->h > 0)) range_warning(c, "cylinder(h=", scad_num(p->h), NULL, scad_num(0), ", ...)");
    if (p->r1 < 0 || p->r2 < 0 || (p->r1 == 0 && p->r2 == 0))
        range_warning(c, "cylinder(r1=", scad_num(p->r1), ", r2=", scad_num(p->r2), ", ...)");
    p->center = scad_arg_bool(c->arg[CYL_CENTER], 0);
    p->f = scad_facets_read_clamped(c);
}

static int cylinder_print(scad_call *c, const void *args, scad_buf *b)
{
    const cylinder_args *p = args;
    (void)c;
    scad_buf_puts(b, "cylinder(");
    scad_print_facets(b, p->f, "", ", h = ");
    scad_print_g(b, p->h);
    scad_buf_puts(b, ", r1 = ");
    scad_print_g(b, p->r1);
    scad_buf_puts(b, ", r2 = ");
    scad_print_g(b, p->r2);
    scad_buf_puts(b, ", center = ");
    scad_print_bool(b, p->center);
    scad_buf_puts(b, ")");
    return 0;
}

static scad_geom *cylinder_build(scad_call *c, const void *args)
{
    const cylinder_args *p = args;
    double h = p->h, r1 = p->r1, r2 = p->r2;
    if (!(h > 0) || !isfinite(h) || !(r1 >= 0) || !(r2 >= 0) || !isfinite(r1) || !isfinite(r2) ||
        (r1 == 0 && r2 == 0))
        return NULL;
    csg_affine t = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, p->center ? -h / 2 : 0};
    iv_shape sh;
    memset(&sh, 0, sizeof sh);
    if (!scad_facets_shown(c->ev, p->f, r1 > r2 ? r1 : r2)) {
        sh.kind = IV_SHAPE_CONE;
        sh.u.cone.r1 = r1;
        sh.u.cone.r2 = r2;
        sh.u.cone.h = h;
        scad_geom *g = scad_optics_leaf(c, &sh, t);
        if (g && g->is_leaf) g->cap = scad_fragments(fmax(r1, r2), p->f);
        return g;
    }
    int n = scad_fragments(fmax(r1, r2), p->f), np = 0;
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
            double q[2];
            scad_circle_point(rr, j, n, q);
            P[np][0] = q[0];
            P[np][1] = q[1];
            P[np++][2] = k ? h : 0;
        }
    }
    scad_geom *g = hull_leaf(c, (const double(*)[3])P, np, t);
    free(P);
    return g;
}

static const char *const cylinder_params[] = {"h", "r1", "r2", "center", "r",
                                              "d", "d1", "d2", NULL};
static const scad_module_def cylinder = {
    "cylinder",     cylinder_params, 4, sizeof(cylinder_args), cylinder_read,
    cylinder_print, cylinder_build};

/* ---- square ----------------------------------------------------------------------- */

enum { SQUARE_SIZE, SQUARE_CENTER };

typedef struct square_args {
    double size[2];
    int center;
} square_args;

/* Value::getVec2: two numbers, or neither is taken. */
static int vec2(scad_value v, double out[2])
{
    double t[2];
    if (!scad_arg_vec(v, 2, t)) return 0;
    out[0] = t[0];
    out[1] = t[1];
    return 1;
}

static void square_read(scad_call *c, void *out)
{
    square_args *p = out;
    scad_value size = c->arg[SQUARE_SIZE];
    double x;
    p->size[0] = p->size[1] = 1;
    if (scad_arg_num(size, &x)) {
        p->size[0] = p->size[1] = x;
    } else if (!vec2(size, p->size) && size.kind != SV_UNDEF) {
        scad_buf b = {0};
        scad_value_format(&b, size, 1);
        scad_diag_warning(c->ev->d, c->st->loc,
                          "Unable to convert square(size=%s, ...) parameter to a number or a vec2 "
                          "of numbers",
                          scad_buf_str(&b));
        scad_buf_free(&b);
    }
    if (!(p->size[0] > 0 && p->size[1] > 0))
        range_warning(c, "square(size=", size, NULL, size, ", ...)");
    p->center = scad_arg_bool(c->arg[SQUARE_CENTER], 0);
}

static int square_print(scad_call *c, const void *args, scad_buf *b)
{
    const square_args *p = args;
    (void)c;
    scad_buf_puts(b, "square(size = [");
    scad_print_g(b, p->size[0]);
    scad_buf_puts(b, ", ");
    scad_print_g(b, p->size[1]);
    scad_buf_puts(b, "], center = ");
    scad_print_bool(b, p->center);
    scad_buf_puts(b, ")");
    return 0;
}

static scad_geom *square_build(scad_call *c, const void *args)
{
    const square_args *p = args;
    double sx = p->size[0], sy = p->size[1];
    if (!(sx > 0) || !(sy > 0) || !isfinite(sx) || !isfinite(sy)) return NULL;
    double x0 = p->center ? -sx / 2 : 0, y0 = p->center ? -sy / 2 : 0;
    double P[4][2] = {{x0, y0}, {x0 + sx, y0}, {x0 + sx, y0 + sy}, {x0, y0 + sy}};
    int ps[2] = {0, 4};
    scad_geom *g = scad_region_leaf(c->ev, iv_region_new((const double(*)[2])P, ps, 1), c->state);
    if (g) g->raw2d = 1;
    return scad_with_optics(c, g);
}

static const char *const square_params[] = {"size", "center", NULL};
static const scad_module_def square = {"square",    square_params, 2,           sizeof(square_args),
                                       square_read, square_print,  square_build};

/* ---- polygon, polyhedron ------------------------------------------------------------ */

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
            if (!scad_arg_num(p.u.vec->v[k], &P[i * n + k]) || !isfinite(P[i * n + k])) goto bad;
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
            if (!scad_arg_num(f->v[j], &x) || !(x >= 0) || !(x < npts)) return -1;
            (*idx)[k++] = (int)x;
        }
    }
    (*start)[m] = k;
    *count = m;
    return 0;
}

enum { POLY_POINTS, POLY_SECOND, POLY_CONVEXITY, POLY_TRIANGLES };

/* polygon(points, paths) and polyhedron(points, faces): the values as
 * given (borrowed from the call), printed as OpenSCAD prints them. */
typedef struct poly_args {
    scad_value points, second;
    int convexity;
} poly_args;

static void poly_read(scad_call *c, void *out)
{
    poly_args *p = out;
    p->points = c->arg[POLY_POINTS];
    p->second = c->arg[POLY_SECOND];
    if (c->def->params[POLY_TRIANGLES] && p->second.kind == SV_UNDEF) {
        p->second = c->arg[POLY_TRIANGLES];
        if (p->second.kind != SV_UNDEF)
            scad_diag_line(c->ev->d, RAYSCAD_MSG_WARNING,
                           "DEPRECATED: polyhedron(triangles=[]) will be removed in future "
                           "releases. Use polyhedron(faces=[]) instead.");
    }
    p->convexity = scad_arg_int(c->arg[POLY_CONVEXITY], 1);
    if (p->convexity < 1) p->convexity = 1;
}

static int poly_print(scad_call *c, const void *args, scad_buf *b)
{
    const poly_args *p = args;
    int hedron = c->def->params[POLY_TRIANGLES] != NULL;
    scad_buf_puts(b, hedron ? "polyhedron(points = " : "polygon(points = ");
    scad_value_format(b, p->points, 1);
    scad_buf_puts(b, hedron ? ", faces = " : ", paths = ");
    scad_value_format(b, p->second, 1);
    scad_buf_printf(b, ", convexity = %d)", p->convexity);
    return 0;
}

static scad_geom *polygon_build(scad_call *c, const void *args)
{
    const poly_args *p = args;
    scad_eval *ev = c->ev;
    int n = 0;
    double *P = points_of(p->points, 2, &n);
    if (!P) return NULL;
    iv_region *g = NULL;
    /* no paths, or an empty list of them: the points in order (2021.01) */
    if (p->second.kind == SV_UNDEF || (p->second.kind == SV_VEC && p->second.u.vec->n == 0)) {
        int ps[2] = {0, n};
        g = iv_region_new((const double(*)[2])P, ps, 1);
    } else {
        int *idx, *start, np;
        if (index_lists(p->second, n, &idx, &start, &np) == 0 && np > 0) {
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
            scad_diag_warning(ev->d, c->st->loc, "polygon(): paths must be lists of point indices");
        }
        free(idx);
        free(start);
    }
    free(P);
    return scad_with_optics(c, scad_region_leaf(ev, g, c->state));
}

static scad_geom *polyhedron_build(scad_call *c, const void *args)
{
    const poly_args *p = args;
    scad_eval *ev = c->ev;
    int n = 0;
    double *P = points_of(p->points, 3, &n);
    if (!P) return NULL;
    int *idx, *start, nf;
    scad_geom *g = NULL;
    if (index_lists(p->second, n, &idx, &start, &nf) != 0 || nf == 0) {
        scad_diag_warning(ev->d, c->st->loc, "polyhedron(): faces must be lists of point indices");
    } else {
        iv_shape s;
        int rc = (ev->for_mesh ? iv_shape_polyhedron_solid
                               : iv_shape_polyhedron)(&s, (const double(*)[3])P, n, idx, start, nf);
        if (rc == 3 && !ev->for_mesh)
            scad_diag_note(ev->d, c->st->loc,
                           "polyhedron() is not closed (it has holes); it is drawn as a surface "
                           "without inside");
        if (rc >= 0 && scad_geom_keep(ev, &s) == 0) g = scad_leaf_at(ev, &s, c->state, NULL);
    }
    free(idx);
    free(start);
    free(P);
    return scad_with_optics(c, g);
}

static const char *const polygon_params[] = {"points", "paths", "convexity", NULL};
static const scad_module_def polygon = {"polygon",  polygon_params, 3, sizeof(poly_args), poly_read,
                                        poly_print, polygon_build};
static const char *const polyhedron_params[] = {"points", "faces", "convexity", "triangles", NULL};
static const scad_module_def polyhedron = {
    "polyhedron", polyhedron_params, 3, sizeof(poly_args), poly_read, poly_print, polyhedron_build};

const scad_module_def *const scad_primitive_modules[] = {&cube,   &sphere,  &cylinder,   &square,
                                                         &circle, &polygon, &polyhedron, NULL};
