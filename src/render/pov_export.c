/*
 * pov_export.c — a committed scene as POV-Ray 3.7 SDL, so that POV-Ray
 * renders the same solids from the same camera (a user feature, and the
 * benchmark's way of handing POV-Ray our scenes).
 *
 * The scene's flat tree (csg_scene_node_get) maps one to one: a union is a
 * `union` (a `merge` when a transparent leaf lies below it, so overlapping
 * glass shows no inner faces, as in our renderer), intersection and
 * difference keep their names, and each leaf is its analytic POV primitive
 * placed by `matrix` (POV multiplies row vectors, so its rows are our
 * columns):
 *   sphere, box, cone/cylinder, halfspace → plane, convex polytope →
 *   intersection of planes (bounded_by its box), mesh → mesh2 with an
 *   inside_vector, prism → prism (POV sweeps along y: a swap matrix turns
 *   it onto z), disc prism → cylinder, revolve → lathe about y swapped onto
 *   z, cut to its angle by one or two planes.  A region of several paths
 *   becomes one spline whose paths are joined by a bridge walked there and
 *   back, which adds no crossing to POV's even-odd inside test.
 * Colours are `srgbt` with transmit = 1 − alpha under assumed_gamma 1.0; an
 * uncoloured leaf gets the scheme's face colour, or its back colour when it
 * is subtracted an odd number of times (POV shows a cut face in the
 * texture of the solid that cut it, as our renderer does).  The '#' and '%'
 * roots take the highlight and background-modifier colours.
 *
 * The camera is given by explicit direction/up/right vectors, which places
 * pixels exactly as render_camera_ray (and needs no handedness trick).
 * Lights are the preview's: two opposite parallel lights, shadowless, and
 * ambient 0.2 (shade.c), so a face gets 0.2 + |n·L| as in OpenSCAD — in
 * linear rather than sRGB values, so shading differs slightly in tone, not
 * in silhouette.
 */
#include "render.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Deeper CSG than this is refused rather than recursed into. */
#define MAX_DEPTH 10000
#define PI 3.14159265358979323846
/* Relative growth of subtracted leaves (see leaf). */
#define GROW 1e-5
#define GROW_DEG 1e-3

typedef struct out {
    char *buf;
    size_t len, cap;
    int failed;
} out;

static void put(out *w, const char *fmt, ...)
{
    if (w->failed) return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        size_t room = w->cap - w->len;
        int n = vsnprintf(w->buf ? w->buf + w->len : NULL, w->buf ? room : 0, fmt, ap);
        va_end(ap);
        if (n < 0) {
            w->failed = 1;
            return;
        }
        if (w->buf && (size_t)n < room) {
            w->len += (size_t)n;
            return;
        }
        size_t cap = w->cap ? w->cap : 1 << 16;
        while (cap < w->len + (size_t)n + 1)
            cap *= 2;
        char *b = realloc(w->buf, cap);
        if (!b) {
            w->failed = 1;
            return;
        }
        w->buf = b;
        w->cap = cap;
    }
}

/* Shortest round-tripping decimal, so a file reads back what we hold. */
static void num(out *w, double v)
{
    if (!isfinite(v)) v = v > 0 ? 1e30 : v < 0 ? -1e30 : 0;
    put(w, "%.17g", v);
}

static void vec(out *w, const double v[3])
{
    put(w, "<");
    num(w, v[0]);
    put(w, ",");
    num(w, v[1]);
    put(w, ",");
    num(w, v[2]);
    put(w, ">");
}

/* `matrix` for world_from_object m: POV's row i is our column i. */
static void matrix(out *w, const csg_affine m)
{
    put(w, "matrix <");
    for (int col = 0; col < 4; col++) {
        for (int row = 0; row < 3; row++) {
            num(w, m[4 * row + col]);
            if (col < 3 || row < 2) put(w, ",");
        }
    }
    put(w, ">\n");
}

/* POV's prism and lathe live in (x, z) sweeping along y; this swaps y and z
 * so they sweep along our z. */
static const char swap_yz[] = "matrix <1,0,0, 0,0,1, 0,1,0, 0,0,0>\n";

typedef struct ctx {
    const csg_scene *s;
    const render_options *opt;
    int root;
    out *w;
    int too_deep;
} ctx;

static int transparent_leaf(const ctx *c, int32_t prim)
{
    if (c->root == RAYSCAD_ROOT_HIGHLIGHT || c->root == RAYSCAD_ROOT_BACKGROUND) return 1;
    const csg_material *m = csg_scene_material(c->s, prim);
    return m->has_color && m->rgba[3] < 1;
}

static int subtree_transparent(const ctx *c, int32_t i)
{
    csg_scene_node_info n;
    csg_scene_node_get(c->s, i, &n);
    for (int32_t j = i; j < n.end; j++) {
        csg_scene_node_info k;
        csg_scene_node_get(c->s, j, &k);
        if (k.is_leaf && transparent_leaf(c, k.prim)) return 1;
    }
    return 0;
}

static void texture(const ctx *c, int32_t prim, int subtracted)
{
    const render_colors *col = &c->opt->colors;
    const csg_material *m = csg_scene_material(c->s, prim);
    float rgba[4];
    if (c->root == RAYSCAD_ROOT_HIGHLIGHT) {
        memcpy(rgba, col->highlight, sizeof rgba);
    } else if (c->root == RAYSCAD_ROOT_BACKGROUND) {
        memcpy(rgba, col->background_modifier, sizeof rgba);
    } else if (m->has_color) {
        memcpy(rgba, m->rgba, sizeof rgba);
    } else {
        memcpy(rgba, subtracted ? col->back : col->face, 3 * sizeof *rgba);
        rgba[3] = 1;
    }
    put(c->w, "texture { pigment { srgbt <%.6g,%.6g,%.6g,%.6g> } finish { RS_Finish } }\n", rgba[0],
        rgba[1], rgba[2], 1 - rgba[3]);
}

/* The points of region g as POV's prism wants them, "N, <a,b>, …": each
 * path closed by repeating its first point, which makes it a sub-polygon
 * of POV's even-odd inside test. */
static void region_spline(out *w, const iv_region *g)
{
    int npts, npaths;
    const double(*p)[2] = iv_region_points(g, &npts);
    const int *start = iv_region_paths(g, &npaths);
    put(w, "%d", npts + npaths);
    for (int k = 0; k < npaths; k++) {
        for (int i = start[k]; i < start[k + 1]; i++)
            put(w, ", <%.17g,%.17g>", p[i][0], p[i][1]);
        put(w, ", <%.17g,%.17g>", p[start[k]][0], p[start[k]][1]);
    }
    put(w, "\n");
}

/* Whether (x, y) lies inside path k of g (crossing count). */
static int path_contains(const iv_region *g, int k, double x, double y)
{
    int npts, npaths, in = 0;
    const double(*p)[2] = iv_region_points(g, &npts);
    const int *start = iv_region_paths(g, &npaths);
    for (int i = start[k], j = start[k + 1] - 1; i < start[k + 1]; j = i++) {
        if ((p[i][1] > y) != (p[j][1] > y) &&
            x < p[j][0] + (y - p[j][1]) * (p[i][0] - p[j][0]) / (p[i][1] - p[j][1]))
            in = !in;
    }
    return in;
}

/* How many other paths of g contain path k's first point. */
static int path_depth(const iv_region *g, int k)
{
    int npts, npaths, d = 0;
    const double(*p)[2] = iv_region_points(g, &npts);
    const int *start = iv_region_paths(g, &npaths);
    for (int j = 0; j < npaths; j++)
        if (j != k && path_contains(g, j, p[start[k]][0], p[start[k]][1])) d++;
    return d;
}

static void lathe(out *w, const iv_region *g, int k)
{
    int npts, npaths;
    const double(*p)[2] = iv_region_points(g, &npts);
    const int *start = iv_region_paths(g, &npaths);
    put(w, "lathe { linear_spline %d", start[k + 1] - start[k] + 1);
    for (int i = start[k]; i < start[k + 1]; i++)
        put(w, ", <%.17g,%.17g>", p[i][0], p[i][1]);
    put(w, ", <%.17g,%.17g>\n%s}\n", p[start[k]][0], p[start[k]][1], swap_yz);
}

/* The solid of revolution of region g (full turn, in our object space):
 * POV's lathe takes one closed path, so the even-odd region becomes, for
 * each path at even nesting depth, its lathe minus the lathes of the paths
 * directly inside it (paths of a region do not cross). */
static void revolve_solid(out *w, const iv_region *g)
{
    int npts, npaths;
    iv_region_points(g, &npts);
    iv_region_paths(g, &npaths);
    if (npaths == 1) {
        lathe(w, g, 0);
        return;
    }
    int *depth = malloc((size_t)npaths * sizeof *depth);
    if (!depth) {
        w->failed = 1;
        return;
    }
    for (int k = 0; k < npaths; k++)
        depth[k] = path_depth(g, k);
    put(w, "union {\n");
    for (int k = 0; k < npaths; k++) {
        if (depth[k] % 2) continue;
        int holes = 0, npt, np;
        const double(*p)[2] = iv_region_points(g, &npt);
        const int *start = iv_region_paths(g, &np);
        for (int j = 0; j < npaths; j++)
            holes +=
                depth[j] == depth[k] + 1 && path_contains(g, k, p[start[j]][0], p[start[j]][1]);
        if (holes) put(w, "difference {\n");
        lathe(w, g, k);
        for (int j = 0; holes && j < npaths; j++)
            if (depth[j] == depth[k] + 1 && path_contains(g, k, p[start[j]][0], p[start[j]][1]))
                lathe(w, g, j);
        if (holes) put(w, "}\n");
    }
    put(w, "}\n");
    free(depth);
}

static void leaf(const ctx *c, int32_t prim, int subtracted)
{
    out *w = c->w;
    const iv_shape *sh = csg_scene_prim_shape(c->s, prim);
    csg_affine m;
    csg_scene_prim_transform(c->s, prim, m);
    double lo[3], hi[3];
    if (subtracted && iv_shape_bounds(sh, lo, hi) == 0 && isfinite(lo[0] + lo[1] + lo[2]) &&
        isfinite(hi[0] + hi[1] + hi[2])) {
        /* POV-Ray picks either of two coincident surfaces (a hole exactly
         * as deep as the plate), where our merges prefer the cut; grow a
         * subtracted solid about its centre by GROW of its size so the cut
         * wins in POV too. */
        csg_affine g = {0};
        for (int k = 0; k < 3; k++) {
            double ext = hi[k] - lo[k], sc = ext > 0 ? 1 + 2 * GROW : 1;
            g[5 * k] = sc;
            g[4 * k + 3] = (1 - sc) * 0.5 * (lo[k] + hi[k]);
        }
        csg_affine_mul(m, g, m);
    }
    switch (sh->kind) {
    case IV_SHAPE_HALFSPACE: {
        const double *n = sh->u.halfspace.n;
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double u[3] = {n[0] / l, n[1] / l, n[2] / l};
        put(w, "plane { ");
        vec(w, u);
        put(w, ", ");
        num(w, sh->u.halfspace.d / l);
        put(w, "\n");
        break;
    }
    case IV_SHAPE_SPHERE:
        put(w, "sphere { <0,0,0>, ");
        num(w, sh->u.sphere.r);
        put(w, "\n");
        break;
    case IV_SHAPE_BOX:
        put(w, "box { ");
        vec(w, sh->u.box.lo);
        put(w, ", ");
        vec(w, sh->u.box.hi);
        put(w, "\n");
        break;
    case IV_SHAPE_CONE: {
        double r1 = sh->u.cone.r1, r2 = sh->u.cone.r2, h = sh->u.cone.h;
        if (r1 == r2)
            put(w, "cylinder { <0,0,0>, <0,0,%.17g>, %.17g\n", h, r1);
        else
            put(w, "cone { <0,0,0>, %.17g, <0,0,%.17g>, %.17g\n", r1, h, r2);
        break;
    }
    case IV_SHAPE_POLYTOPE: {
        int np, nv;
        const double(*pl)[4] = iv_polytope_planes(sh, &np);
        const double(*v)[3] = iv_polytope_vertices(sh, &nv);
        double plo[3] = {INFINITY, INFINITY, INFINITY}, phi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (int i = 0; i < nv; i++)
            for (int k = 0; k < 3; k++) {
                plo[k] = fmin(plo[k], v[i][k]);
                phi[k] = fmax(phi[k], v[i][k]);
            }
        /* POV cannot bound an intersection of planes by itself. */
        for (int k = 0; k < 3; k++) {
            double e = 1e-6 * (fabs(plo[k]) + fabs(phi[k])) + 1e-9;
            plo[k] -= e;
            phi[k] += e;
        }
        put(w, "intersection {\n");
        for (int i = 0; i < np; i++) {
            put(w, "plane { ");
            vec(w, pl[i]);
            put(w, ", ");
            num(w, pl[i][3]);
            put(w, " }\n");
        }
        put(w, "bounded_by { box { ");
        vec(w, plo);
        put(w, ", ");
        vec(w, phi);
        put(w, " } }\n");
        break;
    }
    case IV_SHAPE_MESH: {
        int nv, nt;
        const double(*v)[3] = iv_mesh_vertices(sh, &nv);
        const int(*t)[3] = iv_mesh_triangles(sh, &nt);
        put(w, "mesh2 {\nvertex_vectors { %d", nv);
        for (int i = 0; i < nv; i++) {
            put(w, ", ");
            vec(w, v[i]);
        }
        put(w, " }\nface_indices { %d", nt);
        for (int i = 0; i < nt; i++)
            put(w, ", <%d,%d,%d>", t[i][0], t[i][1], t[i][2]);
        put(w, " }\ninside_vector <0.2718,0.3141,0.9093>\n");
        break;
    }
    case IV_SHAPE_PRISM:
        if (!sh->u.prism.g) {
            put(w, "cylinder { <0,0,%.17g>, <0,0,%.17g>, %.17g\n", sh->u.prism.z0, sh->u.prism.z1,
                sh->u.prism.r);
        } else {
            put(w, "prism { linear_spline %.17g, %.17g, ", sh->u.prism.z0, sh->u.prism.z1);
            region_spline(w, sh->u.prism.g);
            put(w, "%s", swap_yz);
        }
        break;
    case IV_SHAPE_REVOLVE: {
        /* Keep azimuth [a0, a1].  A subtracted revolve's wedge is widened by
         * GROW_DEG on both sides: the growth above scales about a point on
         * the axis, which leaves its cut planes coincident with the ones it
         * cuts. */
        double a0 = 0, a1 = sh->u.revolve.angle;
        if (subtracted) {
            a0 -= GROW_DEG;
            a1 += GROW_DEG;
        }
        int partial = a1 - a0 < 360;
        /* A wrapper object carries the cut, the transform and the texture. */
        put(w, "%s {\n", !partial ? "union" : a1 - a0 <= 180 ? "intersection" : "difference");
        revolve_solid(w, sh->u.revolve.g);
        if (partial) {
            double s0 = sin(a0 * PI / 180), c0 = cos(a0 * PI / 180);
            double s1 = sin(a1 * PI / 180), c1 = cos(a1 * PI / 180);
            /* Up to 180°, the sides of the rays at a0 and a1 that face each
             * other; beyond, remove the wedge (a1, a0 + 360). */
            if (a1 - a0 <= 180)
                put(w, "plane { <%.17g,%.17g,0>, 0 }\nplane { <%.17g,%.17g,0>, 0 }\n", s0, -c0, -s1,
                    c1);
            else
                put(w,
                    "intersection { plane { <%.17g,%.17g,0>, 0 } plane { <%.17g,%.17g,0>, 0 } }\n",
                    -s0, c0, s1, -c1);
        }
        break;
    }
    }
    matrix(w, m);
    texture(c, prim, subtracted);
    put(w, "}\n");
}

static void node(ctx *c, int32_t i, int subtracted, int depth)
{
    if (depth > MAX_DEPTH) {
        c->too_deep = 1;
        return;
    }
    csg_scene_node_info n;
    csg_scene_node_get(c->s, i, &n);
    if (n.is_leaf) {
        leaf(c, n.prim, subtracted);
        return;
    }
    const char *name = n.op == CSG_OP_INTERSECTION ? "intersection"
                       : n.op == CSG_OP_DIFFERENCE ? "difference"
                       : subtree_transparent(c, i) ? "merge"
                                                   : "union";
    put(c->w, "%s {\n", name);
    int first = 1;
    for (int32_t k = i + 1; k < n.end;) {
        csg_scene_node_info kn;
        csg_scene_node_get(c->s, k, &kn);
        int sub = subtracted ^ (n.op == CSG_OP_DIFFERENCE && !first);
        node(c, k, sub, depth + 1);
        first = 0;
        k = kn.end;
    }
    put(c->w, "}\n");
}

int render_pov_export(const csg_scene *s, const render_camera *cam, const render_options *opt,
                      char **text, size_t *len, char *err, size_t errlen)
{
    *text = NULL;
    *len = 0;
    out w = {0};
    const render_colors *col = &opt->colors;
    double aspect = (double)opt->width / (double)opt->height;
    put(&w,
        "// rayscad export: POV-Ray 3.7 SDL.  Render at the same size:\n"
        "//   povray +W%d +H%d -D +Iscene.pov +Oscene.png\n"
        "#version 3.7;\n"
        "global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 256 }\n"
        "#declare RS_Finish = finish { ambient 0.2 diffuse 1 specular 0 }\n",
        opt->width, opt->height);
    put(&w, "background { srgb <%.6g,%.6g,%.6g> }\n", col->background[0], col->background[1],
        col->background[2]);
    /* Camera: direction = forward, up and right scaled so that the image
     * plane at distance 1 spans exactly render_camera_ray's. */
    if (cam->ortho) {
        double h = 2 * cam->ortho_half_height;
        put(&w, "camera { orthographic\n  location ");
        vec(&w, cam->eye);
        put(&w, "\n  direction ");
        vec(&w, cam->forward);
        double u[3], r[3];
        for (int k = 0; k < 3; k++) {
            u[k] = cam->up[k] * h;
            r[k] = cam->right[k] * h * aspect;
        }
        put(&w, "\n  up ");
        vec(&w, u);
        put(&w, "\n  right ");
        vec(&w, r);
        put(&w, "\n}\n");
    } else {
        double th = 2 * tan(cam->fovy_deg / 2 * PI / 180);
        double u[3], r[3];
        for (int k = 0; k < 3; k++) {
            u[k] = cam->up[k] * th;
            r[k] = cam->right[k] * th * aspect;
        }
        put(&w, "camera { perspective\n  location ");
        vec(&w, cam->eye);
        put(&w, "\n  direction ");
        vec(&w, cam->forward);
        put(&w, "\n  up ");
        vec(&w, u);
        put(&w, "\n  right ");
        vec(&w, r);
        put(&w, "\n}\n");
    }
    /* The preview's lights: L0 = (-right - forward + up)/√3 and its
     * opposite, parallel (shade.c). */
    double L[3];
    for (int k = 0; k < 3; k++)
        L[k] = (-cam->right[k] - cam->forward[k] + cam->up[k]) / sqrt(3.0);
    for (int sgn = 1; sgn >= -1; sgn -= 2) {
        double p[3] = {sgn * L[0] * 1e6, sgn * L[1] * 1e6, sgn * L[2] * 1e6};
        put(&w, "light_source { ");
        vec(&w, p);
        put(&w, " color rgb 1 parallel point_at <0,0,0> shadowless }\n");
    }
    ctx c = {.s = s, .opt = opt, .w = &w};
    for (int r = 0; r < csg_scene_root_count(s); r++) {
        int32_t i = csg_scene_root_node(s, r);
        if (i < 0) continue;
        c.root = r;
        put(&w, "// root %d%s\n", r,
            r == RAYSCAD_ROOT_HIGHLIGHT    ? " (# highlight)"
            : r == RAYSCAD_ROOT_BACKGROUND ? " (% background)"
                                           : "");
        node(&c, i, 0, 0);
    }
    if (c.too_deep || w.failed) {
        free(w.buf);
        if (err && errlen)
            snprintf(err, errlen, c.too_deep ? "CSG deeper than %d levels" : "out of memory",
                     MAX_DEPTH);
        return -1;
    }
    *text = w.buf;
    *len = w.len;
    return 0;
}
