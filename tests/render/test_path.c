/*
 * test_path.c — the path-traced quality mode (src/render/path_trace.c),
 * against closed forms computed here: the inside of a closed sphere whose
 * wall emits Le and reflects ρ converges to Le/(1 − ρ) (every bounce sees
 * the same wall: the integrating sphere), a Lambertian plane under one
 * point light reads ρ/π·I·cos θ/d², images are the same bytes for any
 * thread count, and interreflection carries a red wall's colour onto the
 * white floor beside it, which direct light alone (--bounces 1) does not.
 */
#include "../../src/csg/csg.h"
#include "../../src/render/render.h"

#include <criterion/criterion.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static double srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static double linear_to_srgb(double c)
{
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1 / 2.4) - 0.055;
}

/* A material of linear albedo rgb (stored sRGB-encoded, as color() does). */
static csg_material albedo(double r, double g, double b)
{
    csg_material m = {.has_color = 1};
    m.rgba[0] = (float)linear_to_srgb(r);
    m.rgba[1] = (float)linear_to_srgb(g);
    m.rgba[2] = (float)linear_to_srgb(b);
    m.rgba[3] = 1;
    return m;
}

static csg_node *box(double x0, double y0, double z0, double x1, double y1, double z1,
                     const csg_material *m)
{
    iv_shape s = {.kind = IV_SHAPE_BOX};
    s.u.box.lo[0] = x0, s.u.box.lo[1] = y0, s.u.box.lo[2] = z0;
    s.u.box.hi[0] = x1, s.u.box.hi[1] = y1, s.u.box.hi[2] = z1;
    csg_node *n = csg_node_shape(&s, csg_affine_identity, m);
    cr_assert_not_null(n);
    return n;
}

static csg_node *sphere(double r, const csg_material *m)
{
    iv_shape s = {.kind = IV_SHAPE_SPHERE};
    s.u.sphere.r = r;
    csg_node *n = csg_node_shape(&s, csg_affine_identity, m);
    cr_assert_not_null(n);
    return n;
}

static csg_scene *scene_of(csg_node **parts, int n)
{
    csg_node *u = csg_node_op(CSG_OP_UNION);
    for (int i = 0; i < n; i++)
        cr_assert_eq(csg_node_add(u, parts[i]), 0);
    csg_node *roots[3] = {u, NULL, NULL};
    char err[256];
    csg_scene *s = csg_scene_new(roots, 3, err, sizeof err);
    cr_assert_not_null(s, "%s", err);
    return s;
}

static render_options opts(int w, int h, int spp)
{
    render_options o = {.width = w, .height = h, .samples = 1, .threads = 2, .path_trace = spp};
    cr_assert_eq(render_colors_by_name("Cornfield", &o.colors), 0);
    memset(o.colors.background, 0, sizeof o.colors.background); /* no sky light */
    return o;
}

static float *render(const csg_scene *s, const render_camera *cam, const render_options *o)
{
    float *px = malloc((size_t)o->width * (size_t)o->height * 4 * sizeof *px);
    cr_assert_not_null(px);
    char err[256];
    cr_assert_eq(render_image(s, cam, o, px, err, sizeof err), 0, "%s", err);
    return px;
}

/* Top view, orthographic, looking down -z at the origin; W×W pixels span
 * 2·50·tan(11.25°) world units, as in test_light.c. */
enum { W = 41 };

static render_camera top_camera(void)
{
    const render_view top = {
        .kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 0, 0, 0, 50}, .ortho = 1};
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&top, NULL, NULL, 0, W, W, &cam), 0);
    return cam;
}

/* The world (x, y) at the centre of pixel (px, py) of the top view. */
static void world_at(const render_camera *cam, int px, int py, double *x, double *y)
{
    double scale = 2 * cam->ortho_half_height / W; /* units per pixel */
    *x = (px + 0.5 - W / 2.0) * scale;
    *y = (W / 2.0 - py - 0.5) * scale;
}

/* Inside a closed shell (sphere 21 minus sphere 20) whose inner wall has
 * linear albedo ρ = 0.5 and emits Le = i·ρ (i = 0.4; the light's centre is
 * the model's, so the 1/d² scale of path_trace.c is 1): L = Le + ρ·L, so
 * every pixel converges to Le/(1 − ρ) = 0.4.  With 256 paths per pixel
 * (Russian roulette, up to 64 bounces) the image mean is within 1 % and
 * each pixel within 6 % (about 4 standard deviations, measured). */
/* The shell of the next two tests: inner radius 20, albedo rho, emitting
 * i·rho, seen from its centre in 8×8 pixels with spp paths each (up to 64
 * bounces); the camera into *cam, the options into *o. */
static csg_scene *integrating_sphere(double rho, double i, int spp, render_camera *cam,
                                     render_options *o)
{
    const double R = 20;
    csg_material m = albedo(rho, rho, rho);
    m.emit = (float)i;
    m.light[3] = (float)R;
    csg_node *shell = csg_node_op(CSG_OP_DIFFERENCE);
    cr_assert_eq(csg_node_add(shell, sphere(R + 1, &m)), 0);
    cr_assert_eq(csg_node_add(shell, sphere(R, &m)), 0);
    const render_view v = {.kind = RAYSCAD_CAMERA_EYE, .v = {0, 0, 0, 10, 3, 2}};
    *o = opts(8, 8, spp);
    o->bounces = 64;
    cr_assert_eq(render_camera_resolve(&v, NULL, NULL, 0, o->width, o->height, cam), 0);
    return scene_of(&shell, 1);
}

Test(path_converges, integrating_sphere_le_over_one_minus_rho)
{
    const double rho = 0.5, i = 0.4;
    render_camera cam;
    render_options o;
    csg_scene *s = integrating_sphere(rho, i, 256, &cam, &o);
    float *img = render(s, &cam, &o);
    const double want = i * rho / (1 - rho);
    double mean = 0;
    for (int p = 0; p < o.width * o.height; p++)
        for (int c = 0; c < 3; c++) {
            double got = srgb_to_linear(img[4 * p + c]);
            mean += got / (3.0 * o.width * o.height);
            cr_expect(fabs(got - want) <= 0.06 * want, "pixel %d channel %d: %.4f, expected %.4f",
                      p, c, got, want);
        }
    cr_expect(fabs(mean - want) <= 0.01 * want, "mean %.5f, expected %.5f", mean, want);
    free(img);
    csg_scene_free(s);
}

/* The same sphere glowing brighter than white: Le/(1 − ρ) = 2.  Clamped,
 * every pixel shows 1; unclamped, the mean over passes (rayscad's
 * progressive refinement: pass k draws its own paths) of 4 paths each, in
 * linear light, converges to 2 — within 1.5 % in the image's mean after
 * 32 passes — and passes differ from one another. */
Test(path_converges, unclamped_passes_average_to_the_light)
{
    const double rho = 0.5, i = 2;
    render_camera cam;
    render_options o;
    csg_scene *s = integrating_sphere(rho, i, 4, &cam, &o);
    const double want = i * rho / (1 - rho);
    float *img = render(s, &cam, &o);
    for (int p = 0; p < 4 * o.width * o.height; p++)
        cr_assert(img[p] <= 1, "clamped: %g", img[p]);
    free(img);
    o.unclamped = 1;
    const int passes = 32, n = o.width * o.height;
    double mean = 0, first = -1;
    int differ = 0;
    for (int k = 0; k < passes; k++) {
        o.pass = k;
        img = render(s, &cam, &o);
        double pm = 0;
        for (int p = 0; p < n; p++)
            for (int c = 0; c < 3; c++)
                pm += srgb_to_linear(img[4 * p + c]) / (3.0 * n);
        differ += first >= 0 && pm != first;
        if (k == 0) first = pm;
        mean += pm / passes;
        free(img);
    }
    cr_expect(fabs(mean - want) <= 0.015 * want, "mean %.5f, expected %.5f", mean, want);
    cr_expect_eq(differ, passes - 1, "every pass draws its own paths");
    csg_scene_free(s);
}

/* A plane of albedo ρ = 0.5 (the top of a box, z = 0) under a point light
 * at height 30 with intensity i = 0.5: the light's radiant intensity is
 * I = π·i·d_c² (d_c = 30.5, from the light to the centre of the box), and
 * the plane reads ρ/π·I·cos θ/d² at (x, y).  Direct light from a point is
 * not random and bounce rays leave into a black sky, so only the pixel's
 * footprint (its 16 samples spread over a pixel, where the value is smooth)
 * separates the two: 0.2 % here. */
Test(path_converges, point_light_on_a_plane_is_lambert)
{
    const double rho = 0.5, i = 0.5, hgt = 30;
    csg_material m = albedo(rho, rho, rho);
    csg_node *plane = box(-50, -50, -1, 50, 50, 0, &m);
    csg_scene *s = scene_of(&plane, 1);
    render_options o = opts(W, W, 16);
    o.nlights = 1;
    o.lights[0] = (render_light){{0, 0, hgt}, 0, i};
    render_camera cam = top_camera();
    float *img = render(s, &cam, &o);
    const double dc = hgt + 0.5, I = M_PI * i * dc * dc;
    int checked = 0;
    for (int py = 2; py < W; py += 6)
        for (int px = 1; px < W; px += 5) {
            double x, y;
            world_at(&cam, px, py, &x, &y);
            double d2 = x * x + y * y + hgt * hgt, cs = hgt / sqrt(d2);
            double want = rho / M_PI * I * cs / d2;
            double got = srgb_to_linear(img[4 * (py * W + px)]);
            cr_expect(fabs(got - want) <= 0.002 * want, "(%.2f, %.2f): %.5f, expected %.5f", x, y,
                      got, want);
            checked++;
        }
    cr_assert_gt(checked, 40);
    free(img);
    csg_scene_free(s);
}

/* A floor, a red wall on it and a white one: the scene of the next test. */
static csg_scene *corner(void)
{
    csg_material white = albedo(0.8, 0.8, 0.8), red = albedo(0.8, 0.05, 0.05);
    csg_node *parts[3] = {box(-30, -30, -1, 30, 30, 0, &white), box(8, -30, 0, 11, 30, 40, &red),
                          box(-30, 12, 0, 8, 15, 40, &white)};
    return scene_of(parts, 3);
}

Test(path_threads, byte_identical_for_any_thread_count)
{
    csg_scene *s = corner();
    render_camera cam = top_camera();
    render_options o = opts(W, W, 8);
    o.nlights = 1;
    o.lights[0] = (render_light){{-10, -10, 25}, 3, 0.8};
    o.seed = 7;
    o.threads = 1;
    float *a = render(s, &cam, &o);
    o.threads = 3;
    float *b = render(s, &cam, &o);
    o.threads = 0;
    float *c = render(s, &cam, &o);
    size_t n = (size_t)W * W * 4 * sizeof *a;
    cr_expect(memcmp(a, b, n) == 0, "1 and 3 threads differ (seed 7)");
    cr_expect(memcmp(a, c, n) == 0, "1 thread and all cores differ (seed 7)");
    free(a);
    free(b);
    free(c);
    csg_scene_free(s);
}

/* The white floor next to the red wall: direct light alone leaves it
 * neutral (red/green = 1, the albedo's ratio); with interreflection light
 * that bounced off the wall arrives red, and the ratio rises.  Averaged
 * over a strip of pixels 1–4 units from the wall, the rise is several
 * percent; 2 % is asked. */
Test(path_interreflection, red_wall_bleeds_onto_white_floor)
{
    csg_scene *s = corner();
    render_camera cam = top_camera();
    render_options o = opts(W, W, 64);
    o.nlights = 1;
    o.lights[0] = (render_light){{-10, -10, 25}, 0, 0.8};
    double ratio[2];
    for (int k = 0; k < 2; k++) {
        o.bounces = k == 0 ? 1 : 8;
        float *img = render(s, &cam, &o);
        double r = 0, g = 0;
        for (int py = 0; py < W; py++)
            for (int px = 0; px < W; px++) {
                double x, y;
                world_at(&cam, px, py, &x, &y);
                if (x < 4 || x > 7 || y < -8 || y > 8) continue;
                r += srgb_to_linear(img[4 * (py * W + px)]);
                g += srgb_to_linear(img[4 * (py * W + px) + 1]);
            }
        cr_assert_gt(g, 0);
        ratio[k] = r / g;
        free(img);
    }
    cr_expect(fabs(ratio[0] - 1) < 1e-4, "direct only: red/green %.5f, expected 1", ratio[0]);
    cr_expect(ratio[1] > 1.02 * ratio[0], "red/green %.4f with bounces, %.4f direct only", ratio[1],
              ratio[0]);
    csg_scene_free(s);
}
