/*
 * test_dxf_builtins.c — what the language does with DXF drawings: import()
 * of a .dxf (volumes of its extrusions by ray sampling), dxf_dim() and
 * dxf_cross() against the values openscad 2021.01 echoes for its own
 * example009.dxf, their warnings, and files the services cannot read.
 */
/*
 * test_dxf.c — the DXF reader (src/scad/dxf.c) and its builtins: areas of
 * DXF squares and circles against closed forms (from the outlines, and
 * from rays through the imported region), dxf_dim()/dxf_cross() against the
 * values openscad 2021.01 echoes for its example009.dxf, OpenSCAD's
 * warnings word for word, and hostile files that must end.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../src/intervals/intervals.h"
#include "../../src/geom/dxf.h"
#include "../../src/scad/scad.h"
#include "../scad_support.h"

#define PI 3.14159265358979323846

#define EXAMPLE009 "/usr/share/openscad/examples/Old/example009.dxf"

static const char square_dxf[] = "0\nSECTION\n2\nENTITIES\n"
                                 "0\nLWPOLYLINE\n8\nsq\n90\n4\n70\n1\n"
                                 "10\n0\n20\n0\n10\n10\n20\n0\n10\n10\n20\n10\n10\n0\n20\n10\n"
                                 "0\nCIRCLE\n8\nround\n10\n3\n20\n4\n40\n5\n"
                                 "0\nENDSEC\n0\nEOF\n";

static csg_scene *scene_of(const char *src, msgs *m)
{
    char main_file[256];
    snprintf(main_file, sizeof main_file, "%s/t.scad", scratch);
    return scene_as(main_file, src, m);
}

/* The echo lines of src, evaluated as scratch/t.scad. */
static void echo_of(const char *src, msgs *m)
{
    char main_file[256];
    snprintf(main_file, sizeof main_file, "%s/t.scad", scratch);
    scad_result r;
    eval_as(main_file, src, m, &r);
    scad_result_free(&r);
}

Test(dxf_import, extruded_square_with_a_round_hole, .init = scratch_setup, .fini = scratch_teardown)
{
    char path[256];
    write_file("a.dxf", square_dxf, path, sizeof path);
    msgs m = {""};
    /* all layers: the 16-gon crosses the square's edges, even-odd keeps
     * the square minus the overlap plus the 16-gon's part outside it */
    csg_scene *s = scene_of("linear_extrude(height = 2) import(\"a.dxf\", layer = \"sq\");", &m);
    double v = traced_volume(s, 300);
    cr_expect(fabs(v - 200) < 0.01 * 200, "square volume %g", v);
    csg_scene_free(s);
    s = scene_of("linear_extrude(height = 1) import(\"a.dxf\", layer = \"round\", $fn = 36);", &m);
    v = traced_volume(s, 300);
    double exact = 18 * 25 * sin(2 * PI / 36);
    cr_expect(fabs(v - exact) < 0.01 * exact, "circle volume %g vs %g", v, exact);
    csg_scene_free(s);
    cr_expect_str_empty(m.text);
}

Test(dxf_dim, example009_values_as_openscad_echoes_them, .init = scratch_setup,
     .fini = scratch_teardown)
{
    if (access(EXAMPLE009, R_OK) != 0) cr_skip_test("no %s (openscad not installed)", EXAMPLE009);
    msgs m = {""};
    /* openscad 2021.01: 22, 20, 2, 57.5288 + 7.70915e-6 (echo(v - 57.5288)),
     * [0, -40], [-1.5, -16.5] and 11 */
    echo_of(
        "f = \"" EXAMPLE009 "\";\n"
        "echo(dxf_dim(file = f, name = \"bodywidth\"), dxf_dim(file = f, name = \"fanwidth\"),"
        " dxf_dim(file = f, name = \"platewidth\"));\n"
        "echo((dxf_dim(file = f, name = \"fanrot\") - 57.5288) * 1e10);\n"
        "echo(dxf_cross(file = f, layer = \"fan_side_center\"));\n"
        "echo(dxf_cross(file = f, layer = \"fan_side_center\", origin = [3, -7], scale = 0.5));\n"
        "echo(dxf_dim(file = f, name = \"bodywidth\", scale = 0.5, origin = [3, 4]));\n",
        &m);
    cr_expect_str_eq(m.text, "ECHO: 22, 20, 2\n"
                             "ECHO: 77091.5\n"
                             "ECHO: [0, -40]\n"
                             "ECHO: [-1.5, -16.5]\n"
                             "ECHO: 11\n");
}

Test(dxf_dim, warnings_as_openscad_words_them, .init = scratch_setup, .fini = scratch_teardown)
{
    char path[256];
    write_file("a.dxf", square_dxf, path, sizeof path);
    msgs m = {""};
    echo_of("echo(dxf_dim(file = \"nothere.dxf\", name = \"a\"));\n"
            "echo(dxf_dim(file = \"a.dxf\", name = \"nope\"));\n"
            "echo(dxf_dim(\"a.dxf\", foo = 1, origin = \"x\"));\n"
            "echo(dxf_cross(file = \"a.dxf\", layer = \"sq\"));\n",
            &m);
    cr_expect_str_eq(
        m.text,
        "WARNING: Can't open DXF file 'nothere.dxf'! in file t.scad, line 1\n"
        "ECHO: undef\n"
        "WARNING: Can't find dimension 'nope' in 'a.dxf', layer ''! in file t.scad, line 2\n"
        "ECHO: undef\n"
        "WARNING: dxf_dim(..., =...) is not supported in file t.scad, line 3\n"
        "WARNING: dxf_dim(..., foo=...) is not supported in file t.scad, line 3\n"
        "WARNING: dxf_dim(..., origin=\"x\") could not be converted in file t.scad, line 3\n"
        "WARNING: Can't open DXF file ''! in file t.scad, line 3\n"
        "ECHO: undef\n"
        "WARNING: Can't find cross in 'a.dxf', layer 'sq'! in file t.scad, line 4\n"
        "ECHO: undef\n");
}

/* Files the language cannot read (a folder, a missing file) are OpenSCAD's
 * warning and an empty drawing; the file services decide, not the reader. */
Test(dxf_import, unreadable_files_warn, .init = scratch_setup, .fini = scratch_teardown)
{
    char path[256];
    write_file("gone.dxf", "", path, sizeof path);
    remove(path);
    char folder[300];
    snprintf(folder, sizeof folder, "%s/folder.dxf", scratch);
    cr_assert_eq(mkdir(folder, 0700), 0);
    msgs m = {""};
    char src[700];
    snprintf(src, sizeof src, "import(\"%s\");\nimport(\"%s\");\n", path, folder);
    echo_of(src, &m);
    char want[1024];
    snprintf(want, sizeof want,
             "WARNING: Can't open DXF file '%s'.\nWARNING: Can't open DXF file '%s'.\n", path,
             folder);
    cr_expect_str_eq(m.text, want);
}
