/*
 * test_pov.c — render_pov_export checked against POV-Ray itself: each model
 * is rendered by our renderer and, from the exported SDL, by `povray` at the
 * same size, and the object masks must agree (IoU ≥ 0.99 outside the
 * one-pixel band at the reference silhouette, as tests/tools/maskcmp.c).
 * A wrong matrix, camera vector or primitive mapping moves or reshapes the
 * silhouette and fails; a control case checks that a camera turned by 3°
 * does fail, so the threshold can tell.  Skipped when povray is missing.
 */
#include "../../src/csg/csg.h"
#include "../../src/io/io.h"
#include "../../src/render/render.h"
#include "../../src/scad/scad.h"

#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int have_povray(void)
{
    return system("command -v povray >/dev/null 2>&1") == 0;
}

static csg_scene *scene_of(const char *src, int facets)
{
    scad_options so = {.facets = facets};
    scad_result res;
    cr_assert_eq(scad_eval_string("m.scad", src, &so, &res), 0);
    csg_node *roots[3] = {res.model, res.highlight, res.background};
    res.model = res.highlight = res.background = NULL;
    scad_result_free(&res);
    char err[256];
    csg_scene *s = csg_scene_new(roots, 3, err, sizeof err);
    cr_assert_not_null(s, "%s", err);
    return s;
}

static void camera_of(const csg_scene *s, const render_view *v, int w, int h, render_camera *cam)
{
    double lo[3], hi[3];
    int have = 0;
    for (int r = 0; r < csg_scene_root_count(s); r++) {
        double l[3], u[3];
        if (csg_scene_view_bounds(s, r, l, u) != 0) continue;
        for (int k = 0; k < 3; k++) {
            lo[k] = have && lo[k] < l[k] ? lo[k] : l[k];
            hi[k] = have && hi[k] > u[k] ? hi[k] : u[k];
        }
        have = 1;
    }
    cr_assert_eq(render_camera_resolve(v, lo, hi, have, w, h, cam), 0);
}

static unsigned char *mask_of(const float *px, int n, int ch, const float bg[3])
{
    unsigned char *m = malloc((size_t)n);
    for (int i = 0; i < n; i++) {
        m[i] = 0;
        for (int c = 0; c < 3; c++)
            if (fabsf(px[(size_t)i * (size_t)ch + (size_t)c] - bg[c]) * 255.0f > 8.0f) m[i] = 1;
    }
    return m;
}

/* IoU of the masks outside the band where the reference mask changes within
 * a pixel's 3×3 neighbourhood. */
static double masked_iou(const unsigned char *a, const unsigned char *ref, int w, int h)
{
    long inter = 0, uni = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int v = ref[y * w + x], band = 0;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (xx >= 0 && yy >= 0 && xx < w && yy < h && ref[yy * w + xx] != v) band = 1;
                }
            if (band) continue;
            inter += a[y * w + x] && v;
            uni += a[y * w + x] || v;
        }
    return uni ? (double)inter / (double)uni : 1.0;
}

/* Mask IoU of our image (from camera `ours`) against POV-Ray's render of
 * the export (from camera `pov`). */
static double compare(const char *src, int facets, const render_view *ours, const render_view *pov,
                      int w, int h)
{
    csg_scene *s = scene_of(src, facets);
    render_options ro = {.width = w, .height = h, .samples = 1, .threads = 2};
    cr_assert_eq(render_colors_by_name("Cornfield", &ro.colors), 0);
    render_camera cam_ours, cam_pov;
    camera_of(s, ours, w, h, &cam_ours);
    camera_of(s, pov, w, h, &cam_pov);

    float *img = malloc((size_t)w * (size_t)h * 4 * sizeof *img);
    char err[256];
    cr_assert_eq(render_image(s, &cam_ours, &ro, img, err, sizeof err), 0, "%s", err);
    char *text;
    size_t len;
    cr_assert_eq(render_pov_export(s, &cam_pov, &ro, &text, &len, err, sizeof err), 0, "%s", err);
    csg_scene_free(s);

    char dir[] = "/tmp/rayscad-pov-XXXXXX";
    cr_assert_not_null(mkdtemp(dir));
    char path[256], png[256], cmd[1024];
    snprintf(path, sizeof path, "%s/scene.pov", dir);
    snprintf(png, sizeof png, "%s/pov.png", dir);
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f);
    fwrite(text, 1, len, f);
    fclose(f);
    free(text);
    snprintf(cmd, sizeof cmd, "povray +W%d +H%d -D -A +WT2 +I%s +O%s >%s/log 2>&1", w, h, path, png,
             dir);
    int rc = system(cmd);
    int pw, ph, pch;
    float *ref = NULL;
    if (rc == 0) rc = io_image_read(png, &pw, &ph, &pch, &ref, err, sizeof err);
    cr_assert_eq(rc, 0, "povray failed on %s (see %s/log)", path, dir);
    cr_assert(pw == w && ph == h);

    unsigned char *ma = mask_of(img, w * h, 4, ro.colors.background);
    unsigned char *mb = mask_of(ref, w * h, pch, ro.colors.background);
    double iou = masked_iou(ma, mb, w, h);
    free(ma);
    free(mb);
    free(img);
    free(ref);
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0) { /* leftovers in /tmp are harmless */
    }
    return iou;
}

static const char primitives[] =
    "difference() { cube(20, center=true); sphere(13);\n"
    "  translate([5,0,0]) rotate([0,90,0]) cylinder(r=4, h=30, center=true); }\n"
    "translate([-25,0,-10]) linear_extrude(10) difference() { square(12, center=true); "
    "circle(3); }\n"
    "translate([0,25,0]) rotate_extrude(angle=270) translate([6,0]) square([3,5]);\n"
    "translate([0,0,20]) polyhedron([[0,0,0],[10,0,0],[0,10,0],[0,0,10]],"
    "[[0,1,2],[0,3,1],[0,2,3],[1,3,2]]);\n"
    "rotate([30,20,10]) translate([20,0,0]) scale([1,2,0.5]) cylinder(r1=5, r2=2, h=8);\n";

static const char revolves[] =
    "rotate_extrude(angle=200) translate([8,0]) difference() { square([6,8]); "
    "translate([3,4]) circle(1.5); }\n"
    "translate([0,0,12]) rotate_extrude() polygon([[2,0],[6,0],[4,5]]);\n"
    "translate([-20,0,0]) intersection() { sphere(7); cube(10, center=true); }\n"
    "translate([0,-20,0]) color(\"red\", 0.4) union() { sphere(5); translate([4,0,0]) "
    "sphere(5); }\n"
    "#translate([20,0,0]) cube(4);\n"
    "%translate([20,10,0]) sphere(3);\n";

static const char facets[] =
    "sphere(8, $fn=12); translate([18,0,0]) cylinder(r=5, h=10, $fn=7);\n"
    "translate([0,18,0]) hull() { cube(4); translate([6,6,6]) sphere(2, $fn=8); }\n"
    "translate([-18,0,0]) rotate([90,0,0]) linear_extrude(4) polygon([[0,0],[8,0],[4,7]]);\n";

Test(pov_export, primitives_default_view)
{
    if (!have_povray()) cr_skip_test("povray not installed");
    render_view v = {.kind = RAYSCAD_CAMERA_DEFAULT};
    double iou = compare(primitives, 0, &v, &v, 200, 160);
    cr_expect_geq(iou, 0.99, "IoU %.5f", iou);
}

Test(pov_export, revolves_transparency_modifiers_gimbal)
{
    if (!have_povray()) cr_skip_test("povray not installed");
    render_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {10, 5, 3, 60, 0, 30, 120}};
    double iou = compare(revolves, 0, &v, &v, 160, 200);
    cr_expect_geq(iou, 0.99, "IoU %.5f", iou);
}

Test(pov_export, facets_orthographic)
{
    if (!have_povray()) cr_skip_test("povray not installed");
    render_view v = {.kind = RAYSCAD_CAMERA_DEFAULT, .ortho = 1};
    double iou = compare(facets, RAYSCAD_FACETS_OPENSCAD, &v, &v, 200, 150);
    cr_expect_geq(iou, 0.99, "IoU %.5f", iou);
}

Test(pov_export, eye_camera)
{
    if (!have_povray()) cr_skip_test("povray not installed");
    render_view v = {.kind = RAYSCAD_CAMERA_EYE, .v = {80, -60, 50, 0, 0, 0}};
    double iou = compare(primitives, 0, &v, &v, 160, 120);
    cr_expect_geq(iou, 0.99, "IoU %.5f", iou);
}

Test(pov_export, turned_camera_fails)
{
    if (!have_povray()) cr_skip_test("povray not installed");
    render_view a = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 55, 0, 25, 120}};
    render_view b = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 55, 0, 28, 120}};
    double iou = compare(primitives, 0, &a, &b, 200, 160);
    cr_expect_lt(iou, 0.99, "a 3° turn still gives IoU %.5f", iou);
}
