/*
 * test_light.c — transparency and the opt-in light model, each checked
 * against a closed form computed here from the geometry (not from the
 * renderer's code paths): front-to-back compositing of slabs and shells,
 * the missing inner face of a union, order independence through the
 * language (every permutation of a file's objects, bit for bit), shadows
 * from the key light and a point light through opaque and transparent
 * occluders, a mirror that shows what the reflection law says,
 * Beer–Lambert absorption over a slab's thickness, and secondary rays that
 * start just off a sphere on the side they leave to (its equation says
 * which).
 */
#include "../../src/csg/csg.h"
#include "../../src/render/render.h"
#include "../../src/render/surface.h"
#include "../../src/scad/scad.h"

#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double K = 0.57735026918962576; /* 1/√3 */

/* ---- scenes ------------------------------------------------------------- */

static csg_material material(const float *rgba)
{
    csg_material m = {.rgba = {1, 1, 1, 1}};
    if (rgba) {
        memcpy(m.rgba, rgba, sizeof m.rgba);
        m.has_color = 1;
    }
    return m;
}

static csg_node *box_m(const double lo[3], const double hi[3], const csg_affine xf,
                       const csg_material *m)
{
    iv_shape s = {.kind = IV_SHAPE_BOX};
    memcpy(s.u.box.lo, lo, sizeof s.u.box.lo);
    memcpy(s.u.box.hi, hi, sizeof s.u.box.hi);
    csg_node *n = csg_node_shape(&s, xf ? xf : csg_affine_identity, m);
    cr_assert_not_null(n);
    return n;
}

static csg_node *box(double x0, double y0, double z0, double x1, double y1, double z1,
                     const float *rgba)
{
    csg_material m = material(rgba);
    const double lo[3] = {x0, y0, z0}, hi[3] = {x1, y1, z1};
    return box_m(lo, hi, NULL, &m);
}

static csg_node *sphere(double cx, double cy, double cz, double r, const float *rgba)
{
    iv_shape s = {.kind = IV_SHAPE_SPHERE};
    s.u.sphere.r = r;
    csg_affine xf = {1, 0, 0, cx, 0, 1, 0, cy, 0, 0, 1, cz};
    csg_material m = material(rgba);
    csg_node *n = csg_node_shape(&s, xf, &m);
    cr_assert_not_null(n);
    return n;
}

static csg_node *op(csg_op o, csg_node *a, csg_node *b)
{
    csg_node *n = csg_node_op(o);
    cr_assert_eq(csg_node_add(n, a), 0);
    cr_assert_eq(csg_node_add(n, b), 0);
    return n;
}

static csg_scene *scene1(csg_node *model)
{
    csg_node *roots[3] = {model, NULL, NULL};
    char err[256];
    csg_scene *s = csg_scene_new(roots, 3, err, sizeof err);
    cr_assert_not_null(s, "%s", err);
    return s;
}

/* Top view, orthographic: +x right, +y up, looking down -z; a W×W image
 * spans 2·50·tan(11.25°) world units (OpenSCAD's scale at dist 50). */
static const render_view top = {
    .kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 0, 0, 0, 50}, .ortho = 1};
enum { W = 41 };

static render_options opts(void)
{
    render_options o = {.width = W, .height = W, .samples = 1, .threads = 2};
    cr_assert_eq(render_colors_by_name("Cornfield", &o.colors), 0);
    return o;
}

static float *render(const csg_scene *s, const render_camera *cam, const render_options *o)
{
    float *px = malloc((size_t)o->width * (size_t)o->height * 4 * sizeof *px);
    char err[256];
    cr_assert_eq(render_image(s, cam, o, px, err, sizeof err), 0, "%s", err);
    return px;
}

static render_camera top_camera(void)
{
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&top, NULL, NULL, 0, W, W, &cam), 0);
    return cam;
}

/* The pixel whose centre looks down at world (x, y). */
static void pixel_at(const render_camera *cam, double x, double y, int *px, int *py)
{
    double scale = W / (2 * cam->ortho_half_height); /* pixels per unit */
    *px = (int)floor(W / 2.0 + x * scale);
    *py = (int)floor(W / 2.0 - y * scale);
}

static const float *pix(const float *img, int x, int y)
{
    return img + ((size_t)y * W + (size_t)x) * 4;
}

static void expect_rgb(const float *got, const double want[3], double tol, const char *what)
{
    for (int i = 0; i < 3; i++)
        cr_expect(fabs(got[i] - want[i]) <= tol, "%s, channel %d: %.6f, expected %.6f", what, i,
                  got[i], want[i]);
}

/* The preview's factor for a world normal n in the top view: lights
 * ±(-1,-1,1)/√3 in (right, forward, up) = (x, -z, y). */
static double preview_factor(const double n[3])
{
    return 0.2 + fabs(K * (-n[0] + n[2] + n[1]));
}

/* ---- compositing ------------------------------------------------------------ */

/* A transparent shell (sphere 12 minus sphere 11, alpha a) around an opaque
 * red cube, straight down the middle: the shell's outer face (normal +z),
 * its inner face (the subtracted sphere, normal -z, shaded alike), then the
 * cube's top: a·S + (1-a)·a·S + (1-a)²·R, every factor 0.2 + 1/√3. */
Test(light_composite, shell_shows_opaque_core)
{
    const float glass[4] = {0.3f, 0.6f, 1.0f, 0.3f}, red[4] = {0.86f, 0.08f, 0.24f, 1};
    csg_node *u = op(CSG_OP_UNION, box(-4, -4, -4, 4, 4, 4, red),
                     op(CSG_OP_DIFFERENCE, sphere(0, 0, 0, 12, glass), sphere(0, 0, 0, 11, glass)));
    csg_scene *s = scene1(u);
    render_camera cam = top_camera();
    render_options o = opts();
    float *img = render(s, &cam, &o);
    double f = 0.2 + K, a = glass[3], want[3];
    for (int i = 0; i < 3; i++)
        want[i] = a * glass[i] * f + (1 - a) * a * glass[i] * f + (1 - a) * (1 - a) * red[i] * f;
    expect_rgb(pix(img, W / 2, W / 2), want, 1e-5, "shell over core");
    free(img);
    csg_scene_free(s);
}

/* Two overlapping transparent spheres, centres (±3, 0, 0), r = 5, as one
 * union.  At x = 1 the ray enters the right sphere at z = +√21 and leaves
 * at -√21; the left sphere's surfaces (z = ±3) lie inside the union and
 * must not show: exactly two surfaces, with the right sphere's normals. */
Test(light_composite, union_of_transparent_spheres_has_no_inner_face)
{
    const float c[4] = {0.2f, 0.5f, 1.0f, 0.4f};
    csg_scene *s = scene1(op(CSG_OP_UNION, sphere(-3, 0, 0, 5, c), sphere(3, 0, 0, 5, c)));
    render_camera cam = top_camera();
    render_options o = opts();
    float *img = render(s, &cam, &o);
    int px, py;
    pixel_at(&cam, 1, 0, &px, &py);
    double o3[3], d[3];
    render_camera_ray(&cam, W, W, px + 0.5, py + 0.5, o3, d);
    double x = o3[0] - 3, y = o3[1], z = sqrt(25 - x * x - y * y);
    double n_in[3] = {x / 5, y / 5, z / 5}, n_out[3] = {x / 5, y / 5, -z / 5};
    double f1 = preview_factor(n_in), f2 = preview_factor(n_out), a = c[3], want[3];
    for (int i = 0; i < 3; i++)
        want[i] =
            a * c[i] * f1 + (1 - a) * a * c[i] * f2 + (1 - a) * (1 - a) * o.colors.background[i];
    expect_rgb(pix(img, px, py), want, 1e-5, "lens of the union");
    free(img);
    csg_scene_free(s);
}

/* A cut shows the cutter's own colour: a red cube minus a blue box from
 * above shows the pocket's floor in blue (as OpenSCAD's preview does). */
Test(light_composite, difference_cut_in_cutter_colour)
{
    const float red[4] = {1, 0, 0, 1}, blue[4] = {0.1f, 0.2f, 0.9f, 1};
    csg_scene *s =
        scene1(op(CSG_OP_DIFFERENCE, box(-5, -5, -5, 5, 5, 5, red), box(-2, -2, 0, 2, 2, 9, blue)));
    render_camera cam = top_camera();
    render_options o = opts();
    float *img = render(s, &cam, &o);
    double want[3];
    for (int i = 0; i < 3; i++)
        want[i] = blue[i] * (0.2 + K);
    expect_rgb(pix(img, W / 2, W / 2), want, 1e-5, "pocket floor");
    free(img);
    csg_scene_free(s);
}

/* ---- order independence, through the language -------------------------------- */

static csg_scene *scene_of_source(const char *src)
{
    scad_options so = {0};
    scad_result r;
    cr_assert_eq(scad_eval_string("perm.scad", src, &so, &r), 0, "%s", src);
    csg_node *roots[3] = {r.model, r.highlight, r.background};
    r.model = r.highlight = r.background = NULL;
    scad_result_free(&r);
    char err[256];
    csg_scene *s = csg_scene_new(roots, 3, err, sizeof err);
    cr_assert_not_null(s, "%s", err);
    return s;
}

static float *render_source(const char *src, const render_options *o)
{
    csg_scene *s = scene_of_source(src);
    render_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 60, 0, 30, 80}};
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&v, NULL, NULL, 0, o->width, o->height, &cam), 0);
    float *px = malloc((size_t)o->width * (size_t)o->height * 4 * sizeof *px);
    char err[256];
    cr_assert_eq(render_image(s, &cam, o, px, err, sizeof err), 0, "%s", err);
    csg_scene_free(s);
    return px;
}

/* Every permutation of five top-level objects (overlapping transparent
 * and opaque solids, a difference, a '#' and a '%' subtree) renders the
 * same bytes — in the preview look and in the light model. */
Test(light_order, permutations_render_bit_for_bit)
{
    static const char *const obj[5] = {
        "color([0.2,0.5,1],0.4) sphere(8);\n",
        "color([1,0.3,0.2],0.5) translate([6,2,1]) sphere(7);\n",
        "color(\"gold\") difference() { translate([-4,-12,-3]) cube([8,8,8]); sphere(6); }\n",
        "#translate([-14,4,-2]) cylinder(h=9, r=3);\n",
        "color([0.4,0.9,0.4],0.3) translate([3,-3,-10]) cube([12,12,3], $rs_reflect=0.4);\n",
    };
    render_options lit = {.width = 48,
                          .height = 36,
                          .samples = 2,
                          .threads = 3,
                          .shadows = 1,
                          .xray = 0.6,
                          .nlights = 1};
    lit.lights[0] = (render_light){{20, -30, 40}, 3, 1};
    cr_assert_eq(render_colors_by_name("Cornfield", &lit.colors), 0);
    render_options plain = {.width = 48, .height = 36, .samples = 2, .threads = 3};
    plain.colors = lit.colors;
    const render_options *modes[2] = {&plain, &lit};
    size_t bytes = 48 * 36 * 4 * sizeof(float);
    for (int mode = 0; mode < 2; mode++) {
        float *first = NULL;
        int perm[5] = {0, 1, 2, 3, 4}, count = 0;
        /* all 120 orders, Heap's algorithm (iterative) */
        int c[5] = {0};
        for (int i = 0;;) {
            char src[2048] = "";
            for (int k = 0; k < 5; k++)
                strcat(src, obj[perm[k]]);
            float *img = render_source(src, modes[mode]);
            count++;
            if (!first) {
                first = img;
            } else {
                cr_expect(memcmp(first, img, bytes) == 0, "mode %d: order %d%d%d%d%d differs", mode,
                          perm[0], perm[1], perm[2], perm[3], perm[4]);
                free(img);
            }
            while (i < 5 && c[i] >= i)
                c[i++] = 0;
            if (i == 5) break;
            int j = i % 2 ? c[i] : 0, t = perm[j];
            perm[j] = perm[i];
            perm[i] = t;
            c[i]++;
            i = 0;
        }
        cr_expect_eq(count, 120);
        free(first);
    }
}

/* ---- shadows -------------------------------------------------------------------- */

/* A grey floor and a 4-unit cube on it, lit by the preview's key light
 * (--shadows).  In the top view the key light comes from (-1,1,1)/√3, so
 * the floor point (3,-3,0) sees the light through the cube: its value is
 * ambient only, 0.2·grey, while (-3,3,0) gets 0.2 + 1/√3 as in the preview.
 * With a half-transparent cube the light crosses two faces: (1-a)². */
static void key_light_shadow(double alpha)
{
    const float grey[4] = {0.5f, 0.5f, 0.5f, 1};
    const float cube_c[4] = {0.9f, 0.1f, 0.1f, (float)alpha};
    csg_scene *s = scene1(
        op(CSG_OP_UNION, box(-12, -12, -1, 12, 12, 0, grey), box(-2, -2, 0, 2, 2, 4, cube_c)));
    render_camera cam = top_camera();
    render_options o = opts();
    o.shadows = 1;
    float *img = render(s, &cam, &o);
    int sx, sy, lx, ly;
    pixel_at(&cam, 3, -3, &sx, &sy);
    pixel_at(&cam, -3, 3, &lx, &ly);
    double T = alpha >= 1 ? 0 : (1 - alpha) * (1 - alpha), shadow[3], lit[3];
    for (int i = 0; i < 3; i++) {
        shadow[i] = grey[i] * (0.2 + K * T);
        lit[i] = grey[i] * (0.2 + K);
    }
    expect_rgb(pix(img, sx, sy), shadow, 1e-5, "floor in the cube's shadow");
    expect_rgb(pix(img, lx, ly), lit, 1e-5, "floor in the light");
    free(img);
    csg_scene_free(s);
}

Test(light_shadow, key_light_opaque_occluder)
{
    key_light_shadow(1);
}

Test(light_shadow, key_light_transparent_occluder_attenuates)
{
    key_light_shadow(0.35);
}

/* A point light at (40, 0, 40) over a grey floor with a pillar at the
 * origin: the floor at (-4, 0) is shadowed (its ray to the light passes
 * x = -2 at z = 1.8 < 4), at (6, 6) it is lit with cos θ = n·L.  Samples
 * are jittered inside the pixel, so the expected values come from the
 * floor points at each sample's reach; a far light keeps cos θ within
 * 1e-3 across a pixel. */
Test(light_shadow, point_light_darkens_by_the_expected_factor)
{
    const float grey[4] = {0.6f, 0.6f, 0.6f, 1};
    csg_scene *s =
        scene1(op(CSG_OP_UNION, box(-12, -12, -1, 12, 12, 0, grey), box(-2, -2, 0, 2, 2, 4, grey)));
    render_camera cam = top_camera();
    render_options o = opts();
    o.nlights = 1;
    o.lights[0] = (render_light){{40, 0, 40}, 0, 1};
    float *img = render(s, &cam, &o);
    int sx, sy, lx, ly;
    pixel_at(&cam, -4, 0, &sx, &sy);
    pixel_at(&cam, 6, 6, &lx, &ly);
    double dl[3] = {40 - 6, -6, 40},
           cosl = dl[2] / sqrt(dl[0] * dl[0] + dl[1] * dl[1] + dl[2] * dl[2]);
    double shadow[3], lit[3];
    for (int i = 0; i < 3; i++) {
        shadow[i] = grey[i] * 0.2;
        lit[i] = grey[i] * (0.2 + cosl);
    }
    expect_rgb(pix(img, sx, sy), shadow, 1e-5, "floor in the pillar's shadow");
    expect_rgb(pix(img, lx, ly), lit, 4e-3, "floor in the light");
    /* An area light of the same power softens the edge but keeps the umbra
     * and the fully lit floor: values between, never outside. */
    o.lights[0].radius = 6;
    float *soft = render(s, &cam, &o);
    expect_rgb(pix(soft, sx, sy), shadow, 1e-5, "umbra under an area light");
    int pen = 0;
    for (int x = 0; x < W; x++) {
        const float *p = pix(soft, x, sy);
        if (p[0] > shadow[0] + 0.01 && p[0] < lit[0] - 0.05) pen++;
    }
    cr_expect(pen >= 1, "no penumbra along the shadow's row");
    free(soft);
    free(img);
    csg_scene_free(s);
}

/* ---- mirror ------------------------------------------------------------------------ */

/* A perfect mirror through the origin with normal (-1,0,1)/√2 (a box turned
 * -45° about y) and a red block at x in [-30,-20], |y|, |z| <= 3.  A ray
 * looking down -z at (0, y) reflects into -x along z = 0 and meets the
 * block's +x face when |y| < 3: red × (0.2 + 1/√3) (that face's preview
 * factor); at |y| = 4 it escapes to the background. */
static void mirror_checks(const csg_scene *s)
{
    render_camera cam = top_camera();
    render_options o = opts();
    float *img = render(s, &cam, &o);
    int px, py;
    double want[3], bg[3];
    for (int i = 0; i < 3; i++) {
        want[i] = (i == 0 ? 1.0 : 0.0) * (0.2 + K);
        bg[i] = o.colors.background[i];
    }
    pixel_at(&cam, 0.3, 0.3, &px, &py);
    expect_rgb(pix(img, px, py), want, 1e-5, "the block in the mirror");
    pixel_at(&cam, 0.3, 2.2, &px, &py);
    expect_rgb(pix(img, px, py), want, 1e-5, "the block in the mirror, off centre");
    pixel_at(&cam, 0.3, 4.3, &px, &py);
    expect_rgb(pix(img, px, py), bg, 1e-5, "the sky beside it");
    free(img);
}

Test(light_mirror, reflection_shows_what_geometry_says)
{
    const float red[4] = {1, 0, 0, 1}, silver[4] = {0.75f, 0.75f, 0.75f, 1};
    const double c = sqrt(0.5);
    /* rotation -45° about y: z axis -> (-c, 0, c) */
    const csg_affine turn = {c, 0, -c, 0, 0, 1, 0, 0, c, 0, c, 0};
    csg_material mirror = material(silver);
    mirror.reflect = 1;
    const double lo[3] = {-6, -6, -2}, hi[3] = {6, 6, 0};
    csg_scene *s =
        scene1(op(CSG_OP_UNION, box_m(lo, hi, turn, &mirror), box(-30, -3, -3, -20, 3, 3, red)));
    mirror_checks(s);
    csg_scene_free(s);
}

/* The same scene in the language: $rs_reflect set on a module call reaches
 * the leaves below it, dynamically scoped like $fn. */
Test(light_mirror, rs_reflect_through_the_language)
{
    csg_scene *s = scene_of_source("module plate() cube([12,12,2], center=true);\n"
                                   "color(\"silver\") rotate([0,-45,0]) translate([0,0,-1])\n"
                                   "    plate($rs_reflect = 1);\n"
                                   "color(\"red\") translate([-30,-3,-3]) cube([10,6,6]);\n");
    mirror_checks(s);
    csg_scene_free(s);
}

/* ---- secondary rays ---------------------------------------------------------- */

/* Where o + t·d (d unit) meets the sphere of centre c and radius r, by the
 * quadratic: t0 <= t1, or 0 when it misses. */
static int sphere_ts(const double c[3], double r, const double o[3], const double d[3], double *t0,
                     double *t1)
{
    double oc[3] = {o[0] - c[0], o[1] - c[1], o[2] - c[2]};
    double b = dot3(oc, d), disc = b * b - (dot3(oc, oc) - r * r);
    if (disc < 0) return 0;
    *t0 = -b - sqrt(disc);
    *t1 = -b + sqrt(disc);
    return 1;
}

static double dist3(const double a[3], const double b[3])
{
    double v[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return sqrt(dot3(v, v));
}

/* Direction k of n spread evenly over the unit sphere (a Fibonacci
 * lattice: the same directions every run, no seed). */
static void lattice_dir(int k, int n, double u[3])
{
    double z = 1 - (2 * k + 1.0) / n, s = sqrt(1 - z * z), phi = k * 2.39996322972865332;
    u[0] = s * cos(phi);
    u[1] = s * sin(phi);
    u[2] = z;
}

/* A ray spawned from hit h of the sphere (c, r) along dir: its origin lies
 * within eps of h's point, off the surface by `side`·eps (+1 outside, -1
 * inside: `radial` = 1 for a step along the normal, else the cosine of the
 * step to it) by the sphere's own equation, and the scene agrees: traced
 * from there, a ray that leaves meets nothing and one that goes in starts
 * inside (a clip at t = 0) and leaves where the quadratic says. */
static void expect_spawn(const csg_scene *s, iv_arena *a, const render_hit *h, const double dir[3],
                         render_spawn rule, double eps, const double c[3], double r, int side,
                         double radial, int k)
{
    double o[3];
    render_ray_spawn(h, dir, rule, eps, o);
    double step = dist3(o, h->p), off = dist3(o, c) - r;
    cr_expect(fabs(step - eps) <= 1e-6 * eps, "ray %d: origin %.3g from the hit, not eps %.3g", k,
              step, eps);
    cr_expect(side * off > 0 && fabs(fabs(off) - radial * eps) <= 1e-3 * eps,
              "ray %d: origin %.3g off the surface, expected %s%.3g", k, off, side > 0 ? "+" : "-",
              radial * eps);
    iv_list l;
    memset(&l, 0, sizeof l);
    cr_assert_eq(csg_trace(s, RAYSCAD_ROOT_MODEL, o, dir, 0, INFINITY, a, &l), 0);
    if (side > 0) {
        cr_expect_eq(l.n, 0, "ray %d: leaves the sphere but meets it again at t = %g", k,
                     l.n ? l.v[0].enter.t : 0);
    } else {
        double t0, t1, dl = sqrt(dot3(dir, dir)), du[3] = {dir[0] / dl, dir[1] / dl, dir[2] / dl};
        cr_assert(sphere_ts(c, r, o, du, &t0, &t1));
        cr_expect(l.n == 1 && l.v[0].enter.prim == IV_PRIM_NONE && l.v[0].enter.t == 0 &&
                      fabs(l.v[0].exit.t * dl - t1) <= 1e-9 * r,
                  "ray %d: does not start inside the sphere and leave at t = %g", k, t1);
    }
    iv_arena_reset(a);
}

/* render_ray_spawn on a sphere, against its equation: 256 rays from all
 * around enter it, and at the entry the mirror ray and a light ray leave
 * outward, the refracted ray and one going straight on (the path tracer's
 * pass) start inside; at the exit, with the path tracer's facing, the
 * internally reflected ray stays inside and a straight one is outside. */
Test(light_spawn, origin_is_eps_off_the_surface_on_the_side_the_ray_takes)
{
    const double c[3] = {1, -2, 3}, r = 10, eta = 1 / 1.5;
    csg_scene *s = scene1(sphere(c[0], c[1], c[2], r, NULL));
    iv_arena *a = iv_arena_new(0);
    cr_assert_not_null(a);
    const double eps = render_ray_offset(2 * r * sqrt(3.0)); /* model_scale's size */
    enum { N = 256 };
    for (int k = 0; k < N; k++) {
        double u[3], v[3], o[3], d[3];
        lattice_dir(k, N, u);
        lattice_dir((37 * k + 11) % N, N, v);
        for (int i = 0; i < 3; i++) {
            o[i] = c[i] + 25 * u[i];
            d[i] = c[i] + 0.9 * r * v[i] - o[i]; /* through a point inside */
        }
        double dl = sqrt(dot3(d, d)), t0, t1;
        for (int i = 0; i < 3; i++)
            d[i] /= dl;
        cr_assert(sphere_ts(c, r, o, d, &t0, &t1));

        iv_bound b;
        cr_assert_eq(csg_trace_first(s, RAYSCAD_ROOT_MODEL, o, d, 0, INFINITY, a, &b), 1);
        cr_expect(fabs(b.t - t0) <= 1e-9 * r, "ray %d: entry at %.12g, expected %.12g", k, b.t, t0);
        render_hit h;
        render_surface_hit(s, NULL, &b, b.t, o, d, RENDER_GRAZE_ENTERS, &h);
        iv_arena_reset(a);
        cr_expect(h.entering, "ray %d: the entry is not an entry", k);
        double cosi = -dot3(d, h.nf); /* the step along d, to the normal */

        double rd[3], td[3];
        render_reflect_dir(d, h.nf, rd);
        expect_spawn(s, a, &h, rd, RENDER_SPAWN_SIDE, eps, c, r, +1, 1, k);
        expect_spawn(s, a, &h, h.nf, RENDER_SPAWN_SIDE, eps, c, r, +1, 1, k);
        cr_assert(render_refract_dir(d, h.nf, eta, td) >= 0);
        expect_spawn(s, a, &h, td, RENDER_SPAWN_SIDE, eps, c, r, -1, 1, k);
        expect_spawn(s, a, &h, d, RENDER_SPAWN_AHEAD, eps, c, r, -1, cosi, k);

        /* on along the refracted ray to the exit, seen as the path tracer sees it */
        double oi[3];
        render_ray_spawn(&h, td, RENDER_SPAWN_SIDE, eps, oi);
        iv_list l;
        memset(&l, 0, sizeof l);
        cr_assert_eq(csg_trace(s, RAYSCAD_ROOT_MODEL, oi, td, 0, INFINITY, a, &l), 0);
        cr_assert_eq(l.n, 1);
        iv_bound out = l.v[0].exit;
        render_hit x;
        render_surface_hit(s, NULL, &out, out.t, oi, td, RENDER_GRAZE_LEAVES, &x);
        iv_arena_reset(a);
        cr_expect(!x.entering, "ray %d: the exit is not an exit", k);
        render_reflect_dir(td, x.nf, rd);
        expect_spawn(s, a, &x, rd, RENDER_SPAWN_SIDE, eps, c, r, -1, 1, k);
        expect_spawn(s, a, &x, td, RENDER_SPAWN_AHEAD, eps, c, r, +1, -dot3(td, x.nf), k);
    }
    iv_arena_free(a);
    csg_scene_free(s);
}

/* Every kind of solid takes the optical $-variables: spheres, cylinders,
 * 2D shapes under an extrusion (set on the extrusion call, inherited by the
 * 2D children), polyhedra and hulls — each leaf's material says so. */
Test(light_materials, every_primitive_takes_rs_variables)
{
    const char *src[] = {
        "sphere(3, $rs_reflect = 0.5);",
        "cylinder(h = 2, r = 1, $rs_reflect = 0.5);",
        "cylinder(h = 2, r = 1, $fn = 6, $rs_reflect = 0.5);",
        "linear_extrude(2, $rs_reflect = 0.5) square(3);",
        "linear_extrude(2, $rs_reflect = 0.5) circle(3);",
        "rotate_extrude($rs_reflect = 0.5) translate([4, 0]) circle(1);",
        "polyhedron([[0,0,0],[1,0,0],[0,1,0],[0,0,1]], [[0,1,2],[0,3,1],[0,2,3],[1,3,2]], "
        "$rs_reflect = 0.5);",
        "hull($rs_reflect = 0.5) { cube(1); translate([3, 0, 0]) cube(1); }",
        "square(2, $rs_reflect = 0.5);",
    };
    for (size_t i = 0; i < sizeof src / sizeof src[0]; i++) {
        csg_scene *s = scene_of_source(src[i]);
        cr_assert_gt(csg_scene_prim_count(s), 0, "%s", src[i]);
        for (int p = 0; p < csg_scene_prim_count(s); p++)
            cr_expect_float_eq(csg_scene_material(s, p)->reflect, 0.5f, 1e-6, "%s", src[i]);
        csg_scene_free(s);
    }
}

/* ---- absorption ---------------------------------------------------------------------- */

/* A slab of thickness L seen from above: Beer–Lambert gives transmittance
 * exp(-σL), and the slab shows its lit colour with the rest as opacity:
 * C·(1 - e^{-σL}) + e^{-σL}·bg, the exit face adding nothing. */
Test(light_absorb, beer_lambert_over_a_slab)
{
    const float glass[4] = {0.2f, 0.7f, 0.9f, 0.5f};
    const double sigma = 0.15, L = 3.5;
    csg_material m = material(glass);
    m.absorb = (float)sigma;
    const double lo[3] = {-8, -8, -1}, hi[3] = {8, 8, -1 + L};
    csg_scene *s = scene1(box_m(lo, hi, NULL, &m));
    render_camera cam = top_camera();
    render_options o = opts();
    float *img = render(s, &cam, &o);
    double T = exp(-(double)m.absorb * L), want[3];
    for (int i = 0; i < 3; i++)
        want[i] = glass[i] * (0.2 + K) * (1 - T) + T * o.colors.background[i];
    expect_rgb(pix(img, W / 2, W / 2), want, 1e-5, "absorbing slab");
    free(img);
    csg_scene_free(s);
}

/* --absorb=T: a colour's alpha is the opacity of T units, so a slab of
 * thickness L has opacity 1 - (1-a)^(L/T); twice as thick, (1-a)^(2L/T). */
Test(light_absorb, absorb_mode_scales_alpha_with_thickness)
{
    const float glass[4] = {0.9f, 0.4f, 0.1f, 0.4f};
    render_camera cam = top_camera();
    for (int k = 1; k <= 2; k++) {
        double L = 2.5 * k;
        csg_scene *s = scene1(box(-8, -8, 0, 8, 8, L, glass));
        render_options o = opts();
        o.absorb = 5;
        float *img = render(s, &cam, &o);
        double T = pow(1 - glass[3], L / o.absorb), want[3];
        for (int i = 0; i < 3; i++)
            want[i] = glass[i] * (0.2 + K) * (1 - T) + T * o.colors.background[i];
        expect_rgb(pix(img, W / 2, W / 2), want, 1e-5, k == 1 ? "thin slab" : "thick slab");
        free(img);
        csg_scene_free(s);
    }
}

/* --xray: an opaque cube becomes two surfaces of opacity x. */
Test(light_absorb, xray_makes_opaque_solids_see_through)
{
    csg_scene *s = scene1(box(-5, -5, -5, 5, 5, 5, NULL));
    render_camera cam = top_camera();
    render_options o = opts();
    o.xray = 0.25;
    float *img = render(s, &cam, &o);
    double x = o.xray, want[3];
    for (int i = 0; i < 3; i++) {
        double F = o.colors.face[i] * (0.2 + K);
        want[i] = x * F + (1 - x) * x * F + (1 - x) * (1 - x) * o.colors.background[i];
    }
    expect_rgb(pix(img, W / 2, W / 2), want, 1e-5, "x-ray cube");
    free(img);
    csg_scene_free(s);
}

/* ---- determinism ------------------------------------------------------------------------ */

/* Jitter, area lights, a thin lens and mirrors draw random numbers from
 * per-pixel streams: 1, 2 and 7 threads give the same bytes. */
Test(light_determinism, stochastic_features_identical_for_any_thread_count)
{
    const float glass[4] = {0.3f, 0.6f, 1, 0.4f};
    csg_material shiny = material(NULL);
    shiny.reflect = 0.5f;
    const double lo[3] = {-15, -15, -3}, hi[3] = {15, 15, -2};
    csg_node *u = op(CSG_OP_UNION, box_m(lo, hi, NULL, &shiny), sphere(0, 0, 3, 5, glass));
    csg_scene *s = scene1(op(CSG_OP_UNION, u, box(6, 6, -2, 10, 10, 6, NULL)));
    render_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 55, 0, 25, 90}};
    render_camera cam;
    cr_assert_eq(render_camera_resolve(&v, NULL, NULL, 0, 64, 48, &cam), 0);
    render_options o = {.width = 64,
                        .height = 48,
                        .samples = 2,
                        .threads = 1,
                        .nlights = 1,
                        .aperture = 2,
                        .ior = 1.4,
                        .seed = 7};
    o.lights[0] = (render_light){{10, -20, 30}, 4, 1};
    cr_assert_eq(render_colors_by_name("Cornfield", &o.colors), 0);
    float *one = render(s, &cam, &o);
    o.threads = 2;
    float *two = render(s, &cam, &o);
    o.threads = 7;
    float *seven = render(s, &cam, &o);
    size_t bytes = 64 * 48 * 4 * sizeof(float);
    cr_expect(memcmp(one, two, bytes) == 0, "1 and 2 threads differ");
    cr_expect(memcmp(one, seven, bytes) == 0, "1 and 7 threads differ");
    o.seed = 8;
    float *other = render(s, &cam, &o);
    cr_expect(memcmp(one, other, bytes) != 0, "the seed changes nothing");
    free(one);
    free(two);
    free(seven);
    free(other);
    csg_scene_free(s);
}

/* Nothing of the light model set: the bytes of the preview look, whatever
 * the seed. */
Test(light_determinism, defaults_keep_the_preview_look)
{
    csg_scene *s = scene1(op(CSG_OP_UNION, box(-5, -5, -5, 5, 5, 5, NULL),
                             sphere(4, 4, 4, 3, (const float[4]){0.2f, 0.4f, 0.9f, 0.5f})));
    render_camera cam = top_camera();
    render_options o = opts();
    float *a = render(s, &cam, &o);
    o.seed = 12345;
    float *b = render(s, &cam, &o);
    cr_expect(memcmp(a, b, (size_t)W * W * 4 * sizeof(float)) == 0);
    free(a);
    free(b);
    csg_scene_free(s);
}

Test(light_options, bad_light_options_fail_with_message)
{
    csg_scene *s = scene1(box(0, 0, 0, 1, 1, 1, NULL));
    render_camera cam = top_camera();
    render_options o = opts();
    o.xray = 2;
    float *px = malloc((size_t)W * W * 4 * sizeof *px);
    char err[256] = "";
    cr_expect_eq(render_image(s, &cam, &o, px, err, sizeof err), -1);
    cr_expect(strstr(err, "light options") != NULL, "%s", err);
    o.xray = 0;
    o.nlights = RAYSCAD_MAX_LIGHTS + 1;
    cr_expect_eq(render_image(s, &cam, &o, px, err, sizeof err), -1);
    free(px);
    csg_scene_free(s);
}
