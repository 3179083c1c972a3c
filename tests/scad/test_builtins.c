/*
 * test_builtins.c — geometry builtins with closed forms: twisted and scaled
 * linear_extrude (volumes, points against the inverse map), surface()
 * against OpenSCAD's volumes, import() round trips and warnings, resize();
 * volumes by ray sampling of the scene each source evaluates to.
 */
/*
 * test_geometry.c — the shapes with shared data (polytope, hull, mesh,
 * prism, revolve): their interval lists along random lines against an
 * independent point classifier, watertightness on lines through vertices and
 * edges, and reference counting.  Property tests print their seed.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "../../src/intervals/intervals.h"
#include "../../src/io/io.h"
#include "../../src/geom/hull3d.h"
#include "../../src/geom/hull3d_internal.h"
#include "../../src/scad/scad.h"
#include "../services.h"
#include "../scad_support.h"
#include "../shape_check.h"

#define PI 3.14159265358979323846

/* ---- geometry built by the language: twisted extrusion, surface, import,
 * resize — through scad_eval_string and a committed scene ---------------------- */

/* The model of src as a scene; messages into m. */
static csg_scene *scene_of(const char *src, msgs *m)
{
    return scene_as("t.scad", src, m);
}

/* 1 when p is inside root 0 (a vertical ray through it). */
static int scene_contains(const csg_scene *s, const double p[3])
{
    iv_arena_reset(arena);
    iv_list l;
    double o[3] = {p[0], p[1], -1000};
    cr_assert_eq(csg_trace(s, 0, o, (double[3]){0, 0, 1}, 0, INFINITY, arena, &l), 0);
    return iv_list_contains(&l, p[2] + 1000);
}

/* Inside the twisted, scaled square: p's shadow turned back by the twist at
 * its height and scaled back lies in the square; points within `margin` of
 * the boundary are no test (OpenSCAD's flat slices lie within it). */
typedef struct twist_case {
    double h, twist, s1, half, margin;
} twist_case;

static int twist_classify(const double p[3], const twist_case *c, int *sure)
{
    *sure = 0;
    if (p[2] < 0 || p[2] > c->h) {
        *sure = fabs(p[2] - (p[2] < 0 ? 0 : c->h)) > c->margin;
        return 0;
    }
    double f = p[2] / c->h, a = c->twist * f * PI / 180, sc = 1 - (1 - c->s1) * f;
    /* the extrusion turns by -twist·f; undo it */
    double x = (cos(a) * p[0] - sin(a) * p[1]) / sc, y = (sin(a) * p[0] + cos(a) * p[1]) / sc;
    double d = fmin(c->half - fabs(x), c->half - fabs(y)) * sc;
    *sure = fabs(d) > c->margin && fabs(p[2]) > c->margin && fabs(p[2] - c->h) > c->margin;
    return d > 0;
}

/* Scene bounds are padded a little for the tracer. */
static int bounds_near(double x, double want)
{
    return fabs(x - want) < 1e-3 * (1 + fabs(want));
}

Test(linear_extrude, twisted_square_volume_is_the_prism_volume, .init = arena_setup,
     .fini = arena_teardown)
{
    msgs m = {""};
    csg_scene *s = scene_of(
        "linear_extrude(height = 20, twist = 90, slices = 40) square(10, center = true);", &m);
    /* the twisted solid has the untwisted volume, 2000; OpenSCAD's slices
     * split each twisted quad along its shorter diagonal, which bulges out:
     * its own mesh (openscad -o x.off, 2021.01) holds 2025.659 */
    double v = traced_volume(s, 300);
    cr_expect(fabs(v - 2025.659) < 0.001 * 2025.659, "volume %g", v);
    cr_expect(fabs(v - 2000) < 0.015 * 2000, "volume %g", v);
    cr_expect_str_empty(m.text);
    csg_scene_free(s);
}

Test(linear_extrude, scaled_frustum_and_pyramid_volumes, .init = arena_setup,
     .fini = arena_teardown)
{
    msgs m = {""};
    /* uniform scale alone: one slice, planar faces, a frustum h·A·(1+s+s²)/3 */
    csg_scene *s = scene_of("linear_extrude(12, scale = 0.5) square(10, center = true);", &m);
    double v = traced_volume(s, 300);
    cr_expect(fabs(v - 12 * 100 * 1.75 / 3) < 0.003 * 700, "frustum %g", v);
    csg_scene_free(s);
    /* scale 0: a pyramid, h·A/3, closed at its apex */
    s = scene_of("linear_extrude(9, scale = 0) square(10, center = true);", &m);
    v = traced_volume(s, 300);
    cr_expect(fabs(v - 300) < 0.003 * 300, "pyramid %g", v);
    csg_scene_free(s);
    cr_expect_str_empty(m.text);
}

Test(linear_extrude, twisted_points_against_the_inverse_map, .init = arena_setup,
     .fini = arena_teardown)
{
    msgs m = {""};
    csg_scene *s = scene_of("linear_extrude(height = 16, twist = -120, scale = 0.6, slices = 48)"
                            " square(12, center = true);",
                            &m);
    twist_case c = {16, -120, 0.6, 6, 0.08};
    rng_state = 42;
    int bad = 0, tested = 0;
    for (int i = 0; i < 4000; i++) {
        double p[3] = {rng_uniform(-9, 9), rng_uniform(-9, 9), rng_uniform(-2, 18)};
        int certain;
        int want = twist_classify(p, &c, &certain);
        if (!certain) continue;
        tested++;
        if (want != scene_contains(s, p)) {
            if (bad < 5) cr_log_warn("seed 42 p %g %g %g: want %d", p[0], p[1], p[2], want);
            bad++;
        }
    }
    cr_expect(tested > 3000);
    cr_expect_eq(bad, 0);
    csg_scene_free(s);
}

Test(linear_extrude, twist_with_a_hole_and_off_centre_disc, .init = arena_setup,
     .fini = arena_teardown)
{
    msgs m = {""};
    /* the hole stays empty along its twisted axis; the disc is OpenSCAD's
     * 24-gon swept around the axis (its centre line inside, the axis not) */
    csg_scene *s = scene_of("linear_extrude(10, twist = 180, $fn = 24) difference() {"
                            "  square(12, center = true); circle(3); }"
                            "translate([0, 0, 20]) linear_extrude(10, twist = 90, $fn = 24)"
                            "  translate([5, 0]) circle(2);",
                            &m);
    cr_expect(!scene_contains(s, (double[3]){0, 0, 5}));
    cr_expect(scene_contains(s, (double[3]){5, 5, 0.5}));
    cr_expect(!scene_contains(s, (double[3]){0, 0, 25}));
    for (int k = 0; k <= 10; k++) {
        double z = 20 + k, a = -90.0 * k / 10 * PI / 180;
        cr_expect(scene_contains(s, (double[3]){5 * cos(a), 5 * sin(a), z - (k == 10) * 1e-6}),
                  "k %d", k);
    }
    csg_scene_free(s);
}

Test(surface, dat_and_png_volumes_match_openscad, .init = arena_setup, .fini = arena_teardown)
{
    msgs m = {""};
    /* volumes of `openscad -o x.off` of the same calls (2021.01): 115.5 and
     * 2029.34 (bottoms at min(0, lowest - 1)) */
    csg_scene *s = scene_of("surface(\"tests/models/data/surface.dat\", center = true);", &m);
    double v = traced_volume(s, 400);
    cr_expect(fabs(v - 115.5) < 0.002 * 115.5, "dat %g", v);
    csg_scene_free(s);
    s = scene_of("surface(\"tests/models/data/surface.png\");", &m);
    v = traced_volume(s, 400);
    cr_expect(fabs(v - 2029.34) < 0.002 * 2029.34, "png %g", v);
    csg_scene_free(s);
    cr_expect_str_empty(m.text);
}

Test(import, stl_and_one_line_off_round_trip, .init = arena_setup, .fini = arena_teardown)
{
    char dir[] = "/tmp/rayscad-test-XXXXXX";
    cr_assert(mkdtemp(dir));
    char stl[256], off[256], src[1024];
    snprintf(stl, sizeof stl, "%s/box.stl", dir);
    snprintf(off, sizeof off, "%s/box.off", dir);
    /* the STL: written by io_mesh_write from a plain box (volume 24) */
    const float bv[8][3] = {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0},
                            {0, 0, 2}, {4, 0, 2}, {4, 3, 2}, {0, 3, 2}};
    const int32_t bt[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                               {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    char err[256];
    cr_assert_eq(io_mesh_write(stl, &bv[0][0], 8, &bt[0][0], 12, 0, NULL, err, sizeof err), 0, "%s",
                 err);
    /* the OFF as OpenSCAD writes it: counts on the header line */
    FILE *f = fopen(off, "w");
    cr_assert(f);
    fprintf(f, "OFF 8 12 0\n");
    for (int i = 0; i < 8; i++)
        fprintf(f, "%g %g %g \n", bv[i][0], bv[i][1], bv[i][2]);
    for (int i = 0; i < 12; i++)
        fprintf(f, "3 %d %d %d\n", bt[i][0], bt[i][1], bt[i][2]);
    fclose(f);
    msgs m = {""};
    snprintf(src, sizeof src,
             "import(\"%s\"); translate([10, 0, 0]) import(\"%s\", convexity = 2);", stl, off);
    csg_scene *s = scene_of(src, &m);
    cr_expect_str_empty(m.text);
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    cr_expect(fabs(lo[0]) < 1e-3 && fabs(hi[0] - 14) < 1e-3 && fabs(hi[2] - 2) < 1e-3);
    double vol = traced_volume(s, 280);
    cr_expect(fabs(vol - 48) < 0.01 * 48, "volume %g", vol);
    cr_expect(scene_contains(s, (double[3]){12, 1.5, 1}));
    cr_expect(!scene_contains(s, (double[3]){7, 1.5, 1}));
    csg_scene_free(s);
    remove(stl);
    remove(off);
    rmdir(dir);
}

Test(import, missing_and_unsupported_files_warn, .init = arena_setup, .fini = arena_teardown)
{
    msgs m = {""};
    scad_options o;
    memset(&o, 0, sizeof o);
    o.message = on_msg;
    o.ud = &m;
    o.services = test_services();
    scad_result r;
    cr_assert_eq(scad_eval_string("t.scad",
                                  "import(\"nowhere.stl\");\nimport(\"a.svg\");\n"
                                  "surface(\"nowhere.dat\");\nimport(\"x.abc\");",
                                  &o, &r),
                 0);
    cr_expect_str_eq(m.text,
                     "WARNING: Can't open import file 'nowhere.stl' in file t.scad, line 1\n"
                     "t.scad:2:1: note: import(): Can't open file 'a.svg': nothing imported\n"
                     "WARNING: The file 'nowhere.dat' couldn't be opened. in file t.scad, line 3\n"
                     "WARNING: Unsupported file format while trying to import file "
                     "'\"x.abc\"' in file t.scad, line 4\n");
    cr_expect(!r.model || csg_node_child_count(r.model) == 0);
    scad_result_free(&r);
}

Test(import, amf_and_3mf_warnings_as_openscad_words_them, .init = arena_setup,
     .fini = arena_teardown)
{
    msgs m = {""};
    scad_options o;
    memset(&o, 0, sizeof o);
    o.message = on_msg;
    o.ud = &m;
    o.services = test_services();
    scad_result r;
    cr_assert_eq(scad_eval_string("t.scad",
                                  "import(\"tests/hostile/data/zip_two_entries.amf\");\n"
                                  "import(\"nowhere.3mf\");\n"
                                  "  import(\"tests/hostile/data/no_triangles.amf\");\n"
                                  "import(\"tests/hostile/data/second_object_broken.amf\");",
                                  &o, &r),
                 0);
    cr_expect_str_eq(m.text,
                     "WARNING: Can't read file 'zip_two_entries.amf' from zipped AMF "
                     "'tests/hostile/data/zip_two_entries.amf' in file t.scad, line 1\n"
                     "WARNING: Can't open import file 'tests/hostile/data/zip_two_entries.amf' "
                     "in file t.scad, line 1\n"
                     "WARNING: Could not read file 'nowhere.3mf' in file t.scad, line 2\n"
                     "WARNING: Failed to parse file 'tests/hostile/data/second_object_broken.amf': "
                     "line 20: <v3> 'x' is not an index in file t.scad, line 4\n");
    /* the complete first object of the last file is drawn */
    cr_expect_not_null(r.model);
    scad_result_free(&r);
}

Test(resize, box_auto_and_2d, .init = arena_setup, .fini = arena_teardown)
{
    msgs m = {""};
    double lo[3], hi[3];
    csg_scene *s = scene_of("resize([30, 10, 5]) translate([1, 1, 1]) cube(2);", &m);
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    /* scaled about the origin: [1,3] → [15,45] in x */
    cr_expect(bounds_near(lo[0], 15) && bounds_near(hi[0], 45), "%g %g", lo[0], hi[0]);
    cr_expect(bounds_near(hi[1], 15) && bounds_near(hi[2], 7.5));
    csg_scene_free(s);
    /* auto: y follows x's scale (2), z keeps its size */
    s = scene_of("resize([8, 0, 0], auto = [0, 1, 0]) cube([4, 3, 2]);", &m);
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    cr_expect(bounds_near(hi[0], 8) && bounds_near(hi[1], 6) && bounds_near(hi[2], 2));
    csg_scene_free(s);
    /* 2D: x and y only, the preview slab stays 1 thick */
    s = scene_of("resize([10, 4]) square([5, 1]);", &m);
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    cr_expect(bounds_near(hi[0], 10) && bounds_near(hi[1], 4) && bounds_near(hi[2], 0.5));
    csg_scene_free(s);
    cr_expect_str_empty(m.text);
}
