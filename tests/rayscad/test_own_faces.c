/*
 * test_own_faces.c — a part that is one polyhedral primitive alone is
 * meshed as its own faces (src/mesh/exact_faces.c): against closed forms
 * (corners, volumes, the Euler count of a closed triangulated sphere) and
 * against the contour where the part is not alone.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../include/rayscad.h"
#include "scene_of.h"

#define PI 3.14159265358979323846

/* The mesh of src at the default options, simplified to 0.01 (contour_all
 * as given: 2 for the contour unsimplified). */
static rayscad_mesh *mesh_of(const char *src, int contour_all)
{
    rayscad_scene *scene = scene_of(src, NULL);
    rayscad_mesh_options mo;
    rayscad_mesh_options_default(&mo);
    mo.tolerance = contour_all == 2 ? 0 : 0.01;
    mo.contour_all = contour_all != 0;
    rayscad_sampling *d;
    char err[256];
    cr_assert_eq(rayscad_sampling_new(scene, &mo, &d, err, sizeof err), RAYSCAD_OK, "%s", err);
    rayscad_mesh *m;
    cr_assert_eq(rayscad_sampling_mesh(d, &mo, &m, err, sizeof err), RAYSCAD_OK, "%s", err);
    rayscad_sampling_free(d);
    rayscad_scene_free(scene);
    return m;
}

static int cmp_edge(const void *a, const void *b)
{
    const int64_t *x = a, *y = b;
    return (*x > *y) - (*x < *y);
}

/* Whether every directed edge is used once and its reverse once (closed,
 * 2-manifold at the edges, consistently wound), with no vertex repeated. */
static int closed(const rayscad_mesh *m)
{
    int nt = rayscad_mesh_triangle_count(m), nv = rayscad_mesh_vertex_count(m);
    const int32_t *t = rayscad_mesh_triangles(m);
    int64_t *e = malloc(3 * (size_t)nt * sizeof *e);
    cr_assert(e);
    for (int i = 0; i < nt; i++)
        for (int k = 0; k < 3; k++)
            e[3 * i + k] = (int64_t)t[3 * i + k] * nv + t[3 * i + (k + 1) % 3];
    qsort(e, 3 * (size_t)nt, sizeof *e, cmp_edge);
    int ok = 1;
    for (size_t i = 0; ok && i < 3 * (size_t)nt; i++) {
        int64_t a = e[i] / nv, b = e[i] % nv, rev = b * nv + a;
        ok = a != b && (i == 0 || e[i] != e[i - 1]) &&
             bsearch(&rev, e, 3 * (size_t)nt, sizeof *e, cmp_edge) != NULL;
    }
    free(e);
    return ok;
}

/* Whether the vertex at p (within eps) is in m. */
static int has_vertex(const rayscad_mesh *m, const double p[3], double eps)
{
    const float *v = rayscad_mesh_vertices(m);
    for (int i = 0; i < rayscad_mesh_vertex_count(m); i++)
        if (fabs(v[3 * i] - p[0]) < eps && fabs(v[3 * i + 1] - p[1]) < eps &&
            fabs(v[3 * i + 2] - p[2]) < eps)
            return 1;
    return 0;
}

/* A turned box: its eight corners where the rotation puts them, twelve
 * triangles, 6000 to float rounding. */
Test(own_faces, turned_box_is_its_corners)
{
    rayscad_mesh *m = mesh_of("rotate([20, 30, 40]) cube([10, 20, 30]);", 0);
    cr_expect_eq(rayscad_mesh_triangle_count(m), 12);
    cr_expect_eq(rayscad_mesh_vertex_count(m), 8);
    cr_expect(closed(m));
    cr_expect_float_eq(rayscad_mesh_volume(m), 6000, 6000 * 1e-6);
    /* OpenSCAD's rotate([a, b, c]): about x, then y, then z */
    double a = 20 * PI / 180, b = 30 * PI / 180, c = 40 * PI / 180;
    for (int i = 0; i < 8; i++) {
        double p[3] = {i & 1 ? 10 : 0, i & 2 ? 20 : 0, i & 4 ? 30 : 0}, q[3], r[3], s[3];
        q[0] = p[0], q[1] = cos(a) * p[1] - sin(a) * p[2], q[2] = sin(a) * p[1] + cos(a) * p[2];
        r[0] = cos(b) * q[0] + sin(b) * q[2], r[1] = q[1], r[2] = -sin(b) * q[0] + cos(b) * q[2];
        s[0] = cos(c) * r[0] - sin(c) * r[1], s[1] = sin(c) * r[0] + cos(c) * r[1], s[2] = r[2];
        cr_expect(has_vertex(m, s, 1e-5), "corner %d (%g, %g, %g) missing", i, s[0], s[1], s[2]);
    }
    rayscad_mesh_free(m);
}

/* hull() of two cubes is the box spanning them (3000); of an octahedron's
 * six tips its eight faces ((4/3)·a³); mirrored, still wound outward. */
Test(own_faces, hulls_are_their_faces)
{
    rayscad_mesh *m = mesh_of("hull() { cube(10); translate([20, 0, 0]) cube(10); }", 0);
    cr_expect_eq(rayscad_mesh_triangle_count(m), 12);
    cr_expect(closed(m));
    cr_expect_float_eq(rayscad_mesh_volume(m), 3000, 3000 * 1e-6);
    rayscad_mesh_free(m);

    const char *octa = "mirror([1, 0, 0]) translate([5, 0, 0]) hull() polyhedron("
                       "[[3, 0, 0], [-3, 0, 0], [0, 3, 0], [0, -3, 0], [0, 0, 3], [0, 0, -3]],"
                       " [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],"
                       "  [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]);";
    m = mesh_of(octa, 0);
    cr_expect(closed(m));
    cr_expect_eq(rayscad_mesh_triangle_count(m), 8);
    cr_expect_float_eq(rayscad_mesh_volume(m), 36, 36 * 1e-6); /* 4/3 · 3³ */
    cr_expect(has_vertex(m, (double[3]){-8, 0, 0}, 1e-6) &&
                  has_vertex(m, (double[3]){-2, 0, 0}, 1e-6),
              "the mirrored tip");
    rayscad_mesh_free(m);
}

/* A faceted sphere alone: a closed triangulated sphere (2V - 4
 * triangles), its vertices on the sphere, a volume below the ball's by the
 * facets' share; its colour kept on every triangle. */
Test(own_faces, faceted_sphere_keeps_its_colour)
{
    rayscad_mesh *m = mesh_of("color(\"red\") sphere(5, $fn = 10);", 0);
    int nv = rayscad_mesh_vertex_count(m), nt = rayscad_mesh_triangle_count(m);
    cr_expect_eq(nv, 10 * 5); /* OpenSCAD's rings: (10 + 1) / 2 of 10 */
    cr_expect_eq(nt, 2 * nv - 4);
    cr_expect(closed(m));
    const float *v = rayscad_mesh_vertices(m);
    for (int i = 0; i < nv; i++) {
        double r =
            sqrt(v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]);
        cr_expect_float_eq(r, 5, 1e-5, "vertex %d at radius %g", i, r);
    }
    double vol = rayscad_mesh_volume(m), ball = 4.0 / 3 * PI * 125;
    cr_expect(vol < ball && vol > 0.8 * ball, "volume %g", vol);
    cr_assert_eq(rayscad_mesh_color_count(m), 1);
    const float *rgba = rayscad_mesh_colors(m);
    cr_expect(rgba[0] == 1 && rgba[1] == 0 && rgba[2] == 0);
    const uint16_t *tc = rayscad_mesh_triangle_colors(m);
    for (int i = 0; i < nt; i++)
        cr_expect_eq(tc[i], 1);
    rayscad_mesh_free(m);
}

/* Near another operand the part is contoured with it (its faces alone
 * would pass through the other's); far from it, it keeps its faces while
 * the other is contoured; contour_all contours it too. */
Test(own_faces, only_alone)
{
    const char *near = "cube(10); translate([10, 10, 10]) sphere(3);";
    rayscad_mesh *m = mesh_of(near, 0);
    cr_expect(closed(m));
    cr_expect_gt(rayscad_mesh_triangle_count(m), 12 + 100);
    /* 1000 + the sphere's seven eighths outside the cube, within the
     * simplification's few thousandths */
    double want = 1000 + 4.0 / 3 * PI * 27 * (1 - 1.0 / 8);
    cr_expect_float_eq(rayscad_mesh_volume(m), want, want * 3e-3);
    rayscad_mesh_free(m);

    m = mesh_of("cube(10); translate([100, 0, 0]) sphere(3);", 0);
    cr_expect(closed(m));
    cr_expect(has_vertex(m, (double[3]){10, 10, 10}, 1e-6));
    want = 1000 + 4.0 / 3 * PI * 27;
    cr_expect_float_eq(rayscad_mesh_volume(m), want, want * 3e-3);
    rayscad_mesh_free(m);

    m = mesh_of("sphere(5, $fn = 10);", 2);
    cr_expect(closed(m));
    cr_expect_neq(rayscad_mesh_vertex_count(m), 50, "the facets' own corners");
    rayscad_mesh_free(m);
}

/* A polyhedron alone is its own triangles where they bound its solid: an
 * L-shaped prism (its two hexagons in four triangles each, six quads in
 * two: 20), a cube with a cube-shaped void (24, 1000 - 64).  Where they do
 * not, it is contoured: two overlapping cubes written as one polyhedron
 * (their union, 1875, not the 2000 their triangles enclose twice over),
 * two nested cubes wound alike (the outer, 1000, not 1064). */
Test(own_faces, polyhedra_that_bound_their_solid)
{
    const char *lib =
        "function cpts(c, s) = [for (z = [0, 1], y = [0, 1], x = [0, 1]) c + s * [x, y, z]];"
        "function cfaces(o, inward = false) = let(f = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1],"
        "  [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]])"
        "  [for (q = f) let(g = [for (i = q) i + o]) inward ? [g[3], g[2], g[1], g[0]] : g];";
    static const struct {
        const char *body;
        int triangles; /* 0: contoured, any number */
        double volume, rel;
    } cases[] = {
        {"polyhedron([[0,0,0],[20,0,0],[20,5,0],[5,5,0],[5,15,0],[0,15,0],"
         "[0,0,8],[20,0,8],[20,5,8],[5,5,8],[5,15,8],[0,15,8]],"
         "[[5,4,3,2,1,0],[6,7,8,9,10,11],[0,1,7,6],[1,2,8,7],[2,3,9,8],[3,4,10,9],"
         "[4,5,11,10],[5,0,6,11]]);",
         20, 1200, 1e-6},
        {"polyhedron(concat(cpts([0,0,0],10), cpts([3,3,3],4)), concat(cfaces(0), cfaces(8, "
         "true)));",
         24, 936, 1e-6},
        {"polyhedron(concat(cpts([0,0,0],10), cpts([5,5,5],10)), concat(cfaces(0), cfaces(8)));", 0,
         1875, 3e-3},
        {"polyhedron(concat(cpts([0,0,0],10), cpts([3,3,3],4)), concat(cfaces(0), cfaces(8)));", 0,
         1000, 3e-3},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char src[1024];
        snprintf(src, sizeof src, "%s %s", lib, cases[i].body);
        rayscad_mesh *m = mesh_of(src, 0);
        cr_expect(closed(m), "case %zu", i);
        if (cases[i].triangles)
            cr_expect_eq(rayscad_mesh_triangle_count(m), cases[i].triangles, "case %zu", i);
        double want = cases[i].volume;
        cr_expect_float_eq(rayscad_mesh_volume(m), want, want * cases[i].rel, "case %zu: %g", i,
                           rayscad_mesh_volume(m));
        rayscad_mesh_free(m);
    }
}

/* A twisted extrusion with a hole, or of an outline that turns both ways:
 * its caps cut into triangles (src/geom/earcut.c) so that the mesh bounds
 * its solid, and it is its own faces: the sides' 2 per quad per slice and
 * n + 2h - 2 a cap, enclosing the volume the rays measure (to rounding:
 * plane faces). */
Test(own_faces, twisted_extrusions_with_holes)
{
    static const struct {
        const char *src;
        int triangles;
    } cases[] = {
        {"linear_extrude(height = 6, twist = 60, slices = 2) difference() {"
         " square([12, 8], center = true); square([4, 4], center = true); }",
         (4 + 4) * 2 * 2 + 2 * (8 + 2 - 2)},
        {"linear_extrude(height = 5, twist = 30, slices = 3, scale = 0.5)"
         " polygon([[0, 0], [10, 0], [10, 6], [6, 6], [6, 2], [4, 2], [4, 6], [0, 6]]);",
         8 * 3 * 2 + 2 * (8 - 2)},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        rayscad_mesh *m = mesh_of(cases[i].src, 0);
        cr_expect(closed(m), "case %zu", i);
        cr_expect_eq(rayscad_mesh_triangle_count(m), cases[i].triangles, "case %zu", i);
        rayscad_scene *scene = scene_of(cases[i].src, NULL);
        rayscad_measure_options o;
        rayscad_measure_options_default(&o);
        rayscad_measurement x;
        char err[256];
        cr_assert_eq(rayscad_scene_measure(scene, &o, &x, err, sizeof err), RAYSCAD_OK, "%s", err);
        cr_expect_float_eq(rayscad_mesh_volume(m), x.volume, 1e-6 * x.volume,
                           "case %zu: mesh %.9g, rays %.9g", i, rayscad_mesh_volume(m), x.volume);
        rayscad_scene_free(scene);
        rayscad_mesh_free(m);
    }
}

/* A linear_extrude of one polygon alone is a prism, written as its own
 * faces: the caps cut by ear clipping, each edge a quad.  A concave
 * pentagon (100 less the notch's 35, 4 high: 260; caps 3 triangles, sides
 * 5 quads: 16), a square with a square hole given as paths (84 · 2.5; caps
 * 8 + 2 - 2 each, sides 8 quads: 32); every vertex a corner of the
 * outline at z = 0 or the height. */
Test(own_faces, prisms_are_their_faces)
{
    static const struct {
        const char *src;
        int triangles;
        double volume, height;
        double corners[8][2];
        int ncorners;
    } cases[] = {
        {"linear_extrude(4) polygon([[0, 0], [10, 0], [10, 10], [5, 3], [0, 10]]);",
         16,
         260,
         4,
         {{0, 0}, {10, 0}, {10, 10}, {5, 3}, {0, 10}},
         5},
        {"linear_extrude(2.5) polygon([[0, 0], [10, 0], [10, 10], [0, 10], [3, 3], [3, 7], [7, 7],"
         " [7, 3]], [[0, 1, 2, 3], [4, 5, 6, 7]]);",
         32,
         84 * 2.5,
         2.5,
         {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {3, 3}, {3, 7}, {7, 7}, {7, 3}},
         8},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        rayscad_mesh *m = mesh_of(cases[i].src, 0);
        cr_expect(closed(m), "case %zu", i);
        cr_expect_eq(rayscad_mesh_triangle_count(m), cases[i].triangles, "case %zu", i);
        cr_expect_eq(rayscad_mesh_vertex_count(m), 2 * cases[i].ncorners, "case %zu", i);
        cr_expect_float_eq(rayscad_mesh_volume(m), cases[i].volume, 1e-9 * cases[i].volume,
                           "case %zu: %.12g", i, rayscad_mesh_volume(m));
        for (int k = 0; k < cases[i].ncorners; k++)
            for (int top = 0; top < 2; top++) {
                double p[3] = {cases[i].corners[k][0], cases[i].corners[k][1],
                               top ? cases[i].height : 0};
                cr_expect(has_vertex(m, p, 1e-9), "case %zu: corner (%g, %g, %g)", i, p[0], p[1],
                          p[2]);
            }
        rayscad_mesh_free(m);
    }
}

/* The centre of triangle i of m, in doubles. */
static void centroid(const rayscad_mesh *m, int i, double c[3])
{
    const float *v = rayscad_mesh_vertices(m);
    const int32_t *t = rayscad_mesh_triangles(m);
    for (int a = 0; a < 3; a++)
        c[a] = 0;
    for (int k = 0; k < 3; k++)
        for (int a = 0; a < 3; a++)
            c[a] += (double)v[3 * t[3 * i + k] + a] / 3;
}

/* A part whose every primitive is plane-faced is the exact boundary of its
 * booleans (src/mesh/polyhedral.c), its flat faces cut from their
 * outlines: a box with a square hole through it (16 corners, 32
 * triangles, 1000 - 160), two overlapping cubes (1875, their corners and
 * the six where their faces cross), a cube cut by a turned one (an
 * octagonal prism: 16 corners, 28 triangles, 10 · 100 (2√2 - 2)), a plate
 * with a hundred holes in rows and columns. */
Test(own_faces, plane_faced_booleans)
{
    static const struct {
        const char *src;
        int vertices, triangles;
        double volume;
    } cases[] = {
        {"difference() { cube(10); translate([3, 3, -1]) cube([4, 4, 12]); }", 16, 32, 840},
        {"cube(10); translate([5, 5, 5]) cube(10);", 20, 36, 1875},
        {"intersection() { cube(10, center = true); rotate([0, 0, 45]) cube(10, center = true); }",
         16, 28, 1000 * (2 * 1.41421356237309505 - 2)},
        /* a plate with a 10 × 10 grid of square holes: 4 + 400 corners a
         * side; each side 404 + 200 - 2 triangles, 404 walls two each */
        {"difference() { cube([100, 100, 10]); for (i = [0:9], j = [0:9])"
         " translate([i * 10 + 3, j * 10 + 3, -1]) cube([4, 4, 12]); }",
         808, 2 * 602 + 2 * 404, 100000 - 100 * 160},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        rayscad_mesh *m = mesh_of(cases[i].src, 0);
        cr_expect(closed(m), "case %zu", i);
        cr_expect_eq(rayscad_mesh_vertex_count(m), cases[i].vertices, "case %zu", i);
        cr_expect_eq(rayscad_mesh_triangle_count(m), cases[i].triangles, "case %zu", i);
        cr_expect_float_eq(rayscad_mesh_volume(m), cases[i].volume, 1e-6 * cases[i].volume,
                           "case %zu: %.12g", i, rayscad_mesh_volume(m));
        rayscad_mesh_free(m);
    }
    /* two colours: exact too, each triangle of its cube's colour (the
     * red one's faces: a coordinate 0 or 10, all within [0, 10]), faces of
     * two colours not merged (each cube's outside corner has three faces
     * of two triangles; the six where their faces cross four each) */
    rayscad_mesh *two =
        mesh_of("color(\"red\") cube(10); color(\"blue\") translate([5, 5, 5]) cube(10);", 0);
    cr_expect(closed(two));
    cr_expect_float_eq(rayscad_mesh_volume(two), 1875, 1875 * 1e-9);
    cr_assert_eq(rayscad_mesh_color_count(two), 2);
    cr_expect_eq(rayscad_mesh_triangle_count(two), 36);
    const float *pal = rayscad_mesh_colors(two);
    const uint16_t *tc = rayscad_mesh_triangle_colors(two);
    for (int i = 0; i < rayscad_mesh_triangle_count(two); i++) {
        double c[3];
        centroid(two, i, c);
        int on_red = 1, face = 0;
        for (int a = 0; a < 3; a++) {
            on_red &= c[a] >= -1e-9 && c[a] <= 10 + 1e-9;
            face |= fabs(c[a]) < 1e-9 || fabs(c[a] - 10) < 1e-9;
        }
        cr_assert(tc[i] >= 1);
        const float *rgba = pal + 4 * (tc[i] - 1);
        int red = rgba[0] > 0.5f && rgba[2] < 0.5f;
        cr_expect_eq(red, on_red && face, "triangle %d at (%g, %g, %g)", i, c[0], c[1], c[2]);
    }
    rayscad_mesh_free(two);
    /* a difference's cut faces take the colour of what cut them: the
     * hole's four walls (x or y 3 or 7) blue, the rest red */
    rayscad_mesh *cut = mesh_of("difference() { color(\"red\") cube(10);"
                                " color(\"blue\") translate([3, 3, -1]) cube([4, 4, 12]); }",
                                0);
    cr_assert_eq(rayscad_mesh_color_count(cut), 2);
    cr_expect_eq(rayscad_mesh_triangle_count(cut), 32);
    pal = rayscad_mesh_colors(cut);
    tc = rayscad_mesh_triangle_colors(cut);
    for (int i = 0; i < rayscad_mesh_triangle_count(cut); i++) {
        double c[3];
        centroid(cut, i, c);
        int wall = 0;
        for (int a = 0; a < 2; a++)
            wall |=
                (fabs(c[a] - 3) < 1e-9 || fabs(c[a] - 7) < 1e-9) && c[1 - a] > 3 && c[1 - a] < 7;
        cr_assert(tc[i] >= 1);
        int blue = pal[4 * (tc[i] - 1) + 2] > 0.5f && pal[4 * (tc[i] - 1)] < 0.5f;
        cr_expect_eq(blue, wall, "triangle %d at (%g, %g, %g)", i, c[0], c[1], c[2]);
    }
    rayscad_mesh_free(cut);
    /* the overlapping cubes' corners: each coordinate 0, 5, 10 or 15 */
    rayscad_mesh *m = mesh_of(cases[1].src, 0);
    const float *v = rayscad_mesh_vertices(m);
    for (int i = 0; i < 3 * rayscad_mesh_vertex_count(m); i++)
        cr_expect(v[i] == 0 || v[i] == 5 || v[i] == 10 || v[i] == 15, "coordinate %g", v[i]);
    rayscad_mesh_free(m);
}

static int cmp_vertex(const void *a, const void *b)
{
    const float *x = a, *y = b;
    for (int k = 0; k < 3; k++)
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    return 0;
}

/* Whether no two vertices of m are at one position (a reader that welds
 * by position sees the same manifold). */
static int apart_as_floats(const rayscad_mesh *m)
{
    int nv = rayscad_mesh_vertex_count(m);
    float *v = malloc(3 * (size_t)nv * sizeof *v);
    cr_assert(v);
    memcpy(v, rayscad_mesh_vertices(m), 3 * (size_t)nv * sizeof *v);
    qsort(v, (size_t)nv, 3 * sizeof *v, cmp_vertex);
    int ok = 1;
    for (int i = 1; i < nv && ok; i++)
        ok = cmp_vertex(v + 3 * (i - 1), v + 3 * i) != 0;
    free(v);
    return ok;
}

/* Plane-faced solids that touch along an edge or at a corner (the exact
 * union has four faces at the edge: no 2-manifold) are still their own
 * faces, each cube's corners its own and moved a hair (1e-5 of the size)
 * into it: two cubes along an edge, at a corner, a checkerboard of eight,
 * and an L of plates whose walls meet along an edge that ends on the floor
 * (highlight-modifier2.scad's, 10 times smaller).  Volumes to 2e-4: the
 * faces about a moved corner tilt by the gap over their size. */
Test(own_faces, touching_solids_kept_apart)
{
    static const struct {
        const char *src;
        int vertices, triangles;
        double volume;
    } cases[] = {
        {"cube(1); translate([1, 1, 0]) cube(1);", 16, 24, 2},
        {"cube(1); translate([1, 1, 1]) cube(1);", 16, 24, 2},
        {"for (i = [0:3], j = [0:3]) if ((i + j) % 2 == 0) translate([i, j, 0]) cube(1);", 64, 96,
         8},
        {"cube([7, 5, 0.2]); translate([7, 0, 0]) cube([0.2, 5, 3]);"
         " translate([0, 5, 0]) cube([7, 0.2, 3]);",
         -1, -1, 14.2},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        rayscad_mesh *m = mesh_of(cases[i].src, 0);
        cr_expect(closed(m), "case %zu", i);
        cr_expect(apart_as_floats(m), "case %zu", i);
        if (cases[i].vertices >= 0) {
            cr_expect_eq(rayscad_mesh_vertex_count(m), cases[i].vertices, "case %zu", i);
            cr_expect_eq(rayscad_mesh_triangle_count(m), cases[i].triangles, "case %zu", i);
        } else { /* the exact faces, not a contour of thousands */
            cr_expect_lt(rayscad_mesh_triangle_count(m), 100, "case %zu", i);
        }
        cr_expect_float_eq(rayscad_mesh_volume(m), cases[i].volume, 2e-4 * cases[i].volume,
                           "case %zu: %.12g", i, rayscad_mesh_volume(m));
        rayscad_mesh_free(m);
    }
}

/* Where the parts are too many for grids of their own (thirty faceted
 * balls and a sphere: one grid), the plane-faced clusters of operands are
 * still exact (src/mesh/clusters.c): each ball's corners and triangles are
 * those of the ball meshed alone (its own faces, exact_faces.c), which a
 * contour does not give, and the sphere alone is contoured; the volume
 * within the sphere's simplification. */
Test(own_faces, plane_faced_clusters_beside_a_curved_one)
{
    rayscad_mesh *ball = mesh_of("sphere(1, $fn = 8);", 0);
    int bv = rayscad_mesh_vertex_count(ball), bt = rayscad_mesh_triangle_count(ball);
    double bvol = rayscad_mesh_volume(ball);
    rayscad_mesh *m =
        mesh_of("sphere(5); for (i = [0:29])"
                " translate([8 + (i % 6) * 4, floor(i / 6) * 4, 0]) sphere(1, $fn = 8);",
                0);
    cr_expect(closed(m));
    const float *b = rayscad_mesh_vertices(ball);
    for (int i = 0; i < 30; i++)
        for (int c = 0; c < bv; c++) {
            double p[3] = {8 + (i % 6) * 4 + b[3 * c], (i / 6) * 4 + b[3 * c + 1], b[3 * c + 2]};
            cr_expect(has_vertex(m, p, 1e-6), "ball %d corner (%g, %g, %g)", i, p[0], p[1], p[2]);
        }
    /* the balls' triangles: those whose corners all lie in x >= 6 */
    const float *v = rayscad_mesh_vertices(m);
    const int32_t *t = rayscad_mesh_triangles(m);
    int balls = 0;
    for (int i = 0; i < rayscad_mesh_triangle_count(m); i++)
        balls += v[3 * t[3 * i]] >= 6 && v[3 * t[3 * i + 1]] >= 6 && v[3 * t[3 * i + 2]] >= 6;
    cr_expect_eq(balls, 30 * bt);
    double exact = 30 * bvol + 4.0 / 3 * PI * 125;
    cr_expect_float_eq(rayscad_mesh_volume(m), exact, 3e-3 * exact, "%.9g", rayscad_mesh_volume(m));
    rayscad_mesh_free(m);
    rayscad_mesh_free(ball);
}

/* surface() of a 7 × 6 heightmap, alone: its triangles (each cell four to
 * its centre at the corners' mean height, a bottom of many corners along
 * straight edges that the ray queries cut by halving, some without area)
 * mended as a plane-faced part's: closed, and its volume the closed form,
 * each cell's mean corner height over the base (0 here), to rounding. */
Test(own_faces, heightmap_alone_is_exact)
{
    enum { W = 7, H = 6 };
    double z[H][W], volume = 0;
    char path[] = "/tmp/rayscad_heightmap_XXXXXX";
    int fd = mkstemp(path);
    cr_assert(fd >= 0);
    FILE *f = fdopen(fd, "w");
    cr_assert(f);
    for (int i = 0; i < H; i++) {
        for (int j = 0; j < W; j++) {
            z[i][j] = 1 + 0.5 * ((i * 7 + j * 3) % 5);
            fprintf(f, "%g ", z[i][j]);
        }
        fprintf(f, "\n");
    }
    fclose(f);
    for (int i = 1; i < H; i++)
        for (int j = 1; j < W; j++)
            volume += (z[i - 1][j - 1] + z[i - 1][j] + z[i][j - 1] + z[i][j]) / 4;
    char src[128];
    snprintf(src, sizeof src, "surface(\"%s\");", path);
    rayscad_mesh *m = mesh_of(src, 0);
    remove(path);
    cr_expect(closed(m));
    cr_expect_float_eq(rayscad_mesh_volume(m), volume, 1e-9 * volume, "%.12g of %.12g",
                       rayscad_mesh_volume(m), volume);
    rayscad_mesh_free(m);
}

/* A polyhedron whose faces have corners along straight edges (as surface()
 * writes its bottom): its triangles, cut from each face by halving (the
 * ray queries' own), include some without area, so it is no boundary as
 * given; alone in its part it is mended (corners along straight edges
 * where two faces meet dropped, faces re-cut): a 3 × 3 × 3 box, 12
 * triangles on its 8 corners, 27 to rounding. */
Test(own_faces, polyhedron_with_corners_along_edges)
{
    rayscad_mesh *m = mesh_of("polyhedron(points = [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0],"
                              " [3, 3, 0], [0, 3, 0], [0, 0, 3], [3, 0, 3], [3, 3, 3], [0, 3, 3]],"
                              " faces = [[0, 5, 4, 3, 2, 1], [6, 7, 8, 9], [0, 1, 2, 3, 7, 6],"
                              " [3, 4, 8, 7], [4, 5, 9, 8], [5, 0, 6, 9]]);",
                              0);
    cr_expect(closed(m));
    cr_expect_eq(rayscad_mesh_triangle_count(m), 12);
    cr_expect_eq(rayscad_mesh_vertex_count(m), 8);
    cr_expect_float_eq(rayscad_mesh_volume(m), 27, 27e-12, "%.15g", rayscad_mesh_volume(m));
    for (int c = 0; c < 8; c++) {
        double p[3] = {3.0 * (c & 1), 1.5 * (c & 2), 0.75 * (c & 4)};
        cr_expect(has_vertex(m, p, 1e-12), "corner (%g, %g, %g)", p[0], p[1], p[2]);
    }
    rayscad_mesh_free(m);
}
