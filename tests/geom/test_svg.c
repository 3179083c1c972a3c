/*
 * test_svg.c — the SVG reader (src/geom/svg.c, svg_parse.c): libsvg's
 * readings of numbers, lengths, transforms and path data, shapes' outlines
 * against closed forms (shoelace areas), the page frame against the
 * coordinates openscad 2021.01 exports, and XML errors with their line and
 * column.
 */
#include <criterion/criterion.h>

#include <math.h>

#define PI 3.14159265358979323846
#include <string.h>

#include "../../src/geom/svg.h"

static int read_svg(const char *text, geom_svg *d)
{
    char err[256];
    return geom_svg_read(text, strlen(text), d, err, sizeof err);
}

/* Shoelace area of path i (signed, y down as in SVG). */
static double area(const geom_svg *d, int i)
{
    double a = 0;
    int s = d->start[i], e = d->start[i + 1];
    for (int k = s; k < e; k++) {
        const double *p = d->pts[k], *q = d->pts[k + 1 < e ? k + 1 : s];
        a += p[0] * q[1] - q[0] * p[1];
    }
    return a / 2;
}

Test(svg, number_is_the_whole_text)
{
    cr_expect_eq(geom_svg_number("12.5"), 12.5);
    cr_expect_eq(geom_svg_number("-1e2"), -100);
    cr_expect_eq(geom_svg_number("10px"), 0); /* libsvg: not a number at all */
    cr_expect_eq(geom_svg_number(" 2"), 0);
    cr_expect_eq(geom_svg_number(NULL), 0);
}

Test(svg, length_units)
{
    geom_svg_length l = geom_svg_parse_length(" 20 mm ");
    cr_expect(l.number == 20 && l.unit == GEOM_SVG_UNIT_MM);
    l = geom_svg_parse_length("50%");
    cr_expect(l.number == 50 && l.unit == GEOM_SVG_UNIT_PERCENT);
    l = geom_svg_parse_length("7");
    cr_expect(l.number == 7 && l.unit == GEOM_SVG_UNIT_NONE);
    cr_expect_eq(geom_svg_parse_length("7 furlongs").unit, GEOM_SVG_UNIT_UNDEFINED);
}

Test(svg, transform_composes_left_to_right)
{
    const double id[6] = {1, 0, 0, 1, 0, 0};
    double m[6];
    geom_svg_transform("translate(10,20) rotate(90) scale(2)", id, m);
    /* (1, 0) -> scale (2, 0) -> rotate (0, 2) -> translate (10, 22) */
    cr_expect_float_eq(m[0] * 1 + m[4], 10, 1e-12);
    cr_expect_float_eq(m[1] * 1 + m[5], 22, 1e-12);
    geom_svg_transform("rotate(90 5 5)", id, m);
    cr_expect_float_eq(m[0] * 5 + m[2] * 0 + m[4], 10, 1e-12); /* (5,0) -> (10,5) */
    cr_expect_float_eq(m[1] * 5 + m[3] * 0 + m[5], 5, 1e-12);
    geom_svg_transform("matrix(1 2 3)", id, m); /* wrong count: left out */
    cr_expect_arr_eq(m, id, sizeof id);
}

Test(svg, path_data_relative_exponent_and_holes)
{
    geom_svg d;
    cr_assert_eq(
        read_svg("<svg><g><path d='M0,0 h10 v1e1 H0 z m2,2 l6 0 0 6 -6 0 Z'/></g></svg>", &d), 0);
    cr_assert_eq(d.nshapes, 1);
    cr_assert_eq(d.npaths, 2);
    cr_expect_float_eq(fabs(area(&d, 0)), 100, 1e-9);
    cr_expect_float_eq(fabs(area(&d, 1)), 36, 1e-9);
    cr_expect_eq(d.stroke[0] + d.stroke[1], 0);
    geom_svg_free(&d);
}

Test(svg, open_subpaths_are_stroked_unless_a_z_came)
{
    geom_svg d;
    cr_assert_eq(read_svg("<svg><g><path d='M0 0 L10 0'/><path d='M0 0 L5 5 L0 5 Z M9 9 L20 20'/>"
                          "<line x2='3'/><polyline points='0 0 1 1 2 0'/></g></svg>",
                          &d),
                 0);
    cr_assert_eq(d.nshapes, 4);
    cr_expect_eq(d.stroke[d.shapes[0].first], 1);
    cr_expect_eq(d.shapes[1].count, 2);
    cr_expect_eq(d.stroke[d.shapes[1].first + 1], 0); /* libsvg keeps it as an outline */
    cr_expect_eq(d.stroke[d.shapes[2].first], 1);
    cr_expect_eq(d.stroke[d.shapes[3].first], 1);
    geom_svg_free(&d);
}

Test(svg, shapes_and_stroke_style)
{
    geom_svg d;
    cr_assert_eq(read_svg("<svg><g><circle cx='5' cy='5' r='2'/>"
                          "<rect x='1' y='1' width='10' height='4' rx='1'/>"
                          "<line x2='5' style='stroke-width:3;stroke-linecap:round'/>"
                          "<line x2='5' style='stroke-width: 3'/></g></svg>",
                          &d),
                 0);
    cr_assert_eq(d.nshapes, 4);
    cr_expect_eq(d.shapes[0].count, 1);
    cr_expect_eq(d.start[1] - d.start[0], 40); /* libsvg's 40 points */
    double n = 40, circle = 0.5 * n * 4 * sin(2 * PI / n);
    cr_expect_float_eq(fabs(area(&d, 0)), circle, 1e-9);
    /* rounded rect: 40 minus the corners (4 - pi), less the arcs' chords */
    double a = fabs(area(&d, d.shapes[1].first));
    cr_expect(a < 40 - (4 - PI) && a > 40 - (4 - PI) - 0.05, "rounded rect area %g", a);
    cr_expect_eq(d.shapes[2].stroke_width, 3);
    cr_expect_eq(d.shapes[2].cap, GEOM_SVG_CAP_ROUND);
    cr_expect_eq(d.shapes[3].stroke_width, 1); /* " 3" is not a number to libsvg */
    cr_expect_eq(d.shapes[3].cap, GEOM_SVG_CAP_SQUARE);
    geom_svg_free(&d);
}

Test(svg, root_transform_and_defs_left_out)
{
    geom_svg d;
    cr_assert_eq(read_svg("<svg transform='translate(100 0)'><defs><rect width='5' height='5'/>"
                          "</defs><rect width='1' height='1' transform='translate(2 0)'/></svg>",
                          &d),
                 0);
    cr_assert_eq(d.nshapes, 1);
    cr_expect_eq(d.shapes[0].world_from_local[4], 2);
    geom_svg_free(&d);
}

Test(svg, page_frame_as_openscad)
{
    /* openscad 2021.01 puts this svg's circle centre (50, 50) at
     * (50, -14.7222): no viewBox, so user units are mm and y = h_mm - y */
    geom_svg d;
    cr_assert_eq(
        read_svg("<svg width='100' height='100'><circle cx='50' cy='50' r='4'/></svg>", &d), 0);
    geom_svg_frame f;
    double bbox[4] = {1, 1, 0, 0};
    geom_svg_frame_of(&d, 72, 0, bbox, &f);
    double y = f.s[1] * (-f.vb[1] - 50) + f.c[1];
    cr_expect_float_eq(y, 25.4 * 100 / 72 - 50, 1e-12);
    geom_svg_free(&d);
    /* viewBox 0 0 200 100 on 100 x 50 mm: half a millimetre per unit */
    cr_assert_eq(read_svg("<svg width='100mm' height='50mm' viewBox='0 0 200 100'/>", &d), 0);
    geom_svg_frame_of(&d, 72, 0, bbox, &f);
    cr_expect_float_eq(f.s[0], 0.5, 1e-12);
    cr_expect_float_eq(f.c[1], 50, 1e-12);
    geom_svg_free(&d);
}

Test(svg, xml_errors_have_line_and_column)
{
    geom_svg d;
    char err[256];
    const char *bad = "<svg>\n<g>\n</svg>\n";
    cr_expect_eq(geom_svg_read(bad, strlen(bad), &d, err, sizeof err), 1);
    cr_expect(strncmp(err, "3:", 2) == 0, "%s", err);
    cr_expect(strstr(err, "mismatch") != NULL, "%s", err);
    geom_svg_free(&d);
    const char *ext = "<!DOCTYPE svg [<!ENTITY x SYSTEM 'file:///etc/passwd'>]><svg>&x;</svg>";
    int rc = geom_svg_read(ext, strlen(ext), &d, err, sizeof err);
    cr_expect(rc == 0 || rc == 1);
    cr_expect_eq(d.nshapes, 0);
    geom_svg_free(&d);
}
