/*
 * test_dxf.c — the DXF reader (src/geom/dxf.c): areas of the outlines it
 * joins against the shoelace formula, OpenSCAD 2021.01's warnings for bad
 * values and unsupported entities word for word, and hostile drawings that
 * must end.
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

static void on_dxf_msg(void *ud, int kind, const char *text)
{
    on_msg(ud, kind == GEOM_DXF_NOTE ? RAYSCAD_MSG_NOTE : RAYSCAD_MSG_WARNING, text);
}

/* geom_dxf_read of the file at path (its bytes read here), named abs and
 * rel in messages. */
static int read_named(const char *path, const char *abs, const char *rel, const geom_dxf_params *p,
                      msgs *m, geom_dxf *d)
{
    FILE *f = fopen(path, "rb");
    cr_assert(f, "%s", path);
    static char text[1 << 20];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = 0;
    return geom_dxf_read(text, n, abs, rel, p, on_dxf_msg, m, d);
}

static int read_path(const char *path, const geom_dxf_params *p, msgs *m, geom_dxf *d)
{
    return read_named(path, path, path, p, m, d);
}

/* Σ shoelace area of the toPolygon2d outlines (all one way round here). */
static double outline_area(const geom_dxf *d)
{
    double(*p)[2];
    int *start, n;
    cr_assert_eq(geom_dxf_outlines(d, &p, &start, &n), 0);
    double a = 0;
    for (int i = 0; i < n; i++) {
        double s = 0;
        for (int j = start[i]; j < start[i + 1]; j++) {
            int k = j + 1 < start[i + 1] ? j + 1 : start[i];
            s += p[j][0] * p[k][1] - p[k][0] * p[j][1];
        }
        a += fabs(s) / 2;
    }
    free(p);
    free(start);
    return a;
}

static const char square_dxf[] = "0\nSECTION\n2\nENTITIES\n"
                                 "0\nLWPOLYLINE\n8\nsq\n90\n4\n70\n1\n"
                                 "10\n0\n20\n0\n10\n10\n20\n0\n10\n10\n20\n10\n10\n0\n20\n10\n"
                                 "0\nCIRCLE\n8\nround\n10\n3\n20\n4\n40\n5\n"
                                 "0\nENDSEC\n0\nEOF\n";

Test(dxf_read, square_and_circle_areas, .init = scratch_setup, .fini = scratch_teardown)
{
    char path[256];
    write_file("a.dxf", square_dxf, path, sizeof path);
    msgs m = {""};
    geom_dxf d;
    geom_dxf_params sq = {"sq", 0, 0, 1, 0, 12, 2};
    cr_assert_eq(read_path(path, &sq, &m, &d), 0);
    cr_expect_eq(d.npaths, 1);
    cr_expect(d.closed[0]);
    cr_expect(fabs(outline_area(&d) - 100) < 1e-12, "%g", outline_area(&d));
    geom_dxf_free(&d);
    /* origin moves, scale scales: 2.5² × 100 */
    geom_dxf_params sq2 = {"sq", 4, -1, 2.5, 0, 12, 2};
    cr_assert_eq(read_path(path, &sq2, &m, &d), 0);
    cr_expect(fabs(outline_area(&d) - 625) < 1e-9);
    cr_expect(fabs(d.pts[0][0] + 10) < 1e-12 && fabs(d.pts[0][1] - 2.5) < 1e-12);
    geom_dxf_free(&d);
    /* r = 5 at $fa = 12, $fs = 2: 16 fragments; $fn = 36: 36.  The n-gon's
     * area is n/2 r² sin(2π/n); the points snap to 0.001 */
    int fn[2] = {0, 36}, want[2] = {16, 36};
    for (int i = 0; i < 2; i++) {
        geom_dxf_params c = {"round", 0, 0, 1, fn[i], 12, 2};
        cr_assert_eq(read_path(path, &c, &m, &d), 0);
        cr_expect_eq(d.npaths, 1);
        cr_expect_eq(d.path_start[1], want[i] + 1);
        double exact = want[i] / 2.0 * 25 * sin(2 * PI / want[i]);
        cr_expect(fabs(outline_area(&d) - exact) < 0.01, "%d: %g vs %g", want[i], outline_area(&d),
                  exact);
        geom_dxf_free(&d);
    }
    /* all layers: both outlines */
    geom_dxf_params all = {NULL, 0, 0, 1, 0, 12, 2};
    cr_assert_eq(read_path(path, &all, &m, &d), 0);
    cr_expect_eq(d.npaths, 2);
    geom_dxf_free(&d);
    cr_expect_str_empty(m.text);
}

Test(dxf_read, bad_values_and_unsupported_entities, .init = scratch_setup, .fini = scratch_teardown)
{
    /* openscad 2021.01 (stderr of -o x.stl) on this very file */
    char path[256], want[2048];
    write_file("bad.dxf",
               "0\nSECTION\n2\nENTITIES\n0\nPOLYLINE\n8\n0\n0\nSPLINE\n8\n0\n"
               "0\nLINE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n"
               "0\nLINE\n8\n0\n10\n10\n20\n0\n11\n0\n21\n10\n"
               "0\nLINE\n8\n0\n10\nabc\n20\n0\n11\n0\n21\n10\n0\nENDSEC\n0\nEOF\n",
               path, sizeof path);
    cr_assert_eq(chdir(scratch), 0);
    msgs m = {""};
    geom_dxf d;
    geom_dxf_params p = {"0", 0, 0, 1, 0, 12, 2};
    char abs[300];
    snprintf(abs, sizeof abs, "%s/bad.dxf", scratch); /* as the language names it */
    cr_assert_eq(read_named("bad.dxf", abs, "bad.dxf", &p, &m, &d), 0);
    snprintf(want, sizeof want,
             "Illegal value 'abc'in `%s/bad.dxf'\n"
             "Not enough input values for ENDSEC. in '%s/bad.dxf'\n"
             "Not enough input values for EOF. in '%s/bad.dxf'\n"
             "Unsupported DXF Entity 'SPLINE' (1) in layer '0' of bad.dxf\n"
             "Unsupported DXF Entity 'POLYLINE' (1) in layer '0' of bad.dxf\n",
             scratch, scratch, scratch);
    cr_expect_str_eq(m.text, want);
    /* the two good lines meet at (10, 0): one open path of 3 points */
    cr_expect_eq(d.npaths, 1);
    cr_expect(!d.closed[0]);
    cr_expect_eq(d.path_start[1], 3);
    geom_dxf_free(&d);
    cr_assert_eq(chdir("/"), 0);
}

Test(dxf_read, hostile_files_end, .init = scratch_setup, .fini = scratch_teardown)
{
    char path[256];
    /* an arc over 1e300 degrees, non-finite points, an ellipse of NaN
     * angles, a block inserted into itself, a huge $fn, garbage */
    write_file("h.dxf",
               "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nb\n"
               "0\nLINE\n10\n0\n20\n0\n11\n1\n21\n1\n"
               "0\nINSERT\n2\nb\n10\n1\n20\n1\n"
               "0\nINSERT\n2\nb\n10\n2\n20\n2\n"
               "0\nENDBLK\n0\nENDSEC\n"
               "0\nSECTION\n2\nENTITIES\n"
               "0\nARC\n10\n0\n20\n0\n40\n1\n50\n0\n51\n1e300\n"
               "0\nARC\n10\n0\n20\n0\n40\n1\n50\n1e300\n51\n0\n"
               "0\nLINE\n10\nnan\n20\n0\n11\ninf\n21\n1e308\n"
               "0\nELLIPSE\n10\n0\n20\n0\n11\n0\n21\n0\n40\n1\n41\nnan\n42\ninf\n"
               "0\nCIRCLE\n10\n0\n20\n0\n40\n1e308\n"
               "0\nLWPOLYLINE\n70\n1\n"
               "0\nINSERT\n2\nb\n10\n0\n20\n0\n41\n1e308\n42\n-1e308\n"
               "0\nENDSEC\n0\nEOF\n\x01\xff garbage\n",
               path, sizeof path);
    msgs m = {""};
    geom_dxf d;
    geom_dxf_params p = {NULL, 0, 0, 1, 1e9, 12, 2};
    cr_assert_eq(read_path(path, &p, &m, &d), 0);
    cr_expect(d.npts <= 2 * GEOM_DXF_MAX_SEGMENTS);
    cr_expect(strstr(m.text, "more than 1000000 segments"), "%s", m.text);
    cr_expect(strstr(m.text, "Not enough input values for INSERT."), "%s", m.text);
    geom_dxf_free(&d);
}
