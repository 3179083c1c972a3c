/*
 * test_mesh.c — tri-dexel measurement and contouring, checked against closed
 * forms (box, sphere, cone volumes and areas; the cube minus sphere minus
 * three cylinders of the OpenSCAD manual, 2404.778358 by exact integration)
 * and against properties checked here independently of src/mesh: every
 * directed edge once and its reverse once, one fan per vertex, positive
 * signed volume close to the measured one, no zero-area triangle, every
 * vertex near the analytic surface (distance from the shape's formula).
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../src/csg/csg.h"
#include "../../src/io/io.h"
#include "../../src/mesh/dexels.h"
#include "../../src/mesh/mesh.h"

#define PI 3.14159265358979323846
#define CSG_VOLUME 2404.778358 /* cube(20,center) - sphere(11) - 3 cylinders r=6.5 */

/* ---- scene builders ----------------------------------------------------- */

static const csg_material plain = {.rgba = {1, 1, 1, 1}};

static csg_node *box_node(double x0, double y0, double z0, double x1, double y1, double z1)
{
    iv_shape s = {.kind = IV_SHAPE_BOX};
    double lo[3] = {x0, y0, z0}, hi[3] = {x1, y1, z1};
    memcpy(s.u.box.lo, lo, sizeof lo);
    memcpy(s.u.box.hi, hi, sizeof hi);
    return csg_node_shape(&s, csg_affine_identity, &plain);
}

static csg_node *sphere_node(double r, double cx, double cy, double cz)
{
    iv_shape s = {.kind = IV_SHAPE_SPHERE};
    s.u.sphere.r = r;
    csg_affine m = {1, 0, 0, cx, 0, 1, 0, cy, 0, 0, 1, cz};
    return csg_node_shape(&s, m, &plain);
}

/* A cone/cylinder of height h along `axis`, centred on the origin along it
 * when centred, else from 0 to h. */
static csg_node *cone_node(double r1, double r2, double h, int axis, int centred)
{
    iv_shape s = {.kind = IV_SHAPE_CONE};
    s.u.cone.r1 = r1;
    s.u.cone.r2 = r2;
    s.u.cone.h = h;
    double off = centred ? -h / 2 : 0;
    /* Object z goes to world `axis`; the map is a cyclic permutation. */
    csg_affine m;
    if (axis == 2) {
        csg_affine z = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, off};
        memcpy(m, z, sizeof m);
    } else if (axis == 0) {
        csg_affine x = {0, 0, 1, off, 1, 0, 0, 0, 0, 1, 0, 0};
        memcpy(m, x, sizeof m);
    } else {
        csg_affine y = {0, 1, 0, 0, 0, 0, 1, off, 1, 0, 0, 0};
        memcpy(m, y, sizeof m);
    }
    return csg_node_shape(&s, m, &plain);
}

static csg_scene *scene_of(csg_node *root)
{
    char err[256] = "";
    csg_node *roots[1] = {root};
    csg_scene *s = csg_scene_new(roots, 1, err, sizeof err);
    cr_assert(s, "csg_scene_new: %s", err);
    return s;
}

/* difference() { cube(20, center=true); sphere(11); three cylinders r=6.5 } */
static csg_scene *csg_example(void)
{
    csg_node *d = csg_node_op(CSG_OP_DIFFERENCE);
    cr_assert(csg_node_add(d, box_node(-10, -10, -10, 10, 10, 10)) == 0);
    cr_assert(csg_node_add(d, sphere_node(11, 0, 0, 0)) == 0);
    for (int a = 0; a < 3; a++)
        cr_assert(csg_node_add(d, cone_node(6.5, 6.5, 30, a, 1)) == 0);
    return scene_of(d);
}

/* Lower bound of the distance to the surface of csg_example (exact near the
 * box faces and on the sphere/cylinder surfaces away from edges). */
static double sd_box(const double p[3], const double lo[3], const double hi[3])
{
    double q[3], out = 0, in = -INFINITY;
    for (int c = 0; c < 3; c++) {
        double ctr = 0.5 * (lo[c] + hi[c]), half = 0.5 * (hi[c] - lo[c]);
        q[c] = fabs(p[c] - ctr) - half;
        out += q[c] > 0 ? q[c] * q[c] : 0;
        in = fmax(in, q[c]);
    }
    return sqrt(out) + fmin(in, 0);
}

static double sd_csg_example(const double p[3])
{
    double lo[3] = {-10, -10, -10}, hi[3] = {10, 10, 10};
    double d = sd_box(p, lo, hi);
    d = fmax(d, 11 - sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    d = fmax(d, 6.5 - hypot(p[1], p[2]));
    d = fmax(d, 6.5 - hypot(p[0], p[2]));
    d = fmax(d, 6.5 - hypot(p[0], p[1]));
    return d;
}

/* The contour's options (a box alone would be written as its own faces:
 * mesh_own_faces tests those). */
static mesh_options opts_h(double h)
{
    mesh_options o;
    mesh_options_default(&o);
    o.h = h;
    o.threads = 2;
    o.contour_all = 1;
    return o;
}

static mesh_measure measure(const csg_scene *s, double h)
{
    mesh_options o = opts_h(h);
    mesh_measure m;
    char err[256] = "";
    cr_assert(mesh_measure_scene(s, &o, &m, err, sizeof err) == 0, "%s", err);
    return m;
}

/* ---- independent mesh checks -------------------------------------------- */

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static int has_key(const uint64_t *k, size_t n, uint64_t key)
{
    return bsearch(&key, k, n, sizeof *k, cmp_u64) != NULL;
}

static const float *sort_pts;

static int cmp_point(const void *a, const void *b)
{
    const float *p = sort_pts + 3 * (size_t) * (const int *)a,
                *q = sort_pts + 3 * (size_t) * (const int *)b;
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

/* 1 when two vertices of m lie at the same point: an STL has no vertex
 * indices, every reader welds by position, and two such vertices become
 * one with two fans. */
static int shared_position(const mesh *m)
{
    int nv = mesh_vertex_count(m);
    int *ix = malloc((size_t)(nv ? nv : 1) * sizeof *ix);
    cr_assert(ix);
    for (int i = 0; i < nv; i++)
        ix[i] = i;
    sort_pts = mesh_vertices(m);
    qsort(ix, (size_t)nv, sizeof *ix, cmp_point);
    int dup = 0;
    for (int i = 1; i < nv && !dup; i++)
        dup = cmp_point(&ix[i - 1], &ix[i]) == 0;
    free(ix);
    return dup;
}

/* Closed, 2-manifold, consistently oriented: each directed edge occurs once
 * and its reverse once; around every vertex the triangles form one cycle;
 * every vertex is used.  Returns a message, or NULL. */
static const char *check_manifold(const mesh *m)
{
    int nt = mesh_triangle_count(m), nv = mesh_vertex_count(m);
    const int32_t *t = mesh_triangles(m);
    size_t ne = 3 * (size_t)nt;
    uint64_t *k = malloc((ne ? ne : 1) * sizeof *k);
    cr_assert(k);
    for (size_t q = 0; q < ne; q++) {
        uint32_t a = (uint32_t)t[q], b = (uint32_t)t[q % 3 == 2 ? q - 2 : q + 1];
        if (a == b) {
            free(k);
            return "a triangle repeats a vertex";
        }
        k[q] = (uint64_t)a << 32 | b;
    }
    qsort(k, ne, sizeof *k, cmp_u64);
    const char *msg = NULL;
    for (size_t q = 0; q < ne && !msg; q++) {
        if (q + 1 < ne && k[q] == k[q + 1])
            msg = "a directed edge occurs twice (non-manifold or misoriented)";
        else if (!has_key(k, ne, (k[q] & 0xffffffffu) << 32 | k[q] >> 32))
            msg = "an edge has no opposite (hole)";
    }
    /* One fan per vertex: link a -> (b -> c) for each triangle (a, b, c);
     * keyed (a, b), sorted, the links around a must form a single cycle. */
    if (!msg) {
        typedef struct link {
            uint64_t key; /* a << 32 | b */
            uint32_t c;
        } link;
        link *l = malloc((ne ? ne : 1) * sizeof *l);
        cr_assert(l);
        for (size_t q = 0; q < (size_t)nt; q++)
            for (int r = 0; r < 3; r++) {
                uint32_t a = (uint32_t)t[3 * q + r], b = (uint32_t)t[3 * q + (r + 1) % 3],
                         c = (uint32_t)t[3 * q + (r + 2) % 3];
                l[3 * q + r] = (link){(uint64_t)a << 32 | b, c};
            }
        qsort(l, ne, sizeof *l, cmp_u64); /* key is the first member */
        char *used = calloc((size_t)nv + 1, 1);
        cr_assert(used);
        size_t q = 0;
        while (q < ne && !msg) {
            uint32_t a = (uint32_t)(l[q].key >> 32);
            size_t end = q;
            while (end < ne && (uint32_t)(l[end].key >> 32) == a)
                end++;
            used[a] = 1;
            /* Walk from the first link; count steps back to the start. */
            size_t steps = 0, cur = q;
            do {
                uint64_t want = (uint64_t)a << 32 | l[cur].c;
                link key = {want, 0};
                link *nx = bsearch(&key, l + q, end - q, sizeof *l, cmp_u64);
                if (!nx) {
                    msg = "a vertex fan is open";
                    break;
                }
                cur = (size_t)(nx - l);
                steps++;
            } while (cur != q && steps <= end - q);
            if (!msg && steps != end - q) msg = "a vertex has more than one fan (pinched)";
            q = end;
        }
        for (int v = 0; v < nv && !msg; v++)
            if (!used[v]) msg = "an unused vertex";
        free(used);
        free(l);
    }
    free(k);
    return msg;
}

/* The area of triangle q of m. */
static double tri_area(const mesh *m, int q)
{
    const float *v = mesh_vertices(m);
    const int32_t *t = mesh_triangles(m);
    const float *a = v + 3 * t[3 * q], *b = v + 3 * t[3 * q + 1], *c = v + 3 * t[3 * q + 2];
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                   e1[0] * e2[1] - e1[1] * e2[0]};
    return 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/* Smallest triangle area. */
static double min_area(const mesh *m)
{
    double best = INFINITY;
    for (int q = 0; q < mesh_triangle_count(m); q++)
        best = fmin(best, tri_area(m, q));
    return best;
}

/* The surface's area. */
static double area_of(const mesh *m)
{
    double s = 0;
    for (int q = 0; q < mesh_triangle_count(m); q++)
        s += tri_area(m, q);
    return s;
}

/* Signed volume from the raw arrays, independent of mesh_signed_volume. */
static double volume_of(const mesh *m)
{
    const float *v = mesh_vertices(m);
    const int32_t *t = mesh_triangles(m);
    double s = 0;
    for (int q = 0; q < mesh_triangle_count(m); q++) {
        const float *a = v + 3 * t[3 * q], *b = v + 3 * t[3 * q + 1], *c = v + 3 * t[3 * q + 2];
        s += (a[0] * ((double)b[1] * c[2] - (double)b[2] * c[1]) -
              a[1] * ((double)b[0] * c[2] - (double)b[2] * c[0]) +
              a[2] * ((double)b[0] * c[1] - (double)b[1] * c[0])) /
             6;
    }
    return s;
}

static double max_dist(const mesh *m, double (*sd)(const double p[3], const void *ctx),
                       const void *ctx)
{
    const float *v = mesh_vertices(m);
    double worst = 0;
    for (int q = 0; q < mesh_vertex_count(m); q++) {
        double p[3] = {v[3 * q], v[3 * q + 1], v[3 * q + 2]};
        worst = fmax(worst, fabs(sd(p, ctx)));
    }
    return worst;
}

static double sd_sphere_ctx(const double p[3], const void *ctx)
{
    const double *c = ctx; /* cx, cy, cz, r */
    return sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) +
                (p[2] - c[2]) * (p[2] - c[2])) -
           c[3];
}

static double sd_box_ctx(const double p[3], const void *ctx)
{
    const double *b = ctx;
    return sd_box(p, b, b + 3);
}

static double sd_csg_ctx(const double p[3], const void *ctx)
{
    (void)ctx;
    return sd_csg_example(p);
}

static mesh *contour(const csg_scene *s, double h, mesh_measure *mm)
{
    mesh_options o = opts_h(h);
    mesh *m = NULL;
    char err[256] = "";
    cr_assert(mesh_from_scene(s, &o, &m, mm, err, sizeof err) == 0, "%s", err);
    return m;
}

/* The common checks; returns the mesh for more. */
static void check_mesh(const mesh *m, const mesh_measure *mm, double h, double vol_rel_tol,
                       const char *what)
{
    cr_assert_gt(mesh_triangle_count(m), 0, "%s: empty mesh", what);
    const char *msg = check_manifold(m);
    cr_assert_null(msg, "%s (h=%g): %s", what, h, msg);
    double a = min_area(m);
    cr_assert_gt(a, 1e-7 * h * h, "%s (h=%g): smallest triangle area %g", what, h, a);
    double sv = volume_of(m);
    cr_assert_gt(sv, 0, "%s: signed volume %g is not positive (inward?)", what, sv);
    cr_assert_lt(fabs(sv - mm->volume), vol_rel_tol * mm->volume,
                 "%s (h=%g): mesh volume %.6f vs measured %.6f", what, h, sv, mm->volume);
    cr_assert_lt(fabs(mesh_signed_volume(m) - sv), 1e-9 * fabs(sv) + 1e-9);
}

/* ---- measurement -------------------------------------------------------- */

Test(mesh_measure, box_exact_when_sides_are_multiples_of_h)
{
    csg_scene *s = scene_of(box_node(-3, -2, 1, 5, 2, 3)); /* 8 × 4 × 2 */
    mesh_measure m = measure(s, 8.0 / 128);
    cr_assert_float_eq(m.volume, 64.0, 1e-9, "volume %.12f", m.volume);
    /* csg pads the bounds by 1e-9 relative, which shifts the grid by that
     * much: not enough to change which rays hit, but the centroid moves. */
    cr_assert_float_eq(m.centroid[0], 1.0, 1e-7);
    cr_assert_float_eq(m.centroid[1], 0.0, 1e-7);
    cr_assert_float_eq(m.centroid[2], 2.0, 1e-7);
    double lo[3] = {-3, -2, 1}, hi[3] = {5, 2, 3};
    for (int c = 0; c < 3; c++) {
        cr_assert_float_eq(m.lo[c], lo[c], 1e-9, "lo[%d] %.12f", c, m.lo[c]);
        cr_assert_float_eq(m.hi[c], hi[c], 1e-9, "hi[%d] %.12f", c, m.hi[c]);
    }
    cr_assert_float_eq(m.area, 2 * (8 * 4 + 8 * 2 + 4 * 2), 1e-9, "area %.12f", m.area);
    /* The default h (8/128) is the same grid. */
    mesh_options o;
    mesh_options_default(&o);
    mesh_measure d;
    char err[256];
    cr_assert(mesh_measure_scene(s, &o, &d, err, sizeof err) == 0);
    cr_assert_float_eq(d.volume, 64.0, 1e-9);
    csg_scene_free(s);
}

Test(mesh_measure, box_off_grid_converges)
{
    csg_scene *s = scene_of(box_node(-3.1, -2.05, 1, 4.9, 2.3, 3.7));
    double v = 8 * 4.35 * 2.7, prev = INFINITY;
    for (double h = 0.2; h > 0.04; h /= 2) {
        mesh_measure m = measure(s, h);
        double e = fabs(m.volume - v);
        /* Each family miscounts at most a row of rays per face: O(h·area). */
        cr_assert_lt(e, h * 2 * (8 * 4.35 + 8 * 2.7 + 4.35 * 2.7), "h=%g error %g", h, e);
        cr_assert_lt(e, prev * 0.75 + 1e-12, "h=%g error %g not shrinking (was %g)", h, e, prev);
        prev = e;
    }
    csg_scene_free(s);
}

Test(mesh_measure, sphere_converges)
{
    double r = 5, c[3] = {1.5, -2, 3.25};
    csg_scene *s = scene_of(sphere_node(r, c[0], c[1], c[2]));
    double v = 4.0 / 3 * PI * r * r * r, area = 4 * PI * r * r;
    for (int cells = 16; cells <= 128; cells *= 2) {
        double h = 2 * r / cells;
        mesh_measure m = measure(s, h);
        double ev = fabs(m.volume - v) / v, ea = fabs(m.area - area) / area;
        cr_log_info("sphere h=%g: volume rel error %.2e, area rel error %.2e", h, ev, ea);
        /* Midpoint rule with square-root silhouettes: O(h^1.5); a generous
         * constant, but the bound shrinks ~2.8x per halving. */
        cr_assert_lt(ev, 2 * pow(h / r, 1.5), "h=%g volume %.6f vs %.6f", h, m.volume, v);
        cr_assert_lt(ea, 4 * pow(h / r, 1.5), "h=%g area %.6f vs %.6f", h, m.area, area);
        for (int k = 0; k < 3; k++) {
            cr_assert_lt(fabs(m.centroid[k] - c[k]), 2 * h * pow(h / r, 1.5), "centroid[%d]", k);
            cr_assert_leq(m.lo[k], c[k] - r + h * h / r + 1e-12);
            cr_assert_geq(m.lo[k], c[k] - r - 1e-12);
            cr_assert_geq(m.hi[k], c[k] + r - h * h / r - 1e-12);
            cr_assert_leq(m.hi[k], c[k] + r + 1e-12);
        }
    }
    csg_scene_free(s);
}

Test(mesh_measure, cone_frustum_volume)
{
    double r1 = 4, r2 = 1.5, hh = 6;
    csg_scene *s = scene_of(cone_node(r1, r2, hh, 2, 0));
    double v = PI * hh / 3 * (r1 * r1 + r1 * r2 + r2 * r2);
    mesh_measure m = measure(s, 8.0 / 128);
    cr_assert_lt(fabs(m.volume - v) / v, 2e-3, "volume %.6f vs %.6f", m.volume, v);
    /* Centroid height of a frustum. */
    double zc = hh * (r1 * r1 + 2 * r1 * r2 + 3 * r2 * r2) / (4 * (r1 * r1 + r1 * r2 + r2 * r2));
    cr_assert_lt(fabs(m.centroid[2] - zc), 5e-3, "zc %.6f vs %.6f", m.centroid[2], zc);
    csg_scene_free(s);
}

Test(mesh_measure, csg_example_converges)
{
    csg_scene *s = csg_example();
    double prev = INFINITY;
    for (int cells = 64; cells <= 256; cells *= 2) {
        double h = 20.0 / cells;
        mesh_measure m = measure(s, h);
        double e = fabs(m.volume - CSG_VOLUME) / CSG_VOLUME;
        cr_log_info("csg example h=%g: volume %.6f, rel error %.2e", h, m.volume, e);
        cr_assert_lt(e, 0.5 * pow(h / 10, 1.5), "h=%g volume %.6f", h, m.volume);
        cr_assert_lt(e, prev, "error not shrinking at h=%g", h);
        prev = e;
        for (int k = 0; k < 3; k++)
            cr_assert_lt(fabs(m.centroid[k]), 1e-3, "centroid[%d] %g", k, m.centroid[k]);
    }
    csg_scene_free(s);
}

Test(mesh_measure, empty_and_unbounded)
{
    csg_scene *s = scene_of(NULL);
    mesh_measure m = measure(s, 0);
    cr_assert_eq(m.volume, 0);
    mesh *me = contour(s, 0, &m);
    cr_assert_eq(mesh_triangle_count(me), 0);
    mesh_free(me);
    csg_scene_free(s);

    iv_shape hs = {.kind = IV_SHAPE_HALFSPACE};
    hs.u.halfspace.n[2] = 1;
    hs.u.halfspace.d = 0;
    s = scene_of(csg_node_shape(&hs, csg_affine_identity, &plain));
    mesh_options o = opts_h(0);
    char err[256] = "";
    cr_assert_eq(mesh_measure_scene(s, &o, &m, err, sizeof err), -1);
    cr_assert(strstr(err, "unbounded"), "message: %s", err);
    csg_scene_free(s);
}

/* ---- meshes ------------------------------------------------------------- */

Test(mesh_contour, box_is_exact)
{
    double b[6] = {-3.1, -2.05, 1, 4.9, 2.3, 3.7};
    csg_scene *s = scene_of(box_node(b[0], b[1], b[2], b[3], b[4], b[5]));
    double dim[3] = {8, 4.35, 2.7};
    double v = dim[0] * dim[1] * dim[2], area = 2 * (8 * 4.35 + 8 * 2.7 + 4.35 * 2.7);
    double hs[4] = {0.3, 0.15, 0.075, 0.21};
    for (int q = 0; q < 4; q++) {
        double h = hs[q];
        /* The grid puts the lower faces midway between nodes; an upper face
         * at a half-integer number of cells lies on a node plane, and its
         * vertices keep h/256 off it (no vertex may sit on a node). */
        int on_node = 0;
        for (int c = 0; c < 3; c++) {
            double f = dim[c] / h - 0.5;
            on_node |= fabs(f - round(f)) < 1e-6;
        }
        double tol = on_node ? h / 256 * 1.01 + 1e-5 : 1e-5;
        mesh_measure mm;
        mesh *m = contour(s, h, &mm);
        check_mesh(m, &mm, h, 0.05, "box");
        double d = max_dist(m, sd_box_ctx, b);
        cr_log_info("box h=%g (face on node plane: %d): %d triangles, volume error %.2e, max "
                    "vertex distance %.2e",
                    h, on_node, mesh_triangle_count(m), volume_of(m) - v, d);
        /* Sharp corners and edges: the mesh is the box up to float rounding
         * (and the h/256 offset of a face on a node plane). */
        cr_assert_lt(d, tol, "h=%g: a vertex is %g off the box", h, d);
        cr_assert_lt(fabs(volume_of(m) - v), tol * area + 1e-5 * v, "h=%g mesh volume %.9f", h,
                     volume_of(m));
        cr_assert_lt(fabs(mesh_area(m) - area), 1e-5 * area + tol * 40, "h=%g area %.9f", h,
                     mesh_area(m));
        mesh_free(m);
    }
    csg_scene_free(s);
}

Test(mesh_contour, sphere)
{
    double c[4] = {0.3, -0.2, 0.1, 5};
    csg_scene *s = scene_of(sphere_node(c[3], c[0], c[1], c[2]));
    double v = 4.0 / 3 * PI * 125;
    for (int cells = 8; cells <= 64; cells *= 2) {
        double h = 10.0 / cells;
        mesh_measure mm;
        mesh *m = contour(s, h, &mm);
        check_mesh(m, &mm, h, 2 * (h / 5) * (h / 5) + 0.01, "sphere");
        double d = max_dist(m, sd_sphere_ctx, c);
        cr_log_info("sphere h=%g: %d triangles, max vertex distance %.3g h, mesh volume err %.2e",
                    h, mesh_triangle_count(m), d / h, fabs(volume_of(m) - v) / v);
        cr_assert_lt(d, 0.5 * h, "h=%g: a vertex is %g from the sphere", h, d);
        mesh_free(m);
    }
    csg_scene_free(s);
}

/* The signed distances of the mesh's points (vertices, edge midpoints,
 * centroids) from sd, the most negative and the most positive. */
static void signed_extremes(const mesh *m, double (*sd)(const double p[3], const void *ctx),
                            const void *ctx, double *lo, double *hi)
{
    static const double w[7][3] = {{1, 0, 0},
                                   {0, 1, 0},
                                   {0, 0, 1},
                                   {.5, .5, 0},
                                   {0, .5, .5},
                                   {.5, 0, .5},
                                   {1. / 3, 1. / 3, 1. / 3}};
    const float *v = mesh_vertices(m);
    const int32_t *t = mesh_triangles(m);
    *lo = *hi = 0;
    for (int q = 0; q < mesh_triangle_count(m); q++)
        for (int k = 0; k < 7; k++) {
            double p[3] = {0, 0, 0};
            for (int c = 0; c < 3; c++)
                for (int j = 0; j < 3; j++)
                    p[c] += w[k][j] * v[3 * t[3 * q + j] + c];
            double d = sd(p, ctx);
            *lo = fmin(*lo, d);
            *hi = fmax(*hi, d);
        }
}

/* The largest distance from the surface sd of the points of each triangle
 * (an edge that bridges a groove has its midpoint off the surface though
 * its ends are on it). */
static double max_tri_dist(const mesh *m, double (*sd)(const double p[3], const void *ctx),
                           const void *ctx)
{
    double lo, hi;
    signed_extremes(m, sd, ctx, &lo, &hi);
    return fmax(-lo, hi);
}

/* Two spheres r = 10, centres 10 apart on x: their union (op 0), a concave
 * crease; intersection (1) and difference (2), convex ones. */
static double sd_two_spheres(const double p[3], const void *ctx)
{
    int op = *(const int *)ctx;
    double a = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 10;
    double b = sqrt((p[0] - 10) * (p[0] - 10) + p[1] * p[1] + p[2] * p[2]) - 10;
    return op == 0 ? fmin(a, b) : op == 1 ? fmax(a, b) : fmax(a, -b);
}

/* The contour's sharp-edge vertices lie on the exact crease of two curved
 * surfaces, and no edge bridges the groove where two spheres meet: every
 * point of every triangle is within 3 % of a cell of the surface.  (The QEF
 * alone put the union's crease vertices 0.24 h off it, where the tangent
 * planes of samples a cell away meet.)  Known limit, logged: where a convex
 * rim passes between two nodes (sphere minus sphere), an edge across it
 * whose split would fold a triangle stays, up to 0.3 h inside. */
Test(mesh_contour, curved_creases_are_exact)
{
    static const csg_op ops[3] = {CSG_OP_UNION, CSG_OP_INTERSECTION, CSG_OP_DIFFERENCE};
    for (int op = 0; op < 3; op++)
        for (int q = 0; q < 2; q++) {
            double h = q ? 0.3 : 0.25;
            csg_node *n = csg_node_op(ops[op]);
            cr_assert(csg_node_add(n, sphere_node(10, 0, 0, 0)) == 0);
            cr_assert(csg_node_add(n, sphere_node(10, 10, 0, 0)) == 0);
            csg_scene *s = scene_of(n);
            mesh_measure mm;
            mesh *m = contour(s, h, &mm);
            check_mesh(m, &mm, h, 1e-2, "two spheres");
            double d = max_tri_dist(m, sd_two_spheres, &op);
            cr_log_info("two spheres, op %d, h %g: %d triangles, points within %.5f (%.3f h)", op,
                        h, mesh_triangle_count(m), d, d / h);
            if (op < 2)
                cr_expect_lt(d, 0.03 * h, "op %d h %g: a triangle %g off the surface", op, h, d);
            mesh_free(m);
            csg_scene_free(s);
        }
}

Test(mesh_contour, csg_example)
{
    csg_scene *s = csg_example();
    double prev = INFINITY;
    for (int cells = 32; cells <= 128; cells *= 2) {
        double h = 20.0 / cells;
        mesh_measure mm;
        mesh *m = contour(s, h, &mm);
        check_mesh(m, &mm, h, 0.02, "csg example");
        double d = max_dist(m, sd_csg_ctx, NULL);
        double e = fabs(volume_of(m) - CSG_VOLUME) / CSG_VOLUME;
        cr_log_info("csg h=%g: %d triangles, max vertex distance %.3g h, mesh volume err %.2e", h,
                    mesh_triangle_count(m), d / h, e);
        cr_assert_lt(d, h, "h=%g: a vertex is %g from the surface", h, d);
        cr_assert_lt(e, prev, "mesh volume error not shrinking at h=%g", h);
        prev = e;
        mesh_free(m);
    }
    csg_scene_free(s);
}

/* Shapes that stress the topology: touching and nearly touching boxes, thin
 * walls, a small tunnel, cones with sharp rims and tips, features below h. */
Test(mesh_contour, stress_manifold)
{
    for (int variant = 0; variant < 6; variant++) {
        csg_node *root = csg_node_op(CSG_OP_UNION);
        switch (variant) {
        case 0: /* two boxes sharing only an edge, and one sharing a corner */
            csg_node_add(root, box_node(0, 0, 0, 1, 1, 1));
            csg_node_add(root, box_node(1, 1, 0, 2, 2, 1));
            csg_node_add(root, box_node(2, 2, 1, 3, 3, 2));
            break;
        case 1: /* a thin wall, thinner than h */
            csg_node_add(root, box_node(0, 0, 0, 4, 4, 0.5));
            csg_node_add(root, box_node(0, 0, 0, 0.03, 4, 4));
            break;
        case 2: { /* plate with a pin hole smaller than a cell */
            csg_node *d = csg_node_op(CSG_OP_DIFFERENCE);
            csg_node_add(d, box_node(0, 0, 0, 4, 4, 0.3));
            csg_node_add(d, cone_node(0.04, 0.04, 2, 2, 1));
            csg_node_add(root, d);
            break;
        }
        case 3: /* cones: tip, sharp rims, a tilted union */
            csg_node_add(root, cone_node(2, 0, 3, 2, 0));
            csg_node_add(root, cone_node(1, 1.7, 4, 0, 1));
            break;
        case 4: /* many small spheres near each other */
            for (int q = 0; q < 12; q++)
                csg_node_add(root, sphere_node(0.13 + 0.02 * q, 0.27 * q, 0.1 * (q % 3), 0));
            break;
        default: { /* intersection of a sphere and a box: sharp circles */
            csg_node *x = csg_node_op(CSG_OP_INTERSECTION);
            csg_node_add(x, sphere_node(1.3, 0, 0, 0));
            csg_node_add(x, box_node(-1, -1, -1, 1, 1, 1));
            csg_node_add(root, x);
            break;
        }
        }
        csg_scene *s = scene_of(root);
        for (int cells = 24; cells <= 48; cells += 11) {
            mesh_options o;
            mesh_options_default(&o);
            o.cells_per_side = cells;
            o.threads = 2;
            o.contour_all = 1;
            mesh *m = NULL;
            mesh_measure mm;
            char err[256] = "";
            cr_assert(mesh_from_scene(s, &o, &m, &mm, err, sizeof err) == 0, "%s", err);
            const char *msg = check_manifold(m);
            cr_assert_null(msg, "variant %d, %d cells: %s", variant, cells, msg);
            /* welded by position (as any STL reader does) it stays
             * manifold too, but where the solid itself is not: boxes
             * that share only an edge or a corner */
            if (variant != 0)
                cr_assert(!shared_position(m), "variant %d, %d cells: two vertices at one point",
                          variant, cells);
            double h;
            double org[3];
            int n[3];
            mesh_dexels *dx;
            cr_assert(mesh_dexels_new(s, &o, &dx, err, sizeof err) == 0);
            mesh_dexels_grid(dx, &h, org, n);
            mesh_dexels_free(dx);
            cr_assert_gt(min_area(m), 1e-7 * h * h, "variant %d: zero-area triangle", variant);
            cr_assert_gt(volume_of(m), 0, "variant %d: not outward", variant);
            mesh_free(m);
        }
        csg_scene_free(s);
    }
}

Test(mesh_contour, same_mesh_on_any_thread_count)
{
    csg_scene *s = csg_example();
    mesh *m[3];
    for (int q = 0; q < 3; q++) {
        mesh_options o;
        mesh_options_default(&o);
        o.cells_per_side = 40;
        o.threads = q + 1;
        o.contour_all = 1;
        char err[256] = "";
        cr_assert(mesh_from_scene(s, &o, &m[q], NULL, err, sizeof err) == 0, "%s", err);
    }
    for (int q = 1; q < 3; q++) {
        cr_assert_eq(mesh_vertex_count(m[q]), mesh_vertex_count(m[0]));
        cr_assert_eq(mesh_triangle_count(m[q]), mesh_triangle_count(m[0]));
        cr_assert(!memcmp(mesh_vertices(m[q]), mesh_vertices(m[0]),
                          3 * sizeof(float) * (size_t)mesh_vertex_count(m[0])));
        cr_assert(!memcmp(mesh_triangles(m[q]), mesh_triangles(m[0]),
                          3 * sizeof(int32_t) * (size_t)mesh_triangle_count(m[0])));
    }
    for (int q = 0; q < 3; q++)
        mesh_free(m[q]);
    csg_scene_free(s);
}

/* Random scenes: unions, differences and intersections of boxes, spheres and
 * cones under random rotations, at random resolutions.  The seed is fixed
 * and printed with any failure. */
static uint64_t rng;
static double urand(double lo, double hi)
{
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(rng >> 11) / 9007199254740992.0;
}

static csg_node *random_leaf(void)
{
    /* A random rotation (from a random unit quaternion) and translation. */
    double q[4], n = 0;
    for (int k = 0; k < 4; k++) {
        q[k] = urand(-1, 1);
        n += q[k] * q[k];
    }
    n = sqrt(n);
    double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    csg_affine m = {
        1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),     urand(-2, 2),
        2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),     urand(-2, 2),
        2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y), urand(-2, 2)};
    iv_shape s;
    memset(&s, 0, sizeof s);
    int kind = (int)urand(0, 3);
    if (kind == 0) {
        s.kind = IV_SHAPE_BOX;
        for (int c = 0; c < 3; c++) {
            s.u.box.lo[c] = urand(-2.5, -0.2);
            s.u.box.hi[c] = urand(0.2, 2.5);
        }
    } else if (kind == 1) {
        s.kind = IV_SHAPE_SPHERE;
        s.u.sphere.r = urand(0.3, 2.5);
    } else {
        s.kind = IV_SHAPE_CONE;
        s.u.cone.r1 = urand(0, 2);
        s.u.cone.r2 = urand(0, 2);
        if (s.u.cone.r1 + s.u.cone.r2 < 0.2) s.u.cone.r1 = 0.5;
        s.u.cone.h = urand(0.3, 4);
    }
    return csg_node_shape(&s, m, &plain);
}

static csg_node *random_tree(int depth)
{
    if (depth == 0 || urand(0, 1) < 0.3) return random_leaf();
    static const csg_op ops[3] = {CSG_OP_UNION, CSG_OP_DIFFERENCE, CSG_OP_INTERSECTION};
    csg_node *n = csg_node_op(ops[(int)urand(0, 3)]);
    int kids = 2 + (int)urand(0, 2);
    for (int k = 0; k < kids; k++)
        cr_assert(csg_node_add(n, random_tree(depth - 1)) == 0);
    return n;
}

Test(mesh_contour, random_scenes_are_manifold)
{
    const uint64_t seed = 20240611;
    rng = seed;
    int meshed = 0;
    for (int trial = 0; trial < 40; trial++) {
        csg_scene *s = scene_of(random_tree(3));
        mesh_options o;
        mesh_options_default(&o);
        o.cells_per_side = 12 + (int)urand(0, 40);
        o.threads = 2;
        mesh *m = NULL;
        mesh_measure mm;
        char err[256] = "";
        cr_assert(mesh_from_scene(s, &o, &m, &mm, err, sizeof err) == 0, "seed %llu trial %d: %s",
                  (unsigned long long)seed, trial, err);
        if (mesh_triangle_count(m) > 0) {
            meshed++;
            const char *msg = check_manifold(m);
            cr_assert_null(msg, "seed %llu trial %d (%d cells): %s", (unsigned long long)seed,
                           trial, o.cells_per_side, msg);
            cr_assert(!shared_position(m), "seed %llu trial %d: two vertices at one point",
                      (unsigned long long)seed, trial);
            mesh_dexels *dx;
            double h, org[3];
            int n[3];
            cr_assert(mesh_dexels_new(s, &o, &dx, err, sizeof err) == 0);
            mesh_dexels_grid(dx, &h, org, n);
            mesh_dexels_free(dx);
            cr_assert_gt(min_area(m), 1e-7 * h * h, "seed %llu trial %d: zero-area triangle",
                         (unsigned long long)seed, trial);
            double sv = volume_of(m);
            /* Thin parts below h may be lost or added: a loose bound. */
            cr_assert_lt(fabs(sv - mm.volume), 0.1 * mm.volume + 2 * mm.area * h,
                         "seed %llu trial %d: mesh volume %g vs measured %g",
                         (unsigned long long)seed, trial, sv, mm.volume);
        }
        mesh_free(m);
        csg_scene_free(s);
    }
    cr_assert_gt(meshed, 20, "only %d of 40 random scenes were non-empty", meshed);
}

/* ---- files through OpenMesh --------------------------------------------- */

Test(mesh_io, write_read_round_trip)
{
    csg_scene *s = csg_example();
    mesh_measure mm;
    mesh *m = contour(s, 20.0 / 24, &mm);
    char dir[] = "/tmp/rayscad_mesh_XXXXXX";
    cr_assert(mkdtemp(dir));
    const char *ext[] = {"stl", "stl", "off", "obj", "ply"};
    for (int q = 0; q < 5; q++) {
        char path[256], err[256] = "";
        snprintf(path, sizeof path, "%s/out%d.%s", dir, q, ext[q]);
        int ascii = q == 1;
        cr_assert(io_mesh_write(path, mesh_vertices(m), mesh_vertex_count(m), mesh_triangles(m),
                                mesh_triangle_count(m), ascii, NULL, err, sizeof err) == 0,
                  "%s: %s", path, err);
        float *v = NULL;
        int32_t *t = NULL;
        int nv = 0, nt = 0;
        cr_assert(io_mesh_read(path, &v, &nv, &t, &nt, err, sizeof err) == 0, "%s: %s", path, err);
        cr_assert_eq(nv, mesh_vertex_count(m), "%s: %d vertices back, wrote %d", path, nv,
                     mesh_vertex_count(m));
        cr_assert_eq(nt, mesh_triangle_count(m), "%s: triangles", path);
        mesh *back = mesh_new_from_arrays(v, nv, t, nt);
        cr_assert(back);
        cr_assert_null(check_manifold(back), "%s: read back not manifold", path);
        cr_assert_lt(fabs(volume_of(back) - volume_of(m)), 1e-4 * volume_of(m), "%s", path);
        mesh_free(back);
        free(v);
        free(t);
        unlink(path);
    }
    /* A failed write leaves nothing behind. */
    char bad[300], err[256] = "";
    snprintf(bad, sizeof bad, "%s/no/such/dir/x.stl", dir);
    cr_assert_eq(io_mesh_write(bad, mesh_vertices(m), mesh_vertex_count(m), mesh_triangles(m),
                               mesh_triangle_count(m), 0, NULL, err, sizeof err),
                 -1);
    cr_assert_neq(err[0], 0);
    char unk[300];
    snprintf(unk, sizeof unk, "%s/x.unknownext", dir);
    cr_assert_eq(io_mesh_write(unk, mesh_vertices(m), mesh_vertex_count(m), mesh_triangles(m),
                               mesh_triangle_count(m), 0, NULL, err, sizeof err),
                 -1);
    cr_assert_eq(access(unk, F_OK), -1);
    cr_assert_eq(rmdir(dir), 0, "temporary files left in %s", dir);
    mesh_free(m);
    csg_scene_free(s);
}

/* ---- thin features ------------------------------------------------------ */

static mesh_thin thin_of(csg_scene *s, double h)
{
    mesh_options o = opts_h(h);
    mesh_dexels *d;
    char err[256] = "";
    cr_assert(mesh_dexels_new(s, &o, &d, err, sizeof err) == 0, "%s", err);
    mesh_thin t;
    mesh_dexels_thin(d, h, &t);
    mesh_dexels_free(d);
    return t;
}

Test(mesh_thin, plate_thinner_than_h_is_found)
{
    /* A 0.3-thick plate on a grid of 0.5: every z ray through it reports a
     * wall of thickness 0.3 (its two faces have opposite normals). */
    csg_scene *s = scene_of(box_node(-5, -5, 0.1, 5, 5, 0.4));
    mesh_thin t = thin_of(s, 0.5);
    cr_assert_gt(t.walls, 300, "%lld rays saw the plate", t.walls);
    cr_assert_float_eq(t.min_wall, 0.3, 1e-9);
    cr_assert(t.wall_at[2] > 0.1 && t.wall_at[2] < 0.4, "at z = %g", t.wall_at[2]);
    cr_assert_eq(t.gaps, 0);
    csg_scene_free(s);
}

Test(mesh_thin, narrow_gap_is_found)
{
    /* Two boxes 0.2 apart along x, on a grid of 0.5. */
    csg_node *u = csg_node_op(CSG_OP_UNION);
    cr_assert(csg_node_add(u, box_node(-4, -4, -4, -0.1, 4, 4)) == 0);
    cr_assert(csg_node_add(u, box_node(0.1, -4, -4, 4, 4, 4)) == 0);
    csg_scene *s = scene_of(u);
    mesh_thin t = thin_of(s, 0.5);
    cr_assert_gt(t.gaps, 100);
    cr_assert_float_eq(t.min_gap, 0.2, 1e-9);
    cr_assert_eq(t.walls, 0);
    csg_scene_free(s);
}

Test(mesh_thin, curved_solids_are_not_thin)
{
    /* Rays that graze a sphere or the cylinders cut short chords, but their
     * ends have nearly equal normals: nothing is reported. */
    csg_scene *s = csg_example();
    mesh_thin t = thin_of(s, 20.0 / 64);
    cr_assert_eq(t.walls, 0, "%lld walls, thinnest %g", t.walls, t.min_wall);
    cr_assert_eq(t.gaps, 0);
    csg_scene_free(s);
    s = scene_of(sphere_node(3, 0.1, 0.2, 0.3));
    t = thin_of(s, 0.25);
    cr_assert_eq(t.walls + t.gaps, 0);
    csg_scene_free(s);
}

/* ---- the default grid: far-apart parts and thin parts ------------------- */

/* Mesh s with the default grid (o.h = 0), resolve_thin as given; the
 * mesh, and the spacing reported. */
static mesh *contour_default(const csg_scene *s, int resolve_thin, double *h)
{
    mesh_options o;
    mesh_options_default(&o);
    o.threads = 2;
    o.resolve_thin = resolve_thin;
    mesh_dexels *d;
    char err[256] = "";
    cr_assert(mesh_dexels_new(s, &o, &d, err, sizeof err) == 0, "%s", err);
    double org[3];
    int n[3];
    mesh_dexels_grid(d, h, org, n);
    mesh *m = NULL;
    cr_assert(mesh_dexels_contour(d, &o, &m, err, sizeof err) == 0, "%s", err);
    mesh_dexels_free(d);
    return m;
}

Test(mesh_contour, far_apart_parts_get_grids_of_their_own)
{
    /* A sphere of radius 1 and a unit cube 1000 apart: one grid over both
     * would have 7.8-unit cells and lose the sphere; each gets its own
     * (the cube's 1/128, the sphere's 2/128: the largest is reported). */
    csg_node *u = csg_node_op(CSG_OP_UNION);
    cr_assert(csg_node_add(u, sphere_node(1, 0.1, 0.2, 0.3)) == 0);
    cr_assert(csg_node_add(u, box_node(1000, 0, 0, 1001, 1, 1)) == 0);
    csg_scene *s = scene_of(u);
    double h;
    mesh *m = contour_default(s, 1, &h);
    double v = 4.0 / 3 * PI + 1;
    cr_log_info("far apart: h %g, %d triangles, volume %.6f (exact %.6f)", h,
                mesh_triangle_count(m), volume_of(m), v);
    cr_assert_null(check_manifold(m));
    cr_assert_float_eq(h, (double)(float)(2.0 / 128), 1e-12);
    cr_assert_lt(fabs(volume_of(m) - v), 1e-3 * v, "volume %.6f, exact %.6f", volume_of(m), v);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    const float *p = mesh_vertices(m);
    for (int q = 0; q < mesh_vertex_count(m); q++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], p[3 * q + c]);
            hi[c] = fmax(hi[c], p[3 * q + c]);
        }
    cr_assert_float_eq(lo[0], -0.9, 0.02);
    cr_assert_float_eq(hi[0], 1001, 1e-4);
    mesh_free(m);
    csg_scene_free(s);
}

Test(mesh_contour, default_grid_resolves_a_thin_gap)
{
    /* Two 40 x 40 plates 0.2 apart: the default grid (0.3125, nodes at
     * z = 2.031 and 2.344) would close the gap (+5 % volume, the plates
     * fused); refined, the mesh is the two boxes. */
    csg_node *u = csg_node_op(CSG_OP_UNION);
    cr_assert(csg_node_add(u, box_node(0, 0, 0, 40, 40, 2.05)) == 0);
    cr_assert(csg_node_add(u, box_node(0, 0, 2.25, 40, 40, 4.25)) == 0);
    csg_scene *s = scene_of(u);
    double v = 40 * 40 * 4.05, h;
    mesh *coarse = contour_default(s, 0, &h);
    cr_log_info("thin gap, not refined: h %g, volume %.6f", h, volume_of(coarse));
    cr_assert_gt(volume_of(coarse), v * 1.01, "the coarse grid kept the gap?");
    mesh_free(coarse);
    mesh *m = contour_default(s, 1, &h);
    cr_log_info("thin gap, refined: h %g, %d triangles, volume %.6f", h, mesh_triangle_count(m),
                volume_of(m));
    cr_assert_null(check_manifold(m));
    cr_assert_lt(h, 0.2, "spacing %g does not resolve a 0.2 gap", h);
    cr_assert_lt(fabs(volume_of(m) - v), 1e-6 * v, "volume %.6f", volume_of(m));
    mesh_free(m);
    csg_scene_free(s);
}

/* ---- the TriMesh built for OpenMesh ------------------------------------- */

Test(mesh_contour, default_grid_leaves_a_taper_alone)
{
    /* A slim cone (radius 1, height 20) has walls of every thickness near
     * its tip: those thinner than 4 cells of 20/128 hold 3 % of its volume,
     * those thinner than 2 cells 0.4 % (the share falls as the cube of the
     * thickness).  No grid resolves a tip, so the default one is kept
     * (refined 16 times, the mesh had millions of triangles), and its
     * volume is still within 0.5 % of the exact pi r^2 h / 3. */
    csg_scene *s = scene_of(cone_node(1, 0, 20, 2, 0));
    double v = PI * 20 / 3, h;
    mesh *m = contour_default(s, 1, &h);
    cr_log_info("slim cone: h %g, %d triangles, volume %.6f (exact %.6f)", h,
                mesh_triangle_count(m), volume_of(m), v);
    cr_assert_null(check_manifold(m));
    cr_assert_float_eq(h, (double)(float)(20.0 / 128), 1e-12);
    cr_assert_lt(fabs(volume_of(m) - v), 5e-3 * v, "volume %.6f, exact %.6f", volume_of(m), v);
    mesh_free(m);
    csg_scene_free(s);
}

Test(mesh_io, write_rejects_non_manifold_and_accepts_open)
{
    char dir[] = "/tmp/rayscad_mesh_XXXXXX";
    cr_assert(mkdtemp(dir));
    char path[300], err[256] = "";
    snprintf(path, sizeof path, "%s/x.stl", dir);
    /* Two tetrahedra sharing only vertex 0: closed, every edge paired, but
     * vertex 0 has two fans. */
    const float v[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1};
    const int32_t pinch[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3,
                             0, 5, 4, 0, 4, 6, 0, 6, 5, 4, 5, 6};
    cr_assert_eq(io_mesh_write(path, v, 7, pinch, 8, 0, NULL, err, sizeof err), -1);
    cr_assert(strstr(err, "non-manifold"), "%s", err);
    cr_assert_eq(access(path, F_OK), -1);
    /* One edge in three triangles. */
    const int32_t fin[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 1, 0, 4};
    cr_assert_eq(io_mesh_write(path, v, 7, fin, 5, 0, NULL, err, sizeof err), -1);
    /* A repeated vertex. */
    const int32_t degenerate[] = {0, 1, 1};
    cr_assert_eq(io_mesh_write(path, v, 7, degenerate, 1, 0, NULL, err, sizeof err), -1);
    /* An open mesh (one tetrahedron face missing) goes through add_face. */
    cr_assert(io_mesh_write(path, v, 7, pinch, 3, 0, NULL, err, sizeof err) == 0, "%s", err);
    float *rv;
    int32_t *rt;
    int nv, nt;
    cr_assert(io_mesh_read(path, &rv, &nv, &rt, &nt, err, sizeof err) == 0, "%s", err);
    cr_assert_eq(nt, 3);
    cr_assert_eq(nv, 4);
    free(rv);
    free(rt);
    /* The closed tetrahedron comes back with its vertices in order. */
    cr_assert(io_mesh_write(path, v, 7, pinch, 4, 0, NULL, err, sizeof err) == 0, "%s", err);
    cr_assert(io_mesh_read(path, &rv, &nv, &rt, &nt, err, sizeof err) == 0, "%s", err);
    cr_assert_eq(nt, 4);
    for (int q = 0; q < 12; q++)
        for (int c = 0; c < 3; c++)
            cr_assert_eq(rv[3 * rt[q] + c], v[3 * pinch[q] + c], "corner %d", q);
    free(rv);
    free(rt);
    unlink(path);
    cr_assert_eq(rmdir(dir), 0, "temporary files left in %s", dir);
}

/* ---- simplification (simplify.c) ---------------------------------------- */

/* The largest distance from the exact surface (sd) of a triangle's
 * centroid and edge midpoints: where a flat triangle strays furthest from
 * a curved surface its corners lie on. */
static mesh *simplified(const csg_scene *s, double h, double tol, mesh_measure *mm)
{
    mesh_options o = opts_h(h);
    o.tolerance = tol;
    mesh *m = NULL;
    char err[256] = "";
    cr_assert(mesh_from_scene(s, &o, &m, mm, err, sizeof err) == 0, "%s", err);
    return m;
}

/* A box off the grid: 8 corners, 12 triangles, and the volume the
 * corners give (exact up to float rounding of the corners).  Turned, its
 * contour's vertices along the edges lie up to EPS·h off them, and the
 * edges keep many of them: fewer triangles, the same solid (a known limit,
 * issue 22). */
Test(mesh_simplify, box_is_twelve_triangles)
{
    double b[6] = {-3.1, -2.05, 1, 4.9, 2.3, 3.7};
    csg_scene *s = scene_of(box_node(b[0], b[1], b[2], b[3], b[4], b[5]));
    mesh_measure mm;
    mesh *m = simplified(s, 0.15, 1e-3, &mm);
    cr_assert_null(check_manifold(m));
    cr_expect_eq(mesh_triangle_count(m), 12);
    cr_expect_eq(mesh_vertex_count(m), 8);
    cr_expect_lt(max_dist(m, sd_box_ctx, b), 1e-5, "a corner off the box");
    cr_expect_lt(fabs(volume_of(m) - 8 * 4.35 * 2.7), 1e-4, "volume %.9f", volume_of(m));
    mesh_free(m);
    csg_scene_free(s);

    /* turned 0.7 rad about (1, 2, 3) (Rodrigues) */
    iv_shape cube = {.kind = IV_SHAPE_BOX};
    for (int k = 0; k < 3; k++) {
        cube.u.box.lo[k] = -5;
        cube.u.box.hi[k] = 5;
    }
    double ax[3] = {1 / sqrt(14.0), 2 / sqrt(14.0), 3 / sqrt(14.0)}, cs = cos(0.7), sn = sin(0.7);
    csg_affine r = {0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double cross = i == j ? 0 : ax[3 - i - j] * (((j - i + 3) % 3 == 1) ? -1 : 1);
            r[4 * i + j] = (i == j ? cs : 0) + (1 - cs) * ax[i] * ax[j] + sn * cross;
        }
    s = scene_of(csg_node_shape(&cube, r, &plain));
    mesh *full = contour(s, 0.2, &mm);
    m = simplified(s, 0.2, 1e-2, &mm);
    cr_log_info("turned box: %d -> %d triangles, volume %.6f", mesh_triangle_count(full),
                mesh_triangle_count(m), volume_of(m));
    cr_assert_null(check_manifold(m));
    cr_expect_lt(mesh_triangle_count(m), mesh_triangle_count(full) / 10);
    cr_expect_lt(fabs(volume_of(m) - volume_of(full)), 1e-4 * 1000, "volume %.9f vs %.9f",
                 volume_of(m), volume_of(full));
    mesh_free(full);
    mesh_free(m);
    csg_scene_free(s);
}

/* A plate with a square hole through it: 16 corners, and genus 1 makes
 * the fewest triangles 2·16 = 32 (V − E + F = 0, E = 3F/2). */
Test(mesh_simplify, plate_with_a_hole_is_its_corners)
{
    csg_node *d = csg_node_op(CSG_OP_DIFFERENCE);
    cr_assert_eq(csg_node_add(d, box_node(0, 0, 0, 20, 20, 5)), 0);
    cr_assert_eq(csg_node_add(d, box_node(5, 5, -1, 15, 15, 6)), 0);
    csg_scene *s = scene_of(d);
    mesh_measure mm;
    mesh *m = simplified(s, 0.3, 1e-3, &mm);
    cr_assert_null(check_manifold(m));
    cr_expect_eq(mesh_vertex_count(m), 16);
    cr_expect_eq(mesh_triangle_count(m), 32);
    cr_expect_lt(fabs(volume_of(m) - 1500), 1e-3, "volume %.9f", volume_of(m));
    mesh_free(m);
    csg_scene_free(s);
}

/* A sphere: far fewer triangles, still closed, and within about the
 * tolerance of the sphere on both sides: the simplification leaves
 * triangles that sag inside by up to 1.8 tolerances, and their vertices
 * move out by half that (balance.c), so points lie both outside (the
 * vertices) and inside (the triangles' middles), each within 1.25 tol
 * (the surface between the contour's points adds a little), and the
 * volume's error, in and out partly cancelling, is under a quarter of the
 * area times the tolerance. */
Test(mesh_simplify, sphere_fewer_triangles_close_to_it)
{
    double c[4] = {0.3, -0.2, 0.1, 5};
    csg_scene *s = scene_of(sphere_node(c[3], c[0], c[1], c[2]));
    mesh_measure mm;
    mesh *full = contour(s, 10.0 / 64, &mm);
    double tol = 1e-2, v = 4.0 / 3 * PI * 125, area = 4 * PI * 25;
    mesh *m = simplified(s, 10.0 / 64, tol, &mm);
    double lo, hi;
    signed_extremes(m, sd_sphere_ctx, c, &lo, &hi);
    cr_log_info("sphere tol %g: %d -> %d triangles, from %.3g to %.3g of the sphere, volume "
                "error %.3g",
                tol, mesh_triangle_count(full), mesh_triangle_count(m), lo, hi, volume_of(m) - v);
    cr_assert_null(check_manifold(m));
    cr_expect_lt(mesh_triangle_count(m), mesh_triangle_count(full) / 12);
    cr_expect_gt(-lo, 0.4 * tol, "inside by %g only", -lo);
    cr_expect_gt(hi, 0.4 * tol, "outside by %g only: not balanced", hi);
    cr_expect_lt(fmax(-lo, hi), 1.25 * tol);
    cr_expect_lt(fabs(volume_of(m) - v), 0.25 * tol * area, "volume %.6f", volume_of(m));
    mesh_free(full);
    mesh_free(m);
    csg_scene_free(s);
}

/* Random CSG stays closed and 2-manifold through simplification, and
 * keeps its volume within 1 %. */
Test(mesh_simplify, random_scenes_stay_manifold)
{
    rng = 20261203;
    int meshed = 0;
    for (int trial = 0; trial < 30; trial++) {
        csg_scene *s = scene_of(random_tree(3));
        mesh_options o;
        mesh_options_default(&o);
        o.cells_per_side = 12 + (int)urand(0, 40);
        o.threads = 2;
        o.resolve_thin = 0; /* its finer grids make meshes of 10^6 triangles */
        mesh *m = NULL;
        mesh_measure mm;
        char err[256] = "";
        cr_assert(mesh_from_scene(s, &o, &m, &mm, err, sizeof err) == 0, "%s", err);
        if (mesh_triangle_count(m) > 0) {
            meshed++;
            double before = volume_of(m);
            cr_assert(mesh_simplify(m, 1e-3 * pow(mm.volume, 1 / 3.0),
                                    1e-3 * pow(mm.volume, 1 / 3.0), NULL, 2, err, sizeof err) == 0);
            const char *msg = check_manifold(m);
            cr_assert_null(msg, "trial %d: %s", trial, msg);
            cr_expect_lt(fabs(volume_of(m) - before), 0.01 * before, "trial %d: volume %g -> %g",
                         trial, before, volume_of(m));
        }
        mesh_free(m);
        csg_scene_free(s);
    }
    cr_assert_gt(meshed, 15);
}

/* A mesh of over twice REGION_VERTICES (simplify.c) vertices is simplified
 * in slabs, on threads, and then whole: the same mesh on one thread as on
 * three, closed and 2-manifold, as near the surface and as few triangles as
 * when it was simplified whole (6,414 at h = 0.25, tolerance 0.006). */
Test(mesh_simplify, slabs_on_threads_as_on_one)
{
    csg_scene *s = csg_example();
    mesh_measure mm;
    double tol = 0.01;
    mesh *m1 = contour(s, 0.2, &mm), *m3 = contour(s, 0.2, &mm);
    int nt = mesh_triangle_count(m1);
    cr_assert_gt(mesh_vertex_count(m1), 60000, "%d vertices: one slab", mesh_vertex_count(m1));
    char err[256] = "";
    cr_assert(mesh_simplify(m1, tol, tol, NULL, 1, err, sizeof err) == 0, "%s", err);
    cr_assert(mesh_simplify(m3, tol, tol, NULL, 3, err, sizeof err) == 0, "%s", err);
    cr_log_info("slabs: %d -> %d triangles", nt, mesh_triangle_count(m1));
    cr_assert_null(check_manifold(m3));
    cr_assert_eq(mesh_vertex_count(m1), mesh_vertex_count(m3));
    cr_assert_eq(mesh_triangle_count(m1), mesh_triangle_count(m3));
    cr_expect(memcmp(mesh_vertices(m1), mesh_vertices(m3),
                     3 * sizeof(float) * (size_t)mesh_vertex_count(m1)) == 0);
    cr_expect(memcmp(mesh_triangles(m1), mesh_triangles(m3),
                     3 * sizeof(int32_t) * (size_t)mesh_triangle_count(m1)) == 0);
    cr_expect_lt(mesh_triangle_count(m3), nt / 10);
    cr_expect_lt(max_dist(m3, sd_csg_ctx, NULL), 1.5 * tol);
    mesh_free(m1);
    mesh_free(m3);
    csg_scene_free(s);
}

/* Two boxes of two colours side by side: their top, bottom, front and back
 * faces are one plane each, and the colours' border across them stays
 * where the contour drew it — within a cell of x = 10, as jagged as the
 * contour's (whose triangles take one crossing's colour each) — while the
 * rest collapses. */
Test(mesh_simplify, colour_borders_keep_their_course)
{
    csg_material red = {.has_color = 1, .rgba = {1, 0, 0, 1}},
                 blue = {.has_color = 1, .rgba = {0, 0, 1, 1}};
    iv_shape a = {.kind = IV_SHAPE_BOX}, b = {.kind = IV_SHAPE_BOX};
    for (int k = 0; k < 3; k++) {
        a.u.box.hi[k] = b.u.box.hi[k] = 10;
        a.u.box.lo[k] = b.u.box.lo[k] = 0;
    }
    b.u.box.lo[0] = 10;
    b.u.box.hi[0] = 20.5;
    csg_node *u = csg_node_op(CSG_OP_UNION);
    cr_assert_eq(csg_node_add(u, csg_node_shape(&a, csg_affine_identity, &red)), 0);
    cr_assert_eq(csg_node_add(u, csg_node_shape(&b, csg_affine_identity, &blue)), 0);
    csg_scene *s = scene_of(u);
    mesh_measure mm;
    mesh *m = simplified(s, 0.3, 1e-3, &mm);
    cr_assert_null(check_manifold(m));
    cr_assert_eq(mesh_color_count(m), 2);
    const float *v = mesh_vertices(m), *pal = mesh_colors(m);
    const int32_t *t = mesh_triangles(m);
    const uint16_t *tc = mesh_triangle_colors(m);
    int wrong = 0;
    for (int q = 0; q < mesh_triangle_count(m); q++) {
        double x = (v[3 * t[3 * q]] + v[3 * t[3 * q + 1]] + v[3 * t[3 * q + 2]]) / 3;
        int is_red = tc[q] > 0 && pal[4 * (tc[q] - 1)] > 0.5f;
        wrong += is_red != (x < 10) && fabs(x - 10) > 0.3;
    }
    cr_log_info("two colours: %d triangles", mesh_triangle_count(m));
    cr_expect_eq(wrong, 0, "%d of %d triangles a cell past the colours' border", wrong,
                 mesh_triangle_count(m));
    cr_expect_lt(mesh_triangle_count(m), 1000);
    cr_expect_lt(fabs(volume_of(m) - 2050), 1e-3, "volume %.6f", volume_of(m));
    mesh_free(m);
    csg_scene_free(s);
}

static uint32_t xorshift(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* The twins rule, read off all earlier half-edges (quadratic): x = a → b
 * pairs with the last earlier b → a that found no twin when it came, if
 * that one is still unpaired. */
static void twins_by_rule(const int32_t *t, int nt, int t0, int32_t *opp)
{
    int n = 3 * (nt - t0);
    uint8_t waits[3 * 24] = {0};
    for (int x = 0; x < n; x++) {
        const int32_t *tx = t + 3 * t0 + x / 3 * 3;
        int32_t a = tx[x % 3], b = tx[(x % 3 + 1) % 3], best = -1;
        for (int y = 0; y < x; y++) {
            const int32_t *ty = t + 3 * t0 + y / 3 * 3;
            if (ty[y % 3] == b && ty[(y % 3 + 1) % 3] == a && waits[y]) best = y;
        }
        opp[x] = -1;
        if (best >= 0 && opp[best] < 0) {
            opp[x] = best;
            opp[best] = x;
        } else {
            waits[x] = 1;
        }
    }
}

Test(mesh_topology, half_twins_follow_their_rule)
{
    /* random triangles over a few vertices: edges of one, two, three and
     * more triangles either way, triangles with a corner twice, and a
     * first triangle t0 past the start */
    uint32_t r = 12345;
    for (int trial = 0; trial < 5000; trial++) {
        int32_t t[3 * 24], want[3 * 24], got[3 * 24];
        float v[3 * 10] = {0};
        int nv = 3 + (int)(xorshift(&r) % 8), nt = 1 + (int)(xorshift(&r) % 24);
        for (int i = 0; i < nt; i++) {
            /* one in eight with a corner twice (a reader's degenerate facet) */
            int twice = xorshift(&r) % 8 == 0;
            int32_t a = (int32_t)(xorshift(&r) % (uint32_t)nv), b, c;
            do
                b = (int32_t)(xorshift(&r) % (uint32_t)nv);
            while (b == a && !twice);
            do
                c = (int32_t)(xorshift(&r) % (uint32_t)nv);
            while ((c == a || c == b) && !twice);
            t[3 * i] = a, t[3 * i + 1] = b, t[3 * i + 2] = c;
        }
        int t0 = (int)(xorshift(&r) % (uint32_t)nt);
        mesh *m = mesh_new_from_arrays(v, nv, t, nt);
        cr_assert_not_null(m);
        cr_assert_eq(mesh_half_twins(m, t0, got), 0);
        twins_by_rule(t, nt, t0, want);
        for (int x = 0; x < 3 * (nt - t0); x++)
            cr_assert_eq(got[x], want[x], "trial %d, half-edge %d: %d, not %d", trial, x, got[x],
                         want[x]);
        mesh_free(m);
    }
}

/* ---- flat faces' inner vertices (mesh_flatten) --------------------------- */

/* The box [0, sx] × [0, sy] × [0, sz] with each face cut into n × n
 * squares, each square two triangles (the diagonals alternating), facing
 * out: its vertices shared, one per grid point of the surface. */
static mesh *grid_box(int n, const double size[3])
{
    int side = n + 1, nv = 0;
    float *v = malloc(3 * (size_t)side * side * side * sizeof *v);
    int32_t *id = malloc((size_t)side * side * side * sizeof *id);
    int32_t *t = malloc(6 * 2 * 3 * (size_t)n * n * sizeof *t);
    cr_assert(v && id && t);
    for (int i = 0; i < side * side * side; i++)
        id[i] = -1;
    int nt = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int hi = 0; hi < 2; hi++) {
            int a = (axis + 1) % 3, b = (axis + 2) % 3;
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++) {
                    int32_t q[4];
                    for (int c = 0; c < 4; c++) {
                        int g[3];
                        g[axis] = hi * n;
                        g[a] = i + (c == 1 || c == 2);
                        g[b] = j + (c >= 2);
                        int key = (g[0] * side + g[1]) * side + g[2];
                        if (id[key] < 0) {
                            for (int k = 0; k < 3; k++)
                                v[3 * nv + k] = (float)(size[k] * g[k] / n);
                            id[key] = nv++;
                        }
                        q[c] = id[key];
                    }
                    /* corners 0 (i, j), 1 (i+1, j), 2 (i+1, j+1), 3 (i, j+1):
                     * counter-clockwise about +axis; the low face reversed */
                    int32_t tri[2][3];
                    if ((i + j) & 1) {
                        int32_t x[2][3] = {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}};
                        memcpy(tri, x, sizeof tri);
                    } else {
                        int32_t x[2][3] = {{q[0], q[1], q[3]}, {q[1], q[2], q[3]}};
                        memcpy(tri, x, sizeof tri);
                    }
                    for (int k = 0; k < 2; k++) {
                        t[3 * nt] = tri[k][0];
                        t[3 * nt + 1] = hi ? tri[k][1] : tri[k][2];
                        t[3 * nt + 2] = hi ? tri[k][2] : tri[k][1];
                        nt++;
                    }
                }
        }
    mesh *m = mesh_new_from_arrays(v, nv, t, nt);
    cr_assert(m);
    free(v);
    free(id);
    free(t);
    return m;
}

/* A box's faces cut into a grid: the vertices inside a face go, nearly
 * all, those on its edges stay (they are not in one plane), and the solid
 * is the same:
 * closed and 2-manifold, the same volume and area (a triangle turned over
 * would add its area), every triangle in a face. */
Test(mesh_flatten, box_faces_lose_their_inner_vertices)
{
    const double size[3] = {3, 2, 1};
    int n = 8;
    mesh *m = grid_box(n, size);
    cr_assert_null(check_manifold(m));
    cr_assert_eq(mesh_vertex_count(m), 6 * (n + 1) * (n + 1) - 12 * (n + 1) + 8);
    cr_assert_eq(mesh_flatten(m, 1e-6), 0);
    cr_assert_null(check_manifold(m));
    cr_expect_lt(fabs(volume_of(m) - 6), 1e-9, "volume %.12f", volume_of(m));
    cr_expect_lt(fabs(area_of(m) - 22), 1e-9, "area %.12f", area_of(m));
    const float *v = mesh_vertices(m);
    int inner = 0;
    for (int q = 0; q < mesh_vertex_count(m); q++) {
        int on = 0; /* coordinates at a bound */
        for (int k = 0; k < 3; k++)
            on += v[3 * q + k] == 0 || v[3 * q + k] == (float)size[k];
        inner += on < 2;
    }
    /* (a vertex goes only where a neighbour's fan can stand for it: the
     * last few of a face can be tied to the edges by its neighbours'
     * triangles, and are the simplifier's) */
    cr_log_info("%d of %d vertices left inside the faces", inner, 6 * (n - 1) * (n - 1));
    cr_expect_leq(inner, 6 * (n - 1) * (n - 1) / 16, "%d vertices left inside faces", inner);
    cr_expect_eq(mesh_vertex_count(m), 12 * (n - 1) + 8 + inner);
    const int32_t *t = mesh_triangles(m);
    int off = 0;
    for (int q = 0; q < mesh_triangle_count(m); q++) {
        int face = 0;
        for (int k = 0; k < 3; k++)
            for (int hi = 0; hi < 2; hi++) {
                float x = hi ? (float)size[k] : 0;
                face |= v[3 * t[3 * q] + k] == x && v[3 * t[3 * q + 1] + k] == x &&
                        v[3 * t[3 * q + 2] + k] == x;
            }
        off += !face;
    }
    cr_expect_eq(off, 0, "%d triangles out of the faces", off);
    mesh_free(m);
}

/* A contoured sphere has no vertex whose triangles lie in one plane:
 * nothing goes. */
Test(mesh_flatten, curved_surface_is_left_alone)
{
    csg_scene *s = scene_of(sphere_node(5, 0.3, -0.2, 0.1));
    mesh_options o = opts_h(0.5);
    mesh *m = NULL;
    char err[256] = "";
    cr_assert(mesh_from_scene(s, &o, &m, NULL, err, sizeof err) == 0, "%s", err);
    int nv = mesh_vertex_count(m), nt = mesh_triangle_count(m);
    int32_t *before = malloc(3 * (size_t)nt * sizeof *before);
    cr_assert(before);
    memcpy(before, mesh_triangles(m), 3 * (size_t)nt * sizeof *before);
    cr_assert_eq(mesh_flatten(m, 1e-6), 0);
    cr_expect_eq(mesh_vertex_count(m), nv);
    cr_expect_eq(mesh_triangle_count(m), nt);
    cr_expect_eq(memcmp(before, mesh_triangles(m), 3 * (size_t)nt * sizeof *before), 0);
    free(before);
    mesh_free(m);
    csg_scene_free(s);
}

/* ---- triangles straying from the surface (mesh_tighten) ------------------ */

/* A box's grid mesh with the sides along one of its edges flipped across
 * it: each pair of triangles there a chamfer, cutting the edge off by up
 * to a third of a grid step.  Tightened, every triangle lies on the box
 * again (within the tolerance), closed, 2-manifold, its volume the box's. */
Test(mesh_tighten, chamfers_across_an_edge_go)
{
    const double size[3] = {3, 2, 1}, b[6] = {0, 0, 0, 3, 2, 1};
    mesh *grid = grid_box(4, size);
    csg_scene *s = scene_of(box_node(b[0], b[1], b[2], b[3], b[4], b[5]));
    /* the sides along the edge y = 0, z = 1 whose triangles' third corners
     * are off it and off the end faces, each corner once, flipped: (a, b, c), (b, a, d) -> (c, a,
     * d), (d, b, c) */
    int nv = mesh_vertex_count(grid), nt = mesh_triangle_count(grid), flipped = 0;
    const float *v = mesh_vertices(grid);
    int32_t *t = malloc(3 * (size_t)nt * sizeof *t), *opp = malloc(3 * (size_t)nt * sizeof *opp);
    char *touched = calloc((size_t)nt, 1), *joined = calloc((size_t)nv, 1);
    cr_assert(t && opp && touched && joined && mesh_half_twins(grid, 0, opp) == 0);
    memcpy(t, mesh_triangles(grid), 3 * (size_t)nt * sizeof *t);
#define ON_EDGE(q) (v[3 * (q) + 1] == 0 && v[3 * (q) + 2] == 1)
#define INSIDE(q) (v[3 * (q)] > 0 && v[3 * (q)] < 3) /* (off the end faces) */
    for (int q = 0; q < nt; q++)
        for (int k = 0; k < 3 && !touched[q]; k++) {
            int32_t h = opp[3 * q + k], o = h / 3, j = h % 3;
            int32_t a = t[3 * q + k], bb = t[3 * q + (k + 1) % 3], c = t[3 * q + (k + 2) % 3];
            if (h < 0 || touched[o] || !ON_EDGE(a) || !ON_EDGE(bb)) continue;
            int32_t d = t[3 * o + (j + 2) % 3];
            if (ON_EDGE(c) || ON_EDGE(d) || joined[c] || joined[d] || !INSIDE(c) || !INSIDE(d))
                continue;
            int32_t x[2][3] = {{c, a, d}, {d, bb, c}};
            memcpy(&t[3 * q], x[0], sizeof x[0]);
            memcpy(&t[3 * o], x[1], sizeof x[1]);
            touched[q] = touched[o] = 1;
            joined[c] = joined[d] = 1; /* (one new side from each) */
            flipped++;
        }
#undef ON_EDGE
#undef INSIDE
    mesh *m = mesh_new_from_arrays(v, nv, t, nt);
    cr_assert_not_null(m);
    free(t);
    free(opp);
    free(touched);
    free(joined);
    mesh_free(grid);
    cr_assert_gt(flipped, 0);
    cr_assert_null(check_manifold(m));
    double tol = 1e-3, before = max_tri_dist(m, sd_box_ctx, b);
    cr_assert_gt(before, 100 * tol, "the chamfers cut %g off", before);
    mesh_options o = opts_h(0.1);
    mesh_dexels *d = NULL;
    char err[256] = "";
    double lo[3] = {-0.2, -0.2, -0.2}, hi[3] = {3.2, 2.2, 1.2};
    cr_assert(mesh_dexels_cast(s, &o, 0.1, lo, hi, &d, err, sizeof err) == 0, "%s", err);
    mesh_snapper sn;
    cr_assert_eq(mesh_snapper_init(&sn, d, cos(3.14159265358979323846 / 6)), 0);
    cr_assert_eq(mesh_tighten(m, &sn, tol, 2), 0);
    double after = max_tri_dist(m, sd_box_ctx, b);
    cr_log_info("%d chamfers: %g off -> %g, %d triangles", flipped, before, after,
                mesh_triangle_count(m));
    cr_assert_null(check_manifold(m));
    cr_expect_leq(after, tol, "still %g off the box", after);
    cr_expect_lt(fabs(volume_of(m) - 6), 1e-5, "volume %.9f", volume_of(m));
    mesh_snapper_free(&sn);
    mesh_dexels_free(d);
    mesh_free(m);
    csg_scene_free(s);
}
