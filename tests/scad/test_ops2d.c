/*
 * test_ops2d.c — offset(), projection(), minkowski() and text() against
 * closed forms: for whole .scad sources the area of a 2D result (the volume
 * of its 1 mm preview slab) or the volume of a 3D one measured by ray
 * sampling (mesh.h), each within the stated tessellation or sampling error.
 * Error messages are checked by their file:line:col.
 */
/*
 * test_geometry2d.c — offset(), projection(), minkowski() and text()
 * against closed forms: polygon areas by the shoelace formula for the
 * Clipper adapter (io/polygon.h), and for whole .scad sources the area of a
 * 2D result (the volume of its 1 mm preview slab) or the volume of a 3D one
 * measured by ray sampling (mesh.h), each within the stated tessellation
 * or sampling error.  Error messages are checked by their file:line:col.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/io/polygon.h"
#include "../../src/io/text.h"
#include "../../src/mesh/mesh.h"
#include "../../src/scad/scad.h"
#include "../services.h"

#define PI 3.14159265358979323846

/* ---- helpers ------------------------------------------------------------------------ */

static char msgs[4096];

static void on_msg(void *ud, scad_msg_kind k, const char *line)
{
    (void)ud;
    (void)k;
    strncat(msgs, line, sizeof msgs - strlen(msgs) - 2);
    strcat(msgs, "\n");
}

/* The scene of src (cr_assert on failure). */
static csg_scene *scene_of(const char *src)
{
    msgs[0] = 0;
    scad_options o = {0};
    o.services = test_services();
    o.message = on_msg;
    scad_result r;
    cr_assert_eq(scad_eval_string("t.scad", src, &o, &r), 0, "%s\n%s", src, msgs);
    csg_node *roots[1] = {r.model};
    r.model = NULL;
    scad_result_free(&r);
    char err[256];
    csg_scene *s = csg_scene_new(roots, 1, err, sizeof err);
    cr_assert(s, "%s", err);
    return s;
}

/* Volume of src's model (for a 2D result: its area, the slab being 1 mm
 * thick), by ray sampling at 1/cells of the longest side. */
static double volume_of(const char *src, int cells)
{
    csg_scene *s = scene_of(src);
    mesh_options o;
    mesh_options_default(&o);
    o.cells_per_side = cells;
    o.threads = 1;
    mesh_measure m;
    char err[256];
    cr_assert_eq(mesh_measure_scene(s, &o, &m, err, sizeof err), 0, "%s", err);
    csg_scene_free(s);
    return m.volume;
}

/* ---- the modules -------------------------------------------------------------------- */

Test(offset, round_square_area)
{
    double a = volume_of("offset(r = 2, $fn = 64) square(10);", 512);
    double exact = 100 + 80 + PI * 4;
    cr_assert(fabs(a - exact) < 0.01 * exact, "area %f, exact %f", a, exact);
}

Test(offset, delta_square_and_negative_delta)
{
    double a = volume_of("offset(delta = 2) square(10, center = true);", 512);
    cr_assert(fabs(a - 196) < 0.01 * 196, "area %f", a);
    a = volume_of("offset(delta = -2) square(10, center = true);", 512);
    cr_assert(fabs(a - 36) < 0.01 * 36, "area %f", a);
}

Test(offset, follows_the_transform_outside_it)
{
    /* offset in a scaled frame: the scale applies after the offset */
    csg_scene *s = scene_of("scale([2, 1]) offset(delta = 1) square(10);");
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    cr_assert(fabs(lo[0] + 2) < 1e-6 && fabs(hi[0] - 22) < 1e-6, "x %f .. %f", lo[0], hi[0]);
    cr_assert(fabs(lo[1] + 1) < 1e-6 && fabs(hi[1] - 11) < 1e-6, "y %f .. %f", lo[1], hi[1]);
    csg_scene_free(s);
}

Test(offset, of_a_difference_keeps_the_hole)
{
    double a = volume_of("offset(delta = 1) difference() { square(20, center = true); "
                         "square(10, center = true); }",
                         512);
    cr_assert(fabs(a - (22 * 22 - 8 * 8)) < 0.01 * 420, "area %f", a);
}

Test(offset, many_parts_keep_their_holes)
{
    /* 100 framed squares: a set of 200 paths becomes a union of parts cut
     * where no path spans across in x (geom2d.c), each frame's hole in its
     * part: 100 · (2.2² - 0.8²) */
    double a = volume_of("offset(delta = 0.1) for (i = [0:99]) translate([3 * i, 0])\n"
                         "    difference() { square(2); translate([0.5, 0.5]) square(1); }",
                         3000);
    cr_expect(fabs(a - 420) < 0.01 * 420, "area %f", a);
}

Test(projection, sphere_shadow_is_a_disc)
{
    double a = volume_of("projection() sphere(5);", 512);
    cr_assert(fabs(a - PI * 25) < 0.015 * PI * 25, "area %f", a);
}

Test(projection, cut_of_a_sphere_off_centre)
{
    /* z = 0 cuts a sphere of radius 5 centred at z = 3 in a disc of
     * radius 4 */
    double a = volume_of("projection(cut = true) translate([0, 0, 3]) sphere(5);", 512);
    cr_assert(fabs(a - PI * 16) < 0.01 * PI * 16, "area %f", a);
}

Test(projection, cut_misses_is_empty)
{
    csg_scene *s = scene_of("projection(cut = true) translate([0, 0, 10]) cube(2);");
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), -1);
    csg_scene_free(s);
}

Test(minkowski, cube_and_sphere_volume)
{
    /* cube s ⊕ ball r: s³ + 6 s² r + 3 π s r² + 4/3 π r³; the ball is
     * OpenSCAD's 64-gon tessellation, inside the ball by at most
     * r (1 − cos(π/32))² ≈ 0.5 % of its radius in each direction */
    double s = 10, r = 2;
    double exact = s * s * s + 6 * s * s * r + 3 * PI * s * r * r + 4.0 / 3 * PI * r * r * r;
    double v = volume_of("minkowski() { cube(10); sphere(2, $fn = 64); }", 256);
    cr_assert(v < exact * 1.003 && v > exact * 0.99, "volume %f, exact %f", v, exact);
}

Test(minkowski, distributes_over_union)
{
    /* two unit-separated cubes ⊕ a cube: two 4-cubes that touch */
    double v = volume_of("minkowski() { union() { cube(2); translate([4, 0, 0]) cube(2); } "
                         "cube(2, center = true); }",
                         256);
    cr_assert(fabs(v - (8 * 4 * 4)) < 0.01 * 128, "volume %f", v);
}

Test(minkowski, two_2d_squares)
{
    double a = volume_of("minkowski() { square(10); square(3); }", 512);
    cr_assert(fabs(a - 169) < 0.01 * 169, "area %f", a);
}

/* A difference is summed through its boundary: ([0,4]³ minus the corner
 * [0,2)³) ⊕ [0,1]³ is [0,5]³ minus [0,2)³, a point being reached when
 * [x-1, x]³ meets the solid (closed form 125 - 8). */
Test(minkowski, of_a_difference)
{
    double v = volume_of("minkowski() { difference() { cube(4); cube(2); } cube(1); }", 256);
    cr_assert(fabs(v - 117) < 0.005 * 117, "volume %f, exact 117", v);
    /* and of a revolve (a ring of square section) with a cube: the
     * ring's section grown by 1 across, OpenSCAD's 24 fragments */
    v = volume_of("minkowski() { rotate_extrude($fn = 24) translate([5, 0]) square([2, 3]);\n"
                  "  cube(1, center = true); }",
                  256);
    cr_assert(v > 0.99 * 489.633 && v < 1.01 * 489.633, "volume %f, openscad's 489.633", v);
}

Test(text, capital_height_matches_the_font)
{
    /* Liberation Sans: capitals 1409 units of a 2048-unit em (OS/2
     * sCapHeight); OpenSCAD's em is size · 100 / 72 */
    csg_scene *s = scene_of("text(\"H\", size = 10);");
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    double cap = 1409.0 / 2048 * 10 * 100 / 72;
    cr_assert(fabs(lo[1]) < 0.01 && fabs(hi[1] - cap) < 0.01 * cap, "y %f .. %f, cap %f", lo[1],
              hi[1], cap);
    csg_scene_free(s);
}

Test(text, halign_center_and_valign_center)
{
    csg_scene *s = scene_of("text(\"HH\", size = 10, halign = \"center\", valign = \"center\");");
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    /* H is symmetric in its advance, so the pair centres on x = 0 to
     * within the 1000-vs-1024 scaling OpenSCAD mixes (2.4 % of the
     * advance) */
    cr_assert(fabs(lo[0] + hi[0]) < 0.05 * (hi[0] - lo[0]), "x %f .. %f", lo[0], hi[0]);
    cr_assert(fabs(lo[1] + hi[1]) < 0.05 * (hi[1] - lo[1]), "y %f .. %f", lo[1], hi[1]);
    csg_scene_free(s);
}

Test(text, empty_and_spaces_draw_nothing)
{
    csg_scene *s = scene_of("text(\"  \");");
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), -1);
    csg_scene_free(s);
}

Test(text, without_a_service_is_an_error)
{
    msgs[0] = 0;
    scad_services no_text = *test_services();
    no_text.text = NULL;
    scad_options o = {0};
    o.services = &no_text;
    o.message = on_msg;
    scad_result r;
    cr_assert_eq(scad_eval_string("t.scad", "text(\"A\");", &o, &r), -1);
    cr_assert(strstr(msgs, "t.scad:1:1: error: text() is not available here"), "%s", msgs);
    cr_assert_null(r.model);
}
