/*
 * test_render.c — cameras, colour schemes, lighting and compositing, checked
 * against independent truth: OpenSCAD 2021.01's own preview PNGs (rendered
 * here with xvfb-run), the colour-scheme files it installs, and closed-form
 * compositing.  A camera test casts our rays through every pixel centre at an
 * analytic box (no CSG code involved) and compares that mask with the object
 * mask of OpenSCAD's image.
 */
#include "../../src/csg/csg.h"
#include "../../src/io/io.h"
#include "../../src/render/render.h"
#include "../support.h"

#include <criterion/criterion.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ---- helpers ------------------------------------------------------------- */

static int have_openscad(void)
{
    return system("command -v openscad >/dev/null 2>&1 && command -v xvfb-run >/dev/null 2>&1") ==
           0;
}

/* Render scad source with OpenSCAD's preview into a PNG and read it back.
 * Returns the pixels (caller frees) or NULL. */
static float *openscad_render(const char *scad, const char *args, int *w, int *h, int *ch)
{
    char dir[] = "/tmp/rayscad-test-XXXXXX";
    if (!mkdtemp(dir)) return NULL;
    char src[256], png[256], cmd[1024];
    snprintf(src, sizeof src, "%s/m.scad", dir);
    snprintf(png, sizeof png, "%s/ref.png", dir);
    FILE *f = fopen(src, "w");
    if (!f) return NULL;
    fputs(scad, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "xvfb-run -a openscad -o %s %s %s >%s/log 2>&1", png, args, src, dir);
    float *px = NULL;
    char err[256];
    if (system(cmd) == 0 && io_image_read(png, w, h, ch, &px, err, sizeof err) != 0) px = NULL;
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd) != 0) { /* leftovers in /tmp are harmless */
    }
    return px;
}

/* Object mask of an image: any channel more than 8/255 from the background
 * (OpenSCAD's image_compare.py ignores smaller differences). */
static unsigned char *mask_of(const float *px, int w, int h, int ch, const float bg[3])
{
    unsigned char *m = malloc((size_t)w * (size_t)h);
    for (int i = 0; i < w * h; i++) {
        m[i] = 0;
        for (int c = 0; c < 3; c++)
            if (fabsf(px[i * ch + c] - bg[c]) * 255.0f > 8.0f) m[i] = 1;
    }
    return m;
}

/* Slab test: does o + t·d, t in [tmin, tmax], meet the box lo..hi? */
static int ray_hits_box(const double o[3], const double d[3], double tmin, double tmax,
                        const double lo[3], const double hi[3])
{
    for (int k = 0; k < 3; k++) {
        if (d[k] == 0) {
            if (o[k] < lo[k] || o[k] > hi[k]) return 0;
            continue;
        }
        double a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
        if (a > b) {
            double t = a;
            a = b;
            b = t;
        }
        if (a > tmin) tmin = a;
        if (b < tmax) tmax = b;
    }
    return tmin < tmax;
}

typedef struct mask_stats {
    int ref_count, our_count, mismatch, mismatch_outside_band;
    int ref_x0, ref_x1, ref_y0, ref_y1; /* extent of the reference mask */
} mask_stats;

static int in_band(const unsigned char *m, int w, int h, int x, int y)
{
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
            if (m[yy * w + xx] != m[y * w + x]) return 1;
        }
    return 0;
}

/* Compare OpenSCAD's mask of cube(lo..hi) with the mask our camera's rays
 * give for the same box. */
static mask_stats compare_box(const char *args, const render_view *v, int W, int H,
                              const double lo[3], const double hi[3])
{
    char scad[256];
    snprintf(scad, sizeof scad, "translate([%.17g,%.17g,%.17g]) cube([%.17g,%.17g,%.17g]);\n",
             lo[0], lo[1], lo[2], hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    int w, h, ch;
    float *ref = openscad_render(scad, args, &w, &h, &ch);
    cr_assert_not_null(ref, "openscad failed for %s", args);
    cr_assert(w == W && h == H, "openscad image is %dx%d, expected %dx%d", w, h, W, H);
    const float bg[3] = {0xff / 255.0f, 0xff / 255.0f, 0xe5 / 255.0f};
    unsigned char *rm = mask_of(ref, w, h, ch, bg);

    render_camera cam;
    cr_assert_eq(render_camera_resolve(v, lo, hi, 1, W, H, &cam), 0);
    mask_stats st = {0, 0, 0, 0, W, -1, H, -1};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double o[3], d[3];
            render_camera_ray(&cam, W, H, x + 0.5, y + 0.5, o, d);
            double df = d[0] * cam.forward[0] + d[1] * cam.forward[1] + d[2] * cam.forward[2];
            int ours = ray_hits_box(o, d, cam.clip_near / df, cam.clip_far / df, lo, hi);
            int theirs = rm[y * W + x];
            st.our_count += ours;
            st.ref_count += theirs;
            if (theirs) {
                if (x < st.ref_x0) st.ref_x0 = x;
                if (x > st.ref_x1) st.ref_x1 = x;
                if (y < st.ref_y0) st.ref_y0 = y;
                if (y > st.ref_y1) st.ref_y1 = y;
            }
            if (ours != theirs) {
                st.mismatch++;
                if (!in_band(rm, W, H, x, y)) st.mismatch_outside_band++;
            }
        }
    free(rm);
    free(ref);
    return st;
}

#define REQUIRE_OPENSCAD()                                                                         \
    do {                                                                                           \
        if (!have_openscad()) cr_skip_test("openscad or xvfb-run not installed");                  \
    } while (0)

/* ---- camera against OpenSCAD --------------------------------------------- */

/* REFERENCE.md: a 10 mm cube at dist 50 is 150 px tall in a 300 px image
 * (ortho half-height = 50·tan 11.25° = 9.946 → 300/19.89 px per mm). */
Test(render_camera, gimbal_ortho_top_view_matches_openscad)
{
    REQUIRE_OPENSCAD();
    render_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 0, 0, 0, 50}, .ortho = 1};
    double lo[3] = {-5, -5, -5}, hi[3] = {5, 5, 5};
    mask_stats st = compare_box("--imgsize=300,300 --camera=0,0,0,0,0,0,50 --projection=o", &v, 300,
                                300, lo, hi);
    int ref_w = st.ref_x1 - st.ref_x0 + 1, ref_h = st.ref_y1 - st.ref_y0 + 1;
    double expect = 10 / (2 * 50 * tan(22.5 / 2 * M_PI / 180)) * 300;
    cr_expect(fabs(ref_w - expect) <= 1 && fabs(ref_h - expect) <= 1,
              "OpenSCAD's cube is %dx%d px, closed form %.2f", ref_w, ref_h, expect);
    cr_expect(st.mismatch_outside_band == 0 && st.mismatch <= 4 * ref_w / 10,
              "masks differ in %d px (%d outside the 1-px band); ours %d px, OpenSCAD %d px",
              st.mismatch, st.mismatch_outside_band, st.our_count, st.ref_count);
}

Test(render_camera, default_view_matches_openscad)
{
    REQUIRE_OPENSCAD();
    render_view v = {.kind = RAYSCAD_CAMERA_DEFAULT};
    double lo[3] = {0, 0, 0}, hi[3] = {10, 20, 5};
    mask_stats st = compare_box("--imgsize=320,240", &v, 320, 240, lo, hi);
    cr_expect(st.ref_count > 1000, "OpenSCAD's image shows %d object px", st.ref_count);
    cr_expect(st.mismatch_outside_band == 0 && st.mismatch < st.ref_count / 100,
              "masks differ in %d px (%d outside the 1-px band); ours %d px, OpenSCAD %d px",
              st.mismatch, st.mismatch_outside_band, st.our_count, st.ref_count);
}

Test(render_camera, eye_centre_view_matches_openscad)
{
    REQUIRE_OPENSCAD();
    render_view v = {.kind = RAYSCAD_CAMERA_EYE, .v = {30, -40, 25, 2, 3, 1}};
    double lo[3] = {-3, -2, -1}, hi[3] = {7, 6, 4};
    mask_stats st = compare_box("--imgsize=300,300 --camera=30,-40,25,2,3,1", &v, 300, 300, lo, hi);
    cr_expect(st.ref_count > 1000, "OpenSCAD's image shows %d object px", st.ref_count);
    cr_expect(st.mismatch_outside_band == 0 && st.mismatch < st.ref_count / 100,
              "masks differ in %d px (%d outside the 1-px band); ours %d px, OpenSCAD %d px",
              st.mismatch, st.mismatch_outside_band, st.our_count, st.ref_count);
}

Test(render_camera, eye_straight_down_matches_openscad)
{
    REQUIRE_OPENSCAD();
    render_view v = {.kind = RAYSCAD_CAMERA_EYE, .v = {0, 0, 60, 0, 0, 0}, .ortho = 1};
    double lo[3] = {-4, -2, 0}, hi[3] = {8, 6, 3};
    mask_stats st =
        compare_box("--imgsize=200,200 --camera=0,0,60,0,0,0 --projection=o", &v, 200, 200, lo, hi);
    cr_expect(st.ref_count > 1000, "OpenSCAD's image shows %d object px", st.ref_count);
    cr_expect(st.mismatch_outside_band == 0 && st.mismatch < st.ref_count / 100,
              "masks differ in %d px (%d outside the 1-px band); ours %d px, OpenSCAD %d px",
              st.mismatch, st.mismatch_outside_band, st.our_count, st.ref_count);
}

Test(render_camera, gimbal_perspective_wide_image_matches_openscad)
{
    REQUIRE_OPENSCAD();
    render_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {3, 2, 1, 63.3, 10, 31.7, 80}};
    double lo[3] = {-6, -3, -2}, hi[3] = {9, 8, 5};
    mask_stats st =
        compare_box("--imgsize=320,200 --camera=3,2,1,63.3,10,31.7,80", &v, 320, 200, lo, hi);
    cr_expect(st.ref_count > 1000, "OpenSCAD's image shows %d object px", st.ref_count);
    cr_expect(st.mismatch_outside_band == 0 && st.mismatch < st.ref_count / 100,
              "masks differ in %d px (%d outside the 1-px band); ours %d px, OpenSCAD %d px",
              st.mismatch, st.mismatch_outside_band, st.our_count, st.ref_count);
}

Test(render_camera, viewall_alone_keeps_the_centre)
{
    REQUIRE_OPENSCAD();
    render_view v = {
        .kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 70, 0, 300, 10}, .viewall = 1, .ortho = 1};
    double lo[3] = {2, 3, 0}, hi[3] = {12, 9, 4};
    mask_stats st = compare_box("--imgsize=240,240 --camera=0,0,0,70,0,300,10 --viewall "
                                "--projection=o",
                                &v, 240, 240, lo, hi);
    cr_expect(st.ref_count > 500, "OpenSCAD's image shows %d object px", st.ref_count);
    cr_expect(st.mismatch_outside_band == 0 && st.mismatch < st.ref_count / 100,
              "masks differ in %d px (%d outside the 1-px band); ours %d px, OpenSCAD %d px",
              st.mismatch, st.mismatch_outside_band, st.our_count, st.ref_count);
}

Test(render_camera, viewall_autocenter_explicit_camera)
{
    REQUIRE_OPENSCAD();
    render_view v = {.kind = RAYSCAD_CAMERA_GIMBAL,
                     .v = {50, 50, 50, 20, 0, 140, 10},
                     .viewall = 1,
                     .autocenter = 1};
    double lo[3] = {2, 3, 0}, hi[3] = {12, 9, 4};
    mask_stats st = compare_box("--imgsize=240,180 --camera=50,50,50,20,0,140,10 --viewall "
                                "--autocenter",
                                &v, 240, 180, lo, hi);
    cr_expect(st.ref_count > 500, "OpenSCAD's image shows %d object px", st.ref_count);
    cr_expect(st.mismatch_outside_band == 0 && st.mismatch < st.ref_count / 100,
              "masks differ in %d px (%d outside the 1-px band); ours %d px, OpenSCAD %d px",
              st.mismatch, st.mismatch_outside_band, st.our_count, st.ref_count);
}

/* Closed form, no OpenSCAD: the default view of a box looks at its centre
 * from (rx 55, rz 25) at (|diag|/2) / sin 11.25°. */
Test(render_camera, default_view_closed_form)
{
    render_view v = {.kind = RAYSCAD_CAMERA_DEFAULT};
    double lo[3] = {0, 0, 0}, hi[3] = {10, 20, 5};
    render_camera c;
    cr_assert_eq(render_camera_resolve(&v, lo, hi, 1, 100, 100, &c), 0);
    double dist = sqrt(100 + 400 + 25) / 2 / sin(11.25 * M_PI / 180);
    /* The eye sits 90-55 = 35° above the centre; rz = 25 turns the camera
     * 25° counter-clockwise about +z from the front (-y) view, so its
     * azimuth from +x is -90 + 25 (front right, as OpenSCAD's GUI shows). */
    double centre[3] = {5, 10, 2.5}, e[3];
    for (int i = 0; i < 3; i++)
        e[i] = c.eye[i] - centre[i];
    cr_expect(fabs(sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) - dist) < 1e-9);
    for (int i = 0; i < 3; i++)
        cr_expect(fabs(-e[i] / dist - c.forward[i]) < 1e-6);
    cr_expect(fabs(asin(e[2] / dist) * 180 / M_PI - 35) < 1e-4);
    cr_expect(fabs(atan2(e[1], e[0]) * 180 / M_PI - (-90 + 25)) < 1e-4, "azimuth %g",
              atan2(e[1], e[0]) * 180 / M_PI);
    cr_expect(fabs(c.up[2] - cos(35 * M_PI / 180)) < 1e-6);
    cr_expect_eq(c.ortho, 0);
    cr_expect(fabs(c.fovy_deg - 22.5) < 1e-12);
}

Test(render_camera, degenerate_and_empty)
{
    render_camera c;
    render_view eye = {.kind = RAYSCAD_CAMERA_EYE, .v = {1, 2, 3, 1, 2, 3}};
    cr_expect_eq(render_camera_resolve(&eye, NULL, NULL, 0, 10, 10, &c), -1);
    render_view def = {.kind = RAYSCAD_CAMERA_DEFAULT};
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    cr_expect_eq(render_camera_resolve(&def, lo, hi, 0, 10, 10, &c), 0);
    for (int i = 0; i < 3; i++)
        cr_expect(isfinite(c.eye[i]));
}

/* Pixel centres at +0.5: the centre ray of an odd image is the forward axis. */
Test(render_camera, centre_pixel_is_forward)
{
    render_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {1, 2, 3, 40, 20, 10, 30}};
    render_camera c;
    cr_assert_eq(render_camera_resolve(&v, NULL, NULL, 0, 101, 51, &c), 0);
    double o[3], d[3];
    render_camera_ray(&c, 101, 51, 50.5, 25.5, o, d);
    for (int i = 0; i < 3; i++)
        cr_expect(fabs(d[i] - c.forward[i]) < 1e-12);
    /* and it passes through the look-at point (1,2,3) at distance 30 */
    double at[3] = {1, 2, 3};
    for (int i = 0; i < 3; i++)
        cr_expect(fabs(o[i] + 30 * d[i] - at[i]) < 1e-9);
}

/* render_raygen_cover: over random views and boxes, the ray of every pixel
 * position outside the rectangle misses the box (an independent slab test
 * on the ray render_raygen_ray makes), and every corner's own pixel lies
 * inside it.  A box reaching behind a perspective eye has no rectangle. */
Test(render_camera, cover_rectangle_holds_every_ray_that_meets_the_box)
{
    rng_seed(7);
    int W = 48, H = 32, stated = 0, outside = 0, tight = 0;
    for (int trial = 0; trial < 150; trial++) {
        render_view v = {.kind = RAYSCAD_CAMERA_GIMBAL,
                         .v = {rng_uniform(-5, 5), rng_uniform(-5, 5), rng_uniform(-5, 5),
                               rng_uniform(0, 360), rng_uniform(0, 360), rng_uniform(0, 360),
                               rng_uniform(20, 80)},
                         .ortho = trial % 3 == 0};
        render_camera c;
        cr_assert_eq(render_camera_resolve(&v, NULL, NULL, 0, W, H, &c), 0);
        render_raygen g;
        render_raygen_init(&g, &c, W, H);
        double lo[3], hi[3], rect[4];
        for (int k = 0; k < 3; k++) {
            double m = rng_uniform(-12, 12), e = rng_uniform(0.1, trial % 5 == 0 ? 60 : 6);
            lo[k] = m - e;
            hi[k] = m + e;
        }
        if (render_raygen_cover(&g, lo, hi, rect) != 0) {
            /* only a perspective view with some corner at or behind the eye */
            cr_expect(!c.ortho);
            int behind = 0;
            for (int k = 0; k < 8; k++) {
                double p[3] = {k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]};
                double f = 0;
                for (int i = 0; i < 3; i++)
                    f += (p[i] - c.eye[i]) * c.forward[i];
                behind |= f <= 0;
            }
            cr_expect(behind, "trial %d: no rectangle for a box in front of the eye", trial);
            continue;
        }
        stated++;
        /* hx0..hy1: the extent of the positions whose rays meet the box */
        double hx0 = INFINITY, hx1 = -INFINITY, hy0 = INFINITY, hy1 = -INFINITY;
        /* positions over three times the image each way, every half pixel */
        for (int y = -2 * H; y <= 4 * H; y++)
            for (int x = -2 * W; x <= 4 * W; x++) {
                double px = x / 2.0, py = y / 2.0, o[3], d[3];
                render_raygen_ray(&g, px, py, o, d);
                int hit = ray_hits_box(o, d, c.ortho ? -INFINITY : 0, INFINITY, lo, hi);
                if (hit) {
                    hx0 = fmin(hx0, px);
                    hx1 = fmax(hx1, px);
                    hy0 = fmin(hy0, py);
                    hy1 = fmax(hy1, py);
                }
                if (px >= rect[0] && px <= rect[1] && py >= rect[2] && py <= rect[3]) continue;
                outside++;
                cr_assert(!hit,
                          "trial %d: the ray of (%g, %g) meets the box outside [%g %g]x[%g %g]",
                          trial, px, py, rect[0], rect[1], rect[2], rect[3]);
            }
        /* and tight: a rectangle within the sampled range lies within a few
         * pixels of the hits — the margin, plus the sampling step and the
         * thin tips of the box's outline that the half-pixel grid misses */
        if (rect[0] > -W && rect[1] < 2 * W && rect[2] > -H && rect[3] < 2 * H) {
            cr_expect(hx0 - rect[0] <= 3, "trial %d left %g %g ortho %d", trial, hx0, rect[0],
                      c.ortho);
            cr_expect(rect[1] - hx1 <= 3, "trial %d right %g %g ortho %d", trial, hx1, rect[1],
                      c.ortho);
            cr_expect(hy0 - rect[2] <= 3, "trial %d top", trial);
            cr_expect(rect[3] - hy1 <= 3, "trial %d bottom", trial);
            tight++;
        }
    }
    cr_expect(stated > 75, "only %d of 150 views stated a rectangle", stated);
    cr_expect(tight > 30, "only %d rectangles checked for tightness", tight);
    cr_expect(outside > 100000, "only %d positions fell outside a rectangle", outside);
}

/* ---- colour schemes ------------------------------------------------------- */

/* Read "key" : "#rrggbb" out of one of OpenSCAD's installed scheme files. */
static int json_color(const char *file, const char *key, float out[3])
{
    FILE *f = fopen(file, "r");
    if (!f) return -1;
    char buf[8192];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    char pat[128];
    snprintf(pat, sizeof pat, "\"%s\"", key);
    char *p = strstr(buf, pat);
    if (!p) return -1;
    p = strchr(p + strlen(pat), '#');
    unsigned rgb;
    if (!p || sscanf(p + 1, "%6x", &rgb) != 1) return -1;
    out[0] = (float)((rgb >> 16) & 255) / 255.0f;
    out[1] = (float)((rgb >> 8) & 255) / 255.0f;
    out[2] = (float)(rgb & 255) / 255.0f;
    return 0;
}

Test(render_colors, schemes_match_openscad_files)
{
    static const char *names[][2] = {
        {"Metallic", "metallic"},
        {"Sunset", "sunset"},
        {"Starnight", "starnight"},
        {"BeforeDawn", "beforedawn"},
        {"Nature", "nature"},
        {"DeepOcean", "deepocean"},
        {"Solarized", "solarized"},
        {"Tomorrow", "tomorrow"},
        {"Tomorrow Night", "tomorrow-night"},
        {"Monotone", "monotone"},
    };
    const char *dir = "/usr/share/openscad/color-schemes/render";
    if (access(dir, R_OK) != 0) cr_skip_test("OpenSCAD's colour schemes are not installed");
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char file[512];
        snprintf(file, sizeof file, "%s/%s.json", dir, names[i][1]);
        float bg[3], face[3], back[3];
        cr_assert_eq(json_color(file, "background", bg), 0, "%s", file);
        cr_assert_eq(json_color(file, "opencsg-face-front", face), 0, "%s", file);
        cr_assert_eq(json_color(file, "opencsg-face-back", back), 0, "%s", file);
        render_colors c;
        cr_assert_eq(render_colors_by_name(names[i][0], &c), 0, "%s", names[i][0]);
        for (int k = 0; k < 3; k++) {
            cr_expect(c.background[k] == bg[k], "%s background", names[i][0]);
            cr_expect(c.face[k] == face[k], "%s face", names[i][0]);
            cr_expect(c.back[k] == back[k], "%s back", names[i][0]);
        }
    }
}

/* Cornfield is compiled in: OpenSCAD src/colormap.cc, RenderColorScheme():
 * BACKGROUND ff,ff,e5; OPENCSG_FACE_FRONT f9,d7,2c; OPENCSG_FACE_BACK 9d,cb,51.
 * Modifiers: src/renderer.cc, Renderer(): HIGHLIGHT {255,81,81,128},
 * BACKGROUND {180,180,180,128}. */
Test(render_colors, cornfield_and_modifiers)
{
    render_colors c;
    cr_assert_eq(render_colors_by_name("Cornfield", &c), 0);
    const float bg[3] = {0xff, 0xff, 0xe5}, face[3] = {0xf9, 0xd7, 0x2c},
                back[3] = {0x9d, 0xcb, 0x51};
    const float hl[4] = {255, 81, 81, 128}, bm[4] = {180, 180, 180, 128};
    for (int k = 0; k < 3; k++) {
        cr_expect(c.background[k] == bg[k] / 255.0f);
        cr_expect(c.face[k] == face[k] / 255.0f);
        cr_expect(c.back[k] == back[k] / 255.0f);
    }
    for (int k = 0; k < 4; k++) {
        cr_expect(c.highlight[k] == hl[k] / 255.0f);
        cr_expect(c.background_modifier[k] == bm[k] / 255.0f);
    }
    cr_expect_eq(render_colors_by_name("NoSuchScheme", &c), -1);
    cr_expect_eq(render_colors_by_name(NULL, &c), -1);
}

/* ---- scenes for rendering -------------------------------------------------- */

static csg_node *box_node(double x0, double y0, double z0, double x1, double y1, double z1,
                          const float *rgba)
{
    iv_shape s = box(x0, y0, z0, x1, y1, z1);
    csg_material m = {.rgba = {1, 1, 1, 1}};
    if (rgba) {
        memcpy(m.rgba, rgba, sizeof m.rgba);
        m.has_color = 1;
    }
    csg_node *n = csg_node_shape(&s, csg_affine_identity, &m);
    cr_assert_not_null(n);
    return n;
}

static csg_node *sphere_node(double cx, double cy, double cz, double r, const float *rgba)
{
    iv_shape s = {.kind = IV_SHAPE_SPHERE};
    s.u.sphere.r = r;
    csg_affine m = {1, 0, 0, cx, 0, 1, 0, cy, 0, 0, 1, cz};
    csg_material mat = {.rgba = {1, 1, 1, 1}};
    if (rgba) {
        memcpy(mat.rgba, rgba, sizeof mat.rgba);
        mat.has_color = 1;
    }
    csg_node *n = csg_node_shape(&s, m, &mat);
    cr_assert_not_null(n);
    return n;
}

static csg_scene *scene_of(csg_node *model, csg_node *highlight, csg_node *background)
{
    csg_node *roots[3] = {model, highlight, background};
    char err[256];
    csg_scene *s = csg_scene_new(roots, 3, err, sizeof err);
    cr_assert_not_null(s, "%s", err);
    return s;
}

static float *render_or_die(const csg_scene *s, const render_camera *cam, render_options *o)
{
    float *px = malloc((size_t)o->width * (size_t)o->height * 4 * sizeof *px);
    char err[256];
    cr_assert_eq(render_image(s, cam, o, px, err, sizeof err), 0, "%s", err);
    return px;
}

static const render_view top_ortho = {
    .kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 0, 0, 0, 50}, .ortho = 1};

/* ---- lighting ---------------------------------------------------------------- */

/* A face turned to the camera: colour × (0.2 + 1/√3), the fixed-pipeline
 * value (ambient 0.2 + light 0 at (-1,-1,1)/√3). */
Test(render_image, face_toward_camera_is_0_777_of_face_colour)
{
    csg_scene *s = scene_of(box_node(-5, -5, -5, 5, 5, 5, NULL), NULL, NULL);
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&top_ortho, NULL, NULL, 0, 31, 31, &cam), 0);
    render_options o = {.width = 31, .height = 31, .samples = 1, .threads = 1};
    cr_assert_eq(render_colors_by_name("Cornfield", &o.colors), 0);
    float *px = render_or_die(s, &cam, &o);
    const float *c = px + (15 * 31 + 15) * 4;
    double k = 0.2 + 1 / sqrt(3.0);
    for (int i = 0; i < 3; i++)
        cr_expect(fabs(c[i] - o.colors.face[i] * k) < 1e-5, "channel %d: %g vs %g", i, c[i],
                  o.colors.face[i] * k);
    cr_expect(c[3] == 1);
    /* and a corner pixel shows the background */
    for (int i = 0; i < 3; i++)
        cr_expect(px[i] == o.colors.background[i]);
    free(px);
    csg_scene_free(s);
}

/* Render `model` as we do and `scad` with OpenSCAD (same flags) and compare
 * colours at every pixel whose 3×3 neighbourhood is uniform in both images
 * (edges, where faceting and rasterisation differ, are left out).  Each must
 * agree within 2/255 per channel. */
static void compare_colours(const char *scad, const char *args, csg_node *model,
                            const render_view *v, int W, int H, const char *scheme)
{
    REQUIRE_OPENSCAD();
    int w, h, ch;
    float *ref = openscad_render(scad, args, &w, &h, &ch);
    cr_assert_not_null(ref, "openscad failed for %s", args);
    cr_assert(w == W && h == H);
    csg_scene *s = scene_of(model, NULL, NULL);
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    render_camera cam;
    cr_assert_eq(render_camera_resolve(v, lo, hi, 1, W, H, &cam), 0);
    render_options o = {.width = W, .height = H, .samples = 1, .threads = 2};
    cr_assert_eq(render_colors_by_name(scheme, &o.colors), 0);
    float *px = render_or_die(s, &cam, &o);
    int compared = 0, bad = 0, object = 0;
    double worst = 0;
    for (int y = 1; y < H - 1; y++)
        for (int x = 1; x < W - 1; x++) {
            int uniform = 1;
            for (int dy = -1; dy <= 1 && uniform; dy++)
                for (int dx = -1; dx <= 1 && uniform; dx++)
                    for (int c = 0; c < 3; c++) {
                        int i = (y + dy) * W + (x + dx), j = y * W + x;
                        if (fabsf(ref[i * ch + c] - ref[j * ch + c]) > 1.5f / 255 ||
                            fabsf(px[i * 4 + c] - px[j * 4 + c]) > 1.5f / 255)
                            uniform = 0;
                    }
            if (!uniform) continue;
            compared++;
            int is_bg = 1;
            for (int c = 0; c < 3; c++) {
                double diff = fabs(px[(y * W + x) * 4 + c] - ref[(y * W + x) * ch + c]) * 255;
                if (diff > worst) worst = diff;
                if (fabsf(ref[(y * W + x) * ch + c] - o.colors.background[c]) > 1.5f / 255)
                    is_bg = 0;
                if (diff > 2) {
                    bad++;
                    break;
                }
            }
            object += !is_bg;
        }
    cr_expect(compared > W * H / 2, "only %d pixels compared", compared);
    cr_expect(object > W * H / 20, "only %d object pixels compared", object);
    cr_expect(bad == 0, "%s: %d of %d pixels differ by more than 2/255 (worst %.1f)", args, bad,
              compared, worst);
    free(px);
    free(ref);
    csg_scene_free(s);
}

/* The three visible faces of a box in the default view: OpenSCAD shows the
 * top at 250/249 of the face colour and the sides at 0.663 and 0.574 —
 * lighting in the gimbal-rotated world (see shade.c). */
Test(render_image, default_view_colours_match_openscad)
{
    render_view v = {.kind = RAYSCAD_CAMERA_DEFAULT};
    compare_colours("cube([10,20,5]);\n", "--imgsize=200,160", box_node(0, 0, 0, 10, 20, 5, NULL),
                    &v, 200, 160, "Cornfield");
}

Test(render_image, tilted_view_colours_match_openscad)
{
    render_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {3, 2, 1, 63.3, 10, 31.7, 60}};
    compare_colours("translate([-6,-3,-2]) cube([15,11,7]);\n",
                    "--imgsize=200,200 --camera=3,2,1,63.3,10,31.7,60 --colorscheme=Sunset",
                    box_node(-6, -3, -2, 9, 8, 5, NULL), &v, 200, 200, "Sunset");
}

/* A pocket cut into a box: the pocket's floor and walls are the cutter's
 * faces, drawn in the scheme's back colour with OpenSCAD's lighting. */
Test(render_image, pocket_colours_match_openscad)
{
    csg_node *d = csg_node_op(CSG_OP_DIFFERENCE);
    cr_assert_eq(csg_node_add(d, box_node(0, 0, 0, 10, 10, 10, NULL)), 0);
    cr_assert_eq(csg_node_add(d, box_node(2, 2, 5, 8, 8, 15, NULL)), 0);
    render_view v = {.kind = RAYSCAD_CAMERA_DEFAULT};
    compare_colours("difference() { cube(10); translate([2,2,5]) cube([6,6,10]); }\n",
                    "--imgsize=240,200", d, &v, 240, 200, "Cornfield");
}

/* Subtracted surfaces take the scheme's back colour: a top view into a
 * box with a hole cut from above shows the hole's floor (the cutter's face,
 * flipped) in #9dcb51 × 0.777. */
Test(render_image, subtracted_surface_uses_back_colour)
{
    csg_node *d = csg_node_op(CSG_OP_DIFFERENCE);
    cr_assert_eq(csg_node_add(d, box_node(-5, -5, -5, 5, 5, 5, NULL)), 0);
    cr_assert_eq(csg_node_add(d, box_node(-2, -2, 0, 2, 2, 10, NULL)), 0);
    csg_scene *s = scene_of(d, NULL, NULL);
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&top_ortho, NULL, NULL, 0, 31, 31, &cam), 0);
    render_options o = {.width = 31, .height = 31, .samples = 1, .threads = 1};
    cr_assert_eq(render_colors_by_name("Cornfield", &o.colors), 0);
    float *px = render_or_die(s, &cam, &o);
    double k = 0.2 + 1 / sqrt(3.0);
    const float *centre = px + (15 * 31 + 15) * 4, *rim = px + (15 * 31 + 10) * 4;
    for (int i = 0; i < 3; i++) {
        cr_expect(fabs(centre[i] - o.colors.back[i] * k) < 1e-5, "hole floor channel %d", i);
        cr_expect(fabs(rim[i] - o.colors.face[i] * k) < 1e-5, "rim channel %d", i);
    }
    free(px);
    csg_scene_free(s);
}

/* ---- compositing --------------------------------------------------------------- */

/* Two coloured slabs of alpha a and b seen from above.  Each slab shows two
 * surfaces (entering and exiting, both lit by the same factor k since the
 * lights are opposite), so front to back:
 *   C = a·A + (1-a)·a·A + (1-a)²·b·B + (1-a)²(1-b)·b·B + (1-a)²(1-b)²·bg
 * with A, B the slab colours × k. */
Test(render_image, two_transparent_slabs_composite_analytically)
{
    const float ca[4] = {0.9f, 0.2f, 0.1f, 0.3f}, cb[4] = {0.1f, 0.6f, 0.8f, 0.6f};
    csg_node *u = csg_node_op(CSG_OP_UNION);
    cr_assert_eq(csg_node_add(u, box_node(-5, -5, 3, 5, 5, 4, ca)), 0);   /* nearer */
    cr_assert_eq(csg_node_add(u, box_node(-5, -5, -2, 5, 5, -1, cb)), 0); /* farther */
    csg_scene *s = scene_of(u, NULL, NULL);
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&top_ortho, NULL, NULL, 0, 21, 21, &cam), 0);
    render_options o = {.width = 21, .height = 21, .samples = 2, .threads = 2};
    cr_assert_eq(render_colors_by_name("Cornfield", &o.colors), 0);
    float *px = render_or_die(s, &cam, &o);
    double k = 0.2 + 1 / sqrt(3.0), a = ca[3], b = cb[3];
    const float *c = px + (10 * 21 + 10) * 4;
    for (int i = 0; i < 3; i++) {
        double A = ca[i] * k, B = cb[i] * k;
        double expect = a * A + (1 - a) * a * A + (1 - a) * (1 - a) * b * B +
                        (1 - a) * (1 - a) * (1 - b) * b * B +
                        (1 - a) * (1 - a) * (1 - b) * (1 - b) * o.colors.background[i];
        cr_expect(fabs(c[i] - expect) < 1e-5, "channel %d: %.6f, expected %.6f", i, c[i], expect);
    }
    free(px);
    csg_scene_free(s);
}

/* A '#' root over the model: the highlight colour (alpha 128/255) first,
 * then the model's face behind it, both lit alike. */
Test(render_image, highlight_over_model)
{
    csg_scene *s =
        scene_of(box_node(-5, -5, -5, 5, 5, 5, NULL), box_node(-5, -5, -5, 5, 5, 5, NULL), NULL);
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&top_ortho, NULL, NULL, 0, 21, 21, &cam), 0);
    render_options o = {.width = 21, .height = 21, .samples = 1, .threads = 1};
    cr_assert_eq(render_colors_by_name("Cornfield", &o.colors), 0);
    float *px = render_or_die(s, &cam, &o);
    double k = 0.2 + 1 / sqrt(3.0), a = o.colors.highlight[3];
    const float *c = px + (10 * 21 + 10) * 4;
    for (int i = 0; i < 3; i++) {
        double H = fmin(1, o.colors.highlight[i] * k), F = o.colors.face[i] * k;
        double expect = a * H + (1 - a) * F;
        cr_expect(fabs(c[i] - expect) < 1e-5, "channel %d: %.6f, expected %.6f", i, c[i], expect);
    }
    free(px);
    csg_scene_free(s);
}

/* ---- threads and progress ------------------------------------------------------- */

static csg_scene *busy_scene(void)
{
    const float red[4] = {0.8f, 0.1f, 0.1f, 1}, glass[4] = {0.2f, 0.4f, 0.9f, 0.4f};
    csg_node *u = csg_node_op(CSG_OP_UNION);
    csg_node *d = csg_node_op(CSG_OP_DIFFERENCE);
    cr_assert_eq(csg_node_add(d, box_node(-10, -10, -10, 10, 10, 10, NULL)), 0);
    cr_assert_eq(csg_node_add(d, sphere_node(0, 0, 10, 9, NULL)), 0);
    cr_assert_eq(csg_node_add(u, d), 0);
    cr_assert_eq(csg_node_add(u, sphere_node(14, 8, 4, 5, red)), 0);
    cr_assert_eq(csg_node_add(u, sphere_node(-12, -9, 8, 6, glass)), 0);
    return scene_of(u, sphere_node(0, 12, 0, 3, NULL), box_node(-20, 10, -3, -8, 16, 3, NULL));
}

Test(render_image, identical_for_any_thread_count)
{
    csg_scene *s = busy_scene();
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    render_view v = {.kind = RAYSCAD_CAMERA_DEFAULT};
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&v, lo, hi, 1, 97, 61, &cam), 0);
    render_options o = {.width = 97, .height = 61, .samples = 2, .threads = 1};
    cr_assert_eq(render_colors_by_name("Metallic", &o.colors), 0);
    float *one = render_or_die(s, &cam, &o);
    o.threads = 2;
    float *two = render_or_die(s, &cam, &o);
    o.threads = 5;
    float *five = render_or_die(s, &cam, &o);
    size_t bytes = 97 * 61 * 4 * sizeof(float);
    cr_expect(memcmp(one, two, bytes) == 0, "1 and 2 threads differ");
    cr_expect(memcmp(one, five, bytes) == 0, "1 and 5 threads differ");
    /* the image is not trivially uniform */
    int distinct = 0;
    for (int i = 1; i < 97 * 61; i++)
        if (one[i * 4] != one[0]) distinct++;
    cr_expect(distinct > 97 * 61 / 10, "only %d pixels show an object", distinct);
    free(one);
    free(two);
    free(five);
    csg_scene_free(s);
}

typedef struct progress_log {
    pthread_t caller;
    int calls, wrong_thread, backwards;
    double last;
} progress_log;

static void on_progress(void *ud, double done)
{
    progress_log *p = ud;
    if (!pthread_equal(pthread_self(), p->caller)) p->wrong_thread++;
    if (done < p->last) p->backwards++;
    p->last = done;
    p->calls++;
}

Test(render_image, progress_from_calling_thread)
{
    csg_scene *s = busy_scene();
    render_view v = {.kind = RAYSCAD_CAMERA_DEFAULT};
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&v, lo, hi, 1, 200, 150, &cam), 0);
    progress_log log = {.caller = pthread_self()};
    render_options o = {.width = 200,
                        .height = 150,
                        .samples = 1,
                        .threads = 2,
                        .progress = on_progress,
                        .ud = &log};
    cr_assert_eq(render_colors_by_name("Cornfield", &o.colors), 0);
    float *px = render_or_die(s, &cam, &o);
    cr_expect(log.calls >= 1);
    cr_expect_eq(log.wrong_thread, 0);
    cr_expect_eq(log.backwards, 0);
    cr_expect(log.last == 1.0, "last progress %g", log.last);
    free(px);
    csg_scene_free(s);
}

Test(render_image, bad_options_fail_with_message)
{
    csg_scene *s = scene_of(box_node(0, 0, 0, 1, 1, 1, NULL), NULL, NULL);
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&top_ortho, NULL, NULL, 0, 4, 4, &cam), 0);
    render_options o = {.width = 4, .height = 4, .samples = 0, .threads = 1};
    cr_assert_eq(render_colors_by_name("Cornfield", &o.colors), 0);
    float px[64];
    char err[128] = "";
    cr_expect_eq(render_image(s, &cam, &o, px, err, sizeof err), -1);
    cr_expect(err[0] != 0);
    o.samples = 1;
    o.width = 0;
    cr_expect_eq(render_image(s, &cam, &o, px, err, sizeof err), -1);
    csg_scene_free(s);
}
