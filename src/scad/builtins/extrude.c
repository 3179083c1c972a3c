/*
 * extrude.c — linear_extrude() and rotate_extrude().
 *
 * Both are point maps from 3D to the plane — p is in linear_extrude(h) of
 * S when its shadow is in S and 0 <= z <= h; p is in rotate_extrude of S
 * when (|p_xy|, p_z) is — and a preimage commutes with union, intersection
 * and difference.  So an extrusion keeps its children's CSG tree and only
 * replaces each 2D leaf by the extrusion of that leaf: the prism's z range
 * for a straight linear_extrude, a revolve of the leaf's region (with the
 * leaf's own 2D transform baked in) for rotate_extrude.  With a twist or a
 * scale the children's 2D union becomes OpenSCAD's own polyhedron
 * (src/geom/extrude.c), one leaf (see twisted).  3D children are
 * ignored, as OpenSCAD ignores them.  Reading a drawing from file= (the
 * deprecated form) is printed in .csg but builds nothing — nor do the
 * children then, which OpenSCAD ignores in favour of the file.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../geom/extrude.h"
#include "builtins.h"

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

/* OpenSCAD extrudes its children's 2D geometry, which has no colour: the
 * solid takes the extrusion's own (a color() or a '#' inside is lost). */
static void extrusion_colour(scad_geom *g, const csg_material *m)
{
    memcpy(g->mat.rgba, m->rgba, sizeof m->rgba);
    g->mat.has_color = m->has_color;
    g->mat.highlight = m->highlight;
}

static void linear_tree(scad_geom *g, const csg_affine local_from_world,
                        const csg_affine world_from_local, const csg_material *mat, double z0,
                        double z1)
{
    if (!g) return;
    if (!g->is_leaf) {
        for (int i = 0; i < g->n; i++)
            linear_tree(g->kids[i], local_from_world, world_from_local, mat, z0, z1);
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
    g->extruded = 1;
    extrusion_colour(g, mat);
}

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
        tmp = scad_circle_region(g->shape.u.prism.r, disc_n);
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

/* With a twist or a scale OpenSCAD extrudes the union of its children as
 * Clipper leaves it (outlines that share an edge merged, collinear and
 * duplicate points dropped) as one polygon set: each outline's vertices
 * climb the slices, so they shape the side faces (two squares side by side,
 * twisted by 180°, are a twisted rectangle, 2.5 % more than two twisted
 * squares; a polygon's points along a straight side are no vertices).  So
 * the children are flattened (scad_flatten_2d) and the union becomes one
 * leaf, OpenSCAD's polyhedron of it (src/geom/extrude.c), in the state's
 * colour: colours inside are lost, as in OpenSCAD.  NULL: nothing (or an
 * error reported). */
static scad_geom *twisted(scad_call *c, geom_extrusion e, const csg_affine local_from_world,
                          scad_facet_params f, const scad_geom *kids)
{
    scad_eval *ev = c->ev;
    scad_paths P;
    if (scad_flatten_2d(ev, kids, local_from_world, f, c->st->loc, "linear_extrude", &P) != 0)
        return NULL;
    int n = P.npaths ? P.start[P.npaths] : 0;
    iv_region *r = n ? iv_region_new((const double(*)[2])P.pts, P.start, P.npaths) : NULL;
    double max_r2 = 0, max_d2 = 0; /* what OpenSCAD sizes its default slices by */
    for (int i = 0; i < n; i++) {
        double x = P.pts[i][0], y = P.pts[i][1];
        double dx = x - x * e.scale[0], dy = y - y * e.scale[1];
        max_r2 = fmax(max_r2, x * x + y * y);
        max_d2 = fmax(max_d2, dx * dx + dy * dy);
    }
    scad_paths_free(&P);
    if (!r) return NULL;
    if (e.slices == 0) e.slices = geom_extrusion_slices(&e, max_r2, max_d2, f.fn, f.fa, f.fs);
    iv_shape s;
    int rc = -1;
    /* each vertex of the mesh is a step of work: a 100,000-gon at 25,000
     * slices would be 2.5·10^9 */
    if (!scad_eval_steps(ev, (long)n * (e.slices + 1), c->st->loc, "linear_extrude")) {
        rc = geom_extrusion_mesh(&e, r, &s);
        if (rc != 0)
            scad_eval_error(ev, c->st->loc,
                            "linear_extrude(): no mesh of %d points at %d slices (out of "
                            "memory); nothing is drawn",
                            n, e.slices);
    }
    iv_region_release(r);
    if (rc != 0 || scad_geom_keep(ev, &s) != 0) return NULL;
    return scad_optics_leaf(c, &s, NULL);
}

/* ---- linear_extrude ------------------------------------------------------------ */

enum {
    LX_FILE,
    LX_LAYER,
    LX_HEIGHT,
    LX_ORIGIN,
    LX_SCALE,
    LX_CENTER,
    LX_TWIST,
    LX_SLICES,
    LX_CONVEXITY
};

typedef struct linear_args {
    scad_file_arg file;
    double height, twist, scale[2], slices;
    int center, convexity;
    scad_facet_params f;
} linear_args;

static void linear_read(scad_call *c, void *out)
{
    linear_args *p = out;
    scad_file_arg_read(c, LX_FILE, LX_LAYER, LX_ORIGIN, -1, -1, "linear_extrude", &p->file);
    if (c->arg[LX_FILE].kind == SV_STR)
        scad_deprecated_once(c->ev, "Support for reading files in linear_extrude will be removed "
                                    "in future releases. Use a child import() instead.");
    p->height = 100;
    /* OpenSCAD takes a first unnamed number for the height when none is
     * named; bound by position, it went to file */
    if (!scad_arg_num(c->arg[LX_HEIGHT], &p->height) && c->st->args.n > 0 && !c->st->args.v[0].name)
        scad_arg_num(c->arg[LX_FILE], &p->height);
    if (!isfinite(p->height)) p->height = 100;
    if (p->height <= 0) p->height = 0;
    p->center = scad_arg_bool(c->arg[LX_CENTER], 0);
    p->convexity = scad_arg_int(c->arg[LX_CONVEXITY], 0);
    if (p->convexity <= 0) p->convexity = 1;
    double x;
    p->scale[0] = p->scale[1] = 1;
    /* getVec2 and getFiniteDouble: infinite or NaN scales are no scale */
    double s[2];
    if (scad_arg_vec(c->arg[LX_SCALE], 2, s) && isfinite(s[0]) && isfinite(s[1]))
        p->scale[0] = s[0], p->scale[1] = s[1];
    else if (scad_arg_num(c->arg[LX_SCALE], &x) && isfinite(x))
        p->scale[0] = p->scale[1] = x;
    for (int k = 0; k < 2; k++)
        if (p->scale[k] < 0) p->scale[k] = 0;
    p->twist = 0;
    if (scad_arg_num(c->arg[LX_TWIST], &x) && isfinite(x)) p->twist = x;
    p->slices = 0;
    scad_arg_num(c->arg[LX_SLICES], &p->slices);
    p->f = scad_facets_read(c);
}

static int linear_print(scad_call *c, const void *args, scad_buf *b)
{
    const linear_args *p = args;
    int nslices = isfinite(p->slices) ? (int)p->slices : 0;
    int children = 1;
    scad_buf_puts(b, "linear_extrude(");
    if (p->file.name) {
        long long mtime;
        scad_file_arg_print(c, &p->file, b, &mtime);
        scad_buf_printf(b, ", timestamp = %lld, ", mtime);
        children = 0;
    }
    scad_buf_puts(b, "height = ");
    scad_print_g(b, p->height);
    scad_buf_puts(b, ", center = ");
    scad_print_bool(b, p->center);
    scad_buf_printf(b, ", convexity = %d", p->convexity);
    if (p->twist != 0) {
        scad_buf_puts(b, ", twist = ");
        scad_print_g(b, p->twist);
    }
    if (nslices > 0) scad_buf_printf(b, ", slices = %d", nslices);
    scad_buf_puts(b, ", scale = [");
    scad_print_g(b, p->scale[0]);
    scad_buf_puts(b, ", ");
    scad_print_g(b, p->scale[1]);
    scad_buf_puts(b, "]");
    if (nslices <= 0)
        scad_print_facets(b, p->f, ", ", ")");
    else
        scad_buf_puts(b, ")");
    return children;
}

static scad_geom *linear_build(scad_call *c, const void *args)
{
    const linear_args *p = args;
    double h = p->height;
    /* with file= 2021.01 extrudes the drawing instead of the children */
    if (!(h > 0) || p->file.name) return NULL;
    geom_extrusion e = {.h1 = p->center ? -h / 2 : 0,
                        .h2 = p->center ? h / 2 : h,
                        .twist = p->twist,
                        .scale = {p->scale[0], p->scale[1]}};
    for (int k = 0; k < 2; k++) /* NaN: no top; infinite: none */
        if (!(e.scale[k] >= 0) || !isfinite(e.scale[k])) e.scale[k] = e.scale[k] > 0 ? 1 : 0;
    if (isfinite(p->slices) && p->slices >= 1)
        e.slices = p->slices > 100000 ? 100000 : (int)p->slices;
    scad_geom *kids = scad_call_children(c, NULL);
    if (!kids) return NULL;
    csg_affine inv;
    if (csg_affine_invert(c->state->xf, inv) != 0) return NULL;
    if (e.twist == 0 && e.scale[0] == 1 && e.scale[1] == 1) {
        /* straight: the exact prism (more slices change nothing) */
        linear_tree(kids, inv, c->state->xf, &c->state->mat, e.h1, e.h2);
        kids->whole = !kids->is_leaf;
        return kids;
    }
    return twisted(c, e, inv, p->f, kids);
}

static const char *const linear_extrude_params[] = {
    "file", "layer", "height", "origin", "scale", "center", "twist", "slices", "convexity", NULL};
static const scad_module_def linear_extrude = {
    "linear_extrude", linear_extrude_params, 8,           sizeof(linear_args),
    linear_read,      linear_print,          linear_build};

/* ---- rotate_extrude ------------------------------------------------------------- */

typedef struct revolve_ctx {
    scad_eval *ev;
    const double *local_from_world;
    const double *world_place; /* world_from_local ∘ the flips */
    const csg_material *mat;   /* the extrusion's (extrusion_colour) */
    double xmin, xmax;
    double angle;
    double sign; /* -1: the profile is on the negative side, mirrored */
    int disc_fragments_smooth;
    scad_facet_params f;
    int fragments; /* OpenSCAD's steps over the angle (solid.c tessellates by them) */
    int faceted;   /* build OpenSCAD's polyhedron instead of the exact revolve */
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
    s.u.revolve.fragments = c->fragments;
    iv_region_release(r);
    if (c->faceted) { /* OpenSCAD's polyhedron, as its preview draws it */
        scad_geom tmp = *g;
        tmp.shape = s;
        memcpy(tmp.xf, csg_affine_identity, sizeof tmp.xf);
        geom_polys faces = {0};
        iv_shape m;
        if (scad_leaf_polys(&tmp, csg_affine_identity, c->f, &faces) == 0 &&
            scad_polys_mesh(&faces, &m) == 0) {
            iv_shape_release(&s);
            s = m;
        }
        geom_polys_free(&faces);
    }
    if (scad_geom_keep(c->ev, &s) != 0) {
        make_empty(g);
        return;
    }
    g->shape = s;
    memcpy(g->xf, c->world_place, sizeof(csg_affine));
    extrusion_colour(g, c->mat);
}

enum { RX_FILE, RX_LAYER, RX_ORIGIN, RX_SCALE, RX_ANGLE, RX_CONVEXITY };

typedef struct rotate_args {
    scad_file_arg file;
    double scale, angle;
    int convexity;
    scad_facet_params f;
} rotate_args;

static void rotate_read(scad_call *c, void *out)
{
    rotate_args *p = out;
    scad_file_arg_read(c, RX_FILE, RX_LAYER, RX_ORIGIN, -1, -1, NULL, &p->file);
    scad_value f = c->arg[RX_FILE];
    if (f.kind != SV_UNDEF)
        scad_deprecated_once(c->ev, "Support for reading files in rotate_extrude will be removed "
                                    "in future releases. Use a child import() instead.");
    if (f.kind != SV_UNDEF && f.kind != SV_STR) {
        /* openscad 2021.01 takes any value as the file, as its text:
         * rotate_extrude(45) reads a file named "45" */
        scad_buf b = {0};
        scad_value_format(&b, f, 0);
        p->file.name = scad_arena_strndup(c->ev->arena, scad_buf_str(&b), strlen(scad_buf_str(&b)));
        scad_buf_free(&b);
    }
    p->scale = 1;
    scad_arg_num(c->arg[RX_SCALE], &p->scale);
    p->angle = 360;
    scad_arg_num(c->arg[RX_ANGLE], &p->angle);
    if (!isfinite(p->angle) || p->angle <= -360 || p->angle > 360) p->angle = 360;
    p->convexity = scad_arg_int(c->arg[RX_CONVEXITY], 0);
    if (p->convexity <= 0) p->convexity = 2;
    p->f = scad_facets_read(c);
}

static int rotate_print(scad_call *c, const void *args, scad_buf *b)
{
    const rotate_args *p = args;
    int children = 1;
    scad_buf_puts(b, "rotate_extrude(");
    if (p->file.name) {
        long long mtime;
        scad_file_arg_print(c, &p->file, b, &mtime);
        scad_buf_puts(b, ", scale = ");
        scad_print_g(b, p->scale);
        scad_buf_printf(b, ", timestamp = %lld, ", mtime);
        children = 0;
    }
    scad_buf_puts(b, "angle = ");
    scad_print_g(b, p->angle);
    scad_buf_printf(b, ", convexity = %d", p->convexity);
    scad_print_facets(b, p->f, ", ", ")");
    return children;
}

static scad_geom *rotate_build(scad_call *c, const void *args)
{
    const rotate_args *p = args;
    scad_eval *ev = c->ev;
    double angle = p->angle;
    /* with file= (rotate_extrude(45) names a file "45") 2021.01 revolves
     * the drawing instead of the children */
    if (angle == 0 || p->file.name) return NULL;
    scad_geom *kids = scad_call_children(c, NULL);
    if (!kids) return NULL;
    csg_affine inv;
    if (csg_affine_invert(c->state->xf, inv) != 0) return NULL;
    revolve_ctx r = {ev,          inv, NULL, &c->state->mat, INFINITY, -INFINITY,
                     fabs(angle), 1,   256,  p->f,           0,        0};
    revolve_scan(&r, kids, &r.xmin, &r.xmax);
    if (!(r.xmin <= r.xmax)) return NULL;
    if (r.xmin < 0 && r.xmax > 0) {
        scad_diag_warning(ev->d, c->st->loc,
                          "all points for rotate_extrude() must have the same X coordinate sign "
                          "(range is %.2f -> %.2f)",
                          r.xmin, r.xmax);
        return NULL;
    }
    /* 2021.01's GeometryEvaluator::rotatePolygon, truncating */
    double rmax = fmax(fabs(r.xmin), fabs(r.xmax));
    r.fragments = (int)fmax(scad_fragments(rmax, p->f) * fabs(angle) / 360, 1);
    r.faceted = scad_facets_shown(ev, p->f, rmax);
    /* A profile on the negative side is the mirrored profile turned by
     * 180°; a negative angle sweeps clockwise: the mirror image in y. */
    csg_affine place = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    if (r.xmax <= 0 && r.xmin < 0) {
        r.sign = -1;
        place[0] = place[5] = -1;
    }
    if (angle < 0) {
        place[1] = -place[1];
        place[5] = -place[5];
    }
    csg_affine world;
    csg_affine_mul(c->state->xf, place, world);
    r.world_place = world;
    revolve_tree(&r, kids);
    kids->whole = !kids->is_leaf;
    return kids;
}

static const char *const rotate_extrude_params[] = {"file",  "layer",     "origin", "scale",
                                                    "angle", "convexity", NULL};
static const scad_module_def rotate_extrude = {
    "rotate_extrude", rotate_extrude_params, 4,           sizeof(rotate_args),
    rotate_read,      rotate_print,          rotate_build};

const scad_module_def *const scad_extrude_modules[] = {&linear_extrude, &rotate_extrude, NULL};
